//! The floating bodies drawn in the open sea: each present kind's mesh with its own entry
//! points, built in the sea's shader module, where `shaders/sea/bodies.wgsl` lights them as the
//! sea is lit and hazes them with it. Drawn before the sea's grid, so that the water's costly
//! fragments behind their parts above it fail the depth test (their parts under it are then
//! hidden by the water).

use glam::Vec3;

use crate::bodies::{BodyId, KINDS};
use crate::render::scene_parts::{mesh_pipeline, DepthUse, Mesh, MeshPipeline};
use crate::render::View;

pub(super) const WGSL: &str = crate::wgsl!("sea/bodies.wgsl");

/// A present kind's pipelines in the sea: its mesh's, and its outline's if it has one
/// (`BodyKind::edge`), drawn after the sea and blended by the share of each pixel it covers.
pub(super) struct BodyPipelines {
    pub(super) mesh: wgpu::RenderPipeline,
    pub(super) edge: Option<wgpu::RenderPipeline>,
}

/// Per kind of `bodies::KINDS`, its pipelines if it is among `present` (bits of the kinds).
pub(super) fn body_pipelines(
    device: &wgpu::Device,
    module: &wgpu::ShaderModule,
    layouts: &[&wgpu::BindGroupLayout],
    format: wgpu::TextureFormat,
    present: u8,
) -> Vec<Option<BodyPipelines>> {
    let pipeline = |kind: &crate::bodies::BodyKind, suffix: &str, outline: bool| {
        let entries = [format!("vs_{}{suffix}", kind.name), format!("fs_{}{suffix}", kind.name)];
        let p = MeshPipeline {
            label: kind.name,
            module,
            vertex_entry: &entries[0],
            fragment_entry: &entries[1],
            layouts,
            attributes: kind.vertex,
            stride: kind.vertex_stride,
            cull: Some(wgpu::Face::Back),
            front_face: wgpu::FrontFace::Ccw,
            format,
            blend: outline.then_some(wgpu::BlendState::ALPHA_BLENDING),
            write_mask: wgpu::ColorWrites::ALL,
            depth: if outline { DepthUse::Test } else { DepthUse::TestAndWrite },
        };
        mesh_pipeline(device, p)
    };
    BodyId::all()
        .map(|id| {
            let kind = id.kind();
            (present & id.bit() as u8 != 0).then(|| BodyPipelines {
                mesh: pipeline(kind, "", false),
                edge: kind.edge.then(|| pipeline(kind, "_edge", true)),
            })
        })
        .collect()
}

/// Draws the outlines of the present kinds that have one, over what the pass drew before.
pub(super) fn draw_outlines(pass: &mut wgpu::RenderPass<'_>, bodies: &[Option<BodyPipelines>], meshes: &[Mesh]) {
    for (pipelines, mesh) in bodies.iter().zip(meshes) {
        if let Some(edge) = pipelines.as_ref().and_then(|p| p.edge.as_ref()) {
            pass.set_pipeline(edge);
            mesh.draw(pass);
        }
    }
}

/// How far past a body's bounding ball (in its radii) the waves' slopes can carry its mirror
/// image: sideways and down. Found by drawing the mirroring variant on every cell instead: no
/// pixel differed in ten views (the default sea, the `sea`, `calm` and `storm` presets, views
/// 3° to 25° down from 20 to 80 m, every body) after 1.5 s and 2 of 480,000 in the far one after
/// 3.3 s (half a radius each way lost 66 there).
const MIRROR_SIDE: f32 = 1.0;
const MIRROR_DOWN: f32 = 1.0;

/// Boxes (least and most corner, m) round each body's mirror image in the sea plane, grown as
/// far as the waves can carry the image ([`MIRROR_SIDE`], [`MIRROR_DOWN`]) and, sideways, by
/// `carry` (m): the most the waves move a point of the sea's grid.
pub(super) fn mirror_boxes(view: &View, carry: f32) -> Vec<(Vec3, Vec3)> {
    let drawn = view.bodies.iter().zip(&KINDS).filter_map(|(b, kind)| b.as_ref().map(|b| (b, (kind.bound)(b))));
    drawn
        .map(|(body, r)| {
            let c = body.pose.position;
            let (side, down) = (MIRROR_SIDE * r + carry, MIRROR_DOWN * r);
            (Vec3::new(c.x - side, -(c.y + r) - down, c.z - side), Vec3::new(c.x + side, 0.0, c.z + side))
        })
        .collect()
}
