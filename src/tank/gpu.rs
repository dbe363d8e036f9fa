//! The tank's water on the GPU: its state in a ping-pong pair of float textures advanced by
//! one full-screen pass per update (`shaders/tank/update.wgsl`), its cells' medium in a
//! texture, each update's uniforms in a slot of one buffer. Where the device cannot render
//! into float textures the CPU reference runs instead and its state is uploaded.

use super::cpu::CpuTank;
use super::medium::Medium;
use super::plan::{Update, UPDATE_SLOT};
use super::{INTENSITY_TIME, MAX_DIPPERS, MAX_TANK_DROPS, PROBE_SAMPLES};
use crate::gpu::{self, FullscreenPass, FullscreenTarget, PingPong};

/// Format of the state and medium textures: the pool's water's (read with `textureLoad` only).
pub const TANK_STATE_FORMAT: wgpu::TextureFormat = crate::sim::STATE_FORMAT;

/// The constants `update.wgsl` is written against.
fn wgsl_constants() -> String {
    format!(
        "const MAX_DIPPERS: u32 = {MAX_DIPPERS};\nconst MAX_TANK_DROPS: u32 = {MAX_TANK_DROPS};\nconst INTENSITY_TIME: f32 = {INTENSITY_TIME:?};\n{}",
        super::medium::kind_constants()
    )
}

enum Engine {
    /// The update pass and the drops' pass, their layout, the updates' uniform slots and a
    /// bind group per slot and side of the state.
    Gpu {
        update: FullscreenPass,
        drops: FullscreenPass,
        layout: wgpu::BindGroupLayout,
        uniforms: wgpu::Buffer,
        groups: Vec<[wgpu::BindGroup; 2]>,
    },
    /// The CPU reference; its state is uploaded into the current texture after each frame.
    Cpu(Box<CpuTank>),
}

/// The tank's water where the picture reads it: a texture per cell of (h m, v m/s, h² m²).
pub struct TankWater {
    state: PingPong,
    medium: wgpu::Texture,
    medium_view: wgpu::TextureView,
    engine: Engine,
    cells: u32,
    /// The state the strobe last lit, once it has flashed.
    flash: Option<(wgpu::Texture, wgpu::TextureView)>,
    probe: Probe,
}

/// The probe's record: its cell's state after each fixed step in a ring of
/// [`PROBE_SAMPLES`] texels, and the reads of that ring (and of one row of the state) back
/// to the CPU.
struct Probe {
    /// The cell (i, j) sampled, and every how many updates (one fixed step's).
    cell: Option<(u32, u32)>,
    every: usize,
    ring: wgpu::Texture,
    ring_view: wgpu::TextureView,
    /// The ring's copy on the CPU, where the CPU reference runs the water.
    cpu_ring: Vec<[f32; 4]>,
    /// The next texel written, and how many samples were taken since the water was stilled.
    next: u32,
    taken: u64,
    /// Updates since the last sample.
    since: usize,
    readback: Option<gpu::AsyncReadback>,
    /// What the read in flight holds: the ring's newest texel and the samples then, the row.
    in_flight: (u32, u64, Option<u32>),
    /// Counts the times the record started afresh (still water, a new place); a read recorded
    /// before the latest is dropped when it lands.
    generation: u32,
    in_flight_generation: u32,
}

/// A read of the probe's ring and of a row of the state.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ProbeRead {
    /// The probe's heights (m), one a fixed step, oldest first (at most [`PROBE_SAMPLES`]).
    pub heights: Vec<f32>,
    /// The row asked for, if any: its cells' intensity (m²), west to east.
    pub row: Option<(u32, Vec<f32>)>,
}

const TEXEL_BYTES: u64 = 16;

impl Probe {
    /// Notes that the update just recorded or run ended; true when the probe samples now.
    fn due(&mut self) -> bool {
        let p = self;
        if p.cell.is_none() {
            return false;
        }
        p.since += 1;
        if p.since < p.every {
            return false;
        }
        p.since = 0;
        true
    }

    /// Moves the ring on after a sample went into texel `next`.
    fn advance(&mut self) {
        let p = self;
        p.next = (p.next + 1) % PROBE_SAMPLES;
        p.taken += 1;
    }
}

impl TankWater {
    /// Still water in `medium`, advanced on the GPU where it renders into float textures
    /// (`float_targets`), else on the CPU.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue, medium: &Medium, float_targets: bool) -> Self {
        let cells = medium.cells;
        let state = PingPong::new(device, "tank state", cells, cells, TANK_STATE_FORMAT, float_targets);
        let medium_texture = gpu::texture_2d(
            device,
            "tank medium",
            (cells, cells, 1),
            1,
            TANK_STATE_FORMAT,
            wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        );
        gpu::write_texture_2d(queue, &medium_texture, 0, bytemuck::cast_slice(&medium.faces()));
        let medium_view = medium_texture.create_view(&Default::default());
        let engine = if float_targets {
            let stage = wgpu::ShaderStages::FRAGMENT;
            let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some("tank update layout"),
                entries: &[
                    gpu::uniform_entry(0, stage),
                    gpu::float_texture_entry(1, stage),
                    gpu::float_texture_entry(2, stage),
                ],
            });
            let constants = wgsl_constants();
            let pass = |label: &str, entry: &str| {
                FullscreenPass::new(
                    device,
                    label,
                    &[gpu::wgsl::MATH, &constants, crate::wgsl!("tank/update.wgsl")],
                    entry,
                    &[&layout],
                    FullscreenTarget { format: TANK_STATE_FORMAT, blend: None, depth: None },
                )
            };
            let (update, drops) = (pass("tank update", "fs_update"), pass("tank drops", "fs_drops"));
            let uniforms = slots_buffer(device, 0);
            Engine::Gpu { update, drops, layout, uniforms, groups: Vec::new() }
        } else {
            Engine::Cpu(Box::new(CpuTank::new(medium.clone())))
        };
        let usage =
            wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST | wgpu::TextureUsages::COPY_SRC;
        let ring = gpu::texture_2d(device, "tank probe ring", (PROBE_SAMPLES, 1, 1), 1, TANK_STATE_FORMAT, usage);
        let probe = Probe {
            cell: None,
            every: 1,
            ring_view: ring.create_view(&Default::default()),
            ring,
            cpu_ring: vec![[0.0; 4]; PROBE_SAMPLES as usize],
            next: 0,
            taken: 0,
            since: 0,
            readback: None,
            in_flight: (0, 0, None),
            generation: 0,
            in_flight_generation: 0,
        };
        let mut water = Self { state, medium: medium_texture, medium_view, engine, cells, flash: None, probe };
        water.clear(queue);
        water
    }

    /// Cells per side.
    pub fn cells(&self) -> u32 {
        self.cells
    }

    /// The texture holding the latest state.
    pub fn state_view(&self) -> &wgpu::TextureView {
        self.state.current_view()
    }

    /// The state the picture shows: the one the strobe last lit if `strobe` (and it has
    /// flashed), else the latest.
    pub fn shown_view(&self, strobe: bool) -> &wgpu::TextureView {
        match &self.flash {
            Some((_, view)) if strobe => view,
            _ => self.state.current_view(),
        }
    }

    pub fn state_texture(&self) -> &wgpu::Texture {
        self.state.current_texture()
    }

    /// The medium's texture: per cell its faces' c² (m²/s²), beach rate (1/s), kind code
    /// ([`Medium::faces`]).
    pub fn medium_view(&self) -> &wgpu::TextureView {
        &self.medium_view
    }

    /// Whether the CPU reference runs the water (no float render targets).
    pub fn on_cpu(&self) -> bool {
        matches!(self.engine, Engine::Cpu(_))
    }

    /// Puts `medium` in the tray (same cells per side), keeping the water.
    pub fn set_medium(&mut self, queue: &wgpu::Queue, medium: &Medium) {
        gpu::write_texture_2d(queue, &self.medium, 0, bytemuck::cast_slice(&medium.faces()));
        if let Engine::Cpu(tank) = &mut self.engine {
            tank.set_medium(medium.clone());
        }
    }

    /// Still water everywhere.
    pub fn clear(&mut self, queue: &wgpu::Queue) {
        let zeros = vec![0u8; (self.cells * self.cells * 16) as usize];
        for texture in self.state.textures() {
            gpu::write_texture_2d(queue, texture, 0, &zeros);
        }
        if let Engine::Cpu(tank) = &mut self.engine {
            tank.state.iter_mut().for_each(|s| *s = [0.0; 3]);
        }
        // Until the strobe flashes again it shows still water, not the old.
        self.flash = None;
        let p = &mut self.probe;
        p.cpu_ring.iter_mut().for_each(|t| *t = [0.0; 4]);
        gpu::write_texture_2d(queue, &p.ring, 0, bytemuck::cast_slice(&p.cpu_ring));
        (p.next, p.taken, p.since) = (0, 0, 0);
        p.generation += 1;
    }

    /// Samples cell `cell` (i, j) after every `every` updates from now on (none: no probe).
    pub fn probe_at(&mut self, cell: Option<(u32, u32)>, every: usize) {
        let p = &mut self.probe;
        if p.cell != cell {
            // Another place: its history starts afresh.
            (p.next, p.taken, p.since) = (0, 0, 0);
            p.generation += 1;
        }
        (p.cell, p.every) = (cell, every.max(1));
    }

    /// The probe's ring: a texel per sample (its cell's h, v, intensity), the newest at
    /// [`TankWater::probe_newest`].
    pub fn probe_view(&self) -> &wgpu::TextureView {
        &self.probe.ring_view
    }

    /// The ring's newest texel and how many samples it holds (at most [`PROBE_SAMPLES`]).
    pub fn probe_newest(&self) -> (u32, u32) {
        let p = &self.probe;
        ((p.next + PROBE_SAMPLES - 1) % PROBE_SAMPLES, p.taken.min(PROBE_SAMPLES as u64) as u32)
    }

    /// Records a copy of the probe's ring and of state row `row` (if any) for reading back,
    /// unless a read is in flight; call [`TankWater::after_submit`] once submitted.
    pub fn record_read(&mut self, device: &wgpu::Device, encoder: &mut wgpu::CommandEncoder, row: Option<u32>) {
        let ring_bytes = PROBE_SAMPLES as u64 * TEXEL_BYTES;
        let size = ring_bytes + self.cells as u64 * TEXEL_BYTES;
        let readback =
            self.probe.readback.get_or_insert_with(|| gpu::AsyncReadback::new(device, "tank probe read", size));
        let Some(buffer) = readback.record() else { return };
        let copy = |encoder: &mut wgpu::CommandEncoder, from: wgpu::TexelCopyTextureInfo, offset: u64, width: u32| {
            let layout = wgpu::TexelCopyBufferLayout { offset, bytes_per_row: Some(width * 16), rows_per_image: None };
            let extent = wgpu::Extent3d { width, height: 1, depth_or_array_layers: 1 };
            encoder.copy_texture_to_buffer(from, wgpu::TexelCopyBufferInfo { buffer, layout }, extent);
        };
        copy(encoder, self.probe.ring.as_image_copy(), 0, PROBE_SAMPLES);
        if let Some(j) = row.filter(|&j| j < self.cells) {
            let mut from = self.state.current_texture().as_image_copy();
            from.origin.y = j;
            copy(encoder, from, ring_bytes, self.cells);
        }
        let (newest, _) = self.probe_newest();
        self.probe.in_flight = (newest, self.probe.taken, row);
        self.probe.in_flight_generation = self.probe.generation;
    }

    /// Starts the read recorded into the frame just submitted.
    pub fn after_submit(&self) {
        if let Some(readback) = &self.probe.readback {
            readback.after_submit();
        }
    }

    /// The latest completed read, if one completed since the last call.
    pub fn take_read(&self) -> Option<ProbeRead> {
        let bytes = self.probe.readback.as_ref()?.take()?;
        if self.probe.in_flight_generation != self.probe.generation {
            return None;
        }
        let texels: &[[f32; 4]] = bytemuck::cast_slice(&bytes);
        let (newest, taken, row) = self.probe.in_flight;
        let held = taken.min(PROBE_SAMPLES as u64) as u32;
        let heights =
            (0..held).map(|k| texels[((newest + PROBE_SAMPLES + 1 - held + k) % PROBE_SAMPLES) as usize][0]).collect();
        let ring = PROBE_SAMPLES as usize;
        let row = row.map(|j| (j, texels[ring..ring + self.cells as usize].iter().map(|t| t[2]).collect()));
        Some(ProbeRead { heights, row })
    }

    /// Records `updates` (or runs them on the CPU and uploads the result), keeping the state
    /// after update `flash` for the strobe's picture.
    pub fn encode(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        updates: &[Update],
        flash: Option<usize>,
    ) {
        if flash.is_some() && self.flash.is_none() {
            let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
            let texture =
                gpu::texture_2d(device, "tank flash", (self.cells, self.cells, 1), 1, TANK_STATE_FORMAT, usage);
            let view = texture.create_view(&Default::default());
            self.flash = Some((texture, view));
        }
        let size = wgpu::Extent3d { width: self.cells, height: self.cells, depth_or_array_layers: 1 };
        match &mut self.engine {
            Engine::Gpu { update, drops, layout, uniforms, groups } => {
                if groups.len() < updates.len() {
                    *uniforms = slots_buffer(device, updates.len());
                    *groups = (0..updates.len())
                        .map(|slot| {
                            self.state
                                .bind_groups(|view| slot_group(device, layout, uniforms, slot, view, &self.medium_view))
                        })
                        .collect();
                }
                for (slot, update) in updates.iter().enumerate() {
                    queue.write_buffer(uniforms, slot as u64 * UPDATE_SLOT, bytemuck::bytes_of(update));
                }
                for (k, (u, group)) in updates.iter().zip(groups.iter()).enumerate() {
                    if u.bar[3] > 0.0 {
                        self.state.run(encoder, drops, group);
                    }
                    self.state.run(encoder, update, group);
                    if let (Some((texture, _)), true) = (&self.flash, flash == Some(k)) {
                        encoder.copy_texture_to_texture(
                            self.state.current_texture().as_image_copy(),
                            texture.as_image_copy(),
                            size,
                        );
                    }
                    if self.probe.due() {
                        let (mut from, mut to) =
                            (self.state.current_texture().as_image_copy(), self.probe.ring.as_image_copy());
                        let (i, j) = self.probe.cell.unwrap_or_default();
                        from.origin = wgpu::Origin3d { x: i, y: j, z: 0 };
                        to.origin.x = self.probe.next;
                        let texel = wgpu::Extent3d { width: 1, height: 1, depth_or_array_layers: 1 };
                        encoder.copy_texture_to_texture(from, to, texel);
                        self.probe.advance();
                    }
                }
            }
            Engine::Cpu(_) if updates.is_empty() => {}
            Engine::Cpu(_) => self.run_on_cpu(queue, updates, flash),
        }
    }
}

impl TankWater {
    /// [`TankWater::encode`] where the CPU reference runs the water: each update, the strobe's
    /// and the probe's samples, then the state uploaded.
    fn run_on_cpu(&mut self, queue: &wgpu::Queue, updates: &[Update], flash: Option<usize>) {
        let texels = |tank: &CpuTank| -> Vec<[f32; 4]> { tank.state.iter().map(|&[h, v, i]| [h, v, i, 0.0]).collect() };
        let mut sampled = false;
        for (k, u) in updates.iter().enumerate() {
            let Engine::Cpu(tank) = &mut self.engine else { return };
            tank.update(u);
            if let (Some((texture, _)), true) = (&self.flash, flash == Some(k)) {
                gpu::write_texture_2d(queue, texture, 0, bytemuck::cast_slice(&texels(tank)));
            }
            let probed = self.probe.cell.map(|(i, j)| tank.state[(j * self.cells + i) as usize]);
            if self.probe.due() {
                let [h, v, i] = probed.unwrap_or_default();
                self.probe.cpu_ring[self.probe.next as usize] = [h, v, i, 0.0];
                self.probe.advance();
                sampled = true;
            }
        }
        if sampled {
            gpu::write_texture_2d(queue, &self.probe.ring, 0, bytemuck::cast_slice(&self.probe.cpu_ring));
        }
        if let Engine::Cpu(tank) = &self.engine {
            gpu::write_texture_2d(queue, self.state.current_texture(), 0, bytemuck::cast_slice(&texels(tank)));
        }
    }
}

/// A uniform buffer of `slots` update slots (at least one).
fn slots_buffer(device: &wgpu::Device, slots: usize) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("tank updates"),
        size: slots.max(1) as u64 * UPDATE_SLOT,
        usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

/// The bind group of update slot `slot` reading `state`.
fn slot_group(
    device: &wgpu::Device,
    layout: &wgpu::BindGroupLayout,
    uniforms: &wgpu::Buffer,
    slot: usize,
    state: &wgpu::TextureView,
    medium: &wgpu::TextureView,
) -> wgpu::BindGroup {
    device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("tank update"),
        layout,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: wgpu::BindingResource::Buffer(wgpu::BufferBinding {
                    buffer: uniforms,
                    offset: slot as u64 * UPDATE_SLOT,
                    size: wgpu::BufferSize::new(std::mem::size_of::<Update>() as u64),
                }),
            },
            wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(state) },
            wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(medium) },
        ],
    })
}
