//! The one table of user-facing parameters, assembled from the slices each feature declares
//! next to its code (`param_spec::ParamSpec`), in the order the controls show them; the ids
//! that name them; and `Params`, the current values. The HTML controls, the egui panel, URL
//! options, the CLI and the tests all read this table, so they cannot drift apart.

use std::fmt;
use std::ops::Deref;
use std::sync::OnceLock;

pub use crate::param_spec::{choice_label, Control, ParamSpec};
use crate::{ambient, bodies, optics, physics, quality, render, sea, sim, sky, tank};

/// Writes `ParamId` with `ParamId::ALL`, its variants in table order.
macro_rules! param_ids {
    ($($id:ident = $name:literal),* $(,)?) => {
        /// Names a parameter the app reads by id (a body kind's own parameters are read
        /// through its kind's specs); each id is written beside the table's name for it.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum ParamId {
            $($id),*
        }

        impl ParamId {
            /// Every id, in table order.
            pub const ALL: &[ParamId] = &[$(ParamId::$id),*];

            /// The parameter's name in the [`table`].
            pub const fn name(self) -> &'static str {
                match self {
                    $(ParamId::$id => $name),*
                }
            }
        }
    };
}

param_ids! {
    WaveSpeed = "wave_speed",
    Damping = "damping",
    AbsorbingWalls = "absorbing_walls",
    Foam = "foam",
    FoamDecay = "foam_decay",
    DropRadius = "drop_radius",
    DropStrength = "drop_strength",
    StartDrops = "start_drops",
    SunAzimuth = "sun_azimuth",
    SunElevation = "sun_elevation",
    SunSize = "sun_size",
    Exposure = "exposure",
    Scene = "scene",
    SeaWind = "sea_wind",
    SeaWindDirection = "sea_wind_direction",
    SeaWaveHeight = "sea_wave_height",
    SeaChoppiness = "sea_choppiness",
    SeaFog = "sea_fog",
    SeaFogDistance = "sea_fog_distance",
    SeaIsland = "sea_island",
    SeaObjects = "sea_objects",
    SeaGrid = "sea_grid",
    TankSetup = "tank_setup",
    TankLook = "tank_look",
    TankView = "tank_view",
    TankTool = "tank_tool",
    TankFrequency = "tank_frequency",
    TankAmplitude = "tank_amplitude",
    TankDippers = "tank_dippers",
    TankPhase = "tank_phase",
    TankDetune = "tank_detune",
    TankAmplitudeRatio = "tank_amplitude_ratio",
    TankDepth = "tank_depth",
    TankSize = "tank_size",
    TankSlitWidth = "tank_slit_width",
    TankSlitSpacing = "tank_slit_spacing",
    TankLampHeight = "tank_lamp_height",
    TankSourceSpeed = "tank_source_speed",
    TankStrobe = "tank_strobe",
    TankLines = "tank_lines",
    TankBeaches = "tank_beaches",
    TankPulse = "tank_pulse",
    TankProbe = "tank_probe",
    TankProbeX = "tank_probe_x",
    TankProbeZ = "tank_probe_z",
    TankGraph = "tank_graph",
    TankGraphZ = "tank_graph_z",
    Setting = "setting",
    Caustics = "caustics",
    CausticContrast = "caustic_contrast",
    TileGloss = "tile_gloss",
    Ambient = "ambient",
    WindSpeed = "wind_speed",
    WindDirection = "wind_direction",
    WaveHeight = "wave_height",
    WaveSpread = "wave_spread",
    Steepness = "steepness",
    Spectrum = "spectrum",
    FftSize = "fft_size",
    Choppiness = "choppiness",
    Fresnel = "fresnel",
    Specular = "specular",
    Shininess = "shininess",
    Dispersion = "dispersion",
    AbsorptionRed = "absorption_red",
    AbsorptionGreen = "absorption_green",
    AbsorptionBlue = "absorption_blue",
    ScatterRed = "scatter_red",
    ScatterGreen = "scatter_green",
    ScatterBlue = "scatter_blue",
    ViewColour = "view_colour",
    Objects = "objects",
    SphereRadius = "sphere_radius",
    SphereDensity = "sphere_density",
    DuckDensity = "duck_density",
    Gravity = "gravity",
    SimSize = "sim_size",
    Paused = "paused",
    DebugView = "debug_view",
    DebugInset = "debug_inset",
    Quality = "quality",
    FrameBudget = "frame_budget",
    RenderMode = "render_mode",
    Split = "split",
    FlatDistortion = "flat_distortion",
    FlatStrength = "flat_strength",
    DudvSpeed = "dudv_speed",
    FlatResolution = "flat_resolution",
    FlatCaustics = "flat_caustics",
    FlatSoftEdge = "flat_soft_edge",
}

/// The features' slices in the order of the controls (groups stay together); the bodies'
/// kinds each bring theirs after `objects`.
fn slices() -> Vec<&'static [ParamSpec]> {
    let mut slices = vec![
        sim::params::WATER,
        sim::foam::PARAMS,
        sim::params::DROPS,
        sky::SUN_PARAMS,
        optics::SUN_SIZE_PARAMS,
        sky::EXPOSURE_PARAMS,
        sea::SCENE_PARAMS,
        sea::PARAMS,
        tank::PARAMS,
        render::deck::PARAMS,
        render::caustics::PARAMS,
        render::glaze::PARAMS,
        ambient::params::PARAMS,
        optics::PARAMS,
        optics::WATER_COLOUR_PARAMS,
        bodies::PARAMS,
    ];
    slices.extend(bodies::KINDS.iter().map(|kind| kind.params));
    slices.extend([
        physics::GRAVITY_PARAMS,
        sim::params::RUN,
        render::debug_view::PARAMS,
        quality::PARAMS,
        render::flat::PARAMS,
    ]);
    slices
}

/// A parameter of the table: its place in it and its spec (whose fields it derefs to).
#[derive(Clone, Copy, Debug)]
pub struct Param {
    pub index: usize,
    pub spec: &'static ParamSpec,
}

impl Deref for Param {
    type Target = ParamSpec;
    fn deref(&self) -> &ParamSpec {
        self.spec
    }
}

/// Every parameter, in the order the controls show them.
pub fn table() -> &'static [Param] {
    static TABLE: OnceLock<Vec<Param>> = OnceLock::new();
    TABLE.get_or_init(|| {
        let specs = slices().into_iter().flat_map(|slice| slice.iter());
        specs.enumerate().map(|(index, spec)| Param { index, spec }).collect()
    })
}

/// Parameters that matter only for some values of another (a model's own settings): the
/// controls show them only then. (parameter, the one it depends on, the choices it needs.) The
/// scenes each parameter is shown in are the scenes' own (`scenes::shown_when`).
pub const SHOWN_WHEN: &[(ParamId, ParamId, &[&str])] = &[
    (ParamId::WindSpeed, ParamId::Ambient, &["sines", "modes", "gerstner", "fft"]),
    (ParamId::WindDirection, ParamId::Ambient, &["sines", "modes", "gerstner", "fft"]),
    (ParamId::WaveHeight, ParamId::Ambient, &["sines", "modes", "gerstner", "fft"]),
    (ParamId::WaveSpread, ParamId::Ambient, &["sines", "gerstner", "fft"]),
    (ParamId::Steepness, ParamId::Ambient, &["gerstner"]),
    (ParamId::Spectrum, ParamId::Ambient, &["fft"]),
    (ParamId::FftSize, ParamId::Ambient, &["fft"]),
    (ParamId::Choppiness, ParamId::Ambient, &["fft"]),
    (ParamId::Split, ParamId::RenderMode, &["split"]),
    (ParamId::FlatDistortion, ParamId::RenderMode, &["flat", "split"]),
    (ParamId::FlatStrength, ParamId::RenderMode, &["flat", "split"]),
    (ParamId::DudvSpeed, ParamId::RenderMode, &["flat", "split"]),
    (ParamId::FlatResolution, ParamId::RenderMode, &["flat", "split"]),
    (ParamId::FlatCaustics, ParamId::RenderMode, &["flat", "split"]),
    (ParamId::FlatSoftEdge, ParamId::RenderMode, &["flat", "split"]),
    (ParamId::TankDippers, ParamId::TankSetup, &["two_dippers"]),
    (ParamId::TankPhase, ParamId::TankSetup, &["two_dippers"]),
    (ParamId::TankDetune, ParamId::TankSetup, &["two_dippers"]),
    (ParamId::TankAmplitudeRatio, ParamId::TankSetup, &["two_dippers"]),
    (ParamId::TankSlitWidth, ParamId::TankSetup, &["single_slit", "double_slit"]),
    (ParamId::TankSlitSpacing, ParamId::TankSetup, &["double_slit", "two_dippers"]),
    (ParamId::TankLines, ParamId::TankSetup, &["single_slit", "double_slit"]),
    (ParamId::TankSourceSpeed, ParamId::TankSetup, &["doppler"]),
    (ParamId::TankProbeX, ParamId::TankProbe, &["on"]),
    (ParamId::TankProbeZ, ParamId::TankProbe, &["on"]),
    (ParamId::TankGraphZ, ParamId::TankGraph, &["on"]),
];

impl ParamId {
    /// Its place in the [`table`].
    pub fn index(self) -> usize {
        static PLACES: OnceLock<Vec<usize>> = OnceLock::new();
        let places = PLACES.get_or_init(|| {
            let place = |id: &ParamId| {
                let name = id.name();
                table()
                    .iter()
                    .position(|p| p.name == name)
                    .unwrap_or_else(|| panic!("ParamId::{id:?}: no parameter {name}"))
            };
            ParamId::ALL.iter().map(place).collect()
        });
        places[self as usize]
    }

    /// The spec of this parameter.
    pub fn spec(self) -> &'static ParamSpec {
        table()[self.index()].spec
    }
}

/// The conditions of [`SHOWN_WHEN`] on `name`'s control: each a parameter and the values (of
/// its choices) that show it.
pub fn model_conditions(name: &str) -> Vec<(&'static str, Vec<f32>)> {
    SHOWN_WHEN
        .iter()
        .filter(|(id, _, _)| id.spec().name == name)
        .map(|&(_, on, names)| {
            let values = names.iter().map(|n| on.spec().parse(n).expect("a choice of the parameter")).collect();
            (on.spec().name, values)
        })
        .collect()
}

pub fn spec(id: ParamId) -> &'static ParamSpec {
    id.spec()
}

pub fn find(name: &str) -> Option<&'static Param> {
    table().iter().find(|p| p.name == name)
}

#[derive(Clone, Debug, PartialEq)]
pub enum ParamError {
    Unknown(String),
}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParamError::Unknown(name) => {
                let names: Vec<&str> = table().iter().map(|p| p.name).collect();
                write!(f, "unknown parameter '{name}'; known: {}", names.join(", "))
            }
        }
    }
}

impl std::error::Error for ParamError {}

/// What `set` did with a value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SetOutcome {
    /// The value now in effect.
    pub value: f32,
    /// True when the requested value was out of range (or NaN) and was replaced.
    pub clamped: bool,
}

/// Current values of every parameter of the [`table`].
#[derive(Clone, Debug, PartialEq)]
pub struct Params {
    values: Vec<f32>,
}

impl Default for Params {
    fn default() -> Self {
        Self { values: table().iter().map(|p| p.default).collect() }
    }
}

impl Params {
    pub fn get(&self, id: ParamId) -> f32 {
        self.values[id.index()]
    }

    pub fn flag(&self, id: ParamId) -> bool {
        self.get(id) >= 0.5
    }

    /// A choice parameter's option, as the enum its feature declares with `choices!`.
    pub fn choice<T: From<f32>>(&self, id: ParamId) -> T {
        T::from(self.get(id))
    }

    /// Sets a value, clamping it into range.
    pub fn set(&mut self, id: ParamId, value: f32) -> SetOutcome {
        self.set_at(id.index(), value)
    }

    /// The value of the parameter at `index` in the [`table`].
    pub fn get_at(&self, index: usize) -> f32 {
        self.values[index]
    }

    /// Sets the parameter at `index` in the [`table`], clamping the value into its range.
    pub fn set_at(&mut self, index: usize, value: f32) -> SetOutcome {
        let clean = table()[index].sanitise(value);
        self.values[index] = clean;
        SetOutcome { value: clean, clamped: clean != value }
    }

    pub fn get_by_name(&self, name: &str) -> Result<f32, ParamError> {
        find(name).map(|p| self.values[p.index]).ok_or_else(|| ParamError::Unknown(name.to_owned()))
    }

    pub fn set_by_name(&mut self, name: &str, value: f32) -> Result<SetOutcome, ParamError> {
        let param = find(name).ok_or_else(|| ParamError::Unknown(name.to_owned()))?;
        Ok(self.set_at(param.index, value))
    }

    pub fn reset(&mut self, id: ParamId) {
        self.reset_at(id.index());
    }

    /// Puts the parameter at `index` in the [`table`] back to its default.
    pub fn reset_at(&mut self, index: usize) {
        self.values[index] = table()[index].default;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn choices_snap_to_the_nearest_value_and_show_their_names() {
        let size = spec(ParamId::SimSize);
        assert_eq!(size.sanitise(300.0), 256.0);
        assert_eq!(size.sanitise(5000.0), 1024.0);
        assert_eq!(size.sanitise(-3.0), 128.0);
        assert_eq!(size.sanitise(f32::NAN), size.default);
        assert_eq!(choice_label(size, 512.0), "512 cells");
        let view = spec(ParamId::DebugView);
        assert_eq!(view.sanitise(2.4), 2.0);
        assert_eq!(choice_label(view, 0.0), "off");
        assert_eq!(choice_label(view, 4.0), "caustics");
        // Every choice parameter names all of its values or none.
        for p in table() {
            if let Control::Choice { values, names } = p.control {
                assert!(names.is_empty() || names.len() == values.len(), "{}: names do not match values", p.name);
                assert!(values.windows(2).all(|w| w[0] < w[1]), "{}: values not increasing", p.name);
                assert!(values.contains(&p.default), "{}: default is not a choice", p.name);
            }
        }
    }

    #[test]
    fn values_are_read_as_numbers_choice_names_or_on_and_off() {
        let mode = spec(ParamId::RenderMode);
        let cases = [
            (mode.parse("split"), Some(2.0)),
            (mode.parse("Flat"), Some(1.0)),
            (mode.parse("1"), Some(1.0)),
            (mode.parse("curved"), None),
            (spec(ParamId::Caustics).parse("off"), Some(0.0)),
            (spec(ParamId::Caustics).parse("true"), Some(1.0)),
            (spec(ParamId::WaveSpeed).parse(" 0.8 "), Some(0.8)),
            (spec(ParamId::SimSize).parse("512"), Some(512.0)),
            (spec(ParamId::Objects).parse("sphere,duck"), Some(3.0)),
            (spec(ParamId::Objects).parse("both"), Some(3.0)),
            (spec(ParamId::Objects).parse("Duck, ball"), Some(6.0)),
            (spec(ParamId::Objects).parse("ball,ball"), None),
        ];
        println!("{cases:?}");
        for (got, want) in cases {
            assert_eq!(got, want);
        }
    }

    #[test]
    fn table_is_indexed_by_id_and_defaults_are_in_range() {
        // The ids run in the table's order (the app reads by id; the table's order is the controls').
        assert!(ParamId::ALL.windows(2).all(|w| w[0].index() < w[1].index()), "ParamId::ALL out of table order");
        for (i, p) in table().iter().enumerate() {
            assert_eq!(p.index, i, "{} out of place", p.name);
            assert_eq!(p.sanitise(p.default), p.default, "{} default out of range", p.name);
            assert!(p.min() < p.max());
        }
        let mut names: Vec<_> = table().iter().map(|p| p.name).collect();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), table().len(), "parameter names must be unique");
    }

    #[test]
    fn out_of_range_values_are_clamped_and_reported() {
        let mut params = Params::default();
        let out = params.set_by_name("wave_speed", 99.0).unwrap();
        assert_eq!(out, SetOutcome { value: 2.0, clamped: true });
        assert_eq!(params.get(ParamId::WaveSpeed), 2.0);
        let out = params.set_by_name("damping", f32::NAN).unwrap();
        assert!(out.clamped);
        assert_eq!(out.value, spec(ParamId::Damping).default);
        let out = params.set_by_name("caustics", 0.2).unwrap();
        assert_eq!(out.value, 0.0);
        assert!(matches!(params.set_by_name("nope", 1.0), Err(ParamError::Unknown(_))));
        assert!(params.get_by_name("nope").unwrap_err().to_string().contains("wave_speed"));
    }
}
