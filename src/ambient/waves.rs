//! The ambient surfaces' waves and formulas: how the travelling waves and the basin's modes
//! are chosen from the spectrum, and each model's height and slopes at a point (the same
//! formulas `scene_surface.wgsl` evaluates).

use super::{
    angular_frequency_in, phillips, AmbientSettings, Wave, GERSTNER_NEWTON_STEPS, MAX_AMBIENT_WAVES, SINE_WAVES,
};
use crate::sim::SplitMix64;

/// The `sines` and `gerstner` models' travelling waves: wavenumbers evenly in log between the
/// shortest and longest wavelengths, each direction within the spread around the wind, each
/// amplitude from the Phillips spectrum there (scaled to the significant height later).
pub(super) fn travelling_waves(settings: &AmbientSettings, rng: &mut SplitMix64, k_min: f32, k_max: f32) -> Vec<Wave> {
    let mut waves = Vec::new();
    let wind = settings.wind_direction_deg.to_radians();
    for i in 0..SINE_WAVES {
        // Wavenumbers evenly in log between the shortest and longest wavelengths,
        // each direction within the spread around the wind.
        let k = k_min * (k_max / k_min).powf((i as f32 + rng.range(0.0, 1.0)) / SINE_WAVES as f32);
        let angle = wind + settings.spread_deg.to_radians() * (2.0 * rng.range(0.0, 1.0) - 1.0);
        let (kx, kz) = (k * angle.cos(), k * angle.sin());
        let weight = phillips(kx, kz, settings).max(0.0) * k * k;
        waves.push(Wave {
            kx,
            kz,
            amplitude: weight.sqrt(),
            omega: angular_frequency_in(k, settings.basin.depth),
            phase: rng.range(0.0, 1.0) as f64 * std::f64::consts::TAU,
        });
    }
    waves
}

/// The basin's standing modes (n, m) with wavenumbers in the band, weighted by the spectrum at
/// their wavevector (a standing wave is two opposite travelling ones: the wind picks the modes
/// lined up with it): in each of MAX_AMBIENT_WAVES bands of wavenumber (even in log, as the
/// sines) the strongest, so short and long waves are all there.
pub(super) fn basin_modes(settings: &AmbientSettings, rng: &mut SplitMix64, k_min: f32, k_max: f32) -> Vec<Wave> {
    let mut waves = Vec::new();
    // Basin modes (n, m) with wavenumbers in the band, weighted by the spectrum at
    // their wavevector (a standing wave is two opposite travelling ones: the wind
    // picks the modes lined up with it): in each of MAX_AMBIENT_WAVES bands of
    // wavenumber (even in log, as the sines) the strongest, so short and long
    // waves are all there.
    let width = 2.0 * settings.basin.half_width;
    let unit = std::f32::consts::PI / width;
    let mut candidates = Vec::new();
    let top = (k_max / unit).ceil() as i32;
    for n in 0..=top {
        for m in 0..=top {
            let (kx, kz) = (n as f32 * unit, m as f32 * unit);
            let k = (kx * kx + kz * kz).sqrt();
            if k < k_min || k > k_max {
                continue;
            }
            // Both diagonal directions of the mode's wavevector: its best alignment.
            let w = phillips(kx, kz, settings).max(phillips(kx, -kz, settings)) * k * k;
            candidates.push((w * (0.5 + rng.range(0.0, 1.0)), kx, kz, k));
        }
    }
    let band = |k: f32| {
        ((k / k_min).ln() / (k_max / k_min).ln() * MAX_AMBIENT_WAVES as f32).min(MAX_AMBIENT_WAVES as f32 - 1.0)
            as usize
    };
    let mut strongest: [Option<(f32, f32, f32, f32)>; MAX_AMBIENT_WAVES] = [None; MAX_AMBIENT_WAVES];
    for c in candidates {
        let slot = &mut strongest[band(c.3)];
        if slot.is_none_or(|s| c.0 > s.0) {
            *slot = Some(c);
        }
    }
    for &(w, kx, kz, k) in strongest.iter().flatten() {
        waves.push(Wave {
            kx,
            kz,
            amplitude: w.max(0.0).sqrt(),
            omega: angular_frequency_in(k, settings.basin.depth),
            phase: rng.range(0.0, 1.0) as f64 * std::f64::consts::TAU,
        });
    }
    waves
}

/// J⁻¹ v for a symmetric 2×2 matrix J given as (xx, xz, zz).
pub fn symmetric_solve(j: [f32; 3], v: [f32; 2]) -> [f32; 2] {
    let det = j[0] * j[2] - j[1] * j[1];
    [(j[2] * v[0] - j[1] * v[1]) / det, (j[0] * v[1] - j[1] * v[0]) / det]
}

/// The Gerstner surface above the point (x, z): Newton's method finds the rest point x₀ that
/// the waves carry to (x, z) (x₀ − D(x₀) = x, with D(x₀) = Σ b K sin θ, b = c a / k), then the
/// height Σ a cos θ there and the slopes J⁻¹ ∇₀h, J = I − Σ b cos θ K Kᵀ the Jacobian of the
/// motion (symmetric). Same steps as `gerstner_at` in scene_surface.wgsl.
pub(super) fn gerstner(waves: &[Wave], phases: &[f32], c: f32, x: f32, z: f32) -> [f32; 3] {
    // Per rest point: the displacement, the Jacobian (xx, xz, zz), height and gradient at rest.
    let at = |x0: f32, z0: f32| {
        let (mut d, mut j, mut h, mut g) = ([0.0f32; 2], [1.0f32, 0.0, 1.0], 0.0f32, [0.0f32; 2]);
        for (w, &p) in waves.iter().zip(phases) {
            let theta = w.kx * x0 + w.kz * z0 + p;
            let (s, co) = theta.sin_cos();
            let b = c * w.amplitude / (w.kx * w.kx + w.kz * w.kz).sqrt();
            d = [d[0] + b * w.kx * s, d[1] + b * w.kz * s];
            j = [j[0] - b * co * w.kx * w.kx, j[1] - b * co * w.kx * w.kz, j[2] - b * co * w.kz * w.kz];
            h += w.amplitude * co;
            g = [g[0] - w.amplitude * s * w.kx, g[1] - w.amplitude * s * w.kz];
        }
        (d, j, h, g)
    };
    let solve = symmetric_solve;
    let (mut x0, mut z0) = (x, z);
    for _ in 0..GERSTNER_NEWTON_STEPS {
        let (d, j, _, _) = at(x0, z0);
        // F(x₀) = x₀ − D(x₀) − x; F' = J.
        let step = solve(j, [x0 - d[0] - x, z0 - d[1] - z]);
        x0 -= step[0];
        z0 -= step[1];
    }
    let (_, j, h, g) = at(x0, z0);
    let slope = solve(j, g);
    [h, slope[0], slope[1]]
}

/// Mean of ((sin θ + 1)/2)² over θ: 3/8 (for [`CREST_SHARPNESS`] = 2).
pub(super) const SHARP_SINE_MEAN: f32 = 0.375;

/// Finch's sharpened travelling wave and its slopes: h = 2a(s² − 3/8), s = (sin θ + 1)/2,
/// θ = kx x + kz z + p.
pub(super) fn sharp_sine(kx: f32, kz: f32, a: f32, p: f32, x: f32, z: f32) -> [f32; 3] {
    let theta = kx * x + kz * z + p;
    let s = (theta.sin() + 1.0) * 0.5;
    let h = 2.0 * a * (s * s - SHARP_SINE_MEAN);
    // dh/dθ = 2a · 2s · cos θ / 2
    let dh = 2.0 * a * s * theta.cos();
    [h, dh * kx, dh * kz]
}

/// A standing mode and its slopes at (x, z) measured from the basin's corner (m): h = a cos(kx x)
/// cos(kz z) cos p.
pub(super) fn standing(kx: f32, kz: f32, a: f32, p: f32, x: f32, z: f32) -> [f32; 3] {
    let (u, v) = (kx * x, kz * z);
    let c = a * p.cos();
    [c * u.cos() * v.cos(), -c * kx * u.sin() * v.cos(), -c * kz * u.cos() * v.sin()]
}
