//! The renderer: caustics map, then one scene pass of sky, pool, sphere and the water
//! surface (from above and from below) into any colour target.

mod caustics_mips;
mod deck;
pub mod flat;
mod meshes;
mod shaders;
mod variants;

use std::collections::HashMap;

use glam::{Mat4, Vec3};

use crate::ambient::{AmbientModel, MAX_AMBIENT_WAVES, SPECTRUM_IMAGE_SIZE};
use crate::duck;
use crate::gpu::{self, FullscreenPass, FullscreenTarget};
use crate::optics::{self, FresnelModel, SpecularModel};
use crate::scene::{self, Sphere};
use crate::sim::foam::Foam;
use crate::sim::HeightField;
use crate::textures::{self, SkyCube};
use caustics_mips::CausticsMips;
pub use deck::EYE_CLEARANCE;
use flat::{FlatCaustics, FlatView, FlatWater};
use meshes::{pool_box, unit_sphere, water_grid, Mesh};
pub use variants::Features;
use variants::{PipelineTargets, ScenePipelines};

pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
/// Caustics map: red = light, green = light with the sphere's shadow.
pub const CAUSTICS_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rg16Float;
/// Caustics map where float render targets are missing: 8-bit, holding light / [`CAUSTICS_8BIT_SCALE`].
pub const CAUSTICS_FORMAT_8BIT: wgpu::TextureFormat = wgpu::TextureFormat::Rg8Unorm;
/// Light (relative to a calm surface) that the 8-bit caustics map's 1.0 stands for: focused
/// light up to 10x is kept in 1/255 steps of it, brighter lines are clipped (the tone curve
/// has flattened them by then anyway).
pub const CAUSTICS_8BIT_SCALE: f32 = 10.0;

/// Everything a frame's picture depends on besides the water state.
#[derive(Clone, Copy, Debug)]
pub struct View {
    pub view_proj: Mat4,
    /// Eye position (m).
    pub eye: Vec3,
    /// Unit vector towards the sun.
    pub sun: Vec3,
    pub sphere: Option<Sphere>,
    /// The rubber duck's pose, if it is in the pool.
    pub duck: Option<crate::physics::Pose>,
    pub caustics: bool,
    /// The optical models and their parameters (optics.rs).
    pub optics: Optics,
    /// The ambient waves to add to the simulated surface, at this frame's simulated time.
    pub ambient: AmbientView,
    /// Foam is drawn on the surface (from the map [`Renderer::upload_foam`] filled).
    pub foam: bool,
    /// A view of the simulation's textures drawn over the scene, if any.
    pub debug: Option<DebugView>,
    /// Fraction of the target's width and height the scene is drawn at (0.5-1; below 1 it
    /// is scaled up to the target).
    pub render_scale: f32,
    /// Flat water instead of (or beside) the ray-traced surface; `None`: ray-traced.
    pub flat: Option<FlatView>,
    /// Photographic exposure before the tone curve (EV: +1 doubles the light).
    pub exposure: f32,
    /// The pool is sunk in a paved deck (else the classic's cut-away box in the open).
    pub deck: bool,
}

/// The ambient waves as the shader takes them (see ambient.rs).
#[derive(Clone, Copy, Debug, Default)]
pub struct AmbientView {
    pub model: AmbientModel,
    /// Per wave (kx, kz in rad/m, amplitude in m, phase now).
    pub waves: [[f32; 4]; MAX_AMBIENT_WAVES],
    /// (waves, Gerstner's c, the FFT's choppiness, 0); see `AmbientWaves::uniform`.
    pub header: [f32; 4],
}

impl AmbientView {
    /// Whether the FFT ocean carries its water sideways (reads the displacement map).
    pub fn choppy(&self) -> bool {
        self.model == AmbientModel::Fft && self.header[2] > 0.0
    }
}

/// How the water surface reflects (see optics.rs).
#[derive(Clone, Copy, Debug, Default)]
pub struct Optics {
    pub fresnel: FresnelModel,
    pub specular: SpecularModel,
    /// Exponent of the sun highlight's cos^s.
    pub shininess: f32,
    /// Angular diameter of the sun's disk (degrees).
    pub sun_size: f32,
    /// The surface shows its Fresnel reflectance as grey instead of its colour (a debug view).
    pub show_reflectance: bool,
    /// Beer–Lambert absorption of the water per channel (1/m).
    pub absorption: Vec3,
    /// Light the water scatters towards the eye per channel (linear units); zero: none.
    pub scatter: Vec3,
    /// The scattered light is tinted by the path's angle (seed 002).
    pub view_colour: bool,
    /// Times the real spread of water's refractive index across colours (0: one index).
    pub dispersion: f32,
}

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

/// The `debug_view` value that shows the water's Fresnel reflectance: not a texture but a
/// variant of the surface shader ([`Optics::show_reflectance`]).
pub const REFLECTANCE_VIEW: i32 = 5;

impl DebugTexture {
    /// From the `debug_view` parameter's value (0 = none).
    pub fn from_param(value: f32) -> Option<Self> {
        match value.round() as i32 {
            1 => Some(Self::Height),
            2 => Some(Self::Normals),
            3 => Some(Self::Velocity),
            4 => Some(Self::Caustics),
            6 => Some(Self::Spectrum),
            _ => None,
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

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct SceneUniforms {
    view_proj: [[f32; 4]; 4],
    inv_view_proj: [[f32; 4]; 4],
    eye: [f32; 4],
    sun: [f32; 4],
    refracted_sun: [f32; 4],
    sphere: [f32; 4],
    pool: [f32; 4],
    water: [f32; 4],
    output: [f32; 4],
    optics: [f32; 4],
    absorption: [f32; 4],
    scatter: [f32; 4],
    ior: [f32; 4],
    duck_pose: [[f32; 4]; 4],
    duck_bound: [f32; 4],
    duck_parts: [[f32; 4]; 3 * duck::TRACED_PARTS.len()],
    ambient_header: [f32; 4],
    ambient_waves: [[f32; 4]; MAX_AMBIENT_WAVES],
    flat: [f32; 4],
    sun_light: [f32; 4],
    sky_light: [f32; 4],
}

/// Renderer settings fixed at creation.
#[derive(Clone, Copy, Debug)]
pub struct RenderSettings {
    /// Format of the colour targets it will draw into.
    pub target_format: wgpu::TextureFormat,
    /// Side of the caustics map in texels.
    pub caustics_size: u32,
    /// Quads per side of the water surface mesh. The fragment shader reads heights and
    /// normals per pixel, so this only shapes the surface's outline and parallax.
    pub surface_grid: u32,
    /// Whether the device can render (and blend) into float textures; without, the caustics
    /// map is 8-bit ([`CAUSTICS_FORMAT_8BIT`]).
    pub float_targets: bool,
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

/// Quads per side of the mesh projected into the caustics map for a simulation of
/// `sim_size` cells per side: one quad per two cells resolves the shortest waves that make
/// caustics while keeping the triangle count, which software rasterisers pay for, low.
pub fn caustics_grid(sim_size: u32) -> u32 {
    (sim_size / 2).clamp(64, 256)
}

/// The duck's traced parts as the scene shader takes them: per part its centre and semi-axes
/// in the duck's frame (m), and its colour.
fn duck_parts() -> [[f32; 4]; 3 * duck::TRACED_PARTS.len()] {
    let mut out = [[0.0; 4]; 3 * duck::TRACED_PARTS.len()];
    for (slots, part) in out.chunks_mut(3).zip(&duck::TRACED_PARTS) {
        slots[0] = part.shape.centre.extend(0.0).to_array();
        slots[1] = part.shape.radii.extend(0.0).to_array();
        slots[2] = part.colour.extend(1.0).to_array();
    }
    out
}

/// The caustics map and the water grid (see [`caustics_grid`]) drawn into it (its pipeline
/// is one of the [`ScenePipelines`]).
struct CausticsMap {
    /// The map and its mip chain.
    mips: CausticsMips,
    /// Texels per side.
    size: u32,
    /// Whether `view` holds light per colour channel (dispersion; an RGBA map).
    per_channel: bool,
    grid: Mesh,
    /// Quads per side of `grid`.
    grid_size: u32,
}

impl CausticsMap {
    fn new(device: &wgpu::Device, size: u32, format: wgpu::TextureFormat, sim_size: u32) -> Self {
        let grid_size = caustics_grid(sim_size);
        let (grid_vertices, grid_indices) = water_grid(grid_size);
        let grid = Mesh::new(device, "caustics grid", &grid_vertices, &grid_indices);
        Self { mips: CausticsMips::new(device, size, format), size, per_channel: false, grid, grid_size }
    }
}

struct DepthBuffer {
    view: wgpu::TextureView,
    size: (u32, u32),
}

/// Draws the pool scene. Holds the pipelines, meshes, textures and bind groups.
pub struct Renderer {
    settings: RenderSettings,
    uniforms: wgpu::Buffer,
    water_layout: wgpu::BindGroupLayout,
    textures_layout: wgpu::BindGroupLayout,
    /// Scene uniforms + water state, one per ping-pong texture.
    water_groups: [wgpu::BindGroup; 2],
    /// The same for the flat water's mirrored camera (its reflection texture).
    mirror_uniforms: wgpu::Buffer,
    mirror_groups: [wgpu::BindGroup; 2],
    flat: FlatWater,
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
    sky: FullscreenPass,
    /// The scene's pipelines per feature set drawn so far (see [`Features`]).
    variants: HashMap<Features, ScenePipelines>,
    /// The debug view's pass per texture shown so far.
    debug_passes: HashMap<(DebugTexture, AmbientModel, bool), FullscreenPass>,
    /// The water surface, both sides in one draw.
    grid: Mesh,
    pool_mesh: Mesh,
    deck_mesh: Mesh,
    sphere_mesh: Mesh,
    duck_mesh: Mesh,
    depth: Option<DepthBuffer>,
    upscale: Upscale,
}

/// The scene drawn at a reduced resolution and the pass that scales it up to the target.
struct Upscale {
    pass: FullscreenPass,
    layout: wgpu::BindGroupLayout,
    sampler: wgpu::Sampler,
    /// The reduced-resolution image, its size (pixels) and its bind group, once needed.
    image: Option<(wgpu::TextureView, (u32, u32), wgpu::BindGroup)>,
}

impl Upscale {
    fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        let vis = wgpu::ShaderStages::FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("upscale layout"),
            entries: &[gpu::filtered_texture_entry(0, vis), gpu::sampler_entry(1, vis)],
        });
        let pass = FullscreenPass::new(
            device,
            "upscale",
            &[include_str!("../../shaders/upscale.wgsl")],
            "fs_upscale",
            &[&layout],
            FullscreenTarget { format, blend: None, depth: None },
        );
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        Self { pass, layout, sampler, image: None }
    }

    /// The image to draw the scene into at `size` pixels (made again when the size changes).
    fn image(&mut self, device: &wgpu::Device, format: wgpu::TextureFormat, size: (u32, u32)) -> wgpu::TextureView {
        if self.image.as_ref().map(|i| i.1) != Some(size) {
            let texture = gpu::texture_2d(
                device,
                "scene at reduced resolution",
                size.0,
                size.1,
                1,
                1,
                format,
                wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
            );
            let view = texture.create_view(&Default::default());
            let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("upscale"),
                layout: &self.layout,
                entries: &[
                    wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&view) },
                    wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(&self.sampler) },
                ],
            });
            self.image = Some((view, size, group));
        }
        self.image.as_ref().expect("just made").0.clone()
    }

    /// Scales the image up over the whole of `target`.
    fn run(&self, encoder: &mut wgpu::CommandEncoder, target: &wgpu::TextureView) {
        if let Some((_, _, group)) = &self.image {
            self.pass.run(encoder, target, &[group]);
        }
    }
}

/// The textures and samplers of the scene passes' group 1, besides the caustics map.
struct SceneTextures {
    tiles: wgpu::TextureView,
    sky: wgpu::TextureView,
    fresnel_table: wgpu::TextureView,
    /// The foam amount per cell (R32Float), 1 x 1 until foam is first drawn.
    foam: (wgpu::Texture, wgpu::TextureView),
    /// The ambient waves' spectrum for the debug view (R32Float, log10 of the amplitude in m).
    spectrum: (wgpu::Texture, wgpu::TextureView),
    /// The flat water's dUdV map (flat.rs).
    dudv: wgpu::TextureView,
    clamp: wgpu::Sampler,
    repeat: wgpu::Sampler,
}

impl SceneTextures {
    fn bind_group(
        &self,
        device: &wgpu::Device,
        layout: &wgpu::BindGroupLayout,
        caustics: &wgpu::TextureView,
    ) -> wgpu::BindGroup {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("scene textures"),
            layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(caustics) },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(&self.tiles) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(&self.sky) },
                wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::Sampler(&self.clamp) },
                wgpu::BindGroupEntry { binding: 4, resource: wgpu::BindingResource::Sampler(&self.repeat) },
                wgpu::BindGroupEntry { binding: 5, resource: wgpu::BindingResource::TextureView(&self.fresnel_table) },
                wgpu::BindGroupEntry { binding: 6, resource: wgpu::BindingResource::TextureView(&self.foam.1) },
                wgpu::BindGroupEntry { binding: 7, resource: wgpu::BindingResource::TextureView(&self.spectrum.1) },
                wgpu::BindGroupEntry { binding: 8, resource: wgpu::BindingResource::TextureView(&self.dudv) },
            ],
        })
    }
}

/// A `size` x `size` foam map (R32Float, filled from the CPU).
fn foam_map(device: &wgpu::Device, size: u32) -> (wgpu::Texture, wgpu::TextureView) {
    let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
    let texture = gpu::texture_2d(device, "foam", size, size, 1, 1, wgpu::TextureFormat::R32Float, usage);
    let view = texture.create_view(&Default::default());
    (texture, view)
}

/// The scene uniforms with each of the water's two state textures and the ambient map (group
/// 0 of every scene pass).
fn water_bind_groups(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    uniforms: &wgpu::Buffer,
    water: &HeightField,
    ambient: &[wgpu::TextureView; 2],
) -> [wgpu::BindGroup; 2] {
    water.state().bind_groups(|view| {
        device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("scene + water"),
            layout,
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: uniforms.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(view) },
                wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(&ambient[0]) },
                wgpu::BindGroupEntry { binding: 3, resource: wgpu::BindingResource::TextureView(&ambient[1]) },
            ],
        })
    })
}

/// A `size` x `size` ambient map (RGBA32Float: height, slopes of the FFT ocean), filled from
/// the CPU or drawn by the GPU FFT.
fn ambient_map(device: &wgpu::Device, size: u32) -> (wgpu::Texture, wgpu::TextureView) {
    let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
    let texture = gpu::texture_2d(device, "ambient map", size, size, 1, 1, wgpu::TextureFormat::Rgba32Float, usage);
    let view = texture.create_view(&Default::default());
    (texture, view)
}

impl Renderer {
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, settings: RenderSettings, water: &HeightField) -> Self {
        let vis = wgpu::ShaderStages::VERTEX_FRAGMENT;
        let water_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("scene + water layout"),
            entries: &[
                gpu::uniform_entry(0, vis),
                gpu::float_texture_entry(1, vis),
                gpu::float_texture_entry(2, vis),
                gpu::float_texture_entry(3, vis),
            ],
        });
        let textures_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("scene textures layout"),
            entries: &[
                gpu::filtered_texture_entry(0, vis),
                gpu::filtered_texture_entry(1, vis),
                gpu::texture_entry(
                    2,
                    vis,
                    wgpu::TextureSampleType::Float { filterable: true },
                    wgpu::TextureViewDimension::Cube,
                ),
                gpu::sampler_entry(3, vis),
                gpu::sampler_entry(4, vis),
                gpu::float_texture_entry(5, vis),
                gpu::float_texture_entry(6, vis),
                gpu::float_texture_entry(7, vis),
                gpu::filtered_texture_entry(8, vis),
            ],
        });
        let uniforms = gpu::uniform_buffer(device, "scene uniforms", &<SceneUniforms as bytemuck::Zeroable>::zeroed());
        let cpu_ambient = [ambient_map(device, 1), ambient_map(device, 1)];
        let ambient_views = [cpu_ambient[0].1.clone(), cpu_ambient[1].1.clone()];
        let water_groups = water_bind_groups(device, &water_layout, &uniforms, water, &ambient_views);
        let mirror_uniforms =
            gpu::uniform_buffer(device, "mirrored scene uniforms", &<SceneUniforms as bytemuck::Zeroable>::zeroed());
        let mirror_groups = water_bind_groups(device, &water_layout, &mirror_uniforms, water, &ambient_views);
        let (caustics_format, _) = settings.caustics_format();
        let caustics = CausticsMap::new(device, settings.caustics_size, caustics_format, water.size());
        let sky_cube = SkyCube::new(device);
        let tiles = textures::create_tile_texture(device, queue);
        let sampler = |address: wgpu::AddressMode| {
            device.create_sampler(&wgpu::SamplerDescriptor {
                address_mode_u: address,
                address_mode_v: address,
                address_mode_w: address,
                mag_filter: wgpu::FilterMode::Linear,
                min_filter: wgpu::FilterMode::Linear,
                // Nearest mip level for the repeating tiles: the level is chosen per pixel
                // already (tile_lod), and trilinear filtering costs software rasterisers twice
                // the texel reads. Linear for the clamped maps: the caustics map is read
                // between its levels (caustics_at), the others have one level.
                mipmap_filter: if address == wgpu::AddressMode::Repeat {
                    wgpu::MipmapFilterMode::Nearest
                } else {
                    wgpu::MipmapFilterMode::Linear
                },
                ..Default::default()
            })
        };
        let scene_textures = SceneTextures {
            tiles: tiles.create_view(&Default::default()),
            sky: sky_cube.view(),
            fresnel_table: textures::create_fresnel_table(device, queue).create_view(&Default::default()),
            foam: foam_map(device, 1),
            spectrum: {
                let size = SPECTRUM_IMAGE_SIZE as u32;
                let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
                let texture =
                    gpu::texture_2d(device, "ambient spectrum", size, size, 1, 1, wgpu::TextureFormat::R32Float, usage);
                let view = texture.create_view(&Default::default());
                (texture, view)
            },
            dudv: flat::dudv_texture(device, queue),
            clamp: sampler(wgpu::AddressMode::ClampToEdge),
            repeat: sampler(wgpu::AddressMode::Repeat),
        };
        let textures_group = scene_textures.bind_group(device, &textures_layout, &caustics.mips.view);

        let layouts = [&water_layout, &textures_layout];
        let format = settings.target_format;
        let sky = FullscreenPass::new(
            device,
            "sky",
            &[&shaders::scene_prelude(Features::default()), shaders::SKY],
            "fs_sky",
            &layouts,
            FullscreenTarget { format, blend: None, depth: Some(DEPTH_FORMAT) },
        );
        let (grid_vertices, grid_indices) = water_grid(settings.surface_grid.clamp(8, 1024));
        let (pool_vertices, pool_indices) = pool_box();
        let (sphere_vertices, sphere_indices) = unit_sphere(24, 48);
        let (duck_vertices, duck_indices) = duck::mesh();
        Self {
            settings,
            uniforms,
            water_layout,
            textures_layout,
            water_groups,
            mirror_uniforms,
            mirror_groups,
            flat: FlatWater::new(device, settings.target_format),
            ambient_views,
            cpu_ambient,
            textures_group,
            scene_textures,
            caustics,
            sky_cube,
            sky,
            variants: HashMap::new(),
            debug_passes: HashMap::new(),
            grid: Mesh::new(device, "water grid", &grid_vertices, &grid_indices),
            pool_mesh: Mesh::new(device, "pool", &pool_vertices, &pool_indices),
            deck_mesh: {
                let (vertices, indices) = deck::deck_ring();
                Mesh::new(device, "deck", &vertices, &indices)
            },
            sphere_mesh: Mesh::new(device, "sphere", &sphere_vertices, &sphere_indices),
            duck_mesh: Mesh::new(device, "duck", &duck_vertices, &duck_indices),
            depth: None,
            upscale: Upscale::new(device, settings.target_format),
        }
    }

    /// The pipelines for `features`, built the first time they are asked for. Building
    /// compiles five shaders; do it ahead (see [`Renderer::prepare_variant`]) to keep it out
    /// of a frame that must be quick.
    fn variant(&mut self, device: &wgpu::Device, features: Features) -> &ScenePipelines {
        let targets = PipelineTargets {
            format: self.settings.target_format,
            caustics_format: self.settings.caustics_format_for(features.dispersion).0,
            water_layout: &self.water_layout,
            textures_layout: &self.textures_layout,
        };
        self.variants.entry(features).or_insert_with(|| ScenePipelines::new(device, features, &targets))
    }

    /// Builds the pipelines of a feature set now, if they are not built yet.
    pub fn prepare_variant(&mut self, device: &wgpu::Device, features: Features) {
        self.variant(device, features);
    }

    /// Feature sets whose pipelines are built.
    pub fn variants_built(&self) -> usize {
        self.variants.len()
    }

    /// The debug view's pass for `texture`, seeing the water with `ambient` waves added.
    fn debug_pass(&mut self, device: &wgpu::Device, texture: DebugTexture, ambient: AmbientView) -> &FullscreenPass {
        let layouts = [&self.water_layout, &self.textures_layout];
        let format = self.settings.target_format;
        let key = (texture, ambient.model, ambient.choppy());
        self.debug_passes.entry(key).or_insert_with(|| {
            let features = Features { ambient: ambient.model, choppy: ambient.choppy(), ..Features::default() };
            let constants = format!("const DEBUG_TEXTURE: i32 = {};\n", texture as i32);
            FullscreenPass::new(
                device,
                "debug view",
                &[&constants, &shaders::scene_prelude(features), shaders::DEBUG_VIEW],
                "fs_debug",
                &layouts,
                FullscreenTarget { format, blend: None, depth: None },
            )
        })
    }

    /// Rebinds the water state textures (after the heightfield was replaced).
    /// Points the renderer at another heightfield (after a change of resolution); the caustics
    /// mesh follows the new simulation size.
    pub fn rebind_water(&mut self, device: &wgpu::Device, water: &HeightField) {
        let grid_size = caustics_grid(water.size());
        if grid_size != self.caustics.grid_size {
            let (vertices, indices) = water_grid(grid_size);
            self.caustics.grid = Mesh::new(device, "caustics grid", &vertices, &indices);
            self.caustics.grid_size = grid_size;
        }
        self.bind_water(device, water);
    }

    /// Makes the scene passes' group 0 (for the camera and the mirrored one) for `water`.
    fn bind_water(&mut self, device: &wgpu::Device, water: &HeightField) {
        self.water_groups = water_bind_groups(device, &self.water_layout, &self.uniforms, water, &self.ambient_views);
        self.mirror_groups =
            water_bind_groups(device, &self.water_layout, &self.mirror_uniforms, water, &self.ambient_views);
    }

    /// Reads the FFT ocean's surface and displacement from `views` (the GPU ocean's outputs)
    /// from now on.
    pub fn use_ambient_views(&mut self, device: &wgpu::Device, water: &HeightField, views: [&wgpu::TextureView; 2]) {
        self.ambient_views = views.map(|v| v.clone());
        self.bind_water(device, water);
    }

    /// Copies the FFT ocean's surface and, with choppiness, its displacement (`size`² texels
    /// each, from `Ocean::surface` and `Ocean::displacement`) into the ambient maps the water
    /// is read with (remade, and `water`'s groups rebound, when the size changes).
    pub fn upload_ambient(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        water: &HeightField,
        size: u32,
        maps: [Option<&[[f32; 4]]>; 2],
    ) {
        let cpu_views = [self.cpu_ambient[0].1.clone(), self.cpu_ambient[1].1.clone()];
        if self.cpu_ambient[0].0.width() != size || self.ambient_views != cpu_views {
            if self.cpu_ambient[0].0.width() != size {
                self.cpu_ambient = [ambient_map(device, size), ambient_map(device, size)];
            }
            let views = [self.cpu_ambient[0].1.clone(), self.cpu_ambient[1].1.clone()];
            self.use_ambient_views(device, water, [&views[0], &views[1]]);
        }
        for (map, texels) in self.cpu_ambient.iter().zip(maps) {
            let Some(texels) = texels else { continue };
            gpu::write_texture_2d(queue, &map.0, 0, bytemuck::cast_slice(texels));
        }
    }

    /// Side (texels) of the caustics map for a frame drawn at `render_scale`: the map's texels
    /// follow the screen's pixels, so a frame at half resolution also lights the pool from a
    /// map of half the side (at least 128), a quarter of the work.
    pub fn caustics_size(&self, render_scale: f32) -> u32 {
        let side = (self.settings.caustics_size as f32 * render_scale.clamp(0.25, 1.0)).round() as u32;
        side.clamp(128.min(self.settings.caustics_size), self.settings.caustics_size)
    }

    /// Copies the foam amounts into the foam map the surface reads (remade, and rebound, when
    /// the foam's grid changes size). Call before [`Renderer::encode_scene`] when foam is on.
    pub fn upload_foam(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, foam: &Foam) {
        let size = foam.size();
        if self.scene_textures.foam.0.width() != size {
            self.scene_textures.foam = foam_map(device, size);
            self.textures_group =
                self.scene_textures.bind_group(device, &self.textures_layout, &self.caustics.mips.view);
        }
        gpu::write_texture_2d(queue, &self.scene_textures.foam.0, 0, bytemuck::cast_slice(foam.amount()));
    }

    /// Copies the ambient waves' spectrum image (`AmbientWaves::spectrum_image`) for the
    /// spectrum debug view.
    pub fn upload_spectrum(&self, queue: &wgpu::Queue, image: &[f32]) {
        gpu::write_texture_2d(queue, &self.scene_textures.spectrum.0, 0, bytemuck::cast_slice(image));
    }

    /// Makes the caustics map `size` texels per side, with light per colour channel or not
    /// (rebinding it), if it is not already.
    fn resize_caustics(&mut self, device: &wgpu::Device, size: u32, per_channel: bool) {
        if size != self.caustics.size || per_channel != self.caustics.per_channel {
            self.caustics.mips = CausticsMips::new(device, size, self.settings.caustics_format_for(per_channel).0);
            self.caustics.size = size;
            self.caustics.per_channel = per_channel;
            self.textures_group =
                self.scene_textures.bind_group(device, &self.textures_layout, &self.caustics.mips.view);
        }
    }

    /// Writes this frame's uniforms and repaints the sky if the sun moved.
    /// Call once per submission, before [`Renderer::encode_caustics`] and [`Renderer::encode_scene`].
    pub fn prepare(
        &mut self,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        view: &View,
        water: &HeightField,
    ) {
        self.sky_cube.update(queue, encoder, view.sun);
        let daylight = *self.sky_cube.daylight();
        let sphere = view.sphere.map_or([0.0; 4], |s| [s.centre.x, s.centre.y, s.centre.z, s.radius]);
        let refracted = scene::refracted_sun(view.sun);
        let n = water.size() as f32;
        let u = SceneUniforms {
            view_proj: view.view_proj.to_cols_array_2d(),
            inv_view_proj: view.view_proj.inverse().to_cols_array_2d(),
            eye: view.eye.extend(1.0).to_array(),
            sun: [view.sun.x, view.sun.y, view.sun.z, 0.0],
            refracted_sun: refracted.extend(0.0).to_array(),
            sphere,
            pool: [scene::HALF_WIDTH, scene::DEPTH, scene::RIM, 0.0],
            water: [n, 1.0 / n, if view.caustics { 1.0 } else { 0.0 }, self.settings.caustics_format().1],
            output: [
                if self.settings.target_format.is_srgb() { 0.0 } else { 1.0 },
                view.debug.map_or(0.0, |d| d.texture as u32 as f32),
                0.0,
                0.0,
            ],
            optics: {
                let (edge, core) = optics::sun_disk_cosines(view.optics.sun_size);
                [view.optics.shininess, edge, core, 0.0]
            },
            absorption: view.optics.absorption.extend(0.0).to_array(),
            scatter: view.optics.scatter.extend(0.0).to_array(),
            ior: {
                let [r, g, b] = optics::channel_iors(view.optics.dispersion);
                [r, g, b, view.optics.dispersion]
            },
            duck_pose: view
                .duck
                .map_or(Mat4::IDENTITY, |p| Mat4::from_rotation_translation(p.rotation, p.position))
                .to_cols_array_2d(),
            duck_bound: view.duck.map_or([0.0; 4], |p| p.position.extend(duck::bounding_radius()).to_array()),
            duck_parts: duck_parts(),
            ambient_header: view.ambient.header,
            ambient_waves: view.ambient.waves,
            flat: view.flat.map_or([0.0; 4], |f| f.uniform()),
            sun_light: daylight.sun_light.extend(2f32.powf(view.exposure)).to_array(),
            sky_light: daylight.ambient.extend(if view.deck { 1.0 } else { 0.0 }).to_array(),
        };
        queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&u));
        if let Some(f) = flat_shown(view) {
            // The mirrored camera: everything it sees is above the water, so nothing is dimmed
            // by water on the way (no absorption, no scattering).
            let mirrored = view.view_proj * flat::mirror(f.plane);
            let eye = view.eye * glam::Vec3::new(1.0, -1.0, 1.0) + glam::Vec3::new(0.0, 2.0 * f.plane, 0.0);
            let m = SceneUniforms {
                view_proj: mirrored.to_cols_array_2d(),
                inv_view_proj: mirrored.inverse().to_cols_array_2d(),
                eye: eye.extend(1.0).to_array(),
                absorption: [0.0; 4],
                scatter: [0.0; 4],
                ..u
            };
            queue.write_buffer(&self.mirror_uniforms, 0, bytemuck::bytes_of(&m));
        }
    }

    /// Projects the water grid along the refracted sunlight into the caustics map.
    pub fn encode_caustics(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        view: &View,
        water: &HeightField,
    ) {
        let features = Features::of(view);
        self.resize_caustics(device, self.caustics_size(view.render_scale), features.dispersion);
        // The ray-traced part reads the map if caustics are on, flat water if it uses the real ones.
        let traced_shown = flat_shown(view).is_none_or(|f| f.mode == flat::RenderMode::Split && f.split < 1.0);
        let flat_reads = flat_shown(view).is_some_and(|f| f.caustics == FlatCaustics::Real);
        if !((view.caustics && traced_shown) || flat_reads) {
            return;
        }
        self.variant(device, features);
        let mut pass = gpu::colour_pass(
            encoder,
            "caustics",
            &self.caustics.mips.target,
            wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
        );
        pass.set_bind_group(0, Some(&self.water_groups[water.state().current()]), &[]);
        // One draw, or with dispersion one per colour channel (each with its own index).
        for pipeline in &self.variants[&features].caustics {
            pass.set_pipeline(pipeline);
            self.caustics.grid.draw(&mut pass);
        }
        drop(pass);
        self.caustics.mips.encode(encoder);
    }

    fn depth_view(&mut self, device: &wgpu::Device, size: (u32, u32)) -> &wgpu::TextureView {
        if self.depth.as_ref().map(|d| d.size) != Some(size) {
            let texture = gpu::texture_2d(
                device,
                "depth",
                size.0.max(1),
                size.1.max(1),
                1,
                1,
                DEPTH_FORMAT,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            );
            self.depth = Some(DepthBuffer { view: texture.create_view(&Default::default()), size });
        }
        &self.depth.as_ref().expect("depth buffer just made").view
    }

    /// Draws sky, pool, sphere and water into `target` (of `size` pixels) at the view's
    /// render scale, the split view's divider and the debug view over them.
    pub fn encode_scene(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        size: (u32, u32),
        view: &View,
        water: &HeightField,
    ) {
        let scale = view.render_scale.clamp(0.25, 1.0);
        if scale < 1.0 {
            let scaled = |side: u32| ((side as f32 * scale).round() as u32).max(1);
            let scaled = (scaled(size.0), scaled(size.1));
            let image = self.upscale.image(device, self.settings.target_format, scaled);
            self.draw_picture(device, encoder, &image, scaled, view, water);
            self.upscale.run(encoder, target);
        } else {
            self.draw_picture(device, encoder, target, size, view, water);
        }
        if let Some(f) = flat_shown(view).filter(|f| f.mode == flat::RenderMode::Split) {
            self.flat.draw_divider(encoder, target, size, f.divider(size.0));
        }
        if let Some(debug) = view.debug {
            self.debug_pass(device, debug.texture, view.ambient);
            let mut pass = gpu::colour_pass(encoder, "debug view", target, wgpu::LoadOp::Load);
            let [x, y, w, h] = debug.viewport(size);
            pass.set_viewport(x, y, w, h, 0.0, 1.0);
            let water_group = &self.water_groups[water.state().current()];
            self.debug_passes[&(debug.texture, view.ambient.model, view.ambient.choppy())]
                .draw(&mut pass, &[water_group, &self.textures_group]);
        }
    }

    /// The scene at `size` pixels: ray-traced, flat, or flat left of the divider and
    /// ray-traced right of it (two passes on disjoint pixels, so each is shaded once).
    fn draw_picture(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        size: (u32, u32),
        view: &View,
        water: &HeightField,
    ) {
        let Some(f) = flat_shown(view) else {
            self.draw_scene(device, encoder, target, size, view, water, None, [0, 0, size.0, size.1]);
            return;
        };
        let divider = f.divider(size.0);
        if divider > 0 {
            self.encode_flat_textures(device, encoder, view, water, size, &f);
            self.draw_scene(device, encoder, target, size, view, water, Some(&f), [0, 0, divider, size.1]);
        }
        if divider < size.0 {
            self.draw_scene(device, encoder, target, size, view, water, None, [divider, 0, size.0 - divider, size.1]);
        }
    }

    /// The flat water's reflection texture (for tests: what the mirrored camera drew), once
    /// flat water has been drawn.
    #[doc(hidden)]
    pub fn flat_reflection_texture(&self) -> Option<&wgpu::Texture> {
        self.flat.targets.as_ref().map(|t| &t.reflection)
    }

    /// Draws the flat water's reflection (mirrored camera, above the plane, with the sky) and
    /// refraction (below the plane) textures for a scene of `size` pixels. In a split view only
    /// the columns the flat part can read: left of the divider plus the largest shift.
    fn encode_flat_textures(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        view: &View,
        water: &HeightField,
        size: (u32, u32),
        f: &FlatView,
    ) {
        let resolution = f.resolution.clamp(0.25, 1.0);
        let side = |s: u32| ((s as f32 * resolution).round() as u32).max(1);
        let texture_size = (side(size.0), side(size.1));
        let divider = f.divider(size.0);
        let reach = if divider < size.0 {
            let x = divider as f32 / size.0 as f32 + f.strength;
            ((x * texture_size.0 as f32).ceil() as u32 + 2).min(texture_size.0)
        } else {
            texture_size.0
        };
        let lit = f.lit_features(Features::of(view));
        let (reflection, refraction) = (Features { clip: 1, ..lit }, Features { clip: -1, ..lit });
        self.variant(device, reflection);
        self.variant(device, refraction);
        let targets = self.flat.targets(device, self.settings.target_format, texture_size);
        let (reflection_view, refraction_view, depth) =
            (targets.reflection_view.clone(), targets.refraction_view.clone(), targets.depth.clone());
        let current = water.state().current();
        let passes = [
            ("flat water reflection", &reflection_view, reflection, &self.mirror_groups[current]),
            ("flat water refraction", &refraction_view, refraction, &self.water_groups[current]),
        ];
        for (label, colour, features, group) in passes {
            // Cleared to alpha 0: "nothing here" for the water reading the refraction.
            let mut pass = begin_scene_pass(encoder, label, colour, &depth, Some(wgpu::Color::TRANSPARENT));
            pass.set_scissor_rect(0, 0, reach, texture_size.1);
            pass.set_bind_group(0, Some(group), &[]);
            pass.set_bind_group(1, Some(&self.textures_group), &[]);
            self.draw_deck(&mut pass, features, view);
            self.draw_solids(&mut pass, features, view);
            if features.clip > 0 {
                self.sky.draw(&mut pass, &[group, &self.textures_group]);
            }
        }
    }

    /// A scene pass over the pixels `rect` (x, y, width, height) of `target`: the water
    /// surface (ray-traced, or flat with `flat`), objects and pool front to back (early depth
    /// testing skips what the water and objects hide), then the sky where nothing else was
    /// drawn. The pass starting at column 0 clears the target.
    #[allow(clippy::too_many_arguments)]
    fn draw_scene(
        &mut self,
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        size: (u32, u32),
        view: &View,
        water: &HeightField,
        flat: Option<&FlatView>,
        rect: [u32; 4],
    ) {
        let depth = self.depth_view(device, size).clone();
        // Everything on the flat side is lit as its refraction texture is (FlatView::lit_features).
        let features = flat.map_or(Features::of(view), |f| f.lit_features(Features::of(view)));
        let regions = if flat.is_some() { None } else { variants::surface_regions(view, size) };
        self.variant(device, features);
        for (_, needs) in regions.iter().flatten() {
            self.variant(device, *needs);
        }
        if flat.is_some() {
            let targets = PipelineTargets {
                format: self.settings.target_format,
                caustics_format: self.settings.caustics_format_for(features.dispersion).0,
                water_layout: &self.water_layout,
                textures_layout: &self.textures_layout,
            };
            self.flat.prepare_pipeline(device, features, &targets);
        }
        let clear = (rect[0] == 0).then_some(wgpu::Color::BLACK);
        let mut pass = begin_scene_pass(encoder, "scene", target, &depth, clear);
        let pipelines = &self.variants[&features];
        let water_group = &self.water_groups[water.state().current()];
        pass.set_bind_group(0, Some(water_group), &[]);
        pass.set_bind_group(1, Some(&self.textures_group), &[]);
        let [x, y, w, h] = rect;
        pass.set_scissor_rect(x, y, w, h);
        self.draw_deck(&mut pass, features, view);
        match (flat, regions) {
            (Some(_), _) => {
                let group = &self.flat.targets.as_ref().expect("flat textures are drawn first").group;
                pass.set_pipeline(self.flat.pipeline(features));
                pass.set_bind_group(2, Some(group), &[]);
                self.grid.draw(&mut pass);
            }
            // The objects are traced only where the water can show them (see surface_regions).
            (None, Some(regions)) => {
                for (region, needs) in regions {
                    if let Some([x, y, w, h]) = overlap(region, rect) {
                        pass.set_pipeline(&self.variants[&needs].surface);
                        pass.set_scissor_rect(x, y, w, h);
                        self.grid.draw(&mut pass);
                    }
                }
                pass.set_scissor_rect(x, y, w, h);
            }
            (None, None) => {
                pass.set_pipeline(&pipelines.surface);
                self.grid.draw(&mut pass);
            }
        }
        self.draw_solids(&mut pass, features, view);
        self.sky.draw(&mut pass, &[water_group, &self.textures_group]);
    }

    /// Draws the deck around the pool if the view has one. Drawn first: where it hides the
    /// water's cut-away side, those costly fragments then fail the depth test.
    fn draw_deck(&self, pass: &mut wgpu::RenderPass<'_>, features: Features, view: &View) {
        if view.deck {
            pass.set_pipeline(&self.variants[&features].deck);
            self.deck_mesh.draw(pass);
        }
    }

    /// Draws the sphere and the duck (those the view has) and the pool with the pipelines of
    /// `features`, front to back.
    fn draw_solids(&self, pass: &mut wgpu::RenderPass<'_>, features: Features, view: &View) {
        let pipelines = &self.variants[&features];
        if view.sphere.is_some() {
            pass.set_pipeline(&pipelines.sphere);
            self.sphere_mesh.draw(pass);
        }
        if view.duck.is_some() {
            pass.set_pipeline(&pipelines.duck);
            self.duck_mesh.draw(pass);
        }
        pass.set_pipeline(&pipelines.pool);
        self.pool_mesh.draw(pass);
    }
}

/// The flat water settings if flat water is drawn this frame: flat or split mode with the
/// camera above the plane (flat water is an above-water technique; under it the ray tracer
/// draws everything).
pub fn flat_shown(view: &View) -> Option<FlatView> {
    view.flat.filter(|f| f.mode != flat::RenderMode::RayTraced && view.eye.y > f.plane)
}

/// The part two rectangles (x, y, width, height) share, if any.
fn overlap(a: [u32; 4], b: [u32; 4]) -> Option<[u32; 4]> {
    let (x0, y0) = (a[0].max(b[0]), a[1].max(b[1]));
    let (x1, y1) = ((a[0] + a[2]).min(b[0] + b[2]), (a[1] + a[3]).min(b[1] + b[3]));
    (x1 > x0 && y1 > y0).then(|| [x0, y0, x1 - x0, y1 - y0])
}

/// A render pass on a colour and a depth target, clearing the colour (to `clear`) or keeping
/// it, and clearing the depth.
fn begin_scene_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    label: &str,
    colour: &wgpu::TextureView,
    depth: &wgpu::TextureView,
    clear: Option<wgpu::Color>,
) -> wgpu::RenderPass<'e> {
    let load = clear.map_or(wgpu::LoadOp::Load, wgpu::LoadOp::Clear);
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some(label),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view: colour,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations { load, store: wgpu::StoreOp::Store },
        })],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: depth,
            depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Discard }),
            stencil_ops: None,
        }),
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    })
}
