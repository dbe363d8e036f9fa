//! The island in the open sea: a heightmap of our own, made once on the CPU. A round hill on a
//! sea floor [`FLOOR_DEPTH`] down, its coast bent by noise, flattened round the waterline into
//! beaches and shallows, and rough on its slopes. The sea reads the floor's depth from it (the
//! shallows' colour, the shore's foam); the island's pass draws its land (sand, grass, rock by
//! height and slope). Lengths in metres, in the sea's frame (y up, the mean sea level at 0).

use glam::Vec2;

use crate::util::hash01;

/// The island's middle (x, z), in view of the sea's default camera and its lesson preset.
pub const CENTRE: [f32; 2] = [-330.0, 620.0];
/// How far the middle lies from the origin (the clicks' patch) when the island stands at the
/// patch ([`Place::Shore`]): the patch's middle is then over about 6 m of water on the island's
/// shelf, its near edge at the beach, its far edge 13 m deep.
pub const SHORE_DISTANCE: f32 = 162.0;

/// Where the island stands.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Place {
    /// Ahead in the haze, 700 m off ([`CENTRE`]).
    Offshore,
    /// In the same direction, its shallows across the clicks' patch ([`SHORE_DISTANCE`]).
    Shore,
}

impl Place {
    /// The island's middle (x, z; m).
    pub fn centre(self) -> Vec2 {
        match self {
            Place::Offshore => Vec2::from(CENTRE),
            Place::Shore => Vec2::from(CENTRE).normalize() * SHORE_DISTANCE,
        }
    }
}
/// About where its coast lies from the middle.
pub const RADIUS: f32 = 160.0;
/// The highest its hill rises, before the noise.
pub const PEAK: f32 = 70.0;
/// How much the noise on its slopes adds at most, and the highest the ground can rise.
pub const ROUGHNESS: f32 = 14.0;
pub const HIGHEST: f32 = PEAK + ROUGHNESS;
/// The sea floor's depth away from the island.
pub const FLOOR_DEPTH: f32 = 30.0;
/// Heights within about this of the sea level are flattened into beaches and shallows.
pub const SHELF: f32 = 8.0;
/// The map: texels a side, over [`MAP_HALF_WIDTH`] each way from the middle. Past it the floor
/// is [`FLOOR_DEPTH`] down.
pub const MAP_TEXELS: u32 = 256;
pub const MAP_HALF_WIDTH: f32 = 320.0;
/// Quads a side of the land's grid over the map (a few map texels each).
pub const LAND_GRID: u32 = 128;
/// Quads whose corners all lie deeper than this (m) are left out of the land's mesh: the sea
/// draws its floor there.
const LAND_LOWEST: f32 = -2.0;
/// Water deeper than this (m) hides its floor: through twice the depth, exp(-c L) is a few %
/// in the blue (shaders/sea/island.wgsl fades the floor out from 60 % of it).
pub const SEE_DEPTH: f32 = 25.0;
/// Water shallower than this (m) foams along the shore.
pub const SHORE_FOAM_DEPTH: f32 = 1.2;
/// Where land turns from sand to grass (m above the sea), and the slope (rise over run) past
/// which it is bare rock.
pub const BEACH_TOP: f32 = 2.5;
pub const ROCK_SLOPE: f32 = 0.8;

/// Value noise in [-1, 1] on the unit lattice: a smooth blend of each corner's hash.
fn value_noise(p: Vec2, seed: u32) -> f32 {
    let cell = p.floor();
    let f = p - cell;
    let s = f * f * (Vec2::splat(3.0) - 2.0 * f);
    let corner = |dx: i32, dy: i32| {
        let (x, y) = (cell.x as i32 + dx, cell.y as i32 + dy);
        hash01(x as u32 ^ seed.wrapping_mul(0x68E3_1DA4), y as u32) * 2.0 - 1.0
    };
    let bottom = corner(0, 0) + (corner(1, 0) - corner(0, 0)) * s.x;
    let top = corner(0, 1) + (corner(1, 1) - corner(0, 1)) * s.x;
    bottom + (top - bottom) * s.y
}

/// Four octaves of value noise, each twice as fine and half as strong (about [-1, 1]).
fn fbm(p: Vec2, seed: u32) -> f32 {
    (0..4).map(|i| value_noise(p * 2f32.powi(i), seed + i as u32) * 0.5f32.powi(i)).sum::<f32>() / 1.875
}

/// Flattens heights near the sea level (h^3 / (h^2 + SHELF^2)): the land meets the water in a
/// gentle beach and a shallow shelf, and rises as before away from it.
fn shelve(h: f32) -> f32 {
    h * h * h / (h * h + SHELF * SHELF)
}

/// The ground's height (m above the mean sea level; negative: the sea floor) at (x, z) with
/// the island at `place`.
pub fn height(p: Vec2, place: Place) -> f32 {
    shape(p - place.centre())
}

/// The ground's height (m) at `offset` (m) from the island's middle.
fn shape(offset: Vec2) -> f32 {
    let q = offset / RADIUS;
    let warp = Vec2::new(fbm(q * 1.5 + 7.1, 11), fbm(q * 1.5 - 3.3, 23)) * 0.35;
    let r2 = (q + warp).length_squared();
    let hill = (-1.2 * r2).exp();
    let rough = fbm(q * 4.0, 37);
    shelve(-FLOOR_DEPTH + (PEAK + FLOOR_DEPTH) * hill + ROUGHNESS * hill * rough)
}

/// The island's map for the GPU (the same wherever it stands), row by row from (-x, -z): height (m) and its slopes dh/dx,
/// dh/dz by central differences, and 0.
pub fn map() -> Vec<[f32; 4]> {
    let n = MAP_TEXELS;
    let texel = 2.0 * MAP_HALF_WIDTH / n as f32;
    let origin = -Vec2::splat(MAP_HALF_WIDTH - 0.5 * texel);
    let mut out = Vec::with_capacity((n * n) as usize);
    for j in 0..n {
        for i in 0..n {
            let p = origin + Vec2::new(i as f32, j as f32) * texel;
            let (dx, dz) = (Vec2::new(0.5 * texel, 0.0), Vec2::new(0.0, 0.5 * texel));
            let slope_x = (shape(p + dx) - shape(p - dx)) / texel;
            let slope_z = (shape(p + dz) - shape(p - dz)) / texel;
            out.push([shape(p), slope_x, slope_z, 0.0]);
        }
    }
    out
}

/// The land's mesh: indices (two triangles a quad) into the grid's vertices, numbered row by
/// row from (-x, -z), `LAND_GRID + 1` a row, for the quads that rise above [`LAND_LOWEST`].
pub fn land_indices() -> Vec<u32> {
    let row = LAND_GRID + 1;
    let heights: Vec<f32> = land_vertices().map(shape).collect();
    let mut out = Vec::new();
    for j in 0..LAND_GRID {
        for i in 0..LAND_GRID {
            let a = j * row + i;
            let corners = [a, a + 1, a + row, a + row + 1];
            if corners.iter().any(|&v| heights[v as usize] > LAND_LOWEST) {
                out.extend_from_slice(&[a, a + row, a + 1, a + 1, a + row, a + row + 1]);
            }
        }
    }
    out
}

/// The land grid's vertices (x, z; from the island's middle), row by row.
fn land_vertices() -> impl Iterator<Item = Vec2> {
    let row = LAND_GRID + 1;
    (0..row * row).map(move |v| {
        let g = Vec2::new((v % row) as f32, (v / row) as f32) / LAND_GRID as f32;
        (g * 2.0 - Vec2::ONE) * MAP_HALF_WIDTH
    })
}

/// The box (least and most x, z, and the highest ground, m) round the land grid's vertices
/// whose ground lies above `level` (m), one grid cell wider each way, with the island at `place`.
pub fn extent_above(level: f32, place: Place) -> ([f32; 2], [f32; 2], f32) {
    let cell = 2.0 * MAP_HALF_WIDTH / LAND_GRID as f32;
    let (mut least, mut most, mut top) = (Vec2::splat(f32::INFINITY), Vec2::splat(f32::NEG_INFINITY), level);
    for p in land_vertices() {
        let h = shape(p);
        if h > level {
            (least, most, top) = (least.min(p), most.max(p), top.max(h));
        }
    }
    let centre = place.centre();
    ((least - cell + centre).to_array(), (most + cell + centre).to_array(), top)
}

/// The island's WGSL constants, standing at `place` (`ISLAND_AT_PATCH`: its shallows reach
/// the clicks' patch).
pub fn wgsl_constants(place: Place) -> String {
    let [x, z] = place.centre().to_array();
    let at_patch = place == Place::Shore;
    format!(
        "const ISLAND_AT_PATCH: bool = {at_patch};\nconst ISLAND_CENTRE: vec2<f32> = vec2<f32>({x:?}, {z:?});\nconst ISLAND_MAP_HALF_WIDTH: f32 = {MAP_HALF_WIDTH:?};\n\
         const ISLAND_MAP_TEXELS: u32 = {MAP_TEXELS}u;\nconst FLOOR_DEPTH: f32 = {FLOOR_DEPTH:?};\n\
         const SHORE_FOAM_DEPTH: f32 = {SHORE_FOAM_DEPTH:?};\nconst BEACH_TOP: f32 = {BEACH_TOP:?};\n\
         const ROCK_SLOPE: f32 = {ROCK_SLOPE:?};\nconst LAND_GRID: u32 = {LAND_GRID}u;\nconst SEE_DEPTH: f32 = {SEE_DEPTH:?};\n"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_island_rises_out_of_a_deep_floor_with_shallows_round_it() {
        let top = shape(Vec2::ZERO);
        let edge = shape(Vec2::new(MAP_HALF_WIDTH, 0.0));
        let mut shallow = 0;
        let samples = 400;
        for k in 0..samples {
            let angle = k as f32 / samples as f32 * std::f32::consts::TAU;
            let along = |r: f32| shape(Vec2::from_angle(angle) * r);
            // Along each ray out from the middle, the first metre of depth is some metres wide.
            let first_wet = (0..400).map(|i| i as f32).find(|&r| along(r) < 0.0).expect("a coast");
            shallow += usize::from(along(first_wet + 4.0) > -SHORE_FOAM_DEPTH);
        }
        println!(
            "top {top:.1} m, floor at the map's edge {edge:.1} m, {shallow}/{samples} rays with shallows 4 m wide"
        );
        assert!(top > 30.0 && edge < -0.8 * FLOOR_DEPTH);
        assert!(shallow > samples * 3 / 4, "the coast should be shelved: {shallow}/{samples}");
    }
}
