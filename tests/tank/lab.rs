//! The tank as a lab: walls drawn and dippers moved with the pointer, the probe, the sketch in
//! a share link, the single pulse, the apparatus, a row of dippers and each dipper's own
//! settings.

use super::common::picture::Rect;
use super::common::{demo, gpu, render};
use super::run;
use wavepool::demo::{DemoOptions, WaterDemo, STEP_DT};
use wavepool::params::ParamId;
use wavepool::tank::cpu::CpuTank;
use wavepool::tank::medium::{CellKind, Medium};
use wavepool::tank::plan::plan;
use wavepool::tank::{Setup, TankSettings};

/// The RMS height (m) at a tray point (x, z in m) of `d`'s water, read back from the GPU now.
fn rms_heights(d: &WaterDemo) -> impl Fn(f32, f32) -> f32 {
    let (m, g) = (d.tank().medium().clone(), gpu());
    let bytes = wavepool::gpu::read_texture(&g.device, &g.queue, d.tank().water().unwrap().state_texture());
    let state: Vec<[f32; 4]> = bytemuck::cast_slice(&bytes).to_vec();
    move |x, z| {
        let (i, j) = m.cell_at(x, z).unwrap();
        state[(j * m.cells + i) as usize][2].sqrt()
    }
}

/// Drags the pointer over `d`'s picture (`width` x `height` pixels) from the tray's point
/// `from` to `to` (x, z in m) in `moves` moves (0: a press and a release).
fn drag(d: &mut WaterDemo, (width, height): (u32, u32), from: (f32, f32), to: (f32, f32), moves: u32) {
    d.set_viewport(width, height);
    let size = glam::Vec2::new(width as f32, height as f32);
    let at =
        |d: &WaterDemo, (x, z): (f32, f32)| d.camera().project(glam::Vec3::new(x, 0.0, z), size).expect("on screen");
    let (a, b) = (at(d, from), at(d, to));
    d.pointer_down(a.x, a.y);
    for k in 1..=moves {
        let p = a + (b - a) * (k as f32 / moves as f32);
        d.pointer_move(p.x, p.y);
    }
    d.pointer_up();
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
            drag(&mut d, (width, height), (-0.22, 0.05), (0.22, 0.05), 8);
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
        // Reset stills the water and forgets what the probe read.
        d.reset(&gpu().queue);
        let cleared =
            d.tank().probe_reading().frequency.is_none() && d.readings().iter().all(|r| r.0 != "probe frequency");
        assert!(cleared, "the reading outlived the reset: {:?}", d.readings());
    }
}

#[test]
fn a_sketch_in_a_share_link_redraws_the_walls_and_the_ruler() {
    let mut d = demo(DemoOptions::default());
    d.params.set(ParamId::Scene, 2.0);
    d.params.set(ParamId::TankTool, wavepool::tank::Tool::Walls.value());
    d.sync_scene();
    drag(&mut d, (320, 240), (-0.1, 0.05), (0.1, 0.08), 1);
    d.params.set(ParamId::TankTool, wavepool::tank::Tool::Ruler.value());
    d.sync_scene();
    drag(&mut d, (320, 240), (-0.2, -0.1), (0.1, -0.1), 1);
    let text = d.sketch();
    let ruler = d.readings().iter().find(|r| r.0 == "ruler").map(|r| r.1).expect("a ruler reading");
    println!("sketch {text:?}, ruler {ruler:.1} mm");
    assert!(text.starts_with('W') && text.contains("_R"), "{text}");
    assert!((ruler - 300.0).abs() < 3.0, "the ruler laid over 300 mm reads {ruler} mm");
    let mut copy = demo(DemoOptions::default());
    copy.params.set(ParamId::Scene, 2.0);
    copy.set_sketch(&text).expect("the sketch reads");
    assert_eq!(copy.sketch(), text);
    // A wall's drag paints its cells once a frame.
    render(&mut d, 32, 24, 1, 1.0 / 60.0);
    let walls = |d: &WaterDemo| {
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
    // A click in the right half lands where the top view shows it: the probe goes there.
    split.params.set(ParamId::TankTool, wavepool::tank::Tool::Probe.value());
    split.sync_scene();
    let half = glam::Vec2::new((width / 2) as f32, height as f32);
    let top = wavepool::scenes::tank::top_camera(split.tank().settings().size, half.x / half.y);
    let p = top.project(glam::Vec3::new(0.1, 0.0, -0.05), half).unwrap() + glam::Vec2::new(half.x, 0.0);
    split.pointer_down(p.x, p.y);
    split.pointer_up();
    split.sync_scene();
    let probe = split.tank().settings().probe;
    println!("a click at the top view's (100, -50) mm puts the probe at {probe:?}");
    let (x, z) = probe.expect("the probe tool's click puts the probe in");
    assert!((x - 0.1).abs() < 0.004 && (z + 0.05).abs() < 0.004, "the split's click missed: {probe:?}");
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
    // From the dipper in the middle to (80, 60) mm, in four moves.
    drag(&mut d, (320, 240), (0.0, 0.0), (0.08, 0.06), 4);
    let dipper = d.tank().medium().sources.dippers[0];
    let text = d.sketch();
    println!("the dipper is at ({:.1}, {:.1}) mm; sketch {text:?}", dipper.x * 1e3, dipper.z * 1e3);
    assert!((dipper.x - 0.08).abs() < 0.004 && (dipper.z - 0.06).abs() < 0.004, "the dipper did not follow");
    assert!(text.starts_with("D0,"), "{text}");
    // Its rings after half a second (0.16 m of travel): round where it was left the water
    // moves; 200 mm from there (but 100 mm from where it stood) it is still.
    render(&mut d, 64, 48, 30, 1.0 / 60.0);
    let swing_at = rms_heights(&d);
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

#[test]
fn a_dippers_own_frequency_amplitude_and_phase_change_its_waves_and_the_link_keeps_them() {
    let mut d = demo(DemoOptions::default());
    d.params.set(ParamId::Scene, 2.0);
    d.params.set(ParamId::TankSetup, Setup::TwoDippers.value());
    d.params.set(ParamId::TankSize, 0.4);
    d.sync_scene();
    assert!(d.picked().is_none(), "a dipper's settings show with the move tool only");
    d.params.set(ParamId::TankTool, wavepool::tank::Tool::Move.value());
    d.sync_scene();
    let picked = d.picked().expect("the move tool shows a dipper's settings");
    let shown: Vec<(&str, f32)> = picked.settings.iter().map(|(s, v)| (s.name, *v)).collect();
    println!("{}: {shown:?}", picked.english_title());
    assert_eq!(
        (picked.english_title().as_str(), shown),
        ("Dipper 1", vec![("frequency", 10.0), ("amplitude", 0.3), ("phase", 0.0)])
    );
    // A press on the second dipper picks it.
    let second = d.tank().medium().sources.dippers[1];
    drag(&mut d, (320, 240), (second.x, second.z), (second.x, second.z), 0);
    assert_eq!(d.picked().unwrap().english_title(), "Dipper 2");
    let bad = d.set_picked("colour", 1.0);
    assert!(bad.is_err(), "a dipper has no colour");
    // Crest against trough: the line through the middle between them is still.
    d.set_picked("phase", 180.0).unwrap();
    let (out_of_step, _) = swing_and_frequency(&d, (0.0, 0.1));
    d.set_picked("phase", 0.0).unwrap();
    let (in_step, _) = swing_and_frequency(&d, (0.0, 0.1));
    println!(
        "100 mm out on the middle line: swing {:.4} mm in step, {:.4} mm 180° apart",
        in_step * 1e3,
        out_of_step * 1e3
    );
    assert!(out_of_step < 0.15 * in_step, "180° apart, the middle line should be still");
    // The second at 15 Hz and the first stilled: the water beside them runs at 15 Hz.
    d.set_picked("frequency", 15.0).unwrap();
    let text = d.sketch();
    let mut copy = demo(DemoOptions::default());
    for (id, v) in [(ParamId::Scene, 2.0), (ParamId::TankSetup, Setup::TwoDippers.value()), (ParamId::TankSize, 0.4)] {
        copy.params.set(id, v);
    }
    copy.sync_scene();
    copy.set_sketch(&format!("{text}_T0,10,0,0")).expect("the sketch reads");
    println!("sketch {text:?}; the copy's {:?}", copy.sketch());
    let (swing, frequency) = swing_and_frequency(&copy, (second.x, 0.1));
    println!("beside the second dipper: {frequency:.3} Hz, swing {:.4} mm", swing * 1e3);
    assert!((frequency / 15.0 - 1.0).abs() < 0.01, "{frequency} Hz against its own 15 Hz");
    let first = copy.tank().medium().sources.dippers[0];
    assert_eq!(first.amplitude, 0.0, "the first dipper was stilled");
}

/// The swing (m) and frequency (Hz) at `at` (m) over the last second of three, with the
/// dippers of `d`'s tank on the CPU reference (a coarser grid of the same tray).
fn swing_and_frequency(d: &WaterDemo, at: (f32, f32)) -> (f32, f32) {
    let settings = *d.tank().settings();
    let mut medium = Medium::of(&settings, 160);
    medium.sources.dippers = d.tank().medium().sources.dippers.clone();
    let mut tank = CpuTank::new(medium);
    let (i, j) = tank.medium.cell_at(at.0, at.1).unwrap();
    let mut heights = Vec::new();
    run(&mut tank, &settings, 3.0, |tank| heights.push(tank.height(i, j)));
    let last = &heights[heights.len() * 2 / 3..];
    let reading = wavepool::tank::probe::read(last, 1.0 / (heights.len() as f32 / 3.0));
    (reading.swing, reading.frequency.unwrap_or(0.0))
}

#[test]
fn the_bar_dragged_with_the_move_tool_sends_its_waves_from_where_it_was_left_and_the_link_keeps_it() {
    let mut d = demo(DemoOptions::default());
    d.params.set(ParamId::Scene, 2.0);
    d.params.set(ParamId::TankSetup, Setup::PlaneWave.value());
    d.params.set(ParamId::TankTool, wavepool::tank::Tool::Move.value());
    d.sync_scene();
    let bar = d.tank().medium().sources.bar.expect("the plane wave's bar");
    drag(&mut d, (320, 240), (0.05, bar.z), (0.05, 0.0), 4);
    let moved = d.tank().medium().sources.bar.unwrap();
    let text = d.sketch();
    println!("the bar from z = {:.1} mm to {:.1} mm; sketch {text:?}", bar.z * 1e3, moved.z * 1e3);
    assert!(moved.z.abs() < 0.004, "the bar did not follow");
    assert!(text.contains(&format!("B{}", (moved.z * 1e3).round() as i32)), "{text}");
    // A quarter of a second (80 mm of travel): the water moves beside its new place and is
    // still 170 mm from it (60 mm from its old place).
    render(&mut d, 64, 48, 15, 1.0 / 60.0);
    let swing_at = rms_heights(&d);
    let (near, old) = (swing_at(0.0, 0.04), swing_at(0.0, -0.17));
    println!("after 0.25 s: rms height 40 mm from it {near:.2e} m, by its old place {old:.2e} m");
    assert!(near > 10.0 * old.max(1e-9), "the waves should start where the bar was left");
    let mut copy = demo(DemoOptions::default());
    copy.params.set(ParamId::Scene, 2.0);
    copy.params.set(ParamId::TankSetup, Setup::PlaneWave.value());
    copy.sync_scene();
    copy.set_sketch(&text).expect("the sketch reads");
    assert!((copy.tank().medium().sources.bar.unwrap().z - moved.z).abs() < 1e-3, "the link lost the bar's place");
}
