//! The debug view: one of the renderer's inner textures drawn in an inset or over the
//! whole frame (`shaders/debug_view.wgsl`), one pass per texture shown.

use super::debug_choice::{DebugChoice, DebugTexture};
use super::{shaders, AmbientView, Features, Renderer};
use crate::gpu::{FullscreenPass, FullscreenTarget};
use crate::param_spec::{Control, ParamSpec};

impl Renderer {
    /// The debug view's pass for `texture`, seeing the water with `ambient` waves added.
    pub(super) fn debug_pass(
        &mut self,
        device: &wgpu::Device,
        texture: DebugTexture,
        ambient: AmbientView,
    ) -> &FullscreenPass {
        let layouts = [&self.water_layout, &self.textures_layout];
        let format = self.settings.target_format;
        let key = (texture, ambient.model, ambient.choppy());
        self.debug_passes.entry(key).or_insert_with(|| {
            let features = Features { ambient: ambient.model, choppy: ambient.choppy(), ..Features::default() };
            let constants = format!("const DEBUG_TEXTURE: i32 = {};\n", texture as i32);
            FullscreenPass::new(
                device,
                "debug view",
                &[&constants, &shaders::scene_prelude(features, format), shaders::DEBUG_VIEW],
                "fs_debug",
                &layouts,
                FullscreenTarget { format, blend: None, depth: None },
            )
        })
    }
}

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
