//! The arithmetic of a batch of steps, shared by the GPU passes and the CPU reference
//! ([`super::cpu`]): drops, wave settings, the sponge layer, bounds, the step plan and the
//! fixed time step. Lengths in metres, times in seconds.

use super::coupling::{CellRange, HullMove};
use super::scale_of;

/// Drops the drop pass applies at once; more wait for the next frame.
pub const MAX_DROPS_PER_PASS: usize = 32;
/// Largest Courant number c dt / dx a step may use; the 2-D scheme is stable up to 1/sqrt(2).
pub const MAX_COURANT: f32 = 0.6;

/// A drop: a smooth cosine bump, zero-mean corrected over the pool.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drop {
    /// Centre (m).
    pub x: f32,
    pub z: f32,
    /// Radius (m).
    pub radius: f32,
    /// Height of the bump's centre (m); negative dips.
    pub strength: f32,
}

/// Physical settings of a step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaveSettings {
    /// Wave speed c (m/s).
    pub wave_speed: f32,
    /// Velocity damping rate k (1/s).
    pub damping: f32,
    /// Absorbing walls: a sponge layer along the walls (see [`sponge_profile`]) instead of
    /// purely reflecting walls.
    pub absorbing_walls: bool,
}

impl WaveSettings {
    /// Reflecting walls.
    pub fn reflecting(wave_speed: f32, damping: f32) -> Self {
        Self { wave_speed, damping, absorbing_walls: false }
    }
}

/// Width (m) of the damping layer along each wall when the walls absorb.
pub const SPONGE_WIDTH: f32 = 0.25;

/// Damping rate at the wall, in units of c / SPONGE_WIDTH: with the quadratic profile a wave
/// crossing the layer and back loses amplitude by about exp(-2 * 12 / 3) = 3e-4, while the
/// gentle ramp keeps its own reflection small.
const SPONGE_STRENGTH: f32 = 12.0;

/// Shape of the sponge layer at pool point (x, z) (m): 0 farther than [`SPONGE_WIDTH`] from
/// every wall, rising quadratically to 1 at the wall. Both height and velocity decay there at
/// `sponge rate * profile` per second, which swallows outgoing waves.
pub fn sponge_profile(x: f32, z: f32, half_width: f32) -> f32 {
    let from_wall = half_width - x.abs().max(z.abs());
    let t = (1.0 - from_wall / (SPONGE_WIDTH * scale_of(half_width))).max(0.0);
    t * t
}

/// Largest |height| an update may leave (m, for the pool; [`scale_of`] times it for a field); it clamps to it and replaces NaN or infinity
/// by rest. The once-per-frame mean subtraction can move a clamped cell by at most the
/// mean, itself at most MAX_HEIGHT, so |h| <= 2 * MAX_HEIGHT = 0.16 m always: below the
/// 1/6 m rim, no wave ever overtops the pool.
pub const MAX_HEIGHT: f32 = 0.08;
/// Largest |vertical velocity| the state may hold (m/s).
pub const MAX_VELOCITY: f32 = 5.0;

/// Everything one batch of steps needs, worked out once on the CPU and used by both the
/// GPU passes and the CPU reference, so the two run the same arithmetic.
#[derive(Clone, Debug, PartialEq)]
pub struct StepPlan {
    /// Drops applied before the steps.
    pub drops: Vec<Drop>,
    /// Uniform height (m) subtracted with the drops so they add no water.
    pub correction: f32,
    /// Update passes to run (steps times substeps).
    pub updates: u32,
    /// Length of one update (s).
    pub dt: f32,
    /// c^2 dt / dx^2 of one update.
    pub coupling: f32,
    /// Factor exp(-k dt) applied to the velocity each update.
    pub velocity_decay: f32,
    /// Sponge damping rate at the wall (1/s); 0 for reflecting walls.
    pub sponge_rate: f32,
    /// Body moves per step: the first step's with the drops, each later one's before its step.
    pub moves: Vec<Vec<HullMove>>,
    /// Mean height the water is held at (m); heights are bounded around it.
    pub rest_level: f32,
    /// This field's bounds on |height| (m) and |velocity| (m/s), and its sponge's width (m):
    /// the pool's [`MAX_HEIGHT`], [`MAX_VELOCITY`], [`SPONGE_WIDTH`] times [`scale_of`].
    pub max_height: f32,
    pub max_velocity: f32,
    pub sponge_width: f32,
}

impl StepPlan {
    /// Plans `steps` steps of `dt` seconds on an `n` x `n` grid over a pool of `half_width`
    /// (m), taking at most [`MAX_DROPS_PER_PASS`] drops from the front of `pending`.
    pub fn new(pending: &mut Vec<Drop>, n: u32, half_width: f32, steps: u32, dt: f32, settings: WaveSettings) -> Self {
        let take = pending.len().min(MAX_DROPS_PER_PASS);
        let drops: Vec<Drop> = pending.drain(..take).collect();
        let dx = 2.0 * half_width / n as f32;
        let substeps = substeps(dt, settings.wave_speed, dx);
        let h = dt / substeps as f32;
        let scale = scale_of(half_width);
        Self {
            correction: drops.iter().map(|d| drop_mean(d, n, half_width)).sum(),
            drops,
            updates: steps * substeps,
            dt: h,
            coupling: settings.wave_speed * settings.wave_speed * h / (dx * dx),
            velocity_decay: (-settings.damping.max(0.0) * h).exp(),
            sponge_rate: if settings.absorbing_walls {
                SPONGE_STRENGTH * settings.wave_speed.abs() / (SPONGE_WIDTH * scale)
            } else {
                0.0
            },
            moves: Vec::new(),
            rest_level: 0.0,
            max_height: MAX_HEIGHT * scale,
            max_velocity: MAX_VELOCITY * scale,
            sponge_width: SPONGE_WIDTH * scale,
        }
    }

    /// Whether the drop pass has anything to do before step `step` (0: with the drops). A
    /// body that did not move pushes nothing.
    pub fn pushes_water(&self, step: usize) -> bool {
        (step == 0 && !self.drops.is_empty()) || self.moves.get(step).is_some_and(|m| m.iter().any(|m| m.from != m.to))
    }

    /// The cells the drop pass before step `step` changes on an `n` x `n` grid, as rectangles
    /// that do not overlap: all of them with drops (their correction is subtracted everywhere),
    /// else those under each moving ellipsoid, rectangles that overlap merged, so bodies cost
    /// in proportion to their size, not to the pool's nor to the distance between them.
    pub fn pushed_cells(&self, step: usize, n: u32, half_width: f32) -> Vec<CellRange> {
        if step == 0 && !self.drops.is_empty() {
            return vec![CellRange::all(n)];
        }
        let moved = self.moves.get(step).into_iter().flatten().filter(|m| m.from != m.to);
        let mut rects: Vec<CellRange> = Vec::new();
        for mut rect in moved.map(|m| CellRange::under(&[m.from, m.to], n, half_width)) {
            // Swallow every rectangle this one overlaps, until it overlaps none.
            while let Some(k) = rects.iter().position(|r| r.overlaps(&rect)) {
                rect = rect.union(rects.swap_remove(k));
            }
            rects.push(rect);
        }
        rects
    }

    /// Updates (substeps) per step.
    pub fn updates_per_step(&self, steps: u32) -> u32 {
        self.updates.checked_div(steps).unwrap_or(0)
    }

    /// Whether the normals need recomputing after this batch.
    pub fn changes_state(&self) -> bool {
        self.updates > 0 || (0..self.moves.len().max(1)).any(|k| self.pushes_water(k))
    }
}

/// Updates per step of `dt` seconds that keep the Courant number c dt / dx of each at or
/// below [`MAX_COURANT`] on cells of `dx` metres.
pub fn substeps(dt: f32, wave_speed: f32, dx: f32) -> u32 {
    let courant = wave_speed.abs() * dt / dx;
    if courant.is_finite() {
        ((courant / MAX_COURANT).ceil() as u32).max(1)
    } else {
        1
    }
}

/// Shape of a drop at distance `d` from its centre, 1 at the centre and 0 from the radius on.
pub fn drop_shape(d: f32, radius: f32) -> f32 {
    0.5 - 0.5 * (std::f32::consts::PI * (1.0 - d / radius).max(0.0)).cos()
}

/// Mean of a drop's bump over all cells of an `n` x `n` grid on the pool: subtracting
/// it everywhere makes the drop add no water.
pub fn drop_mean(drop: &Drop, n: u32, half_width: f32) -> f32 {
    let dx = 2.0 * half_width / n as f32;
    let index = |x: f32| ((x + half_width) / dx - 0.5).clamp(0.0, n as f32 - 1.0);
    let (i0, i1) = (index(drop.x - drop.radius).floor() as u32, index(drop.x + drop.radius).ceil() as u32);
    let (j0, j1) = (index(drop.z - drop.radius).floor() as u32, index(drop.z + drop.radius).ceil() as u32);
    let mut sum = 0.0f64;
    for j in j0..=j1 {
        let z = -half_width + (j as f32 + 0.5) * dx;
        for i in i0..=i1 {
            let x = -half_width + (i as f32 + 0.5) * dx;
            let d = ((x - drop.x).powi(2) + (z - drop.z).powi(2)).sqrt();
            sum += drop_shape(d, drop.radius) as f64;
        }
    }
    (sum / (n as f64 * n as f64)) as f32 * drop.strength
}

/// Fixed simulation time step with an accumulator: whatever the frame rate, the water
/// advances in steps of `dt` seconds of simulated time.
#[derive(Clone, Debug)]
pub struct FixedStep {
    /// Step length (s).
    pub dt: f32,
    /// Most steps one frame may take; the rest of a long frame is dropped so a slow
    /// device cannot spiral.
    pub max_steps: u32,
    accumulator: f32,
}

impl FixedStep {
    pub fn new(dt: f32, max_steps: u32) -> Self {
        Self { dt, max_steps, accumulator: 0.0 }
    }

    /// Adds a frame's duration (s) and returns how many steps to take now.
    pub fn advance(&mut self, frame_time: f32) -> u32 {
        if frame_time.is_finite() && frame_time > 0.0 {
            self.accumulator += frame_time.min(1.0);
        }
        // A tiny tolerance keeps 1/60 s frames from alternating 1 and 3 steps by rounding.
        let steps = ((self.accumulator + 1e-6) / self.dt).floor() as u32;
        let taken = steps.min(self.max_steps);
        self.accumulator =
            if steps > self.max_steps { 0.0 } else { (self.accumulator - taken as f32 * self.dt).max(0.0) };
        taken
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_step_is_frame_rate_independent() {
        for fps in [30.0f32, 60.0, 144.0] {
            let mut clock = FixedStep::new(1.0 / 120.0, 8);
            let frames = (fps * 2.0).round() as u32;
            let steps: u32 = (0..frames).map(|_| clock.advance(1.0 / fps)).sum();
            assert!((239..=240).contains(&steps), "{fps} fps gave {steps} steps in 2 s");
        }
    }

    #[test]
    fn slow_frames_are_capped() {
        let mut clock = FixedStep::new(1.0 / 120.0, 8);
        assert_eq!(clock.advance(0.5), 8);
        assert_eq!(clock.advance(1.0 / 120.0), 1);
    }

    #[test]
    fn drop_mean_matches_the_analytic_integral_away_from_walls() {
        // Integral of the cosine bump over its disc: pi r^2 (1/2 - 2/pi^2).
        let d = Drop { x: 0.1, z: -0.2, radius: 0.1, strength: 1.0 };
        let n = 512;
        let pool_area = 4.0;
        let analytic = std::f32::consts::PI * 0.01 * (0.5 - 2.0 / std::f32::consts::PI.powi(2)) / pool_area;
        let numeric = drop_mean(&d, n, 1.0);
        assert!((numeric - analytic).abs() / analytic < 0.01, "{numeric} vs {analytic}");
    }

    #[test]
    fn bodies_far_apart_are_pushed_in_two_rectangles_and_overlapping_ones_in_one() {
        use super::super::coupling::HullSlot;
        use glam::{Mat3, Vec3};
        // Balls of 0.1 m radius (unit_from_world scales by 1 / radius) in a 2 m pool of 64 cells.
        let ball = |x: f32, z: f32| HullSlot {
            centre: Vec3::new(x, 0.0, z),
            unit_from_world: Mat3::from_diagonal(Vec3::splat(10.0)),
        };
        let moving = |x: f32, z: f32| HullMove { from: ball(x, z), to: ball(x + 0.01, z) };
        let mut plan = StepPlan::new(&mut Vec::new(), 64, 1.0, 1, 1.0 / 120.0, WaveSettings::reflecting(0.6, 0.5));
        let cells = |plan: &StepPlan| plan.pushed_cells(0, 64, 1.0);
        plan.moves = vec![vec![moving(-0.6, -0.6), moving(0.6, 0.6)]];
        let apart = cells(&plan);
        plan.moves = vec![vec![moving(-0.6, -0.6), moving(-0.5, -0.55), moving(0.6, 0.6)]];
        let two_close = cells(&plan);
        println!("apart: {apart:?}; two close and one apart: {two_close:?}");
        assert_eq!(apart.len(), 2);
        assert!(apart.iter().map(CellRange::cells).sum::<u32>() < 64 * 64 / 10, "{apart:?}");
        assert_eq!(two_close.len(), 2);
        assert!(!two_close[0].overlaps(&two_close[1]));
        // Every cell a ball can push is in one of them: its reach and the cell past it.
        for m in plan.moves.iter().flatten() {
            let under = CellRange::under(&[m.from, m.to], 64, 1.0);
            assert!(two_close.iter().any(|r| r.union(under) == *r), "{under:?} not in {two_close:?}");
        }
    }
}
