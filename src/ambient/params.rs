//! The ambient waves' parameters (see `params::table` for the whole table).

use crate::param_spec::{slider, Control, ParamSpec};

/// The ambient waves: which model and its settings. (The parameter table, `params::table`, lists them in this order.)
pub const PARAMS: &[ParamSpec] =
    &[AMBIENT, WIND_SPEED, WIND_DIRECTION, WAVE_HEIGHT, WAVE_SPREAD, STEEPNESS, SPECTRUM, FFT_SIZE, CHOPPINESS];

/// The `ambient` parameter.
pub const AMBIENT: ParamSpec = ParamSpec {
    name: "ambient",
    label: "Ambient waves",
    group: "Ambient waves",
    unit: "",
    control: Control::Choice { values: super::AmbientModel::VALUES, names: super::AmbientModel::NAMES },
    default: 0.0,
    help: "A surface that moves on its own under your ripples: none, a sum of sharp-crested travelling sines, the pool's own standing waves (modes) that meet every wall flat, Gerstner waves (the water moves in circles, crests sharpen), or an FFT ocean (thousands of waves from a spectrum).",
};

/// The `wind_speed` parameter.
pub const WIND_SPEED: ParamSpec = ParamSpec {
    name: "wind_speed",
    label: "Wind speed",
    group: "Ambient waves",
    unit: "m/s",
    control: slider(0.5, 10.0, 0.1),
    default: 3.0,
    help: "Wind of the Phillips spectrum the waves' amplitudes come from: stronger wind gives the longer waves more of the height.",
};

/// The `wind_direction` parameter.
pub const WIND_DIRECTION: ParamSpec = ParamSpec {
    name: "wind_direction",
    label: "Wind direction",
    group: "Ambient waves",
    unit: "°",
    control: slider(-180.0, 180.0, 1.0),
    default: 30.0,
    help: "Direction the wind blows towards, from +x towards +z.",
};

/// The `wave_height` parameter.
pub const WAVE_HEIGHT: ParamSpec = ParamSpec {
    name: "wave_height",
    label: "Wave height",
    group: "Ambient waves",
    unit: "m",
    control: slider(0.0, 0.03, 0.001),
    default: 0.01,
    help: "Significant height H_s of the ambient waves: four times the surface's standard deviation.",
};

/// The `wave_spread` parameter.
pub const WAVE_SPREAD: ParamSpec = ParamSpec {
    name: "wave_spread",
    label: "Spread of directions",
    group: "Ambient waves",
    unit: "°",
    control: slider(0.0, 90.0, 1.0),
    default: 30.0,
    help: "How far (±) the travelling waves' directions stray from the wind's.",
};

/// The `steepness` parameter.
pub const STEEPNESS: ParamSpec = ParamSpec {
    name: "steepness",
    label: "Steepness Q",
    group: "Ambient waves",
    unit: "",
    control: slider(0.0, crate::ambient::MAX_STEEPNESS, 0.05),
    default: 0.6,
    help: "Gerstner steepness: 0 gives plain sines; towards 1 the water gathers under sharp crests (at 1 they would become cusps).",
};

/// The `spectrum` parameter.
pub const SPECTRUM: ParamSpec = ParamSpec {
    name: "spectrum",
    label: "Spectrum",
    group: "Ambient waves",
    unit: "",
    control: Control::Choice { values: super::Spectrum::VALUES, names: super::Spectrum::NAMES },
    default: 0.0,
    help: "The FFT ocean's wave spectrum: Phillips (Tessendorf's) or JONSWAP (measured seas of limited fetch, a sharper peak; here a 100 m fetch).",
};

/// The `fft_size` parameter.
pub const FFT_SIZE: ParamSpec = ParamSpec {
    name: "fft_size",
    label: "FFT grid",
    group: "Ambient waves",
    unit: "",
    control: Control::Choice { values: &[64.0, 128.0], names: &[] },
    default: 64.0,
    help: "Waves per side of the FFT ocean's lattice: 128 adds ripples down to 6 cm.",
};

/// The `choppiness` parameter.
pub const CHOPPINESS: ParamSpec = ParamSpec {
    name: "choppiness",
    label: "Choppiness",
    group: "Ambient waves",
    unit: "",
    control: slider(0.0, crate::ambient::ocean::MAX_CHOPPINESS, 0.1),
    default: 0.0,
    help: "The FFT ocean's water also moves sideways, gathering under the crests (Tessendorf's choppy waves); 0 is the height field alone.",
};
