//! The paved deck the pool is sunk in (the `setting` parameter's default): a ring of ground at
//! the rim's height from the pool's opening out to [`DECK_EXTENT`], coping stones along the
//! opening, paving slabs beyond, fading into the sky's haze with distance (`shaders/deck.wgsl`).

use glam::Vec3;

use crate::param_spec::{Control, ParamSpec};
use crate::scene;
use crate::util::push_triangle;

/// How far the deck reaches from the pool's centre (m): past any frame the camera can show.
pub const DECK_EXTENT: f32 = 400.0;
/// Width of the band of coping stones around the opening (m).
pub const COPING_WIDTH: f32 = 0.3;
/// Side of a paving slab (m).
pub const SLAB_SIZE: f32 = 0.6;
/// Distance over which the deck fades half-way into the horizon's haze (m).
pub const HAZE_DISTANCE: f32 = 60.0;
/// Clearance of the camera's eye above the deck (m): it never goes under the paving.
pub const EYE_CLEARANCE: f32 = 0.15;

/// The deck's fragment shader (its vertices go through the pool's `vs_pool`).
pub const WGSL: &str = include_str!("../../shaders/deck.wgsl");

/// The deck's WGSL constants.
pub fn wgsl_constants() -> String {
    format!(
        "const COPING_WIDTH: f32 = {COPING_WIDTH:?};\nconst SLAB_SIZE: f32 = {SLAB_SIZE:?};\n\
         const HAZE_DISTANCE: f32 = {HAZE_DISTANCE:?};\n"
    )
}

/// The deck as four quads around the opening at the rim's height, facing up, with the pool
/// mesh's vertex layout (position, normal).
pub fn deck_ring() -> (Vec<[f32; 6]>, Vec<u32>) {
    let (w, e, y) = (scene::HALF_WIDTH, DECK_EXTENT, scene::RIM);
    let inner = [Vec3::new(-w, y, -w), Vec3::new(w, y, -w), Vec3::new(w, y, w), Vec3::new(-w, y, w)];
    let outer = [Vec3::new(-e, y, -e), Vec3::new(e, y, -e), Vec3::new(e, y, e), Vec3::new(-e, y, e)];
    let positions: Vec<Vec3> = inner.iter().chain(outer.iter()).copied().collect();
    let vertices = positions.iter().map(|p| [p.x, p.y, p.z, 0.0, 1.0, 0.0]).collect();
    let mut indices = Vec::new();
    for i in 0..4u32 {
        let j = (i + 1) % 4;
        push_triangle(&mut indices, &positions, [i, j, 4 + j], Vec3::Y);
        push_triangle(&mut indices, &positions, [i, 4 + j, 4 + i], Vec3::Y);
    }
    (vertices, indices)
}

/// Where the pool is: in the deck or the cut-away box. (The parameter table, `params::table`, lists them in this order.)
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        name: "setting",
        label: "Setting",
        group: "Light",
        unit: "",
        control: Control::Choice { values: &[0.0, 1.0], names: &["deck", "cutaway"] },
        default: 0.0,
        help: "Where the pool is: sunk in a paved deck under the sky, or the classic's cut-away box, open at the near walls so you see the water's cross-section.",
    },
];
