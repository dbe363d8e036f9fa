//! The renderer: what every scene's passes bind and share (the scene uniforms, the water's and
//! the textures' bind groups, the sky cube, the tiles, the caustics map, the bodies' meshes, the
//! depth target and the upscaler), the shared WGSL and the features it is compiled for. Each
//! scene draws its own passes on it (`scenes/<name>/render`); it names no scene.

pub(crate) mod caustics;
mod caustics_mips;
mod debug_choice;
pub(crate) mod debug_view;
pub(crate) mod deck;
mod features;
pub mod flat;
pub(crate) mod glaze;
mod meshes;
mod pipelines;
mod render_mode;
mod resources;
pub mod scene_parts;
mod shaders;
/// The ray helpers without bindings (`shaders/common.wgsl`), for other scenes' shaders.
pub use shaders::COMMON;
mod uniforms;
mod upscale;
mod view;

use crate::gpu;
use crate::sim::HeightField;
use crate::textures::SkyCube;
use caustics::CausticsMap;
pub use caustics::{CAUSTICS_8BIT_SCALE, CAUSTICS_FORMAT, CAUSTICS_FORMAT_8BIT};
pub use debug_choice::{DebugChoice, DebugTexture, DebugView};
pub use deck::{Setting, EYE_CLEARANCE};
pub use features::Features;
use meshes::Mesh;
pub use render_mode::{Distortion, FlatCaustics, RenderMode};
use resources::{ambient_map, water_bind_groups, DepthBuffer, SceneTextures};
use uniforms::SceneUniforms;
use upscale::Upscale;
pub use view::{flat_shown, AmbientView, Optics, View};

/// The numbers of the features every scene pass reads, as WGSL constants (the optics, the
/// ambient waves, flat water, the sky, the deck, the tiles' glaze, the caustics' mips): the
/// renderer's features are named here, at its root, not in the shader plumbing.
fn scene_constants() -> [String; 7] {
    [
        crate::optics::wgsl_constants(),
        crate::ambient::wgsl_constants(),
        flat::wgsl_constants(),
        crate::sky::Daylight::wgsl_constants(),
        deck::wgsl_constants(),
        glaze::wgsl_constants(),
        caustics_mips::CausticsMips::wgsl_constants(),
    ]
}

pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// Renderer settings fixed at creation.
#[derive(Clone, Copy, Debug)]
pub struct RenderSettings {
    /// Format of the colour targets it will draw into.
    pub target_format: wgpu::TextureFormat,
    /// Side of the caustics map in texels.
    pub caustics_size: u32,
    /// Quads per side of the pool's water surface mesh (its passes' grid). The fragment shader
    /// reads heights and normals per pixel, so this only shapes the surface's outline and
    /// parallax.
    pub surface_grid: u32,
    /// Whether the device can render (and blend) into float textures; without, the caustics
    /// map is 8-bit ([`CAUSTICS_FORMAT_8BIT`]).
    pub float_targets: bool,
    /// The pool's box (m): the uniforms give it to every scene pass, the pool's passes draw it.
    pub pool: crate::world::PoolShape,
}

impl RenderSettings {
    /// Format and scale (light per unit stored) of the caustics map.
    pub fn caustics_format(&self) -> (wgpu::TextureFormat, f32) {
        self.caustics_format_for(false)
    }

    /// The same for a map with light per colour channel (dispersion): red, green and blue
    /// light with the objects' shadows, and green light without them in alpha.
    pub fn caustics_format_for(&self, per_channel: bool) -> (wgpu::TextureFormat, f32) {
        match (self.float_targets, per_channel) {
            (true, false) => (CAUSTICS_FORMAT, 1.0),
            (true, true) => (wgpu::TextureFormat::Rgba16Float, 1.0),
            (false, false) => (CAUSTICS_FORMAT_8BIT, CAUSTICS_8BIT_SCALE),
            (false, true) => (wgpu::TextureFormat::Rgba8Unorm, CAUSTICS_8BIT_SCALE),
        }
    }
}

/// What every scene pass binds and shares: the uniforms, layouts and bind groups, the textures
/// and samplers, the caustics map, the bodies' meshes, the depth target and the upscaler.
pub struct Renderer {
    settings: RenderSettings,
    uniforms: wgpu::Buffer,
    /// This frame's uniforms as [`Renderer::prepare`] wrote them.
    frame_uniforms: SceneUniforms,
    water_layout: wgpu::BindGroupLayout,
    textures_layout: wgpu::BindGroupLayout,
    /// Scene uniforms + water state, one per ping-pong texture.
    water_groups: [wgpu::BindGroup; 2],
    /// How many times `water_groups` has been made ([`Renderer::water_binding`]).
    water_binding: u64,
    /// The maps the FFT ocean is read from (its surface, and its displacement with
    /// choppiness): the GPU ocean's outputs, or `cpu_ambient` filled from the CPU; a 1 x 1
    /// `cpu_ambient` until then.
    ambient_views: [wgpu::TextureView; 2],
    cpu_ambient: [(wgpu::Texture, wgpu::TextureView); 2],
    textures_group: wgpu::BindGroup,
    /// What `textures_group` binds besides the caustics map (kept to bind a resized map).
    scene_textures: SceneTextures,
    caustics: CausticsMap,
    sky_cube: SkyCube,
    /// The deck's haze colour (`deck::horizon_fit`) and the sun it was fitted for: refitted
    /// only when the sun moves, as the cube is repainted.
    horizon: (glam::Vec3, [[f32; 4]; deck::HORIZON_TERMS]),
    /// Each kind of body's mesh, in the order of `bodies::KINDS`.
    body_meshes: Vec<Mesh>,
    /// Each kind's mesh for its outline's pass (`BodyKind::outline_mesh`).
    body_outline_meshes: Vec<Mesh>,
    depth: Option<DepthBuffer>,
    upscale: Upscale,
    /// The tiles' mean albedo (linear RGB), for the light the floor sends back up.
    floor_albedo: glam::Vec3,
    /// The bodies' outlines are blended in (`BodyKind::edge`), and the water at their
    /// waterlines (`shaders/pool/water.wgsl`); off for tests to compare with.
    body_outlines: bool,
}

impl Renderer {
    /// The renderer of `water`, with the tile texture's levels made ahead
    /// ([`crate::textures::tile_mips`]).
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        settings: RenderSettings,
        water: &HeightField,
        tile_mips: &[Vec<u8>],
    ) -> Self {
        let (water_layout, textures_layout) = resources::scene_layouts(device);
        let zeroed = <SceneUniforms as bytemuck::Zeroable>::zeroed();
        let uniforms = gpu::uniform_buffer(device, "scene uniforms", &zeroed);
        let cpu_ambient = [ambient_map(device, 1), ambient_map(device, 1)];
        let ambient_views = [cpu_ambient[0].1.clone(), cpu_ambient[1].1.clone()];
        let water_groups = water_bind_groups(device, &water_layout, &uniforms, water, &ambient_views);
        let (caustics_format, _) = settings.caustics_format();
        let caustics = CausticsMap::new(device, settings.caustics_size, caustics_format);
        let sky_cube = SkyCube::new(device);
        let scene_textures = SceneTextures::new(device, queue, &sky_cube, tile_mips);
        let textures_group = scene_textures.bind_group(device, &textures_layout, &caustics.mips.view);
        Self {
            settings,
            uniforms,
            frame_uniforms: zeroed,
            water_layout,
            textures_layout,
            water_groups,
            water_binding: 0,
            ambient_views,
            cpu_ambient,
            textures_group,
            scene_textures,
            caustics,
            horizon: (glam::Vec3::ZERO, deck::horizon_fit(sky_cube.daylight())),
            sky_cube,
            body_meshes: kinds_meshes(device, |kind| (kind.mesh)()),
            body_outline_meshes: kinds_meshes(device, |kind| (kind.outline_mesh)()),
            depth: None,
            upscale: Upscale::new(device, settings.target_format),
            floor_albedo: crate::textures::tile_mean_albedo(tile_mips),
            body_outlines: true,
        }
    }

    /// Whether the bodies' outlines and the water at their waterlines are blended in (the
    /// default) or left as the pixels draw them, each wholly in or out (for tests to compare
    /// with).
    #[doc(hidden)]
    pub fn set_body_outlines(&mut self, on: bool) {
        self.body_outlines = on;
    }

    /// See [`Renderer::set_body_outlines`].
    pub fn body_outlines(&self) -> bool {
        self.body_outlines
    }
}

/// One mesh per kind of body, in the order of `bodies::KINDS`, each made by `make`.
fn kinds_meshes(
    device: &wgpu::Device,
    make: impl Fn(&crate::bodies::BodyKind) -> crate::bodies::BodyMesh,
) -> Vec<Mesh> {
    crate::bodies::KINDS
        .iter()
        .map(|kind| {
            let mesh = make(kind);
            Mesh::new(device, kind.name, &mesh.vertices, &mesh.indices)
        })
        .collect()
}
