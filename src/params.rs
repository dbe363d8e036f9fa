//! The one table of user-facing parameters: name, label, group, unit, range, step and
//! default. The HTML controls, the egui panel, URL options, the CLI and the tests all read
//! it, so they cannot drift apart. Values are stored as `f32`; toggles are 0 or 1.

use std::fmt;

/// Identifies a parameter; its discriminant is its index in [`PARAMS`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ParamId {
    WaveSpeed,
    Damping,
    AbsorbingWalls,
    Foam,
    FoamDecay,
    DropRadius,
    DropStrength,
    SunAzimuth,
    SunElevation,
    SunSize,
    Exposure,
    Setting,
    Caustics,
    Ambient,
    WindSpeed,
    WindDirection,
    WaveHeight,
    WaveSpread,
    Steepness,
    Spectrum,
    FftSize,
    Choppiness,
    Fresnel,
    Specular,
    Shininess,
    Dispersion,
    AbsorptionRed,
    AbsorptionGreen,
    AbsorptionBlue,
    ScatterRed,
    ScatterGreen,
    ScatterBlue,
    ViewColour,
    Objects,
    SphereRadius,
    SphereDensity,
    DuckDensity,
    Gravity,
    SimSize,
    Paused,
    DebugView,
    DebugInset,
    Quality,
    FrameBudget,
    RenderMode,
    Split,
    FlatDistortion,
    FlatStrength,
    DudvSpeed,
    FlatResolution,
    FlatCaustics,
    FlatSoftEdge,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Control {
    Slider {
        min: f32,
        max: f32,
        step: f32,
    },
    Toggle,
    /// One of a few values, in increasing order; `names` (empty, or one per value) are what
    /// controls show instead of the numbers.
    Choice {
        values: &'static [f32],
        names: &'static [&'static str],
    },
}

#[derive(Clone, Copy, Debug)]
pub struct ParamSpec {
    pub id: ParamId,
    /// Stable machine name used in URLs, `set(name, value)` and the CLI.
    pub name: &'static str,
    pub label: &'static str,
    pub group: &'static str,
    /// Unit symbol shown after the value ("m/s", "1/s", "m", "°"), empty when unitless.
    pub unit: &'static str,
    pub control: Control,
    pub default: f32,
    pub help: &'static str,
}

impl ParamSpec {
    pub fn min(&self) -> f32 {
        match self.control {
            Control::Slider { min, .. } => min,
            Control::Toggle => 0.0,
            Control::Choice { values, .. } => values[0],
        }
    }

    pub fn max(&self) -> f32 {
        match self.control {
            Control::Slider { max, .. } => max,
            Control::Toggle => 1.0,
            Control::Choice { values, .. } => values[values.len() - 1],
        }
    }

    /// A value as a user writes it (command line, URL): a number, one of a choice's names
    /// (any case), or on/off/true/false for a toggle. `None` if it is none of those.
    pub fn parse(&self, text: &str) -> Option<f32> {
        let text = text.trim();
        if let Control::Choice { values, names } = self.control {
            if let Some(i) = names.iter().position(|n| n.eq_ignore_ascii_case(text)) {
                return Some(values[i]);
            }
        }
        match text.to_ascii_lowercase().as_str() {
            "on" | "true" => Some(1.0),
            "off" | "false" => Some(0.0),
            _ => text.parse().ok(),
        }
    }

    /// The nearest valid value: clamped to the range; toggles snap to 0 or 1, choices to the
    /// nearest value; NaN gives the default.
    pub fn sanitise(&self, value: f32) -> f32 {
        if value.is_nan() {
            return self.default;
        }
        match self.control {
            Control::Slider { min, max, .. } => value.clamp(min, max),
            Control::Toggle => {
                if value >= 0.5 {
                    1.0
                } else {
                    0.0
                }
            }
            Control::Choice { values, .. } => {
                values.iter().copied().min_by(|a, b| (a - value).abs().total_cmp(&(b - value).abs())).unwrap_or(value)
            }
        }
    }
}

/// Parameters that matter only for some values of another (a model's own settings): the
/// controls show them only then. (parameter, the one it depends on, the values it needs)
pub const SHOWN_WHEN: &[(ParamId, ParamId, &[f32])] = &[
    (ParamId::WindSpeed, ParamId::Ambient, &[1.0, 2.0, 3.0, 4.0]),
    (ParamId::WindDirection, ParamId::Ambient, &[1.0, 2.0, 3.0, 4.0]),
    (ParamId::WaveHeight, ParamId::Ambient, &[1.0, 2.0, 3.0, 4.0]),
    (ParamId::WaveSpread, ParamId::Ambient, &[1.0, 3.0, 4.0]),
    (ParamId::Steepness, ParamId::Ambient, &[3.0]),
    (ParamId::Spectrum, ParamId::Ambient, &[4.0]),
    (ParamId::FftSize, ParamId::Ambient, &[4.0]),
    (ParamId::Choppiness, ParamId::Ambient, &[4.0]),
    (ParamId::Split, ParamId::RenderMode, &[2.0]),
    (ParamId::FlatDistortion, ParamId::RenderMode, &[1.0, 2.0]),
    (ParamId::FlatStrength, ParamId::RenderMode, &[1.0, 2.0]),
    (ParamId::DudvSpeed, ParamId::RenderMode, &[1.0, 2.0]),
    (ParamId::FlatResolution, ParamId::RenderMode, &[1.0, 2.0]),
    (ParamId::FlatCaustics, ParamId::RenderMode, &[1.0, 2.0]),
    (ParamId::FlatSoftEdge, ParamId::RenderMode, &[1.0, 2.0]),
];

impl ParamId {
    /// The parameter this one's control depends on, and the values that show it.
    pub fn shown_when(self) -> Option<(ParamId, &'static [f32])> {
        SHOWN_WHEN.iter().find(|(id, _, _)| *id == self).map(|&(_, on, values)| (on, values))
    }
}

const fn slider(min: f32, max: f32, step: f32) -> Control {
    Control::Slider { min, max, step }
}

pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        id: ParamId::WaveSpeed,
        name: "wave_speed",
        label: "Wave speed",
        group: "Water",
        unit: "m/s",
        control: slider(0.1, 2.0, 0.05),
        default: 0.6,
        help: "Speed c of ripples in the wave equation h_tt = c² ∇²h.",
    },
    ParamSpec {
        id: ParamId::Damping,
        name: "damping",
        label: "Damping",
        group: "Water",
        unit: "1/s",
        control: slider(0.0, 5.0, 0.05),
        default: 0.5,
        help: "Rate k at which waves lose energy (amplitude decays as exp(-k t / 2)).",
    },
    ParamSpec {
        id: ParamId::AbsorbingWalls,
        name: "absorbing_walls",
        label: "Absorbing walls",
        group: "Water",
        unit: "",
        control: Control::Toggle,
        default: 0.0,
        help: "Walls swallow waves in a damping layer along them instead of reflecting them.",
    },
    ParamSpec {
        id: ParamId::Foam,
        name: "foam",
        label: "Foam",
        group: "Water",
        unit: "",
        control: Control::Toggle,
        default: 0.0,
        help: "White water where crests fall faster than a quarter of g, where water runs up a wall, and where drops and bodies throw water about; it fades and spreads.",
    },
    ParamSpec {
        id: ParamId::FoamDecay,
        name: "foam_decay",
        label: "Foam lifetime",
        group: "Water",
        unit: "s",
        control: slider(0.3, 5.0, 0.1),
        default: 1.5,
        help: "Time constant tau of the foam's fading: after tau seconds 37 % of it is left.",
    },
    ParamSpec {
        id: ParamId::DropRadius,
        name: "drop_radius",
        label: "Drop radius",
        group: "Drops",
        unit: "m",
        control: slider(0.01, 0.3, 0.005),
        default: 0.04,
        help: "Radius of the cosine bump a click or drag adds.",
    },
    ParamSpec {
        id: ParamId::DropStrength,
        name: "drop_strength",
        label: "Drop strength",
        group: "Drops",
        unit: "m",
        control: slider(-0.05, 0.05, 0.001),
        default: 0.012,
        help: "Height of the bump at its centre (negative pushes the water down).",
    },
    ParamSpec {
        id: ParamId::SunAzimuth,
        name: "sun_azimuth",
        label: "Sun azimuth",
        group: "Light",
        unit: "°",
        control: slider(-180.0, 180.0, 1.0),
        default: 35.0,
        help: "Compass direction of the sun around the pool.",
    },
    ParamSpec {
        id: ParamId::SunElevation,
        name: "sun_elevation",
        label: "Sun elevation",
        group: "Light",
        unit: "°",
        control: slider(10.0, 90.0, 1.0),
        default: 55.0,
        help: "Height of the sun above the horizon.",
    },
    ParamSpec {
        id: ParamId::SunSize,
        name: "sun_size",
        label: "Sun size",
        group: "Light",
        unit: "°",
        control: slider(0.5, 5.0, 0.1),
        default: crate::optics::DEFAULT_SUN_SIZE_DEG,
        help: "Angular diameter of the sun's disk in the sky and in its reflections (the real sun: 0.5°).",
    },
    ParamSpec {
        id: ParamId::Exposure,
        name: "exposure",
        label: "Exposure",
        group: "Light",
        unit: "EV",
        control: slider(-2.0, 2.0, 0.1),
        default: 0.0,
        help: "Brightness of the picture in photographic stops (each +1 doubles the light before the filmic tone curve).",
    },
    ParamSpec {
        id: ParamId::Setting,
        name: "setting",
        label: "Setting",
        group: "Light",
        unit: "",
        control: Control::Choice { values: &[0.0, 1.0], names: &["deck", "cutaway"] },
        default: 0.0,
        help: "Where the pool is: sunk in a paved deck under the sky, or the classic's cut-away box, open at the near walls so you see the water's cross-section.",
    },
    ParamSpec {
        id: ParamId::Caustics,
        name: "caustics",
        label: "Caustics",
        group: "Light",
        unit: "",
        control: Control::Toggle,
        default: 1.0,
        help: "Light focused by the waves onto the floor, walls and sphere.",
    },
    ParamSpec {
        id: ParamId::Ambient,
        name: "ambient",
        label: "Ambient waves",
        group: "Ambient waves",
        unit: "",
        control: Control::Choice {
            values: &[0.0, 1.0, 2.0, 3.0, 4.0],
            names: &["none", "sines", "modes", "gerstner", "fft"],
        },
        default: 0.0,
        help: "A surface that moves on its own under your ripples: none, a sum of sharp-crested travelling sines, the pool's own standing waves (modes) that meet every wall flat, Gerstner waves (the water moves in circles, crests sharpen), or an FFT ocean (thousands of waves from a spectrum).",
    },
    ParamSpec {
        id: ParamId::WindSpeed,
        name: "wind_speed",
        label: "Wind speed",
        group: "Ambient waves",
        unit: "m/s",
        control: slider(0.5, 10.0, 0.1),
        default: 3.0,
        help: "Wind of the Phillips spectrum the waves' amplitudes come from: stronger wind gives the longer waves more of the height.",
    },
    ParamSpec {
        id: ParamId::WindDirection,
        name: "wind_direction",
        label: "Wind direction",
        group: "Ambient waves",
        unit: "°",
        control: slider(-180.0, 180.0, 1.0),
        default: 30.0,
        help: "Direction the wind blows towards, from +x towards +z.",
    },
    ParamSpec {
        id: ParamId::WaveHeight,
        name: "wave_height",
        label: "Wave height",
        group: "Ambient waves",
        unit: "m",
        control: slider(0.0, 0.03, 0.001),
        default: 0.01,
        help: "Significant height H_s of the ambient waves: four times the surface's standard deviation.",
    },
    ParamSpec {
        id: ParamId::WaveSpread,
        name: "wave_spread",
        label: "Spread of directions",
        group: "Ambient waves",
        unit: "°",
        control: slider(0.0, 90.0, 1.0),
        default: 30.0,
        help: "How far (±) the travelling waves' directions stray from the wind's.",
    },
    ParamSpec {
        id: ParamId::Steepness,
        name: "steepness",
        label: "Steepness Q",
        group: "Ambient waves",
        unit: "",
        control: slider(0.0, crate::ambient::MAX_STEEPNESS, 0.05),
        default: 0.6,
        help: "Gerstner steepness: 0 gives plain sines; towards 1 the water gathers under sharp crests (at 1 they would become cusps).",
    },
    ParamSpec {
        id: ParamId::Spectrum,
        name: "spectrum",
        label: "Spectrum",
        group: "Ambient waves",
        unit: "",
        control: Control::Choice { values: &[0.0, 1.0], names: &["phillips", "jonswap"] },
        default: 0.0,
        help: "The FFT ocean's wave spectrum: Phillips (Tessendorf's) or JONSWAP (measured seas of limited fetch, a sharper peak; here a 100 m fetch).",
    },
    ParamSpec {
        id: ParamId::FftSize,
        name: "fft_size",
        label: "FFT grid",
        group: "Ambient waves",
        unit: "",
        control: Control::Choice { values: &[64.0, 128.0], names: &[] },
        default: 64.0,
        help: "Waves per side of the FFT ocean's lattice: 128 adds ripples down to 6 cm.",
    },
    ParamSpec {
        id: ParamId::Choppiness,
        name: "choppiness",
        label: "Choppiness",
        group: "Ambient waves",
        unit: "",
        control: slider(0.0, crate::ambient::ocean::MAX_CHOPPINESS, 0.1),
        default: 0.0,
        help: "The FFT ocean's water also moves sideways, gathering under the crests (Tessendorf's choppy waves); 0 is the height field alone.",
    },
    ParamSpec {
        id: ParamId::Fresnel,
        name: "fresnel",
        label: "Fresnel model",
        group: "Optics",
        unit: "",
        control: Control::Choice {
            values: &[0.0, 1.0, 2.0, 3.0, 4.0, 5.0],
            names: &["exact", "table", "schlick", "inverse_power", "clamped_power", "linear"],
        },
        default: 0.0,
        help: "How much of the light the surface reflects at each angle: the exact Fresnel equations, the same from a lookup texture, Schlick's approximation, 1/(1+cos θ)^8, clamp((1-cos θ)^4, 0.05, 0.3) or 1-cos θ.",
    },
    ParamSpec {
        id: ParamId::Specular,
        name: "specular",
        label: "Sun highlight",
        group: "Optics",
        unit: "",
        control: Control::Choice { values: &[0.0, 1.0], names: &["phong", "blinn_phong"] },
        default: 0.0,
        help: "Shape of the sun's glint on the water: Phong (reflected ray against the sun) or Blinn-Phong (normal against the half vector), wider at the same shininess.",
    },
    ParamSpec {
        id: ParamId::Shininess,
        name: "shininess",
        label: "Shininess",
        group: "Optics",
        unit: "",
        control: slider(100.0, 10000.0, 100.0),
        default: 3000.0,
        help: "Exponent s of the highlight's cos^s: higher is a smaller, sharper glint.",
    },
    ParamSpec {
        id: ParamId::Dispersion,
        name: "dispersion",
        label: "Dispersion",
        group: "Optics",
        unit: "×",
        control: slider(0.0, 20.0, 0.5),
        default: 0.0,
        help: "Red and blue light bend by their own refractive indices (water: 1.331 red, 1.335 green, 1.337 blue), this many times the real spread: coloured fringes at the caustics' edges and at the rim of Snell's window. 0: off.",
    },
    ParamSpec {
        id: ParamId::AbsorptionRed,
        name: "absorption_red",
        label: "Absorption, red",
        group: "Water colour",
        unit: "1/m",
        control: slider(0.0, 2.0, 0.005),
        default: 1.2,
        help: "Beer-Lambert absorption of red light per metre of water: after d metres exp(-a d) of it is left.",
    },
    ParamSpec {
        id: ParamId::AbsorptionGreen,
        name: "absorption_green",
        label: "Absorption, green",
        group: "Water colour",
        unit: "1/m",
        control: slider(0.0, 2.0, 0.005),
        default: 0.24,
        help: "Beer-Lambert absorption of green light per metre of water: after d metres exp(-a d) of it is left.",
    },
    ParamSpec {
        id: ParamId::AbsorptionBlue,
        name: "absorption_blue",
        label: "Absorption, blue",
        group: "Water colour",
        unit: "1/m",
        control: slider(0.0, 2.0, 0.005),
        default: 0.10,
        help: "Beer-Lambert absorption of blue light per metre of water: after d metres exp(-a d) of it is left.",
    },
    ParamSpec {
        id: ParamId::ScatterRed,
        name: "scatter_red",
        label: "Scattered light, red",
        group: "Water colour",
        unit: "",
        control: slider(0.0, 0.5, 0.005),
        default: 0.0,
        help: "Light the water itself scatters towards you (red, linear units; the sky is about 0.5): it fills in what absorption takes, so deep water turns this colour instead of black. 0 in every channel: off.",
    },
    ParamSpec {
        id: ParamId::ScatterGreen,
        name: "scatter_green",
        label: "Scattered light, green",
        group: "Water colour",
        unit: "",
        control: slider(0.0, 0.5, 0.005),
        default: 0.0,
        help: "Light the water itself scatters towards you (green, linear units; the sky is about 0.5): it fills in what absorption takes, so deep water turns this colour instead of black. 0 in every channel: off.",
    },
    ParamSpec {
        id: ParamId::ScatterBlue,
        name: "scatter_blue",
        label: "Scattered light, blue",
        group: "Water colour",
        unit: "",
        control: slider(0.0, 0.5, 0.005),
        default: 0.0,
        help: "Light the water itself scatters towards you (blue, linear units; the sky is about 0.5): it fills in what absorption takes, so deep water turns this colour instead of black. 0 in every channel: off.",
    },
    ParamSpec {
        id: ParamId::ViewColour,
        name: "view_colour",
        label: "Colour by view angle",
        group: "Water colour",
        unit: "",
        control: Control::Toggle,
        default: 0.0,
        help: "The scattered light loses half its green along grazing paths and keeps it looking straight down, as seed 002 tints its water by the view angle (needs scattered light).",
    },
    ParamSpec {
        id: ParamId::Objects,
        name: "objects",
        label: "Objects",
        group: "Objects",
        unit: "",
        control: Control::Choice { values: &[0.0, 1.0, 2.0, 3.0], names: &["none", "sphere", "duck", "both"] },
        default: 3.0,
        help: "What floats in the pool: nothing, the sphere, a rubber duck, or both.",
    },
    ParamSpec {
        id: ParamId::SphereRadius,
        name: "sphere_radius",
        label: "Sphere radius",
        group: "Objects",
        unit: "m",
        control: slider(0.1, 0.4, 0.01),
        default: 0.25,
        help: "Radius of the sphere.",
    },
    ParamSpec {
        id: ParamId::SphereDensity,
        name: "sphere_density",
        label: "Sphere density",
        group: "Objects",
        unit: "kg/m³",
        control: slider(100.0, 2000.0, 10.0),
        default: 600.0,
        help: "Mass per volume; below water's 1000 kg/m³ the sphere floats.",
    },
    ParamSpec {
        id: ParamId::DuckDensity,
        name: "duck_density",
        label: "Duck density",
        group: "Objects",
        unit: "kg/m³",
        control: slider(100.0, 900.0, 10.0),
        default: 300.0,
        help: "Mass per volume of the rubber duck: the lighter, the higher it floats.",
    },
    ParamSpec {
        id: ParamId::Gravity,
        name: "gravity",
        label: "Gravity",
        group: "Objects",
        unit: "",
        control: Control::Toggle,
        default: 1.0,
        help: "Let the objects fall, float, bob and drift on the waves (G key); off, they stay where they are put.",
    },
    ParamSpec {
        id: ParamId::SimSize,
        name: "sim_size",
        label: "Grid resolution",
        group: "Simulation",
        unit: "cells",
        control: Control::Choice { values: &[128.0, 256.0, 512.0, 1024.0], names: &[] },
        default: 256.0,
        help: "Cells per side of the simulation grid; a change resamples the water, it does not reset it.",
    },
    ParamSpec {
        id: ParamId::Paused,
        name: "paused",
        label: "Paused",
        group: "Simulation",
        unit: "",
        control: Control::Toggle,
        default: 0.0,
        help: "Freeze the water (space bar).",
    },
    ParamSpec {
        id: ParamId::DebugView,
        name: "debug_view",
        label: "Debug view",
        group: "Debug",
        unit: "",
        control: Control::Choice {
            values: &[0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0],
            names: &["off", "height", "normals", "velocity", "caustics", "reflectance", "spectrum"],
        },
        default: 0.0,
        help: "Shows one of the simulation's textures: height (red up, blue down), surface normals, vertical velocity, or the caustics map; or the water's Fresnel reflectance as grey (black 0, white 1); or the ambient waves' spectrum (amplitude per wavevector, log scale, k = 0 in the middle, rings at the 0.9 m and 0.2 m wavelengths).",
    },
    ParamSpec {
        id: ParamId::DebugInset,
        name: "debug_inset",
        label: "Debug view as inset",
        group: "Debug",
        unit: "",
        control: Control::Toggle,
        default: 1.0,
        help: "Show the debug view in a corner of the scene (on) or over all of it (off).",
    },
    ParamSpec {
        id: ParamId::Quality,
        name: "quality",
        label: "Resolution",
        group: "Display",
        unit: "",
        control: Control::Choice {
            values: &[0.0, 0.5, 0.6, 0.7, 0.85, 1.0],
            names: &["auto", "50%", "60%", "70%", "85%", "100%"],
        },
        default: 0.0,
        help: "Scale of the scene's resolution: fixed, or auto (lowered in steps down to 50% while frames take longer than the frame budget, raised again when there is headroom).",
    },
    ParamSpec {
        id: ParamId::FrameBudget,
        name: "frame_budget",
        label: "Frame budget",
        group: "Display",
        unit: "ms",
        control: slider(10.0, 200.0, 1.0),
        default: 33.0,
        help: "Time a frame should take at most; with automatic resolution, slower frames lower the resolution.",
    },
    ParamSpec {
        id: ParamId::RenderMode,
        name: "render_mode",
        label: "Water rendering",
        group: "Flat water",
        unit: "",
        control: Control::Choice { values: &[0.0, 1.0, 2.0], names: &["raytraced", "flat", "split"] },
        default: 0.0,
        help: "How the water surface is drawn. raytraced: every pixel of the surface traces its reflected and refracted rays through the pool. flat: the games' technique (seeds 000, 002, 003): the scene is drawn twice more into textures, mirrored in the water plane (reflection) and clipped under it (refraction), and a flat plane blends the two by Fresnel, wobbled by a distortion instead of bent by the waves. It is an above-water technique: under water the ray tracer draws. split: flat on the left, ray-traced on the right of a divider you drag.",
    },
    ParamSpec {
        id: ParamId::Split,
        name: "split",
        label: "Divider",
        group: "Flat water",
        unit: "",
        control: slider(0.0, 1.0, 0.01),
        default: 0.5,
        help: "Where the divider stands, as a fraction of the width from the left: flat water to its left, ray-traced to its right. Drag the divider on the canvas to move it.",
    },
    ParamSpec {
        id: ParamId::FlatDistortion,
        name: "flat_distortion",
        label: "Distortion",
        group: "Flat water",
        unit: "",
        control: Control::Choice { values: &[0.0, 1.0], names: &["dudv", "ripples"] },
        default: 0.0,
        help: "What wobbles the flat water's reflection and refraction: dudv, a tiling distortion map scrolled over time (seed 000's moveFactor; clicks make no ripples in it), or ripples, the simulation's own slopes (the same waves as the ray tracer, with faked optics).",
    },
    ParamSpec {
        id: ParamId::FlatStrength,
        name: "flat_strength",
        label: "Distortion strength",
        group: "Flat water",
        unit: "",
        control: slider(0.0, 0.08, 0.002),
        default: 0.02,
        help: "How far the reflection and refraction textures are shifted by the distortion, as a fraction of the screen (seed 000's waveStrength). It does not grow with the distance to what is seen, as real refraction does: a rim far above the water wobbles as much as the tiles under it.",
    },
    ParamSpec {
        id: ParamId::DudvSpeed,
        name: "dudv_speed",
        label: "Distortion speed",
        group: "Flat water",
        unit: "1/s",
        control: slider(0.0, 0.2, 0.005),
        default: 0.03,
        help: "Tiles of the dudv map scrolled per simulated second (it stops when the water is paused); with the dudv distortion.",
    },
    ParamSpec {
        id: ParamId::FlatResolution,
        name: "flat_resolution",
        label: "Texture resolution",
        group: "Flat water",
        unit: "",
        control: Control::Choice { values: &[0.25, 0.5, 0.75, 1.0], names: &["25%", "50%", "75%", "100%"] },
        default: 0.5,
        help: "Size of the reflection and refraction textures against the scene's: smaller is cheaper and blurrier.",
    },
    ParamSpec {
        id: ParamId::FlatCaustics,
        name: "flat_caustics",
        label: "Caustics",
        group: "Flat water",
        unit: "",
        control: Control::Choice { values: &[0.0, 1.0, 2.0], names: &["off", "fake", "real"] },
        default: 1.0,
        help: "Light on the pool under flat water: off (a calm surface's), fake (seed 000: a highlight where the distortion's normal would send the sun straight down; no focusing, no pass) or real (the ray tracer's caustics map, one more pass).",
    },
    ParamSpec {
        id: ParamId::FlatSoftEdge,
        name: "flat_soft_edge",
        label: "Soft edge",
        group: "Flat water",
        unit: "m",
        control: slider(0.0, 0.3, 0.01),
        default: 0.1,
        help: "Water shallower than this (along the view) is distorted less (seed 002), hiding the seam where the flat plane meets the walls; 0 shows the seam.",
    },
];

/// The label a choice parameter shows for `value` (its name, or the number with its unit).
pub fn choice_label(spec: &ParamSpec, value: f32) -> String {
    if let Control::Choice { values, names } = spec.control {
        if let Some(i) = values.iter().position(|&v| v == value) {
            if let Some(name) = names.get(i) {
                return (*name).to_owned();
            }
        }
    }
    if spec.unit.is_empty() {
        format!("{value}")
    } else {
        format!("{value} {}", spec.unit)
    }
}

pub fn spec(id: ParamId) -> &'static ParamSpec {
    &PARAMS[id as usize]
}

pub fn find(name: &str) -> Option<&'static ParamSpec> {
    PARAMS.iter().find(|p| p.name == name)
}

#[derive(Clone, Debug, PartialEq)]
pub enum ParamError {
    Unknown(String),
}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ParamError::Unknown(name) => {
                let names: Vec<&str> = PARAMS.iter().map(|p| p.name).collect();
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

/// Current values of every parameter in [`PARAMS`].
#[derive(Clone, Debug, PartialEq)]
pub struct Params {
    values: Vec<f32>,
}

impl Default for Params {
    fn default() -> Self {
        Self { values: PARAMS.iter().map(|p| p.default).collect() }
    }
}

impl Params {
    pub fn get(&self, id: ParamId) -> f32 {
        self.values[id as usize]
    }

    pub fn flag(&self, id: ParamId) -> bool {
        self.get(id) >= 0.5
    }

    /// Sets a value, clamping it into range.
    pub fn set(&mut self, id: ParamId, value: f32) -> SetOutcome {
        let spec = spec(id);
        let clean = spec.sanitise(value);
        self.values[id as usize] = clean;
        SetOutcome { value: clean, clamped: clean != value }
    }

    pub fn get_by_name(&self, name: &str) -> Result<f32, ParamError> {
        find(name).map(|s| self.get(s.id)).ok_or_else(|| ParamError::Unknown(name.to_owned()))
    }

    pub fn set_by_name(&mut self, name: &str, value: f32) -> Result<SetOutcome, ParamError> {
        let spec = find(name).ok_or_else(|| ParamError::Unknown(name.to_owned()))?;
        Ok(self.set(spec.id, value))
    }

    pub fn reset(&mut self, id: ParamId) {
        self.values[id as usize] = spec(id).default;
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
        for p in PARAMS {
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
        ];
        println!("{cases:?}");
        for (got, want) in cases {
            assert_eq!(got, want);
        }
    }

    #[test]
    fn table_is_indexed_by_id_and_defaults_are_in_range() {
        for (i, p) in PARAMS.iter().enumerate() {
            assert_eq!(p.id as usize, i, "{} out of place", p.name);
            assert_eq!(p.sanitise(p.default), p.default, "{} default out of range", p.name);
            assert!(p.min() < p.max());
        }
        let mut names: Vec<_> = PARAMS.iter().map(|p| p.name).collect();
        names.sort();
        names.dedup();
        assert_eq!(names.len(), PARAMS.len(), "parameter names must be unique");
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
