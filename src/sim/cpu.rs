//! The CPU reference of the water: the same drops, update and normals as the GPU passes in
//! `shaders/sim_*.wgsl`, in plain Rust with the same f32 arithmetic, driven by the same
//! [`StepPlan`]. Tests compare the GPU against it; it also serves where the GPU cannot render
//! to float textures.

use super::{drop_shape, sponge_profile, Drop, StepPlan, WaveSettings, MAX_HEIGHT, MAX_VELOCITY};

/// Mirrors the shaders' `bounded`: finite values clamped, NaN and infinity to rest.
fn bounded(x: f32, limit: f32) -> f32 {
    if x.abs() <= 3.0e38 {
        x.clamp(-limit, limit)
    } else {
        0.0
    }
}

/// A heightfield in memory: `size * size` cells of (height m, velocity m/s, normal x, normal z),
/// row by row along +z, the same layout as the GPU state texture.
#[derive(Clone, Debug)]
pub struct CpuHeightField {
    size: u32,
    half_width: f32,
    cells: Vec<[f32; 4]>,
    scratch: Vec<[f32; 4]>,
    pending: Vec<Drop>,
}

impl CpuHeightField {
    /// A calm heightfield; `size` must be a power of two (as on the GPU).
    pub fn new(size: u32, half_width: f32) -> Self {
        assert!(size.is_power_of_two() && size >= 2, "simulation size must be a power of two");
        let calm = vec![[0.0; 4]; (size * size) as usize];
        Self { size, half_width, cells: calm.clone(), scratch: calm, pending: Vec::new() }
    }

    pub fn size(&self) -> u32 {
        self.size
    }

    pub fn cells(&self) -> &[[f32; 4]] {
        &self.cells
    }

    /// Queues a drop for the next [`CpuHeightField::advance`]; same rules as the GPU.
    pub fn add_drop(&mut self, drop: Drop) {
        let ok = [drop.x, drop.z, drop.radius, drop.strength].iter().all(|v| v.is_finite());
        if ok && drop.radius > 0.0 && drop.strength != 0.0 {
            self.pending.push(drop);
        }
    }

    fn at(&self, i: i64, j: i64) -> [f32; 4] {
        let n = self.size as i64;
        let (i, j) = (i.clamp(0, n - 1), j.clamp(0, n - 1));
        self.cells[(j * n + i) as usize]
    }

    fn centre(&self, i: u32) -> f32 {
        ((i as f32 + 0.5) * (1.0 / self.size as f32) * 2.0 - 1.0) * self.half_width
    }

    /// Applies the queued drops, `steps` steps of `dt` seconds, the mean-level hold and the
    /// normals, exactly as [`super::HeightField::encode`] does on the GPU.
    pub fn advance(&mut self, steps: u32, dt: f32, settings: WaveSettings) {
        let plan = StepPlan::new(&mut self.pending, self.size, self.half_width, steps, dt, settings);
        if !plan.drops.is_empty() {
            self.apply_drops(&plan);
        }
        for _ in 0..plan.updates {
            self.update(&plan);
        }
        if plan.changes_state() {
            self.update_normals();
        }
    }

    fn apply_drops(&mut self, plan: &StepPlan) {
        let n = self.size;
        for j in 0..n {
            let z = self.centre(j);
            for i in 0..n {
                let x = self.centre(i);
                let cell = &mut self.cells[(j * n + i) as usize];
                for d in &plan.drops {
                    let dist = ((x - d.x).powi(2) + (z - d.z).powi(2)).sqrt();
                    cell[0] += d.strength * drop_shape(dist, d.radius);
                }
                cell[0] = bounded(cell[0] - plan.correction, MAX_HEIGHT);
            }
        }
    }

    fn update(&mut self, plan: &StepPlan) {
        let n = self.size as i64;
        for j in 0..n {
            for i in 0..n {
                let c = self.at(i, j);
                let neighbours =
                    self.at(i + 1, j)[0] + self.at(i - 1, j)[0] + self.at(i, j + 1)[0] + self.at(i, j - 1)[0];
                let laplacian = neighbours - 4.0 * c[0];
                let absorb = if plan.sponge_rate > 0.0 {
                    let profile = sponge_profile(self.centre(i as u32), self.centre(j as u32), self.half_width);
                    (-plan.sponge_rate * profile * plan.dt).exp()
                } else {
                    1.0 // exp(0): the same value the GPU computes, without the cost
                };
                let v = bounded((c[1] + plan.coupling * laplacian) * plan.velocity_decay * absorb, MAX_VELOCITY);
                let h = bounded((c[0] + plan.dt * v) * absorb, MAX_HEIGHT);
                self.scratch[(j * n + i) as usize] = [h, v, c[2], c[3]];
            }
        }
        std::mem::swap(&mut self.cells, &mut self.scratch);
    }

    /// Mean height by the same 2x2 pairwise averaging as `shaders/sim_mean.wgsl`.
    fn reduced_mean(&self) -> f32 {
        let mut side = self.size as usize;
        let mut level: Vec<f32> = self.cells.iter().map(|c| c[0]).collect();
        while side > 1 {
            let half = side / 2;
            let mut next = vec![0.0f32; half * half];
            for j in 0..half {
                for i in 0..half {
                    let at = |x: usize, y: usize| level[y * side + x];
                    let (a, b) = (at(2 * i, 2 * j), at(2 * i + 1, 2 * j));
                    let (c, d) = (at(2 * i, 2 * j + 1), at(2 * i + 1, 2 * j + 1));
                    next[j * half + i] = ((a + b) + (c + d)) * 0.25;
                }
            }
            level = next;
            side = half;
        }
        level[0]
    }

    fn update_normals(&mut self) {
        let mean = self.reduced_mean();
        let n = self.size as i64;
        let two_dx = 2.0 * (2.0 * self.half_width / self.size as f32);
        for j in 0..n {
            for i in 0..n {
                let c = self.at(i, j);
                let slope_x = (self.at(i + 1, j)[0] - self.at(i - 1, j)[0]) / two_dx;
                let slope_z = (self.at(i, j + 1)[0] - self.at(i, j - 1)[0]) / two_dx;
                let len = (slope_x * slope_x + 1.0 + slope_z * slope_z).sqrt();
                self.scratch[(j * n + i) as usize] = [c[0] - mean, c[1], -slope_x / len, -slope_z / len];
            }
        }
        std::mem::swap(&mut self.cells, &mut self.scratch);
    }

    /// Mean height over all cells (m).
    pub fn mean_height(&self) -> f64 {
        self.cells.iter().map(|c| c[0] as f64).sum::<f64>() / self.cells.len() as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nan_and_huge_values_never_enter_the_state() {
        let mut water = CpuHeightField::new(32, 1.0);
        water.cells[100][0] = f32::NAN;
        water.cells[200][1] = f32::INFINITY;
        water.cells[300][0] = 1.0e30;
        water.advance(10, 1.0 / 120.0, WaveSettings::reflecting(0.6, 0.5));
        for c in water.cells() {
            assert!(c.iter().all(|v| v.is_finite()));
            assert!(c[0].abs() <= 2.0 * MAX_HEIGHT && c[1].abs() <= MAX_VELOCITY);
        }
    }

    #[test]
    fn drops_keep_the_mean_level() {
        let mut water = CpuHeightField::new(64, 1.0);
        water.add_drop(Drop { x: 0.9, z: -0.95, radius: 0.2, strength: 0.03 });
        water.add_drop(Drop { x: 0.0, z: 0.1, radius: 0.05, strength: -0.02 });
        water.advance(50, 1.0 / 120.0, WaveSettings::reflecting(0.6, 0.5));
        assert!(water.mean_height().abs() < 1e-8, "{}", water.mean_height());
    }
}
