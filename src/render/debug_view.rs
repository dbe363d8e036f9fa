//! The debug view's parameters: which of the renderer's inner textures it shows, and where
//! (drawn by the pool's passes, `scenes/pool/render/debug_view.rs`).

use super::debug_choice::DebugChoice;
use crate::param_spec::{Control, ParamSpec};

/// Which inner texture the debug view shows, and where. (The parameter table, `params::table`, lists them in this order.)
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        name: "debug_view",
        label: "Debug view",
        group: "Debug",
        unit: "",
        control: Control::Choice { values: DebugChoice::VALUES, names: DebugChoice::NAMES },
        default: 0.0,
        help: "Shows one of the simulation's textures: height (red up, blue down), surface normals, vertical velocity, or the caustics map; or the water's Fresnel reflectance as grey (black 0, white 1); or the ambient waves' spectrum (amplitude per wavevector, log scale, k = 0 in the middle, rings at the 0.9 m and 0.2 m wavelengths).",
    },
    ParamSpec {
        name: "debug_inset",
        label: "Debug view as inset",
        group: "Debug",
        unit: "",
        control: Control::Toggle,
        default: 1.0,
        help: "Show the debug view in a corner of the scene (on) or over all of it (off).",
    },
];
