//! The arithmetic of a frame's updates, worked out once on the CPU and used by the GPU pass
//! and the CPU reference alike: how many updates a fixed step takes (from the fastest cell),
//! each update's uniforms (the sources' phase at its end, the drops of the first).

use super::medium::{Bar, Medium};
use super::{TankSettings, MAX_DIPPERS, MAX_TANK_DROPS, MAX_TANK_HEIGHT, MAX_TANK_VELOCITY};
use crate::sim::Drop;
use crate::sim::MAX_COURANT;

/// One update's uniforms, as `shaders/tank/update.wgsl` reads them (each in a 256-byte slot).
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Update {
    /// Cells per side, cell size dx (m), update length dt (s), the tray's half width (m).
    pub grid: [f32; 4],
    /// The sources' phase at the update's end (rad), amplitude (m), angular frequency (rad/s),
    /// number of point dippers.
    pub wave: [f32; 4],
    /// The bar's z (m) and half thickness (m), 1 if there is a bar, number of drops.
    pub bar: [f32; 4],
    /// Largest |h| (m) and |v| (m/s) the update leaves, the bar's half length (m), 1 if the
    /// sources make a single pulse (one raised cosine: h = A (1 - cos phase) / 2), else 0.
    pub bounds: [f32; 4],
    /// Each dipper's centre x, z (m) at the update's end, radius (m), phase (rad).
    pub dippers: [[f32; 4]; MAX_DIPPERS],
    /// Each dipper's amplitude as a share of `wave[1]`.
    pub dipper_amplitudes: [f32; MAX_DIPPERS],
    /// Each drop's centre x, z (m), radius (m), height (m), added before the update.
    pub drops: [[f32; 4]; MAX_TANK_DROPS],
}

/// Bytes between updates' uniforms in the GPU's buffer (its uniform offset alignment).
pub const UPDATE_SLOT: u64 = 256;
const _: () = assert!(std::mem::size_of::<Update>() as u64 <= UPDATE_SLOT);

/// Updates per fixed step of `step_dt` (s) in `medium`: enough that the fastest cell's
/// Courant number stays under the pool's [`MAX_COURANT`] (the same scheme, stable up to
/// 1/sqrt(2)).
pub fn updates_per_step(medium: &Medium, step_dt: f32) -> u32 {
    ((medium.fastest() * step_dt / (MAX_COURANT * medium.dx())).ceil() as u32).max(1)
}

/// The updates of `steps` fixed steps of `step_dt` (s) starting at simulated time `t0` (s):
/// the sources of `medium` at the frequency and amplitude of `settings`; `drops` go into the
/// first (at most [`MAX_TANK_DROPS`]; the rest are left in the vector for the next frame).
pub fn plan(
    medium: &Medium,
    settings: &TankSettings,
    t0: f64,
    steps: u32,
    step_dt: f32,
    drops: &mut Vec<Drop>,
) -> Vec<Update> {
    let per_step = updates_per_step(medium, step_dt);
    let dt = step_dt / per_step as f32;
    let omega = std::f64::consts::TAU * settings.frequency as f64;
    let bar = medium.sources.bar.unwrap_or(Bar { z: 0.0, half_thickness: 0.0, half_length: 0.0 });
    let mut base = Update {
        grid: [medium.cells as f32, medium.dx(), dt, 0.5 * medium.size],
        wave: [0.0, settings.amplitude, omega as f32, medium.sources.dippers.len().min(MAX_DIPPERS) as f32],
        bar: [bar.z, bar.half_thickness, if medium.sources.bar.is_some() { 1.0 } else { 0.0 }, 0.0],
        bounds: [MAX_TANK_HEIGHT, MAX_TANK_VELOCITY, bar.half_length, 0.0],
        dippers: [[0.0; 4]; MAX_DIPPERS],
        dipper_amplitudes: [1.0; MAX_DIPPERS],
        drops: [[0.0; 4]; MAX_TANK_DROPS],
    };
    for (share, d) in base.dipper_amplitudes.iter_mut().zip(&medium.sources.dippers) {
        *share = d.amplitude;
    }
    let count = steps * per_step;
    (0..count)
        .map(|k| {
            let mut update = base;
            let t = t0 + (k + 1) as f64 * (step_dt as f64 / per_step as f64);
            update.wave[0] = (omega * t).rem_euclid(std::f64::consts::TAU) as f32;
            for (slot, d) in update.dippers.iter_mut().zip(&medium.sources.dippers) {
                let (x, z) = d.centre_at(t);
                // Its phase against the set frequency's, in [0, 2π) (worked out in f64, so a
                // detuned dipper never drifts).
                let phase =
                    (d.phase as f64 + std::f64::consts::TAU * d.detune as f64 * t).rem_euclid(std::f64::consts::TAU);
                *slot = [x, z, d.radius, phase as f32];
            }
            if k == 0 {
                let n = drops.len().min(MAX_TANK_DROPS);
                for (slot, d) in update.drops.iter_mut().zip(drops.drain(..n)) {
                    *slot = [d.x, d.z, d.radius, d.strength];
                }
                update.bar[3] = n as f32;
            }
            update
        })
        .collect()
}

/// Which of a frame's `count` updates, each `dt` (s) long from time `t0` (s), the strobe of
/// `flashes` per second (Hz) lights: the one ending nearest its last flash in the frame, if
/// one falls in it.
pub fn strobe_flash(flashes: f32, t0: f64, count: usize, dt: f64) -> Option<usize> {
    if flashes <= 0.0 {
        return None;
    }
    let flash_count = |t: f64| (t * flashes as f64).floor();
    let mut lit = None;
    for k in 0..count {
        let (before, after) = (t0 + k as f64 * dt, t0 + (k + 1) as f64 * dt);
        if flash_count(after) > flash_count(before) {
            let flash = flash_count(after) / flashes as f64;
            lit = Some(if k > 0 && flash - before < after - flash { k - 1 } else { k });
        }
    }
    lit
}

/// Makes `updates` (from [`plan`], starting at time `t0`, s) one pulse of the sources begun at
/// time `start` (s): during its period 1/f they lift the water in one raised cosine from their
/// own phase 0, and outside it they do not act (their cells are water like any other).
pub fn shape_pulse(updates: &mut [Update], t0: f64, start: f64) {
    for (k, u) in updates.iter_mut().enumerate() {
        let (dt, omega) = (u.grid[2] as f64, u.wave[2] as f64);
        let phase = omega * (t0 + (k + 1) as f64 * dt - start);
        if (0.0..=std::f64::consts::TAU).contains(&phase) {
            u.wave[0] = phase as f32;
            u.bounds[3] = 1.0;
            u.dippers.iter_mut().for_each(|d| d[3] = 0.0);
        } else {
            u.wave[3] = 0.0;
            u.bar[2] = 0.0;
        }
    }
}
