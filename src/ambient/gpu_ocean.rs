//! The FFT ocean's surface made on the GPU every frame: one spectrum pass and 2·log₂N
//! Stockham stages (shaders/ambient_fft.wgsl), full-screen fragment passes over RGBA32Float
//! ping-pong textures, so WebGPU and WebGL2 (with float render targets) run the same code.
//! Devices without float render targets take the CPU's [`Ocean::surface`] instead, which
//! runs the same stages ([`super::ocean::inverse_fft_2d`]).

use super::ocean::{epoch_of, Band, Ocean};
use crate::gpu::{self, FullscreenPass, FullscreenTarget, PingPong};

/// Format of the spectrum and of the passes' targets: two complex numbers per texel.
const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;

pub struct GpuOcean {
    size: u32,
    /// The spectrum at its epoch (`Ocean::epoch_spectrum`), re-uploaded when the ocean (its
    /// amplitudes or its band) or the epoch changes.
    spectrum: wgpu::Texture,
    uploaded: Option<(Vec<[f32; 4]>, Band, f64)>,
    time: wgpu::Buffer,
    spectrum_groups: [wgpu::BindGroup; 2],
    stage_pass: FullscreenPass,
    /// The surface's chain (height, slopes, ∂Dx/∂z) and the displacement's (Dx, Dz, ∂Dx/∂x,
    /// ∂Dz/∂z; run only with choppiness).
    chains: [Chain; 2],
}

/// One inverse FFT: its spectrum pass, its targets and its stages' bind groups.
struct Chain {
    spectrum_pass: FullscreenPass,
    /// The passes' targets; every frame's chain starts afresh and ends in texture 1.
    fields: PingPong,
    output: wgpu::TextureView,
    /// Per stage (rows first, then columns), its bind groups reading texture 0 or 1.
    stage_groups: Vec<[wgpu::BindGroup; 2]>,
}

impl GpuOcean {
    /// The passes for a lattice of `size`² points (a power of two).
    pub fn new(device: &wgpu::Device, size: u32) -> Self {
        let vis = wgpu::ShaderStages::FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("ocean fft layout"),
            entries: &[gpu::uniform_entry(0, vis), gpu::float_texture_entry(1, vis)],
        });
        let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
        let spectrum = gpu::texture_2d(device, "ocean spectrum", size, size, 1, 1, FORMAT, usage);
        let spectrum_view = spectrum.create_view(&Default::default());
        let group = |buffer: &wgpu::Buffer, view: &wgpu::TextureView| {
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("ocean fft"),
                layout: &layout,
                entries: &[
                    wgpu::BindGroupEntry { binding: 0, resource: buffer.as_entire_binding() },
                    wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(view) },
                ],
            })
        };
        let time = gpu::uniform_buffer(device, "ocean time", &[0.0f32; 8]);
        let spectrum_groups = [group(&time, &spectrum_view), group(&time, &spectrum_view)];
        let mut stage_buffers = Vec::new();
        for axis in [0.0f32, 1.0] {
            let mut half = 1;
            while half < size {
                let params = [half as f32, axis, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
                stage_buffers.push(gpu::uniform_buffer(device, "ocean stage", &params));
                half *= 2;
            }
        }
        let target = || FullscreenTarget { format: FORMAT, blend: None, depth: None };
        let constants = super::wgsl_constants();
        let parts = [constants.as_str(), gpu::wgsl::MATH, crate::wgsl!("ambient_fft.wgsl")];
        let chain = |label: &str, entry: &str| {
            let fields = PingPong::new(device, label, size, size, FORMAT, true);
            let views = [0, 1].map(|i| fields.textures()[i].create_view(&Default::default()));
            let stage_groups = stage_buffers.iter().map(|b| [group(b, &views[0]), group(b, &views[1])]).collect();
            let spectrum_pass = FullscreenPass::new(device, label, &parts, entry, &[&layout], target());
            let [_, output] = views;
            Chain { spectrum_pass, fields, output, stage_groups }
        };
        let chains =
            [chain("ocean surface", "fs_ocean_spectrum"), chain("ocean displacement", "fs_ocean_choppy_spectrum")];
        let stage_pass = FullscreenPass::new(device, "ocean fft stage", &parts, "fs_ocean_stage", &[&layout], target());
        Self { size, spectrum, uploaded: None, time, spectrum_groups, stage_pass, chains }
    }

    /// Lattice points per side.
    pub fn size(&self) -> u32 {
        self.size
    }

    /// Encodes the passes that make `ocean`'s surface (the pool's, or a sea cascade's) at
    /// simulated time `t` (s) in
    /// [`GpuOcean::surface`] (per texel height (m), ∂h/∂x, ∂h/∂z, ∂Dx/∂z, as `Ocean::surface`)
    /// and, with choppiness, its displacement in [`GpuOcean::displacement`] (as
    /// `Ocean::displacement`).
    pub fn encode(&mut self, queue: &wgpu::Queue, encoder: &mut wgpu::CommandEncoder, ocean: &Ocean, t: f64) {
        let epoch = epoch_of(t);
        let fresh =
            self.uploaded.as_ref().is_some_and(|(h0, band, at)| *at == epoch && *band == ocean.band && *h0 == ocean.h0);
        if !fresh {
            let texels = ocean.epoch_spectrum(epoch);
            gpu::write_texture_2d(queue, &self.spectrum, 0, bytemuck::cast_slice(&texels));
            self.uploaded = Some((ocean.h0.clone(), ocean.band, epoch));
        }
        let band = [std::f32::consts::PI / ocean.band.half_tile, ocean.band.depth];
        queue.write_buffer(
            &self.time,
            0,
            bytemuck::cast_slice(&[0.0f32, 0.0, (t - epoch) as f32, 0.0, band[0], band[1], 0.0, 0.0]),
        );
        let chains = if ocean.choppiness > 0.0 { &mut self.chains[..] } else { &mut self.chains[..1] };
        for chain in chains {
            chain.fields.restart();
            chain.fields.run(encoder, &chain.spectrum_pass, &self.spectrum_groups);
            for groups in &chain.stage_groups {
                chain.fields.run(encoder, &self.stage_pass, groups);
            }
            debug_assert_eq!(chain.fields.current(), 1);
        }
    }

    /// The surface the last [`GpuOcean::encode`] made (the ambient map the renderer reads).
    pub fn surface(&self) -> &wgpu::TextureView {
        &self.chains[0].output
    }

    /// The displacement the last [`GpuOcean::encode`] with choppiness made.
    pub fn displacement(&self) -> &wgpu::TextureView {
        &self.chains[1].output
    }

    /// The textures behind [`GpuOcean::surface`] and [`GpuOcean::displacement`] (for tests
    /// to read back).
    pub fn output_textures(&self) -> [&wgpu::Texture; 2] {
        [&self.chains[0].fields.textures()[1], &self.chains[1].fields.textures()[1]]
    }
}
