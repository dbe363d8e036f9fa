//! The GPU engine: the drop, update, normals and resample passes with their uniforms, the
//! mean level reduction and its asynchronous readback, and the CPU copy of the water kept
//! for the bodies.

use bytemuck::Zeroable;

use super::coupling::{displacement_depth, CPU_COPY_SIZE, MAX_HULL_MOVES, MAX_PUSH_STEPS};
use super::plan::{StepPlan, MAX_DROPS_PER_PASS};
use super::{cpu, WaterLevel, STATE_FORMAT};
use crate::gpu::{self, FullscreenPass, FullscreenTarget, PingPong};

/// The simulation's WGSL: its uniforms (`SHARED`) and one file per pass.
mod wgsl {
    pub const SHARED: &str = crate::wgsl!("sim_shared.wgsl");
    pub const DROP: &str = crate::wgsl!("sim_drop.wgsl");
    pub const UPDATE: &str = crate::wgsl!("sim_update.wgsl");
    pub const NORMALS: &str = crate::wgsl!("sim_normals.wgsl");
    pub const RESAMPLE: &str = crate::wgsl!("sim_resample.wgsl");
    pub const MEAN: &str = crate::wgsl!("sim_mean.wgsl");
}

/// The sizes of `SimUniforms`' arrays and one step's share of the hull slots, for
/// `sim_shared.wgsl` and `sim_drop.wgsl`.
fn wgsl_constants() -> String {
    format!(
        "const MAX_DROPS: u32 = {};\nconst HULL_SLOTS: u32 = {};\nconst STEP_HULL_SLOTS: i32 = {};\n",
        MAX_DROPS_PER_PASS,
        MAX_PUSH_STEPS * MAX_HULL_MOVES * 8,
        MAX_HULL_MOVES * 8
    )
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

/// The GPU engine's passes and buffers.
pub(super) struct GpuSim {
    pub(super) uniforms: wgpu::Buffer,
    pub(super) layout: wgpu::BindGroupLayout,
    pub(super) bind_groups: [wgpu::BindGroup; 2],
    /// Per step of a frame, a group telling the drop pass which step's moves to apply.
    pub(super) step_groups: Vec<wgpu::BindGroup>,
    pub(super) drop_pass: FullscreenPass,
    pub(super) resample_pass: FullscreenPass,
    pub(super) update_pass: FullscreenPass,
    pub(super) normals_pass: FullscreenPass,
    pub(super) mean: MeanLevel,
    pub(super) probe: LevelProbe,
    /// The water again, on the CPU at [`CPU_COPY_SIZE`], for the bodies' buoyancy.
    pub(super) cpu_copy: Box<cpu::CpuHeightField>,
}

/// Format of the level reduction textures: x mean height (m), y largest |height| (m).
const LEVEL_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;

/// The water's mean height and largest |height|, found on the GPU by folding 2x2 blocks level
/// by level down to one texel (`shaders/sim_mean.wgsl`), so the mean can be subtracted without
/// a readback.
pub(super) struct MeanLevel {
    views: Vec<wgpu::TextureView>,
    pub(super) result: wgpu::Texture,
    from_state: [wgpu::BindGroup; 2],
    from_level: Vec<wgpu::BindGroup>,
    state_pass: FullscreenPass,
    level_pass: FullscreenPass,
}

impl MeanLevel {
    fn new(device: &wgpu::Device, state: &PingPong, size: u32) -> Self {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("mean level layout"),
            entries: &[gpu::float_texture_entry(0, wgpu::ShaderStages::FRAGMENT)],
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
            textures.push(gpu::texture_2d(device, "water level", (side, side, 1), 1, LEVEL_FORMAT, usage));
            side /= 2;
        }
        let views: Vec<_> = textures.iter().map(|t| t.create_view(&Default::default())).collect();
        let from_level = views[..views.len() - 1].iter().map(group).collect();
        let pass = |entry: &str| {
            FullscreenPass::new(
                device,
                "sim water level",
                &[wgsl::MEAN],
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
    pub(super) fn encode(&self, encoder: &mut wgpu::CommandEncoder, current: usize) {
        self.state_pass.run(encoder, &self.views[0], &[&self.from_state[current]]);
        for (group, target) in self.from_level.iter().zip(&self.views[1..]) {
            self.level_pass.run(encoder, target, &[group]);
        }
    }

    /// The one-texel texture holding (mean height, largest |height|) in m.
    pub(super) fn result_view(&self) -> &wgpu::TextureView {
        self.views.last().expect("at least one level")
    }
}

/// Reads the one-texel [`MeanLevel`] result back without ever waiting (see
/// [`gpu::AsyncReadback`]): the statistics are one to a few frames old.
pub(super) struct LevelProbe {
    readback: gpu::AsyncReadback,
    pub(super) latest: Option<WaterLevel>,
}

impl LevelProbe {
    fn new(device: &wgpu::Device) -> Self {
        Self { readback: gpu::AsyncReadback::new(device, "water level readback", 16), latest: None }
    }

    /// Takes a finished read and, when idle, records a new copy of `result`.
    pub(super) fn encode(&mut self, encoder: &mut wgpu::CommandEncoder, result: &wgpu::Texture) {
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
    pub(super) fn after_submit(&self) {
        self.readback.after_submit();
    }
}

impl GpuSim {
    pub(super) fn new(device: &wgpu::Device, state: &PingPong, size: u32, half_width: f32) -> Self {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("sim layout"),
            entries: &[
                gpu::uniform_entry(0, wgpu::ShaderStages::FRAGMENT),
                gpu::float_texture_entry(1, wgpu::ShaderStages::FRAGMENT),
                gpu::float_texture_entry(2, wgpu::ShaderStages::FRAGMENT),
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
        let constants = wgsl_constants();
        let pass = |label: &str, source: &str, entry: &str| {
            FullscreenPass::new(
                device,
                label,
                &[&constants, wgsl::SHARED, source],
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
            &[&constants, gpu::wgsl::MATH, wgsl::SHARED, wgsl::DROP],
            "fs_drop",
            &[&layout, &step_layout],
            FullscreenTarget { format: STATE_FORMAT, blend: None, depth: None },
        );
        Self {
            drop_pass,
            step_groups,
            update_pass: pass("sim update", wgsl::UPDATE, "fs_update"),
            normals_pass: pass("sim normals", wgsl::NORMALS, "fs_normals"),
            resample_pass: pass("sim resample", wgsl::RESAMPLE, "fs_resample"),
            uniforms,
            layout,
            bind_groups,
            mean,
            probe: LevelProbe::new(device),
            cpu_copy: Box::new(cpu::CpuHeightField::new(size.min(CPU_COPY_SIZE), half_width)),
        }
    }

    pub(super) fn write_uniforms(&self, queue: &wgpu::Queue, plan: &StepPlan, size: u32, half_width: f32) {
        let mut u = SimUniforms::zeroed();
        u.grid = [size as f32, 1.0 / size as f32, 2.0 * half_width / size as f32, half_width];
        u.step = [plan.dt, plan.coupling, plan.velocity_decay, plan.sponge_rate];
        u.bounds = [plan.max_height, plan.max_velocity, plan.sponge_width, 0.0];
        u.drops_info = [plan.drops.len() as f32, plan.correction, 0.0, 0.0];
        for (slot, d) in u.drops.iter_mut().zip(&plan.drops) {
            *slot = [d.x, d.z, d.radius, d.strength];
        }
        let per_step = plan.moves.iter().map(Vec::len).max().unwrap_or(0);
        u.bodies = [per_step as f32, plan.rest_level, displacement_depth(half_width), 0.0];
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
