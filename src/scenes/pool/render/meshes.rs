//! The pool's meshes, built on the CPU once: the water surface's grid (indexed by rows and by
//! columns, so a draw can take a band of either) and the pool's box.

use std::ops::Range;

use glam::Vec3;

use crate::render::scene_parts::{grid_coordinate, Mesh};
use crate::util::push_triangle;
use crate::world::PoolShape;

/// Rows (along x, one per step in z) or columns (along z) of the water grid's cells.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum GridBand {
    Rows(Range<u32>),
    Columns(Range<u32>),
}

/// The water grid's mesh ([`water_grid`]) with its cells indexed twice, row by row and then
/// column by column, so that a draw can take any band of rows or of columns.
pub struct GridMesh {
    mesh: Mesh,
    /// Quads per side.
    n: u32,
}

impl GridMesh {
    pub fn new(device: &wgpu::Device, n: u32) -> Self {
        let (vertices, rows) = water_grid(n);
        // The same triangles column by column: cell (i, j)'s six indices are at 6 (j n + i).
        let columns: Vec<u32> = (0..n * n)
            .flat_map(|k| {
                let (i, j) = (k / n, k % n);
                let at = (6 * (j * n + i)) as usize;
                rows[at..at + 6].to_vec()
            })
            .collect();
        let indices: Vec<u32> = rows.iter().chain(&columns).copied().collect();
        Self { mesh: Mesh::new(device, "water grid", &vertices, &indices), n }
    }

    /// Quads per side.
    pub fn n(&self) -> u32 {
        self.n
    }

    /// Draws the whole grid.
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>) {
        self.draw_band(pass, &GridBand::Rows(0..self.n));
    }

    /// Draws a band of rows or columns.
    pub fn draw_band(&self, pass: &mut wgpu::RenderPass<'_>, band: &GridBand) {
        let per_strip = 6 * self.n;
        let (range, first) = match band {
            GridBand::Rows(r) => (r, 0),
            GridBand::Columns(c) => (c, per_strip * self.n),
        };
        if !range.is_empty() {
            self.mesh.draw_indices(pass, first + range.start * per_strip..first + range.end * per_strip);
        }
    }
}

/// The water grid: (n + 1)^2 points spanning [-1, 1]^2 in pool units, facing up.
pub fn water_grid(n: u32) -> (Vec<[f32; 2]>, Vec<u32>) {
    let side = n + 1;
    let vertices: Vec<[f32; 2]> =
        (0..side * side).map(|i| [grid_coordinate(i % side, n), grid_coordinate(i / side, n)]).collect();
    let positions: Vec<Vec3> = vertices.iter().map(|v| Vec3::new(v[0], 0.0, v[1])).collect();
    let mut indices = Vec::with_capacity((n * n * 6) as usize);
    for j in 0..n {
        for i in 0..n {
            let v00 = j * side + i;
            let (v10, v01, v11) = (v00 + 1, v00 + side, v00 + side + 1);
            push_triangle(&mut indices, &positions, [v00, v01, v10], Vec3::Y);
            push_triangle(&mut indices, &positions, [v10, v01, v11], Vec3::Y);
        }
    }
    (vertices, indices)
}

/// The pool's floor and four walls up to the rim, as (position, inward normal), wound to
/// face inwards so that walls between the eye and the pool are culled.
pub fn pool_box(pool: PoolShape) -> (Vec<[f32; 6]>, Vec<u32>) {
    pool_walls(-pool.depth, true, pool)
}

/// `pool`'s four walls from `bottom` (m, under the rest level) up to the rim, and its floor if
/// `floor`, laid out as [`pool_box`]'s.
pub fn pool_walls(bottom: f32, floor: bool, pool: PoolShape) -> (Vec<[f32; 6]>, Vec<u32>) {
    let (w, d, r) = (pool.half_width, -bottom, pool.rim);
    let faces: [(Vec3, [Vec3; 4]); 5] = [
        (Vec3::Y, [Vec3::new(-w, -d, -w), Vec3::new(w, -d, -w), Vec3::new(w, -d, w), Vec3::new(-w, -d, w)]),
        (Vec3::X, [Vec3::new(-w, -d, -w), Vec3::new(-w, r, -w), Vec3::new(-w, r, w), Vec3::new(-w, -d, w)]),
        (Vec3::NEG_X, [Vec3::new(w, -d, -w), Vec3::new(w, r, -w), Vec3::new(w, r, w), Vec3::new(w, -d, w)]),
        (Vec3::Z, [Vec3::new(-w, -d, -w), Vec3::new(w, -d, -w), Vec3::new(w, r, -w), Vec3::new(-w, r, -w)]),
        (Vec3::NEG_Z, [Vec3::new(-w, -d, w), Vec3::new(w, -d, w), Vec3::new(w, r, w), Vec3::new(-w, r, w)]),
    ];
    let mut positions = Vec::new();
    let mut vertices = Vec::new();
    let mut indices = Vec::new();
    for (normal, corners) in faces.into_iter().skip(usize::from(!floor)) {
        let base = positions.len() as u32;
        for c in corners {
            positions.push(c);
            vertices.push([c.x, c.y, c.z, normal.x, normal.y, normal.z]);
        }
        push_triangle(&mut indices, &positions, [base, base + 1, base + 2], normal);
        push_triangle(&mut indices, &positions, [base, base + 2, base + 3], normal);
    }
    (vertices, indices)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::scene_parts::{banded_grid, GRID_BAND, VERTEX_CACHE};

    /// A mesh's triangles as sorted corner positions, each rotated to start at its least
    /// corner (so that the winding is kept), in a sorted list.
    fn triangles(vertices: &[[f32; 2]], indices: &[u32]) -> Vec<[[i64; 2]; 3]> {
        let key = |i: u32| vertices[i as usize].map(|c| (c * 1.0e5).round() as i64);
        let mut out: Vec<[[i64; 2]; 3]> = indices
            .chunks(3)
            .map(|t| {
                let corners = [key(t[0]), key(t[1]), key(t[2])];
                let first = (0..3).min_by_key(|&k| corners[k]).unwrap();
                [corners[first], corners[(first + 1) % 3], corners[(first + 2) % 3]]
            })
            .collect();
        out.sort();
        out
    }

    #[test]
    fn the_banded_grid_has_the_water_grids_triangles_wound_the_same() {
        for n in [64, 100, 128, 256] {
            let (plain_vertices, plain_indices) = water_grid(n);
            let (vertices, indices) = banded_grid(n);
            assert_eq!(triangles(&vertices, &indices), triangles(&plain_vertices, &plain_indices), "n = {n}");
            let bands = n.div_ceil(GRID_BAND);
            println!(
                "n = {n}: {} triangles, {} points in {bands} bands (the plain grid: {})",
                indices.len() / 3,
                vertices.len(),
                plain_vertices.len()
            );
        }
    }

    /// SwiftShader's vertex cache: VERTEX_CACHE entries by index modulo its size; a miss shades
    /// the next four indices of the list.
    fn shaded_per_point(indices: &[u32], points: usize) -> f32 {
        let (mut tags, mut shaded) = ([u32::MAX; VERTEX_CACHE as usize], 0);
        for (at, &index) in indices.iter().enumerate() {
            if tags[(index % VERTEX_CACHE) as usize] != index {
                shaded += 4;
                for &next in indices[at..(at + 4).min(indices.len())].iter().rev() {
                    tags[(next % VERTEX_CACHE) as usize] = next;
                }
            }
        }
        shaded as f32 / points as f32
    }

    #[test]
    fn a_small_vertex_cache_shades_each_point_of_the_banded_grid_under_twice() {
        let n = 128;
        let (plain_vertices, plain_indices) = water_grid(n);
        let (_, indices) = banded_grid(n);
        let (plain, banded) =
            (shaded_per_point(&plain_indices, plain_vertices.len()), shaded_per_point(&indices, plain_vertices.len()));
        println!(
            "vertex shader runs per grid point, {VERTEX_CACHE}-entry cache: row by row {plain:.2}, banded {banded:.2}"
        );
        assert!(banded < 2.0 && plain > 3.0 * banded, "row by row {plain}, banded {banded}");
    }
}
