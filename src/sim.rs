//! The water: a heightfield on the GPU advanced by the damped 2-D wave equation in
//! full-screen fragment passes (so WebGL2, without compute shaders, runs the same code).
//! State per cell: height above rest (m), vertical velocity (m/s), normal x and z.
//!
//! By concern: `plan` holds the step arithmetic the GPU and the CPU engine share, `coupling`
//! how the floating bodies and the water meet, `gpu_engine` the GPU engine's passes, [`cpu`] the CPU
//! reference engine, `random` seeded drops; this module the [`HeightField`] that drives them.
//! Everything public is re-exported here.

use crate::gpu::PingPong;

mod coupling;
pub mod cpu;
pub mod foam;
mod gpu_engine;
pub mod params;
mod plan;
mod random;

use coupling::merge_push_steps;
use gpu_engine::GpuSim;

pub use coupling::{
    displaced_column, displacement_depth, pool_area, BodyCoupling, CellRange, HullMove, HullSlot, ProbeSamples,
    CPU_COPY_SIZE, DISPLACEMENT_DEPTH, MAX_HULL_MOVES, MAX_PROBES, MAX_PUSH_STEPS, PUSH_MIN_MOVE,
};
pub use plan::{
    drop_mean, drop_shape, sponge_profile, substeps, Drop, FixedStep, StepPlan, WaveSettings, MAX_COURANT,
    MAX_DROPS_PER_PASS, MAX_HEIGHT, MAX_VELOCITY, SPONGE_WIDTH,
};
pub use random::{random_drops, SplitMix64};

/// A field's width against the pool's: its sponge and bounds grow with it, so a field of any
/// width (the open sea's patch) behaves as the pool would at that size; exactly 1 for the pool.
pub fn scale_of(half_width: f32) -> f32 {
    half_width / crate::world::PoolShape::CLASSIC.half_width
}

/// Format of the state textures: 32-bit floats, read with `textureLoad` only (no filtering).
pub const STATE_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;

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

/// Water statistics read back from the GPU, a frame or two old.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct WaterLevel {
    /// Mean height above rest before the frame's correction (m).
    pub mean: f32,
    /// Largest |height| over the pool (m).
    pub max_abs: f32,
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
                    sim.cpu_copy.add_drop(drop);
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
        sim.cpu_copy.advance_with(steps, dt, settings, plan.moves.clone(), plan.rest_level);
        if !coupling.probes.is_empty() {
            let heights = coupling.probes.iter().map(|p| sim.cpu_copy.height_at(p.x, p.y)).collect();
            self.probes = Some(ProbeSamples { points: coupling.probes, heights, frame: self.frames });
        }
        sim.write_uniforms(queue, &plan, self.size, self.half_width);
        let per_step = plan.updates_per_step(steps);
        for step in 0..(steps as usize).max(1) {
            if plan.pushes_water(step) {
                let slot = step.min(MAX_PUSH_STEPS - 1);
                let group = Some(&sim.step_groups[slot]);
                for cells in plan.pushed_cells(step, self.size, self.half_width) {
                    if cells == CellRange::all(self.size) {
                        self.state.run_with(encoder, &sim.drop_pass, &sim.bind_groups, group);
                    } else {
                        let rect = [cells.x.0, cells.z.0, cells.x.1 + 1 - cells.x.0, cells.z.1 + 1 - cells.z.0];
                        self.state.run_in_place(encoder, &sim.drop_pass, &sim.bind_groups, group, rect);
                    }
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

    /// Turns foam on (decay time in s) or off. Foam is integrated per step on the CPU field
    /// of either engine (the GPU engine's CPU copy of the water, at most [`CPU_COPY_SIZE`] cells
    /// per side), the same code for both.
    pub fn set_foam(&mut self, decay_s: Option<f32>) {
        match &mut self.engine {
            Engine::Gpu(sim) => sim.cpu_copy.set_foam(decay_s),
            Engine::Cpu { water, .. } => water.set_foam(decay_s),
        }
    }

    /// The foam, when on (updated by [`HeightField::encode`]).
    pub fn foam(&self) -> Option<&foam::Foam> {
        match &self.engine {
            Engine::Gpu(sim) => sim.cpu_copy.foam(),
            Engine::Cpu { water, .. } => water.foam(),
        }
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
    /// (the CPU engine's own grid, or the GPU engine's [`CPU_COPY_SIZE`] copy), so nothing is
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
                *sim.cpu_copy = old.cpu_copy.resampled(size.min(CPU_COPY_SIZE));
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
            Engine::Gpu(sim) => *sim.cpu_copy = cpu::CpuHeightField::new(sim.cpu_copy.size(), self.half_width),
        }
        let zeros = vec![0u8; (self.size * self.size * 16) as usize];
        for texture in self.state.textures() {
            crate::gpu::write_texture_2d(queue, texture, 0, &zeros);
        }
    }

    /// The two state textures and which of them is current, for binding in the renderer.
    pub fn state(&self) -> &PingPong {
        &self.state
    }

    /// Reads the current state back: `size * size` cells of (height, velocity, nx, nz),
    /// row by row along +z. Blocking; for tests and tools.
    #[cfg(not(target_arch = "wasm32"))]
    #[allow(clippy::disallowed_methods)]
    pub fn read_state(&self, device: &wgpu::Device, queue: &wgpu::Queue) -> Vec<[f32; 4]> {
        if let Engine::Cpu { water, .. } = &self.engine {
            return water.cells();
        }
        let bytes = crate::gpu::read_texture(device, queue, self.state.current_texture());
        bytemuck::cast_slice(&bytes).to_vec()
    }
}

/// Writes the CPU engine's state into the texture the renderer samples (16 B per cell).
/// `cells` is a buffer kept between frames.
fn upload(queue: &wgpu::Queue, texture: &wgpu::Texture, water: &cpu::CpuHeightField, cells: &mut Vec<[f32; 4]>) {
    water.write_cells(cells);
    crate::gpu::write_texture_2d(queue, texture, 0, bytemuck::cast_slice(cells));
}
