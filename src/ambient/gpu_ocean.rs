//! The FFT ocean's surface made on the GPU every frame: a spectrum pass, then Stockham's
//! stages of radix up to 4 (`GPU_RADIX`; shaders/ambient_fft.wgsl; three along the rows and
//! three along the columns of a 64² lattice), as full-screen fragment passes over RGBA32Float ping-pong
//! textures, so WebGPU and WebGL2 (with float render targets) run the same code.
//! With choppiness each pass writes the displacement's fields too (a second target). Several
//! lattices of one size (the sea's cascades) lie side by side in the same textures, each N
//! texels wide, and every pass transforms them all at once; the last stage can write each
//! lattice into a layer of the caller's array textures instead (the sea's half-float maps,
//! [`GpuOcean::layer_targets`]). Devices without float render
//! targets take the CPU's [`Ocean::surface`] instead, which gathers the same way by radix-2
//! stages ([`super::ocean::inverse_fft_2d`]; the GPU's plan is [`super::ocean::inverse_fft_2d_by`]).

use super::ocean::{epoch_of, fft_plan, Band, Ocean, GPU_RADIX};
use crate::gpu::{self, FullscreenPass, FullscreenTarget, PingPong};
use bytemuck::Zeroable;
use std::rc::Rc;

/// Format of the spectrum and of the passes' targets: two complex numbers per texel.
const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba32Float;
/// The most lattices one [`GpuOcean`] transforms side by side (its uniform's band array).
pub const MAX_LATTICES: usize = 8;

/// The passes' uniform (shaders/ambient_fft.wgsl `FftStage`).
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct StageUniform {
    params: [f32; 4],
    time: [f32; 4],
    bands: [[f32; 4]; MAX_LATTICES],
}

/// A pass's uniform, its bind groups (reading the spectrum, for the spectrum pass, or the
/// ping-pong textures 0 or 1) and its pipelines, `[surface only, both]`.
struct Pass {
    /// Its uniform's stage parameters (radix, span, axis, first column read).
    params: [f32; 4],
    uniform: wgpu::Buffer,
    groups: [wgpu::BindGroup; 2],
    pipelines: [Rc<FullscreenPass>; 2],
}

/// The last stage written into layers of array textures (`GpuOcean::layer_targets`): per
/// lattice, its pass and the layer's views `[surface, displacement]`.
pub struct LayerTargets {
    passes: Vec<(Pass, [wgpu::TextureView; 2])>,
}

/// What the passes are made from: the bind group layout and the textures they read.
struct Sources {
    layout: wgpu::BindGroupLayout,
    spectrum: wgpu::TextureView,
    /// Per field, the ping-pong textures' views.
    fields: [[wgpu::TextureView; 2]; 2],
}

impl Sources {
    /// A pass's bind groups reading the ping-pong textures 0 and 1 (or the spectrum, twice).
    fn groups(&self, device: &wgpu::Device, uniform: &wgpu::Buffer, spectrum: bool) -> [wgpu::BindGroup; 2] {
        [0, 1].map(|i| {
            let [a, b] = if spectrum { [&self.spectrum; 2] } else { [&self.fields[0][i], &self.fields[1][i]] };
            device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("ocean fft"),
                layout: &self.layout,
                entries: &[
                    wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() },
                    wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(a) },
                    wgpu::BindGroupEntry { binding: 2, resource: wgpu::BindingResource::TextureView(b) },
                ],
            })
        })
    }

    /// The pipelines `[surface only, both]` of the fragment entries `entries` for stages of
    /// `radix`, writing `format`.
    fn pipelines(
        &self,
        device: &wgpu::Device,
        radix: usize,
        entries: [&str; 2],
        format: wgpu::TextureFormat,
    ) -> [Rc<FullscreenPass>; 2] {
        let constants = format!(
            "{}const FFT_MAX_LATTICES: u32 = {MAX_LATTICES}u;\nconst FFT_RADIX: i32 = {radix};\n\
             const FFT_RADIX_LOG2: u32 = {}u;\n",
            super::wgsl_constants(),
            radix.trailing_zeros()
        );
        let parts = [constants.as_str(), gpu::wgsl::MATH, crate::wgsl!("ambient_fft.wgsl")];
        [(entries[0], 1), (entries[1], 2)].map(|(entry, targets)| {
            let targets: Vec<_> = (0..targets).map(|_| FullscreenTarget { format, blend: None, depth: None }).collect();
            Rc::new(FullscreenPass::with_targets(device, "ocean fft", &parts, entry, &[&self.layout], &targets))
        })
    }
}

/// What the spectrum texture holds: each lattice's amplitudes and band, at an epoch (s).
type Uploaded = (Vec<(Vec<[f32; 4]>, Band)>, f64);

pub struct GpuOcean {
    size: u32,
    count: u32,
    /// The lattices' spectra at their epoch (`Ocean::epoch_spectrum`), side by side,
    /// re-uploaded when an ocean (its amplitudes or its band) or the epoch changes.
    spectrum: wgpu::Texture,
    uploaded: Option<Uploaded>,
    sources: Sources,
    /// The spectrum pass, then the stages along the rows and along the columns.
    passes: Vec<Pass>,
    /// The surface's fields (height, slopes, ∂Dx/∂z) and the displacement's (Dx, Dz, ∂Dx/∂x,
    /// ∂Dz/∂z; written only with choppiness), each pass writing the texture the last read
    /// not; the last stage's in texture `output`.
    fields: [PingPong; 2],
    output: usize,
}

impl GpuOcean {
    /// The passes for `count` lattices of `size`² points each (a power of two), side by side.
    pub fn new(device: &wgpu::Device, size: u32, count: u32) -> Self {
        assert!((1..=MAX_LATTICES as u32).contains(&count), "{count} lattices in one FFT");
        let width = size * count;
        let vis = wgpu::ShaderStages::FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("ocean fft layout"),
            entries: &[gpu::uniform_entry(0, vis), gpu::float_texture_entry(1, vis), gpu::float_texture_entry(2, vis)],
        });
        let usage = wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST;
        let spectrum = gpu::texture_2d(device, "ocean spectrum", (width, size, 1), 1, FORMAT, usage);
        let fields =
            ["ocean surface", "ocean displacement"].map(|l| PingPong::new(device, l, width, size, FORMAT, true));
        let sources = Sources {
            layout,
            spectrum: spectrum.create_view(&Default::default()),
            fields: fields.each_ref().map(|f| [0, 1].map(|i| f.view(i).clone())),
        };
        let uniform = gpu::uniform_buffer(device, "ocean spectrum", &StageUniform::zeroed());
        let groups = sources.groups(device, &uniform, true);
        let pipelines =
            sources.pipelines(device, GPU_RADIX, ["fs_fft_spectrum_surface", "fs_fft_spectrum_both"], FORMAT);
        let mut passes = vec![Pass { params: [0.0; 4], uniform, groups, pipelines }];
        let mut stage_pipelines = std::collections::BTreeMap::new();
        for axis in [0.0f32, 1.0] {
            for &(radix, span) in &fft_plan(size as usize, GPU_RADIX) {
                let params = [radix as f32, span as f32, axis, 0.0];
                let uniform =
                    gpu::uniform_buffer(device, "ocean stage", &StageUniform { params, ..Zeroable::zeroed() });
                let groups = sources.groups(device, &uniform, false);
                let pipelines = stage_pipelines
                    .entry(radix)
                    .or_insert_with(|| sources.pipelines(device, radix, ["fs_fft_surface", "fs_fft_both"], FORMAT))
                    .clone();
                passes.push(Pass { params, uniform, groups, pipelines });
            }
        }
        // Pass k writes texture (k + 1) mod 2.
        let output = passes.len() % 2;
        Self { size, count, spectrum, uploaded: None, sources, passes, fields, output }
    }

    /// Lattice points per side.
    pub fn size(&self) -> u32 {
        self.size
    }

    /// How many lattices lie side by side.
    pub fn count(&self) -> u32 {
        self.count
    }

    /// The last stage written into `layers` (the surface's and the displacement's array
    /// textures, [`GpuOcean::count`] layers of its size each, any float format a render
    /// target takes): lattice i into layer i. See [`GpuOcean::encode_into`].
    pub fn layer_targets(&self, device: &wgpu::Device, layers: [&wgpu::Texture; 2]) -> LayerTargets {
        let last = self.passes.last().expect("an FFT has stages");
        let (format, radix) = (layers[0].format(), last.params[0] as usize);
        let pipelines = self.sources.pipelines(device, radix, ["fs_fft_surface", "fs_fft_both"], format);
        let passes = (0..self.count)
            .map(|i| {
                // The stage's own, reading from lattice i's first column.
                let mut params = last.params;
                params[3] = (i * self.size) as f32;
                let uniform =
                    gpu::uniform_buffer(device, "ocean layer", &StageUniform { params, ..Zeroable::zeroed() });
                let groups = self.sources.groups(device, &uniform, false);
                let views = layers.map(|t| {
                    t.create_view(&wgpu::TextureViewDescriptor {
                        dimension: Some(wgpu::TextureViewDimension::D2),
                        base_array_layer: i,
                        array_layer_count: Some(1),
                        ..Default::default()
                    })
                });
                (Pass { params, uniform, groups, pipelines: pipelines.clone() }, views)
            })
            .collect();
        LayerTargets { passes }
    }

    /// Encodes the passes that make the `oceans`' surfaces (the pool's, or the sea's
    /// cascades; as many as [`GpuOcean::count`], of its size) at simulated time `t` (s) in
    /// [`GpuOcean::surface`] (per texel height (m), ∂h/∂x, ∂h/∂z, ∂Dx/∂z, as `Ocean::surface`;
    /// ocean i in columns i N to (i + 1) N) and, with choppiness, their displacements in
    /// [`GpuOcean::displacement`] (as `Ocean::displacement`).
    pub fn encode(&mut self, queue: &wgpu::Queue, encoder: &mut wgpu::CommandEncoder, oceans: &[&Ocean], t: f64) {
        self.encode_into(queue, encoder, oceans, t, None);
    }

    /// [`GpuOcean::encode`], the last stage writing into `layers` if given (and not into
    /// [`GpuOcean::surface`] and [`GpuOcean::displacement`]).
    pub fn encode_into(
        &mut self,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        oceans: &[&Ocean],
        t: f64,
        layers: Option<&LayerTargets>,
    ) {
        assert_eq!(oceans.len(), self.count as usize, "one ocean per lattice");
        self.upload(queue, oceans, t);
        let both = oceans.iter().any(|o| o.choppiness > 0.0);
        let fields = if both { &self.fields[..] } else { &self.fields[..1] };
        let own = if layers.is_some() { self.passes.len() - 1 } else { self.passes.len() };
        for (k, pass) in self.passes[..own].iter().enumerate() {
            let (read, write) = (k % 2, (k + 1) % 2);
            let targets: Vec<_> = fields.iter().map(|f| f.view(write)).collect();
            pass.pipelines[usize::from(both)].run_on(encoder, &targets, &[&pass.groups[read]]);
        }
        for (pass, views) in layers.map_or(&[][..], |l| &l.passes[..]) {
            let targets: Vec<_> = views.iter().take(fields.len()).collect();
            pass.pipelines[usize::from(both)].run_on(encoder, &targets, &[&pass.groups[own % 2]]);
        }
    }

    /// Uploads the oceans' spectra when they or the epoch changed, and the spectrum pass's
    /// time and bands.
    fn upload(&mut self, queue: &wgpu::Queue, oceans: &[&Ocean], t: f64) {
        let epoch = epoch_of(t);
        let fresh = self.uploaded.as_ref().is_some_and(|(made, at)| {
            *at == epoch && made.iter().zip(oceans).all(|((h0, band), o)| *band == o.band && *h0 == o.h0)
        });
        if !fresh {
            for (i, ocean) in oceans.iter().enumerate() {
                debug_assert_eq!(ocean.size as u32, self.size);
                let texels = ocean.epoch_spectrum(epoch);
                write_block(queue, &self.spectrum, i as u32 * self.size, self.size, bytemuck::cast_slice(&texels));
            }
            self.uploaded = Some((oceans.iter().map(|o| (o.h0.clone(), o.band)).collect(), epoch));
        }
        let mut bands = [[0.0; 4]; MAX_LATTICES];
        for (band, ocean) in bands.iter_mut().zip(oceans) {
            *band = [std::f32::consts::PI / ocean.band.half_tile, ocean.band.depth, 0.0, 0.0];
        }
        let time = [(t - epoch) as f32, self.size.trailing_zeros() as f32, 0.0, 0.0];
        let offset = std::mem::offset_of!(StageUniform, time) as u64;
        queue.write_buffer(&self.passes[0].uniform, offset, bytemuck::cast_slice(&[time]));
        queue.write_buffer(&self.passes[0].uniform, offset + 16, bytemuck::cast_slice(&bands));
    }

    /// The surface the last [`GpuOcean::encode`] made (the ambient map the renderer reads;
    /// not written by [`GpuOcean::encode_into`] with layers).
    pub fn surface(&self) -> &wgpu::TextureView {
        self.fields[0].view(self.output)
    }

    /// The displacement the last [`GpuOcean::encode`] with choppiness made.
    pub fn displacement(&self) -> &wgpu::TextureView {
        self.fields[1].view(self.output)
    }

    /// The textures behind [`GpuOcean::surface`] and [`GpuOcean::displacement`] (for tests
    /// to read back).
    pub fn output_textures(&self) -> [&wgpu::Texture; 2] {
        self.fields.each_ref().map(|f| &f.textures()[self.output])
    }
}

/// Copies `data` (a `size`² lattice, rows top first) into the block of `texture` whose first
/// column is `column`.
fn write_block(queue: &wgpu::Queue, texture: &wgpu::Texture, column: u32, size: u32, data: &[u8]) {
    let texel = FORMAT.block_copy_size(None).expect("colour format");
    queue.write_texture(
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: 0,
            origin: wgpu::Origin3d { x: column, y: 0, z: 0 },
            aspect: wgpu::TextureAspect::All,
        },
        data,
        wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(size * texel), rows_per_image: Some(size) },
        wgpu::Extent3d { width: size, height: size, depth_or_array_layers: 1 },
    );
}
