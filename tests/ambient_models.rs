//! The ambient wave models against their physics, on the CPU (no GPU): the phase speed of a
//! single wave measured from sampled heights against the dispersion relation, Gerstner heights
//! against the closed form, the FFT ocean against its direct sum and Parseval, and every model
//! finite and below the rim at every parameter's extreme.

use wavepool::ambient::ocean::{lattice_k, Ocean, MAX_CHOPPINESS};
use wavepool::ambient::{angular_frequency_in, AmbientModel, AmbientSettings, AmbientWaves, Spectrum, MAX_STEEPNESS};
use wavepool::world::PoolShape;

const HALF_WIDTH: f32 = PoolShape::CLASSIC.half_width;
const RIM: f32 = PoolShape::CLASSIC.rim;

fn settings(model: AmbientModel) -> AmbientSettings {
    AmbientSettings::default_for(model)
}

/// The speed (m/s) at which the heights along +x move: the shift s that best matches
/// h(x, t + dt) to h(x − s, t), searched to 0.1 mm, over dt.
fn measured_phase_speed(height: impl Fn(f32, f64) -> f32, dt: f64, longest: f32) -> f32 {
    let xs: Vec<f32> = (0..200).map(|i| -0.5 + i as f32 * 0.005).collect();
    let later: Vec<f32> = xs.iter().map(|&x| height(x, dt)).collect();
    let mismatch = |s: f32| -> f32 { xs.iter().zip(&later).map(|(&x, &h)| (height(x - s, 0.0) - h).powi(2)).sum() };
    let best =
        (0..(longest * 1e4) as i32).map(|i| i as f32 * 1e-4).min_by(|a, b| mismatch(*a).total_cmp(&mismatch(*b)));
    best.unwrap() / dt as f32
}

#[test]
fn a_single_sine_and_a_single_fft_wave_travel_at_the_speed_the_dispersion_relation_gives() {
    let mut worst = 0.0f32;
    for wavelength in [0.25f32, 0.5, 1.0] {
        let k = std::f32::consts::TAU / wavelength;
        let expected = angular_frequency_in(k, PoolShape::CLASSIC.depth) / k;
        // A sharpened sine along +x.
        let sines = AmbientWaves::new(&settings(AmbientModel::Sines));
        let mut one = sines.clone();
        one.waves = vec![wavepool::ambient::Wave {
            kx: k,
            kz: 0.0,
            amplitude: 0.01,
            omega: angular_frequency_in(k, PoolShape::CLASSIC.depth),
            phase: 0.3,
        }];
        let dt = 0.1 * (wavelength / expected) as f64; // a tenth of a period
        let sine = measured_phase_speed(|x, t| one.sample(x, 0.1, t)[0], dt, 0.5 * wavelength);
        // One lattice wave of the FFT ocean: k = (π/W) m along x, m = 2W/λ.
        let n = 64;
        let m = (2.0 * HALF_WIDTH / wavelength).round() as usize;
        let mut h0 = vec![[0.0f32; 4]; n * n];
        h0[m] = [0.004, 0.001, 0.0, 0.0];
        let ocean =
            Ocean { size: n, band: wavepool::ambient::ocean::Band::pool(n, PoolShape::CLASSIC), h0, choppiness: 0.0 };
        let k_lattice = lattice_k(m, n, PoolShape::CLASSIC);
        let expected_lattice = angular_frequency_in(k_lattice, PoolShape::CLASSIC.depth) / k_lattice;
        let fft = measured_phase_speed(|x, t| ocean.sample(x, 0.2, t)[0], dt, 0.5 * wavelength);
        // And the same from the FFT's grid: the crest's position between texels (sub-texel
        // by the phase of the fundamental along a row).
        let phase_at = |t: f64| {
            let row = &ocean.surface(t)[(n / 2) * n..(n / 2 + 1) * n];
            let (mut c, mut s) = (0.0f32, 0.0f32);
            for (i, v) in row.iter().enumerate() {
                let x = -HALF_WIDTH + (i as f32 + 0.5) * 2.0 * HALF_WIDTH / n as f32;
                c += v[0] * (k_lattice * x).cos();
                s += v[0] * (k_lattice * x).sin();
            }
            s.atan2(c)
        };
        let turned = (phase_at(dt) - phase_at(0.0) + std::f32::consts::PI).rem_euclid(std::f32::consts::TAU)
            - std::f32::consts::PI;
        let grid = turned / k_lattice / dt as f32;
        let errors = [sine / expected - 1.0, fft / expected_lattice - 1.0, grid / expected_lattice - 1.0];
        println!(
            "λ {wavelength} m: dispersion relation {expected:.4} m/s (lattice wave {expected_lattice:.4}); measured: sine \
             {sine:.4}, FFT wave {fft:.4}, FFT grid {grid:.4} (errors {:.2} %, {:.2} %, {:.2} %)",
            errors[0] * 100.0,
            errors[1] * 100.0,
            errors[2] * 100.0
        );
        worst = errors.iter().fold(worst, |w, e| w.max(e.abs()));
    }
    assert!(worst < 0.02, "a phase speed is {:.2} % off the dispersion relation", worst * 100.0);
}

#[test]
fn gerstner_heights_are_the_closed_form_at_the_points_the_waves_carry_to() {
    // A rest point x0 goes to x0 − Σ c a (K/k) sin θ, at height Σ a cos θ: sampling the
    // surface there (Newton's method inside) must give that height.
    for q in [0.0, 0.6, MAX_STEEPNESS] {
        let waves = AmbientWaves::new(&AmbientSettings { steepness: q, ..settings(AmbientModel::Gerstner) });
        let t = 1.7;
        let phases = waves.phases(t);
        let (mut worst, mut moved) = (0.0f32, 0.0f32);
        for i in 0..400 {
            let (x0, z0) = ((i % 20) as f32 * 0.09 - 0.85, (i / 20) as f32 * 0.09 - 0.85);
            let (mut x, mut z, mut h) = (x0, z0, 0.0f32);
            for (w, &p) in waves.waves.iter().zip(&phases) {
                let theta = w.kx * x0 + w.kz * z0 + p;
                let b = waves.gerstner_c * w.amplitude / (w.kx * w.kx + w.kz * w.kz).sqrt();
                x -= b * w.kx * theta.sin();
                z -= b * w.kz * theta.sin();
                h += w.amplitude * theta.cos();
            }
            moved = moved.max(((x - x0).powi(2) + (z - z0).powi(2)).sqrt());
            worst = worst.max((waves.sample(x, z, t)[0] - h).abs());
        }
        println!(
            "Gerstner Q {q}: points carried up to {:.1} mm; sampled height within {worst:.2e} m of the closed form",
            moved * 1e3
        );
        assert!(worst < 2e-6, "Q {q}: {worst} m off the closed form");
        assert!(q == 0.0 || moved > 0.01, "Q {q}: the water does not move sideways ({moved} m)");
    }
    // The water gathers under the crests and spreads in the troughs: the surface is steeper
    // above its mean level than below it, the more the steeper the waves (Q 0, a plain sum
    // of cosines, is the reference: six waves at one instant are not symmetric on their own).
    let asymmetry = |q: f32| {
        let w = AmbientWaves::new(&AmbientSettings { steepness: q, ..settings(AmbientModel::Gerstner) });
        let samples: Vec<[f32; 3]> =
            (0..40000).map(|i| w.sample((i % 200) as f32 * 0.01 - 1.0, (i / 200) as f32 * 0.01 - 1.0, 0.4)).collect();
        let mean = samples.iter().map(|s| s[0]).sum::<f32>() / samples.len() as f32;
        let steepness = |above: bool| {
            let side: Vec<f32> =
                samples.iter().filter(|s| (s[0] > mean) == above).map(|s| (s[1] * s[1] + s[2] * s[2]).sqrt()).collect();
            side.iter().sum::<f32>() / side.len() as f32
        };
        steepness(true) / steepness(false)
    };
    let (flat, mid, sharp) = (asymmetry(0.0), asymmetry(0.6), asymmetry(MAX_STEEPNESS));
    println!("mean slope above the mean level / below it: Q 0 {flat:.3}, Q 0.6 {mid:.3}, Q {MAX_STEEPNESS} {sharp:.3}");
    assert!(mid > 1.1 * flat && sharp > mid, "asymmetry {flat} / {mid} / {sharp}");
}

#[test]
fn the_fft_surface_is_its_waves_summed_and_its_variance_is_the_spectrum_sum() {
    for (size, spectrum) in [(64, Spectrum::Phillips), (128, Spectrum::Jonswap)] {
        let ocean = Ocean::new(&AmbientSettings { fft_size: size, spectrum, ..settings(AmbientModel::Fft) }, size);
        let t = 2.3;
        let map = ocean.surface(t);
        let peak = map.iter().map(|v| v[0].abs()).fold(0.0f32, f32::max);
        // The grid against the direct sum at texel centres.
        let mut worst = [0.0f32; 3];
        for idx in (0..size * size).step_by(97) {
            let (i, j) = (idx % size, idx / size);
            let cell = 2.0 * HALF_WIDTH / size as f32;
            let (x, z) = (-HALF_WIDTH + (i as f32 + 0.5) * cell, -HALF_WIDTH + (j as f32 + 0.5) * cell);
            let direct = ocean.sample(x, z, t);
            for c in 0..3 {
                worst[c] = worst[c].max((map[idx][c] - direct[c]).abs());
            }
        }
        // Parseval: the mean of h² over the grid is Σ |h(k, t)|².
        let mean = map.iter().map(|v| v[0] as f64).sum::<f64>() / map.len() as f64;
        let variance = map.iter().map(|v| (v[0] as f64 - mean).powi(2)).sum::<f64>() / map.len() as f64;
        let spectrum_sum: f64 =
            (0..size * size).map(|idx| ocean.amplitude(idx, t)).map(|a| (a[0] * a[0] + a[1] * a[1]) as f64).sum();
        let hs = 4.0 * variance.sqrt();
        println!(
            "{spectrum:?} {size}²: {} waves; grid vs direct sum: height {:.1e} of the peak {peak:.4} m, slopes {:.1e} / \
             {:.1e}; variance {variance:.4e} vs spectrum sum {spectrum_sum:.4e} ({:+.4} %); H_s now {hs:.4} m",
            ocean.wave_count(),
            worst[0] / peak,
            worst[1],
            worst[2],
            (variance / spectrum_sum - 1.0) * 100.0
        );
        assert!(worst[0] < 1e-5 * peak.max(1e-3) + 1e-7, "grid and direct sum differ by {} m", worst[0]);
        assert!((variance / spectrum_sum - 1.0).abs() < 0.01);
        assert!(ocean.wave_count() > 100 && hs > 0.005 && hs < 0.02, "{} waves, H_s {hs}", ocean.wave_count());
    }
}

#[test]
fn every_model_stays_finite_and_below_the_rim_at_every_extreme() {
    let mut highest = 0.0f32;
    for model in [AmbientModel::Sines, AmbientModel::Gerstner, AmbientModel::Modes, AmbientModel::Fft] {
        for wind_speed in [0.5, 10.0] {
            for spread_deg in [0.0, 90.0] {
                for (steepness, spectrum, fft_size, choppiness) in
                    [(0.0, Spectrum::Phillips, 64, 0.0), (MAX_STEEPNESS, Spectrum::Jonswap, 128, MAX_CHOPPINESS)]
                {
                    let s = AmbientSettings {
                        model,
                        wind_speed,
                        wind_direction_deg: -180.0,
                        significant_height: 0.03,
                        spread_deg,
                        steepness,
                        spectrum,
                        fft_size,
                        choppiness,
                        basin: PoolShape::CLASSIC,
                    };
                    let waves = AmbientWaves::new(&s);
                    for i in 0..300 {
                        let (x, z, t) = ((i % 17) as f32 / 8.0 - 1.0, (i / 17) as f32 / 9.0 - 1.0, i as f64 * 0.37);
                        let v = waves.sample(x, z, t);
                        assert!(v.iter().all(|c| c.is_finite()), "{model:?} {s:?}: {v:?} at ({x}, {z})");
                        highest = highest.max(v[0].abs());
                    }
                }
            }
        }
    }
    println!("highest ambient height at the extremes: {:.1} mm (rim {:.0} mm above rest)", highest * 1e3, RIM * 1e3);
    assert!(highest < 0.5 * RIM);
}

#[test]
fn the_choppy_ocean_carries_its_water_sideways_and_its_maps_are_its_waves_summed() {
    for choppiness in [1.0, MAX_CHOPPINESS] {
        let ocean =
            Ocean::new(&AmbientSettings { choppiness, significant_height: 0.03, ..settings(AmbientModel::Fft) }, 64);
        let t = 3.1;
        // The surface above the point a rest point is carried to has the rest point's height.
        let (mut worst, mut moved) = (0.0f32, 0.0f32);
        for i in 0..64 {
            let (x0, z0) = ((i % 8) as f32 * 0.23 - 0.8, (i / 8) as f32 * 0.23 - 0.8);
            let f = ocean.fields_at(x0, z0, t);
            let (x, z) = (x0 - choppiness * f[3], z0 - choppiness * f[4]);
            moved = moved.max(((x - x0).powi(2) + (z - z0).powi(2)).sqrt());
            worst = worst.max((ocean.sample(x, z, t)[0] - f[0]).abs());
        }
        // The displacement map against the wave-by-wave sums at texel centres.
        let map = ocean.displacement(t);
        let peak = map.iter().map(|v| v[0].abs().max(v[1].abs())).fold(0.0f32, f32::max);
        let mut off = 0.0f32;
        for idx in (0..64 * 64).step_by(61) {
            let cell = 2.0 / 64.0;
            let (x, z) = (-1.0 + ((idx % 64) as f32 + 0.5) * cell, -1.0 + ((idx / 64) as f32 + 0.5) * cell);
            let f = ocean.fields_at(x, z, t);
            for (c, want) in [f[3], f[4], f[5], f[7]].into_iter().enumerate() {
                off = off.max((map[idx][c] - want).abs());
            }
        }
        println!(
            "choppiness {choppiness}: water carried up to {:.1} mm; height above the carried point within {worst:.1e} m \
             of the rest point's; displacement map vs direct sums {:.1e} of its peak {:.2} mm",
            moved * 1e3,
            off / peak,
            peak * 1e3
        );
        assert!(moved > 1e-3 * choppiness, "the water does not move sideways ({moved} m)");
        assert!(worst < 2e-5, "{worst} m off the carried height");
        assert!(off < 1e-4 * peak, "the displacement map is {off} off");
    }
}
