//! The ripple tank (`scene` = tank): its waves on the CPU reference (walls, the double slit),
//! the GPU engine against the CPU's, and the lamp's image on the screen below in the demo.
// The tests read the tank's state and screen back from the GPU, waiting for it.
#![allow(clippy::disallowed_methods)]

mod common;

use common::picture::Rect;
use common::{demo, gpu, render};
use wavepool::demo::{DemoOptions, STEP_DT};
use wavepool::params::ParamId;
use wavepool::tank::cpu::CpuTank;
use wavepool::tank::gpu::TankWater;
use wavepool::tank::medium::{CellKind, Dipper, Medium};
use wavepool::tank::plan::plan;
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
    let settings = TankSettings { setup: Setup::DoubleSlit, ..Default::default() };
    let medium = Medium::of(&settings, TANK_CELLS);
    let g = gpu();
    let mut water = TankWater::new(&g.device, &g.queue, &medium, true);
    assert!(!water.on_cpu());
    let mut cpu = CpuTank::new(medium.clone());
    let mut drops = vec![wavepool::sim::Drop { x: 0.1, z: 0.1, radius: 0.01, strength: 0.0005 }];
    let mut cpu_drops = drops.clone();
    for frame in 0..60u32 {
        let t0 = (2 * frame) as f64 * STEP_DT as f64;
        let mut encoder = g.device.create_command_encoder(&Default::default());
        water.encode(&g.device, &g.queue, &mut encoder, &plan(&medium, &settings, t0, 2, STEP_DT, &mut drops), None);
        g.queue.submit([encoder.finish()]);
        cpu.run(&plan(&medium, &settings, t0, 2, STEP_DT, &mut cpu_drops));
    }
    let bytes = wavepool::gpu::read_texture(&g.device, &g.queue, water.state_texture());
    let on_gpu: &[[f32; 4]] = bytemuck::cast_slice(&bytes);
    let (mut diff, mut sum, mut worst) = (0.0f64, 0.0f64, 0.0f32);
    for (a, b) in on_gpu.iter().zip(&cpu.state) {
        diff += ((a[0] - b[0]) as f64).powi(2);
        sum += (b[0] as f64).powi(2);
        worst = worst.max((a[0] - b[0]).abs());
    }
    let relative = (diff / sum).sqrt();
    println!("1 s of the double slit: GPU against CPU, RMS difference {relative:.2e} of the RMS height, largest {worst:.2e} m");
    assert!(sum > 0.0 && relative < 1e-3);
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

#[test]
fn a_wall_drawn_with_the_pointer_keeps_the_waves_from_the_water_behind_it() {
    let (width, height) = (320u32, 240u32);
    let mut behind = Vec::new();
    for draw in [false, true] {
        let mut d = demo(DemoOptions::default());
        d.params.set(ParamId::Scene, 2.0);
        d.params.set(ParamId::TankTool, wavepool::tank::Tool::Walls.value());
        d.sync_scene();
        d.set_viewport(width, height);
        if draw {
            // A stroke across the tray 5 cm past the dipper, in eight moves.
            let size = glam::Vec2::new(width as f32, height as f32);
            let at = |x: f32| d.camera().project(glam::Vec3::new(x, 0.0, 0.05), size).expect("on screen");
            let (a, b) = (at(-0.22), at(0.22));
            d.pointer_down(a.x, a.y);
            for k in 1..=8 {
                let p = a + (b - a) * (k as f32 / 8.0);
                d.pointer_move(p.x, p.y);
            }
            d.pointer_up();
        }
        render(&mut d, width, height, 72, 1.0 / 60.0);
        let tank = d.tank();
        let g = gpu();
        let bytes = wavepool::gpu::read_texture(&g.device, &g.queue, tank.water().unwrap().state_texture());
        let state: &[[f32; 4]] = bytemuck::cast_slice(&bytes);
        let m = tank.medium();
        let walls = (0..m.cells * m.cells).filter(|&k| m.kind(k % m.cells, k / m.cells) == CellKind::Wall).count();
        let mut largest = 0.0f32;
        for j in 0..m.cells {
            for i in 0..m.cells {
                let (x, z) = m.centre(i, j);
                if x.abs() < 0.05 && (0.08..0.12).contains(&z) {
                    largest = largest.max(state[(j * m.cells + i) as usize][0].abs());
                }
            }
        }
        println!(
            "wall drawn: {draw} ({} strokes, {walls} wall cells): largest |h| behind it {:.2e} m",
            tank.strokes().len(),
            largest
        );
        behind.push(largest);
    }
    assert!(behind[0] > 1e-5, "the rings should reach the water past the stroke's line");
    assert!(behind[1] < 0.05 * behind[0], "the drawn wall let the waves through");
}

#[test]
fn the_probe_reads_the_dippers_frequency_within_one_percent_and_draws_its_graph() {
    let (width, height) = (160u32, 120u32);
    for frequency in [10.0f32, 6.5] {
        let mut d = demo(DemoOptions::default());
        d.params.set(ParamId::Scene, 2.0);
        d.params.set(ParamId::TankFrequency, frequency);
        d.params.set(ParamId::TankProbe, 1.0);
        // 120 mm from the dipper: its waves arrive within half a second.
        d.params.set(ParamId::TankProbeZ, 120.0);
        d.sync_scene();
        render(&mut d, width, height, 300, 1.0 / 60.0);
        let frame = render(&mut d, width, height, 2, 1.0 / 60.0);
        let reading = d.tank().probe_reading();
        let read = reading.frequency.expect("the probe should read a frequency after five seconds");
        println!("dipper {frequency} Hz: the probe reads {read:.3} Hz, swing {:.3} mm", reading.swing * 1e3);
        assert!((read / frequency - 1.0).abs() < 0.01, "{read} Hz against {frequency} Hz");
        assert!(reading.swing > 1e-5, "the probe should see the waves swing");
        let readings = d.readings();
        assert!(readings.iter().any(|&(name, v, _)| name == "probe frequency" && v == read));
        // The graph in the picture's lower right corner: the trace's yellow ink.
        let panel = Rect { x: width * 62 / 100, y: height * 76 / 100, w: width * 34 / 100, h: height * 20 / 100 };
        let pixels = frame.region(panel);
        let ink =
            pixels.iter().filter(|&&[r, g, b]| r > 180 && g > 140 && b < 120).count() as f32 / pixels.len() as f32;
        println!("  the graph's ink covers {:.1} % of its panel", ink * 100.0);
        assert!(ink > 0.05, "the probe's graph should be drawn");
    }
}

#[test]
fn a_sketch_in_a_share_link_redraws_the_walls_and_the_ruler() {
    let mut d = demo(DemoOptions::default());
    d.params.set(ParamId::Scene, 2.0);
    d.params.set(ParamId::TankTool, wavepool::tank::Tool::Walls.value());
    d.sync_scene();
    let (width, height) = (320u32, 240u32);
    d.set_viewport(width, height);
    let size = glam::Vec2::new(width as f32, height as f32);
    let at =
        |d: &wavepool::demo::WaterDemo, x: f32, z: f32| d.camera().project(glam::Vec3::new(x, 0.0, z), size).unwrap();
    let (a, b) = (at(&d, -0.1, 0.05), at(&d, 0.1, 0.08));
    d.pointer_down(a.x, a.y);
    d.pointer_move(b.x, b.y);
    d.pointer_up();
    d.params.set(ParamId::TankTool, wavepool::tank::Tool::Ruler.value());
    d.sync_scene();
    let (a, b) = (at(&d, -0.2, -0.1), at(&d, 0.1, -0.1));
    d.pointer_down(a.x, a.y);
    d.pointer_move(b.x, b.y);
    d.pointer_up();
    let text = d.sketch();
    let ruler = d.readings().iter().find(|r| r.0 == "ruler").map(|r| r.1).expect("a ruler reading");
    println!("sketch {text:?}, ruler {ruler:.1} mm");
    assert!(text.starts_with('W') && text.contains("_R"), "{text}");
    assert!((ruler - 300.0).abs() < 3.0, "the ruler laid over 300 mm reads {ruler} mm");
    let mut copy = demo(DemoOptions::default());
    copy.params.set(ParamId::Scene, 2.0);
    copy.set_sketch(&text).expect("the sketch reads");
    assert_eq!(copy.sketch(), text);
    let walls = |d: &wavepool::demo::WaterDemo| {
        let m = d.tank().medium();
        (0..m.cells * m.cells).filter(|&k| m.kind(k % m.cells, k / m.cells) == CellKind::Wall).count()
    };
    println!("wall cells: drawn {}, from the sketch {}", walls(&d), walls(&copy));
    assert!(walls(&d) > 50 && walls(&d) == walls(&copy));
    assert!(copy.set_sketch("W1,2").is_err() && copy.sketch() == text, "a bad sketch changes nothing");
}

#[test]
fn a_single_pulse_makes_one_crest_that_passes_and_leaves_the_water_still() {
    let settings = TankSettings { size: 0.3, pulse: true, ..Default::default() };
    let mut tank = CpuTank::new(Medium::of(&settings, 128));
    let (i, j) = tank.medium.cell_at(0.0, 0.08).expect("in the tray");
    let mut heights = Vec::new();
    let mut drops = Vec::new();
    let steps = (2.0 / STEP_DT).round() as u32;
    for batch in 0..steps / 2 {
        let t0 = (2 * batch) as f64 * STEP_DT as f64;
        let mut updates = plan(&tank.medium, &settings, t0, 2, STEP_DT, &mut drops);
        wavepool::tank::plan::shape_pulse(&mut updates, t0, 0.1);
        tank.run(&updates);
        heights.push(tank.height(i, j));
    }
    let peak = heights.iter().fold(0.0f32, |m, &h| m.max(h));
    // Crests: runs of heights over half the peak.
    let crests = heights.windows(2).filter(|w| w[0] < 0.5 * peak && w[1] >= 0.5 * peak).count();
    let last = heights[heights.len() - 20..].iter().fold(0.0f32, |m, &h| m.max(h.abs()));
    println!(
        "80 mm from the dipper: peak {:.3} mm, {crests} crest(s), the last 1/6 s of 2 s within {:.4} mm",
        peak * 1e3,
        last * 1e3
    );
    assert!(peak > 0.05 * settings.amplitude, "the pulse should reach the point");
    assert_eq!(crests, 1, "one pulse, one crest");
    // (In two dimensions a pulse leaves a fading tail behind it: no sharp end as in 1-D or 3-D.)
    assert!(last < 0.3 * peak, "the water should settle after the pulse has passed");
}

#[test]
fn the_apparatus_shows_the_lamp_over_the_tray_and_its_image_on_the_paper_and_the_split_shows_both_views() {
    let (width, height) = (240u32, 180u32);
    let start = |look: wavepool::tank::Look| {
        let mut d = demo(DemoOptions::default());
        d.params.set(ParamId::Scene, 2.0);
        d.params.set(ParamId::TankLook, look.value());
        d.sync_scene();
        d
    };
    let mut d = start(wavepool::tank::Look::Apparatus);
    let frame = render(&mut d, width, height, 90, 1.0 / 60.0);
    let settings = d.tank().settings();
    let size = glam::Vec2::new(width as f32, height as f32);
    let lamp = d.camera().project(glam::Vec3::new(0.0, settings.lamp_height, 0.0), size).expect("the lamp in view");
    let paper_y = -settings.depth - wavepool::tank::SCREEN_BELOW;
    // The rings' image on the paper, a little way in front of the dipper's (seen past the tray).
    let paper = d.camera().project(glam::Vec3::new(0.0, paper_y, 0.25), size).expect("the paper in view");
    let around = |p: glam::Vec2, r: u32| Rect { x: p.x as u32 - r, y: p.y as u32 - r, w: 2 * r, h: 2 * r };
    let bulb = frame.luma(lamp.x as u32, lamp.y as u32);
    let rings = frame.luma_spread(around(paper, 12));
    let room = frame.luma(width / 10, height / 10);
    println!("apparatus: the bulb's luma {bulb:.0}, the room's {room:.0}; the paper's luma spread round the rings' image {rings:.1}");
    assert!(bulb > 240.0 && room < 60.0, "the lamp should shine in a dim room");
    assert!(rings > 8.0, "the lamp's image of the rings should show on the paper");
    // The split: the apparatus on the left (as drawn alone in that half), the screen view on the right.
    let mut split = start(wavepool::tank::Look::Split);
    let both = render(&mut split, width, height, 90, 1.0 / 60.0);
    let mut alone = start(wavepool::tank::Look::Apparatus);
    let left = render(&mut alone, width / 2, height, 90, 1.0 / 60.0);
    let left_half = Rect { x: 0, y: 0, w: width / 2, h: height };
    let mut diff = 0.0;
    for (x, y) in left_half.points() {
        diff += (both.luma(x, y) - left.luma(x, y)).abs();
    }
    diff /= left_half.pixels() as f64;
    let right_half = Rect { x: width / 2, ..left_half };
    let (right_spread, right_mean) = (both.luma_spread(right_half), both.mean(right_half));
    println!("split: left half against the apparatus alone {diff:.2} luma; right half spread {right_spread:.1}, mean {right_mean:.0?}");
    assert!(diff < 2.0, "the split's left half should be the apparatus");
    assert!(right_spread > 20.0 && right_mean[0] > 60.0, "the split's right half should show the paper from above");
}

#[test]
fn a_phased_array_of_four_dippers_steers_its_beam_to_the_angle_theory_gives() {
    // Four dippers 30 mm apart at 6 Hz (0.58 of a wavelength), each a quarter cycle behind its
    // −x neighbour.
    let settings = TankSettings {
        setup: Setup::TwoDippers,
        dippers: 4,
        slit_spacing: 0.03,
        frequency: 6.0,
        phase_step: 90f32.to_radians(),
        size: 1.0,
        ..Default::default()
    };
    let mut tank = CpuTank::new(Medium::of(&settings, 320));
    run(&mut tank, &settings, 4.0, |_| {});
    // The intensity round an arc 0.35 m from the row's middle (its far field), every half degree.
    let m = tank.medium.clone();
    let (radius, mut best, mut brightest) = (0.35f32, 0.0f32, 0.0f32);
    for k in -140..=140 {
        let angle = (k as f32 * 0.5).to_radians();
        let Some((i, j)) = m.cell_at(radius * angle.sin(), radius * angle.cos()) else { continue };
        if tank.intensity(i, j) > brightest {
            (best, brightest) = (angle.to_degrees(), tank.intensity(i, j));
        }
    }
    let lambda = settings.wavelength();
    let theory = (settings.phase_step * lambda / (std::f32::consts::TAU * settings.slit_spacing)).asin().to_degrees();
    println!(
        "the beam at {best:.1}° (towards +x), theory arcsin(Δφ λ / (2π d)) = {theory:.1}° (λ {:.1} mm)",
        lambda * 1e3
    );
    // Within 2°: the dippers are disks that also scatter each other's waves, which the theory's
    // points do not (the beam sits about 1.3° short); a lost or reversed phase step is 25° off.
    assert!((best - theory).abs() <= 2.0, "the beam at {best}°, not {theory}°");
}

#[test]
fn a_dipper_dragged_with_the_move_tool_makes_its_waves_where_it_was_left_and_the_link_keeps_it() {
    let mut d = demo(DemoOptions::default());
    d.params.set(ParamId::Scene, 2.0);
    d.params.set(ParamId::TankTool, wavepool::tank::Tool::Move.value());
    d.sync_scene();
    let (width, height) = (320u32, 240u32);
    d.set_viewport(width, height);
    let size = glam::Vec2::new(width as f32, height as f32);
    let at =
        |d: &wavepool::demo::WaterDemo, x: f32, z: f32| d.camera().project(glam::Vec3::new(x, 0.0, z), size).unwrap();
    // From the dipper in the middle to (80, 60) mm, in four moves.
    let (a, b) = (at(&d, 0.0, 0.0), at(&d, 0.08, 0.06));
    d.pointer_down(a.x, a.y);
    for k in 1..=4 {
        let p = a + (b - a) * (k as f32 / 4.0);
        d.pointer_move(p.x, p.y);
    }
    d.pointer_up();
    let dipper = d.tank().medium().sources.dippers[0];
    let text = d.sketch();
    println!("the dipper is at ({:.1}, {:.1}) mm; sketch {text:?}", dipper.x * 1e3, dipper.z * 1e3);
    assert!((dipper.x - 0.08).abs() < 0.004 && (dipper.z - 0.06).abs() < 0.004, "the dipper did not follow");
    assert!(text.starts_with("D0,"), "{text}");
    // Its rings after half a second (0.16 m of travel): round where it was left the water
    // moves; 200 mm from there (but 100 mm from where it stood) it is still.
    render(&mut d, 64, 48, 30, 1.0 / 60.0);
    let m = d.tank().medium();
    let g = gpu();
    let bytes = wavepool::gpu::read_texture(&g.device, &g.queue, d.tank().water().unwrap().state_texture());
    let state: &[[f32; 4]] = bytemuck::cast_slice(&bytes);
    let swing_at = |x: f32, z: f32| {
        let (i, j) = m.cell_at(x, z).unwrap();
        state[(j * m.cells + i) as usize][2].sqrt()
    };
    let (near, far) = (swing_at(0.08, 0.09), swing_at(-0.08, -0.06));
    println!("after 0.5 s: rms height 30 mm from where it was left {:.2e} m, 200 mm from it {:.2e} m", near, far);
    assert!(near > 10.0 * far.max(1e-9), "the waves should start where the dipper was left");
    let mut copy = demo(DemoOptions::default());
    copy.params.set(ParamId::Scene, 2.0);
    copy.set_sketch(&text).expect("the sketch reads");
    let copied = copy.tank().medium().sources.dippers[0];
    assert!(
        (copied.x - dipper.x).abs() < 1e-3 && (copied.z - dipper.z).abs() < 1e-3,
        "the link lost the dipper's place"
    );
}

#[test]
fn two_dippers_a_hertz_apart_beat_once_a_second_where_their_waves_meet() {
    for ratio in [1.0f32, 0.5] {
        beats(ratio);
    }
}

/// Two dippers 1 Hz apart, the second `ratio` as strong: their beats where the waves meet.
fn beats(ratio: f32) {
    let settings =
        TankSettings { setup: Setup::TwoDippers, detune: 1.0, amplitude_ratio: ratio, size: 0.4, ..Default::default() };
    let mut tank = CpuTank::new(Medium::of(&settings, 160));
    // On the line between them, 100 mm out: both waves arrive together, so the swing there
    // grows and dies as their phases slide past each other.
    let (i, j) = tank.medium.cell_at(0.0, 0.1).unwrap();
    let mut heights = Vec::new();
    run(&mut tank, &settings, 6.0, |tank| heights.push(tank.height(i, j)));
    // The swing over each half period of the dippers (1/20 s), after the waves have arrived.
    let per_chunk = heights.len() / 120;
    let swings: Vec<f32> =
        heights.chunks(per_chunk).skip(10).map(|c| c.iter().fold(0.0f32, |m, &h| m.max(h.abs()))).collect();
    let loudest = swings.iter().fold(0.0f32, |m, &s| m.max(s));
    let quietest = swings.iter().fold(f32::MAX, |m, &s| m.min(s));
    // Unequal waves cancel only in part: at best (1 - r) / (1 + r) of their sum is left.
    let left = (1.0 - ratio) / (1.0 + ratio);
    println!("amplitude ratio {ratio}: the quietest swing {:.2} of the loudest (theory {left:.2})", quietest / loudest);
    // (Each swing is over a twentieth of a second, so even equal waves show 0.08 at their quietest.)
    assert!((quietest / loudest - left).abs() < 0.1, "the quietest swing is {} of the loudest", quietest / loudest);
    if ratio < 1.0 {
        return;
    }
    // The quiet moments: swings under a third of the loudest, each run of them one beat.
    let quiet: Vec<usize> =
        (1..swings.len()).filter(|&k| swings[k] < loudest / 3.0 && swings[k - 1] >= loudest / 3.0).collect();
    let beat = (quiet.last().unwrap() - quiet[0]) as f32 / (quiet.len() - 1) as f32 / 20.0;
    println!(
        "swing between {:.3} and {:.3} mm; {} quiet moments, {beat:.3} s apart (1 / 1 Hz = 1 s)",
        swings.iter().fold(f32::MAX, |m, &s| m.min(s)) * 1e3,
        loudest * 1e3,
        quiet.len()
    );
    assert!(quiet.len() >= 4, "the waves should beat");
    assert!((beat - 1.0).abs() < 0.05, "the beats are {beat} s apart");
}
