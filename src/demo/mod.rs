//! The platform-free core of the demo: parameters, camera, water, sphere and renderer, driven
//! by a small input API (pointer in pixels, keys, frame time). The browser and native shells
//! only forward events to it and hand it a target to draw into.

mod bodies;
mod input;
mod options;
mod sea;
mod sea_bodies;
mod view;

use glam::{Vec2, Vec3};

use crate::ambient::gpu_ocean::GpuOcean;
use crate::ambient::{AmbientSettings, AmbientWaves};
use crate::bodies::Body;
pub use crate::bodies::BodyId;
use crate::camera::OrbitCamera;
pub use crate::gpu::FrameContext;
use crate::params::{ParamId, Params};
use crate::quality::{ResolutionGovernor, StepGovernor};
use crate::render::{DebugTexture, RenderSettings, Renderer};
use crate::scene;
use crate::sim::{FixedStep, HeightField, SimEngine, WaterLevel, WaveSettings};
use input::Drag;
pub use input::{Key, DIVIDER_GRAB_PX};
pub use options::{DemoOptions, OptionSpec, SizeCaps, SOFTWARE_CAPS};
pub use sea::sea_settings;

/// Fixed simulation steps per simulated second.
pub const STEPS_PER_SECOND: u32 = 120;
/// Simulated seconds per step.
pub const STEP_DT: f32 = 1.0 / STEPS_PER_SECOND as f32;
/// Slowest frame rate (frames/s) at which the water still keeps up with wall time.
pub const REAL_TIME_DOWN_TO_FPS: u32 = 10;
/// Most steps one frame may take: enough for a frame of 1/[`REAL_TIME_DOWN_TO_FPS`] s. A longer
/// frame drops the rest, so below 10 frames/s the water runs in slow motion (simulated time
/// per frame stays at 0.1 s) instead of each slow frame taking more steps and so getting
/// slower still; the frame's cost is bounded by the scene plus this many steps. Where the
/// steps themselves would push frames under 10 frames/s, fewer are allowed
/// ([`StepGovernor`]).
pub const MAX_STEPS_PER_FRAME: u32 = STEPS_PER_SECOND / REAL_TIME_DOWN_TO_FPS;

/// Stages of a frame, for timing: each is the index of its mark (`StageTimer::mark`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    Start,
    AfterSimulation,
    /// After the waves that move on their own: the pool's FFT ocean, the sea's cascades.
    AfterWaves,
    AfterCaustics,
    AfterScene,
}

/// What each timed stage of a frame does, in the order of the marks between them (from
/// [`Stage::Start`] to [`Stage::AfterScene`]), as the shells name their times.
pub const STAGE_NAMES: [&str; 4] = ["simulation", "waves", "caustics", "scene"];

pub struct WaterDemo {
    pub params: Params,
    /// The `sim_size` parameter value the water was last built or resampled for.
    applied_sim_size: f32,
    pub camera: OrbitCamera,
    /// One body per kind of `bodies::KINDS`, indexed by [`BodyId`].
    bodies: Vec<Body>,
    /// Frames between the water heights the bodies last used and the frame using them.
    probe_latency: Option<u64>,
    water: HeightField,
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
    /// The ambient waves of the current parameters, and the settings they were made for.
    ambient: AmbientWaves,
    ambient_settings: AmbientSettings,
    /// Whether the FFT ocean is summed on the GPU (float render targets) or on the CPU.
    ocean_on_gpu: bool,
    /// Whether the sea's cascades are: with float render targets, unless the adapter is a
    /// software rasteriser. There the GPU's passes run on the CPU as well, each paying for
    /// every texel it writes, where the CPU's radix-2 stages sum the cascades ahead of the
    /// next frame beside the drawing (on lavapipe 117–121 against 126–130 ms a sea frame).
    sea_fft_on_gpu: bool,
    /// The GPU's FFT passes, made when the FFT ocean is first drawn on the GPU path.
    gpu_ocean: Option<GpuOcean>,
    /// Whether the renderer holds the current ambient waves' spectrum image.
    spectrum_shown: bool,
    /// The scene `camera` belongs to, and the other scene's camera, kept for its return.
    camera_scene: crate::sea::SceneKind,
    other_camera: OrbitCamera,
    /// The open sea's waves, once the sea has been shown.
    sea: Option<sea::Sea>,
    /// What the sea draws beyond its waves (some of it off only in tests).
    sea_extras: sea::SeaExtras,
    /// Drops asked for in the sea before its first frame made its patch.
    early_sea_drops: Vec<crate::sim::Drop>,
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
            self.water = Some(HeightField::new_on(device, options.sim_size, scene::HALF_WIDTH, engine));
            return None;
        };
        let settings = RenderSettings {
            target_format: self.target_format,
            caustics_size: options.caustics_size,
            surface_grid: options.surface_grid,
            float_targets: options.float_targets,
        };
        let renderer = Renderer::new(device, queue, settings, &water, self.tile_mips.as_deref().unwrap_or_default());
        let software = device.adapter_info().device_type == wgpu::DeviceType::Cpu;
        Some(WaterDemo::assemble(water, renderer, options, software))
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
    fn assemble(water: HeightField, renderer: Renderer, options: DemoOptions, software: bool) -> Self {
        let mut params = Params::default();
        let applied_sim_size = params.set(ParamId::SimSize, options.sim_size as f32).value;
        let mut demo = Self {
            params,
            applied_sim_size,
            camera: OrbitCamera::default(),
            bodies: Vec::new(),
            probe_latency: None,
            water,
            renderer,
            clock: FixedStep::new(STEP_DT, MAX_STEPS_PER_FRAME),
            viewport: Vec2::new(800.0, 600.0),
            drag: Drag::None,
            steps_taken: 0,
            governor: ResolutionGovernor::default(),
            step_governor: StepGovernor::new(MAX_STEPS_PER_FRAME, 1.0 / REAL_TIME_DOWN_TO_FPS as f32),
            render_scale: 1.0,
            ambient: AmbientWaves::new(&AmbientSettings::default()),
            ambient_settings: AmbientSettings::default(),
            ocean_on_gpu: options.float_targets,
            sea_fft_on_gpu: options.float_targets && !software,
            gpu_ocean: None,
            spectrum_shown: false,
            camera_scene: crate::sea::SceneKind::Pool,
            other_camera: crate::sea::default_camera(),
            sea: None,
            sea_extras: sea::SeaExtras::default(),
            early_sea_drops: Vec::new(),
        };
        demo.refresh_ambient();
        demo.place_bodies_at_start();
        demo
    }

    /// Builds one of the pipelines the next frame, `size` pixels, will draw with, if one is
    /// missing; true when none is. A shell that must keep a browser's thread responsive
    /// calls it once per task before the first frame (which would otherwise build them all
    /// at once: over a second on WebGL2 without a GPU).
    pub fn build_ahead(&mut self, device: &wgpu::Device, size: (u32, u32)) -> bool {
        self.follow_params(size);
        if self.scene() == crate::sea::SceneKind::Sea {
            return true; // the sea's two pipelines are built with its first frame
        }
        if self.params.get(ParamId::Quality) > 0.0 {
            self.choose_render_scale(0.0); // a fixed scale (the automatic one observes frames)
        }
        let view = self.view();
        self.renderer.build_ahead(device, &view, size)
    }

    /// Brings what the view is made from up to the parameters before a frame of `size`
    /// pixels: the viewport, the camera's clearance over the deck, the ambient waves, the foam.
    fn follow_params(&mut self, size: (u32, u32)) {
        self.set_viewport(size.0, size.1);
        self.sync_scene();
        if self.on_deck() && self.camera_scene == crate::sea::SceneKind::Pool {
            // The camera stays above the paving.
            self.camera.keep_eye_above(scene::RIM + crate::render::EYE_CLEARANCE);
        }
        self.refresh_ambient();
        let foam = self.params.flag(ParamId::Foam).then(|| self.params.get(ParamId::FoamDecay));
        self.water.set_foam(foam);
    }

    /// See [`Renderer::set_object_regions`].
    #[doc(hidden)]
    pub fn set_object_regions(&mut self, on: bool) {
        self.renderer.set_object_regions(on);
    }

    /// See [`Renderer::set_body_outlines`].
    #[doc(hidden)]
    pub fn set_body_outlines(&mut self, on: bool) {
        self.renderer.set_body_outlines(on);
    }

    /// Pipeline sets built so far (see [`Renderer::pipeline_sets_built`]).
    pub fn pipeline_sets_built(&self) -> usize {
        self.renderer.pipeline_sets_built()
    }

    pub fn water(&self) -> &HeightField {
        &self.water
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
        scene::sun_direction(self.params.get(ParamId::SunAzimuth), self.params.get(ParamId::SunElevation))
    }

    /// The ambient waves (heights in m at simulated time [`WaterDemo::sim_time`]).
    pub fn ambient(&self) -> &AmbientWaves {
        &self.ambient
    }

    /// The GPU's FFT ocean, once the FFT ocean has been drawn on the GPU path (for tests).
    pub fn gpu_ocean(&self) -> Option<&GpuOcean> {
        self.gpu_ocean.as_ref()
    }

    /// Flattens the water and puts the bodies back where they started, at rest.
    pub fn reset(&mut self, queue: &wgpu::Queue) {
        self.water.reset(queue);
        self.reset_sea(queue);
        self.place_bodies_at_start();
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
    /// asynchronous read of the water statistics ([`WaterDemo::water_level`]) and the
    /// objects' water samples not yet started (encode_frame starts them already); in the sea,
    /// sums the next frame's waves while the GPU draws this one.
    pub fn after_submit(&mut self) {
        self.water.after_submit();
        self.sum_sea_ahead();
    }

    /// Mean and largest |height| of the water (m), read back asynchronously, a frame or
    /// two old; `None` before the first read has completed.
    pub fn water_level(&self) -> Option<WaterLevel> {
        self.water.level()
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

    /// The FFT ocean's maps for this frame: its passes on the GPU (recorded into `encoder`), or
    /// its surface summed on the CPU and uploaded.
    fn encode_ocean(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, encoder: &mut wgpu::CommandEncoder) {
        if let Some(ocean) = &self.ambient.ocean {
            let t = self.sim_time();
            if self.ocean_on_gpu {
                let size = ocean.size as u32;
                if self.gpu_ocean.as_ref().is_none_or(|g| g.size() != size) {
                    let made = GpuOcean::new(device, size, 1);
                    self.renderer.use_ambient_views(device, &self.water, [made.surface(), made.displacement()]);
                    self.gpu_ocean = Some(made);
                }
                if let Some(gpu_ocean) = &mut self.gpu_ocean {
                    gpu_ocean.encode(queue, encoder, &[ocean], t);
                }
            } else {
                let surface = ocean.surface(t);
                let displacement = (ocean.choppiness > 0.0).then(|| ocean.displacement(t));
                let maps = [Some(&surface[..]), displacement.as_deref()];
                self.renderer.upload_ambient(device, queue, &self.water, ocean.size as u32, maps);
            }
        }
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
        let FrameContext { device, queue, encoder, target, size } = cx;
        self.follow_params(size);
        if self.camera_scene == crate::sea::SceneKind::Sea {
            self.encode_sea_frame(FrameContext { device, queue, encoder, target, size }, frame_time, mark);
            return;
        }
        self.choose_render_scale(frame_time);
        let steps = self.take_steps(frame_time);
        let pushes = self.step_bodies(steps);
        // The simulation goes in a submission of its own, ahead of the drawing: the objects'
        // water samples and the water statistics can then be mapped as soon as the water is
        // done rather than after the whole frame, which keeps them a frame old even where
        // drawing is slow (software rendering in a browser).
        let mut sim_encoder = device.create_command_encoder(&Default::default());
        let wanted_size = self.params.get(ParamId::SimSize);
        if wanted_size != self.applied_sim_size {
            self.applied_sim_size = wanted_size;
            let frames = self.water.frames();
            self.water = self.water.resampled(device, queue, &mut sim_encoder, wanted_size as u32);
            self.water.set_frames(frames);
            self.renderer.rebind_water(device, &self.water);
        }
        self.couple_water(pushes);
        let settings = WaveSettings {
            wave_speed: self.params.get(ParamId::WaveSpeed),
            damping: self.params.get(ParamId::Damping),
            absorbing_walls: self.params.flag(ParamId::AbsorbingWalls),
        };
        mark(&mut sim_encoder, Stage::Start);
        // Again: a resampled field above starts without foam.
        let foam = self.params.flag(ParamId::Foam).then(|| self.params.get(ParamId::FoamDecay));
        self.water.set_foam(foam);
        self.water.encode(queue, &mut sim_encoder, steps, STEP_DT, settings);
        mark(&mut sim_encoder, Stage::AfterSimulation);
        queue.submit([sim_encoder.finish()]);
        self.water.after_submit();
        let view = self.view();
        if let Some(foam) = self.water.foam() {
            self.renderer.upload_foam(device, queue, foam);
        }
        if view.debug.is_some_and(|d| d.texture == DebugTexture::Spectrum) && !self.spectrum_shown {
            self.renderer.upload_spectrum(queue, &self.ambient.spectrum_image());
            self.spectrum_shown = true;
        }
        self.encode_ocean(device, queue, encoder);
        mark(encoder, Stage::AfterWaves);
        self.renderer.prepare(queue, encoder, &view, &self.water);
        self.renderer.encode_caustics(device, encoder, &view, &self.water);
        mark(encoder, Stage::AfterCaustics);
        self.renderer.encode_scene(device, encoder, target, size, &view, &self.water);
        mark(encoder, Stage::AfterScene);
    }
}
