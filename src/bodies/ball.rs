//! The beach ball: large and light, so it floats high and the wind of a drag sends it off; a
//! thin plastic shell in six coloured gores with white caps, spinning with its pose.

use glam::{Mat3, Vec3};

use super::{ball_floating_height, BodyKind, BodyMesh, BodyView};
use crate::param_spec::{slider, ParamSpec};
use crate::physics::{Ellipsoid, Pose};
use crate::util::unit_sphere;

/// Where the ball starts (x, z in m; it starts at its floating height).
const START_XZ: [f32; 2] = [0.3, 0.45];

pub const KIND: BodyKind = BodyKind {
    name: "ball",
    params: PARAMS,
    hull_parts: 1,
    hull: |v| vec![Ellipsoid { centre: Vec3::ZERO, radii: Vec3::splat(v("ball_radius")) }],
    density: |v| v("ball_density"),
    centre_of_mass: Vec3::ZERO,
    start: |v| {
        let y = ball_floating_height(v("ball_radius"), v("ball_density"));
        Pose::at(Vec3::new(START_XZ[0], y, START_XZ[1]))
    },
    // Wide: a light ball's own push on the water near it would otherwise lift and drop it
    // in turn, a frame late each time, until it leaps.
    probe_ring: |v| v("ball_radius") * 2.0 + 0.05,
    bump_radius: |v| v("ball_radius"),
    pick: |pose, v, origin, dir| {
        let s = super::sphere::drawn(pose, v("ball_radius"));
        crate::camera::ray_sphere(&crate::camera::Ray { origin, dir }, s.centre, s.radius)
    },
    drawn: |pose, v| {
        let s = super::sphere::drawn(pose, v("ball_radius"));
        BodyView::at(Pose { position: s.centre, rotation: pose.rotation }, s.radius)
    },
    bound: |b| b.size,
    uniform_slots: 4,
    // Centre (m) and radius (m; 0: no ball), then the columns of its rotation.
    uniform: |b, out| {
        out[0] = b.map_or([0.0; 4], |b| b.pose.position.extend(b.size).to_array());
        let turn = b.map_or(Mat3::IDENTITY, |b| Mat3::from_quat(b.pose.rotation));
        for (slot, column) in out[1..4].iter_mut().zip([turn.x_axis, turn.y_axis, turn.z_axis]) {
            *slot = column.extend(0.0).to_array();
        }
    },
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
    wgsl: crate::wgsl!("body_ball.wgsl"),
    wgsl_constants: String::new,
    edge: true,
    seen_below: false,
};

/// The ball's size and density. (The parameter table, `params::table`, lists them in this order.)
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        name: "ball_radius",
        label: "Ball radius",
        group: "Objects",
        unit: "m",
        control: slider(0.1, 0.3, 0.01),
        default: 0.2,
        help: "Radius of the beach ball.",
    },
    ParamSpec {
        name: "ball_density",
        label: "Ball density",
        group: "Objects",
        unit: "kg/m³",
        control: slider(20.0, 400.0, 5.0),
        default: 150.0,
        help: "Mass per volume of the beach ball (air in a thin shell, with sand in it so it bobs less): light, so it rides high on the water.",
    },
];
