//! The pool's passes: the caustics map, then one scene pass of the deck, the bodies, the water
//! surface (from above and from below), the pool's box and the sky, ray-traced, flat or split,
//! and the debug view over them; drawn on the renderer's shared uniforms, textures and targets.

mod caustics;
mod debug_view;
mod flat_water;
mod meshes;
mod passes;
mod regions;
mod shaders;
mod variants;

use std::collections::HashMap;

use crate::ambient::AmbientModel;
use crate::gpu::{FullscreenPass, FullscreenTarget};
use crate::render::scene_parts::{water_bind_groups, Mesh, DEPTH_FORMAT};
use crate::render::{deck, flat, flat_shown, DebugTexture, Features, Renderer, View};
use crate::sim::HeightField;
use caustics::CausticsGrid;
use flat_water::FlatWater;
use meshes::{pool_box, pool_walls, GridMesh};
use variants::{PipelineTargets, ScenePipelines, VariantBuild};

/// The pool's pipelines, meshes and passes.
pub struct PoolPasses {
    /// The flat water's mirrored camera: its uniforms and its group 0 with each of the water's
    /// state textures, made again when the renderer's are ([`Renderer::water_binding`]).
    mirror_uniforms: wgpu::Buffer,
    mirror_groups: [wgpu::BindGroup; 2],
    mirror_binding: u64,
    flat: FlatWater,
    sky: FullscreenPass,
    /// The scene's pipelines per feature set drawn so far (see [`Features`]).
    variants: HashMap<Features, ScenePipelines>,
    /// Feature sets whose pipelines are being built ahead of their first frame, one pipeline
    /// at a time ([`PoolPasses::build_ahead`]).
    building: HashMap<Features, VariantBuild>,
    /// The debug view's pass per texture shown so far.
    debug_passes: HashMap<(DebugTexture, AmbientModel, bool), FullscreenPass>,
    /// The water grid drawn into the caustics map.
    caustics_grid: CausticsGrid,
    /// The water surface, both sides in one draw.
    grid: GridMesh,
    pool_mesh: Mesh,
    /// The pool's walls above [`deck::DRY_BAND_BOTTOM`]: all of the pool a scene pass with the
    /// deck sees directly.
    dry_band_mesh: Mesh,
    deck_mesh: Mesh,
    /// The water surface traces the objects only in their regions (`regions::surface_regions`);
    /// off, everywhere (for tests: the regions must not change the picture).
    object_regions: bool,
}

impl PoolPasses {
    /// The passes of the pool `renderer` draws (its box, surface grid and formats), for `water`.
    pub fn new(device: &wgpu::Device, renderer: &Renderer, water: &HeightField) -> Self {
        let settings = *renderer.settings();
        let mirror_uniforms = renderer.scene_uniform_buffer(device, "mirrored scene uniforms");
        let [water_layout, _] = renderer.scene_layouts();
        let mirror_groups = water_bind_groups(device, water_layout, &mirror_uniforms, water, renderer.ambient_views());
        let format = settings.target_format;
        let sky = FullscreenPass::new(
            device,
            "sky",
            &[&shaders::scene_prelude(Features::default(), format), shaders::SKY],
            "fs_sky",
            &renderer.scene_layouts(),
            FullscreenTarget { format, blend: None, depth: Some(DEPTH_FORMAT) },
        );
        let (pool_vertices, pool_indices) = pool_box(settings.pool);
        Self {
            mirror_uniforms,
            mirror_groups,
            mirror_binding: renderer.water_binding(),
            flat: FlatWater::new(device, format),
            sky,
            variants: HashMap::new(),
            building: HashMap::new(),
            debug_passes: HashMap::new(),
            caustics_grid: CausticsGrid::new(device, water.size()),
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
            object_regions: true,
        }
    }

    /// The pipelines for `features`, built the first time they are asked for (finished, if
    /// [`PoolPasses::build_ahead`] had started them).
    fn variant(&mut self, renderer: &Renderer, device: &wgpu::Device, features: Features) -> &ScenePipelines {
        if !self.variants.contains_key(&features) {
            let format = renderer.settings().target_format;
            let build = self.building.remove(&features).unwrap_or_else(|| VariantBuild::new(features, format));
            let pipelines = build.finish(device, &pipeline_targets(renderer, features));
            self.variants.insert(features, pipelines);
        }
        &self.variants[&features]
    }

    /// Builds the flat water's pipeline for `features` if it is not built yet.
    fn prepare_flat_pipeline(&mut self, renderer: &Renderer, device: &wgpu::Device, features: Features) {
        self.flat.prepare_pipeline(device, features, &pipeline_targets(renderer, features));
    }

    /// Builds the pipelines of a feature set now, if they are not built yet.
    pub fn prepare_variant(&mut self, renderer: &Renderer, device: &wgpu::Device, features: Features) {
        self.variant(renderer, device, features);
    }

    /// Builds one pipeline of those a frame of `view` at `size` pixels will draw with, if
    /// any is missing; true when none is. A shell that must not hold a browser's thread for
    /// long calls it once per task before the first frame (a frame builds what is missing at
    /// once: on WebGL2 without a GPU, a second or more).
    pub fn build_ahead(&mut self, renderer: &Renderer, device: &wgpu::Device, view: &View, size: (u32, u32)) -> bool {
        let drawn = self.variants_drawn(renderer, view, size);
        let Some(features) = drawn.into_iter().find(|f| !self.variants.contains_key(f)) else {
            // Then the flat water's own pipeline, if the frame shows flat water (as
            // `draw_picture` decides: some columns left of the divider).
            let flat = flat_shown(view).filter(|f| f.divider(renderer.scene_size(view, size).0) > 0);
            let Some(lit) = flat.map(|f| f.lit_features(view.features())) else {
                return true;
            };
            if self.flat.has_pipeline(lit) {
                return true;
            }
            self.prepare_flat_pipeline(renderer, device, lit);
            return false;
        };
        let format = renderer.settings().target_format;
        let mut build = self.building.remove(&features).unwrap_or_else(|| VariantBuild::new(features, format));
        if build.step(device, &pipeline_targets(renderer, features)) {
            let pipelines = build.finish(device, &pipeline_targets(renderer, features));
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

    /// Pipeline sets built: feature sets of the scene's pipelines and of the flat water's.
    pub fn pipeline_sets_built(&self) -> usize {
        self.variants.len() + self.flat.pipelines_built()
    }

    /// After [`Renderer::prepare`], before the passes: the flat water's mirrored camera's
    /// uniforms for this frame, if flat water is shown, and its bind groups made again if the
    /// renderer's were.
    pub fn prepare(
        &mut self,
        renderer: &Renderer,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        view: &View,
        water: &HeightField,
    ) {
        if self.mirror_binding != renderer.water_binding() {
            let [water_layout, _] = renderer.scene_layouts();
            self.mirror_groups =
                water_bind_groups(device, water_layout, &self.mirror_uniforms, water, renderer.ambient_views());
            self.mirror_binding = renderer.water_binding();
        }
        if let Some(f) = flat_shown(view) {
            // Everything the mirrored camera sees is above the water.
            let mirrored = view.view_proj * flat::mirror(f.plane);
            let eye = view.eye * glam::Vec3::new(1.0, -1.0, 1.0) + glam::Vec3::new(0.0, 2.0 * f.plane, 0.0);
            renderer.write_uniforms_above_water(queue, &self.mirror_uniforms, mirrored, eye);
        }
    }
}

/// Formats and layouts of `renderer` the pool's pipelines of `features` are built for.
fn pipeline_targets(renderer: &Renderer, features: Features) -> PipelineTargets<'_> {
    let [water_layout, textures_layout] = renderer.scene_layouts();
    PipelineTargets {
        format: renderer.settings().target_format,
        caustics_format: renderer.settings().caustics_format_for(features.dispersion).0,
        water_layout,
        textures_layout,
    }
}
