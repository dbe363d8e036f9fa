//! The pipelines and passes every scene's meshes are drawn with: a mesh's pipeline on the
//! scene's bind groups ([`mesh_pipeline`]) and a pass on a colour and a depth target
//! ([`begin_scene_pass`]).

use super::DEPTH_FORMAT;
use crate::gpu;

/// A mesh's pipeline: its label, shader module and entry points, bind group layouts, vertex
/// attributes and stride (bytes), culling and winding, colour target, blending and depth use.
pub struct MeshPipeline<'a> {
    pub label: &'a str,
    pub module: &'a wgpu::ShaderModule,
    pub vertex_entry: &'a str,
    pub fragment_entry: &'a str,
    pub layouts: &'a [&'a wgpu::BindGroupLayout],
    pub attributes: &'a [wgpu::VertexAttribute],
    pub stride: u64,
    pub cull: Option<wgpu::Face>,
    /// The winding of front faces on screen (clockwise under a mirrored camera).
    pub front_face: wgpu::FrontFace,
    pub format: wgpu::TextureFormat,
    pub blend: Option<wgpu::BlendState>,
    pub write_mask: wgpu::ColorWrites,
    pub depth: DepthUse,
}

/// What a pipeline does with the depth target ([`DEPTH_FORMAT`]).
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum DepthUse {
    /// No depth target.
    None,
    /// Drawn where nearer than what is there, without changing the depth.
    Test,
    /// Drawn where nearer than what is there, and its depth kept.
    TestAndWrite,
}

/// The pipeline `p` describes.
pub fn mesh_pipeline(device: &wgpu::Device, p: MeshPipeline<'_>) -> wgpu::RenderPipeline {
    let layout = gpu::pipeline_layout(device, p.label, p.layouts);
    let buffer = Some(wgpu::VertexBufferLayout {
        array_stride: p.stride,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: p.attributes,
    });
    // Without attributes, no vertex buffer: the shader makes its vertices from their index.
    let buffers = if p.attributes.is_empty() { &[][..] } else { std::slice::from_ref(&buffer) };
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(p.label),
        layout: Some(&layout),
        vertex: wgpu::VertexState {
            module: p.module,
            entry_point: Some(p.vertex_entry),
            compilation_options: Default::default(),
            buffers,
        },
        primitive: wgpu::PrimitiveState { cull_mode: p.cull, front_face: p.front_face, ..Default::default() },
        depth_stencil: (p.depth != DepthUse::None).then(|| wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(p.depth == DepthUse::TestAndWrite),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: wgpu::MultisampleState::default(),
        fragment: Some(wgpu::FragmentState {
            module: p.module,
            entry_point: Some(p.fragment_entry),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState { format: p.format, blend: p.blend, write_mask: p.write_mask })],
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// A render pass on a colour and a depth target, clearing the colour (to `clear`) or keeping
/// it, and clearing the depth.
pub fn begin_scene_pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    label: &str,
    colour: &wgpu::TextureView,
    depth: &wgpu::TextureView,
    clear: Option<wgpu::Color>,
) -> wgpu::RenderPass<'e> {
    let load = clear.map_or(wgpu::LoadOp::Load, wgpu::LoadOp::Clear);
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some(label),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view: colour,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations { load, store: wgpu::StoreOp::Store },
        })],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: depth,
            depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Discard }),
            stencil_ops: None,
        }),
        timestamp_writes: None,
        occlusion_query_set: None,
        multiview_mask: None,
    })
}
