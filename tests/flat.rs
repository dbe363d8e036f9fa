//! Flat water, the games' technique, beside the ray tracer (lavapipe in CI): a split frame is
//! the flat frame left of the divider and the ray-traced one right of it; the reflection is
//! drawn by the mirrored camera and holds nothing from under the water; the dUdV distortion
//! moves with simulated time only; the `ripples` distortion follows a click; the divider
//! drags; under water the ray tracer draws.
// Tests read results back and wait for the GPU (clippy.toml: not in the frame path).
#![allow(clippy::disallowed_methods)]

mod common;

use common::{render, Area, Image};
use glam::{Vec2, Vec3};
use wavepool::demo::{DemoOptions, WaterDemo};
use wavepool::params::ParamId;
use wavepool::sim::random_drops;

const W: u32 = 320;
const H: u32 = 240;

/// A pool with `objects` (0 none, 1 sphere, 3 both), full resolution, bodies held still.
fn pool(objects: f32) -> WaterDemo {
    let mut demo = common::demo(DemoOptions::default());
    // The cut-away box: these tests look from low and from under the water, which the deck's
    // coping would hide or the camera's limit above the paving would not allow.
    demo.params.set(ParamId::Setting, 1.0);
    demo.params.set(ParamId::Objects, objects);
    demo.params.set(ParamId::Quality, 1.0);
    demo.params.set(ParamId::Gravity, 0.0);
    demo
}

/// Flat water, undistorted and still, at full texture resolution, seen from low (20°) under a
/// high sun (85°, so the sphere's shadow falls under it), with a ball of radius 0.15 m at
/// `centre` (m).
fn sphere_over_flat_water(centre: Vec3) -> WaterDemo {
    let mut demo = pool(1.0);
    demo.params.set(ParamId::Paused, 1.0);
    demo.params.set(ParamId::SunElevation, 85.0);
    demo.params.set(ParamId::RenderMode, 1.0);
    demo.params.set(ParamId::FlatStrength, 0.0);
    demo.params.set(ParamId::FlatResolution, 1.0);
    demo.params.set(ParamId::SphereRadius, 0.15);
    demo.camera_mut().pitch = 20.0;
    demo.camera_mut().distance = 4.2;
    demo.set_sphere_centre(centre);
    demo
}

/// The flat water's reflection texture as a frame.
fn reflection(demo: &WaterDemo) -> Image {
    let g = common::gpu();
    let texture = demo.flat_reflection_texture().expect("flat water was drawn");
    Image {
        width: texture.width(),
        height: texture.height(),
        rgba: wavepool::gpu::read_texture(&g.device, &g.queue, texture),
    }
}

/// Centroid (pixels) of the pixels where two frames differ by more than `threshold`.
fn changed_centroid(a: &Image, b: &Image, threshold: u8) -> Option<Vec2> {
    let (mut sum, mut count) = (Vec2::ZERO, 0.0);
    for (x, y) in Area::ALL.pixels(a) {
        let i = ((y * a.width + x) * 4) as usize;
        if (0..3).any(|k| a.rgba[i + k].abs_diff(b.rgba[i + k]) > threshold) {
            sum += Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            count += 1.0;
        }
    }
    (count > 0.0).then(|| sum / count)
}

#[test]
fn split_at_half_equals_flat_on_the_left_and_raytraced_on_the_right() {
    // Flat from the start, so that nothing a ray-traced frame leaves behind (its caustics
    // map) can make the flat frame, and again after the others: a frame owes nothing to the
    // modes drawn before it.
    let mut demo = pool(3.0);
    demo.params.set(ParamId::RenderMode, 1.0);
    for d in random_drops(7, 6, 0.9, 0.05, 0.02) {
        demo.add_drop(d.x, d.z, d.radius, d.strength);
    }
    render(&mut demo, W, H, 20, 1.0 / 60.0);
    demo.params.set(ParamId::Paused, 1.0);
    let mut frame = |mode: f32| {
        demo.params.set(ParamId::RenderMode, mode);
        render(&mut demo, W, H, 1, 1.0 / 60.0)
    };
    let (flat, split, traced, flat_again) = (frame(1.0), frame(2.0), frame(0.0), frame(1.0));
    let history = flat_again.changed_fraction(&flat, Area::ALL, 0);
    // The divider is drawn over column W/2 (and its grip 5 px either side).
    let (left, right) = (Area(0.0, 0.0, 0.48, 1.0), Area(0.52, 0.0, 1.0, 1.0));
    let (left_diff, right_diff) = (split.changed_fraction(&flat, left, 0), split.changed_fraction(&traced, right, 0));
    let modes_differ = flat.changed_fraction(&traced, Area::ALL, 8);
    println!(
        "split vs flat on the left: {:.4} % of pixels differ; vs ray-traced on the right: {:.4} %; flat vs ray-traced \
         anywhere: {:.1} %; flat after the other modes vs flat from the start: {:.4} %",
        left_diff * 100.0,
        right_diff * 100.0,
        modes_differ * 100.0,
        history * 100.0
    );
    assert_eq!(history, 0.0, "the flat frame depends on the modes drawn before it");
    assert_eq!(left_diff, 0.0, "the split frame's left half is not the flat frame");
    assert_eq!(right_diff, 0.0, "the split frame's right half is not the ray-traced frame");
    assert!(modes_differ > 0.05, "flat and ray-traced water look alike ({:.1} %)", modes_differ * 100.0);
    // The divider is there: a bright line down the middle.
    let line = split.mean_colour(Area(0.5 - 1.0 / W as f32, 0.0, 0.5 + 1.0 / W as f32, 1.0));
    assert!(line.iter().all(|&c| c > 0.85), "no divider at the middle: {line:?}");
}

#[test]
fn the_sphere_above_the_water_appears_where_the_mirrored_camera_puts_it() {
    let setup = |height: f32| sphere_over_flat_water(Vec3::new(0.1, height, -0.1));
    let mut above = setup(0.35);
    let frame = render(&mut above, W, H, 2, 1.0 / 60.0);
    let mirror_above = reflection(&above);
    let mut higher = setup(0.45);
    let frame_higher = render(&mut higher, W, H, 2, 1.0 / 60.0);
    let mirror_higher = reflection(&higher);
    // The sphere's mirror image through the mirrored camera: the centre mirrored in the
    // plane (y = 0: the sphere is out of the water and raises no level).
    let size = Vec2::new(W as f32, H as f32);
    let predicted = |y: f32| above.camera().project(Vec3::new(0.1, -y, -0.1), size).expect("in front");
    // In the reflection texture: where the two spheres differ, the mirror images are, and
    // the lower sphere's image lies nearer the water line (above the higher one's on screen).
    let centroid = changed_centroid(&mirror_above, &mirror_higher, 16).expect("the reflection changed");
    let (p35, p45) = (predicted(0.35), predicted(0.45));
    let between = (p35 + p45) / 2.0;
    println!(
        "mirror images predicted at {p35:.1} (0.35 m) and {p45:.1} (0.45 m); the reflection texture changed around \
         {centroid:.1}"
    );
    let margin = 0.02 * H as f32;
    assert!(
        (centroid.x - between.x).abs() < margin
            && centroid.y > p35.y.min(p45.y) - margin
            && centroid.y < p35.y.max(p45.y) + margin,
        "the reflection's change at {centroid:.1} is not at the mirror images ({p35:.1}, {p45:.1})"
    );
    // In the frame: at the predicted pixel of the image the water shows the sphere (it differs
    // from the frame without one), a sphere's width away to the side it shows the sky.
    let mut empty = setup(0.35);
    empty.params.set(ParamId::Objects, 0.0);
    let without = render(&mut empty, W, H, 2, 1.0 / 60.0);
    // A faint change (over 2/255): at this grazing angle the pale sphere's image is blended in by
    // a reflectance of about 0.1 over the bright horizon it hides.
    let at_image = frame.changed_fraction(&without, Area::around(p35.x, p35.y, &frame, 0.01), 2);
    let beside = frame.changed_fraction(&without, Area::around(p35.x + 0.12 * W as f32, p35.y, &frame, 0.01), 8);
    let moved = frame.changed_fraction(&frame_higher, Area::around(p45.x, p45.y, &frame, 0.01), 8);
    println!(
        "at the predicted image {:.0} % of pixels differ from the empty pool, beside it {:.0} %; the higher sphere's \
         image changes {:.0} % at its own predicted pixel",
        at_image * 100.0,
        beside * 100.0,
        moved * 100.0
    );
    assert!(at_image > 0.9, "the mirror image is not at the predicted pixel ({:.0} %)", at_image * 100.0);
    assert!(beside < 0.1, "the water beside the image changed too ({:.0} %)", beside * 100.0);
}

#[test]
fn geometry_under_the_water_never_appears_in_the_reflection() {
    let setup = |y: f32| {
        let mut demo = sphere_over_flat_water(Vec3::new(0.0, y, 0.0));
        render(&mut demo, W, H, 2, 1.0 / 60.0);
        reflection(&demo)
    };
    // Two places under the water (the same volume, so the same plane): the reflection does not
    // change; two places above it: it does.
    let (deep, deeper) = (setup(-0.5), setup(-0.65));
    let (high, higher) = (setup(0.35), setup(0.5));
    let under = deep.changed_fraction(&deeper, Area::ALL, 3);
    let over = high.changed_fraction(&higher, Area::ALL, 3);
    println!(
        "moving the sphere 15 cm under the water changes {:.4} % of the reflection texture; above it {:.2} %",
        under * 100.0,
        over * 100.0
    );
    assert_eq!(under, 0.0, "the reflection shows something under the water");
    assert!(over > 0.003, "the reflection does not show the sphere above the water ({:.3} %)", over * 100.0);
}

#[test]
fn dudv_distortion_moves_on_calm_water_and_stops_when_paused() {
    let mut demo = pool(0.0);
    demo.params.set(ParamId::RenderMode, 1.0);
    demo.params.set(ParamId::DudvSpeed, 0.05);
    let water = Area(0.25, 0.3, 0.75, 0.8);
    let a = render(&mut demo, W, H, 10, 1.0 / 60.0);
    let b = render(&mut demo, W, H, 30, 1.0 / 60.0);
    let level = demo.water_level().map_or(0.0, |l| l.max_abs);
    demo.params.set(ParamId::Paused, 1.0);
    let c = render(&mut demo, W, H, 1, 1.0 / 60.0);
    let d = render(&mut demo, W, H, 30, 1.0 / 60.0);
    // Running, with the map not scrolling: nothing moves.
    demo.params.set(ParamId::Paused, 0.0);
    demo.params.set(ParamId::DudvSpeed, 0.0);
    let e = render(&mut demo, W, H, 1, 1.0 / 60.0);
    let f = render(&mut demo, W, H, 30, 1.0 / 60.0);
    let (running, paused, still) =
        (a.changed_fraction(&b, water, 4), c.changed_fraction(&d, water, 0), e.changed_fraction(&f, water, 0));
    println!(
        "calm water (largest |h| {level:.2e} m): 0.5 s apart {:.1} % of the water's pixels changed; paused for 30 \
         frames {:.4} %; running with the map not scrolling {:.4} %",
        running * 100.0,
        paused * 100.0,
        still * 100.0
    );
    assert!(level < 1e-6, "the water is not calm");
    assert!(running > 0.05, "the dUdV distortion does not move ({:.2} %)", running * 100.0);
    assert_eq!(paused, 0.0, "the distortion moves while paused");
    assert_eq!(still, 0.0, "calm flat water with a still map changes");
}

#[test]
fn ripples_distortion_follows_a_click() {
    let mut demo = pool(0.0);
    demo.params.set(ParamId::RenderMode, 1.0);
    demo.params.set(ParamId::FlatDistortion, 1.0);
    // The distortion alone (fake caustics move with the ripples too, 0.7 m away where the
    // sunbeams through them land), and a big drop.
    demo.params.set(ParamId::FlatCaustics, 0.0);
    demo.params.set(ParamId::FlatStrength, 0.04);
    demo.params.set(ParamId::DropRadius, 0.08);
    demo.params.set(ParamId::DropStrength, 0.03);
    let before = render(&mut demo, W, H, 5, 1.0 / 60.0);
    let calm = render(&mut demo, W, H, 5, 1.0 / 60.0);
    let size = Vec2::new(W as f32, H as f32);
    let click = demo.camera().project(Vec3::new(0.3, 0.0, 0.4), size).expect("in view");
    let far = demo.camera().project(Vec3::new(-0.5, 0.0, -0.4), size).expect("in view");
    demo.pointer_down(click.x, click.y);
    demo.pointer_up();
    let after = render(&mut demo, W, H, 20, 1.0 / 60.0);
    let (still, near, away) = (
        before.changed_fraction(&calm, Area::ALL, 0),
        after.changed_fraction(&calm, Area::around(click.x, click.y, &after, 0.05), 8),
        after.changed_fraction(&calm, Area::around(far.x, far.y, &after, 0.05), 8),
    );
    println!(
        "calm: {:.4} % changed; 1/3 s after a click {:.1} % changed around it, {:.2} % across the pool",
        still * 100.0,
        near * 100.0,
        away * 100.0
    );
    assert_eq!(still, 0.0, "calm water with ripple distortion moves");
    assert!(near > 0.05, "the ripples do not distort the flat water ({:.1} %)", near * 100.0);
    assert!(away < 0.002, "the distortion is not where the ripples are ({:.2} %)", away * 100.0);
}

#[test]
fn the_divider_drags_from_the_pointer_and_a_press_beside_it_still_orbits() {
    let mut demo = pool(0.0);
    demo.params.set(ParamId::RenderMode, 2.0);
    render(&mut demo, W, H, 1, 1.0 / 60.0);
    let yaw = demo.camera().yaw;
    let (w, h) = (W as f32, H as f32);
    demo.pointer_down(0.5 * w + 5.0, 0.5 * h);
    demo.pointer_move(0.6 * w, 0.5 * h);
    demo.pointer_move(0.7 * w, 0.4 * h);
    demo.pointer_up();
    let split = demo.params.get(ParamId::Split);
    let yaw_after_divider = demo.camera().yaw;
    // Out of reach of the divider (and above the water): the camera orbits.
    demo.pointer_down(0.2 * w, 0.05 * h);
    demo.pointer_move(0.3 * w, 0.05 * h);
    demo.pointer_up();
    println!(
        "divider dragged to {split:.3} (pointer at 0.700); yaw {yaw:.1} -> {yaw_after_divider:.1} -> {:.1}",
        demo.camera().yaw
    );
    assert!((split - 0.7).abs() < 0.01, "the divider is at {split}");
    assert_eq!(yaw_after_divider, yaw, "dragging the divider turned the camera");
    assert_ne!(demo.camera().yaw, yaw, "a press away from the divider does not orbit");
    // Only in the split view.
    demo.params.set(ParamId::RenderMode, 1.0);
    demo.pointer_down(0.7 * w, 0.05 * h);
    demo.pointer_move(0.9 * w, 0.05 * h);
    demo.pointer_up();
    assert_eq!(demo.params.get(ParamId::Split), split, "the divider moved without a split view");
}

#[test]
fn under_the_water_flat_mode_draws_the_ray_traced_picture_and_says_why() {
    let mut demo = pool(1.0);
    demo.params.set(ParamId::Paused, 1.0);
    demo.camera_mut().pitch = -30.0;
    let traced = render(&mut demo, W, H, 2, 1.0 / 60.0);
    assert!(demo.flat_water_note().is_none());
    demo.params.set(ParamId::RenderMode, 1.0);
    let flat = render(&mut demo, W, H, 1, 1.0 / 60.0);
    let note = demo.flat_water_note();
    let diff = flat.changed_fraction(&traced, Area::ALL, 0);
    println!("under water: flat vs ray-traced {:.4} % of pixels differ; note: {note:?}", diff * 100.0);
    assert_eq!(diff, 0.0);
    let text = note.and_then(wavepool::page_words::english);
    assert!(text.is_some_and(|n| n.contains("above-water")), "no note says why: {note:?}");
}
