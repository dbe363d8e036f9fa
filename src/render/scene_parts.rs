//! What a scene's own passes (`scenes/<name>/render`) take from the renderer: the scene
//! uniforms and the layouts and bind groups every scene pass binds (the water's, the
//! textures'), the caustics map, the depth target, the bodies' meshes, the render scale and its
//! upscaler, and the helpers pipelines and passes are built with. The renderer names no scene.

use super::{Renderer, View};

pub use super::meshes::{banded_grid, grid_coordinate, Mesh, GRID_BAND, VERTEX_CACHE};
pub use super::pipelines::{begin_scene_pass, mesh_pipeline, DepthUse, MeshPipeline};
pub use super::resources::water_bind_groups;
pub use super::shaders::scene_prelude_in;
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

    /// A buffer of the scene uniforms' layout (zeroed), for a pass with a camera of its own
    /// ([`Renderer::write_uniforms_above_water`]).
    pub fn scene_uniform_buffer(&self, device: &wgpu::Device, label: &str) -> wgpu::Buffer {
        crate::gpu::uniform_buffer(device, label, &<super::uniforms::SceneUniforms as bytemuck::Zeroable>::zeroed())
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

    /// Each kind of body's mesh for its outline's pass, in the order of `bodies::KINDS`.
    pub fn body_outline_meshes(&self) -> &[Mesh] {
        &self.body_outline_meshes
    }

    /// The depth target for a frame of `size` pixels (made again when the size changes).
    pub fn scene_depth(&mut self, device: &wgpu::Device, size: (u32, u32)) -> &wgpu::TextureView {
        self.depth_view(device, size)
    }

    /// The size (pixels) a frame of `size` is drawn at: the view's render scale of it.
    pub fn scene_size(&self, view: &View, size: (u32, u32)) -> (u32, u32) {
        let scale = view.render_scale.clamp(0.25, 1.0);
        if scale < 1.0 {
            let scaled = |side: u32| ((side as f32 * scale).round() as u32).max(1);
            (scaled(size.0), scaled(size.1))
        } else {
            size
        }
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
