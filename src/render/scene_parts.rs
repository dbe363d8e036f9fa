//! What a scene's own passes (`scenes/<name>/render`) take from the renderer: the scene
//! uniforms and the layouts and bind groups every scene pass binds (the water's, the
//! textures'), the depth target, the bodies' meshes, the render scale and its upscaler, and the
//! helpers the pool's pipelines and passes are built with. The renderer names no scene but the
//! pool it draws itself.

use super::{Renderer, View};

pub use super::meshes::{banded_grid, Mesh};
pub use super::passes::begin_scene_pass;
pub use super::resources::water_bind_groups;
pub use super::shaders::scene_prelude_in;
pub use super::variants::{mesh_pipeline, DepthUse, MeshPipeline};
pub use super::DEPTH_FORMAT;

impl Renderer {
    /// The settings it was made with.
    pub fn settings(&self) -> &super::RenderSettings {
        &self.settings
    }

    /// The scene uniforms' buffer (written by [`Renderer::prepare`]).
    pub fn uniforms(&self) -> &wgpu::Buffer {
        &self.uniforms
    }

    /// The layouts of a scene pass's first two bind groups: the uniforms with a water's state,
    /// and the textures (sky, tiles, caustics).
    pub fn scene_layouts(&self) -> [&wgpu::BindGroupLayout; 2] {
        [&self.water_layout, &self.textures_layout]
    }

    /// The textures' bind group (the second of a scene pass).
    pub fn textures_group(&self) -> &wgpu::BindGroup {
        &self.textures_group
    }

    /// The maps the FFT ocean is read from, bound with a water's state.
    pub fn ambient_views(&self) -> &[wgpu::TextureView; 2] {
        &self.ambient_views
    }

    /// Each kind of body's mesh, in the order of `bodies::KINDS`.
    pub fn body_meshes(&self) -> &[Mesh] {
        &self.body_meshes
    }

    /// The depth target for a frame of `size` pixels (made again when the size changes).
    pub fn scene_depth(&mut self, device: &wgpu::Device, size: (u32, u32)) -> &wgpu::TextureView {
        self.depth_view(device, size)
    }

    /// The size (pixels) a frame of `size` is drawn at by the view's render scale.
    pub fn scene_size(&self, view: &View, size: (u32, u32)) -> (u32, u32) {
        self.scaled_size(view, size)
    }

    /// The image to draw a frame into at `size` pixels below the target's (see
    /// [`Renderer::scene_size`]), then scaled up by [`Renderer::upscale_into`].
    pub fn upscale_image(&mut self, device: &wgpu::Device, size: (u32, u32)) -> wgpu::TextureView {
        self.upscale.image(device, self.settings.target_format, size)
    }

    /// Scales the image of [`Renderer::upscale_image`] up over the whole of `target`.
    pub fn upscale_into(&self, encoder: &mut wgpu::CommandEncoder, target: &wgpu::TextureView) {
        self.upscale.run(encoder, target);
    }
}
