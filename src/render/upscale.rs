//! The scene drawn at a reduced resolution and scaled up to the target.

use crate::gpu::{self, FullscreenPass, FullscreenTarget};

/// The scene drawn at a reduced resolution and the pass that scales it up to the target.
pub(super) struct Upscale {
    pub(super) pass: FullscreenPass,
    pub(super) layout: wgpu::BindGroupLayout,
    pub(super) sampler: wgpu::Sampler,
    /// The reduced-resolution image, its size (pixels) and its bind group, once needed.
    pub(super) image: Option<(wgpu::TextureView, (u32, u32), wgpu::BindGroup)>,
}

impl Upscale {
    pub(super) fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        let vis = wgpu::ShaderStages::FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("upscale layout"),
            entries: &[gpu::filtered_texture_entry(0, vis), gpu::sampler_entry(1, vis)],
        });
        let pass = FullscreenPass::new(
            device,
            "upscale",
            &[crate::wgsl!("upscale.wgsl")],
            "fs_upscale",
            &[&layout],
            FullscreenTarget { format, blend: None, depth: None },
        );
        let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            ..Default::default()
        });
        Self { pass, layout, sampler, image: None }
    }

    /// The image to draw the scene into at `size` pixels (made again when the size changes).
    pub(super) fn image(
        &mut self,
        device: &wgpu::Device,
        format: wgpu::TextureFormat,
        size: (u32, u32),
    ) -> wgpu::TextureView {
        if self.image.as_ref().map(|i| i.1) != Some(size) {
            let texture = gpu::texture_2d(
                device,
                "scene at reduced resolution",
                (size.0, size.1, 1),
                1,
                format,
                wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING,
            );
            let view = texture.create_view(&Default::default());
            let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("upscale"),
                layout: &self.layout,
                entries: &[
                    wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&view) },
                    wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::Sampler(&self.sampler) },
                ],
            });
            self.image = Some((view, size, group));
        }
        self.image.as_ref().expect("just made").0.clone()
    }

    /// Scales the image up over the whole of `target`.
    pub(super) fn run(&self, encoder: &mut wgpu::CommandEncoder, target: &wgpu::TextureView) {
        if let Some((_, _, group)) = &self.image {
            self.pass.run(encoder, target, &[group]);
        }
    }
}
