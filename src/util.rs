//! Small helpers every layer may use: building triangle meshes on the CPU, a lattice hash.

use glam::Vec3;

/// Appends triangle (a, b, c), wound counter-clockwise when seen from the side `outward` points to.
pub fn push_triangle(indices: &mut Vec<u32>, positions: &[Vec3], tri: [u32; 3], outward: Vec3) {
    let [a, b, c] = tri.map(|i| positions[i as usize]);
    if (b - a).cross(c - a).dot(outward) >= 0.0 {
        indices.extend_from_slice(&tri);
    } else {
        indices.extend_from_slice(&[tri[0], tri[2], tri[1]]);
    }
}

/// A unit sphere (latitude-longitude), wound to face outwards.
pub fn unit_sphere(stacks: u32, slices: u32) -> (Vec<[f32; 3]>, Vec<u32>) {
    let mut positions = Vec::new();
    for i in 0..=stacks {
        let theta = std::f32::consts::PI * i as f32 / stacks as f32;
        for j in 0..=slices {
            let phi = std::f32::consts::TAU * j as f32 / slices as f32;
            positions.push(Vec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin()));
        }
    }
    let row = slices + 1;
    let mut indices = Vec::new();
    for i in 0..stacks {
        for j in 0..slices {
            let a = i * row + j;
            let (b, c, e) = (a + 1, a + row, a + row + 1);
            for tri in [[a, c, b], [b, c, e]] {
                let centre = tri.iter().map(|&k| positions[k as usize]).sum::<Vec3>();
                let [p, q, s] = tri.map(|k| positions[k as usize]);
                if (q - p).cross(s - p).length_squared() > 1e-12 {
                    push_triangle(&mut indices, &positions, tri, centre);
                }
            }
        }
    }
    (positions.iter().map(|p| p.to_array()).collect(), indices)
}

/// Small integer hash to a value in [0, 1).
pub fn hash01(a: u32, b: u32) -> f32 {
    let mut h = a.wrapping_mul(0x9E37_79B9) ^ b.wrapping_mul(0x85EB_CA6B);
    h ^= h >> 15;
    h = h.wrapping_mul(0x2C1B_3C6D);
    h ^= h >> 12;
    (h & 0xFFFF) as f32 / 65536.0
}
