//! The CPU reference of the tank's update (`shaders/tank/update.wgsl`), the same arithmetic in
//! the same order: the tests' ground truth, and the engine where the device cannot render into
//! float textures.

use super::medium::{CellKind, Medium};
use super::plan::Update;
use super::INTENSITY_TIME;

/// The tank's water on the CPU: per cell height h (m) and vertical velocity v (m/s).
#[derive(Clone, Debug)]
pub struct CpuTank {
    pub medium: Medium,
    /// The medium's faces as the update reads them ([`Medium::faces`]).
    faces: Vec<[f32; 4]>,
    /// Per cell: h (m), v (m/s) and h² averaged over the last [`INTENSITY_TIME`] (m²).
    pub state: Vec<[f32; 3]>,
}

/// A drop's bump at distance `r` (m) from its centre: a raised cosine of radius `radius` less
/// a quarter of one twice as wide, which holds four times its water: the drop adds none (a
/// shallow ring round the bump), so clicks never raise the tank's level.
pub fn drop_bump(r: f32, radius: f32, height: f32) -> f32 {
    let cosine = |r: f32, radius: f32| 0.5 + 0.5 * (std::f32::consts::PI * (r / radius).min(1.0)).cos();
    height * (cosine(r, radius) - 0.25 * cosine(r, 2.0 * radius))
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
        let faces = medium.faces();
        Self { medium, faces, state: vec![[0.0; 3]; n] }
    }

    /// Puts `medium` in the tray (same cells), keeping the water.
    pub fn set_medium(&mut self, medium: Medium) {
        self.faces = medium.faces();
        self.medium = medium;
    }

    /// The height of cell (i, j) (m).
    pub fn height(&self, i: u32, j: u32) -> f32 {
        self.state[(j * self.medium.cells + i) as usize][0]
    }

    /// The intensity of cell (i, j): h² averaged over the last [`INTENSITY_TIME`] (m²).
    pub fn intensity(&self, i: u32, j: u32) -> f32 {
        self.state[(j * self.medium.cells + i) as usize][2]
    }

    /// Runs `updates` in order, each after its drops.
    pub fn run(&mut self, updates: &[Update]) {
        for u in updates {
            self.update(u);
        }
    }

    /// Adds the update's drops to the water, not to walls (see `fs_drops`).
    fn add_drops(&mut self, u: &Update) {
        let n = self.medium.cells;
        for k in 0..self.state.len() {
            if self.faces[k][3] == CellKind::Wall.code() {
                continue;
            }
            let (x, z) = self.medium.centre(k as u32 % n, k as u32 / n);
            let mut h = self.state[k][0];
            for d in &u.drops[..u.bar[3] as usize] {
                h += drop_bump(((x - d[0]).powi(2) + (z - d[1]).powi(2)).sqrt(), d[2], d[3]);
            }
            self.state[k][0] = bounded(h, u.bounds[0]);
        }
    }

    /// One update of every cell after its drops (see `update.wgsl`).
    pub fn update(&mut self, u: &Update) {
        if u.bar[3] > 0.0 {
            self.add_drops(u);
        }
        let n = self.medium.cells as usize;
        let [_, dx, dt, _] = u.grid;
        let h_at = |k: usize| self.state[k][0];
        let mut next = vec![[0.0f32; 3]; self.state.len()];
        for j in 0..n {
            for i in 0..n {
                let k = j * n + i;
                let m = self.faces[k];
                if m[3] == CellKind::Wall.code() {
                    continue;
                }
                let west = if i > 0 { self.faces[k - 1][0] } else { 0.0 };
                let south = if j > 0 { self.faces[k - n][1] } else { 0.0 };
                let [h, v0, intensity] = self.state[k];
                let flux = m[0] * (h_at(if i + 1 < n { k + 1 } else { k }) - h)
                    + west * (h_at(if i > 0 { k - 1 } else { k }) - h)
                    + m[1] * (h_at(if j + 1 < n { k + n } else { k }) - h)
                    + south * (h_at(if j > 0 { k - n } else { k }) - h);
                let absorb = (-m[2] * dt).exp();
                let mut v = (v0 + dt / (dx * dx) * flux) * absorb;
                let mut hn = (h + dt * v) * absorb;
                let (x, z) = self.medium.centre(i as u32, j as u32);
                if let Some((phase, a)) = source_phase(u, x, z) {
                    (hn, v) = if u.bounds[3] > 0.5 {
                        (0.5 * a * (1.0 - phase.cos()), 0.5 * a * u.wave[2] * phase.sin())
                    } else {
                        (a * phase.sin(), a * u.wave[2] * phase.cos())
                    };
                }
                let hn = bounded(hn, u.bounds[0]);
                next[k] = [hn, bounded(v, u.bounds[1]), intensity + (hn * hn - intensity) * (dt / INTENSITY_TIME)];
            }
        }
        self.state = next;
    }
}

/// The phase (rad) and amplitude (m) of the source covering point (x, z) (m), if one does.
pub fn source_phase(u: &Update, x: f32, z: f32) -> Option<(f32, f32)> {
    for (d, share) in u.dippers[..u.wave[3] as usize].iter().zip(u.dipper_amplitudes) {
        if (x - d[0]).powi(2) + (z - d[1]).powi(2) <= d[2] * d[2] {
            return Some((u.wave[0] + d[3], u.wave[1] * share));
        }
    }
    let on_bar = u.bar[2] > 0.0 && (z - u.bar[0]).abs() <= u.bar[1] && x.abs() <= u.bounds[2];
    on_bar.then_some((u.wave[0], u.wave[1]))
}
