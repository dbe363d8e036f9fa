//! The FFT ocean's surface made on the GPU every frame: one spectrum pass and 2·log₂N
//! Stockham stages (shaders/ambient_fft.wgsl), full-screen fragment passes over RGBA32Float
//! ping-pong textures, so WebGPU and WebGL2 (with float render targets) run the same code.
//! Devices without float render targets take the CPU's [`Ocean::surface`] instead, which
//! runs the same stages ([`super::ocean::inverse_fft_2d`]).

use super::ocean::{epoch_of, Ocean};
use crate::gpu::{self, FullscreenPass, FullscreenTarget, PingPong};

/// Format of the spectrum and of the passes' targets: two complex numbers per texel.
const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;

pub struct GpuOcean {
    size: u32,
    /// The spectrum at its epoch (`Ocean::epoch_spectrum`), re-uploaded when the ocean or the
    /// epoch changes.
    spectrum: wgpu::Texture,
    uploaded: Option<(Vec<[f32; 4]>, f64)>,
    /// The passes' targets; every frame's chain starts afresh and ends in texture 1.
    fields: PingPong,
    surface: wgpu::TextureView,
    time: wgpu::Buffer,
    spectrum_pass: FullscreenPass,
    spectrum_groups: [wgpu::BindGroup; 2],
    stage_pass: FullscreenPass,
    /// Per stage (rows first, then columns), its bind groups reading texture 0 or 1.
    stage_groups: Vec<[wgpu::BindGroup; 2]>,
}

impl GpuOcean {
    /// The passes for a lattice of `size`² points (a power of two).
    pub fn new(device: &wgpu::Device, size: u32) -> Self {
        let vis = wgpu::ShaderStages::FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("ocean fft layout"),
            entries: &[
                gpu::uniform_entry(0, vis),
                gpu::texture_entry(
                    1,
                    vis,
                    wgpu::TextureSampleType::Float { filterable: false },
                    wgpu::TextureViewDimension::D2,
                ),
            ],
        });
        let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
        let spectrum = gpu::texture_2d(device, "ocean spectrum", size, size, 1, 1, FORMAT, usage);
        let spectrum_view = spectrum.create_view(&Default::default());
        let fields = PingPong::new(device, "ocean fields", size, size, FORMAT, true);
        let views = [0, 1].map(|i| fields.textures()[i].create_view(&Default::default()));
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
        let time = gpu::uniform_buffer(device, "ocean time", &[0.0f32; 4]);
        let spectrum_groups = [group(&time, &spectrum_view), group(&time, &spectrum_view)];
        let mut stage_groups = Vec::new();
        for axis in [0.0f32, 1.0] {
            let mut half = 1;
            while half < size {
                let buffer = gpu::uniform_buffer(device, "ocean stage", &[half as f32, axis, 0.0, 0.0]);
                stage_groups.push([group(&buffer, &views[0]), group(&buffer, &views[1])]);
                half *= 2;
            }
        }
        let target = || FullscreenTarget { format: FORMAT, blend: None, depth: None };
        let parts = [gpu::wgsl::AMBIENT_FFT];
        let spectrum_pass =
            FullscreenPass::new(device, "ocean spectrum", &parts, "fs_ocean_spectrum", &[&layout], target());
        let stage_pass = FullscreenPass::new(device, "ocean fft stage", &parts, "fs_ocean_stage", &[&layout], target());
        let [_, surface] = views;
        Self {
            size,
            spectrum,
            uploaded: None,
            fields,
            surface,
            time,
            spectrum_pass,
            spectrum_groups,
            stage_pass,
            stage_groups,
        }
    }

    /// Lattice points per side.
    pub fn size(&self) -> u32 {
        self.size
    }

    /// Encodes the passes that make `ocean`'s surface at simulated time `t` (s) in
    /// [`GpuOcean::surface`]: per texel height (m), ∂h/∂x, ∂h/∂z and 0, as `Ocean::surface`.
    pub fn encode(&mut self, queue: &wgpu::Queue, encoder: &mut wgpu::CommandEncoder, ocean: &Ocean, t: f64) {
        let epoch = epoch_of(t);
        let fresh = self.uploaded.as_ref().is_some_and(|(h0, at)| *at == epoch && *h0 == ocean.h0);
        if !fresh {
            let texels = ocean.epoch_spectrum(epoch);
            queue.write_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: &self.spectrum,
                    mip_level: 0,
                    origin: wgpu::Origin3d::ZERO,
                    aspect: wgpu::TextureAspect::All,
                },
                bytemuck::cast_slice(&texels),
                wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(self.size * 16), rows_per_image: None },
                wgpu::Extent3d { width: self.size, height: self.size, depth_or_array_layers: 1 },
            );
            self.uploaded = Some((ocean.h0.clone(), epoch));
        }
        queue.write_buffer(&self.time, 0, bytemuck::cast_slice(&[0.0f32, 0.0, (t - epoch) as f32, 0.0]));
        self.fields.restart();
        self.fields.run(encoder, &self.spectrum_pass, &self.spectrum_groups);
        for groups in &self.stage_groups {
            self.fields.run(encoder, &self.stage_pass, groups);
        }
        debug_assert_eq!(self.fields.current(), 1);
    }

    /// The surface the last [`GpuOcean::encode`] made (the ambient map the renderer reads).
    pub fn surface(&self) -> &wgpu::TextureView {
        &self.surface
    }

    /// The texture behind [`GpuOcean::surface`] (for tests to read back).
    pub fn surface_texture(&self) -> &wgpu::Texture {
        &self.fields.textures()[1]
    }
}
