//! The platform-free core of the demo: parameters, camera, water, sphere and renderer, driven
//! by a small input API (pointer in pixels, keys, frame time). The browser and native shells
//! only forward events to it and hand it a target to draw into.

use glam::{Quat, Vec2, Vec3};

use crate::ambient::gpu_ocean::GpuOcean;
use crate::ambient::{AmbientModel, AmbientSettings, AmbientWaves};
use crate::camera::{self, OrbitCamera, Pick};
use crate::duck;
use crate::optics::{FresnelModel, SpecularModel};
use crate::params::{ParamId, Params};
use crate::physics::{self, Ellipsoid, FloatingBody, Pose, Shape, WaterPlane};
use crate::quality::{ResolutionGovernor, StepGovernor};
use crate::render::flat::{Distortion, FlatCaustics, FlatView, RenderMode};
use crate::render::{AmbientView, DebugTexture, DebugView, Optics, RenderSettings, Renderer, View, REFLECTANCE_VIEW};
use crate::scene::{self, Sphere};
use crate::sim::{
    self, BodyCoupling, Drop, FixedStep, HeightField, HullMove, HullSlot, SimEngine, WaterLevel, WaveSettings,
};

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

/// Where the sphere starts (m).
const START_SPHERE_CENTRE: Vec3 = Vec3::new(-0.35, -0.45, 0.3);
/// Where the duck starts (x, z in m; it starts at its floating height) and where it looks
/// (turn about the vertical, radians; 0 is along +x).
const START_DUCK_XZ: Vec2 = Vec2::new(0.35, -0.3);
const START_DUCK_TURN: f32 = 2.4;
/// Points on the ring around each body where the water is sampled for its buoyancy.
const PROBES_PER_BODY: usize = 8;
/// Radius (m) of the ring on which a body feels the ambient waves (about the duck's and a
/// small sphere's waterline).
const AMBIENT_RING_RADIUS: f32 = 0.05;

/// The things that float in the pool.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BodyId {
    Sphere = 0,
    Duck = 1,
}

impl BodyId {
    pub const ALL: [BodyId; 2] = [BodyId::Sphere, BodyId::Duck];
}

/// Choices fixed when the demo is created.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DemoOptions {
    /// Simulation cells per side at the start (a power of two); the `sim_size` parameter
    /// starts at the nearest of its choices and changes it later.
    pub sim_size: u32,
    /// Caustics map texels per side.
    pub caustics_size: u32,
    /// Quads per side of the water surface mesh. Software rasterisers pay mostly per
    /// triangle, and the surface is shaded per pixel anyway: 48 costs little detail.
    pub surface_grid: u32,
    /// Whether the device can render into float textures. Without, the water is simulated
    /// by the CPU reference and the caustics map is 8-bit; the picture stays the same.
    pub float_targets: bool,
}

/// One creation option as the shells show it (web mount options and URL, CLI flags): its
/// name, range, default and, when only some values are allowed, those values.
#[derive(Clone, Copy, Debug)]
pub struct OptionSpec {
    pub name: &'static str,
    pub label: &'static str,
    pub min: u32,
    pub max: u32,
    pub default: u32,
    /// Allowed values (empty: any integer in range).
    pub choices: &'static [u32],
}

impl OptionSpec {
    /// `value` clamped to the range and snapped to the nearest choice, if there are any.
    pub fn clamp(&self, value: u32) -> u32 {
        let v = value.clamp(self.min, self.max);
        self.choices.iter().copied().min_by_key(|c| c.abs_diff(v)).unwrap_or(v)
    }
}

impl DemoOptions {
    /// The creation options' table: the one source of their names, ranges and defaults.
    pub const SPECS: [OptionSpec; 2] = [
        OptionSpec {
            name: "meshSize",
            label: "quads per side of the water surface mesh",
            min: 16,
            max: 512,
            default: 48,
            choices: &[],
        },
        OptionSpec {
            name: "causticsSize",
            label: "texels per side of the caustics map",
            min: 128,
            max: 2048,
            default: 512,
            choices: &[],
        },
    ];

    /// Options from raw values: the simulation size as the `sim_size` parameter would take it,
    /// mesh and caustics sizes clamped to their specs.
    pub fn clamped(sim_size: u32, surface_grid: u32, caustics_size: u32) -> Self {
        let [mesh, caustics] = &Self::SPECS;
        Self {
            sim_size: crate::params::spec(ParamId::SimSize).sanitise(sim_size as f32) as u32,
            surface_grid: mesh.clamp(surface_grid),
            caustics_size: caustics.clamp(caustics_size),
            float_targets: true,
        }
    }
}

impl Default for DemoOptions {
    fn default() -> Self {
        let [mesh, caustics] = &Self::SPECS;
        Self {
            sim_size: crate::params::spec(ParamId::SimSize).default as u32,
            surface_grid: mesh.default,
            caustics_size: caustics.default,
            float_targets: true,
        }
    }
}

/// Keys the core understands; shells map their key events to these.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Key {
    /// Pause or resume the water.
    Space,
    /// Put the sun behind the camera.
    L,
    /// Toggle gravity on the sphere.
    G,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Drag {
    None,
    Orbit {
        last: Vec2,
    },
    Water {
        last: Vec2,
    },
    Body {
        id: BodyId,
        offset: Vec3,
        plane_normal: Vec3,
        plane_point: Vec3,
    },
    /// The split view's divider.
    Divider,
}

/// How near (pixels) to the split view's divider a press grabs it.
pub const DIVIDER_GRAB_PX: f32 = 12.0;

/// Stages of a frame, for timing: each is the index of its mark (`StageTimer::mark`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    Start,
    AfterSimulation,
    AfterCaustics,
    AfterScene,
}

pub struct WaterDemo {
    pub params: Params,
    /// The `sim_size` parameter value the water was last built or resampled for.
    applied_sim_size: f32,
    pub camera: OrbitCamera,
    /// The sphere and the duck, indexed by [`BodyId`].
    bodies: [FloatingBody; 2],
    /// Each body's hull ellipsoids as the water last took them in (`None`: not in the pool).
    pushed: [Option<Vec<HullSlot>>; 2],
    /// Each body's submerged volume after the last step (m³).
    submerged: [f32; 2],
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
    /// The GPU's FFT passes, made when the FFT ocean is first drawn on the GPU path.
    gpu_ocean: Option<GpuOcean>,
    /// Whether the renderer holds the current ambient waves' spectrum image.
    spectrum_shown: bool,
}

impl WaterDemo {
    /// Creates the demo for colour targets of `target_format`.
    pub fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        target_format: wgpu::TextureFormat,
        options: DemoOptions,
    ) -> Self {
        let engine = if options.float_targets { SimEngine::Gpu } else { SimEngine::Cpu };
        let water = HeightField::new_on(device, options.sim_size, scene::HALF_WIDTH, engine);
        let settings = RenderSettings {
            target_format,
            caustics_size: options.caustics_size,
            surface_grid: options.surface_grid,
            float_targets: options.float_targets,
        };
        let renderer = Renderer::new(device, queue, settings, &water);
        let mut params = Params::default();
        let applied_sim_size = params.set(ParamId::SimSize, options.sim_size as f32).value;
        let mut demo = Self {
            params,
            applied_sim_size,
            camera: OrbitCamera::default(),
            bodies: [FloatingBody::at(Pose::at(START_SPHERE_CENTRE)), FloatingBody::at(Pose::at(Vec3::ZERO))],
            pushed: [None, None],
            submerged: [0.0; 2],
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
            gpu_ocean: None,
            spectrum_shown: false,
        };
        demo.refresh_ambient();
        demo.place_duck_at_start();
        demo
    }

    fn place_duck_at_start(&mut self) {
        let y = duck::shape(self.params.get(ParamId::DuckDensity)).floating_height(0.0);
        let pose = Pose {
            position: Vec3::new(START_DUCK_XZ.x, y, START_DUCK_XZ.y),
            rotation: Quat::from_rotation_y(START_DUCK_TURN),
        };
        self.bodies[BodyId::Duck as usize] = FloatingBody::at(pose);
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

    /// Whether a body is in the pool (the `objects` parameter: none, sphere, duck, both).
    pub fn shows(&self, id: BodyId) -> bool {
        let objects = self.params.get(ParamId::Objects) as u32;
        objects & (1 << id as u32) != 0
    }

    /// The sphere, if shown.
    pub fn sphere(&self) -> Option<Sphere> {
        self.shows(BodyId::Sphere).then(|| {
            let mut s = Sphere { centre: self.bodies[0].pose.position, radius: self.params.get(ParamId::SphereRadius) };
            s.clamp_to_pool();
            s
        })
    }

    /// The duck's pose, if shown.
    pub fn duck(&self) -> Option<Pose> {
        self.shows(BodyId::Duck).then_some(self.bodies[BodyId::Duck as usize].pose)
    }

    /// A body's motion (shown or not).
    pub fn body(&self, id: BodyId) -> &FloatingBody {
        &self.bodies[id as usize]
    }

    pub fn set_sphere_centre(&mut self, centre: Vec3) {
        self.set_body_pose(BodyId::Sphere, Pose::at(centre));
    }

    /// Puts a body somewhere (kept inside the pool) and stops it.
    pub fn set_body_pose(&mut self, id: BodyId, pose: Pose) {
        if pose.position.is_finite() && pose.rotation.is_finite() {
            let mut pose = Pose { position: pose.position, rotation: pose.rotation.normalize() };
            physics::keep_in_pool(&mut pose, &self.hull(id));
            self.bodies[id as usize] = FloatingBody::at(pose);
        }
    }

    /// A body's hull ellipsoids, in its own frame.
    fn hull(&self, id: BodyId) -> Vec<Ellipsoid> {
        match id {
            BodyId::Sphere => {
                vec![Ellipsoid { centre: Vec3::ZERO, radii: Vec3::splat(self.params.get(ParamId::SphereRadius)) }]
            }
            BodyId::Duck => duck::HULL.to_vec(),
        }
    }

    fn density(&self, id: BodyId) -> f32 {
        match id {
            BodyId::Sphere => self.params.get(ParamId::SphereDensity),
            BodyId::Duck => self.params.get(ParamId::DuckDensity),
        }
    }

    fn centre_of_mass(id: BodyId) -> Vec3 {
        match id {
            BodyId::Sphere => Vec3::ZERO,
            BodyId::Duck => duck::CENTRE_OF_MASS,
        }
    }

    /// Radius (m) of the ring around a body on which the water is sampled for it: just
    /// outside its waterline, so the water it pushes up itself counts little.
    fn ring_radius(&self, id: BodyId) -> f32 {
        match id {
            BodyId::Sphere => self.params.get(ParamId::SphereRadius) * 1.1 + 0.02,
            BodyId::Duck => 0.3,
        }
    }

    /// Radius (m) of a ball standing in for a body when the two bump into each other.
    fn bump_radius(&self, id: BodyId) -> f32 {
        match id {
            BodyId::Sphere => self.params.get(ParamId::SphereRadius),
            BodyId::Duck => 0.13,
        }
    }

    /// Frames between the water heights the bodies last used and the frame that used them:
    /// 1, the heights of the water as the frame starts (sampled on the CPU at the end of the
    /// frame before, see [`HeightField::probes`]); `None` before the first frame.
    pub fn probe_latency(&self) -> Option<u64> {
        self.probe_latency
    }

    /// Volume (m³) of the bodies under water after the last step.
    pub fn submerged_volume(&self) -> f32 {
        BodyId::ALL.iter().filter(|&&id| self.shows(id)).map(|&id| self.submerged[id as usize]).sum()
    }

    /// Unit vector towards the sun.
    pub fn sun(&self) -> Vec3 {
        scene::sun_direction(self.params.get(ParamId::SunAzimuth), self.params.get(ParamId::SunElevation))
    }

    /// Sets the size (pixels) of the viewport that pointer coordinates refer to.
    pub fn set_viewport(&mut self, width: u32, height: u32) {
        self.viewport = Vec2::new(width.max(1) as f32, height.max(1) as f32);
    }

    /// Queues a drop at pool coordinates (m) with radius (m) and strength (m); values are
    /// clamped into the parameter ranges.
    pub fn add_drop(&mut self, x: f32, z: f32, radius: f32, strength: f32) {
        let r = crate::params::spec(ParamId::DropRadius).sanitise(radius);
        let s = crate::params::spec(ParamId::DropStrength).sanitise(strength);
        let w = scene::HALF_WIDTH;
        if x.is_finite() && z.is_finite() {
            self.water.add_drop(Drop { x: x.clamp(-w, w), z: z.clamp(-w, w), radius: r, strength: s });
        }
    }

    /// A drop with the current radius and strength parameters.
    fn click_drop(&mut self, x: f32, z: f32) {
        self.add_drop(x, z, self.params.get(ParamId::DropRadius), self.params.get(ParamId::DropStrength));
    }

    /// The nearest body under pixel (x, y) and the point hit (m), if any.
    pub fn pick_body(&self, pixel: Vec2) -> Option<(BodyId, Vec3)> {
        let ray = self.camera.ray(pixel, self.viewport);
        let sphere = self.sphere().and_then(|s| camera::ray_sphere(&ray, s.centre, s.radius));
        let duck = self.duck().and_then(|pose| {
            duck::TRACED_PARTS
                .iter()
                .filter_map(|p| p.shape.ray_hit(&pose, ray.origin, ray.dir))
                .min_by(|a, b| a.total_cmp(b))
        });
        let hit = |t: f32| ray.origin + ray.dir * t;
        match (sphere, duck) {
            (Some(s), Some(d)) if d < s => Some((BodyId::Duck, hit(d))),
            (Some(s), _) => Some((BodyId::Sphere, hit(s))),
            (None, Some(d)) => Some((BodyId::Duck, hit(d))),
            (None, None) => None,
        }
    }

    /// Whether a press at column `x` (pixels) grabs the split view's divider (shown only in
    /// the split view with the camera above the water).
    pub fn over_divider(&self, x: f32) -> bool {
        RenderMode::from_param(self.params.get(ParamId::RenderMode)) == RenderMode::Split
            && (x - self.params.get(ParamId::Split) * self.viewport.x).abs() <= DIVIDER_GRAB_PX
            && self.flat_water_drawn()
    }

    /// Pointer pressed at pixel (x, y): on the split view's divider moves it; on the sphere or the duck starts moving it, on the
    /// water starts drawing ripples, elsewhere starts orbiting.
    pub fn pointer_down(&mut self, x: f32, y: f32) {
        let p = Vec2::new(x, y);
        if self.over_divider(x) {
            self.drag = Drag::Divider;
            return;
        }
        if let Some((id, hit)) = self.pick_body(p) {
            let centre = self.bodies[id as usize].pose.position;
            let plane_normal = (self.camera.eye() - hit).normalize();
            self.drag = Drag::Body { id, offset: centre - hit, plane_normal, plane_point: hit };
            return;
        }
        self.drag = match self.camera.pick(p, self.viewport) {
            Pick::Water { x, z } => {
                self.click_drop(x, z);
                Drag::Water { last: p }
            }
            Pick::Nothing => Drag::Orbit { last: p },
        };
    }

    pub fn pointer_move(&mut self, x: f32, y: f32) {
        let p = Vec2::new(x, y);
        match self.drag {
            Drag::None => {}
            Drag::Divider => {
                self.params.set(ParamId::Split, x / self.viewport.x.max(1.0));
            }
            Drag::Orbit { last } => {
                let d = p - last;
                self.camera.orbit(d.x, d.y);
                self.drag = Drag::Orbit { last: p };
            }
            Drag::Water { last } => {
                // Drops along the stroke, about one per drop radius, so fast drags draw lines.
                let from = self.camera.pick(last, self.viewport);
                let to = self.camera.pick(p, self.viewport);
                if let (Pick::Water { x: x0, z: z0 }, Pick::Water { x: x1, z: z1 }) = (from, to) {
                    let r = self.params.get(ParamId::DropRadius);
                    let length = Vec2::new(x1 - x0, z1 - z0).length();
                    let count = ((length / r).ceil() as u32).clamp(1, 16);
                    for i in 1..=count {
                        let t = i as f32 / count as f32;
                        self.click_drop(x0 + (x1 - x0) * t, z0 + (z1 - z0) * t);
                    }
                } else if let Pick::Water { x, z } = to {
                    self.click_drop(x, z);
                }
                self.drag = Drag::Water { last: p };
            }
            Drag::Body { id, offset, plane_normal, plane_point } => {
                let ray = self.camera.ray(p, self.viewport);
                let denom = ray.dir.dot(plane_normal);
                if denom.abs() > 1e-5 {
                    let t = (plane_point - ray.origin).dot(plane_normal) / denom;
                    if t > 0.0 {
                        let rotation = self.bodies[id as usize].pose.rotation;
                        self.set_body_pose(id, Pose { position: ray.origin + ray.dir * t + offset, rotation });
                    }
                }
            }
        }
    }

    pub fn pointer_up(&mut self) {
        self.drag = Drag::None;
    }

    /// Mouse wheel or pinch: positive moves the camera away.
    pub fn zoom(&mut self, amount: f32) {
        self.camera.zoom((amount * 0.1).clamp(-2.0, 2.0).exp());
    }

    pub fn key(&mut self, key: Key) {
        match key {
            Key::Space => {
                let paused = self.params.flag(ParamId::Paused);
                self.params.set(ParamId::Paused, if paused { 0.0 } else { 1.0 });
            }
            Key::G => {
                // Gravity on the sphere and the duck.
                let on = self.params.flag(ParamId::Gravity);
                self.params.set(ParamId::Gravity, if on { 0.0 } else { 1.0 });
            }
            Key::L => {
                let (azimuth, elevation) = scene::direction_angles(self.camera.back());
                self.params.set(ParamId::SunAzimuth, azimuth);
                self.params.set(ParamId::SunElevation, elevation);
            }
        }
    }

    /// Remakes the ambient waves if their parameters changed.
    fn refresh_ambient(&mut self) {
        let settings = AmbientSettings::from_params(&self.params);
        if settings != self.ambient_settings {
            self.ambient = AmbientWaves::new(&settings);
            self.ambient_settings = settings;
            self.spectrum_shown = false;
        }
    }

    /// The ambient waves (heights in m at simulated time [`WaterDemo::sim_time`]).
    pub fn ambient(&self) -> &AmbientWaves {
        &self.ambient
    }

    /// The GPU's FFT ocean, once the FFT ocean has been drawn on the GPU path (for tests).
    pub fn gpu_ocean(&self) -> Option<&GpuOcean> {
        self.gpu_ocean.as_ref()
    }

    /// The water plane under each body from the newest probe heights plus the ambient waves
    /// there now (flat at the rest level before any probes have arrived).
    fn water_planes(&mut self) -> [WaterPlane; 2] {
        let frame = self.water.frames() + 1;
        let level = self.submerged_volume() / sim::pool_area(scene::HALF_WIDTH);
        let mut planes = [WaterPlane::flat(level); 2];
        let t = self.sim_time();
        // The ambient surface now, made once for both bodies' probes.
        let mut ambient_now = None;
        if let Some(samples) = self.water.probes() {
            self.probe_latency = Some(frame.saturating_sub(samples.frame));
            for id in BodyId::ALL {
                let k = id as usize * PROBES_PER_BODY;
                if let Some(heights) = samples.heights.get(k..k + PROBES_PER_BODY) {
                    let points = &samples.points[k..k + PROBES_PER_BODY];
                    let radius = points[0].distance(points[PROBES_PER_BODY / 2]) / 2.0;
                    planes[id as usize] = WaterPlane::from_ring(heights, radius);
                    if self.ambient.model != AmbientModel::None {
                        // The ambient waves on a ring of their own, at the body's waterline:
                        // the simulated water's ring keeps clear of the ripples the body
                        // makes itself (up to 0.3 m), which would average short ambient waves
                        // away or even turn them over (a 0.5 m wave on a 0.3 m ring).
                        let centre = points.iter().fold(Vec2::ZERO, |a, p| a + *p) / PROBES_PER_BODY as f32;
                        let now = ambient_now.get_or_insert_with(|| self.ambient.at(t));
                        let ring: Vec<f32> = (0..PROBES_PER_BODY)
                            .map(|i| {
                                let a = std::f32::consts::TAU * i as f32 / PROBES_PER_BODY as f32;
                                let p = centre + AMBIENT_RING_RADIUS * Vec2::new(a.cos(), a.sin());
                                now.sample(p.x, p.y)[0]
                            })
                            .collect();
                        let waves = WaterPlane::from_ring(&ring, AMBIENT_RING_RADIUS);
                        planes[id as usize] = planes[id as usize].plus(waves);
                    }
                }
            }
        }
        planes
    }

    /// Moves the bodies through `steps` fixed steps on the water planes under them; a body
    /// held by the pointer stays put. The two bump off each other. Returns, per step, how the
    /// bodies' hulls moved in it, to push the water by.
    fn step_bodies(&mut self, steps: u32) -> Vec<Vec<HullMove>> {
        let planes = self.water_planes();
        let gravity = self.params.flag(ParamId::Gravity);
        let held = match self.drag {
            Drag::Body { id, .. } => Some(id),
            _ => None,
        };
        let hulls = [self.hull(BodyId::Sphere), self.hull(BodyId::Duck)];
        let shapes = BodyId::ALL.map(|id| Shape {
            hull: &hulls[id as usize],
            centre_of_mass: Self::centre_of_mass(id),
            density: self.density(id),
        });
        let both = self.shows(BodyId::Sphere) && self.shows(BodyId::Duck);
        let mut pushes = Vec::with_capacity(steps as usize);
        for _ in 0..steps.max(1) {
            for id in BodyId::ALL {
                let k = id as usize;
                let body = &mut self.bodies[k];
                self.submerged[k] = if held == Some(id) || steps == 0 {
                    if held == Some(id) {
                        body.hold();
                    }
                    shapes[k].submerged(&body.pose, &planes[k]).0
                } else {
                    body.step(&shapes[k], gravity, &planes[k], STEP_DT)
                };
            }
            if both {
                let mass = |id: BodyId| if held == Some(id) { f32::INFINITY } else { shapes[id as usize].mass() };
                let (ms, md) = (mass(BodyId::Sphere), mass(BodyId::Duck));
                let (rs, rd) = (self.bump_radius(BodyId::Sphere), self.bump_radius(BodyId::Duck));
                let [sphere, duck] = &mut self.bodies;
                physics::separate(sphere, rs, ms, duck, rd, md);
                for (k, id) in BodyId::ALL.iter().enumerate() {
                    physics::keep_in_pool(&mut self.bodies[k].pose, &hulls[*id as usize]);
                }
            }
            if steps > 0 {
                pushes.push(self.take_pushes());
            }
        }
        pushes
    }

    /// How each body's hull moved since the water last took it in; records where it is now.
    /// A body that just appeared only records its place (the rest level accounts for it).
    fn take_pushes(&mut self) -> Vec<HullMove> {
        let mut moves = Vec::new();
        for id in BodyId::ALL {
            let k = id as usize;
            if !self.shows(id) {
                self.pushed[k] = None;
                continue;
            }
            let pose = self.bodies[k].pose;
            let current: Vec<HullSlot> = self.hull(id).iter().map(|e| e.hull_slot(&pose)).collect();
            if let Some(previous) = &self.pushed[k] {
                if !previous.iter().zip(&current).any(|(before, now)| now.moved_from(before)) {
                    continue;
                }
                moves.extend(previous.iter().zip(&current).map(|(&from, &to)| HullMove { from, to }));
            }
            self.pushed[k] = Some(current);
        }
        moves
    }

    /// Tells the water what the bodies did this frame: how their hulls moved in each step
    /// (`pushes`), the rest level their submerged volume raises, and where to sample heights
    /// for the next frames.
    fn couple_water(&mut self, pushes: Vec<Vec<HullMove>>) {
        let mut probes = Vec::with_capacity(2 * PROBES_PER_BODY);
        for id in BodyId::ALL {
            let k = id as usize;
            let pose = self.bodies[k].pose;
            if self.shows(id) && self.pushed[k].is_none() {
                self.pushed[k] = Some(self.hull(id).iter().map(|e| e.hull_slot(&pose)).collect());
            }
            let radius = self.ring_radius(id);
            for i in 0..PROBES_PER_BODY {
                let a = std::f32::consts::TAU * i as f32 / PROBES_PER_BODY as f32;
                probes.push(Vec2::new(pose.position.x, pose.position.z) + radius * Vec2::new(a.cos(), a.sin()));
            }
        }
        let rest_level = self.submerged_volume() / sim::pool_area(scene::HALF_WIDTH);
        self.water.set_bodies(BodyCoupling { moves: pushes, rest_level, probes });
    }

    /// Flattens the water and puts the bodies back where they started, at rest.
    pub fn reset(&mut self, queue: &wgpu::Queue) {
        self.water.reset(queue);
        self.bodies[BodyId::Sphere as usize] = FloatingBody::at(Pose::at(START_SPHERE_CENTRE));
        self.place_duck_at_start();
        self.pushed = [None, None];
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

    fn view(&self) -> View {
        View {
            view_proj: self.camera.view_projection(self.viewport.x / self.viewport.y),
            eye: self.camera.eye(),
            sun: self.sun(),
            sphere: self.sphere(),
            duck: self.duck(),
            caustics: self.params.flag(ParamId::Caustics),
            optics: Optics {
                fresnel: FresnelModel::from_param(self.params.get(ParamId::Fresnel)),
                specular: SpecularModel::from_param(self.params.get(ParamId::Specular)),
                shininess: self.params.get(ParamId::Shininess),
                sun_size: self.params.get(ParamId::SunSize),
                show_reflectance: self.params.get(ParamId::DebugView).round() as i32 == REFLECTANCE_VIEW,
                absorption: Vec3::new(
                    self.params.get(ParamId::AbsorptionRed),
                    self.params.get(ParamId::AbsorptionGreen),
                    self.params.get(ParamId::AbsorptionBlue),
                ),
                scatter: Vec3::new(
                    self.params.get(ParamId::ScatterRed),
                    self.params.get(ParamId::ScatterGreen),
                    self.params.get(ParamId::ScatterBlue),
                ),
                view_colour: self.params.flag(ParamId::ViewColour),
                dispersion: self.params.get(ParamId::Dispersion),
            },
            ambient: {
                let (waves, header) = self.ambient.uniform(self.sim_time());
                AmbientView { model: self.ambient.model, waves, header }
            },
            foam: self.water.foam().is_some(),
            debug: DebugTexture::from_param(self.params.get(ParamId::DebugView))
                .map(|texture| DebugView { texture, inset: self.params.flag(ParamId::DebugInset) }),
            render_scale: self.render_scale,
            flat: self.flat_view(),
            exposure: self.params.get(ParamId::Exposure),
            deck: self.on_deck(),
        }
    }

    /// Whether the pool is sunk in the deck (`setting` deck) rather than the cut-away box.
    fn on_deck(&self) -> bool {
        self.params.get(ParamId::Setting).round() == 0.0
    }

    /// The flat water settings in the parameters (`None` when ray-traced).
    fn flat_view(&self) -> Option<FlatView> {
        let mode = RenderMode::from_param(self.params.get(ParamId::RenderMode));
        let scroll = self.params.get(ParamId::DudvSpeed) as f64 * self.sim_time();
        (mode != RenderMode::RayTraced).then(|| FlatView {
            mode,
            split: self.params.get(ParamId::Split),
            distortion: Distortion::from_param(self.params.get(ParamId::FlatDistortion)),
            strength: self.params.get(ParamId::FlatStrength),
            move_factor: (scroll - scroll.floor()) as f32,
            resolution: self.params.get(ParamId::FlatResolution),
            caustics: FlatCaustics::from_param(self.params.get(ParamId::FlatCaustics)),
            soft_edge: self.params.get(ParamId::FlatSoftEdge),
            plane: self.submerged_volume() / sim::pool_area(scene::HALF_WIDTH),
        })
    }

    /// The flat water's reflection texture, once flat water has been drawn (for tests).
    #[doc(hidden)]
    pub fn flat_reflection_texture(&self) -> Option<&wgpu::Texture> {
        self.renderer.flat_reflection_texture()
    }

    /// Whether the flat water is drawn now: flat or split chosen and the camera above the
    /// water (it is an above-water technique; under water the ray tracer draws).
    pub fn flat_water_drawn(&self) -> bool {
        crate::render::flat_shown(&self.view()).is_some()
    }

    /// Why the chosen flat water is not drawn, if it is not (for the page and the viewer).
    pub fn flat_water_note(&self) -> Option<&'static str> {
        let mode = RenderMode::from_param(self.params.get(ParamId::RenderMode));
        (mode != RenderMode::RayTraced && !self.flat_water_drawn())
            .then_some("Flat water is an above-water technique: under the water the ray tracer draws.")
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
        self.encode_frame(device, queue, &mut encoder, target, size, frame_time, &mut |_, _| {});
        queue.submit([encoder.finish()]);
        self.after_submit();
        // Never waits: only lets finished readbacks (water statistics, body probes) complete.
        let _ = device.poll(wgpu::PollType::Poll);
    }

    /// Call after submitting a frame recorded with [`WaterDemo::encode_frame`]: starts any
    /// asynchronous read of the water statistics ([`WaterDemo::water_level`]) and the
    /// objects' water samples not yet started (encode_frame starts them already).
    pub fn after_submit(&self) {
        self.water.after_submit();
    }

    /// Mean and largest |height| of the water (m), read back asynchronously, a frame or
    /// two old; `None` before the first read has completed.
    pub fn water_level(&self) -> Option<WaterLevel> {
        self.water.level()
    }

    /// Simulates a frame (submitted at once, in a command buffer of its own) and records its
    /// drawing into `encoder`; `mark` is called at each [`Stage`] boundary (for timestamps;
    /// the first two in the simulation's encoder). Writes uniform buffers, so submit before
    /// encoding another frame.
    #[allow(clippy::too_many_arguments)]
    pub fn encode_frame(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        size: (u32, u32),
        frame_time: f32,
        mark: &mut dyn FnMut(&mut wgpu::CommandEncoder, Stage),
    ) {
        self.set_viewport(size.0, size.1);
        if self.on_deck() {
            // The camera stays above the paving.
            self.camera.keep_eye_above(scene::RIM + crate::render::EYE_CLEARANCE);
        }
        self.refresh_ambient();
        self.choose_render_scale(frame_time);
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
        if let Some(ocean) = &self.ambient.ocean {
            let t = self.sim_time();
            if self.ocean_on_gpu {
                let size = ocean.size as u32;
                if self.gpu_ocean.as_ref().is_none_or(|g| g.size() != size) {
                    let made = GpuOcean::new(device, size);
                    self.renderer.use_ambient_views(device, &self.water, [made.surface(), made.displacement()]);
                    self.gpu_ocean = Some(made);
                }
                if let Some(gpu_ocean) = &mut self.gpu_ocean {
                    gpu_ocean.encode(queue, encoder, ocean, t);
                }
            } else {
                let surface = ocean.surface(t);
                let displacement = (ocean.choppiness > 0.0).then(|| ocean.displacement(t));
                let maps = [Some(&surface[..]), displacement.as_deref()];
                self.renderer.upload_ambient(device, queue, &self.water, ocean.size as u32, maps);
            }
        }
        self.renderer.prepare(queue, encoder, &view, &self.water);
        self.renderer.encode_caustics(device, encoder, &view, &self.water);
        mark(encoder, Stage::AfterCaustics);
        self.renderer.encode_scene(device, encoder, target, size, &view, &self.water);
        mark(encoder, Stage::AfterScene);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn creation_options_clamp_and_snap_to_their_specs() {
        assert_eq!(
            DemoOptions::clamped(300, 4, 99_999),
            DemoOptions { sim_size: 256, surface_grid: 16, caustics_size: 2048, float_targets: true }
        );
        assert_eq!(DemoOptions::clamped(5000, 100, 700).sim_size, 1024);
        assert_eq!(DemoOptions::clamped(0, 100, 700).sim_size, 128);
        let d = DemoOptions::default();
        assert_eq!(DemoOptions::clamped(d.sim_size, d.surface_grid, d.caustics_size), d, "defaults lie in range");
    }
}
