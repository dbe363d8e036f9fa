//! The CPU reference of the water: the same drops, update and normals as the GPU passes in
//! `shaders/sim_*.wgsl`, in plain Rust with the same f32 arithmetic, driven by the same
//! [`StepPlan`]. Tests compare the GPU against it; it also serves where the GPU cannot render
//! to float textures.

use super::foam::Foam;
use super::{displaced_column, drop_shape, sponge_profile, CellRange, Drop, HullMove, StepPlan, WaveSettings};

/// Mirrors the shaders' `bounded`: finite values clamped, NaN and infinity to rest.
fn bounded(x: f32, limit: f32) -> f32 {
    if x.abs() <= 3.0e38 {
        x.clamp(-limit, limit)
    } else {
        0.0
    }
}

/// A heightfield in memory: `size * size` cells, row by row along +z (the GPU state texture's
/// layout), stored as separate planes of height (m), vertical velocity (m/s) and the normal's
/// x and z, so that the update streams through two planes with vectorisable loops.
#[derive(Clone, Debug)]
pub struct CpuHeightField {
    size: u32,
    half_width: f32,
    height: Vec<f32>,
    velocity: Vec<f32>,
    normal_x: Vec<f32>,
    normal_z: Vec<f32>,
    /// Write buffers for the update, swapped with `height` and `velocity` after each.
    next_height: Vec<f32>,
    next_velocity: Vec<f32>,
    /// Per-cell factor exp(-sigma dt) of the absorbing walls, for the (rate, dt) it was made for.
    absorb: Option<(f32, f32, Vec<f32>)>,
    /// Mean height found before the last normals update brought it back to rest (m), and the
    /// largest |height| after it.
    last_mean: f32,
    last_max_abs: f32,
    pending: Vec<Drop>,
    /// Rest level of the last advance (m).
    rest_level: f32,
    /// Foam integrated with the steps, when on.
    foam: Option<Foam>,
}

/// One cell's update, as in `shaders/sim_update.wgsl` (same operations in the same order).
#[inline(always)]
fn update_cell(h: f32, v: f32, neighbours: f32, plan: &StepPlan, absorb: f32) -> (f32, f32) {
    let laplacian = neighbours - 4.0 * h;
    let v = bounded((v + plan.coupling * laplacian) * plan.velocity_decay * absorb, plan.max_velocity);
    let level = plan.rest_level;
    let h = bounded((h - level + plan.dt * v) * absorb, plan.max_height) + level;
    (h, v)
}

impl CpuHeightField {
    /// A calm heightfield; `size` must be a power of two (as on the GPU).
    pub fn new(size: u32, half_width: f32) -> Self {
        assert!(size.is_power_of_two() && size >= 2, "simulation size must be a power of two");
        let zeros = vec![0.0; (size * size) as usize];
        Self {
            size,
            half_width,
            height: zeros.clone(),
            velocity: zeros.clone(),
            normal_x: zeros.clone(),
            normal_z: zeros.clone(),
            next_height: zeros.clone(),
            next_velocity: zeros,
            absorb: None,
            last_mean: 0.0,
            last_max_abs: 0.0,
            pending: Vec::new(),
            rest_level: 0.0,
            foam: None,
        }
    }

    /// Turns foam on with decay time `decay_s` (s), or off (`None`: no work, foam dropped).
    pub fn set_foam(&mut self, decay_s: Option<f32>) {
        match (decay_s, &mut self.foam) {
            (None, _) => self.foam = None,
            (Some(d), Some(foam)) => foam.decay_s = d,
            (Some(d), None) => self.foam = Some(Foam::new(self.size, self.half_width, d)),
        }
    }

    /// The foam, when on.
    pub fn foam(&self) -> Option<&Foam> {
        self.foam.as_ref()
    }

    pub fn size(&self) -> u32 {
        self.size
    }

    /// The state as the GPU texture holds it: (height, velocity, normal x, normal z) per cell.
    pub fn cells(&self) -> Vec<[f32; 4]> {
        let mut cells = Vec::new();
        self.write_cells(&mut cells);
        cells
    }

    /// [`CpuHeightField::cells`] into a buffer the caller keeps (no allocation per frame).
    pub fn write_cells(&self, out: &mut Vec<[f32; 4]>) {
        out.clear();
        out.extend(
            (0..self.height.len()).map(|k| [self.height[k], self.velocity[k], self.normal_x[k], self.normal_z[k]]),
        );
    }

    /// Queues a drop for the next [`CpuHeightField::advance`]; same rules as the GPU.
    pub fn add_drop(&mut self, drop: Drop) {
        let ok = [drop.x, drop.z, drop.radius, drop.strength].iter().all(|v| v.is_finite());
        if ok && drop.radius > 0.0 && drop.strength != 0.0 {
            self.pending.push(drop);
        }
    }

    fn centre(&self, i: u32) -> f32 {
        ((i as f32 + 0.5) * (1.0 / self.size as f32) * 2.0 - 1.0) * self.half_width
    }

    /// Applies the queued drops, `steps` steps of `dt` seconds, the mean-level hold and the
    /// normals, exactly as [`super::HeightField::encode`] does on the GPU. Returns whether
    /// the state changed.
    pub fn advance(&mut self, steps: u32, dt: f32, settings: WaveSettings) -> bool {
        self.advance_with(steps, dt, settings, Vec::new(), 0.0)
    }

    /// [`CpuHeightField::advance`] with bodies: their moves push the water with the drops, and
    /// the mean is held at `rest_level` (m), as on the GPU.
    pub fn advance_with(
        &mut self,
        steps: u32,
        dt: f32,
        settings: WaveSettings,
        moves: Vec<Vec<HullMove>>,
        rest_level: f32,
    ) -> bool {
        let mut plan = StepPlan::new(&mut self.pending, self.size, self.half_width, steps, dt, settings);
        plan.moves = moves;
        plan.rest_level = rest_level;
        self.rest_level = rest_level;
        if plan.sponge_rate > 0.0 {
            self.prepare_absorb(&plan);
        }
        let per_step = plan.updates_per_step(steps);
        for step in 0..(steps as usize).max(1) {
            if let Some(foam) = &mut self.foam {
                foam.begin_step(&self.height);
            }
            if plan.pushes_water(step) {
                self.apply_drops(&plan, step);
            }
            if let Some(foam) = &mut self.foam {
                foam.after_pushes(&self.height, &self.velocity);
            }
            for _ in 0..per_step {
                self.update(&plan);
            }
            if let Some(foam) = &mut self.foam {
                foam.end_step(per_step as f32 * plan.dt, &self.height, &self.velocity, plan.rest_level);
            }
        }
        if plan.changes_state() {
            self.update_normals(plan.rest_level);
        }
        plan.changes_state()
    }

    /// Height (m) at pool point (x, z), bilinear between cell centres (as the GPU's
    /// `sample_state`).
    pub fn height_at(&self, x: f32, z: f32) -> f32 {
        let n = self.size as i64;
        let q = |c: f32| (c / self.half_width * 0.5 + 0.5) * self.size as f32 - 0.5;
        let (px, pz) = (q(x), q(z));
        if !(px.is_finite() && pz.is_finite()) {
            return 0.0;
        }
        let (bx, bz) = (px.floor(), pz.floor());
        let (fx, fz) = (px - bx, pz - bz);
        let at = |i: i64, j: i64| self.height[(j.clamp(0, n - 1) * n + i.clamp(0, n - 1)) as usize];
        let (i, j) = (bx as i64, bz as i64);
        let a = at(i, j) + (at(i + 1, j) - at(i, j)) * fx;
        let b = at(i, j + 1) + (at(i + 1, j + 1) - at(i, j + 1)) * fx;
        a + (b - a) * fz
    }

    /// The water statistics the GPU engine reads back: the mean height before the last
    /// correction and the largest |height| (m).
    pub fn level(&self) -> super::WaterLevel {
        super::WaterLevel { mean: self.last_mean, max_abs: self.last_max_abs }
    }

    /// This water on an `size` x `size` grid, as `shaders/sim_resample.wgsl` does it: each
    /// new cell averages the old cells it covers when shrinking, and interpolates the old
    /// cells bilinearly when growing; then the normals are redone. Queued drops carry over.
    pub fn resampled(&self, size: u32) -> CpuHeightField {
        let mut new = CpuHeightField::new(size, self.half_width);
        new.pending = self.pending.clone();
        let (old_n, n) = (self.size as usize, size as usize);
        let old = |plane: &[f32], i: i64, j: i64| {
            let (i, j) = (i.clamp(0, old_n as i64 - 1) as usize, j.clamp(0, old_n as i64 - 1) as usize);
            plane[j * old_n + i]
        };
        for j in 0..n {
            for i in 0..n {
                let mut hv = [0.0f32; 2];
                for (k, plane) in [&self.height, &self.velocity].into_iter().enumerate() {
                    hv[k] = if old_n >= n {
                        let f = old_n / n;
                        let mut sum = 0.0;
                        for dj in 0..f {
                            for di in 0..f {
                                sum += old(plane, (i * f + di) as i64, (j * f + dj) as i64);
                            }
                        }
                        sum / (f * f) as f32
                    } else {
                        let q = |c: usize| (c as f32 + 0.5) * old_n as f32 / n as f32 - 0.5;
                        let (qx, qz) = (q(i), q(j));
                        let (bx, bz) = (qx.floor(), qz.floor());
                        let (tx, tz) = (qx - bx, qz - bz);
                        let (bx, bz) = (bx as i64, bz as i64);
                        let mix = |a: f32, b: f32, t: f32| a * (1.0 - t) + b * t;
                        let a = mix(old(plane, bx, bz), old(plane, bx + 1, bz), tx);
                        let b = mix(old(plane, bx, bz + 1), old(plane, bx + 1, bz + 1), tx);
                        mix(a, b, tz)
                    };
                }
                new.height[j * n + i] = hv[0];
                new.velocity[j * n + i] = hv[1];
            }
        }
        new.rest_level = self.rest_level;
        new.update_normals(self.rest_level);
        new
    }

    /// Drops over the whole grid, body moves over the cells their ellipsoids can reach, then the
    /// correction and bounds over the cells the pass covers ([`StepPlan::pushed_cells`]): the
    /// sums of `shaders/sim_drop.wgsl` in its order, over the same cells.
    fn apply_drops(&mut self, plan: &StepPlan, step: usize) {
        let n = self.size as usize;
        let first = step == 0;
        if first && !plan.drops.is_empty() {
            for j in 0..n {
                let z = self.centre(j as u32);
                for i in 0..n {
                    let x = self.centre(i as u32);
                    let h = &mut self.height[j * n + i];
                    for d in &plan.drops {
                        let dist = ((x - d.x).powi(2) + (z - d.z).powi(2)).sqrt();
                        *h += d.strength * drop_shape(dist, d.radius);
                    }
                }
            }
        }
        let depth = super::displacement_depth(self.half_width);
        let dx = 2.0 * self.half_width / self.size as f32;
        for m in plan.moves.get(step).into_iter().flatten() {
            let cells = CellRange::under(&[m.from, m.to], self.size, self.half_width);
            for j in cells.z.0..=cells.z.1 {
                let z = self.centre(j);
                for i in cells.x.0..=cells.x.1 {
                    let x = self.centre(i);
                    self.height[j as usize * n + i as usize] +=
                        displaced_column(x, z, &m.to, depth, dx) - displaced_column(x, z, &m.from, depth, dx);
                }
            }
        }
        let level = plan.rest_level;
        let correction = if first { plan.correction } else { 0.0 };
        for cells in plan.pushed_cells(step, self.size, self.half_width) {
            for j in cells.z.0..=cells.z.1 {
                for i in cells.x.0..=cells.x.1 {
                    let h = &mut self.height[j as usize * n + i as usize];
                    *h = bounded(*h - correction - level, plan.max_height) + level;
                }
            }
        }
    }

    /// Fills the absorbing walls' per-cell factors for this plan's rate and time step.
    fn prepare_absorb(&mut self, plan: &StepPlan) {
        if matches!(&self.absorb, Some((rate, dt, _)) if *rate == plan.sponge_rate && *dt == plan.dt) {
            return;
        }
        let n = self.size;
        let mut factors = Vec::with_capacity((n * n) as usize);
        for j in 0..n {
            for i in 0..n {
                let profile = sponge_profile(self.centre(i), self.centre(j), self.half_width);
                factors.push((-plan.sponge_rate * profile * plan.dt).exp());
            }
        }
        self.absorb = Some((plan.sponge_rate, plan.dt, factors));
    }

    /// One update of every cell. Rows are handled as slices (the row, the rows above and
    /// below, clamped at the walls like the GPU's `cell`), the first and last cell of a row
    /// apart, so the inner loop has no bounds checks and vectorises.
    fn update(&mut self, plan: &StepPlan) {
        let n = self.size as usize;
        let m = n - 2;
        let absorb: Option<&[f32]> = match &self.absorb {
            Some((_, _, factors)) if plan.sponge_rate > 0.0 => Some(factors),
            _ => None,
        };
        for j in 0..n {
            let row = &self.height[j * n..(j + 1) * n];
            let up = &self.height[(j + 1).min(n - 1) * n..][..n];
            let down = &self.height[j.saturating_sub(1) * n..][..n];
            let v = &self.velocity[j * n..(j + 1) * n];
            let out_h = &mut self.next_height[j * n..(j + 1) * n];
            let out_v = &mut self.next_velocity[j * n..(j + 1) * n];
            let factor = |i: usize| absorb.map_or(1.0, |a| a[j * n + i]);
            // Walls: the cell beyond mirrors the edge cell.
            for i in [0, n - 1] {
                let (left, right) = (row[i.saturating_sub(1)], row[(i + 1).min(n - 1)]);
                (out_h[i], out_v[i]) = update_cell(row[i], v[i], right + left + up[i] + down[i], plan, factor(i));
            }
            let (h_in, v_in, up_in, down_in) = (&row[1..=m], &v[1..=m], &up[1..=m], &down[1..=m]);
            let (left, right) = (&row[..m], &row[2..]);
            let (oh, ov) = (&mut out_h[1..=m], &mut out_v[1..=m]);
            match absorb {
                None => {
                    for k in 0..m {
                        let neighbours = right[k] + left[k] + up_in[k] + down_in[k];
                        (oh[k], ov[k]) = update_cell(h_in[k], v_in[k], neighbours, plan, 1.0);
                    }
                }
                Some(a) => {
                    let f = &a[j * n + 1..][..m];
                    for k in 0..m {
                        let neighbours = right[k] + left[k] + up_in[k] + down_in[k];
                        (oh[k], ov[k]) = update_cell(h_in[k], v_in[k], neighbours, plan, f[k]);
                    }
                }
            }
        }
        std::mem::swap(&mut self.height, &mut self.next_height);
        std::mem::swap(&mut self.velocity, &mut self.next_velocity);
    }

    /// Mean height by the same 2x2 pairwise averaging as `shaders/sim_mean.wgsl`.
    fn reduced_mean(&self) -> f32 {
        let mut side = self.size as usize;
        let mut level = self.height.clone();
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

    /// Normals from central differences, and the mean level brought back to `rest_level` (m),
    /// as in `shaders/sim_normals.wgsl`.
    fn update_normals(&mut self, rest_level: f32) {
        let mean = self.reduced_mean();
        self.last_mean = mean;
        let n = self.size as usize;
        let two_dx = 2.0 * (2.0 * self.half_width / self.size as f32);
        let h = &self.height;
        let at = |i: usize, j: usize| h[j * n + i];
        // Largest |height| before the correction, as the GPU's level reduction reports it.
        let mut max_abs = 0.0f32;
        for j in 0..n {
            let (jd, ju) = (j.saturating_sub(1), (j + 1).min(n - 1));
            for i in 0..n {
                let (il, ir) = (i.saturating_sub(1), (i + 1).min(n - 1));
                let slope_x = (at(ir, j) - at(il, j)) / two_dx;
                let slope_z = (at(i, ju) - at(i, jd)) / two_dx;
                let len = (slope_x * slope_x + 1.0 + slope_z * slope_z).sqrt();
                self.normal_x[j * n + i] = -slope_x / len;
                self.normal_z[j * n + i] = -slope_z / len;
                self.next_height[j * n + i] = at(i, j) - (mean - rest_level);
                max_abs = max_abs.max(at(i, j).abs());
            }
        }
        self.last_max_abs = max_abs;
        std::mem::swap(&mut self.height, &mut self.next_height);
    }

    /// Mean height over all cells (m).
    pub fn mean_height(&self) -> f64 {
        self.height.iter().map(|&h| h as f64).sum::<f64>() / self.height.len() as f64
    }

    /// Sets one cell's height and velocity (tests: feeding it bad values).
    pub fn set_cell(&mut self, index: usize, height: f32, velocity: f32) {
        self.height[index] = height;
        self.velocity[index] = velocity;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::{MAX_HEIGHT, MAX_VELOCITY};

    #[test]
    fn nan_and_huge_values_never_enter_the_state() {
        let mut water = CpuHeightField::new(32, 1.0);
        water.set_cell(100, f32::NAN, 0.0);
        water.set_cell(200, 0.0, f32::INFINITY);
        water.set_cell(300, 1.0e30, 0.0);
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
