//! Shader variants: the scene's pipelines compiled for one feature set, so that a pixel pays
//! nothing for what is not in the pool. Software rasterisers (SwiftShader in a browser
//! without a GPU, lavapipe) run both sides of every branch, so a uniform "is there a duck"
//! test still costs the duck's ray tests; a constant written into the source lets the shader
//! compiler drop them. The constants come from [`Features::wgsl`]; pipelines are built the
//! first time a feature set is drawn and kept ([`Renderer`](super::Renderer) caches them).

use super::{View, DEPTH_FORMAT};
use crate::gpu;

/// What a frame shows that costs shader work: the shader constants of a variant.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Features {
    /// The sphere is in the pool (traced in reflections and refractions, casts shadows).
    pub sphere: bool,
    /// The duck is in the pool.
    pub duck: bool,
    /// Light under water comes from the caustics map (else from a calm surface).
    pub caustics: bool,
}

impl Features {
    pub fn of(view: &View) -> Self {
        Self { sphere: view.sphere.is_some(), duck: view.duck.is_some(), caustics: view.caustics }
    }

    /// The WGSL constants that select this variant (`HAS_SPHERE`, `HAS_DUCK`, `HAS_CAUSTICS`).
    pub fn wgsl(&self) -> String {
        format!(
            "const HAS_SPHERE: bool = {};\nconst HAS_DUCK: bool = {};\nconst HAS_CAUSTICS: bool = {};\n",
            self.sphere, self.duck, self.caustics
        )
    }
}

/// The pipelines of the passes that read the scene's features: the caustics map and the
/// water surface, pool, sphere and duck of the scene pass.
pub struct ScenePipelines {
    pub caustics: wgpu::RenderPipeline,
    pub surface: wgpu::RenderPipeline,
    pub pool: wgpu::RenderPipeline,
    pub sphere: wgpu::RenderPipeline,
    pub duck: wgpu::RenderPipeline,
}

/// Formats and layouts the scene's pipelines are built for (fixed for a renderer).
pub struct PipelineTargets<'a> {
    /// Colour target of the scene pass.
    pub format: wgpu::TextureFormat,
    pub caustics_format: wgpu::TextureFormat,
    /// Scene uniforms + water state (group 0).
    pub water_layout: &'a wgpu::BindGroupLayout,
    /// Scene textures (group 1).
    pub textures_layout: &'a wgpu::BindGroupLayout,
}

impl ScenePipelines {
    pub fn new(device: &wgpu::Device, features: Features, targets: &PipelineTargets<'_>) -> Self {
        let constants = features.wgsl();
        let module = |label, part| gpu::shader(device, label, &[&constants, gpu::wgsl::COMMON, gpu::wgsl::SCENE, part]);
        let caustics_module = module("caustics", gpu::wgsl::CAUSTICS);
        let additive = wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::One,
            dst_factor: wgpu::BlendFactor::One,
            operation: wgpu::BlendOperation::Add,
        };
        let caustics = mesh_pipeline(
            device,
            MeshPipeline {
                label: "caustics",
                module: &caustics_module,
                vertex_entry: "vs_caustics",
                fragment_entry: "fs_caustics",
                layouts: &[targets.water_layout],
                attributes: &wgpu::vertex_attr_array![0 => Float32x2],
                stride: 8,
                cull: None,
                format: targets.caustics_format,
                blend: Some(wgpu::BlendState { color: additive, alpha: additive }),
                depth: false,
            },
        );
        let layouts = [targets.water_layout, targets.textures_layout];
        let scene_pipeline =
            |label, module: &wgpu::ShaderModule, vs, fs, attributes: &[wgpu::VertexAttribute], stride, cull| {
                mesh_pipeline(
                    device,
                    MeshPipeline {
                        label,
                        module,
                        vertex_entry: vs,
                        fragment_entry: fs,
                        layouts: &layouts,
                        attributes,
                        stride,
                        cull,
                        format: targets.format,
                        blend: None,
                        depth: true,
                    },
                )
            };
        let back = Some(wgpu::Face::Back);
        Self {
            caustics,
            // Culling off: front faces are the surface seen from above, back faces from below.
            surface: scene_pipeline(
                "water surface",
                &module("water surface", gpu::wgsl::WATER),
                "vs_surface",
                "fs_surface",
                &wgpu::vertex_attr_array![0 => Float32x2],
                8,
                None,
            ),
            pool: scene_pipeline(
                "pool",
                &module("pool", gpu::wgsl::POOL),
                "vs_pool",
                "fs_pool",
                &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3],
                24,
                back,
            ),
            sphere: scene_pipeline(
                "sphere",
                &module("sphere", gpu::wgsl::SPHERE),
                "vs_sphere",
                "fs_sphere",
                &wgpu::vertex_attr_array![0 => Float32x3],
                12,
                back,
            ),
            duck: scene_pipeline(
                "duck",
                &module("duck", gpu::wgsl::DUCK),
                "vs_duck",
                "fs_duck",
                &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x3],
                36,
                back,
            ),
        }
    }
}

pub struct MeshPipeline<'a> {
    pub label: &'a str,
    pub module: &'a wgpu::ShaderModule,
    pub vertex_entry: &'a str,
    pub fragment_entry: &'a str,
    pub layouts: &'a [&'a wgpu::BindGroupLayout],
    pub attributes: &'a [wgpu::VertexAttribute],
    pub stride: u64,
    pub cull: Option<wgpu::Face>,
    pub format: wgpu::TextureFormat,
    pub blend: Option<wgpu::BlendState>,
    /// Depth-tested and written against [`DEPTH_FORMAT`].
    pub depth: bool,
}

pub fn mesh_pipeline(device: &wgpu::Device, p: MeshPipeline<'_>) -> wgpu::RenderPipeline {
    let layout = gpu::pipeline_layout(device, p.label, p.layouts);
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(p.label),
        layout: Some(&layout),
        vertex: wgpu::VertexState {
            module: p.module,
            entry_point: Some(p.vertex_entry),
            compilation_options: Default::default(),
            buffers: &[Some(wgpu::VertexBufferLayout {
                array_stride: p.stride,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: p.attributes,
            })],
        },
        primitive: wgpu::PrimitiveState { cull_mode: p.cull, ..Default::default() },
        depth_stencil: p.depth.then(|| wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: wgpu::MultisampleState::default(),
        fragment: Some(wgpu::FragmentState {
            module: p.module,
            entry_point: Some(p.fragment_entry),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState {
                format: p.format,
                blend: p.blend,
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    })
}
