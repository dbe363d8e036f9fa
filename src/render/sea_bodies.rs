//! The floating bodies drawn in the open sea: each present kind's mesh with its own entry
//! points, built in the sea's shader module, where `shaders/sea_bodies.wgsl` lights them as the
//! sea is lit and hazes them with it. Drawn before the sea's grid, so that the water's costly
//! fragments behind their parts above it fail the depth test (their parts under it are then
//! hidden by the water).

use glam::Vec3;

use super::variants::{mesh_pipeline, DepthUse, MeshPipeline};
use super::View;
use crate::bodies::{BodyId, KINDS};

pub(super) const WGSL: &str = crate::wgsl!("sea_bodies.wgsl");

/// Per kind of `bodies::KINDS`, its mesh's pipeline if it is among `present` (bits of the kinds).
pub(super) fn body_pipelines(
    device: &wgpu::Device,
    module: &wgpu::ShaderModule,
    layouts: &[&wgpu::BindGroupLayout],
    format: wgpu::TextureFormat,
    present: u8,
) -> Vec<Option<wgpu::RenderPipeline>> {
    BodyId::all()
        .map(|id| {
            let kind = id.kind();
            let entries = [format!("vs_{}", kind.name), format!("fs_{}", kind.name)];
            (present & id.bit() as u8 != 0).then(|| {
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
                    blend: None,
                    write_mask: wgpu::ColorWrites::ALL,
                    depth: DepthUse::TestAndWrite,
                };
                mesh_pipeline(device, p)
            })
        })
        .collect()
}

/// Boxes (least and most corner, m) round each body of `view` and its mirror image in the sea
/// plane, the image grown down by three times the body's size and sideways by once (the waves'
/// slopes turn the mirrored rays and move the image: a storm's steep ones, that far).
pub(super) fn mirror_boxes(view: &View) -> Vec<(Vec3, Vec3)> {
    let drawn = view.bodies.iter().zip(&KINDS).filter_map(|(b, kind)| b.as_ref().map(|b| (b, (kind.bound)(b))));
    drawn
        .map(|(body, r)| {
            let c = body.pose.position;
            (
                Vec3::new(c.x - 2.0 * r, -(c.y + 4.0 * r), c.z - 2.0 * r),
                Vec3::new(c.x + 2.0 * r, c.y + r, c.z + 2.0 * r),
            )
        })
        .collect()
}
