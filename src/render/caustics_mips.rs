//! The caustics map with its mip chain: each level is the box average of the one above (one
//! bilinear fetch at the centre of each 2x2 texels, `shaders/caustics_mip.wgsl`), so the scene
//! reads the caustics over a pixel's footprint on the floor with one trilinear fetch
//! (`caustics_under` in `shaders/scene_light.wgsl`) instead of several taps.

use crate::gpu::{self, FullscreenPass, FullscreenTarget};

/// Levels of the map: 512 texels down to 64 (a pixel never covers more of the floor).
pub const CAUSTICS_MIPS: u32 = 4;
/// The finest level the scene reads at: 0.7 blends in the next level's average, so lines
/// focused into one texel are about two wide and do not flicker from pixel to pixel.
pub const CAUSTICS_MIN_LOD: f32 = 0.7;
/// Depth (m) over which the caustics sharpen under the surface: the map holds the light on the
/// floor, where the waves' lenses have focused it; nearer the surface the light has gathered
/// less (while the slopes are small, a wave's focusing grows in proportion to the depth), so a
/// point just under it reads the map's coarsest level, and the level falls to the finest at
/// this depth. At 0.25 m (where a ripple a few centimetres long focuses) the walls showed the
/// floor's sharp net up to the surface, long streaks from top to bottom; the start's waves are
/// longer and gather deeper. 0.6 m fades the streaks upwards (the sparkle share from under the
/// water 0.41 % -> 0.35 %, natively, 2026-11-30).
pub const CAUSTICS_SHARPEN_DEPTH: f32 = 0.6;

/// The caustics map (`size` texels at level 0) and the passes that fill its lower levels.
pub struct CausticsMips {
    /// Every level, for sampling.
    pub view: wgpu::TextureView,
    /// Level 0: what the caustics pass draws into.
    pub target: wgpu::TextureView,
    /// Per lower level: its view as a target and the bind group reading the level above.
    levels: Vec<(wgpu::TextureView, wgpu::BindGroup)>,
    pass: FullscreenPass,
}

impl CausticsMips {
    pub fn new(device: &wgpu::Device, size: u32, format: wgpu::TextureFormat) -> Self {
        let mips = CAUSTICS_MIPS.min(size.ilog2() + 1);
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
        let texture = gpu::texture_2d(device, "caustics map", (size, size, 1), mips, format, usage);
        let level = |i: u32| {
            texture.create_view(&wgpu::TextureViewDescriptor {
                label: Some("caustics map level"),
                base_mip_level: i,
                mip_level_count: Some(1),
                ..Default::default()
            })
        };
        let vis = wgpu::ShaderStages::FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("caustics mip layout"),
            entries: &[gpu::filtered_texture_entry(0, vis), gpu::sampler_entry(1, vis)],
        });
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        let levels = (1..mips)
            .map(|i| {
                let above = level(i - 1);
                let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("caustics mip"),
                    layout: &layout,
                    entries: &[
                        wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&above) },
                        wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(&sampler) },
                    ],
                });
                (level(i), group)
            })
            .collect();
        let pass = FullscreenPass::new(
            device,
            "caustics mip",
            &[crate::wgsl!("caustics_mip.wgsl")],
            "fs_caustics_mip",
            &[&layout],
            FullscreenTarget { format, blend: None, depth: None },
        );
        Self { view: texture.create_view(&Default::default()), target: level(0), levels, pass }
    }

    /// Fills the lower levels from level 0 (after the caustics pass drew it).
    pub fn encode(&self, encoder: &mut wgpu::CommandEncoder) {
        for (target, group) in &self.levels {
            self.pass.run(encoder, target, &[group]);
        }
    }

    /// The constants `caustics_under` reads.
    pub fn wgsl_constants() -> String {
        format!(
            "const CAUSTICS_MIN_LOD: f32 = {CAUSTICS_MIN_LOD:?};\nconst CAUSTICS_SHARPEN_DEPTH: f32 = {CAUSTICS_SHARPEN_DEPTH:?};\nconst CAUSTICS_LAST_LOD: f32 = {:?};\n",
            (CAUSTICS_MIPS - 1) as f32
        )
    }
}
