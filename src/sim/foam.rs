//! Foam: white water where the surface breaks, integrated per fixed step on the CPU field
//! (the GPU engine's CPU copy of the water, or the CPU engine itself), so both engines foam by
//! the same code, and uploaded for the renderer once a frame. An amount per cell, 0 to 1:
//!
//! - crests that break: where the surface falls faster than a fraction of g
//!   (the step's downward acceleration beyond [`BREAKING_ACCELERATION`] on a crest);
//! - water running up a wall: rising water in the cells along the walls;
//! - water thrown about: height a drop or a moving body puts in or takes out of a cell;
//!
//! then decaying as exp(−t/τ) and spreading a little (diffusion that keeps the total).
//! Units: metres, seconds.

use crate::param_spec::{slider, Control, ParamSpec};

/// Gravity (m/s²).
const G: f32 = 9.81;
/// Downward acceleration of a crest beyond which it breaks and foams: a quarter of g (a
/// default drop's crest falls at about 0.3 g as it spreads).
pub const BREAKING_ACCELERATION: f32 = 0.25 * G;
/// Foam made per second per g of acceleration beyond that.
const BREAKING_RATE: f32 = 6.0;
/// Height above rest (m) beyond which rising water at a wall foams, and foam per second per
/// m/s of its rise.
const RUN_UP_HEIGHT: f32 = 0.002;
const RUN_UP_RATE: f32 = 20.0;
/// Foam per metre of height a push or a drop moves in a cell beyond SPLASH_MIN (m): below it
/// are the uniform corrections that keep the water's volume, spread over the whole pool.
const SPLASH_RATE: f32 = 150.0;
const SPLASH_MIN: f32 = 0.5e-3;
/// Diffusivity of foam over the surface (m²/s).
const SPREAD: f32 = 2.0e-3;

/// The foam amount per cell of a `size` × `size` field.
#[derive(Clone, Debug)]
pub struct Foam {
    size: u32,
    /// Cell size (m).
    dx: f32,
    /// Amount per cell (0-1), row by row as the state.
    amount: Vec<f32>,
    scratch: Vec<f32>,
    /// The step's snapshots: heights before its drops and pushes, what they moved, velocities
    /// before its updates.
    before_height: Vec<f32>,
    splash: Vec<f32>,
    before_velocity: Vec<f32>,
    /// Splash of drops applied in a frame without steps (a fast display between two steps),
    /// carried to the next step so every frame rate foams alike.
    pending_splash: Vec<f32>,
    /// Decay time τ (s).
    pub decay_s: f32,
}

impl Foam {
    pub fn new(size: u32, half_width: f32, decay_s: f32) -> Self {
        let zeros = vec![0.0; (size * size) as usize];
        Self {
            size,
            dx: 2.0 * half_width / size as f32,
            amount: zeros.clone(),
            scratch: zeros,
            before_height: Vec::new(),
            splash: Vec::new(),
            before_velocity: Vec::new(),
            pending_splash: Vec::new(),
            decay_s,
        }
    }

    pub fn size(&self) -> u32 {
        self.size
    }

    /// The amount per cell (0-1).
    pub fn amount(&self) -> &[f32] {
        &self.amount
    }

    /// Total foam over the pool (amount × m²).
    pub fn total(&self) -> f64 {
        self.amount.iter().map(|&a| a as f64).sum::<f64>() * (self.dx * self.dx) as f64
    }

    /// One fixed step of `dt` s. `splash`: the height change each cell got from drops and
    /// pushes this step beyond the volume corrections (m); `height`, `velocity`: the state after the step; `velocity_before`:
    /// the velocity before the step's updates.
    pub fn step(
        &mut self,
        dt: f32,
        splash: &[f32],
        height: &[f32],
        velocity: &[f32],
        velocity_before: &[f32],
        rest: f32,
    ) {
        let n = self.size as usize;
        let decay = (-dt / self.decay_s.max(1e-3)).exp();
        // Explicit diffusion, stable while SPREAD dt / dx² <= 1/4 (here far below).
        let k = (SPREAD * dt / (self.dx * self.dx)).min(0.2);
        for j in 0..n {
            for i in 0..n {
                let c = j * n + i;
                let a = self.amount[c];
                // Reflecting borders: a cell beyond the wall mirrors the edge cell.
                let at = |ii: usize, jj: usize| self.amount[jj * n + ii];
                let lap = at(i.saturating_sub(1), j)
                    + at((i + 1).min(n - 1), j)
                    + at(i, j.saturating_sub(1))
                    + at(i, (j + 1).min(n - 1))
                    - 4.0 * a;
                let h = height[c] - rest;
                let falling = -(velocity[c] - velocity_before[c]) / dt;
                let breaking = if h > 0.0 { (falling - BREAKING_ACCELERATION).max(0.0) / G } else { 0.0 };
                let at_wall = i == 0 || j == 0 || i == n - 1 || j == n - 1;
                let run_up = if at_wall && h > RUN_UP_HEIGHT { velocity[c].max(0.0) } else { 0.0 };
                let made = BREAKING_RATE * breaking * dt + RUN_UP_RATE * run_up * dt + SPLASH_RATE * splash[c];
                self.scratch[c] = ((a + k * lap) * decay + made).clamp(0.0, 1.0);
            }
        }
        std::mem::swap(&mut self.amount, &mut self.scratch);
    }

    /// Before a step's drops and pushes: remembers the heights they will change.
    pub fn begin_step(&mut self, height: &[f32]) {
        self.before_height.clear();
        self.before_height.extend_from_slice(height);
    }

    /// After the drops and pushes, before the updates: how much they moved each cell, and the
    /// velocities the updates start from.
    pub fn after_pushes(&mut self, height: &[f32], velocity: &[f32]) {
        self.splash.clear();
        self.splash.extend(height.iter().zip(&self.before_height).map(|(h, b)| ((h - b).abs() - SPLASH_MIN).max(0.0)));
        if self.pending_splash.len() == self.splash.len() {
            self.splash.iter_mut().zip(&self.pending_splash).for_each(|(s, p)| *s += p);
        }
        self.pending_splash.clear();
        self.before_velocity.clear();
        self.before_velocity.extend_from_slice(velocity);
    }

    /// After the step's updates (`dt` s in all): integrates the foam ([`Foam::step`]).
    pub fn end_step(&mut self, dt: f32, height: &[f32], velocity: &[f32], rest: f32) {
        if self.splash.len() != height.len() {
            return;
        }
        if dt <= 0.0 {
            // No step this frame (paused, or a frame shorter than a step): keep the splash.
            self.pending_splash.clone_from(&self.splash);
            return;
        }
        let (splash, before) = (std::mem::take(&mut self.splash), std::mem::take(&mut self.before_velocity));
        self.step(dt, &splash, height, velocity, &before, rest);
        (self.splash, self.before_velocity) = (splash, before);
    }

    /// Clears all foam.
    pub fn clear(&mut self) {
        self.amount.iter_mut().for_each(|a| *a = 0.0);
    }
}

/// Foam on or off and how long it lasts. (The parameter table, `params::table`, lists them in this order.)
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        name: "foam",
        label: "Foam",
        group: "Water",
        unit: "",
        control: Control::Toggle,
        default: 0.0,
        help: "White water where crests fall faster than a quarter of g, where water runs up a wall, and where drops and bodies throw water about; it fades and spreads.",
    },
    ParamSpec {
        name: "foam_decay",
        label: "Foam lifetime",
        group: "Water",
        unit: "s",
        control: slider(0.3, 5.0, 0.1),
        default: 1.5,
        help: "Time constant tau of the foam's fading: after tau seconds 37 % of it is left.",
    },
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn foam_decays_with_its_time_constant_and_spreading_keeps_the_total() {
        let n = 32;
        let mut foam = Foam::new(n, 1.0, 1.5);
        let cells = (n * n) as usize;
        foam.amount[(n as usize / 2) * n as usize + n as usize / 2] = 1.0;
        let start = foam.total();
        let calm = vec![0.0; cells];
        let dt = 1.0 / 120.0;
        for _ in 0..180 {
            foam.step(dt, &calm, &calm, &calm, &calm, 0.0);
        }
        let ratio = foam.total() / start;
        let expected = (-1.5f64 / 1.5).exp();
        let centre = foam.amount[(n as usize / 2) * n as usize + n as usize / 2];
        println!("after 1.5 s: total {ratio:.5} of the start (exp(-1) = {expected:.5}), the centre cell {centre:.3}");
        assert!((ratio / expected - 1.0).abs() < 1e-3, "total foam {ratio} vs {expected}");
        assert!(centre < 0.3, "no spreading: {centre}");
    }

    #[test]
    fn a_crest_falling_faster_than_a_quarter_of_g_foams_and_a_gentle_one_does_not() {
        let n = 8;
        let mut foam = Foam::new(n, 1.0, 1.5);
        let cells = (n * n) as usize;
        let dt = 1.0 / 120.0;
        let zeros = vec![0.0; cells];
        let crest = vec![0.01; cells];
        // Velocity change over one step: -0.5 g and -0.1 g.
        let (hard, gentle) = (vec![-0.5 * G * dt; cells], vec![-0.1 * G * dt; cells]);
        foam.step(dt, &zeros, &crest, &gentle, &zeros, 0.0);
        let after_gentle = foam.total();
        foam.step(dt, &zeros, &crest, &hard, &zeros, 0.0);
        let after_hard = foam.total();
        // A trough falling as fast does not break.
        let mut trough_foam = Foam::new(n, 1.0, 1.5);
        trough_foam.step(dt, &zeros, &vec![-0.01; cells], &hard, &zeros, 0.0);
        println!(
            "foam after a gentle crest {after_gentle:.2e}, a breaking one {after_hard:.2e}, a falling trough {:.2e}",
            trough_foam.total()
        );
        assert_eq!(after_gentle, 0.0);
        assert!(after_hard > 0.0);
        assert_eq!(trough_foam.total(), 0.0);
    }

    #[test]
    fn water_rising_up_a_wall_foams_and_in_the_middle_it_does_not() {
        let n = 8usize;
        let dt = 1.0 / 120.0;
        let zeros = vec![0.0; n * n];
        // Raised and rising everywhere (no acceleration): only the wall cells foam.
        let (raised, rising) = (vec![0.01; n * n], vec![0.2; n * n]);
        let mut foam = Foam::new(n as u32, 1.0, 1.5);
        foam.step(dt, &zeros, &raised, &rising, &rising, 0.0);
        let (wall, middle) = (foam.amount()[3 * n], foam.amount()[3 * n + 3]);
        println!(
            "after one step of water 1 cm up and rising at 0.2 m/s: {wall:.4} at the wall, {middle:.4} in the middle"
        );
        assert!(wall > 0.0 && middle == 0.0);
    }
}
