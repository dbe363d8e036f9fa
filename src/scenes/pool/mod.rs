//! The pool (`scene` = pool): the tiled pool's water simulated on a height field, the floating
//! bodies coupled to it, the ambient waves over it, drawn ray-traced, flat or split by the
//! pool's passes (`render/`) on the renderer's shared resources. Its camera orbits the pool
//! within `camera::POOL_LIMITS`.

mod bodies;
pub mod render;
mod view;

use glam::{Vec2, Vec3};

use super::{SceneFrame, Shared, Stage, STEP_DT};
use crate::ambient::gpu_ocean::GpuOcean;
use crate::ambient::{AmbientSettings, AmbientWaves};
use crate::bodies::{Body, BodyId};
use crate::camera::OrbitCamera;
use crate::params::{ParamId, Params};
use crate::physics::Pose;
use crate::render::{DebugTexture, RenderMode, Renderer};
use crate::sim::{Drop, HeightField, WaveSettings};
use crate::world::PoolShape;
use render::PoolPasses;

/// How near (pixels) to the split view's divider a press grabs it.
pub const DIVIDER_GRAB_PX: f32 = 12.0;

/// The pool's state: its camera, water, bodies and ambient waves.
pub struct PoolScene {
    pub camera: OrbitCamera,
    /// The pool's box (m).
    shape: PoolShape,
    /// The `sim_size` parameter value the water was last built or resampled for (set by
    /// [`PoolScene::start`]).
    applied_sim_size: f32,
    /// One body per kind of `bodies::KINDS`, indexed by [`BodyId`].
    bodies: Vec<Body>,
    /// Frames between the water heights the bodies last used and the frame using them.
    probe_latency: Option<u64>,
    water: HeightField,
    /// The ambient waves of the current parameters, and the settings they were made for.
    ambient: AmbientWaves,
    ambient_settings: AmbientSettings,
    /// Whether the FFT ocean is summed on the GPU (float render targets) or on the CPU.
    ocean_on_gpu: bool,
    /// The GPU's FFT passes, made when the FFT ocean is first drawn on the GPU path.
    gpu_ocean: Option<GpuOcean>,
    /// Whether the renderer holds the current ambient waves' spectrum image.
    spectrum_shown: bool,
    /// The pool's pipelines, meshes and passes.
    passes: PoolPasses,
}

impl PoolScene {
    /// The pool of `shape` with `water` (as wide), drawn by `renderer`; the FFT ocean on the
    /// GPU where it renders into `float_targets`.
    pub fn new(
        (device, renderer): (&wgpu::Device, &Renderer),
        shape: PoolShape,
        water: HeightField,
        float_targets: bool,
    ) -> Self {
        Self {
            passes: PoolPasses::new(device, renderer, &water),
            camera: OrbitCamera::default(),
            shape,
            applied_sim_size: 0.0,
            bodies: Vec::new(),
            probe_latency: None,
            water,
            ambient: AmbientWaves::new(&AmbientSettings::default()),
            ambient_settings: AmbientSettings::default(),
            ocean_on_gpu: float_targets,
            gpu_ocean: None,
            spectrum_shown: false,
        }
    }

    /// Makes the ambient waves of `params` and puts the bodies at their starts (the demo's
    /// first parameters).
    pub fn start(&mut self, sh: Shared<'_>) {
        self.applied_sim_size = sh.params.get(ParamId::SimSize);
        self.refresh_ambient(sh.params);
        self.place_bodies_at_start(sh);
    }

    /// The pool's box (m).
    pub fn shape(&self) -> PoolShape {
        self.shape
    }

    pub fn water(&self) -> &HeightField {
        &self.water
    }

    /// The pool's passes.
    pub fn passes(&self) -> &PoolPasses {
        &self.passes
    }

    pub fn passes_mut(&mut self) -> &mut PoolPasses {
        &mut self.passes
    }

    /// The ambient waves (heights in m at the demo's simulated time).
    pub fn ambient(&self) -> &AmbientWaves {
        &self.ambient
    }

    /// The GPU's FFT ocean, once the FFT ocean has been drawn on the GPU path (for tests).
    pub fn gpu_ocean(&self) -> Option<&GpuOcean> {
        self.gpu_ocean.as_ref()
    }

    /// Whether the pool is sunk in the deck (`setting` deck) rather than the cut-away box.
    pub fn on_deck(params: &Params) -> bool {
        params.choice::<crate::render::Setting>(ParamId::Setting) == crate::render::Setting::Deck
    }

    /// The FFT ocean's maps for this frame: its passes on the GPU (recorded into `encoder`), or
    /// its surface summed on the CPU and uploaded.
    fn encode_ocean(&mut self, renderer: &mut Renderer, cx: &mut crate::gpu::FrameContext<'_>, t: f64) {
        let Some(ocean) = &self.ambient.ocean else { return };
        if self.ocean_on_gpu {
            let size = ocean.size as u32;
            if self.gpu_ocean.as_ref().is_none_or(|g| g.size() != size) {
                let made = GpuOcean::new(cx.device, size, 1);
                renderer.use_ambient_views(cx.device, &self.water, [made.surface(), made.displacement()]);
                self.gpu_ocean = Some(made);
            }
            if let Some(gpu_ocean) = &mut self.gpu_ocean {
                gpu_ocean.encode(cx.queue, cx.encoder, &[ocean], t);
            }
        } else {
            let surface = ocean.surface(t);
            let displacement = (ocean.choppiness > 0.0).then(|| ocean.displacement(t));
            let maps = [Some(&surface[..]), displacement.as_deref()];
            renderer.upload_ambient(cx.device, cx.queue, &self.water, ocean.size as u32, maps);
        }
    }

    /// The water's foam lifetime (s) if the parameters ask for foam.
    fn foam(params: &Params) -> Option<f32> {
        params.flag(ParamId::Foam).then(|| params.get(ParamId::FoamDecay))
    }
}

impl super::Scene for PoolScene {
    fn camera(&self) -> &OrbitCamera {
        &self.camera
    }

    fn camera_mut(&mut self) -> &mut OrbitCamera {
        &mut self.camera
    }

    fn follow_params(&mut self, params: &Params) {
        if Self::on_deck(params) {
            // The camera stays above the paving.
            self.camera.keep_eye_above(self.shape.rim + crate::render::EYE_CLEARANCE);
        }
        self.refresh_ambient(params);
        self.water.set_foam(Self::foam(params));
    }

    /// Simulates the frame's steps (submitted at once, in a command buffer of its own) and
    /// records the pool's drawing into the frame's encoder.
    fn encode_frame(&mut self, sh: Shared<'_>, frame: SceneFrame<'_, '_>) {
        let SceneFrame { mut cx, renderer, steps, mark } = frame;
        let params = sh.params;
        let pushes = self.step_bodies(sh, steps);
        // The simulation goes in a submission of its own, ahead of the drawing: the objects'
        // water samples and the water statistics can then be mapped as soon as the water is
        // done rather than after the whole frame, which keeps them a frame old even where
        // drawing is slow (software rendering in a browser).
        let (device, queue) = (cx.device, cx.queue);
        let mut sim_encoder = device.create_command_encoder(&Default::default());
        let wanted_size = params.get(ParamId::SimSize);
        if wanted_size != self.applied_sim_size {
            self.applied_sim_size = wanted_size;
            let frames = self.water.frames();
            self.water = self.water.resampled(device, queue, &mut sim_encoder, wanted_size as u32);
            self.water.set_frames(frames);
            renderer.rebind_water(device, &self.water);
        }
        self.couple_water(sh, pushes);
        let settings = WaveSettings {
            wave_speed: params.get(ParamId::WaveSpeed),
            damping: params.get(ParamId::Damping),
            absorbing_walls: params.flag(ParamId::AbsorbingWalls),
        };
        mark(&mut sim_encoder, Stage::Start);
        // Again: a resampled field above starts without foam.
        self.water.set_foam(Self::foam(params));
        self.water.encode(queue, &mut sim_encoder, steps, STEP_DT, settings);
        mark(&mut sim_encoder, Stage::AfterSimulation);
        queue.submit([sim_encoder.finish()]);
        self.water.after_submit();
        let view = self.view(sh);
        if let Some(foam) = self.water.foam() {
            renderer.upload_foam(device, queue, foam);
        }
        if view.debug.is_some_and(|d| d.texture == DebugTexture::Spectrum) && !self.spectrum_shown {
            renderer.upload_spectrum(queue, &self.ambient.spectrum_image());
            self.spectrum_shown = true;
        }
        self.encode_ocean(renderer, &mut cx, sh.sim_time());
        mark(cx.encoder, Stage::AfterWaves);
        renderer.prepare(queue, cx.encoder, &view, &self.water);
        self.passes.prepare(renderer, device, queue, &view, &self.water);
        self.passes.encode_caustics(renderer, device, cx.encoder, &view, &self.water);
        mark(cx.encoder, Stage::AfterMaps);
        self.passes.encode_pool(renderer, &mut cx, &view, &self.water);
        mark(cx.encoder, Stage::AfterShading);
    }

    fn after_submit(&mut self, _steps_taken: u64) {
        self.water.after_submit();
    }

    fn reset(&mut self, queue: &wgpu::Queue, sh: Shared<'_>) {
        self.water.reset(queue);
        self.place_bodies_at_start(sh);
    }

    fn build_ahead(
        &mut self,
        sh: Shared<'_>,
        renderer: &mut Renderer,
        device: &wgpu::Device,
        size: (u32, u32),
    ) -> bool {
        let view = self.view(sh);
        self.passes.build_ahead(renderer, device, &view, size)
    }

    fn stage_names(&self) -> [&'static str; 4] {
        ["simulation", "waves", "caustics", "shading"]
    }

    fn has_render_modes(&self) -> bool {
        true
    }

    fn drop_area(&self) -> (f32, &'static str) {
        (self.shape.half_width, "the pool")
    }

    fn add_drop(&mut self, drop: Drop) {
        self.water.add_drop(drop);
    }

    fn pick_body(&self, sh: Shared<'_>, pixel: Vec2) -> Option<(BodyId, Vec3, Vec3)> {
        let (id, hit) = self.body_under(sh, pixel)?;
        Some((id, hit, self.bodies[id.0].motion.pose.position))
    }

    fn move_body(&mut self, sh: Shared<'_>, id: BodyId, position: Vec3) {
        let rotation = self.bodies[id.0].motion.pose.rotation;
        self.set_body_pose(sh, id, Pose { position, rotation });
    }

    /// The split view's divider, shown only in the split view with the camera above the water.
    fn grabs_divider(&self, sh: Shared<'_>, x: f32) -> bool {
        sh.params.choice::<RenderMode>(ParamId::RenderMode) == RenderMode::Split
            && (x - sh.params.get(ParamId::Split) * sh.viewport.x).abs() <= DIVIDER_GRAB_PX
            && self.flat_water_drawn(sh)
    }
}
