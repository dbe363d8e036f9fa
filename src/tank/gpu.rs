//! The tank's water on the GPU: its state in a ping-pong pair of float textures advanced by
//! one full-screen pass per update (`shaders/tank/update.wgsl`), its cells' medium in a
//! texture, each update's uniforms in a slot of one buffer. Where the device cannot render
//! into float textures the CPU reference runs instead and its state is uploaded.

use super::cpu::CpuTank;
use super::medium::Medium;
use super::plan::{Update, UPDATE_SLOT};
use super::{INTENSITY_TIME, MAX_DIPPERS, MAX_TANK_DROPS};
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
        let mut water = Self { state, medium: medium_texture, medium_view, engine, cells, flash: None };
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
                }
            }
            Engine::Cpu(_) if updates.is_empty() => {}
            Engine::Cpu(tank) => {
                let texels =
                    |tank: &CpuTank| -> Vec<[f32; 4]> { tank.state.iter().map(|&[h, v, i]| [h, v, i, 0.0]).collect() };
                let split = flash.map_or(0, |k| k + 1);
                tank.run(&updates[..split]);
                if let Some((texture, _)) = &self.flash {
                    if flash.is_some() {
                        gpu::write_texture_2d(queue, texture, 0, bytemuck::cast_slice(&texels(tank)));
                    }
                }
                tank.run(&updates[split..]);
                gpu::write_texture_2d(queue, self.state.current_texture(), 0, bytemuck::cast_slice(&texels(tank)));
            }
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
