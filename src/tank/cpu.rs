//! The CPU reference of the tank's update (`shaders/tank/update.wgsl`), the same arithmetic in
//! the same order: the tests' ground truth, and the engine where the device cannot render into
//! float textures.

use super::medium::Medium;
use super::plan::Update;
use super::INTENSITY_TIME;

/// The tank's water on the CPU: per cell height h (m) and vertical velocity v (m/s).
#[derive(Clone, Debug)]
pub struct CpuTank {
    pub medium: Medium,
    /// Per cell: h (m), v (m/s) and h² averaged over the last [`INTENSITY_TIME`] (m²).
    pub state: Vec<[f32; 3]>,
}

/// A drop's bump at distance `r` (m) from its centre: a raised cosine of radius `radius`.
pub fn drop_bump(r: f32, radius: f32, height: f32) -> f32 {
    height * (0.5 + 0.5 * (std::f32::consts::PI * (r / radius).min(1.0)).cos())
}

/// `x` clamped to ±`limit`, NaN or infinity made 0.
pub fn bounded(x: f32, limit: f32) -> f32 {
    if x.abs() <= 3.0e38 {
        x.clamp(-limit, limit)
    } else {
        0.0
    }
}

impl CpuTank {
    /// Still water in `medium`.
    pub fn new(medium: Medium) -> Self {
        let n = (medium.cells * medium.cells) as usize;
        Self { medium, state: vec![[0.0; 3]; n] }
    }

    /// The height of cell (i, j) (m).
    pub fn height(&self, i: u32, j: u32) -> f32 {
        self.state[(j * self.medium.cells + i) as usize][0]
    }

    /// The intensity of cell (i, j): h² averaged over the last [`INTENSITY_TIME`] (m²).
    pub fn intensity(&self, i: u32, j: u32) -> f32 {
        self.state[(j * self.medium.cells + i) as usize][2]
    }

    /// Runs `updates` in order.
    pub fn run(&mut self, updates: &[Update]) {
        for u in updates {
            self.update(u);
        }
    }

    /// The height of cell (i, j) with the update's drops added (m).
    fn raised(&self, u: &Update, i: u32, j: u32) -> f32 {
        let mut h = self.height(i, j);
        let (x, z) = self.medium.centre(i, j);
        for d in &u.drops[..u.bar[3] as usize] {
            h += drop_bump(((x - d[0]).powi(2) + (z - d[1]).powi(2)).sqrt(), d[2], d[3]);
        }
        h
    }

    /// One update of every cell (see `update.wgsl`).
    pub fn update(&mut self, u: &Update) {
        let n = self.medium.cells;
        let [_, dx, dt, _] = u.grid;
        let mut next = vec![[0.0f32; 3]; self.state.len()];
        for j in 0..n {
            for i in 0..n {
                let k = (j * n + i) as usize;
                let m = self.medium.texels[k];
                if m[2] == 1.0 {
                    continue;
                }
                let h = self.raised(u, i, j);
                let mut flux = 0.0;
                for (di, dj) in [(1i32, 0i32), (-1, 0), (0, 1), (0, -1)] {
                    let (ni, nj) = (i as i32 + di, j as i32 + dj);
                    if ni < 0 || nj < 0 || ni >= n as i32 || nj >= n as i32 {
                        continue;
                    }
                    let mn = self.medium.texels[(nj as u32 * n + ni as u32) as usize];
                    if mn[2] == 1.0 {
                        continue;
                    }
                    flux += 0.5 * (m[0] + mn[0]) * (self.raised(u, ni as u32, nj as u32) - h);
                }
                let absorb = (-m[1] * dt).exp();
                let mut v = (self.state[k][1] + dt / (dx * dx) * flux) * absorb;
                let mut hn = (h + dt * v) * absorb;
                let (x, z) = self.medium.centre(i, j);
                if let Some(phase) = source_phase(u, x, z) {
                    hn = u.wave[1] * phase.sin();
                    v = u.wave[1] * u.wave[2] * phase.cos();
                }
                let hn = bounded(hn, u.bounds[0]);
                let intensity = self.state[k][2];
                next[k] = [hn, bounded(v, u.bounds[1]), intensity + (hn * hn - intensity) * (dt / INTENSITY_TIME)];
            }
        }
        self.state = next;
    }
}

/// The phase (rad) of the source covering point (x, z) (m), if one does.
pub fn source_phase(u: &Update, x: f32, z: f32) -> Option<f32> {
    for d in &u.dippers[..u.wave[3] as usize] {
        if (x - d[0]).powi(2) + (z - d[1]).powi(2) <= d[2] * d[2] {
            return Some(u.wave[0] + d[3]);
        }
    }
    (u.bar[2] > 0.0 && (z - u.bar[0]).abs() <= u.bar[1]).then_some(u.wave[0])
}
