//! The flat water's own resources (`render/flat.rs` has its view, maps and parameters): the
//! reflection and refraction textures it reads, its pipelines per variant and the split view's
//! divider.

use std::collections::HashMap;

use super::shaders;
use super::variants::PipelineTargets;
use crate::gpu::{self, FullscreenPass, FullscreenTarget};
use crate::render::flat::{DIVIDER_GRIP, DIVIDER_LINE};
use crate::render::scene_parts::{mesh_pipeline, DepthUse, MeshPipeline, DEPTH_FORMAT};
use crate::render::Features;

/// The reflection and refraction textures at one size, and the bind group the water reads
/// them through (group 2 of the flat water's pipeline).
pub struct FlatTargets {
    pub reflection: wgpu::Texture,
    pub reflection_view: wgpu::TextureView,
    pub refraction_view: wgpu::TextureView,
    pub depth: wgpu::TextureView,
    pub size: (u32, u32),
    pub group: wgpu::BindGroup,
}

/// The flat water's own resources: its textures, its pipelines per variant and the divider.
pub struct FlatWater {
    layout: wgpu::BindGroupLayout,
    pub targets: Option<FlatTargets>,
    pipelines: HashMap<Features, wgpu::RenderPipeline>,
    divider: FullscreenPass,
}

impl FlatWater {
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat) -> Self {
        let vis = wgpu::ShaderStages::FRAGMENT;
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("flat water textures layout"),
            entries: &[gpu::filtered_texture_entry(0, vis), gpu::filtered_texture_entry(1, vis)],
        });
        let divider = FullscreenPass::new(
            device,
            "divider",
            &["@fragment\nfn fs_divider() -> @location(0) vec4<f32> { return vec4<f32>(0.92, 0.92, 0.92, 1.0); }\n"],
            "fs_divider",
            &[],
            FullscreenTarget { format, blend: None, depth: None },
        );
        Self { layout, targets: None, pipelines: HashMap::new(), divider }
    }

    /// The targets at `size` pixels (made again when the size changes).
    pub fn targets(&mut self, device: &wgpu::Device, format: wgpu::TextureFormat, size: (u32, u32)) -> &FlatTargets {
        if self.targets.as_ref().map(|t| t.size) != Some(size) {
            let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
            let colour = |label| {
                gpu::texture_2d(device, label, (size.0, size.1, 1), 1, format, usage | wgpu::TextureUsages::COPY_SRC)
            };
            let reflection = colour("flat water reflection");
            let refraction = colour("flat water refraction");
            let depth = gpu::texture_2d(device, "flat water depth", (size.0, size.1, 1), 1, DEPTH_FORMAT, usage);
            let reflection_view = reflection.create_view(&Default::default());
            let refraction_view = refraction.create_view(&Default::default());
            let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("flat water textures"),
                layout: &self.layout,
                entries: &[
                    wgpu::BindGroupEntry { binding: 0, resource: wgpu::BindingResource::TextureView(&reflection_view) },
                    wgpu::BindGroupEntry { binding: 1, resource: wgpu::BindingResource::TextureView(&refraction_view) },
                ],
            });
            self.targets = Some(FlatTargets {
                reflection,
                reflection_view,
                refraction_view,
                depth: depth.create_view(&Default::default()),
                size,
                group,
            });
        }
        self.targets.as_ref().expect("just made")
    }

    /// Builds the flat water plane's pipeline for `features`, if not built yet.
    pub fn prepare_pipeline(&mut self, device: &wgpu::Device, features: Features, targets: &PipelineTargets<'_>) {
        let layout = &self.layout;
        self.pipelines.entry(features).or_insert_with(|| {
            let module = gpu::shader(
                device,
                "flat water",
                &[&shaders::scene_prelude(features, targets.format), shaders::FLAT_WATER],
            );
            mesh_pipeline(
                device,
                MeshPipeline {
                    label: "flat water",
                    module: &module,
                    vertex_entry: "vs_flat",
                    fragment_entry: "fs_flat",
                    layouts: &[targets.water_layout, targets.textures_layout, layout],
                    attributes: &wgpu::vertex_attr_array![0 => Float32x2],
                    stride: 8,
                    cull: None,
                    front_face: wgpu::FrontFace::Ccw,
                    format: targets.format,
                    blend: None,
                    write_mask: wgpu::ColorWrites::ALL,
                    depth: DepthUse::TestAndWrite,
                },
            )
        });
    }

    /// How many feature sets' pipelines [`FlatWater::prepare_pipeline`] has built.
    pub fn pipelines_built(&self) -> usize {
        self.pipelines.len()
    }

    /// Whether [`FlatWater::prepare_pipeline`] has built the pipeline for `features`.
    pub fn has_pipeline(&self, features: Features) -> bool {
        self.pipelines.contains_key(&features)
    }

    /// The pipeline [`FlatWater::prepare_pipeline`] built for `features`.
    pub fn pipeline(&self, features: Features) -> &wgpu::RenderPipeline {
        &self.pipelines[&features]
    }

    /// Draws the divider at column `x` of `target` (`size` pixels): a line and a grip.
    pub fn draw_divider(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        size: (u32, u32),
        x: u32,
    ) {
        let rect = |w: u32, h: u32| {
            let x0 = x.saturating_sub(w / 2).min(size.0.saturating_sub(w.min(size.0)));
            let y0 = (size.1.saturating_sub(h)) / 2;
            [x0, y0, w.min(size.0), h.min(size.1)]
        };
        self.divider.run_in_rect(encoder, target, &[], rect(DIVIDER_LINE, size.1));
        self.divider.run_in_rect(encoder, target, &[], rect(DIVIDER_GRIP.0, DIVIDER_GRIP.1));
    }
}
