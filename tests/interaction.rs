//! The core's platform-free input API, as the browser and native shells will drive it:
//! pointer on the water makes ripples, on the sphere moves it, elsewhere orbits; keys act.
// Tests read results back and wait for the GPU (clippy.toml: not in the frame path).
#![allow(clippy::disallowed_methods)]

mod common;

use glam::{Vec2, Vec3};
use wavepool::bodies::sphere;
use wavepool::camera::Pick;
use wavepool::demo::{BodyId, DemoOptions, Key};
use wavepool::params::ParamId;

const SIZE: (u32, u32) = (320, 240);

fn max_height(demo: &wavepool::WaterDemo) -> f32 {
    let g = common::gpu();
    demo.water().read_state(&g.device, &g.queue).iter().map(|c| c[0].abs()).fold(0.0, f32::max)
}

#[test]
fn dragging_on_the_water_makes_ripples_along_the_stroke() {
    let mut demo = common::demo(DemoOptions::default());
    demo.params.set(ParamId::Objects, 0.0);
    let _ = common::render(&mut demo, SIZE.0, SIZE.1, 1, 1.0 / 60.0);
    assert_eq!(max_height(&demo), 0.0, "water should start calm");
    let size = Vec2::new(SIZE.0 as f32, SIZE.1 as f32);
    let a = demo.camera().project(Vec3::new(-0.5, 0.0, 0.0), size).unwrap();
    let b = demo.camera().project(Vec3::new(0.5, 0.0, 0.0), size).unwrap();
    assert!(
        demo.pick_body(a).is_none()
            && matches!(demo.camera().pick_within(a, size, demo.drop_area().0), Pick::Water { .. })
    );
    let yaw = demo.camera().yaw;
    demo.pointer_down(a.x, a.y);
    demo.pointer_move(b.x, b.y);
    demo.pointer_up();
    let _ = common::render(&mut demo, SIZE.0, SIZE.1, 1, 1.0 / 60.0);
    assert_eq!(demo.camera().yaw, yaw, "a drag on the water must not orbit");
    let g = common::gpu();
    let state = demo.water().read_state(&g.device, &g.queue);
    let n = demo.water().size() as usize;
    // Along the stroke (z = 0) the water moved at several points between x = -0.5 and 0.5.
    let disturbed = (0..8)
        .map(|k| -0.45 + k as f32 * 0.9 / 7.0)
        .filter(|&x| {
            let i = (((x + 1.0) * 0.5) * n as f32) as usize;
            state[(n / 2) * n + i][0].abs() > 1e-3
        })
        .count();
    assert!(disturbed >= 6, "only {disturbed} of 8 points along the stroke were disturbed");
}

#[test]
fn dragging_the_sky_orbits_and_dragging_the_sphere_moves_it() {
    let mut demo = common::demo(DemoOptions::default());
    // The sphere alone, held still: the water is flat at the level its volume raises.
    demo.params.set(ParamId::Objects, 1.0);
    demo.params.set(ParamId::Gravity, 0.0);
    // Where a pool without gravity starts it, under the water (the demo was made with gravity).
    demo.set_sphere_centre(sphere::CLASSIC_START);
    let _ = common::render(&mut demo, SIZE.0, SIZE.1, 1, 1.0 / 60.0);
    let calm = max_height(&demo);
    let yaw = demo.camera().yaw;
    demo.pointer_down(2.0, 2.0);
    demo.pointer_move(60.0, 2.0);
    demo.pointer_up();
    assert!((demo.camera().yaw - yaw).abs() > 5.0, "dragging outside the pool should orbit");
    let _ = common::render(&mut demo, SIZE.0, SIZE.1, 1, 1.0 / 60.0);
    assert!((max_height(&demo) - calm).abs() < 1e-6, "orbiting must not touch the water");

    let size = Vec2::new(SIZE.0 as f32, SIZE.1 as f32);
    let sphere = demo.sphere().unwrap();
    let p = demo.camera().project(sphere.centre, size).unwrap();
    assert!(
        demo.pick_body(p).is_some_and(|(id, _)| id == BodyId::named("sphere").unwrap()),
        "the sphere is not under its own centre"
    );
    demo.pointer_down(p.x, p.y);
    demo.pointer_move(p.x + 40.0, p.y);
    demo.pointer_up();
    let moved = demo.sphere().unwrap().centre;
    assert!((moved - sphere.centre).length() > 0.1, "sphere did not follow the pointer: {moved:?}");
    assert!(
        demo.pick_body(Vec2::new(p.x + 40.0, p.y)).is_some_and(|(id, _)| id == BodyId::named("sphere").unwrap()),
        "the sphere should still be under the pointer after the drag"
    );
}

#[test]
fn keys_and_zoom() {
    let mut demo = common::demo(DemoOptions::default());
    demo.key(Key::Space);
    assert!(demo.params.flag(ParamId::Paused));
    demo.add_drop(0.0, 0.0, 0.05, 0.01);
    let _ = common::render(&mut demo, SIZE.0, SIZE.1, 10, 1.0 / 60.0);
    assert_eq!(demo.sim_time(), 0.0, "paused water must not advance");
    demo.key(Key::Space);
    let _ = common::render(&mut demo, SIZE.0, SIZE.1, 10, 1.0 / 60.0);
    assert!(
        (demo.sim_time() - 10.0 / 60.0).abs() < 1e-6,
        "resumed water advances by the frame time: {}",
        demo.sim_time()
    );

    demo.key(Key::L);
    let sun = demo.sun();
    assert!(sun.dot(demo.camera().back()) > 0.999, "L puts the sun behind the camera");

    demo.zoom(1.0e6);
    assert_eq!(demo.camera().distance, wavepool::camera::DISTANCE_RANGE.1);
    demo.zoom(f32::NAN);
    assert!(demo.camera().distance.is_finite());
}

/// The sim_size parameter switches the grid at run time (the next frame) and keeps the waves.
#[test]
fn the_sim_size_parameter_switches_resolution_without_a_reset() {
    switch_resolution(true);
}

/// The same on the CPU engine (no float render targets).
#[test]
fn the_sim_size_parameter_switches_resolution_on_the_cpu_engine() {
    switch_resolution(false);
}

fn switch_resolution(float_targets: bool) {
    let mut demo = common::demo(DemoOptions { sim_size: 128, float_targets, ..DemoOptions::default() });
    assert_eq!(demo.params.get(ParamId::SimSize), 128.0);
    demo.params.set(ParamId::Objects, 0.0);
    demo.add_drop(0.2, -0.1, 0.15, 0.02);
    let _ = common::render(&mut demo, SIZE.0, SIZE.1, 3, 1.0 / 60.0);
    let before = max_height(&demo);
    assert_eq!(demo.params.set(ParamId::SimSize, 500.0).value, 512.0, "snaps to the nearest choice");
    let _ = common::render(&mut demo, SIZE.0, SIZE.1, 1, 1.0 / 60.0);
    assert_eq!(demo.water().size(), 512);
    let after = max_height(&demo);
    println!("max |h| at 128: {before:e} m; one frame later at 512: {after:e} m");
    assert!(before > 1e-3 && after > 0.5 * before, "the water was reset: {before} -> {after}");
}
