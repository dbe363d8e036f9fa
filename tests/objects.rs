//! Things in the water, on the GPU (lavapipe in CI): the sphere and the duck fall, float and
//! come to rest at their waterlines; bodies push the water, also fully submerged; the mean
//! level accounts for the volume they take up; the duck is drawn and casts a shadow; and the
//! water heights the bodies float on are the water the frame starts from, with no GPU readback
//! and no wait on the frame path.
// Tests read results back and wait for the GPU (clippy.toml: not in the frame path).
#![allow(clippy::disallowed_methods)]

mod common;

use glam::{Quat, Vec2, Vec3};
use wavepool::bodies::duck;
use wavepool::demo::{BodyId, DemoOptions};
use wavepool::headless::OffscreenTarget;
use wavepool::params::ParamId;
use wavepool::physics::{Ellipsoid, Pose, Shape};
use wavepool::sim::pool_area;
use wavepool::WaterDemo;

const NONE: f32 = 0.0;
const SPHERE: f32 = 1.0;
const DUCK: f32 = 2.0;
const BALL: f32 = 4.0;

/// Runs `frames` frames of 1/60 s into a small target. After each frame the test waits for the
/// GPU to finish, as a display's frame pacing would (the browser gives a frame per vsync), so
/// the water statistics read back without waiting are current; the demo itself never waits,
/// and the bodies' heights come from the CPU's copy of the water whatever the pacing.
fn run(demo: &mut WaterDemo, frames: u32, mut each: impl FnMut(&mut WaterDemo, u32)) {
    let g = common::gpu();
    let target = OffscreenTarget::new(&g.device, 64, 48);
    for k in 0..frames {
        each(demo, k);
        demo.frame(&g.device, &g.queue, &target.view, target.size(), 1.0 / 60.0);
        g.device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
    }
}

fn heights(demo: &WaterDemo) -> Vec<f32> {
    let g = common::gpu();
    demo.water().read_state(&g.device, &g.queue).iter().map(|c| c[0]).collect()
}

fn mean(h: &[f32]) -> f64 {
    h.iter().map(|&v| v as f64).sum::<f64>() / h.len() as f64
}

fn demo_with(objects: f32, float_targets: bool) -> WaterDemo {
    let mut demo = common::demo(DemoOptions { sim_size: 128, float_targets, ..DemoOptions::default() });
    demo.params.set(ParamId::Objects, objects);
    demo
}

#[test]
fn a_released_sphere_falls_enters_and_rests_at_its_floating_line() {
    let mut demo = demo_with(SPHERE, true);
    demo.params.set(ParamId::SphereRadius, 0.2);
    demo.params.set(ParamId::SphereDensity, 500.0);
    demo.params.set(ParamId::Gravity, 1.0);
    demo.set_sphere_centre(Vec3::new(0.1, 0.35, -0.1));
    let (mut lowest, mut latency) = (f32::INFINITY, 0);
    run(&mut demo, 8 * 60, |demo, _| {
        lowest = lowest.min(demo.sphere().unwrap().centre.y);
        latency = latency.max(demo.probe_latency().unwrap_or(0));
    });
    let sphere = demo.sphere().unwrap();
    let level = demo.submerged_volume() / pool_area(1.0);
    let hull = [Ellipsoid { centre: Vec3::ZERO, radii: Vec3::splat(0.2) }];
    let expected = Shape { hull: &hull, centre_of_mass: Vec3::ZERO, density: 500.0, scale: 1.0 }.floating_height(level);
    let speed = demo.body(BodyId::named("sphere").unwrap()).velocity.length();
    println!(
        "sphere: lowest {lowest:.3} m, rests at {:.4} m (floating line {expected:.4} m, water level {level:.4} m), \
         speed {speed:.4} m/s, probe latency up to {latency} frames",
        sphere.centre.y
    );
    assert!(lowest < -0.02, "the sphere never went below its floating line: lowest {lowest}");
    assert!((sphere.centre.y - expected).abs() < 0.015, "rests at {} m, expected {expected} m", sphere.centre.y);
    assert!(speed < 0.03, "still moving at {speed} m/s");
    assert!((1..=2).contains(&latency), "water heights arrived {latency} frames late");
}

/// A sphere 10 cm under the surface moved sideways at 0.5 m/s: the water above its path rises
/// and falls by millimetres; the same sphere held still leaves the water flat.
fn submerged_wake(float_targets: bool) {
    let path = |demo: &mut WaterDemo, moving: bool| {
        demo.params.set(ParamId::SphereRadius, 0.15);
        demo.params.set(ParamId::Gravity, 0.0);
        let (start, depth) = (-0.5, -0.25);
        run(demo, 150, |demo, k| {
            let t = k.saturating_sub(30) as f32 / 60.0;
            let x = if moving { (start + 0.5 * t).min(0.5) } else { start };
            demo.set_sphere_centre(Vec3::new(x, depth, 0.0));
        });
        let h = heights(demo);
        let level = demo.submerged_volume() / pool_area(1.0);
        let n = demo.water().size() as usize;
        let mut peak = 0.0f32;
        for j in 0..n {
            let z = (j as f32 + 0.5) / n as f32 * 2.0 - 1.0;
            for i in 0..n {
                let x = (i as f32 + 0.5) / n as f32 * 2.0 - 1.0;
                if z.abs() < 0.1 && x.abs() < 0.6 {
                    peak = peak.max((h[j * n + i] - level).abs());
                }
            }
        }
        (peak, mean(&h) - level as f64)
    };
    let (moving, moving_mean) = path(&mut demo_with(SPHERE, float_targets), true);
    let (still, still_mean) = path(&mut demo_with(SPHERE, float_targets), false);
    println!(
        "float targets {float_targets}: largest |h - level| over the path {:.2} mm moving, {:.4} mm still; \
         mean minus level {moving_mean:e} / {still_mean:e} m",
        moving * 1e3,
        still * 1e3
    );
    assert!(moving > 2e-3, "a submerged sphere moving sideways left only {moving} m above its path");
    assert!(still < 1e-4, "a sphere held still disturbed the water by {still} m");
    assert!(moving_mean.abs() < 1e-5 && still_mean.abs() < 1e-5, "the mean left the rest level");
}

#[test]
fn a_submerged_sphere_moved_sideways_raises_a_wake_above_its_path() {
    submerged_wake(true);
}

#[test]
fn a_submerged_sphere_moved_sideways_raises_a_wake_on_the_cpu_engine() {
    submerged_wake(false);
}

#[test]
fn entering_raises_the_level_and_leaving_lowers_it_back() {
    let mut demo = demo_with(SPHERE, true);
    demo.params.set(ParamId::SphereRadius, 0.2);
    demo.params.set(ParamId::Gravity, 0.0);
    let r: f32 = 0.2;
    let volume = 4.0 / 3.0 * std::f32::consts::PI * r.powi(3);
    let (mut near_peak, far_probe) = (0.0f32, Vec2::new(-0.7, -0.7));
    let mut far_max = 0.0f32;
    // Above the water, then down into it over half a second, then held under.
    run(&mut demo, 90, |demo, k| {
        let y = if k < 10 { 0.4 } else { (0.4 - (k - 10) as f32 / 30.0).max(-0.5) };
        demo.set_sphere_centre(Vec3::new(0.0, y, 0.0));
    });
    let h = heights(&demo);
    let n = demo.water().size() as usize;
    for j in 0..n {
        for i in 0..n {
            let p = Vec2::new(i as f32 + 0.5, j as f32 + 0.5) / n as f32 * 2.0 - 1.0;
            if p.length() < 0.4 {
                near_peak = near_peak.max(h[j * n + i]);
            }
            if p.distance(far_probe) < 0.1 {
                far_max = far_max.max(h[j * n + i]);
            }
        }
    }
    let under = mean(&h);
    let expected = (volume / pool_area(1.0)) as f64;
    run(&mut demo, 90, |demo, k| {
        let y = (-0.5 + k as f32 / 30.0).min(0.4);
        demo.set_sphere_centre(Vec3::new(0.0, y, 0.0));
    });
    let out = mean(&heights(&demo));
    println!(
        "mean level: {:.3} mm under water (volume / area {:.3} mm), {:.5} mm after leaving; near peak {:.1} mm",
        under * 1e3,
        expected * 1e3,
        out * 1e3,
        near_peak * 1e3
    );
    assert!((under - expected).abs() < 0.01 * expected, "level {under} m with the sphere in, expected {expected} m");
    assert!(out.abs() < 1e-5, "level {out} m after the sphere left");
    assert!(near_peak > expected as f32 + 2e-3, "the entry pushed no water up around the sphere: {near_peak} m");
}

#[test]
fn a_dropped_duck_floats_upright_at_its_waterline() {
    let mut demo = demo_with(DUCK, true);
    demo.params.set(ParamId::Gravity, 1.0);
    let tilted = Quat::from_rotation_x(0.6) * Quat::from_rotation_y(1.0);
    demo.set_body_pose(BodyId::named("duck").unwrap(), Pose { position: Vec3::new(-0.2, 0.3, 0.1), rotation: tilted });
    run(&mut demo, 10 * 60, |_, _| {});
    let pose = demo.duck().unwrap();
    let up = pose.rotation * Vec3::Y;
    let level = demo.submerged_volume() / pool_area(1.0);
    let expected = duck::shape(demo.params.get(ParamId::DuckDensity)).floating_height(level);
    println!(
        "duck: up {up:.3} ({:.1} degrees from vertical), origin at {:.4} m, floating line {expected:.4} m",
        up.y.acos().to_degrees(),
        pose.position.y
    );
    assert!(up.y > 8f32.to_radians().cos(), "the duck floats tilted: up = {up}");
    assert!((pose.position.y - expected).abs() < 0.015, "floats at {} m, expected {expected} m", pose.position.y);
}

/// A `w` x `h` frame from nearly straight above, the sun from the side at 50°, with `objects`
/// held still where `place` puts them.
fn top_view(objects: f32, w: u32, h: u32, place: impl Fn(&mut WaterDemo)) -> (WaterDemo, common::Image) {
    let mut demo = demo_with(objects, true);
    demo.params.set(ParamId::Gravity, 0.0);
    demo.params.set(ParamId::SunAzimuth, 90.0);
    demo.params.set(ParamId::SunElevation, 50.0);
    demo.camera_mut().yaw = 0.0;
    demo.camera_mut().pitch = 80.0;
    demo.camera_mut().distance = 3.2;
    place(&mut demo);
    let frame = common::render(&mut demo, w, h, 2, 1.0 / 60.0);
    (demo, frame)
}

/// Counts duck-yellow pixels in a square around pixel `p`.
fn yellow_pixels(frame: &common::Image, p: Vec2, half: u32) -> u32 {
    let mut count = 0;
    for y in (p.y as u32).saturating_sub(half)..(p.y as u32 + half).min(frame.height) {
        for x in (p.x as u32).saturating_sub(half)..(p.x as u32 + half).min(frame.width) {
            let [r, g, b] = frame.unit_rgb(x, y);
            if r > 0.7 && g > 0.45 && b < 0.35 && r - b > 0.5 {
                count += 1;
            }
        }
    }
    count
}

#[test]
fn a_frame_shows_the_duck_and_its_shadow_on_the_floor() {
    let (w, h) = (320u32, 240u32);
    let shot = |objects: f32| {
        top_view(objects, w, h, |demo| {
            let y = duck::shape(demo.params.get(ParamId::DuckDensity)).floating_height(0.0);
            demo.set_body_pose(BodyId::named("duck").unwrap(), Pose::at(Vec3::new(0.25, y, 0.0)));
        })
    };
    let (demo, with) = shot(DUCK);
    let (_, without) = shot(NONE);
    let size = Vec2::new(w as f32, h as f32);
    let duck_px = demo.camera().project(demo.duck().unwrap().position, size).unwrap();
    // Where sunlight through the duck's waterline meets the floor.
    let sun = demo.sun();
    let r = wavepool::world::refracted_sun(sun);
    let waterline = Vec3::new(0.25, 0.0, 0.0);
    let floor = waterline + r * (-wavepool::world::PoolShape::CLASSIC.depth / r.y);
    let shadow_px = demo.camera().project(floor, size).unwrap();
    let (yellow_with, yellow_without) = (yellow_pixels(&with, duck_px, 14), yellow_pixels(&without, duck_px, 14));
    let rect = common::Area::around(shadow_px.x, shadow_px.y, &with, 0.015);
    let (shadow, lit) = (with.luma_stats(rect).0, without.luma_stats(rect).0);
    println!(
        "duck at pixel {duck_px}: {yellow_with} yellow pixels (none: {yellow_without}); floor at {floor} (pixel \
         {shadow_px}): luma {shadow:.3} with the duck, {lit:.3} without"
    );
    assert!(yellow_with > 200 && yellow_without == 0, "duck not seen: {yellow_with} / {yellow_without}");
    assert!(shadow < 0.75 * lit, "no shadow on the floor: {shadow} vs {lit}");
}

/// The duck's vinyl has a glossy coat: seen from low over the water, the upper side of the
/// duck, where the coat's Fresnel reflectance climbs, mirrors the blue-white sky, so part of
/// its warm pixels carry blue that its diffuse yellow (blue albedo 0.03) cannot give.
#[test]
fn the_ducks_coat_mirrors_the_sky_where_it_is_seen_at_a_grazing_angle() {
    let (w, h) = (320u32, 240u32);
    let mut demo = demo_with(DUCK, true);
    demo.params.set(ParamId::Gravity, 0.0);
    let y = duck::shape(demo.params.get(ParamId::DuckDensity)).floating_height(0.0);
    demo.set_body_pose(BodyId::named("duck").unwrap(), Pose::at(Vec3::new(0.0, y, 0.0)));
    demo.camera_mut().yaw = 90.0;
    demo.camera_mut().pitch = 12.0;
    demo.camera_mut().distance = 1.5;
    let frame = common::render(&mut demo, w, h, 2, 1.0 / 60.0);
    let size = Vec2::new(w as f32, h as f32);
    let centre = demo.camera().project(demo.duck().unwrap().position, size).unwrap();
    // The duck's pixels: warm (red well over blue), in a box around it.
    let (mut warm, mut sky_lit) = (0u32, 0u32);
    for y in (centre.y as u32).saturating_sub(60)..(centre.y as u32 + 30).min(h) {
        for x in (centre.x as u32).saturating_sub(70)..(centre.x as u32 + 70).min(w) {
            let [r, g, b] = frame.unit_rgb(x, y);
            if r > 0.35 && r > g && r - b > 0.15 {
                warm += 1;
                if b > 0.3 * r {
                    sky_lit += 1;
                }
            }
        }
    }
    let share = sky_lit as f64 / warm.max(1) as f64;
    println!(
        "duck at pixel {centre}: {warm} warm pixels, {sky_lit} of them ({:.1} %) with blue over 0.3 of red",
        share * 100.0
    );
    assert!(warm > 800, "duck not seen: {warm} warm pixels");
    assert!(share > 0.08, "the coat mirrors no sky: {:.1} % of the duck's pixels", share * 100.0);
}

/// Above the water, a floating body's side that faces down is lit by the water under it, not
/// by the sky: with the sun overhead (no sunlight there) the dry band of a high-floating sphere
/// below its equator, seen from low over the water, takes the colour of the floor's light
/// coming back up through the water, whose depth absorbs the red (red / blue 0.24 against 0.52
/// lit by the sky's light, 2026-11-30).
#[test]
fn a_floating_spheres_side_facing_the_water_is_lit_by_the_water_not_the_sky() {
    let (w, h) = (320u32, 240u32);
    let mut demo = demo_with(SPHERE, true);
    demo.params.set(ParamId::Gravity, 0.0);
    demo.params.set(ParamId::SunElevation, 90.0);
    demo.params.set(ParamId::SphereRadius, 0.25);
    let centre = Vec3::new(0.0, 0.2, 0.0);
    demo.set_sphere_centre(centre);
    demo.camera_mut().yaw = 0.0;
    demo.camera_mut().pitch = 6.0;
    demo.camera_mut().distance = 1.6;
    let frame = common::render(&mut demo, w, h, 2, 1.0 / 60.0);
    let size = Vec2::new(w as f32, h as f32);
    // Points on the sphere facing the eye sideways: the band between the water and the equator
    // (normals 15-35° down) and, for scale, the band 15-35° up, which the sky lights.
    let eye = demo.camera().eye();
    let toward = Vec3::new(eye.x - centre.x, 0.0, eye.z - centre.z).normalize();
    let side = Vec3::Y.cross(toward);
    let band = |from: f32, to: f32| {
        let mut rgb = [0.0f64; 3];
        let mut n = 0;
        for i in 0..=8 {
            for j in 0..=6 {
                let tilt = (from + (to - from) * i as f32 / 8.0).to_radians();
                let turn = (-30.0 + 10.0 * j as f32).to_radians();
                let normal = (toward * turn.cos() + side * turn.sin()) * tilt.cos() + Vec3::Y * tilt.sin();
                let point = centre + normal * 0.25;
                if let Some(px) = demo.camera().project(point, size) {
                    let c = frame.unit_rgb(px.x.round() as u32, px.y.round() as u32);
                    (0..3).for_each(|k| rgb[k] += c[k] as f64);
                    n += 1;
                }
            }
        }
        rgb.map(|v| v / n.max(1) as f64)
    };
    let (below, above) = (band(-35.0, -15.0), band(15.0, 35.0));
    let red_to_blue = below[0] / below[2].max(1.0e-3);
    println!(
        "sphere's band facing the water: rgb {:.3} {:.3} {:.3} (red / blue {red_to_blue:.3}); facing the sky: \
         rgb {:.3} {:.3} {:.3}",
        below[0], below[1], below[2], above[0], above[1], above[2]
    );
    assert!(above[2] > 0.3, "the sphere is not seen: {above:?}");
    // The side facing the sky stays near white (0.85 on 2026-11-30).
    assert!(above[0] / above[2] > 0.7, "the side facing the sky is lit as by the water: {above:?}");
    assert!(red_to_blue < 0.37, "the side facing the water is lit as by the sky: red / blue {red_to_blue:.3}");
}

/// The third kind of body, added as one entry of the table of kinds: dropped in, the beach
/// ball pushes the water, comes to rest high at its own waterline, and is drawn in its red and
/// orange gores, their seams blended, with a shadow on the floor that its thin vinyl lightens.
#[test]
fn a_dropped_beach_ball_pushes_water_floats_high_and_is_drawn_with_its_shadow() {
    let ball = BodyId::named("ball").expect("the ball is a kind of body");
    let mut demo = demo_with(BALL, true);
    demo.params.set(ParamId::Gravity, 1.0);
    demo.set_body_pose(ball, Pose::at(Vec3::new(-0.2, 0.25, 0.1)));
    let mut rough = 0.0f32;
    run(&mut demo, 8 * 60, |demo, k| {
        if k == 60 {
            rough = heights(demo).iter().fold(0.0, |a, h| a.max(h.abs()));
        }
    });
    let (radius, density) =
        (demo.params.get_by_name("ball_radius").unwrap(), demo.params.get_by_name("ball_density").unwrap());
    let hull = [Ellipsoid { centre: Vec3::ZERO, radii: Vec3::splat(radius) }];
    let level = demo.submerged_volume() / pool_area(1.0);
    let expected = Shape { hull: &hull, centre_of_mass: Vec3::ZERO, density, scale: 1.0 }.floating_height(level);
    let y = demo.body(ball).pose.position.y;
    println!(
        "ball: waves up to {:.1} mm a second after it fell in; rests at {y:.4} m (floating line {expected:.4} m)",
        rough * 1e3
    );
    assert!(rough > 2e-3, "the ball did not push the water: {rough} m");
    assert!((y - expected).abs() < 0.015, "floats at {y} m, expected {expected} m");
    assert!(y > 0.4 * radius, "a beach ball floats high, its centre {y} m above the water");

    let (w, h) = (320u32, 240u32);
    let shot = |objects: f32, blends: bool| {
        top_view(objects, w, h, |demo| {
            demo.set_body_pose(ball, Pose::at(Vec3::new(0.2, y, 0.0)));
            demo.set_body_outlines(blends);
        })
    };
    let (demo, with) = shot(BALL, true);
    let (_, without) = shot(NONE, true);
    let (_, stepped) = shot(BALL, false);
    let size = Vec2::new(w as f32, h as f32);
    let ball_px = demo.camera().project(demo.body(ball).pose.position, size).unwrap();
    let gores = |frame: &common::Image| {
        let rect = common::Area::around(ball_px.x, ball_px.y, frame, 0.08);
        rect.pixels(frame)
            .into_iter()
            .filter(|&(x, y)| {
                let [r, g, b] = frame.unit_rgb(x, y);
                // The red and orange gores (water and tiles are never this warm).
                r > 0.55 && b < 0.3 && r - b > 0.4 && r > g
            })
            .count()
    };
    let r = wavepool::world::refracted_sun(demo.sun());
    let floor = Vec3::new(0.2, 0.0, 0.0) + r * (-wavepool::world::PoolShape::CLASSIC.depth / r.y);
    let shadow_px = demo.camera().project(floor, size).unwrap();
    let rect = common::Area::around(shadow_px.x, shadow_px.y, &with, 0.015);
    let (shadow, lit) = (with.luma_stats(rect).0, without.luma_stats(rect).0);
    let (seen, unseen) = (gores(&with), gores(&without));
    // The seams between its gores, blended by the share of each pixel on either side: pixels
    // well inside its outline that the blend changes, each to a luma between its neighbours'.
    let edge = demo.camera().project(demo.body(ball).pose.position + Vec3::X * radius, size).unwrap();
    let inner = 0.85 * ball_px.distance(edge);
    let blended = with.blended_against(&stepped);
    let on_seams: Vec<_> =
        blended.iter().filter(|b| Vec2::new(b.x as f32 + 0.5, b.y as f32 + 0.5).distance(ball_px) < inner).collect();
    let between = on_seams.iter().filter(|b| b.between).count();
    println!(
        "ball at pixel {ball_px}: {seen} red or orange pixels (none: {unseen}); floor luma {shadow:.3} with it, {lit:.3} \
         without; {} pixels of its seams blended, {between} of them between their neighbours",
        on_seams.len()
    );
    assert!(seen > 60 && unseen == 0, "ball not seen: {seen} / {unseen}");
    assert!(shadow < 0.8 * lit, "no shadow on the floor: {shadow} vs {lit}");
    assert!(shadow > 0.45 * lit, "the ball's thin vinyl lets no light through: {shadow} vs {lit}");
    assert!(on_seams.len() >= 40, "the seams between the gores are not blended: {} pixels", on_seams.len());
    assert!(between * 20 >= on_seams.len() * 19, "the seams' blend is not between their two colours");
}

#[test]
fn the_bodies_float_on_current_heights_without_waiting_on_the_gpu() {
    // (That the frame path never blocks on the GPU is a lint: clippy.toml's disallowed methods.)
    // The heights are there every frame, those of the water the frame starts from (sampled on
    // the CPU's copy at the end of the frame before), and follow the water: a duck on a wave
    // rides it.
    let mut demo = demo_with(DUCK, true);
    demo.params.set(ParamId::Gravity, 1.0);
    let mut latencies = Vec::new();
    let mut heights = Vec::new();
    run(&mut demo, 120, |demo, k| {
        if k == 60 {
            demo.add_drop(0.35, -0.3, 0.25, 0.04);
        }
        latencies.extend(demo.probe_latency());
        heights.push(demo.body(BodyId::named("duck").unwrap()).pose.position.y);
    });
    let spread =
        |h: &[f32]| h.iter().fold(f32::NEG_INFINITY, |a, &b| a.max(b)) - h.iter().fold(f32::INFINITY, |a, &b| a.min(b));
    let (calm, wave) = (spread(&heights[40..60]), spread(&heights[60..]));
    println!(
        "probe latency per frame: {latencies:?}; duck bobbing {:.2} mm calm, {:.1} mm on the wave",
        calm * 1e3,
        wave * 1e3
    );
    assert!(latencies.len() >= 115, "heights arrived in only {} of 120 frames", latencies.len());
    assert!(latencies.iter().all(|&l| l == 1), "latencies {latencies:?}");
    assert!(wave > 5e-3 && wave > 10.0 * calm, "the duck did not ride the wave: {wave} m vs {calm} m calm");
}

/// Grid-scale ripples (a cell's height against the mean of its four neighbours) as a share of
/// all the waves (heights off their mean), RMS over the cells within `radius` (m) of `centre`.
fn grid_scale_share(h: &[f32], n: usize, half_width: f32, centre: Vec2, radius: f32) -> f64 {
    let at = |i: usize, j: usize| h[j * n + i] as f64;
    let cell = |i: usize| ((i as f32 + 0.5) / n as f32 * 2.0 - 1.0) * half_width;
    let cells: Vec<(usize, usize)> = (1..n - 1)
        .flat_map(|j| (1..n - 1).map(move |i| (i, j)))
        .filter(|&(i, j)| Vec2::new(cell(i), cell(j)).distance(centre) < radius)
        .collect();
    let mean = cells.iter().map(|&(i, j)| at(i, j)).sum::<f64>() / cells.len() as f64;
    let (mut rough, mut all) = (0.0, 0.0);
    for &(i, j) in &cells {
        let around = (at(i - 1, j) + at(i + 1, j) + at(i, j - 1) + at(i, j + 1)) / 4.0;
        rough += (at(i, j) - around).powi(2);
        all += (at(i, j) - mean).powi(2);
    }
    (rough / all.max(1e-30)).sqrt()
}

#[test]
fn the_water_round_a_bobbing_duck_has_no_ripples_at_the_grids_own_scale() {
    // The default pool: the sphere settling sends its rings under the duck, which bobs.
    let mut demo = common::demo(DemoOptions::default());
    run(&mut demo, 30, |_, _| {});
    let h = heights(&demo);
    let n = demo.water().size() as usize;
    let duck = demo.body(BodyId::named("duck").unwrap()).pose.position;
    let share = grid_scale_share(&h, n, wavepool::world::PoolShape::CLASSIC.half_width, Vec2::new(duck.x, duck.z), 0.3);
    println!("within 0.3 m of the duck ({n}² cells): grid-scale ripples {:.1} % of the waves (RMS)", share * 100.0);
    // Pushes taken at the cells' centres (before 2026-11-27, 7abb3de) left 4.6 %: the duck's waterline
    // crossing a cell at once rang at the grid's own scale, dark specks round it on screen.
    assert!(share < 0.03, "grid-scale ripples {:.1} % of the waves", share * 100.0);
}

/// The sphere's shadow on the floor is a contact shadow: sharp where the sphere nearly touches
/// the floor, soft when it floats a metre above it (its penumbra grows with the distance, as
/// the sun's disk and the ripples spread the light). Read off the caustics map (the debug
/// view: the floor's light, no water in front), along the row through the shadow with the sun
/// from the side: the edges' widths from 10 % to 90 % of the lit floor's light.
#[test]
fn a_spheres_shadow_is_sharp_where_it_nearly_touches_the_floor_and_soft_when_it_floats() {
    let (w, h) = (320, 240);
    let radius = 0.25;
    let edge_width = |centre_y: f32| {
        let mut demo = demo_with(SPHERE, true);
        demo.params.set(ParamId::SphereRadius, radius);
        demo.params.set(ParamId::Gravity, 0.0);
        demo.params.set(ParamId::SunAzimuth, 90.0);
        demo.params.set(ParamId::SunElevation, 60.0);
        demo.params.set(ParamId::DebugView, 4.0);
        demo.params.set(ParamId::DebugInset, 0.0);
        demo.set_sphere_centre(Vec3::new(0.0, centre_y, 0.0));
        let frame = common::render(&mut demo, w, h, 2, 1.0 / 60.0);
        // The sun has no z: the shadow's middle is the map's middle row. The map is the frame's
        // middle square (the deck round it), its edge a few pixels in from the pool's rim.
        let row: Vec<f64> = ((w - h) / 2 + 8..(w + h) / 2 - 8).map(|x| frame.luma(x, h / 2)).collect();
        let mut sorted = row.clone();
        sorted.sort_unstable_by(f64::total_cmp);
        let lit = sorted[sorted.len() * 3 / 4];
        let darkest = (0..row.len()).min_by(|&a, &b| row[a].total_cmp(&row[b])).unwrap();
        let crossing = |step: isize, level: f64| {
            let mut x = darkest as isize;
            while x > 0 && x < row.len() as isize - 1 && row[x as usize] < level * lit {
                x += step;
            }
            x
        };
        let left = (crossing(-1, 0.9) - crossing(-1, 0.1)).abs();
        let right = (crossing(1, 0.9) - crossing(1, 0.1)).abs();
        println!("sphere centre at y = {centre_y} m: shadow edges {left} and {right} px wide (lit luma {lit:.0})");
        (left + right) as f32 / 2.0
    };
    let touching = edge_width(-1.0 + radius + 0.01);
    let floating = edge_width(0.0);
    assert!(touching >= 1.0, "no shadow edge found under the sphere on the floor");
    assert!(
        floating > 1.6 * touching,
        "the floating sphere's shadow is not softer: {floating} px against {touching} px"
    );
}

/// The duck's shadow on the floor is sharp where the duck sits on the floor and soft when it
/// floats about 0.9 m above it (each part's penumbra grows with the distance to the point it
/// shades, as the sphere's does). Read off the caustics map (the debug view: the floor's light,
/// no water in front) along the row through the shadow, the sun from the side, divided by the
/// same row without the duck (the walls' shadow left out): the edges' widths from 10 % to 90 %
/// of the light the duck takes away.
#[test]
fn the_ducks_shadow_is_sharp_where_it_sits_on_the_floor_and_soft_when_it_floats() {
    let (w, h) = (320, 240);
    let row_of = |objects: f32, y: f32| {
        let mut demo = demo_with(objects, true);
        demo.params.set(ParamId::Gravity, 0.0);
        demo.params.set(ParamId::SunAzimuth, 90.0);
        demo.params.set(ParamId::SunElevation, 60.0);
        demo.params.set(ParamId::DebugView, 4.0);
        demo.params.set(ParamId::DebugInset, 0.0);
        let id = BodyId::named("duck").expect("the duck is a kind");
        demo.set_body_pose(id, Pose::at(Vec3::new(0.0, y, 0.0)));
        let frame = common::render(&mut demo, w, h, 2, 1.0 / 60.0);
        let row: Vec<f64> = ((w - h) / 2 + 8..(w + h) / 2 - 8).map(|x| frame.luma(x, h / 2)).collect();
        (row, demo.duck().map(|p| p.position.y))
    };
    let (bare, _) = row_of(NONE, 0.0);
    let edge_width = |y: f32| {
        let (row, at) = row_of(DUCK, y);
        // The share of the floor's light the duck leaves, where the floor is lit without it.
        let share: Vec<f64> = row.iter().zip(&bare).map(|(l, b)| if *b > 10.0 { l / b } else { 1.0 }).collect();
        let darkest = (0..share.len()).min_by(|&a, &b| share[a].total_cmp(&share[b])).unwrap();
        let least = share[darkest];
        let crossing = |step: isize, level: f64| {
            let mut x = darkest as isize;
            while x > 0 && x < share.len() as isize - 1 && share[x as usize] < least + level * (1.0 - least) {
                x += step;
            }
            x
        };
        let left = (crossing(-1, 0.9) - crossing(-1, 0.1)).abs();
        let right = (crossing(1, 0.9) - crossing(1, 0.1)).abs();
        println!(
            "duck at y = {:.2} m: its shadow {:.0} % deep, edges {left} and {right} px wide",
            at.expect("the duck is in the pool"),
            100.0 * (1.0 - least)
        );
        assert!(least < 0.5, "no shadow under the duck at y = {y}: {least}");
        (left + right) as f32 / 2.0
    };
    let sitting = edge_width(-0.9);
    let floating = edge_width(0.0);
    assert!(sitting >= 1.0, "no shadow edge found under the duck on the floor");
    assert!(floating > 1.6 * sitting, "the floating duck's shadow is not softer: {floating} px against {sitting} px");
}
