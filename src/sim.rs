//! The water: a heightfield on the GPU advanced by the damped 2-D wave equation in
//! full-screen fragment passes (so WebGL2, without compute shaders, runs the same code).
//! State per cell: height above rest (m), vertical velocity (m/s), normal x and z.

use glam::{Mat3, Vec2, Vec3};

use crate::gpu::{self, FullscreenPass, FullscreenTarget, PingPong};

pub mod cpu;

/// Format of the state textures: 32-bit floats, read with `textureLoad` only (no filtering).
pub const STATE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;
/// Drops the drop pass applies at once; more wait for the next frame.
pub const MAX_DROPS_PER_PASS: usize = 32;
/// Largest Courant number c dt / dx a step may use; the 2-D scheme is stable up to 1/sqrt(2).
pub const MAX_COURANT: f32 = 0.6;

/// A drop: a smooth cosine bump, zero-mean corrected over the pool.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drop {
    /// Centre (m).
    pub x: f32,
    pub z: f32,
    /// Radius (m).
    pub radius: f32,
    /// Height of the bump's centre (m); negative dips.
    pub strength: f32,
}

/// One ellipsoid of a body as the displacement pass takes it: its centre (m) and the matrix
/// taking offsets from the centre (m) into the unit ball.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HullSlot {
    pub centre: Vec3,
    pub unit_from_world: Mat3,
}

/// How far (m) an ellipsoid's centre must move before it pushes the water. A body floating at
/// rest jitters by less; its small moves wait and join a later push (from where it last
/// pushed to where it is), so nothing is lost and a still body runs no pass.
pub const PUSH_MIN_MOVE: f32 = 2.0e-4;

impl HullSlot {
    /// Whether the ellipsoid has moved far enough from `before` to push the water: its centre
    /// by more than [`PUSH_MIN_MOVE`], or its orientation or shape by about as much at its surface.
    pub fn moved_from(&self, before: &HullSlot) -> bool {
        let turned = (self.unit_from_world - before.unit_from_world).to_cols_array();
        self.centre.distance(before.centre) > PUSH_MIN_MOVE || turned.iter().any(|d| d.abs() > 50.0 * PUSH_MIN_MOVE)
    }

    /// The ellipsoid's reach over the pool (m): its half extents along x and z (it pushes no
    /// water outside centre ± reach).
    pub fn reach(&self) -> Vec2 {
        let to_world = self.unit_from_world.inverse();
        // Support of the ellipsoid along x and z: the length of that row of the matrix.
        Vec2::new(to_world.row(0).length(), to_world.row(2).length())
    }
}

/// Cells of an `n` x `n` grid: columns `x.0..=x.1`, rows `z.0..=z.1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CellRange {
    pub x: (u32, u32),
    pub z: (u32, u32),
}

impl CellRange {
    pub fn all(n: u32) -> Self {
        Self { x: (0, n - 1), z: (0, n - 1) }
    }

    /// The cells whose centres lie within the ellipsoids' reach (plus the cell around each end).
    pub fn under(hulls: &[HullSlot], n: u32, half_width: f32) -> Self {
        let (mut lo, mut hi) = (Vec2::splat(f32::INFINITY), Vec2::splat(f32::NEG_INFINITY));
        for hull in hulls {
            let c = Vec2::new(hull.centre.x, hull.centre.z);
            lo = lo.min(c - hull.reach());
            hi = hi.max(c + hull.reach());
        }
        if !(lo.is_finite() && hi.is_finite()) {
            return Self::all(n);
        }
        let dx = 2.0 * half_width / n as f32;
        let last = n as f32 - 1.0;
        let index = |v: f32| ((v + half_width) / dx - 0.5).clamp(0.0, last);
        Self {
            x: (index(lo.x).floor() as u32, index(hi.x).ceil() as u32),
            z: (index(lo.y).floor() as u32, index(hi.y).ceil() as u32),
        }
    }

    /// The smallest range holding both.
    pub fn union(self, other: Self) -> Self {
        Self {
            x: (self.x.0.min(other.x.0), self.x.1.max(other.x.1)),
            z: (self.z.0.min(other.z.0), self.z.1.max(other.z.1)),
        }
    }

    pub fn cells(&self) -> u32 {
        (self.x.1 + 1 - self.x.0) * (self.z.1 + 1 - self.z.0)
    }
}

/// An ellipsoid's move since the water last took the bodies in (see [`displaced_column`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HullMove {
    pub from: HullSlot,
    pub to: HullSlot,
}

/// Most ellipsoid moves one step passes to the water (the sphere, and the duck's body and head).
pub const MAX_HULL_MOVES: usize = 3;
/// Steps of one frame whose body moves are applied each before its own step (later steps' moves
/// are added to the last), so that the water is pushed the same at any frame rate.
pub const MAX_PUSH_STEPS: usize = 4;
/// Cells per side of the CPU copy of the water the GPU engine keeps for the bodies' buoyancy
/// (at most; a smaller grid keeps its own size). It gets the same drops, pushes and steps, so
/// it holds the same waves at a resolution that still resolves everything a body of 0.2 m or
/// more responds to, for about 0.1 ms per step.
pub const SHADOW_SIZE: u32 = 128;
/// Most points the water is sampled at for the bodies each frame.
pub const MAX_PROBES: usize = 16;
/// Depth (m) over which a body's push on the surface fades (see [`displaced_column`]).
pub const DISPLACEMENT_DEPTH: f32 = 0.1;
/// Area of the pool's water surface (m²) for a half width of 1 m; scale by half width².
pub fn pool_area(half_width: f32) -> f32 {
    4.0 * half_width * half_width
}

/// How much water (m, a column height) a body's ellipsoid pushes up at pool point (x, z): the
/// part of the vertical line through (x, z) inside the ellipsoid and below the rest level,
/// each depth y weighted by exp(y / [`DISPLACEMENT_DEPTH`]). A body moving from `from` to `to`
/// raises the surface by column(to) - column(from): water ahead of it and above it rises and
/// falls behind it, fully submerged too (weaker the deeper it is), and a body entering the
/// water pushes its volume out around itself. (`shaders/sim_drop.wgsl` mirrors this.)
pub fn displaced_column(x: f32, z: f32, hull: &HullSlot) -> f32 {
    let u0 = hull.unit_from_world * (Vec3::new(x, 0.0, z) - hull.centre);
    let d = hull.unit_from_world.col(1);
    let (a, b, c) = (d.dot(d), u0.dot(d), u0.dot(u0) - 1.0);
    let disc = b * b - a * c;
    if disc <= 0.0 || a <= 0.0 {
        return 0.0;
    }
    let s = disc.sqrt();
    let y0 = (-b - s) / a;
    let y1 = ((-b + s) / a).min(0.0);
    if y1 <= y0 {
        return 0.0;
    }
    DISPLACEMENT_DEPTH * ((y1 / DISPLACEMENT_DEPTH).exp() - (y0 / DISPLACEMENT_DEPTH).exp())
}

/// What the bodies in the pool do to the water in a frame, set before [`HeightField::encode`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BodyCoupling {
    /// Per step of the frame, the ellipsoid moves to push the water by before that step (at
    /// most [`MAX_HULL_MOVES`] per step, [`MAX_PUSH_STEPS`] steps).
    pub moves: Vec<Vec<HullMove>>,
    /// Mean height (m) the water is held at: the bodies' submerged volume over the pool's
    /// area, because that volume of water has been pushed up into the surface.
    pub rest_level: f32,
    /// Points (x, z in m) to sample the water at for the bodies' buoyancy (at most
    /// [`MAX_PROBES`]); see [`HeightField::probes`].
    pub probes: Vec<Vec2>,
}

/// Heights sampled for the bodies.
#[derive(Clone, Debug, PartialEq)]
pub struct ProbeSamples {
    /// The points (x, z in m) asked for.
    pub points: Vec<Vec2>,
    /// Water height at each (m).
    pub heights: Vec<f32>,
    /// Frame ([`HeightField::frames`]) whose water they were sampled from.
    pub frame: u64,
}

/// Physical settings of a step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaveSettings {
    /// Wave speed c (m/s).
    pub wave_speed: f32,
    /// Velocity damping rate k (1/s).
    pub damping: f32,
    /// Absorbing walls: a sponge layer along the walls (see [`sponge_profile`]) instead of
    /// purely reflecting walls.
    pub absorbing_walls: bool,
}

impl WaveSettings {
    /// Reflecting walls.
    pub fn reflecting(wave_speed: f32, damping: f32) -> Self {
        Self { wave_speed, damping, absorbing_walls: false }
    }
}

/// Width (m) of the damping layer along each wall when the walls absorb.
pub const SPONGE_WIDTH: f32 = 0.25;

/// Damping rate at the wall, in units of c / SPONGE_WIDTH: with the quadratic profile a wave
/// crossing the layer and back loses amplitude by about exp(-2 * 12 / 3) = 3e-4, while the
/// gentle ramp keeps its own reflection small.
const SPONGE_STRENGTH: f32 = 12.0;

/// Shape of the sponge layer at pool point (x, z) (m): 0 farther than [`SPONGE_WIDTH`] from
/// every wall, rising quadratically to 1 at the wall. Both height and velocity decay there at
/// `sponge rate * profile` per second, which swallows outgoing waves.
pub fn sponge_profile(x: f32, z: f32, half_width: f32) -> f32 {
    let from_wall = half_width - x.abs().max(z.abs());
    let t = (1.0 - from_wall / SPONGE_WIDTH).max(0.0);
    t * t
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct SimUniforms {
    grid: [f32; 4],
    step: [f32; 4],
    bounds: [f32; 4],
    drops_info: [f32; 4],
    drops: [[f32; 4]; MAX_DROPS_PER_PASS],
    bodies: [f32; 4],
    hulls: [[f32; 4]; MAX_PUSH_STEPS * MAX_HULL_MOVES * 8],
}

/// Largest |height| an update may leave (m); it clamps to it and replaces NaN or infinity
/// by rest. The once-per-frame mean subtraction can move a clamped cell by at most the
/// mean, itself at most MAX_HEIGHT, so |h| <= 2 * MAX_HEIGHT = 0.16 m always: below the
/// 1/6 m rim, no wave ever overtops the pool.
pub const MAX_HEIGHT: f32 = 0.08;
/// Largest |vertical velocity| the state may hold (m/s).
pub const MAX_VELOCITY: f32 = 5.0;

/// Everything one batch of steps needs, worked out once on the CPU and used by both the
/// GPU passes and the CPU reference, so the two run the same arithmetic.
#[derive(Clone, Debug, PartialEq)]
pub struct StepPlan {
    /// Drops applied before the steps.
    pub drops: Vec<Drop>,
    /// Uniform height (m) subtracted with the drops so they add no water.
    pub correction: f32,
    /// Update passes to run (steps times substeps).
    pub updates: u32,
    /// Length of one update (s).
    pub dt: f32,
    /// c^2 dt / dx^2 of one update.
    pub coupling: f32,
    /// Factor exp(-k dt) applied to the velocity each update.
    pub velocity_decay: f32,
    /// Sponge damping rate at the wall (1/s); 0 for reflecting walls.
    pub sponge_rate: f32,
    /// Body moves per step: the first step's with the drops, each later one's before its step.
    pub moves: Vec<Vec<HullMove>>,
    /// Mean height the water is held at (m); heights are bounded around it.
    pub rest_level: f32,
}

impl StepPlan {
    /// Plans `steps` steps of `dt` seconds on an `n` x `n` grid over a pool of `half_width`
    /// (m), taking at most [`MAX_DROPS_PER_PASS`] drops from the front of `pending`.
    pub fn new(pending: &mut Vec<Drop>, n: u32, half_width: f32, steps: u32, dt: f32, settings: WaveSettings) -> Self {
        let take = pending.len().min(MAX_DROPS_PER_PASS);
        let drops: Vec<Drop> = pending.drain(..take).collect();
        let dx = 2.0 * half_width / n as f32;
        let substeps = substeps(dt, settings.wave_speed, dx);
        let h = dt / substeps as f32;
        Self {
            correction: drops.iter().map(|d| drop_mean(d, n, half_width)).sum(),
            drops,
            updates: steps * substeps,
            dt: h,
            coupling: settings.wave_speed * settings.wave_speed * h / (dx * dx),
            velocity_decay: (-settings.damping.max(0.0) * h).exp(),
            sponge_rate: if settings.absorbing_walls {
                SPONGE_STRENGTH * settings.wave_speed.abs() / SPONGE_WIDTH
            } else {
                0.0
            },
            moves: Vec::new(),
            rest_level: 0.0,
        }
    }

    /// Whether the drop pass has anything to do before step `step` (0: with the drops). A
    /// body that did not move pushes nothing.
    pub fn pushes_water(&self, step: usize) -> bool {
        (step == 0 && !self.drops.is_empty()) || self.moves.get(step).is_some_and(|m| m.iter().any(|m| m.from != m.to))
    }

    /// The cells the drop pass before step `step` changes on an `n` x `n` grid: all of them
    /// with drops (their correction is subtracted everywhere), else only those under the
    /// moving ellipsoids, so bodies cost in proportion to their size, not the pool's.
    pub fn pushed_cells(&self, step: usize, n: u32, half_width: f32) -> CellRange {
        if step == 0 && !self.drops.is_empty() {
            return CellRange::all(n);
        }
        let moved = self.moves.get(step).into_iter().flatten().filter(|m| m.from != m.to);
        moved
            .map(|m| CellRange::under(&[m.from, m.to], n, half_width))
            .reduce(CellRange::union)
            .unwrap_or(CellRange { x: (0, 0), z: (0, 0) })
    }

    /// Updates (substeps) per step.
    pub fn updates_per_step(&self, steps: u32) -> u32 {
        self.updates.checked_div(steps).unwrap_or(0)
    }

    /// Whether the normals need recomputing after this batch.
    pub fn changes_state(&self) -> bool {
        self.updates > 0 || (0..self.moves.len().max(1)).any(|k| self.pushes_water(k))
    }
}

/// Updates per step of `dt` seconds that keep the Courant number c dt / dx of each at or
/// below [`MAX_COURANT`] on cells of `dx` metres.
pub fn substeps(dt: f32, wave_speed: f32, dx: f32) -> u32 {
    let courant = wave_speed.abs() * dt / dx;
    if courant.is_finite() {
        ((courant / MAX_COURANT).ceil() as u32).max(1)
    } else {
        1
    }
}

/// Shape of a drop at distance `d` from its centre, 1 at the centre and 0 from the radius on.
pub fn drop_shape(d: f32, radius: f32) -> f32 {
    0.5 - 0.5 * (std::f32::consts::PI * (1.0 - d / radius).max(0.0)).cos()
}

/// Mean of a drop's bump over all cells of an `n` x `n` grid on the pool: subtracting
/// it everywhere makes the drop add no water.
pub fn drop_mean(drop: &Drop, n: u32, half_width: f32) -> f32 {
    let dx = 2.0 * half_width / n as f32;
    let index = |x: f32| ((x + half_width) / dx - 0.5).clamp(0.0, n as f32 - 1.0);
    let (i0, i1) = (index(drop.x - drop.radius).floor() as u32, index(drop.x + drop.radius).ceil() as u32);
    let (j0, j1) = (index(drop.z - drop.radius).floor() as u32, index(drop.z + drop.radius).ceil() as u32);
    let mut sum = 0.0f64;
    for j in j0..=j1 {
        let z = -half_width + (j as f32 + 0.5) * dx;
        for i in i0..=i1 {
            let x = -half_width + (i as f32 + 0.5) * dx;
            let d = ((x - drop.x).powi(2) + (z - drop.z).powi(2)).sqrt();
            sum += drop_shape(d, drop.radius) as f64;
        }
    }
    (sum / (n as f64 * n as f64)) as f32 * drop.strength
}

/// Fixed simulation time step with an accumulator: whatever the frame rate, the water
/// advances in steps of `dt` seconds of simulated time.
#[derive(Clone, Debug)]
pub struct FixedStep {
    /// Step length (s).
    pub dt: f32,
    /// Most steps one frame may take; the rest of a long frame is dropped so a slow
    /// device cannot spiral.
    pub max_steps: u32,
    accumulator: f32,
}

impl FixedStep {
    pub fn new(dt: f32, max_steps: u32) -> Self {
        Self { dt, max_steps, accumulator: 0.0 }
    }

    /// Adds a frame's duration (s) and returns how many steps to take now.
    pub fn advance(&mut self, frame_time: f32) -> u32 {
        if frame_time.is_finite() && frame_time > 0.0 {
            self.accumulator += frame_time.min(1.0);
        }
        // A tiny tolerance keeps 1/60 s frames from alternating 1 and 3 steps by rounding.
        let steps = ((self.accumulator + 1e-6) / self.dt).floor() as u32;
        let taken = steps.min(self.max_steps);
        self.accumulator =
            if steps > self.max_steps { 0.0 } else { (self.accumulator - taken as f32 * self.dt).max(0.0) };
        taken
    }
}

/// Where the water is simulated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SimEngine {
    /// Full-screen fragment passes into float render targets (the normal path).
    Gpu,
    /// The CPU reference ([`cpu::CpuHeightField`]), its state uploaded to the same texture
    /// each frame: for devices that cannot render to float textures (many phones, WebGL2
    /// without EXT_color_buffer_float). Same arithmetic, so the same water.
    Cpu,
}

/// The GPU engine's passes and buffers.
struct GpuSim {
    uniforms: wgpu::Buffer,
    layout: wgpu::BindGroupLayout,
    bind_groups: [wgpu::BindGroup; 2],
    /// Per step of a frame, a group telling the drop pass which step's moves to apply.
    step_groups: Vec<wgpu::BindGroup>,
    drop_pass: FullscreenPass,
    resample_pass: FullscreenPass,
    update_pass: FullscreenPass,
    normals_pass: FullscreenPass,
    mean: MeanLevel,
    probe: LevelProbe,
    /// The water again, on the CPU at [`SHADOW_SIZE`], for the bodies' buoyancy.
    shadow: Box<cpu::CpuHeightField>,
}

enum Engine {
    Gpu(Box<GpuSim>),
    /// `upload`: the interleaved state written to the texture, kept between frames.
    Cpu {
        water: Box<cpu::CpuHeightField>,
        level: Option<WaterLevel>,
        upload: Vec<[f32; 4]>,
    },
}

/// The heightfield: the state textures the renderer reads, the engine that advances them,
/// and queued drops.
pub struct HeightField {
    size: u32,
    half_width: f32,
    state: PingPong,
    engine: Engine,
    pending: Vec<Drop>,
    coupling: BodyCoupling,
    /// Frames encoded so far.
    frames: u64,
    probes: Option<ProbeSamples>,
}

/// Format of the level reduction textures: x mean height (m), y largest |height| (m).
const LEVEL_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;

/// The water's mean height and largest |height|, found on the GPU by folding 2x2 blocks level
/// by level down to one texel (`shaders/sim_mean.wgsl`), so the mean can be subtracted without
/// a readback.
struct MeanLevel {
    views: Vec<wgpu::TextureView>,
    result: wgpu::Texture,
    from_state: [wgpu::BindGroup; 2],
    from_level: Vec<wgpu::BindGroup>,
    state_pass: FullscreenPass,
    level_pass: FullscreenPass,
}

impl MeanLevel {
    fn new(device: &wgpu::Device, state: &PingPong, size: u32) -> Self {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("mean level layout"),
            entries: &[gpu::texture_entry(
                0,
                wgpu::ShaderStages::FRAGMENT,
                wgpu::TextureSampleType::Float { filterable: false },
                wgpu::TextureViewDimension::D2,
            )],
        });
        let group = |view: &wgpu::TextureView| {
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("mean level group"),
                layout: &layout,
                entries: &[wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(view) }],
            })
        };
        let mut textures = Vec::new();
        let mut side = size / 2;
        while side >= 1 {
            let usage = wgpu::TextureUsages::RENDER_ATTACHMENT
                | wgpu::TextureUsages::TEXTURE_BINDING
                | wgpu::TextureUsages::COPY_SRC;
            textures.push(gpu::texture_2d(device, "water level", side, side, 1, 1, LEVEL_FORMAT, usage));
            side /= 2;
        }
        let views: Vec<_> = textures.iter().map(|t| t.create_view(&Default::default())).collect();
        let from_level = views[..views.len() - 1].iter().map(group).collect();
        let pass = |entry: &str| {
            FullscreenPass::new(
                device,
                "sim water level",
                &[gpu::wgsl::SIM_MEAN],
                entry,
                &[&layout],
                FullscreenTarget { format: LEVEL_FORMAT, blend: None, depth: None },
            )
        };
        Self {
            from_state: state.bind_groups(group),
            from_level,
            views,
            result: textures.pop().expect("at least one level"),
            state_pass: pass("fs_reduce_state"),
            level_pass: pass("fs_reduce_level"),
        }
    }

    /// Records the reduction of the state texture `current` down to [`MeanLevel::result_view`].
    fn encode(&self, encoder: &mut wgpu::CommandEncoder, current: usize) {
        self.state_pass.run(encoder, &self.views[0], &[&self.from_state[current]]);
        for (group, target) in self.from_level.iter().zip(&self.views[1..]) {
            self.level_pass.run(encoder, target, &[group]);
        }
    }

    /// The one-texel texture holding (mean height, largest |height|) in m.
    fn result_view(&self) -> &wgpu::TextureView {
        self.views.last().expect("at least one level")
    }
}

/// Water statistics read back from the GPU, a frame or two old.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WaterLevel {
    /// Mean height above rest before the frame's correction (m).
    pub mean: f32,
    /// Largest |height| over the pool (m).
    pub max_abs: f32,
}

/// Reads the one-texel [`MeanLevel`] result back without ever waiting (see
/// [`gpu::AsyncReadback`]): the statistics are one to a few frames old.
struct LevelProbe {
    readback: gpu::AsyncReadback,
    latest: Option<WaterLevel>,
}

impl LevelProbe {
    fn new(device: &wgpu::Device) -> Self {
        Self { readback: gpu::AsyncReadback::new(device, "water level readback", 16), latest: None }
    }

    /// Takes a finished read and, when idle, records a new copy of `result`.
    fn encode(&mut self, encoder: &mut wgpu::CommandEncoder, result: &wgpu::Texture) {
        if let Some(bytes) = self.readback.take() {
            let v: [f32; 4] = bytemuck::pod_read_unaligned(&bytes[..16]);
            self.latest = Some(WaterLevel { mean: v[0], max_abs: v[1] });
        }
        if let Some(buffer) = self.readback.record() {
            encoder.copy_texture_to_buffer(
                result.as_image_copy(),
                wgpu::TexelCopyBufferInfo {
                    buffer,
                    layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: None, rows_per_image: None },
                },
                wgpu::Extent3d { width: 1, height: 1, depth_or_array_layers: 1 },
            );
        }
    }

    /// Starts mapping a copy recorded into a frame that has now been submitted.
    fn after_submit(&self) {
        self.readback.after_submit();
    }
}

impl GpuSim {
    fn new(device: &wgpu::Device, state: &PingPong, size: u32, half_width: f32) -> Self {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("sim layout"),
            entries: &[
                gpu::uniform_entry(0, wgpu::ShaderStages::FRAGMENT),
                gpu::texture_entry(
                    1,
                    wgpu::ShaderStages::FRAGMENT,
                    wgpu::TextureSampleType::Float { filterable: false },
                    wgpu::TextureViewDimension::D2,
                ),
                gpu::texture_entry(
                    2,
                    wgpu::ShaderStages::FRAGMENT,
                    wgpu::TextureSampleType::Float { filterable: false },
                    wgpu::TextureViewDimension::D2,
                ),
            ],
        });
        let uniforms = gpu::uniform_buffer(device, "sim uniforms", &SimUniforms::zeroed());
        let mean = MeanLevel::new(device, state, size);
        let bind_groups = state.bind_groups(|view| {
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("sim bind group"),
                layout: &layout,
                entries: &[
                    wgpu::BindGroupEntry { binding: 0, resource: uniforms.as_entire_binding() },
                    wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(view) },
                    wgpu::BindGroupEntry {
                        binding: 2,
                        resource: wgpu::BindingResource::TextureView(mean.result_view()),
                    },
                ],
            })
        });
        let pass = |label: &str, source: &str, entry: &str| {
            FullscreenPass::new(
                device,
                label,
                &[gpu::wgsl::SIM_SHARED, source],
                entry,
                &[&layout],
                FullscreenTarget { format: STATE_FORMAT, blend: None, depth: None },
            )
        };
        let step_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("sim step layout"),
            entries: &[gpu::uniform_entry(0, wgpu::ShaderStages::FRAGMENT)],
        });
        let step_groups = (0..MAX_PUSH_STEPS)
            .map(|k| {
                let buffer = gpu::uniform_buffer(device, "sim step", &[k as f32, 0.0, 0.0, 0.0]);
                device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("sim step group"),
                    layout: &step_layout,
                    entries: &[wgpu::BindGroupEntry { binding: 0, resource: buffer.as_entire_binding() }],
                })
            })
            .collect();
        let drop_pass = FullscreenPass::new(
            device,
            "sim drop",
            &[gpu::wgsl::SIM_SHARED, gpu::wgsl::SIM_DROP],
            "fs_drop",
            &[&layout, &step_layout],
            FullscreenTarget { format: STATE_FORMAT, blend: None, depth: None },
        );
        Self {
            drop_pass,
            step_groups,
            update_pass: pass("sim update", gpu::wgsl::SIM_UPDATE, "fs_update"),
            normals_pass: pass("sim normals", gpu::wgsl::SIM_NORMALS, "fs_normals"),
            resample_pass: pass("sim resample", gpu::wgsl::SIM_RESAMPLE, "fs_resample"),
            uniforms,
            layout,
            bind_groups,
            mean,
            probe: LevelProbe::new(device),
            shadow: Box::new(cpu::CpuHeightField::new(size.min(SHADOW_SIZE), half_width)),
        }
    }

    fn write_uniforms(&self, queue: &wgpu::Queue, plan: &StepPlan, size: u32, half_width: f32) {
        let mut u = SimUniforms::zeroed();
        u.grid = [size as f32, 1.0 / size as f32, 2.0 * half_width / size as f32, half_width];
        u.step = [plan.dt, plan.coupling, plan.velocity_decay, plan.sponge_rate];
        u.bounds = [MAX_HEIGHT, MAX_VELOCITY, SPONGE_WIDTH, 0.0];
        u.drops_info = [plan.drops.len() as f32, plan.correction, 0.0, 0.0];
        for (slot, d) in u.drops.iter_mut().zip(&plan.drops) {
            *slot = [d.x, d.z, d.radius, d.strength];
        }
        let per_step = plan.moves.iter().map(Vec::len).max().unwrap_or(0);
        u.bodies = [per_step as f32, plan.rest_level, DISPLACEMENT_DEPTH, 0.0];
        for (step, moves) in plan.moves.iter().enumerate().take(MAX_PUSH_STEPS) {
            let slots = &mut u.hulls[step * MAX_HULL_MOVES * 8..][..MAX_HULL_MOVES * 8];
            // Steps with fewer moves keep zero entries: a zero matrix displaces nothing.
            for (slots, m) in slots.chunks_mut(8).zip(moves) {
                for (k, hull) in [m.from, m.to].iter().enumerate() {
                    slots[4 * k] = hull.centre.extend(0.0).to_array();
                    for c in 0..3 {
                        slots[4 * k + 1 + c] = hull.unit_from_world.col(c).extend(0.0).to_array();
                    }
                }
            }
        }
        queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&u));
    }
}

impl HeightField {
    /// A calm `size` x `size` heightfield over a pool of the given half width (m), simulated
    /// on the GPU.
    pub fn new(device: &wgpu::Device, size: u32, half_width: f32) -> Self {
        Self::new_on(device, size, half_width, SimEngine::Gpu)
    }

    /// A calm heightfield simulated by `engine`. The CPU engine's state texture is only
    /// sampled and written from the CPU, never rendered to.
    pub fn new_on(device: &wgpu::Device, size: u32, half_width: f32, engine: SimEngine) -> Self {
        assert!(size.is_power_of_two() && size >= 16, "simulation size must be a power of two, at least 16");
        let state = PingPong::new(device, "water state", size, size, STATE_FORMAT, engine == SimEngine::Gpu);
        let engine = match engine {
            SimEngine::Gpu => Engine::Gpu(Box::new(GpuSim::new(device, &state, size, half_width))),
            SimEngine::Cpu => Engine::Cpu {
                water: Box::new(cpu::CpuHeightField::new(size, half_width)),
                level: None,
                upload: Vec::new(),
            },
        };
        Self {
            size,
            half_width,
            state,
            engine,
            pending: Vec::new(),
            coupling: BodyCoupling::default(),
            frames: 0,
            probes: None,
        }
    }

    /// Which engine advances this heightfield.
    pub fn engine(&self) -> SimEngine {
        match self.engine {
            Engine::Gpu(_) => SimEngine::Gpu,
            Engine::Cpu { .. } => SimEngine::Cpu,
        }
    }

    /// Cells per side.
    pub fn size(&self) -> u32 {
        self.size
    }

    /// Queues a drop for the next [`HeightField::encode`]. Degenerate drops are ignored.
    pub fn add_drop(&mut self, drop: Drop) {
        let ok = [drop.x, drop.z, drop.radius, drop.strength].iter().all(|v| v.is_finite());
        if ok && drop.radius > 0.0 && drop.strength != 0.0 {
            match &mut self.engine {
                Engine::Gpu(sim) => {
                    self.pending.push(drop);
                    sim.shadow.add_drop(drop);
                }
                Engine::Cpu { water, .. } => water.add_drop(drop),
            }
        }
    }

    /// Records the queued drops, `steps` steps of `dt` seconds each, the mean level and the
    /// normals pass (which also brings the mean level back to rest).
    /// Writes the shared uniform buffer, so call it once per queue submission.
    pub fn encode(
        &mut self,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        steps: u32,
        dt: f32,
        settings: WaveSettings,
    ) {
        self.frames += 1;
        // Moves and probes are used once; the rest level stays until set again.
        let mut coupling = BodyCoupling {
            moves: std::mem::take(&mut self.coupling.moves),
            rest_level: self.coupling.rest_level,
            probes: std::mem::take(&mut self.coupling.probes),
        };
        coupling.moves = merge_push_steps(coupling.moves);
        coupling.probes.truncate(MAX_PROBES);
        let sim = match &mut self.engine {
            Engine::Gpu(sim) => sim,
            Engine::Cpu { water, level, upload: cells } => {
                if water.advance_with(steps, dt, settings, coupling.moves, coupling.rest_level) {
                    upload(queue, self.state.current_texture(), water, cells);
                    *level = Some(water.level());
                }
                if !coupling.probes.is_empty() {
                    let heights = coupling.probes.iter().map(|p| water.height_at(p.x, p.y)).collect();
                    self.probes = Some(ProbeSamples { points: coupling.probes, heights, frame: self.frames });
                }
                return;
            }
        };
        let mut plan = StepPlan::new(&mut self.pending, self.size, self.half_width, steps, dt, settings);
        plan.moves = coupling.moves;
        plan.rest_level = coupling.rest_level;
        sim.shadow.advance_with(steps, dt, settings, plan.moves.clone(), plan.rest_level);
        if !coupling.probes.is_empty() {
            let heights = coupling.probes.iter().map(|p| sim.shadow.height_at(p.x, p.y)).collect();
            self.probes = Some(ProbeSamples { points: coupling.probes, heights, frame: self.frames });
        }
        sim.write_uniforms(queue, &plan, self.size, self.half_width);
        let per_step = plan.updates_per_step(steps);
        for step in 0..(steps as usize).max(1) {
            if plan.pushes_water(step) {
                let slot = step.min(MAX_PUSH_STEPS - 1);
                let cells = plan.pushed_cells(step, self.size, self.half_width);
                let group = Some(&sim.step_groups[slot]);
                if cells == CellRange::all(self.size) {
                    self.state.run_with(encoder, &sim.drop_pass, &sim.bind_groups, group);
                } else {
                    let rect = [cells.x.0, cells.z.0, cells.x.1 + 1 - cells.x.0, cells.z.1 + 1 - cells.z.0];
                    self.state.run_in_place(encoder, &sim.drop_pass, &sim.bind_groups, group, rect);
                }
            }
            for _ in 0..per_step {
                self.state.run(encoder, &sim.update_pass, &sim.bind_groups);
            }
        }
        if plan.changes_state() {
            sim.mean.encode(encoder, self.state.current());
            self.state.run(encoder, &sim.normals_pass, &sim.bind_groups);
        }
        sim.probe.encode(encoder, &sim.mean.result);
    }

    /// Sets what the bodies do to the water in the next [`HeightField::encode`].
    pub fn set_bodies(&mut self, coupling: BodyCoupling) {
        self.coupling = coupling;
    }

    /// Frames encoded so far.
    pub fn frames(&self) -> u64 {
        self.frames
    }

    /// Carries the frame count over to a heightfield that replaces this one.
    pub fn set_frames(&mut self, frames: u64) {
        self.frames = frames;
    }

    /// The heights at the bodies' probe points, sampled at the end of the last
    /// [`HeightField::encode`]: the water as the next frame starts from. Sampled on the CPU
    /// (the CPU engine's own grid, or the GPU engine's [`SHADOW_SIZE`] shadow), so nothing is
    /// ever read back from the GPU for them.
    pub fn probes(&self) -> Option<&ProbeSamples> {
        self.probes.as_ref()
    }

    /// A `size` x `size` heightfield on the same engine holding this one's water resampled
    /// onto the new grid (box average when shrinking, bilinear when growing: on the GPU
    /// `shaders/sim_resample.wgsl`, on the CPU its mirror), with its mean level held and
    /// normals redone; queued drops carry over. Records the GPU passes into `encoder`; like
    /// [`HeightField::encode`], it writes the new field's uniforms, and encoding steps on the
    /// new field in the same submission is fine (same grid values).
    pub fn resampled(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        size: u32,
    ) -> HeightField {
        let mut new = HeightField::new_on(device, size, self.half_width, self.engine());
        new.pending = self.pending.clone();
        new.coupling.rest_level = self.coupling.rest_level;
        match (&self.engine, &mut new.engine) {
            (Engine::Cpu { water: old, .. }, Engine::Cpu { water, level, upload: cells }) => {
                **water = old.resampled(size);
                upload(queue, new.state.current_texture(), water, cells);
                *level = Some(water.level());
            }
            (Engine::Gpu(old), Engine::Gpu(sim)) => {
                *sim.shadow = old.shadow.resampled(size.min(SHADOW_SIZE));
                let from_old = device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("sim resample source"),
                    layout: &sim.layout,
                    entries: &[
                        wgpu::BindGroupEntry { binding: 0, resource: sim.uniforms.as_entire_binding() },
                        wgpu::BindGroupEntry {
                            binding: 1,
                            resource: wgpu::BindingResource::TextureView(self.state.current_view()),
                        },
                        wgpu::BindGroupEntry {
                            binding: 2,
                            resource: wgpu::BindingResource::TextureView(sim.mean.result_view()),
                        },
                    ],
                });
                let mut no_drops = Vec::new();
                let calm = WaveSettings::reflecting(0.0, 0.0);
                let mut plan = StepPlan::new(&mut no_drops, size, self.half_width, 0, 0.0, calm);
                plan.rest_level = self.coupling.rest_level;
                sim.write_uniforms(queue, &plan, size, self.half_width);
                new.state.run(encoder, &sim.resample_pass, &[from_old.clone(), from_old]);
                sim.mean.encode(encoder, new.state.current());
                new.state.run(encoder, &sim.normals_pass, &sim.bind_groups);
            }
            _ => unreachable!("the new field was made on the same engine"),
        }
        new
    }

    /// Call after submitting the frame that [`HeightField::encode`] recorded: starts the
    /// asynchronous read of the water statistics (never waits).
    pub fn after_submit(&self) {
        if let Engine::Gpu(sim) = &self.engine {
            sim.probe.after_submit();
        }
    }

    /// The latest water statistics read back, one to a few frames old; `None` until the
    /// first read completes. Reads complete as the device is polled (natively) or as the
    /// browser runs its event loop.
    pub fn level(&self) -> Option<WaterLevel> {
        match &self.engine {
            Engine::Gpu(sim) => sim.probe.latest,
            Engine::Cpu { level, .. } => *level,
        }
    }

    /// Flattens the water and forgets queued drops.
    pub fn reset(&mut self, queue: &wgpu::Queue) {
        self.pending.clear();
        match &mut self.engine {
            Engine::Cpu { water, level, .. } => {
                **water = cpu::CpuHeightField::new(self.size, self.half_width);
                *level = None;
            }
            Engine::Gpu(sim) => *sim.shadow = cpu::CpuHeightField::new(sim.shadow.size(), self.half_width),
        }
        let zeros = vec![0u8; (self.size * self.size * 16) as usize];
        for texture in self.state.textures() {
            queue.write_texture(
                texture.as_image_copy(),
                &zeros,
                wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(self.size * 16), rows_per_image: None },
                texture.size(),
            );
        }
    }

    /// The two state textures and which of them is current, for binding in the renderer.
    pub fn state(&self) -> &PingPong {
        &self.state
    }

    /// Reads the current state back: `size * size` cells of (height, velocity, nx, nz),
    /// row by row along +z. Blocking; for tests and tools.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn read_state(&self, device: &wgpu::Device, queue: &wgpu::Queue) -> Vec<[f32; 4]> {
        if let Engine::Cpu { water, .. } = &self.engine {
            return water.cells();
        }
        let bytes = gpu::read_texture(device, queue, self.state.current_texture());
        bytemuck::cast_slice(&bytes).to_vec()
    }
}

/// At most [`MAX_PUSH_STEPS`] steps of at most [`MAX_HULL_MOVES`] moves: the moves of later
/// steps join the last step's (an ellipsoid's moves chain: where one ends the next starts, so
/// the chain goes from the first's start to the last's end).
fn merge_push_steps(mut moves: Vec<Vec<HullMove>>) -> Vec<Vec<HullMove>> {
    for step in &mut moves {
        step.truncate(MAX_HULL_MOVES);
    }
    while moves.len() > MAX_PUSH_STEPS {
        let later = moves.pop().expect("more than one step");
        if let Some(last) = moves.last_mut() {
            for l in later {
                if let Some(m) = last.iter_mut().find(|m| m.to == l.from) {
                    m.to = l.to;
                } else if last.len() < MAX_HULL_MOVES {
                    last.push(l);
                }
            }
        }
    }
    moves
}

/// Writes the CPU engine's state into the texture the renderer samples (16 B per cell).
/// `cells` is a buffer kept between frames.
fn upload(queue: &wgpu::Queue, texture: &wgpu::Texture, water: &cpu::CpuHeightField, cells: &mut Vec<[f32; 4]>) {
    water.write_cells(cells);
    queue.write_texture(
        texture.as_image_copy(),
        bytemuck::cast_slice(cells),
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(water.size() * 16), rows_per_image: None },
        texture.size(),
    );
}

use bytemuck::Zeroable;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_step_is_frame_rate_independent() {
        for fps in [30.0f32, 60.0, 144.0] {
            let mut clock = FixedStep::new(1.0 / 120.0, 8);
            let frames = (fps * 2.0).round() as u32;
            let steps: u32 = (0..frames).map(|_| clock.advance(1.0 / fps)).sum();
            assert!((239..=240).contains(&steps), "{fps} fps gave {steps} steps in 2 s");
        }
    }

    #[test]
    fn slow_frames_are_capped() {
        let mut clock = FixedStep::new(1.0 / 120.0, 8);
        assert_eq!(clock.advance(0.5), 8);
        assert_eq!(clock.advance(1.0 / 120.0), 1);
    }

    #[test]
    fn drop_mean_matches_the_analytic_integral_away_from_walls() {
        // Integral of the cosine bump over its disc: pi r^2 (1/2 - 2/pi^2).
        let d = Drop { x: 0.1, z: -0.2, radius: 0.1, strength: 1.0 };
        let n = 512;
        let pool_area = 4.0;
        let analytic = std::f32::consts::PI * 0.01 * (0.5 - 2.0 / std::f32::consts::PI.powi(2)) / pool_area;
        let numeric = drop_mean(&d, n, 1.0);
        assert!((numeric - analytic).abs() / analytic < 0.01, "{numeric} vs {analytic}");
    }
}

/// A small deterministic random generator (SplitMix64) for seeded drops in tools and tests.
#[derive(Clone, Debug)]
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        let unit = (self.next_u64() >> 40) as f32 / (1u64 << 24) as f32;
        lo + (hi - lo) * unit
    }
}

/// `count` drops at seeded random places in the pool (within 90 % of the half width),
/// of the given radius (m) and strength (m), alternating in sign like rain and splashes.
pub fn random_drops(seed: u64, count: u32, half_width: f32, radius: f32, strength: f32) -> Vec<Drop> {
    let mut rng = SplitMix64(seed);
    (0..count)
        .map(|i| Drop {
            x: rng.range(-0.9, 0.9) * half_width,
            z: rng.range(-0.9, 0.9) * half_width,
            radius,
            strength: if i % 2 == 0 { strength } else { -strength },
        })
        .collect()
}
