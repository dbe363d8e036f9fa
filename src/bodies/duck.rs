//! The rubber duck, built here from ellipsoids (our own geometry, under the project's
//! licence): body, head, beak, tail and two eyes, in the duck's frame (m), x forward, y up.
//! The same parts give the mesh drawn directly, the shapes the scene shader traces for
//! reflections, refractions and shadows, and the hull its buoyancy comes from.

use glam::{Mat4, Quat, Vec2, Vec3};

use super::{BodyKind, BodyMesh, BodyView};
use crate::param_spec::{slider, ParamSpec};
use crate::physics::{Ellipsoid, Pose, Shape};

/// Where the duck starts (x, z in m; it starts at its floating height) and where it looks
/// (turn about the vertical, radians; 0 is along +x).
const START_XZ: Vec2 = Vec2::new(0.35, -0.3);
const START_TURN: f32 = 2.4;

pub const KIND: BodyKind = BodyKind {
    name: "duck",
    params: PARAMS,
    hull_parts: HULL.len(),
    hull: |_| HULL.to_vec(),
    density: |v| v("duck_density"),
    centre_of_mass: CENTRE_OF_MASS,
    start: |v| Pose {
        position: Vec3::new(START_XZ.x, shape(v("duck_density")).floating_height(0.0), START_XZ.y),
        rotation: Quat::from_rotation_y(START_TURN),
    },
    probe_ring: |_| 0.3,
    bump_radius: |_| 0.13,
    pick: |pose, _, origin, dir| {
        TRACED_PARTS.iter().filter_map(|p| p.shape.ray_hit(pose, origin, dir)).min_by(|a, b| a.total_cmp(b))
    },
    drawn: |pose, _| BodyView::at(*pose, 0.0),
    bound: |b| bounding_radius() * b.scale,
    uniform_slots: 5 + 3 * TRACED_PARTS.len(),
    uniform: write_uniform,
    mesh: || {
        let (vertices, indices) = mesh();
        BodyMesh { vertices: bytemuck::cast_slice(&vertices).to_vec(), indices }
    },
    outline_mesh: || {
        let (vertices, indices) = outline_mesh();
        BodyMesh { vertices: bytemuck::cast_slice(&vertices).to_vec(), indices }
    },
    // Position and normal in the duck's frame, linear colour, which part.
    vertex: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x3, 3 => Uint32],
    vertex_stride: 40,
    wgsl: concat!(crate::wgsl!("body_duck.wgsl"), crate::wgsl!("body_duck_edge.wgsl")),
    wgsl_constants: parts_wgsl,
    edge: true,
    seen_below: false,
};

/// `duck_parts_light`: the light through every traced part, their product written out with no
/// loop. A software rasteriser (SwiftShader) runs a loop's whole body for every vertex, at
/// several times the cost of its arithmetic, and the caustics' vertices ask twice.
fn parts_wgsl() -> String {
    let light: Vec<String> =
        (0..TRACED_PARTS.len()).map(|i| format!("duck_part_light(o, d, t_max, t_lit, {i})")).collect();
    format!(
        "const DUCK_PARTS: i32 = {};\nfn duck_parts_light(o: vec3<f32>, d: vec3<f32>, t_max: f32, t_lit: f32) -> f32 {{\n    return {};\n}}\n",
        TRACED_PARTS.len(),
        light.join(" * ")
    )
}

/// The duck's share of the scene uniform (see `shaders/body_duck.wgsl`): its frame's rotation
/// and position with its scale (w), a ball holding it (radius 0: no duck), then per traced
/// part its centre and semi-axes in the duck's frame, times its scale (m), and its colour.
fn write_uniform(body: Option<&BodyView>, out: &mut [[f32; 4]]) {
    let frame = body.map_or(Mat4::IDENTITY, |b| Mat4::from_rotation_translation(b.pose.rotation, b.pose.position));
    out[..4].copy_from_slice(&frame.to_cols_array_2d());
    let scale = body.map_or(1.0, |b| b.scale);
    out[3][3] = scale;
    out[4] = body.map_or([0.0; 4], |b| b.pose.position.extend(bounding_radius() * b.scale).to_array());
    for (slots, part) in out[5..].chunks_mut(3).zip(&TRACED_PARTS) {
        slots[0] = (part.shape.centre * scale).extend(0.0).to_array();
        slots[1] = (part.shape.radii * scale).extend(0.0).to_array();
        slots[2] = part.colour.extend(1.0).to_array();
    }
}

/// One piece of the duck: its ellipsoid and colour (linear RGB).
#[derive(Clone, Copy, Debug)]
pub struct DuckPart {
    pub shape: Ellipsoid,
    pub colour: Vec3,
}

const YELLOW: Vec3 = Vec3::new(0.95, 0.62, 0.03);
const ORANGE: Vec3 = Vec3::new(0.95, 0.22, 0.02);
const EYE: Vec3 = Vec3::new(0.02, 0.02, 0.03);

const fn part(centre: [f32; 3], radii: [f32; 3], colour: Vec3) -> DuckPart {
    DuckPart {
        shape: Ellipsoid {
            centre: Vec3::new(centre[0], centre[1], centre[2]),
            radii: Vec3::new(radii[0], radii[1], radii[2]),
        },
        colour,
    }
}

/// The parts the scene shader traces (reflections, refractions, shadows): body, head, beak,
/// tail. The eyes are too small to matter there and are only in the mesh.
pub const TRACED_PARTS: [DuckPart; 4] = [
    part([0.0, 0.0, 0.0], [0.15, 0.085, 0.11], YELLOW),
    part([0.085, 0.115, 0.0], [0.068, 0.065, 0.064], YELLOW),
    part([0.16, 0.105, 0.0], [0.05, 0.016, 0.04], ORANGE),
    part([-0.125, 0.045, 0.0], [0.05, 0.045, 0.06], YELLOW),
];

/// The eyes, drawn in the mesh only.
pub const EYES: [DuckPart; 2] =
    [part([0.128, 0.14, 0.038], [0.012, 0.014, 0.012], EYE), part([0.128, 0.14, -0.038], [0.012, 0.014, 0.012], EYE)];

/// The hull buoyancy is computed from: body and head (the beak and tail are small).
pub const HULL: [Ellipsoid; 2] = [TRACED_PARTS[0].shape, TRACED_PARTS[1].shape];

/// Centre of mass in the duck's frame (m): low in the body, as a weighted bath toy, so it
/// floats upright and rights itself.
pub const CENTRE_OF_MASS: Vec3 = Vec3::new(0.0, -0.04, 0.0);

/// Radius (m) of a ball around the duck's origin holding all its parts (for early outs).
pub fn bounding_radius() -> f32 {
    TRACED_PARTS.iter().chain(&EYES).map(|p| p.shape.centre.length() + p.shape.radii.max_element()).fold(0.0, f32::max)
}

/// The duck's physical shape for a density (kg/m³).
pub fn shape(density: f32) -> Shape<'static> {
    Shape { hull: &HULL, centre_of_mass: CENTRE_OF_MASS, density, scale: 1.0 }
}

/// Mesh vertex: position and normal in the duck's frame, colour (linear RGB), and the part it
/// belongs to (its index in [`TRACED_PARTS`]; the eyes follow them): the outline's pass blends
/// each pixel from the part whose edge crosses it.
#[repr(C)]
#[derive(Clone, Copy, Debug, bytemuck::Pod, bytemuck::Zeroable)]
pub struct DuckVertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    pub colour: [f32; 3],
    pub part: u32,
}

/// The duck as triangles: every part a latitude-longitude ellipsoid, wound to face outwards,
/// its facets within [`DRAWN_FACETS`] of it (its outline within a pixel of the traced one).
pub fn mesh() -> (Vec<DuckVertex>, Vec<u32>) {
    ellipsoids(TRACED_PARTS.iter().chain(&EYES), DRAWN_FACETS)
}

/// The mesh the outline's pass grows (`vs_duck_edge`): the traced parts only, its facets within
/// [`OUTLINE_FACETS`] of them, inside the growth. On lavapipe a pass over 4,600 triangles costs
/// about 0.3 ms whatever their fragments do.
pub fn outline_mesh() -> (Vec<DuckVertex>, Vec<u32>) {
    ellipsoids(TRACED_PARTS.iter(), OUTLINE_FACETS)
}

/// How far (m) the drawn mesh's facets may lie inside the parts: the body's at 24 slices, and
/// each smaller part with as few as keep it as close (2,000 triangles in all; 4,600 when every
/// part, the eyes too, had the body's).
pub const DRAWN_FACETS: f32 = 0.0013;
/// The same for the outline's mesh.
pub const OUTLINE_FACETS: f32 = 0.005;

/// Latitude-longitude ellipsoids wound to face outwards, each with the fewest slices round it
/// that keep its facets within `facets` (m) of it at its longest radius, and two thirds as many
/// stacks down it.
fn ellipsoids<'a>(parts: impl Iterator<Item = &'a DuckPart>, facets: f32) -> (Vec<DuckVertex>, Vec<u32>) {
    let mut vertices = Vec::new();
    let mut indices = Vec::new();
    for (part, p) in parts.enumerate() {
        // A chord of angle a lies r (1 - cos a/2) inside a circle of radius r.
        let longest = p.shape.radii.max_element();
        let slices = (std::f32::consts::PI / (1.0 - facets / longest).max(-1.0).acos()).ceil().max(6.0) as u32;
        let stacks = (slices * 2).div_ceil(3);
        let base = vertices.len() as u32;
        for i in 0..=stacks {
            let theta = std::f32::consts::PI * i as f32 / stacks as f32;
            for j in 0..=slices {
                let phi = std::f32::consts::TAU * j as f32 / slices as f32;
                let unit = Vec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin());
                let position = p.shape.centre + unit * p.shape.radii;
                // The normal of an ellipsoid at unit-sphere point u is u / radii (normalised).
                let normal = (unit / p.shape.radii).normalize();
                vertices.push(DuckVertex {
                    position: position.to_array(),
                    normal: normal.to_array(),
                    colour: p.colour.to_array(),
                    part: part as u32,
                });
            }
        }
        let row = slices + 1;
        for i in 0..stacks {
            for j in 0..slices {
                let a = base + i * row + j;
                let (b, c, e) = (a + 1, a + row, a + row + 1);
                // theta runs from the top down, phi from +x towards +z: (a, b, c) faces outwards.
                if i != 0 {
                    indices.extend_from_slice(&[a, b, c]);
                }
                if i != stacks - 1 {
                    indices.extend_from_slice(&[b, e, c]);
                }
            }
        }
    }
    (vertices, indices)
}

/// The duck's density. (The parameter table, `params::table`, lists them in this order.)
pub const PARAMS: &[ParamSpec] = &[ParamSpec {
    name: "duck_density",
    label: "Duck density",
    group: "Objects",
    unit: "kg/m³",
    control: slider(100.0, 900.0, 10.0),
    default: 300.0,
    help: "Mass per volume of the rubber duck: the lighter, the higher it floats.",
}];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::{Pose, WaterPlane, WATER_DENSITY};

    #[test]
    fn mesh_faces_outwards() {
        let (vertices, indices) = mesh();
        let (outline, outline_indices) = outline_mesh();
        let triangles =
            indices.chunks(3).map(|t| (&vertices, t)).chain(outline_indices.chunks(3).map(|t| (&outline, t)));
        for (vertices, tri) in triangles {
            let [a, b, c] = [0, 1, 2].map(|k| Vec3::from(vertices[tri[k] as usize].position));
            let normal = Vec3::from(vertices[tri[0] as usize].normal);
            let face = (b - a).cross(c - a);
            assert!(face.length() < 1e-9 || face.dot(normal) > 0.0, "inward triangle {tri:?}");
        }
    }

    /// Every triangle's middle lies within one and a half times its mesh's facet allowance (a
    /// chord's sag round the part and another, smaller, down it) of its part (to first order:
    /// the part's unit-ball distance over its gradient), and the drawn mesh is small.
    #[test]
    fn the_meshes_facets_lie_within_their_allowance_of_the_parts() {
        for ((vertices, indices), facets) in [(mesh(), DRAWN_FACETS), (outline_mesh(), OUTLINE_FACETS)] {
            let mut deepest = 0.0f32;
            for tri in indices.chunks(3) {
                let part =
                    &TRACED_PARTS.iter().chain(&EYES).nth(vertices[tri[0] as usize].part as usize).unwrap().shape;
                let middle = tri.iter().map(|&i| Vec3::from(vertices[i as usize].position)).sum::<Vec3>() / 3.0;
                let o = (middle - part.centre) / part.radii;
                let inside = (1.0 - o.length()) * o.length() / (o / part.radii).length();
                deepest = deepest.max(inside);
            }
            println!("{} triangles, the deepest middle {:.2} mm inside its part", indices.len() / 3, deepest * 1000.0);
            assert!(deepest <= 1.5 * facets, "a facet {deepest} m inside its part (allowed {facets})");
        }
        assert!(mesh().1.len() / 3 < 2500, "the drawn mesh has {} triangles", mesh().1.len() / 3);
    }

    #[test]
    fn a_light_duck_floats_with_most_of_its_body_dry() {
        let shape = shape(300.0);
        let y = shape.floating_height(0.0);
        let (submerged, _) = shape.submerged(&Pose::at(Vec3::new(0.0, y, 0.0)), &WaterPlane::flat(0.0));
        assert!((submerged - shape.mass() / WATER_DENSITY).abs() < 1e-6);
        assert!(y > 0.0 && y < HULL[0].radii.y, "floats with its centre at {y} m");
    }
}
