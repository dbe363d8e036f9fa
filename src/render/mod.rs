//! The renderer: caustics map, then one scene pass of sky, pool, sphere and the water
//! surface (from above and from below) into any colour target.

pub(crate) mod caustics;
mod caustics_mips;
mod debug_choice;
pub(crate) mod debug_view;
pub(crate) mod deck;
mod features;
pub mod flat;
pub(crate) mod glaze;
mod meshes;
mod passes;
mod regions;
mod render_mode;
mod resources;
pub mod scene_parts;
mod shaders;
/// The ray helpers without bindings (`shaders/common.wgsl`), for other scenes' shaders.
pub use shaders::COMMON;
mod uniforms;
mod upscale;
mod variants;
mod view;

use std::collections::HashMap;

use crate::ambient::AmbientModel;
use crate::gpu::{self, FullscreenPass, FullscreenTarget};
use crate::sim::HeightField;
use crate::textures::SkyCube;
use caustics::CausticsMap;
pub use caustics::{caustics_grid, CAUSTICS_8BIT_SCALE, CAUSTICS_FORMAT, CAUSTICS_FORMAT_8BIT};
pub use debug_choice::{DebugChoice, DebugTexture, DebugView};
pub use deck::{Setting, EYE_CLEARANCE};
pub use features::Features;
use flat::FlatWater;
use meshes::{pool_box, pool_walls, GridMesh, Mesh};
pub use render_mode::{Distortion, FlatCaustics, RenderMode};
use resources::{ambient_map, water_bind_groups, DepthBuffer, SceneTextures};
use uniforms::SceneUniforms;
use upscale::Upscale;
use variants::{PipelineTargets, ScenePipelines, VariantBuild};
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
    /// Quads per side of the water surface mesh. The fragment shader reads heights and
    /// normals per pixel, so this only shapes the surface's outline and parallax.
    pub surface_grid: u32,
    /// Whether the device can render (and blend) into float textures; without, the caustics
    /// map is 8-bit ([`CAUSTICS_FORMAT_8BIT`]).
    pub float_targets: bool,
    /// The box of the pool it draws (m).
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
    /// The deck's haze colour (`deck::horizon_fit`) and the sun it was fitted for: refitted
    /// only when the sun moves, as the cube is repainted.
    horizon: (glam::Vec3, [[f32; 4]; deck::HORIZON_TERMS]),
    sky: FullscreenPass,
    /// The scene's pipelines per feature set drawn so far (see [`Features`]).
    variants: HashMap<Features, ScenePipelines>,
    /// Feature sets whose pipelines are being built ahead of their first frame, one pipeline
    /// at a time ([`Renderer::build_ahead`]).
    building: HashMap<Features, VariantBuild>,
    /// The debug view's pass per texture shown so far.
    debug_passes: HashMap<(DebugTexture, AmbientModel, bool), FullscreenPass>,
    /// The water surface, both sides in one draw.
    grid: GridMesh,
    pool_mesh: Mesh,
    /// The pool's walls above [`deck::DRY_BAND_BOTTOM`]: all of the pool a scene pass with the
    /// deck sees directly.
    dry_band_mesh: Mesh,
    deck_mesh: Mesh,
    /// Each kind of body's mesh, in the order of `bodies::KINDS`.
    body_meshes: Vec<Mesh>,
    depth: Option<DepthBuffer>,
    upscale: Upscale,
    /// The water surface traces the objects only in their regions (`regions::surface_regions`);
    /// off, everywhere (for tests: the regions must not change the picture).
    object_regions: bool,
    /// The tiles' mean albedo (linear RGB), for the light the floor sends back up.
    floor_albedo: glam::Vec3,
    /// The bodies' outlines are blended in (`BodyKind::edge`), and the water at their
    /// waterlines (`shaders/water.wgsl`); off for tests to compare with.
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
        let scene_textures = SceneTextures::new(device, queue, &sky_cube, tile_mips);
        let textures_group = scene_textures.bind_group(device, &textures_layout, &caustics.mips.view);

        let layouts = [&water_layout, &textures_layout];
        let format = settings.target_format;
        let sky = FullscreenPass::new(
            device,
            "sky",
            &[&shaders::scene_prelude(Features::default(), format), shaders::SKY],
            "fs_sky",
            &layouts,
            FullscreenTarget { format, blend: None, depth: Some(DEPTH_FORMAT) },
        );
        let (pool_vertices, pool_indices) = pool_box(settings.pool);
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
            horizon: (glam::Vec3::ZERO, deck::horizon_fit(sky_cube.daylight())),
            sky_cube,
            sky,
            variants: HashMap::new(),
            building: HashMap::new(),
            debug_passes: HashMap::new(),
            grid: GridMesh::new(device, settings.surface_grid.clamp(8, 1024)),
            pool_mesh: Mesh::new(device, "pool", &pool_vertices, &pool_indices),
            dry_band_mesh: {
                let (vertices, indices) = pool_walls(deck::DRY_BAND_BOTTOM, false, settings.pool);
                Mesh::new(device, "pool's dry band", &vertices, &indices)
            },
            deck_mesh: {
                let (vertices, indices) = deck::deck_ring(settings.pool);
                Mesh::new(device, "deck", &vertices, &indices)
            },
            body_meshes: crate::bodies::KINDS
                .iter()
                .map(|kind| {
                    let mesh = (kind.mesh)();
                    Mesh::new(device, kind.name, &mesh.vertices, &mesh.indices)
                })
                .collect(),
            depth: None,
            upscale: Upscale::new(device, settings.target_format),
            object_regions: true,
            floor_albedo: crate::textures::tile_mean_albedo(tile_mips),
            body_outlines: true,
        }
    }

    /// The pipelines for `features`, built the first time they are asked for (finished, if
    /// [`Renderer::build_ahead`] had started them).
    fn variant(&mut self, device: &wgpu::Device, features: Features) -> &ScenePipelines {
        if !self.variants.contains_key(&features) {
            let build = self
                .building
                .remove(&features)
                .unwrap_or_else(|| VariantBuild::new(features, self.settings.target_format));
            let pipelines = build.finish(device, &self.pipeline_targets(features));
            self.variants.insert(features, pipelines);
        }
        &self.variants[&features]
    }

    /// Builds the flat water's pipeline for `features` if it is not built yet.
    fn prepare_flat_pipeline(&mut self, device: &wgpu::Device, features: Features) {
        // The targets borrow the layouts field by field, beside the flat water's own borrow.
        let targets = PipelineTargets {
            format: self.settings.target_format,
            caustics_format: self.settings.caustics_format_for(features.dispersion).0,
            water_layout: &self.water_layout,
            textures_layout: &self.textures_layout,
        };
        self.flat.prepare_pipeline(device, features, &targets);
    }

    fn pipeline_targets(&self, features: Features) -> PipelineTargets<'_> {
        PipelineTargets {
            format: self.settings.target_format,
            caustics_format: self.settings.caustics_format_for(features.dispersion).0,
            water_layout: &self.water_layout,
            textures_layout: &self.textures_layout,
        }
    }

    /// Builds the pipelines of a feature set now, if they are not built yet.
    pub fn prepare_variant(&mut self, device: &wgpu::Device, features: Features) {
        self.variant(device, features);
    }

    /// Builds one pipeline of those a frame of `view` at `size` pixels will draw with, if
    /// any is missing; true when none is. A shell that must not hold a browser's thread for
    /// long calls it once per task before the first frame (a frame builds what is missing at
    /// once: on WebGL2 without a GPU, a second or more).
    pub fn build_ahead(&mut self, device: &wgpu::Device, view: &View, size: (u32, u32)) -> bool {
        let Some(features) = self.variants_drawn(view, size).into_iter().find(|f| !self.variants.contains_key(f))
        else {
            // Then the flat water's own pipeline, if the frame shows flat water (as
            // `draw_picture` decides: some columns left of the divider).
            let flat = flat_shown(view).filter(|f| f.divider(self.scaled_size(view, size).0) > 0);
            let Some(lit) = flat.map(|f| f.lit_features(view.features())) else {
                return true;
            };
            if self.flat.has_pipeline(lit) {
                return true;
            }
            self.prepare_flat_pipeline(device, lit);
            return false;
        };
        let mut build =
            self.building.remove(&features).unwrap_or_else(|| VariantBuild::new(features, self.settings.target_format));
        if build.step(device, &self.pipeline_targets(features)) {
            let pipelines = build.finish(device, &self.pipeline_targets(features));
            self.variants.insert(features, pipelines);
        } else {
            self.building.insert(features, build);
        }
        false
    }

    /// Whether the water surface traces the objects only where it can show them (the
    /// default) or everywhere (the reference that tests compare the regions with).
    #[doc(hidden)]
    pub fn set_object_regions(&mut self, on: bool) {
        self.object_regions = on;
    }

    /// Whether the bodies' outlines and the water at their waterlines are blended in (the
    /// default) or left as the pixels draw them, each wholly in or out (for tests to compare
    /// with).
    #[doc(hidden)]
    pub fn set_body_outlines(&mut self, on: bool) {
        self.body_outlines = on;
    }

    /// Pipeline sets built: feature sets of the scene's pipelines and of the flat water's.
    pub fn pipeline_sets_built(&self) -> usize {
        self.variants.len() + self.flat.pipelines_built()
    }
}
