//! Ambient waves on the GPU (lavapipe in CI): the picture moves with simulated time only
//! (paused, it stands; 30 and 144 frames/s give the same frame after the same second), the
//! simulation's own state never sees them, a floating duck rides them, the GPU's FFT agrees
//! with the CPU's, and each model draws its own picture and its own caustics.
// Tests read results back and wait for the GPU (clippy.toml: not in the frame path).
#![allow(clippy::disallowed_methods)]

mod common;

use common::render;
use wavepool::ambient::cascades::SeaWaves;
use wavepool::ambient::gpu_ocean::GpuOcean;
use wavepool::ambient::ocean::Ocean;
use wavepool::ambient::{AmbientModel, AmbientSettings};
use wavepool::demo::{DemoOptions, WaterDemo};
use wavepool::params::ParamId;

/// Every ambient model, as (parameter value, name).
const MODELS: [(f32, &str); 4] = [(1.0, "sines"), (2.0, "modes"), (3.0, "gerstner"), (4.0, "fft")];

const W: u32 = 240;
const H: u32 = 180;

/// An empty pool with ambient waves of `model` (1 sines, 2 modes, 3 Gerstner, 4 FFT).
fn pool_with(model: f32) -> WaterDemo {
    let mut demo = common::demo(DemoOptions::default());
    demo.params.set(ParamId::Objects, 0.0);
    demo.params.set(ParamId::Quality, 1.0);
    demo.params.set(ParamId::Ambient, model);
    demo
}

#[test]
fn ambient_waves_move_the_picture_with_simulated_time_only() {
    for (model, name) in MODELS {
        let mut calm = pool_with(0.0);
        let still = render(&mut calm, W, H, 60, 1.0 / 60.0);
        // Five seconds at 30, 60 and 144 frames/s: the same 600 fixed steps, the same surface.
        let mut slow = pool_with(model);
        let at_30 = render(&mut slow, W, H, 150, 1.0 / 30.0);
        let mut mid = pool_with(model);
        let at_60 = render(&mut mid, W, H, 300, 1.0 / 60.0);
        let mut fast = pool_with(model);
        let at_144 = render(&mut fast, W, H, 720, 1.0 / 144.0);
        // Later, and paused for a while.
        let later = render(&mut slow, W, H, 15, 1.0 / 30.0);
        slow.params.set(ParamId::Paused, 1.0);
        let paused_a = render(&mut slow, W, H, 1, 1.0 / 30.0);
        let paused_b = render(&mut slow, W, H, 20, 1.0 / 30.0);
        let all = common::Area::ALL;
        let (vs_calm, rates, moving, paused) = (
            at_30.changed_fraction(&still, all, 8),
            at_30.mean_abs_diff(&at_144, all).max(at_60.mean_abs_diff(&at_144, all)),
            at_30.changed_fraction(&later, all, 8),
            paused_a.mean_abs_diff(&paused_b, all),
        );
        println!(
            "{name}: {:.1} % of pixels differ from calm water; 30 and 60 vs 144 frames/s after 5 s: {rates:.3}/255 mean \
             difference (largest); 0.5 s later {:.1} % changed; paused for 20 frames: {paused:.3}/255",
            vs_calm * 100.0,
            moving * 100.0
        );
        assert!(vs_calm > 0.02, "{name}: the ambient waves do not show ({:.2} %)", vs_calm * 100.0);
        assert!(rates < 0.05, "{name}: 30 and 144 frames/s differ by {rates}/255");
        assert!(moving > 0.02, "{name}: the waves do not move ({:.2} %)", moving * 100.0);
        assert!(paused < 0.01, "{name}: paused, the picture still changes ({paused}/255)");
    }
}

#[test]
fn the_simulation_never_sees_the_ambient_waves() {
    let g = common::gpu();
    let run = |model: f32| {
        let mut demo = pool_with(model);
        demo.add_drop(0.2, -0.3, 0.06, 0.015);
        render(&mut demo, 64, 48, 40, 1.0 / 60.0);
        demo.water().read_state(&g.device, &g.queue)
    };
    let (without, with) = (run(0.0), run(1.0));
    let largest =
        without.iter().zip(&with).map(|(a, b)| (a[0] - b[0]).abs().max((a[1] - b[1]).abs())).fold(0.0f32, f32::max);
    let peak = without.iter().map(|c| c[0].abs()).fold(0.0f32, f32::max);
    println!("state with and without ambient waves: largest difference {largest:e} (ripple peak {peak:.4} m)");
    assert!(peak > 1e-3 && largest == 0.0, "the simulation changed with ambient waves: {largest}");
}

#[test]
fn a_floating_duck_rides_the_ambient_waves() {
    // The duck's height over 2 s, and the ambient surface's under its centre at each frame.
    let ride = |model: f32| {
        let mut demo = pool_with(model);
        demo.params.set(ParamId::Objects, 2.0); // the duck
        demo.params.set(ParamId::WaveHeight, 0.03);
        render(&mut demo, 64, 48, 120, 1.0 / 60.0); // settle for 2 s
        let (mut ys, mut surface) = (Vec::new(), Vec::new());
        for _ in 0..120 {
            render(&mut demo, 64, 48, 1, 1.0 / 60.0);
            let p = demo.duck().expect("the duck is in the pool").position;
            ys.push(p.y as f64);
            surface.push(demo.ambient().sample(p.x, p.z, demo.sim_time())[0] as f64);
        }
        // Its correlation with the surface, best over a lag of 0-0.25 s (a floating body
        // answers the water's push a little later).
        let correlation = |lag: usize| {
            let (y, s) = (&ys[lag..], &surface[..surface.len() - lag]);
            let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
            let (my, ms) = (mean(y), mean(s));
            let cov = y.iter().zip(s).map(|(a, b)| (a - my) * (b - ms)).sum::<f64>();
            let (vy, vs) =
                (y.iter().map(|a| (a - my).powi(2)).sum::<f64>(), s.iter().map(|b| (b - ms).powi(2)).sum::<f64>());
            cov / (vy * vs).sqrt().max(1e-30)
        };
        let (lag, best) = (0..=15).map(|l| (l, correlation(l))).max_by(|a, b| a.1.total_cmp(&b.1)).unwrap();
        let std = |v: &[f64]| {
            let mean = v.iter().sum::<f64>() / v.len() as f64;
            (v.iter().map(|y| (y - mean).powi(2)).sum::<f64>() / v.len() as f64).sqrt()
        };
        (std(&ys), best, lag, std(&surface))
    };
    let (calm, _, _, _) = ride(0.0);
    println!("the duck's heave (std of its height over 2 s): calm {:.2} mm", calm * 1e3);
    assert!(calm < 0.5e-3, "the duck moves on calm water ({calm} m)");
    for (model, name) in MODELS {
        let (heave, follows, lag, surface) = ride(model);
        println!(
            "  {name}: {:.2} mm (the surface under it {:.2} mm), correlation with it {follows:.2} ({:.0} ms later)",
            heave * 1e3,
            surface * 1e3,
            lag as f64 * 1000.0 / 60.0
        );
        assert!(heave > 1e-3, "the duck does not ride the {name} waves ({heave} m)");
        assert!(follows > DUCK_FOLLOWS, "the duck's height does not follow the {name} surface ({follows:.2})");
    }
}

/// The least correlation between the duck's height and the surface's under it (at its best lag
/// up to 0.25 s): it feels the ambient waves on a ring at its waterline (5 cm), and short
/// waves, which it spans, move it less than they move the point under its middle.
const DUCK_FOLLOWS: f64 = 0.35;

/// The height and normals debug views show the surface that is drawn: on calm water with
/// ambient waves they are no longer the flat rest colour.
#[test]
fn the_height_and_normals_views_show_the_ambient_waves() {
    for (view, name, model) in [(1.0, "height", 1.0), (2.0, "normals", 1.0), (1.0, "height", 4.0)] {
        let frame = |model: f32| {
            let mut demo = pool_with(model);
            demo.params.set(ParamId::DebugView, view);
            demo.params.set(ParamId::DebugInset, 0.0);
            render(&mut demo, W, H, 10, 1.0 / 60.0)
        };
        let (calm, waves) = (frame(0.0), frame(model));
        // The view is the centred square (H pixels); compare inside it.
        let square = common::Area(0.5 - 0.5 * H as f32 / W as f32 + 0.02, 0.02, H as f32 / W as f32 - 0.04, 0.96);
        let changed = waves.changed_fraction(&calm, square, 8);
        println!("{name} view: {:.1} % of the pool's square changed by ambient model {model}", changed * 100.0);
        assert!(changed > 0.3, "{name} view does not show the ambient waves ({:.1} %)", changed * 100.0);
    }
}

/// The GPU's FFT (spectrum pass and Stockham stages in fragment passes) against the CPU's
/// (radix-2 stages: any two ways of summing the waves must agree to the floats' rounding),
/// for both lattice sizes of the pool and for the sea's five cascades side by side (each its
/// own tile and depth), early and late (after several epochs), for the surface's chain and
/// the choppy displacement's.
#[test]
fn the_gpu_fft_matches_the_cpu_reference() {
    let g = common::gpu();
    let settings =
        |size| AmbientSettings { fft_size: size, choppiness: 1.5, ..AmbientSettings::default_for(AmbientModel::Fft) };
    let sea = SeaWaves::new(&AmbientSettings { significant_height: 1.0, wind_speed: 8.0, ..settings(64) }, 64);
    let cascades: Vec<Ocean> = sea.cascades.iter().map(|c| c.ocean.clone()).collect();
    let batches = [
        ("pool", vec![Ocean::new(&settings(64), 64)]),
        ("pool", vec![Ocean::new(&settings(128), 128)]),
        ("sea cascades", cascades),
    ];
    for (what, oceans) in batches {
        let (size, count) = (oceans[0].size, oceans.len());
        let mut gpu_ocean = GpuOcean::new(&g.device, size as u32, count as u32);
        let batch: Vec<&Ocean> = oceans.iter().collect();
        for t in [2.3, 1234.56] {
            let mut encoder = g.device.create_command_encoder(&Default::default());
            gpu_ocean.encode(&g.queue, &mut encoder, &batch, t);
            g.queue.submit([encoder.finish()]);
            let [surface, displacement] = gpu_ocean.output_textures();
            for (name, texture) in [("surface", surface), ("displacement", displacement)] {
                let bytes = wavepool::gpu::read_texture(&g.device, &g.queue, texture);
                let all: &[[f32; 4]] = bytemuck::cast_slice(&bytes);
                for (i, ocean) in oceans.iter().enumerate() {
                    let on_cpu = if name == "surface" { ocean.surface(t) } else { ocean.displacement(t) };
                    // Lattice i's block of the rows `count` lattices wide.
                    let on_gpu: Vec<[f32; 4]> =
                        (0..size * size).map(|k| all[(k / size) * size * count + i * size + k % size]).collect();
                    // Each field's largest difference, as a fraction of its largest value.
                    let relative: Vec<f32> = (0..4)
                        .map(|c| {
                            let largest = on_cpu.iter().map(|v| v[c].abs()).fold(0.0f32, f32::max);
                            let off =
                                on_gpu.iter().zip(&on_cpu).map(|(a, b)| (a[c] - b[c]).abs()).fold(0.0f32, f32::max);
                            off / largest
                        })
                        .collect();
                    println!(
                        "FFT {size}² ({what} {}/{count}, tile {} m) {name} at t = {t} s: GPU vs CPU, each \
                         field's largest difference over its largest value: {:.1e} {:.1e} {:.1e} {:.1e}",
                        i + 1,
                        2.0 * ocean.band.half_tile,
                        relative[0],
                        relative[1],
                        relative[2],
                        relative[3]
                    );
                    // Heights (and displacements) to 1e-5 of their peak; derivatives to 1e-4.
                    assert!(relative[0] < 1e-5 && relative[1..].iter().all(|r| *r < 1e-4), "{name}: {relative:?}");
                }
            }
        }
    }
}

/// Each model draws its own picture (no two alike), and moves the caustics on the floor
/// without a click.
#[test]
fn each_model_draws_its_own_picture_and_moves_the_caustics() {
    let all = common::Area::ALL;
    let mut frames = Vec::new();
    for (model, name) in MODELS {
        let mut demo = pool_with(model);
        let picture = render(&mut demo, W, H, 30, 1.0 / 60.0);
        demo.params.set(ParamId::DebugView, 4.0); // the caustics map
        demo.params.set(ParamId::DebugInset, 0.0);
        let caustics = render(&mut demo, W, H, 1, 1.0 / 60.0);
        let later = render(&mut demo, W, H, 20, 1.0 / 60.0);
        let mut calm = pool_with(0.0);
        calm.params.set(ParamId::DebugView, 4.0);
        calm.params.set(ParamId::DebugInset, 0.0);
        let calm_caustics = render(&mut calm, W, H, 31, 1.0 / 60.0);
        let (vs_calm, moving) =
            (caustics.changed_fraction(&calm_caustics, all, 8), caustics.changed_fraction(&later, all, 8));
        println!(
            "{name}: caustics differ from calm water's in {:.1} % of pixels, move in 1/3 s: {:.1} %",
            vs_calm * 100.0,
            moving * 100.0
        );
        assert!(vs_calm > 0.05 && moving > 0.05, "{name}: caustics {vs_calm} / {moving}");
        frames.push((name, picture));
    }
    for (i, (a, fa)) in frames.iter().enumerate() {
        for (b, fb) in &frames[i + 1..] {
            let changed = fa.changed_fraction(fb, all, 8);
            println!("  {a} vs {b}: {:.1} % of pixels differ", changed * 100.0);
            assert!(changed > 0.02, "{a} and {b} look alike ({changed})");
        }
    }
}

/// Without float render targets (many phones, WebGL2 without EXT_color_buffer_float) the FFT
/// ocean is summed on the CPU and uploaded: the same waves on the screen.
#[test]
fn without_float_targets_the_cpu_fft_draws_the_same_ocean() {
    let frame = |float_targets: bool, model: f32| {
        let mut demo = common::demo(DemoOptions { float_targets, ..DemoOptions::default() });
        demo.params.set(ParamId::Objects, 0.0);
        demo.params.set(ParamId::Quality, 1.0);
        demo.params.set(ParamId::Ambient, model);
        demo.params.set(ParamId::DebugView, 1.0); // heights: no 8-bit caustics in the way
        demo.params.set(ParamId::DebugInset, 0.0);
        render(&mut demo, W, H, 20, 1.0 / 60.0)
    };
    let all = common::Area::ALL;
    let (gpu, cpu, calm) = (frame(true, 4.0), frame(false, 4.0), frame(false, 0.0));
    let (same, shows) = (gpu.mean_abs_diff(&cpu, all), cpu.changed_fraction(&calm, all, 8));
    println!(
        "FFT ocean's heights, GPU FFT vs CPU FFT: {same:.3}/255 mean difference; CPU path vs calm: {:.1} % changed",
        shows * 100.0
    );
    assert!(same < 0.1 && shows > 0.3, "GPU vs CPU {same}/255, shows {shows}");
}

/// The spectrum view shows where the waves' energy lies in wavevector space: the FFT ocean's
/// many waves downwind (their centroid in the wind's direction, 30°), a sum of sines' six.
#[test]
fn the_spectrum_view_shows_the_waves_downwind() {
    let lit = |model: f32| {
        let mut demo = pool_with(model);
        demo.params.set(ParamId::DebugView, 6.0);
        demo.params.set(ParamId::DebugInset, 0.0);
        let frame = render(&mut demo, H, H, 2, 1.0 / 60.0); // square: the view fills it
                                                            // Lit cells are blue to orange; the rings are grey (all channels equal).
        let mut points = Vec::new();
        for y in 0..H {
            for x in 0..H {
                let [r, g, b] = frame.unit_rgb(x, y);
                if b.max(r) > 0.15 && (b - r).abs() > 0.1 && (r - g).abs() + (g - b).abs() > 0.1 {
                    points.push((x as f32 / H as f32 - 0.5, y as f32 / H as f32 - 0.5));
                }
            }
        }
        points
    };
    let (fft, sines) = (lit(4.0), lit(1.0));
    let (sx, sz) = fft.iter().fold((0.0, 0.0), |(a, b), p| (a + p.0, b + p.1));
    let angle = sz.atan2(sx).to_degrees();
    println!(
        "spectrum view: FFT {} lit pixels, centroid at {angle:.1}° (wind 30°); sines {} lit pixels",
        fft.len(),
        sines.len()
    );
    assert!((angle - 30.0).abs() < 15.0, "the FFT's waves are not downwind ({angle}°)");
    assert!(fft.len() > 4 * sines.len() && !sines.is_empty());
}

/// The shader's sines, modes and Gerstner waves are their closed forms: the height debug view
/// of calm water with ambient waves (one pixel per simulation cell), its colours turned back
/// into heights, against `AmbientWaves::sample` (the formulas) at each cell's centre.
#[test]
fn the_shaders_ambient_heights_are_the_closed_forms() {
    // The view's red channel: 0.5 + 0.5 t above rest, 0.5 + 0.4 t below (t = h / 5 mm),
    // displayed as colour^2.2 sRGB-encoded (debug_view.wgsl).
    let height_of = |byte: u8| {
        let encoded = byte as f32 / 255.0;
        let linear = if encoded <= 0.04045 { encoded / 12.92 } else { ((encoded + 0.055) / 1.055).powf(2.4) };
        let red = linear.powf(1.0 / 2.2);
        0.005 * if red >= 0.5 { (red - 0.5) / 0.5 } else { (red - 0.5) / 0.4 }
    };
    for (model, name) in [(1.0, "sines"), (2.0, "modes"), (3.0, "gerstner")] {
        let mut demo = common::demo(DemoOptions { sim_size: 256, ..DemoOptions::default() });
        demo.params.set(ParamId::Objects, 0.0);
        demo.params.set(ParamId::Ambient, model);
        demo.params.set(ParamId::WaveHeight, 0.004);
        demo.params.set(ParamId::DebugView, 1.0);
        demo.params.set(ParamId::DebugInset, 0.0);
        let frame = render(&mut demo, 256, 256, 20, 1.0 / 60.0);
        let t = demo.sim_time();
        let (mut worst, mut sum, mut peak) = (0.0f32, 0.0f32, 0.0f32);
        for y in (2..254).step_by(3) {
            for x in (2..254).step_by(3) {
                let i = ((y * 256 + x) * 4) as usize;
                let seen = height_of(frame.rgba[i]);
                let (px, pz) = ((x as f32 + 0.5) / 128.0 - 1.0, (y as f32 + 0.5) / 128.0 - 1.0);
                let expected = demo.ambient().sample(px, pz, t)[0];
                worst = worst.max((seen - expected).abs());
                sum += (seen - expected).abs();
                peak = peak.max(expected.abs());
            }
        }
        let mean = sum / (84.0 * 84.0);
        println!(
            "{name}: the shader's heights within {:.3} mm (mean {:.3} mm) of the closed form; highest {:.2} mm",
            worst * 1e3,
            mean * 1e3,
            peak * 1e3
        );
        assert!(peak > 1e-3 && peak < 4.9e-3, "{name}: heights out of the view's scale ({peak} m)");
        assert!(worst < 1.2e-4 && mean < 4e-5, "{name}: {worst} m off the closed form");
    }
}

/// Choppiness carries the FFT ocean's water sideways: a different picture from the height
/// field alone, still moving, the surface still there (no NaN from the fixed-point steps).
#[test]
fn the_choppy_ocean_draws_its_own_picture() {
    let frame = |choppiness: f32, frames: u32| {
        let mut demo = pool_with(4.0);
        demo.params.set(ParamId::WaveHeight, 0.02);
        demo.params.set(ParamId::Choppiness, choppiness);
        render(&mut demo, W, H, frames, 1.0 / 60.0)
    };
    let all = common::Area::ALL;
    let (plain, choppy, later) = (frame(0.0, 30), frame(3.0, 30), frame(3.0, 45));
    let mut still = pool_with(0.0);
    let calm = render(&mut still, W, H, 30, 1.0 / 60.0);
    let (vs_plain, vs_calm, moving) = (
        choppy.changed_fraction(&plain, all, 8),
        choppy.changed_fraction(&calm, all, 8),
        choppy.changed_fraction(&later, all, 8),
    );
    println!(
        "choppiness 3: {:.1} % of pixels differ from the height field alone, {:.1} % from calm water, {:.1} % moved in 0.25 s",
        vs_plain * 100.0,
        vs_calm * 100.0,
        moving * 100.0
    );
    assert!(vs_plain > 0.01 && vs_calm > 0.03 && moving > 0.02, "{vs_plain} / {vs_calm} / {moving}");
}
