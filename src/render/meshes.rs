//! The GPU buffers that hold a triangle mesh, and the grid of a square of water ordered for a
//! small vertex cache (the caustics' and the tank's screen; the pool's own meshes are in
//! `scenes/pool/render/meshes.rs`, the bodies' come from their kinds).

use std::ops::Range;

use wgpu::util::DeviceExt;

/// A triangle mesh in GPU buffers.
pub struct Mesh {
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
}

impl Mesh {
    pub fn new<V: bytemuck::Pod>(device: &wgpu::Device, label: &str, vertices: &[V], indices: &[u32]) -> Self {
        let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(vertices),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let index_count = indices.len() as u32;
        let indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(label),
            contents: bytemuck::cast_slice(indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        Self { vertices, indices, index_count }
    }

    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>) {
        self.draw_indices(pass, 0..self.index_count);
    }

    /// Draws the triangles of a range of the index buffer.
    pub fn draw_indices(&self, pass: &mut wgpu::RenderPass<'_>, indices: Range<u32>) {
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.set_index_buffer(self.indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(indices, 0, 0..1);
    }
}

/// Where point `i` of `n` quads lies across the grid, in pool units (-1..1).
pub fn grid_coordinate(i: u32, n: u32) -> f32 {
    i as f32 / n as f32 * 2.0 - 1.0
}

/// Vertices SwiftShader's vertex cache holds (Chromium's software GPU: direct-mapped by index
/// modulo this; a miss shades the next four indices of the list).
pub const VERTEX_CACHE: u32 = 64;
/// Quads across a band of [`banded_grid`]: two rows of a band's points fit the vertex cache.
pub const GRID_BAND: u32 = VERTEX_CACHE / 2 - 1;

/// The water grid's triangles (as the pool's `water_grid`'s, wound the same) ordered for a small vertex
/// cache, for a mesh whose vertex shader is dear (the caustics'): the grid is cut into bands
/// [`GRID_BAND`] quads wide, each band's points numbered row by row; each row of quads lists
/// the even quads' upper triangles (each bringing two points new to the cache), then the odd
/// quads', then every lower triangle. [`VERTEX_CACHE`]'s cache then shades each point about
/// 1.5 times, where the row-by-row grid's points, n + 1 apart, evict each other: about 12 times.
pub fn banded_grid(n: u32) -> (Vec<[f32; 2]>, Vec<u32>) {
    let at = |i: u32| grid_coordinate(i, n);
    let (mut vertices, mut indices) = (Vec::new(), Vec::with_capacity((n * n * 6) as usize));
    for first in (0..n).step_by(GRID_BAND as usize) {
        let last = (first + GRID_BAND).min(n);
        let (base, width) = (vertices.len() as u32, last - first + 1);
        vertices.extend((0..=n).flat_map(|j| (first..=last).map(move |i| [at(i), at(j)])));
        let point = |i: u32, j: u32| base + j * width + i - first;
        for j in 0..n {
            // Upper triangles, the even quads' then the odd ones'; then the lower ones.
            for i in (first..last).step_by(2).chain((first + 1..last).step_by(2)) {
                indices.extend([point(i, j + 1), point(i + 1, j + 1), point(i + 1, j)]);
            }
            indices.extend((first..last).flat_map(|i| [point(i, j), point(i, j + 1), point(i + 1, j)]));
        }
    }
    (vertices, indices)
}
