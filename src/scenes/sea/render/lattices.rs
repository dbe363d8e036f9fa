//! The sea's cascades as its shader reads them: one half-float array layer per cascade,
//! sampled filtered and wrapping round its tile. They come from the GPU's FFT, whose last
//! stage writes each cascade into its layer, or from the CPU's lattices, uploaded (devices
//! without float targets).

use crate::ambient::gpu_ocean::{GpuOcean, LayerTargets};
use crate::ambient::ocean::Ocean;
use crate::gpu;
use crate::sea::SEA_LATTICE;

use crate::ambient::cascades::CASCADE_COUNT;

const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba16Float;

/// Where a frame's cascades come from: surface (h, dh/dx, dh/dz, dDx/dz) and displacement
/// (Dx, Dz, dDx/dx, dDz/dz), each in its cascade's frame.
#[derive(Clone, Copy)]
pub enum SeaLattices<'a> {
    /// The CPU's (`SeaWaves::layers`): cascade after cascade, rows of `SEA_LATTICE` texels.
    Texels([&'a [[f32; 4]]; 2]),
    /// The cascades' oceans (`SeaWaves::cascades`) at time `t` (s): their FFT on the GPU.
    Fft { oceans: &'a [&'a Ocean], t: f64 },
}

/// The cascades' half-float maps and, once it fills them, the GPU's FFT writing into them.
pub struct LatticeMaps {
    maps: [wgpu::Texture; 2],
    fft: Option<(GpuOcean, LayerTargets)>,
}

impl LatticeMaps {
    pub fn new(device: &wgpu::Device) -> Self {
        let usage = wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_DST
            | wgpu::TextureUsages::RENDER_ATTACHMENT;
        let map = |label| {
            let (n, layers) = (SEA_LATTICE as u32, CASCADE_COUNT as u32);
            gpu::texture_2d(device, label, (n, n, layers), 1, FORMAT, usage)
        };
        Self { maps: [map("sea surface"), map("sea displacement")], fft: None }
    }

    /// The surface's and the displacement's maps, each layers of an array.
    pub fn views(&self) -> [wgpu::TextureView; 2] {
        self.maps.each_ref().map(|m| {
            m.create_view(&wgpu::TextureViewDescriptor {
                dimension: Some(wgpu::TextureViewDimension::D2Array),
                ..Default::default()
            })
        })
    }

    /// Fills the maps with this frame's cascades: uploads the CPU's, or records the GPU's FFT
    /// into `encoder`.
    pub fn fill(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        lattices: SeaLattices,
    ) {
        match lattices {
            SeaLattices::Texels(texels) => {
                for (map, texels) in self.maps.iter().zip(texels) {
                    let halves: Vec<[u16; 4]> = texels.iter().map(|t| t.map(f16_bits)).collect();
                    gpu::write_texture_2d(queue, map, 0, bytemuck::cast_slice(&halves));
                }
            }
            SeaLattices::Fft { oceans, t } => {
                let (n, count) = (SEA_LATTICE as u32, oceans.len() as u32);
                if self.fft.as_ref().is_none_or(|(fft, _)| (fft.size(), fft.count()) != (n, count)) {
                    let fft = GpuOcean::new(device, n, count);
                    let layers = fft.layer_targets(device, self.maps.each_ref());
                    self.fft = Some((fft, layers));
                }
                let (fft, layers) = self.fft.as_mut().expect("made above");
                fft.encode_into(queue, encoder, oceans, t, Some(layers));
            }
        }
    }
}

/// The half-precision float nearest `x` (round half up; under 2^-14 flushed to zero, past the
/// largest to infinity: the waves' heights and slopes lie well between). Half floats are
/// filterable on every backend, so the shader reads each cascade in one bilinear fetch that
/// wraps round its tile (32-bit floats are not).
pub(super) fn f16_bits(x: f32) -> u16 {
    let bits = x.to_bits();
    let sign = ((bits >> 16) & 0x8000) as u16;
    let exponent = ((bits >> 23) & 0xff) as i32 - 127 + 15;
    if exponent <= 0 {
        return sign;
    }
    if exponent >= 31 {
        return sign | 0x7c00;
    }
    let mantissa = bits & 0x7f_ffff;
    let rounded = (((exponent as u32) << 10) | (mantissa >> 13)) + ((mantissa >> 12) & 1);
    sign | rounded.min(0x7c00) as u16
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_floats_keep_the_waves_numbers_to_three_decimal_digits() {
        for x in [0.0f32, 1.0, -2.5, 0.3337, 1.0e-3, 7.99, -0.0123] {
            let h = f16_bits(x);
            // Back from half precision by its definition: sign, 5-bit exponent, 10-bit fraction.
            let (e, f) = (((h >> 10) & 0x1f) as i32, (h & 0x3ff) as f32);
            let back = if e == 0 { 0.0 } else { (1.0 + f / 1024.0) * 2f32.powi(e - 15) };
            let back = if h & 0x8000 != 0 { -back } else { back };
            assert!((back - x).abs() <= x.abs() / 1024.0 + 1.0e-7, "{x} came back as {back}");
        }
        assert_eq!(f16_bits(1.0), 0x3c00);
        assert_eq!(f16_bits(-2.0), 0xc000);
    }
}
