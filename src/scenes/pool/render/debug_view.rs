//! The debug view: one of the renderer's inner textures drawn in an inset or over the
//! whole frame (`shaders/pool/debug_view.wgsl`), one pass per texture shown.

use super::{shaders, PoolPasses};
use crate::gpu::{FullscreenPass, FullscreenTarget};
use crate::render::{AmbientView, DebugTexture, Features, Renderer};

impl PoolPasses {
    /// The debug view's pass for `texture`, seeing the water with `ambient` waves added.
    pub(super) fn debug_pass(
        &mut self,
        renderer: &Renderer,
        device: &wgpu::Device,
        texture: DebugTexture,
        ambient: AmbientView,
    ) -> &FullscreenPass {
        let layouts = renderer.scene_layouts();
        let format = renderer.settings().target_format;
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
