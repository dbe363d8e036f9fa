//! Procedural textures, made by our own code at start-up: the pool tiles (CPU, with mip
//! levels) and the sky cubemap (GPU, one full-screen pass per face, redone when the sun moves).

use glam::Vec3;

use crate::gpu::{self, FullscreenPass, FullscreenTarget};
use crate::sky::Daylight;
use crate::util::hash01;

/// Tiles per metre along each axis (12.5 cm tiles).
pub const TILES_PER_METRE: u32 = 8;
/// Radius (m) of the cove the tiles turn the pool's inside corners on (a cove tile, as real
/// pools have between floor and wall): within it of a corner the tiles are lit by a normal
/// turning from one face's to the other's (`coved_normal`, shaders/scene_trace.wgsl).
pub const POOL_COVE_RADIUS: f32 = 0.04;
/// Side of the tile texture in texels; it covers 1 m x 1 m and repeats.
pub const TILE_TEXTURE_SIZE: u32 = 512;
/// Side of each sky cube face in texels.
pub const SKY_FACE_SIZE: u32 = 256;
pub const SKY_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

fn srgb_to_linear(c: f32) -> f32 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

fn linear_to_srgb(c: f32) -> f32 {
    if c <= 0.0031308 {
        c * 12.92
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    }
}

/// Encodes linear values in sRGB 8 bits exactly as `(linear_to_srgb(v) * 255).round()` does,
/// by a binary search among the 255 values of v where that result steps up, found once:
/// the tile texture encodes 350,000 texels per channel, and a `powf` each made its making
/// the longest task of a page's start-up.
struct SrgbEncoder {
    /// `steps[k - 1]`: the least v (in [0, 1]) encoded as k or more.
    steps: Vec<f32>,
}

impl SrgbEncoder {
    fn direct(v: f32) -> u8 {
        (linear_to_srgb(v) * 255.0).round() as u8
    }

    fn new() -> Self {
        let steps = (1..=255u8)
            .map(|k| {
                // Bisection over the bit patterns of [0, 1], which order as the values do.
                let (mut low, mut high) = (0u32, 1.0f32.to_bits());
                while low < high {
                    let mid = low + (high - low) / 2;
                    if Self::direct(f32::from_bits(mid)) >= k {
                        high = mid;
                    } else {
                        low = mid + 1;
                    }
                }
                f32::from_bits(low)
            })
            .collect();
        Self { steps }
    }

    fn encode(&self, v: f32) -> u8 {
        self.steps.partition_point(|&step| step <= v) as u8
    }
}

/// Linear RGB of the tile texture at texel (x, y): light blue glazed tiles, each a little
/// different, a soft bevel at their edges and grout a quarter darker (in sRGB) between them;
/// and the glaze's cover there (1 on a tile, 0 on the grout: `render::glaze`). Dark grout,
/// broken up by the ripples the floor is seen through, read as black specks and was most of
/// what the frame's aliasing bench found; pale blue-white tiles put the calm floor so high on
/// the tone curve that the caustic lines had little room above it (both 2026-11-29).
/// The tiles' colour (sRGB) before each tile's variation and bevel.
const TILE_SRGB: [f32; 3] = [0.60, 0.76, 0.86];
/// The grout's colour as a share of the tiles' (sRGB).
const GROUT_SHADE: f32 = 0.75;

fn tile_texel(x: u32, y: u32) -> ([f32; 3], f32) {
    let tile = TILE_TEXTURE_SIZE / TILES_PER_METRE;
    let (tx, ty) = (x / tile, y / tile);
    let (fx, fy) = ((x % tile) as f32 + 0.5, (y % tile) as f32 + 0.5);
    let edge = fx.min(fy).min(tile as f32 - fx).min(tile as f32 - fy);
    let grout_width = 2.0;
    if edge < grout_width {
        return (TILE_SRGB.map(|c| srgb_to_linear(c * GROUT_SHADE)), 0.0);
    }
    let variation = (hash01(tx, ty) - 0.5) * 0.06;
    let bevel = 1.0 - 0.10 * (1.0 - ((edge - grout_width) / 3.0).min(1.0));
    let speckle = (hash01(x, y ^ 0x5bd1) - 0.5) * 0.015;
    (TILE_SRGB.map(|c| srgb_to_linear(((c + variation + speckle) * bevel).clamp(0.0, 1.0))), 1.0)
}

/// The tile texture with its full mip chain (box-filtered in linear light), RGBA8 sRGB: alpha
/// (linear) is the glaze's cover.
pub fn tile_mips() -> Vec<Vec<u8>> {
    let mut level: Vec<[f32; 4]> = (0..TILE_TEXTURE_SIZE * TILE_TEXTURE_SIZE)
        .map(|i| {
            let ([r, g, b], glaze) = tile_texel(i % TILE_TEXTURE_SIZE, i / TILE_TEXTURE_SIZE);
            [r, g, b, glaze]
        })
        .collect();
    let mut size = TILE_TEXTURE_SIZE as usize;
    let mut mips = Vec::new();
    let srgb = SrgbEncoder::new();
    loop {
        mips.push(
            level
                .iter()
                .flat_map(|c| {
                    [c[0], c[1], c[2]].map(|v| srgb.encode(v)).into_iter().chain([(c[3] * 255.0).round() as u8])
                })
                .collect(),
        );
        if size == 1 {
            break;
        }
        let half = size / 2;
        let mut next = vec![[0.0f32; 4]; half * half];
        for y in 0..half {
            for x in 0..half {
                let mut acc = [0.0f32; 4];
                for (dx, dy) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                    let c = level[(2 * y + dy) * size + 2 * x + dx];
                    for k in 0..4 {
                        acc[k] += c[k] * 0.25;
                    }
                }
                next[y * half + x] = acc;
            }
        }
        level = next;
        size = half;
    }
    mips
}

/// The tiles' mean albedo (linear RGB): the last of `mips`, one texel (sRGB-encoded).
pub fn tile_mean_albedo(mips: &[Vec<u8>]) -> glam::Vec3 {
    let last = mips.last().expect("the tiles' mip levels");
    glam::Vec3::from_array([0, 1, 2].map(|k| srgb_to_linear(last[k] as f32 / 255.0)))
}

/// The tile texture from its levels ([`tile_mips`], made ahead by a shell that spreads its
/// start-up over tasks).
pub fn create_tile_texture(device: &wgpu::Device, queue: &wgpu::Queue, mips: &[Vec<u8>]) -> wgpu::Texture {
    let texture = gpu::texture_2d(
        device,
        "tiles",
        (TILE_TEXTURE_SIZE, TILE_TEXTURE_SIZE, 1),
        mips.len() as u32,
        wgpu::TextureFormat::Rgba8UnormSrgb,
        wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
    );
    for (level, data) in mips.iter().enumerate() {
        gpu::write_texture_2d(queue, &texture, level as u32, data);
    }
    texture
}

/// The Fresnel lookup texture (optics::fresnel_table): R32Float, one row per side of the
/// surface, read with textureLoad and interpolated in the shader (32-bit float textures are
/// not filterable everywhere).
pub fn create_fresnel_table(device: &wgpu::Device, queue: &wgpu::Queue) -> wgpu::Texture {
    let size = crate::optics::FRESNEL_TABLE_SIZE;
    let texture = gpu::texture_2d(
        device,
        "Fresnel table",
        (size, 2, 1),
        1,
        wgpu::TextureFormat::R32Float,
        wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
    );
    gpu::write_texture_2d(queue, &texture, 0, bytemuck::cast_slice(&crate::optics::fresnel_table()));
    texture
}

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct SkyFaceUniforms {
    sun: [f32; 4],
    face: [f32; 4],
    /// Daylight::uniform: Perez rows for Y, x, y, their E, the zenith values.
    perez: [[f32; 4]; 5],
    sun_light: [f32; 4],
}

impl SkyFaceUniforms {
    fn new(face: usize, daylight: &Daylight) -> Self {
        let sun = daylight.sun;
        Self {
            sun: [sun.x, sun.y, sun.z, 0.0],
            face: [face as f32, 0.0, 0.0, 0.0],
            perez: daylight.uniform(),
            sun_light: daylight.sun_light.extend(0.0).to_array(),
        }
    }
}

/// The sky cubemap and the passes that paint it.
pub struct SkyCube {
    texture: wgpu::Texture,
    face_views: Vec<wgpu::TextureView>,
    face_uniforms: Vec<wgpu::Buffer>,
    face_groups: Vec<wgpu::BindGroup>,
    pass: FullscreenPass,
    painted_for: Option<Vec3>,
    daylight: Daylight,
}

impl SkyCube {
    pub fn new(device: &wgpu::Device) -> Self {
        let texture = gpu::texture_2d(
            device,
            "sky cube",
            (SKY_FACE_SIZE, SKY_FACE_SIZE, 6),
            1,
            SKY_FORMAT,
            wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::RENDER_ATTACHMENT,
        );
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("sky face layout"),
            entries: &[gpu::uniform_entry(0, wgpu::ShaderStages::FRAGMENT)],
        });
        let face_views = (0..6)
            .map(|face| {
                texture.create_view(&wgpu::TextureViewDescriptor {
                    label: Some("sky face"),
                    dimension: Some(wgpu::TextureViewDimension::D2),
                    base_array_layer: face,
                    array_layer_count: Some(1),
                    ..Default::default()
                })
            })
            .collect();
        let daylight = Daylight::new(Vec3::Y);
        let face_uniforms: Vec<wgpu::Buffer> = (0..6)
            .map(|face| gpu::uniform_buffer(device, "sky face uniforms", &SkyFaceUniforms::new(face, &daylight)))
            .collect();
        let face_groups = face_uniforms
            .iter()
            .map(|buffer| {
                device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("sky face group"),
                    layout: &layout,
                    entries: &[wgpu::BindGroupEntry { binding: 0, resource: buffer.as_entire_binding() }],
                })
            })
            .collect();
        let pass = FullscreenPass::new(
            device,
            "sky cube face",
            &[&Daylight::wgsl_constants(), gpu::wgsl::MATH, crate::wgsl!("sky_cube.wgsl")],
            "fs_sky_face",
            &[&layout],
            FullscreenTarget { format: SKY_FORMAT, blend: None, depth: None },
        );
        Self { texture, face_views, face_uniforms, face_groups, pass, painted_for: None, daylight }
    }

    /// The sky last painted: its sun's light and its ambient light.
    pub fn daylight(&self) -> &Daylight {
        &self.daylight
    }

    /// A cube view of the sky for sampling by direction.
    pub fn view(&self) -> wgpu::TextureView {
        self.texture.create_view(&wgpu::TextureViewDescriptor {
            label: Some("sky cube view"),
            dimension: Some(wgpu::TextureViewDimension::Cube),
            ..Default::default()
        })
    }

    /// Repaints the six faces if the sun moved since the last paint.
    pub fn update(&mut self, queue: &wgpu::Queue, encoder: &mut wgpu::CommandEncoder, sun: Vec3) {
        if self.painted_for == Some(sun) {
            return;
        }
        self.painted_for = Some(sun);
        self.daylight = Daylight::new(sun);
        for face in 0..6 {
            let u = SkyFaceUniforms::new(face, &self.daylight);
            queue.write_buffer(&self.face_uniforms[face], 0, bytemuck::bytes_of(&u));
            self.pass.run(encoder, &self.face_views[face], &[&self.face_groups[face]]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_srgb_encoder_gives_what_the_formula_gives() {
        let srgb = SrgbEncoder::new();
        // Every value of the tile texture's levels, and a sweep of [0, 1] with its ends.
        let mut values: Vec<f32> = (0..TILE_TEXTURE_SIZE * TILE_TEXTURE_SIZE)
            .flat_map(|i| tile_texel(i % TILE_TEXTURE_SIZE, i / TILE_TEXTURE_SIZE).0)
            .collect();
        values.extend((0..=100_000).map(|i| i as f32 / 100_000.0));
        values.extend([-0.1, 0.0, 1.0, 1.5, f32::MIN_POSITIVE]);
        let off = values.iter().filter(|&&v| srgb.encode(v) != SrgbEncoder::direct(v)).count();
        println!("{} values encoded, {off} differ from the formula", values.len());
        assert_eq!(off, 0);
    }

    #[test]
    fn tiles_have_grout_and_mips_average_them() {
        let mips = tile_mips();
        assert_eq!(mips.len(), 10);
        let base = &mips[0];
        let grout = base[0];
        let tile_centre = base[((32 * TILE_TEXTURE_SIZE + 32) * 4) as usize];
        // Grout a little darker than the tiles: visible, but under rippled water a broken grout
        // line is a faint mark, not a black speck.
        println!("tile centre {tile_centre}, grout {grout} (red, sRGB bytes)");
        let ratio = tile_centre as f32 / grout as f32;
        assert!((1.2..1.5).contains(&ratio), "tile {tile_centre} vs grout {grout}");
        // The last level is the whole texture's mean (box-filtered in linear light).
        let last = mips.last().unwrap()[0];
        let linear = |b: u8| srgb_to_linear(b as f32 / 255.0);
        let mean = base.chunks(4).map(|t| linear(t[0])).sum::<f32>() / (base.len() / 4) as f32;
        println!("the whole texture's mean {last}, its texels' {:.4} (linear)", mean);
        assert!(last > grout && (linear(last) - mean).abs() < 0.01);
        // The glaze covers the tiles, not the grout; far away it is their average.
        let glaze = |mip: &[u8], texel: u32| mip[(texel * 4 + 3) as usize];
        let (on_tile, on_grout) = (glaze(base, 32 * TILE_TEXTURE_SIZE + 32), glaze(base, 0));
        let average = glaze(mips.last().unwrap(), 0);
        println!("glaze cover: tile {on_tile}, grout {on_grout}, the whole texture {average} (of 255)");
        assert_eq!((on_tile, on_grout), (255, 0));
        assert!(average > 200 && average < 255, "{average}");
    }
}
