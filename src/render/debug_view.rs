//! The debug view: one of the renderer's inner textures drawn in an inset or over the
//! whole frame (`shaders/debug_view.wgsl`), one pass per texture shown.

use super::{shaders, AmbientView, Features, Renderer};
use crate::gpu::{FullscreenPass, FullscreenTarget};
use crate::param_spec::{Control, ParamSpec};

/// Which inner texture the debug view shows (see `shaders/debug_view.wgsl`), and where.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DebugView {
    pub texture: DebugTexture,
    /// In the lower right corner (a square of 40% of the shorter side) instead of the whole target.
    pub inset: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DebugTexture {
    Height = 1,
    Normals = 2,
    Velocity = 3,
    Caustics = 4,
    /// The ambient waves' spectrum (not a simulation texture: `AmbientWaves::spectrum_image`).
    Spectrum = 6,
}

crate::choices! {
    /// What the `debug_view` parameter shows: nothing, one of the inner textures, or the
    /// water's Fresnel reflectance (not a texture but a variant of the surface shader,
    /// [`Optics::show_reflectance`]).
    pub enum DebugChoice {
        Off = "off",
        Height = "height",
        Normals = "normals",
        Velocity = "velocity",
        Caustics = "caustics",
        Reflectance = "reflectance",
        Spectrum = "spectrum",
    }
}

impl DebugChoice {
    /// The inner texture it shows, if any.
    pub fn texture(self) -> Option<DebugTexture> {
        match self {
            DebugChoice::Height => Some(DebugTexture::Height),
            DebugChoice::Normals => Some(DebugTexture::Normals),
            DebugChoice::Velocity => Some(DebugTexture::Velocity),
            DebugChoice::Caustics => Some(DebugTexture::Caustics),
            DebugChoice::Spectrum => Some(DebugTexture::Spectrum),
            DebugChoice::Off | DebugChoice::Reflectance => None,
        }
    }
}

impl DebugView {
    /// Viewport (x, y, width, height in pixels) of the view in a target of `size` pixels.
    pub fn viewport(&self, size: (u32, u32)) -> [f32; 4] {
        let (w, h) = (size.0 as f32, size.1 as f32);
        if !self.inset {
            // The largest centred square: the pool's square stays square.
            let side = w.min(h);
            return [(w - side) / 2.0, (h - side) / 2.0, side, side];
        }
        let side = (0.4 * w.min(h)).floor();
        let margin = (0.02 * w.min(h)).floor();
        [w - side - margin, h - side - margin, side, side]
    }
}

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
