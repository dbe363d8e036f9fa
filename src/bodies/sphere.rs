//! The sphere: one ball of paint under a clear coat, its radius and density parameters.

use glam::Vec3;

use super::{ball_floating_height, BodyKind, BodyMesh, BodyView};
use crate::param_spec::{slider, ParamSpec};
use crate::physics::{Ellipsoid, Pose};
use crate::util::unit_sphere;
use crate::world::Sphere;

/// Where the classic puts the sphere's centre (m): under the water. The sphere starts there
/// without gravity; with gravity, above it at its floating height, at rest, as the other kinds
/// do (released from under the water it would bob up and fill the first seconds with its rings).
pub const CLASSIC_START: Vec3 = Vec3::new(-0.35, -0.45, 0.3);

pub const KIND: BodyKind = BodyKind {
    name: "sphere",
    params: PARAMS,
    hull_parts: 1,
    hull: |v| vec![Ellipsoid { centre: Vec3::ZERO, radii: Vec3::splat(v("sphere_radius")) }],
    density: |v| v("sphere_density"),
    centre_of_mass: Vec3::ZERO,
    start: |v| {
        let floating = ball_floating_height(v("sphere_radius"), v("sphere_density"));
        let y = if v("gravity") > 0.5 { floating } else { CLASSIC_START.y };
        Pose::at(Vec3::new(CLASSIC_START.x, y, CLASSIC_START.z))
    },
    probe_ring: |v| v("sphere_radius") * 1.1 + 0.02,
    bump_radius: |v| v("sphere_radius"),
    pick: |pose, v, origin, dir| {
        let s = drawn(pose, v("sphere_radius"));
        crate::camera::ray_sphere(&crate::camera::Ray { origin, dir }, s.centre, s.radius)
    },
    drawn: |pose, v| {
        let s = drawn(pose, v("sphere_radius"));
        BodyView::at(Pose::at(s.centre), s.radius)
    },
    bound: |b| b.size,
    uniform_slots: 1,
    // Centre (m) and radius (m); radius 0: no sphere.
    uniform: |b, out| out[0] = b.map_or([0.0; 4], |b| b.pose.position.extend(b.size).to_array()),
    mesh: || {
        let (vertices, indices) = unit_sphere(24, 48);
        BodyMesh { vertices: bytemuck::cast_slice(&vertices).to_vec(), indices }
    },
    // Grown by a tenth (BALL_EDGE_GROWTH), coarse: its facets within 2 % of the sphere.
    outline_mesh: || {
        let (vertices, indices) = unit_sphere(8, 16);
        BodyMesh { vertices: bytemuck::cast_slice(&vertices).to_vec(), indices }
    },
    // A point on the unit sphere.
    vertex: &wgpu::vertex_attr_array![0 => Float32x3],
    vertex_stride: 12,
    wgsl: crate::wgsl!("body_sphere.wgsl"),
    wgsl_constants: String::new,
    edge: true,
    seen_below: true,
};

/// A ball of `radius` as drawn for a body at `pose`: kept inside the classic pool's box, where
/// the kinds' table entries place bodies (the sphere's and the beach ball's).
pub fn drawn(pose: &Pose, radius: f32) -> Sphere {
    let mut s = Sphere { centre: pose.position, radius };
    s.clamp_to_pool(crate::world::PoolShape::CLASSIC);
    s
}

/// The sphere's size and density. (The parameter table, `params::table`, lists them in this order.)
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        name: "sphere_radius",
        label: "Sphere radius",
        group: "Objects",
        unit: "m",
        control: slider(0.1, 0.4, 0.01),
        default: 0.25,
        help: "Radius of the sphere.",
    },
    ParamSpec {
        name: "sphere_density",
        label: "Sphere density",
        group: "Objects",
        unit: "kg/m³",
        control: slider(100.0, 2000.0, 10.0),
        default: 600.0,
        help: "Mass per volume; below water's 1000 kg/m³ the sphere floats.",
    },
];
