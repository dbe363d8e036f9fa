//! The ripple tank (`scene` = tank): its waves on the CPU reference (walls, the double slit,
//! plates, a moving dipper), the GPU engine against the CPU's, and the lamp's image on the
//! screen below in the demo; what the pointer and the instruments do is `lab.rs`.
// The tests read the tank's state and screen back from the GPU, waiting for it.
#![allow(clippy::disallowed_methods)]

#[path = "../common/mod.rs"]
mod common;
mod lab;

use common::picture::Rect;
use common::{demo, gpu, render};
use wavepool::demo::{DemoOptions, STEP_DT};
use wavepool::params::ParamId;
use wavepool::tank::cpu::CpuTank;
use wavepool::tank::gpu::TankWater;
use wavepool::tank::medium::{CellKind, Dipper, Medium};
use wavepool::tank::plan::{plan, shape_pulse};
use wavepool::tank::{Setup, TankSettings, TANK_CELLS};

/// Runs `tank` for `seconds` of fixed steps (two a batch, as a frame at 60 frames/s takes),
/// calling `each` after every update.
fn run(tank: &mut CpuTank, settings: &TankSettings, seconds: f32, mut each: impl FnMut(&CpuTank)) {
    let steps = (seconds / STEP_DT).round() as u32;
    let mut drops = Vec::new();
    for batch in 0..steps / 2 {
        let t0 = (2 * batch) as f64 * STEP_DT as f64;
        for update in plan(&tank.medium, settings, t0, 2, STEP_DT, &mut drops) {
            tank.update(&update);
            each(tank);
        }
    }
}

#[test]
fn a_closed_wall_lets_no_wave_through_and_a_gap_does() {
    let settings = TankSettings { size: 0.3, ..Default::default() };
    let mut far_side = Vec::new();
    for gap in [false, true] {
        let mut medium = Medium::open(128, settings.size, settings.depth, true);
        let dx = medium.dx();
        medium.barrier(0.0, 2.0 * dx, |x| gap && x.abs() < 0.02);
        medium.sources.dippers.push(Dipper::at(0.0, -0.07, 0.004));
        let mut tank = CpuTank::new(medium);
        let (mut near, mut far) = (0.0f32, 0.0f32);
        run(&mut tank, &settings, 1.5, |t| {
            for j in 0..128 {
                for i in 0..128 {
                    let z = t.medium.centre(i, j).1;
                    let h = t.height(i, j).abs();
                    if z < -2.0 * dx && t.medium.kind(i, j) != CellKind::Wall {
                        near = near.max(h);
                    } else if z > 2.0 * dx {
                        far = far.max(h);
                    }
                }
            }
        });
        println!("gap {gap}: largest |h| on the dipper's side {near:.3e} m, beyond the wall {far:.3e} m");
        far_side.push(far / near);
    }
    assert!(far_side[0] <= 1e-6, "a closed wall leaked {:.2e} of the peak", far_side[0]);
    assert!(far_side[1] > 1e-2, "the gap let only {:.2e} of the peak through", far_side[1]);
}

#[test]
fn the_double_slits_bright_lines_leave_at_arcsin_m_lambda_over_d() {
    // A tray of 1.2 m so that an arc 0.65 m from the slits is about in their far field
    // (d² / λ = 0.46 m).
    let settings = TankSettings {
        setup: Setup::DoubleSlit,
        size: 1.2,
        slit_width: 0.012,
        slit_spacing: 0.12,
        ..Default::default()
    };
    let medium = Medium::of(&settings, 512);
    let barrier_z = (0..512)
        .map(|j| medium.centre(0, j).1)
        .find(|&z| medium.cell_at(0.0, z).is_some_and(|(i, j)| medium.kind(i, j) == CellKind::Wall))
        .expect("a barrier");
    let (lambda, d, radius) = (settings.wavelength(), settings.slit_spacing, 0.65);
    let angles: Vec<f32> = (-240..=240).map(|k| k as f32 * 0.25).collect();
    let points: Vec<(u32, u32)> = angles
        .iter()
        .map(|a| {
            let (s, c) = a.to_radians().sin_cos();
            medium.cell_at(radius * s, barrier_z + radius * c).expect("the arc inside the tray")
        })
        .collect();
    let mut tank = CpuTank::new(medium);
    // The waves reach the arc after about 2.3 s; then the intensity is summed over 10 periods.
    run(&mut tank, &settings, 3.0, |_| {});
    let mut intensity = vec![0.0f64; points.len()];
    run(&mut tank, &settings, 10.0 / settings.frequency, |t| {
        for (sum, &(i, j)) in intensity.iter_mut().zip(&points) {
            *sum += (t.height(i, j) as f64).powi(2);
        }
    });
    for m in [1.0f32, 2.0] {
        let predicted = (m * lambda / d).asin().to_degrees();
        for side in [-1.0f32, 1.0] {
            // The brightest angle within 6° of the prediction, refined by a parabola.
            let near: Vec<usize> = (0..angles.len()).filter(|&k| (angles[k] - side * predicted).abs() < 6.0).collect();
            let k = *near.iter().max_by(|&&a, &&b| intensity[a].total_cmp(&intensity[b])).unwrap();
            let (a, b, c) = (intensity[k - 1], intensity[k], intensity[k + 1]);
            let found = (angles[k] + 0.25 * (0.5 * (a - c) / (a - 2.0 * b + c)) as f32).abs();
            println!(
                "m = {m}, {}: bright line at {found:.2}°, arcsin(m λ / d) = {predicted:.2}° (λ = {:.1} mm, d = {:.0} mm)",
                if side < 0.0 { "left" } else { "right" },
                lambda * 1e3,
                d * 1e3
            );
            assert!((found - predicted).abs() <= 0.05 * predicted, "m = {m}: {found:.2}° against {predicted:.2}°");
            assert!(near.first() != Some(&k) && near.last() != Some(&k), "no maximum near {predicted:.1}°");
        }
    }
}

#[test]
fn the_gpu_and_the_cpu_run_the_same_tank() {
    let double_slit = TankSettings { setup: Setup::DoubleSlit, ..Default::default() };
    // A row of three, each with its own phase, frequency and amplitude (the uniforms' per-dipper
    // parts), and a single pulse of it.
    let (phase_step, detune) = (45f32.to_radians(), 0.7);
    let row =
        TankSettings { setup: Setup::TwoDippers, dippers: 3, phase_step, detune, amplitude_ratio: 0.6, ..double_slit };
    let pulse = TankSettings { pulse: true, ..row };
    for (name, settings) in
        [("the double slit", double_slit), ("a row of three dippers", row), ("their single pulse", pulse)]
    {
        let (relative, worst) = gpu_against_cpu(&settings);
        println!(
            "1 s of {name}: GPU against CPU, RMS difference {relative:.2e} of the RMS height, largest {worst:.2e} m"
        );
        assert!(relative < 1e-3, "{name}: {relative}");
    }
}

/// One second of `settings` (a drop in the first frame) on the GPU and on the CPU: their RMS
/// difference as a share of the RMS height, and the largest difference (m).
fn gpu_against_cpu(settings: &TankSettings) -> (f64, f32) {
    let medium = Medium::of(settings, TANK_CELLS);
    let g = gpu();
    let mut water = TankWater::new(&g.device, &g.queue, &medium, true);
    assert!(!water.on_cpu());
    let mut cpu = CpuTank::new(medium.clone());
    let mut drops = vec![wavepool::sim::Drop { x: 0.1, z: 0.1, radius: 0.01, strength: 0.0005 }];
    let mut cpu_drops = drops.clone();
    for frame in 0..60u32 {
        let t0 = (2 * frame) as f64 * STEP_DT as f64;
        let mut updates = plan(&medium, settings, t0, 2, STEP_DT, &mut drops);
        let mut cpu_updates = plan(&medium, settings, t0, 2, STEP_DT, &mut cpu_drops);
        if settings.pulse {
            shape_pulse(&mut updates, t0, 0.0);
            shape_pulse(&mut cpu_updates, t0, 0.0);
        }
        let mut encoder = g.device.create_command_encoder(&Default::default());
        water.encode(&g.device, &g.queue, &mut encoder, &updates, None);
        g.queue.submit([encoder.finish()]);
        cpu.run(&cpu_updates);
    }
    let bytes = wavepool::gpu::read_texture(&g.device, &g.queue, water.state_texture());
    let on_gpu: &[[f32; 4]] = bytemuck::cast_slice(&bytes);
    let (mut diff, mut sum, mut worst) = (0.0f64, 0.0f64, 0.0f32);
    for (a, b) in on_gpu.iter().zip(&cpu.state) {
        diff += ((a[0] - b[0]) as f64).powi(2);
        sum += (b[0] as f64).powi(2);
        worst = worst.max((a[0] - b[0]).abs());
    }
    assert!(sum > 0.0, "the water should move");
    ((diff / sum).sqrt(), worst)
}

/// The value of an IEEE half float.
fn half(bits: u16) -> f32 {
    let (sign, exponent, mantissa) = (bits >> 15, ((bits >> 10) & 0x1f) as i32, (bits & 0x3ff) as f32);
    let magnitude = match exponent {
        0 => mantissa * 2f32.powi(-24),
        _ => (1.0 + mantissa / 1024.0) * 2f32.powi(exponent - 15),
    };
    if sign == 1 {
        -magnitude
    } else {
        magnitude
    }
}

#[test]
fn the_lamp_draws_a_plane_waves_crests_on_the_screen_as_bright_lines_at_its_magnified_period() {
    let mut d = demo(DemoOptions::default());
    d.params.set(ParamId::Scene, 2.0);
    d.params.set(ParamId::TankSetup, Setup::PlaneWave.value());
    d.params.set(ParamId::TankAmplitude, 0.15);
    d.sync_scene();
    let frame = render(&mut d, 320, 240, 150, 1.0 / 60.0);
    let tank = d.tank();
    let (settings, g) = (*tank.settings(), gpu());
    let picture = tank.picture().expect("drawn");
    let texels = picture.screen_image().width();
    let bytes = wavepool::gpu::read_texture(&g.device, &g.queue, picture.screen_image());
    let halves: &[u16] = bytemuck::cast_slice(&bytes);
    let extent = wavepool::scenes::tank::TankPicture::screen_half_extent(&settings);
    let magnification = settings.magnification();
    // The screen's middle column across the tray's middle half, light per row; and the
    // water's heights along the same line, each at the point of the screen it lights.
    let row_z = |row: u32| extent * (1.0 - 2.0 * (row as f32 + 0.5) / texels as f32);
    let rows: Vec<u32> = (0..texels).filter(|&r| row_z(r).abs() < 0.25 * settings.size * magnification).collect();
    let light: Vec<f32> = rows.iter().map(|&r| half(halves[((r * texels + texels / 2) * 4) as usize])).collect();
    let bytes = wavepool::gpu::read_texture(&g.device, &g.queue, tank.water().unwrap().state_texture());
    let state: &[[f32; 4]] = bytemuck::cast_slice(&bytes);
    let medium = tank.medium();
    let height_under = |z_screen: f32| {
        let (i, j) = medium.cell_at(0.0, z_screen / magnification).unwrap();
        state[(j * medium.cells + i) as usize][0]
    };
    // The period: the spacing of the bright lines (local maxima above the mean) on the screen.
    let mean = light.iter().sum::<f32>() / light.len() as f32;
    let peaks: Vec<usize> = (1..light.len() - 1)
        .filter(|&k| light[k] > 1.5 * mean && light[k] >= light[k - 1] && light[k] > light[k + 1])
        .collect();
    let expected = settings.wavelength() * magnification;
    // The period: the lag (rows) at which the light best matches itself, between half and
    // one and a half of the expected, refined by a parabola.
    let row_step = 2.0 * extent / texels as f32;
    let correlation = |lag: usize| -> f32 {
        let n = light.len() - lag;
        (0..n).map(|k| (light[k] - mean) * (light[k + lag] - mean)).sum::<f32>() / n as f32
    };
    let lags: Vec<usize> = ((0.5 * expected / row_step) as usize..=(1.5 * expected / row_step) as usize).collect();
    let best = *lags.iter().max_by(|&&a, &&b| correlation(a).total_cmp(&correlation(b))).unwrap();
    let (a, b, c) = (correlation(best - 1), correlation(best), correlation(best + 1));
    let spacing = (best as f32 + 0.5 * (a - c) / (a - 2.0 * b + c)) * row_step;
    // Each bright line lies under a crest: the water there stands higher than a quarter
    // wavelength to either side.
    let crests = peaks
        .iter()
        .filter(|&&k| {
            let z = row_z(rows[k]);
            let quarter = 0.25 * expected;
            height_under(z) > height_under(z + quarter) && height_under(z) > height_under(z - quarter)
        })
        .count();
    println!(
        "{} bright lines, their period on the screen {:.2} mm (λ × magnification = {:.2} mm); {crests} of them under crests; brightest {:.2}, mean {mean:.2}",
        peaks.len(),
        spacing * 1e3,
        expected * 1e3,
        light.iter().cloned().fold(0.0, f32::max)
    );
    assert!(peaks.len() >= 8);
    assert!((spacing - expected).abs() <= 0.03 * expected);
    assert!(crests * 10 >= peaks.len() * 9, "only {crests} of {} lines under crests", peaks.len());
    // And the frame shows them: the paper under the tray is lit and striped.
    let middle = Rect::centred_square(320, 240, 0.4);
    let (mean_luma, spread) = (frame.luma_stats(middle).0 * 255.0, frame.luma_spread(middle));
    println!("the frame's middle: luma mean {mean_luma:.1}, std {spread:.1}");
    assert!(mean_luma > 60.0 && spread > 8.0);
}

/// Upward zero crossings of `values` sampled at `positions` (m), interpolated.
fn crossings(positions: &[f32], values: &[f32]) -> Vec<f32> {
    (1..values.len())
        .filter(|&k| values[k - 1] < 0.0 && values[k] >= 0.0)
        .map(|k| {
            let t = values[k - 1] / (values[k - 1] - values[k]);
            positions[k - 1] + t * (positions[k] - positions[k - 1])
        })
        .collect()
}

/// The mean spacing of the upward zero crossings of the heights along line z = `z` for x in
/// `from..to` (m), or along x = `x` for z in that range when `along_z`.
fn wavelength_along(tank: &CpuTank, fixed: f32, from: f32, to: f32, along_z: bool) -> f32 {
    let m = &tank.medium;
    let (mut at, mut h) = (Vec::new(), Vec::new());
    for k in 0..m.cells {
        let (x, z) = m.centre(k, k);
        let s = if along_z { z } else { x };
        if s < from || s > to {
            continue;
        }
        let (i, j) = if along_z { m.cell_at(fixed, s) } else { m.cell_at(s, fixed) }.unwrap();
        at.push(s);
        h.push(tank.height(i, j));
    }
    let c = crossings(&at, &h);
    (c[c.len() - 1] - c[0]) / (c.len() - 1) as f32
}

#[test]
fn over_a_glass_plate_the_waves_shorten_by_the_root_of_the_depths_and_bend_by_snells_law() {
    let settings = TankSettings { setup: Setup::PlaneWave, size: 0.8, ..Default::default() };
    let share = wavepool::tank::PLATE_DEPTH_SHARE;
    // A plate whose edge runs parallel to the bar: the wavelengths on either side.
    let mut medium = Medium::of(&settings, 320);
    medium.paint(|_, z| (z > 0.0).then_some(CellKind::Plate));
    let mut tank = CpuTank::new(medium);
    run(&mut tank, &settings, 2.5, |_| {});
    let (deep, shallow) =
        (wavelength_along(&tank, 0.0, -0.22, -0.02, true), wavelength_along(&tank, 0.0, 0.02, 0.25, true));
    let (ratio, expected) = (shallow / deep, share.sqrt());
    println!("edge parallel: λ {:.2} mm in the open, {:.2} mm over the plate: ratio {ratio:.3}, sqrt(d2 / d1) = {expected:.3}", deep * 1e3, shallow * 1e3);
    assert!((ratio - expected).abs() <= 0.05 * expected);
    // The refraction set-up's edge at 30° to the fronts (the angle of incidence): over the
    // plate the fronts turn towards the edge, to θ2 from its normal with sin θ1 / sin θ2 =
    // c1 / c2. Their direction over the plate, from the crossings' spacing along x (sx) and
    // along z (sz): the wave vector is (2π / sx, 2π / sz), turned by atan(sz / sx) from +z.
    let mut tank = CpuTank::new(Medium::of(&TankSettings { setup: Setup::Refraction, ..settings }, 320));
    run(&mut tank, &settings, 3.0, |_| {});
    let sx = wavelength_along(&tank, 0.2, -0.05, 0.25, false);
    let sz = wavelength_along(&tank, 0.15, 0.1, 0.3, true);
    let turned = (sz / sx).atan();
    let (theta1, theta2) = (30f32.to_radians(), 30f32.to_radians() - turned);
    let (measured, expected) = (theta1.sin() / theta2.sin(), 1.0 / share.sqrt());
    println!(
        "edge at 30°: fronts over the plate {:.1}° from the edge's normal (λ {:.2} mm): sin θ1 / sin θ2 = {measured:.3}, c1 / c2 = {expected:.3}",
        theta2.to_degrees(),
        1e3 / (1.0 / (sx * sx) + 1.0 / (sz * sz)).sqrt()
    );
    assert!((measured - expected).abs() <= 0.05 * expected);
}

#[test]
fn a_moving_dipper_crowds_its_waves_ahead_and_spreads_them_behind() {
    let settings = TankSettings { setup: Setup::Doppler, size: 0.8, source_speed: 0.1, ..Default::default() };
    let mut tank = CpuTank::new(Medium::of(&settings, 320));
    let t = 2.5;
    run(&mut tank, &settings, t, |_| {});
    let (x, z) = tank.medium.sources.dippers[0].centre_at(t as f64);
    let ahead = wavelength_along(&tank, z, x + 0.03, x + 0.15, false);
    let behind = wavelength_along(&tank, z, x - 0.17, x - 0.03, false);
    let (c, f, v) = (settings.wave_speed(), settings.frequency, settings.source_speed);
    println!(
        "dipper at x = {x:.3} m moving at {v} m/s: λ ahead {:.2} mm ((c - v) / f = {:.2}), behind {:.2} mm ((c + v) / f = {:.2})",
        ahead * 1e3,
        (c - v) / f * 1e3,
        behind * 1e3,
        (c + v) / f * 1e3
    );
    assert!((ahead - (c - v) / f).abs() <= 0.05 * (c - v) / f);
    assert!((behind - (c + v) / f).abs() <= 0.05 * (c + v) / f);
}

#[test]
fn the_tanks_water_is_the_same_at_30_60_and_144_frames_a_second_and_bounded_with_four_dippers() {
    // The same 1.2 s in frames of three rates: the steps are fixed, so the water is too.
    let settings = TankSettings { setup: Setup::TwoDippers, size: 0.3, ..Default::default() };
    assert_eq!(Medium::of(&TankSettings { dippers: 4, ..settings }, 96).sources.dippers.len(), 4);
    let mut states = Vec::new();
    for fps in [30.0f64, 60.0, 144.0] {
        let medium = Medium::of(&settings, 96);
        let mut tank = CpuTank::new(medium);
        let mut clock = wavepool::sim::FixedStep::new(STEP_DT, 1000);
        let (mut steps_taken, mut drops) = (0u32, Vec::new());
        for _ in 0..(1.2 * fps).round() as u32 {
            let steps = clock.advance(1.0 / fps as f32);
            let t0 = steps_taken as f64 * STEP_DT as f64;
            tank.run(&plan(&tank.medium.clone(), &settings, t0, steps, STEP_DT, &mut drops));
            steps_taken += steps;
        }
        println!("{fps} frames/s: {steps_taken} steps");
        states.push((steps_taken, tank.state));
    }
    let shortest = states.iter().map(|s| s.0).min().unwrap();
    assert!(states.iter().all(|s| s.0 == shortest), "the rates took different numbers of steps");
    assert!(states.windows(2).all(|w| w[0].1 == w[1].1), "the water differs between frame rates");
    // Four dippers at full amplitude for 100,000 steps (a small tray, reflecting walls).
    let loud = TankSettings {
        amplitude: 1e-3,
        beaches: false,
        size: 0.1,
        frequency: 25.0,
        dippers: 4,
        slit_spacing: 0.02,
        ..settings
    };
    let mut medium = Medium::open(24, loud.size, loud.depth, false);
    for (x, z) in [(-0.02, -0.02), (0.02, -0.02), (-0.02, 0.02), (0.02, 0.02)] {
        medium.sources.dippers.push(Dipper::at(x, z, 0.004));
    }
    let mut tank = CpuTank::new(medium);
    let mut drops = Vec::new();
    let mut largest = 0.0f32;
    for batch in 0..1000u32 {
        let t0 = (batch * 100) as f64 * STEP_DT as f64;
        tank.run(&plan(&tank.medium.clone(), &loud, t0, 100, STEP_DT, &mut drops));
        assert!(tank.state.iter().all(|s| s.iter().all(|v| v.is_finite())), "not finite after {} steps", batch * 100);
        largest = tank.state.iter().fold(largest, |m, s| m.max(s[0].abs()));
    }
    println!("100,000 steps with four dippers at 1 mm: largest |h| {:.2} mm", largest * 1e3);
    assert!(largest <= wavepool::tank::MAX_TANK_HEIGHT);
}

#[test]
fn at_the_dippers_frequency_the_strobe_holds_the_pattern_still() {
    let mut worst = Vec::new();
    for strobe in [0.0, 10.0] {
        let mut d = demo(DemoOptions::default());
        d.params.set(ParamId::Scene, 2.0);
        d.params.set(ParamId::TankStrobe, strobe);
        d.sync_scene();
        // 2.5 s for the rings to fill the tray, then successive frames.
        let mut last = render(&mut d, 160, 120, 150, 1.0 / 60.0);
        let mut largest = 0.0f64;
        for _ in 0..8 {
            let next = render(&mut d, 160, 120, 1, 1.0 / 60.0);
            largest = largest.max(last.mean_abs_diff(&next, common::Area::ALL));
            last = next;
        }
        println!("strobe {strobe} Hz: successive frames differ by at most {largest:.3} (0-255, mean per channel)");
        worst.push(largest);
    }
    assert!(worst[0] > 1.0, "without the strobe the rings should move");
    assert!(worst[1] < 0.1 * worst[0], "with the strobe at the dipper's frequency the rings should stand still");
}

/// A ray parallel to the axis at height `a` (m) through a lens of two arcs of radius `r` (m)
/// meeting `t` (m) apart on the axis around `zc`, index `n` against the water outside (z along
/// the axis, m), by Snell's law at each arc: where it leaves the lens and its direction, or
/// nothing if it is turned back inside.
fn lens_ray(a: f32, r: f32, t: f32, zc: f32, n: f32) -> Option<(glam::Vec2, glam::Vec2)> {
    use glam::Vec2;
    let refract = |d: Vec2, normal: Vec2, eta: f32| -> Option<Vec2> {
        let cos_i = -d.dot(normal);
        let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
        (k >= 0.0).then(|| (eta * d + (eta * cos_i - k.sqrt()) * normal).normalize())
    };
    // The front arc's centre lies behind the lens, the back arc's in front of it.
    let (front, back) = (Vec2::new(0.0, zc + r - 0.5 * t), Vec2::new(0.0, zc - r + 0.5 * t));
    let hit = |p: Vec2, d: Vec2, centre: Vec2, far: bool| -> Vec2 {
        let o = p - centre;
        let (b, c) = (o.dot(d), o.dot(o) - r * r);
        let s = (b * b - c).sqrt();
        p + d * if far { -b + s } else { -b - s }
    };
    let p1 = hit(Vec2::new(a, zc - r), Vec2::Y, front, false);
    let d1 = refract(Vec2::Y, (p1 - front).normalize(), 1.0 / n)?;
    let p2 = hit(p1, d1, back, true);
    Some((p2, refract(d1, -(p2 - back).normalize(), n)?))
}

#[test]
fn a_lens_shaped_plate_brings_plane_waves_to_the_focus_rays_give() {
    // 20 Hz waves in cells half the default size (13 to a wavelength in the open, 8 over the
    // plate): the lens is then wide against the wavelength (a Fresnel number of about 5), so
    // diffraction moves the focus little.
    let settings = TankSettings { setup: Setup::Lens, frequency: 20.0, ..Default::default() };
    let mut tank = CpuTank::new(Medium::of(&settings, 512));
    run(&mut tank, &settings, 3.0, |_| {});
    let lens = wavepool::tank::medium::Lens::of(settings.size);
    let n = 1.0 / wavepool::tank::PLATE_DEPTH_SHARE.sqrt();
    let back = lens.centre + 0.5 * lens.thickness;
    let aperture = (lens.radius.powi(2) - (lens.radius - 0.5 * lens.thickness).powi(2)).sqrt();
    // The rays across the aperture: where the nearest to the axis cross it (the paraxial
    // focus), and where their bundle is narrowest (the circle of least confusion: a lens this
    // strong bends its rim's rays to a nearer focus).
    let rays: Vec<_> = (1..40)
        .filter_map(|k| lens_ray(k as f32 / 40.0 * aperture, lens.radius, lens.thickness, lens.centre, n))
        .collect();
    let crossing = |(p, d): (glam::Vec2, glam::Vec2)| p.y - p.x * d.y / d.x;
    let paraxial = crossing(rays[0]);
    let width = |z: f32| rays.iter().map(|(p, d)| (p.x + d.x * (z - p.y) / d.y).abs()).fold(0.0, f32::max);
    let narrowest = (0..400).map(|k| back + k as f32 * 1e-3).min_by(|a, b| width(*a).total_cmp(&width(*b))).unwrap();
    let m = &tank.medium;
    let (mut best, mut brightest) = (0.0, 0.0);
    for j in 0..m.cells {
        let z = m.centre(0, j).1;
        if z > back + 0.01 && z < 0.5 * settings.size * (1.0 - 2.0 * wavepool::tank::BEACH_SHARE) {
            let (i, j) = m.cell_at(0.0, z).unwrap();
            if tank.intensity(i, j) > brightest {
                (best, brightest) = (z, tank.intensity(i, j));
            }
        }
    }
    println!(
        "focus {:.1} mm behind the lens (the waves' brightest point on its axis); rays: narrowest bundle {:.1} mm ({} rays), paraxial focus {:.1} mm",
        (best - back) * 1e3,
        (narrowest - back) * 1e3,
        rays.len(),
        (paraxial - back) * 1e3
    );
    assert!((best - narrowest).abs() <= 0.1 * (narrowest - back));
}
