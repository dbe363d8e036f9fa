//! The platform-free core of the demo: the parameters, the clock, the governors, the renderer
//! and the scenes (`crate::scenes`), driven by a small input API (pointer in pixels, keys,
//! frame time). The browser and native shells only forward events to it and hand it a target
//! to draw into.

/// What the scenes' hooks are told now: a macro, so that it borrows only the fields it reads
/// and a scene can be borrowed beside it.
macro_rules! shared {
    ($demo:expr) => {
        $crate::scenes::Shared {
            params: &$demo.params,
            viewport: $demo.viewport,
            steps_taken: $demo.steps_taken,
            render_scale: $demo.render_scale,
            held: $demo.drag.held(),
        }
    };
}

mod input;
mod options;
mod scene_state;

use glam::{Vec2, Vec3};

pub use crate::bodies::BodyId;
use crate::camera::OrbitCamera;
pub use crate::gpu::FrameContext;
use crate::params::{ParamId, Params};
use crate::quality::{ResolutionGovernor, StepGovernor};
use crate::render::{RenderSettings, Renderer};
pub use crate::scenes::pool::DIVIDER_GRAB_PX;
pub use crate::scenes::sea::sea_settings;
use crate::scenes::{SceneFrame, SceneKind, Scenes};
pub use crate::scenes::{Stage, STEPS_PER_SECOND, STEP_DT};
use crate::sim::{FixedStep, HeightField, SimEngine};
use crate::world::PoolShape;
use input::Drag;
pub use input::Key;
pub use options::{DemoOptions, OptionSpec, SizeCaps, SOFTWARE_CAPS};

/// Slowest frame rate (frames/s) at which the water still keeps up with wall time.
pub const REAL_TIME_DOWN_TO_FPS: u32 = 10;
/// Most steps one frame may take: enough for a frame of 1/[`REAL_TIME_DOWN_TO_FPS`] s. A longer
/// frame drops the rest, so below 10 frames/s the water runs in slow motion (simulated time
/// per frame stays at 0.1 s) instead of each slow frame taking more steps and so getting
/// slower still; the frame's cost is bounded by the scene plus this many steps. Where the
/// steps themselves would push frames under 10 frames/s, fewer are allowed
/// ([`StepGovernor`]).
pub const MAX_STEPS_PER_FRAME: u32 = STEPS_PER_SECOND / REAL_TIME_DOWN_TO_FPS;

/// The pool the demo is made with.
const POOL: PoolShape = PoolShape::CLASSIC;

pub struct WaterDemo {
    pub params: Params,
    /// Every scene, each keeping its state while another is shown.
    scenes: Scenes,
    /// The scene shown: the one the `scene` parameter asked for when the demo last followed
    /// the parameters ([`WaterDemo::sync_scene`]).
    shown: SceneKind,
    renderer: Renderer,
    clock: FixedStep,
    viewport: Vec2,
    drag: Drag,
    /// Steps simulated so far.
    steps_taken: u64,
    /// Chooses the render scale when the `quality` parameter is auto.
    governor: ResolutionGovernor,
    /// How many steps a frame may take (at most [`MAX_STEPS_PER_FRAME`]).
    step_governor: StepGovernor,
    /// The render scale of the last frame drawn.
    render_scale: f32,
}

/// A demo made in steps, each short enough to leave a browser's thread responsive (at most
/// about 150 ms on WebGL2 without a GPU): the tile texture's texels (CPU), the height field
/// (its shaders), then the renderer. The web shell gives the thread back between steps;
/// [`WaterDemo::new`] takes them all at once.
pub struct DemoBuild {
    target_format: wgpu::TextureFormat,
    options: DemoOptions,
    tile_mips: Option<Vec<Vec<u8>>>,
    water: Option<HeightField>,
}

impl DemoBuild {
    /// A demo to draw into colour targets of `target_format`.
    pub fn new(target_format: wgpu::TextureFormat, options: DemoOptions) -> Self {
        Self { target_format, options, tile_mips: None, water: None }
    }

    /// Takes the next step; the demo after the last (do not call it again then).
    pub fn step(&mut self, device: &wgpu::Device, queue: &wgpu::Queue) -> Option<WaterDemo> {
        let options = self.options;
        if self.tile_mips.is_none() {
            self.tile_mips = Some(crate::textures::tile_mips());
            return None;
        }
        let Some(water) = self.water.take() else {
            let engine = if options.float_targets { SimEngine::Gpu } else { SimEngine::Cpu };
            self.water = Some(HeightField::new_on(device, options.sim_size, POOL.half_width, engine));
            return None;
        };
        let settings = RenderSettings {
            target_format: self.target_format,
            caustics_size: options.caustics_size,
            surface_grid: options.surface_grid,
            float_targets: options.float_targets,
            pool: POOL,
        };
        let renderer = Renderer::new(device, queue, settings, &water, self.tile_mips.as_deref().unwrap_or_default());
        let software = device.adapter_info().device_type == wgpu::DeviceType::Cpu;
        Some(WaterDemo::assemble(device, water, renderer, options, software))
    }
}

impl WaterDemo {
    /// Creates the demo for colour targets of `target_format`.
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        target_format: wgpu::TextureFormat,
        options: DemoOptions,
    ) -> Self {
        let mut build = DemoBuild::new(target_format, options);
        loop {
            if let Some(demo) = build.step(device, queue) {
                return demo;
            }
        }
    }

    /// The demo from its parts; `software`: whether the adapter is a software rasteriser.
    fn assemble(
        device: &wgpu::Device,
        water: HeightField,
        renderer: Renderer,
        options: DemoOptions,
        software: bool,
    ) -> Self {
        let mut params = Params::default();
        params.set(ParamId::SimSize, options.sim_size as f32);
        let mut demo = Self {
            params,
            scenes: Scenes::new((device, &renderer), POOL, water, options.float_targets, software),
            shown: SceneKind::default(),
            renderer,
            clock: FixedStep::new(STEP_DT, MAX_STEPS_PER_FRAME),
            viewport: Vec2::new(800.0, 600.0),
            drag: Drag::None,
            steps_taken: 0,
            governor: ResolutionGovernor::default(),
            step_governor: StepGovernor::new(MAX_STEPS_PER_FRAME, 1.0 / REAL_TIME_DOWN_TO_FPS as f32),
            render_scale: 1.0,
        };
        demo.scenes.pool.start(shared!(demo));
        demo
    }

    /// The scene the `scene` parameter asks for.
    pub fn scene(&self) -> SceneKind {
        self.params.choice(ParamId::Scene)
    }

    /// The scene shown (the last frame's, or the one asked for since [`WaterDemo::sync_scene`]).
    pub fn drawn_scene(&self) -> SceneKind {
        self.shown
    }

    /// The camera of the scene shown (each scene keeps its own, with its own limits).
    pub fn camera(&self) -> &OrbitCamera {
        self.scenes.get(self.shown).camera()
    }

    /// The camera of the scene shown; call [`WaterDemo::sync_scene`] first after a change of
    /// `scene`.
    pub fn camera_mut(&mut self) -> &mut OrbitCamera {
        self.scenes.get_mut(self.shown).camera_mut()
    }

    /// What each timed stage of the shown scene's frame does, in the order of its marks (from
    /// [`Stage::Start`] to [`Stage::AfterShading`]), as the shells name their times.
    pub fn stage_names(&self) -> [&'static str; 4] {
        self.scenes.get(self.shown).stage_names()
    }

    /// What `wavepool bench` times apart in the shown scene beside its frame's stages: (name, each run's
    /// ms); waits for the GPU.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn timed_apart(&self, device: &wgpu::Device, queue: &wgpu::Queue) -> Vec<(&'static str, Vec<f64>)> {
        self.scenes.get(self.shown).timed_apart(device, queue, &self.params)
    }

    /// Whether the render modes (ray-traced, flat, split) and their costs apply to the scene
    /// asked for.
    pub fn render_modes_apply(&self) -> bool {
        self.scenes.get(self.scene()).has_render_modes()
    }

    /// Where drops fall in the scene shown: the half width (m) of its water each way from the
    /// origin, and the water's name (for warnings).
    pub fn drop_area(&self) -> (f32, &'static str) {
        self.scenes.get(self.shown).drop_area()
    }

    /// Brings the scene the parameters ask for up to them: it becomes the one shown, its
    /// camera kept clear of what it must not enter. Call before moving the camera after a
    /// change of `scene`.
    pub fn sync_scene(&mut self) {
        self.shown = self.scene();
        self.scenes.get_mut(self.shown).follow_params(&self.params);
    }

    /// Starts over from `preset`: its values, then its view on the camera of the scene it
    /// shows (so a sea preset's view is the sea camera's, within the sea's limits).
    pub fn apply_preset(&mut self, preset: &crate::presets::Preset) {
        let mut view = *self.camera();
        preset.apply(&mut self.params, &mut view);
        self.sync_scene();
        let camera = self.camera_mut();
        (camera.yaw, camera.pitch, camera.distance) = (view.yaw, view.pitch, view.distance);
        camera.clamp();
    }

    /// Builds one of the pipelines the next frame, `size` pixels, will draw with, if one is
    /// missing; true when none is. A shell that must keep a browser's thread responsive
    /// calls it once per task before the first frame (which would otherwise build them all
    /// at once: over a second on WebGL2 without a GPU).
    pub fn build_ahead(&mut self, device: &wgpu::Device, size: (u32, u32)) -> bool {
        self.follow_params(size);
        if self.params.get(ParamId::Quality) > 0.0 {
            self.choose_render_scale(0.0); // a fixed scale (the automatic one observes frames)
        }
        self.scenes.get_mut(self.shown).build_ahead(shared!(self), &mut self.renderer, device, size)
    }

    /// Brings what the frame is made from up to the parameters before a frame of `size`
    /// pixels: the viewport and the scene.
    fn follow_params(&mut self, size: (u32, u32)) {
        self.set_viewport(size.0, size.1);
        self.sync_scene();
    }

    /// See [`PoolPasses::set_object_regions`](crate::scenes::pool::render::PoolPasses::set_object_regions).
    #[doc(hidden)]
    pub fn set_object_regions(&mut self, on: bool) {
        self.scenes.pool.passes_mut().set_object_regions(on);
    }

    /// See [`Renderer::set_body_outlines`].
    #[doc(hidden)]
    pub fn set_body_outlines(&mut self, on: bool) {
        self.renderer.set_body_outlines(on);
    }

    /// The pool's pipeline sets built so far (see
    /// [`PoolPasses::pipeline_sets_built`](crate::scenes::pool::render::PoolPasses::pipeline_sets_built)).
    pub fn pipeline_sets_built(&self) -> usize {
        self.scenes.pool.passes().pipeline_sets_built()
    }

    /// Simulated time so far (s).
    pub fn sim_time(&self) -> f64 {
        self.steps_taken as f64 / STEPS_PER_SECOND as f64
    }

    /// Fixed steps simulated so far.
    pub fn steps_taken(&self) -> u64 {
        self.steps_taken
    }

    /// Unit vector towards the sun.
    pub fn sun(&self) -> Vec3 {
        crate::scenes::sun(&self.params)
    }

    /// Flattens the water of every scene and puts the bodies back where they started, at rest.
    pub fn reset(&mut self, queue: &wgpu::Queue) {
        let sh = shared!(self);
        for scene in self.scenes.all_mut() {
            scene.reset(queue, sh);
        }
    }

    /// Advances the water by `frame_time` seconds (in fixed steps) and draws into `target`
    /// of `size` pixels, all in one submission.
    pub fn frame(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        target: &wgpu::TextureView,
        size: (u32, u32),
        frame_time: f32,
    ) {
        let mut encoder = device.create_command_encoder(&Default::default());
        let cx = FrameContext { device, queue, encoder: &mut encoder, target, size };
        self.encode_frame(cx, frame_time, &mut |_, _| {});
        queue.submit([encoder.finish()]);
        self.after_submit();
        // Never waits: only lets finished readbacks (water statistics, body probes) complete.
        let _ = device.poll(wgpu::PollType::Poll);
    }

    /// Call after submitting a frame recorded with [`WaterDemo::encode_frame`]: starts any
    /// asynchronous read the frame asked for (the water statistics, the bodies' water
    /// samples) not yet started; in the sea, sums the next frame's waves while the GPU draws
    /// this one.
    pub fn after_submit(&mut self) {
        let steps_taken = self.steps_taken;
        self.scenes.get_mut(self.shown).after_submit(steps_taken);
    }

    /// How many fixed steps this frame takes after `frame_time` (s) of wall time: none while
    /// paused, at most what the step governor allows.
    fn take_steps(&mut self, frame_time: f32) -> u32 {
        self.step_governor.observe(frame_time);
        self.clock.max_steps = self.step_governor.cap();
        let steps = if self.params.flag(ParamId::Paused) {
            self.clock.advance(0.0);
            0
        } else {
            self.clock.advance(frame_time)
        };
        self.step_governor.took(steps);
        self.steps_taken += steps as u64;
        steps
    }

    /// Simulates a frame (submitted at once, in a command buffer of its own) and records its
    /// drawing into `cx`'s encoder; `mark` is called at each [`Stage`] boundary (for
    /// timestamps; the first two in the simulation's encoder). Writes uniform buffers, so
    /// submit before encoding another frame.
    pub fn encode_frame(
        &mut self,
        cx: FrameContext<'_>,
        frame_time: f32,
        mark: &mut dyn FnMut(&mut wgpu::CommandEncoder, Stage),
    ) {
        self.follow_params(cx.size);
        self.choose_render_scale(frame_time);
        let steps = self.take_steps(frame_time);
        let frame = SceneFrame { cx, renderer: &mut self.renderer, steps, mark };
        self.scenes.get_mut(self.shown).encode_frame(shared!(self), frame);
    }

    /// Fraction of the target's width and height the scene was last drawn at (see the
    /// `quality` parameter).
    pub fn render_scale(&self) -> f32 {
        self.render_scale
    }

    /// The render scale for this frame: the `quality` parameter's, or with `quality` auto,
    /// the governor's after it has seen `frame_time` (s, the time since the last frame).
    fn choose_render_scale(&mut self, frame_time: f32) {
        let quality = self.params.get(ParamId::Quality);
        self.render_scale = if quality > 0.0 {
            quality
        } else {
            self.governor.observe(frame_time, self.params.get(ParamId::FrameBudget) / 1000.0);
            self.governor.scale()
        };
    }
}
