//! Foam (lavapipe in CI): a hard drop breaks and foams where it fell and nowhere else, a ball
//! dropped into the pool splashes foam around it, both engines (the GPU engine's CPU copy
//! and the CPU engine) foam by the same code to the same amounts, and the surface shows it as
//! white, while with foam off nothing is integrated at all.

mod common;

use common::render;
use glam::Vec3;
use wavepool::demo::BodyId;
use wavepool::demo::{DemoOptions, WaterDemo};
use wavepool::params::ParamId;
use wavepool::physics::Pose;

const W: u32 = 240;
const H: u32 = 180;

fn pool(float_targets: bool, foam: bool) -> WaterDemo {
    let mut demo = common::demo(DemoOptions { sim_size: 128, float_targets, ..DemoOptions::default() });
    demo.params.set(ParamId::Objects, 0.0);
    demo.params.set(ParamId::Quality, 1.0);
    demo.params.set(ParamId::Foam, if foam { 1.0 } else { 0.0 });
    demo
}

/// Foam amount at pool point (x, z) (nearest cell).
fn foam_at(demo: &WaterDemo, x: f32, z: f32) -> f32 {
    let foam = demo.water().foam().expect("foam is on");
    let n = foam.size() as usize;
    let cell = |c: f32| (((c + 1.0) / 2.0 * n as f32) as usize).min(n - 1);
    foam.amount()[cell(z) * n + cell(x)]
}

#[test]
fn a_hard_drop_foams_where_it_fell_and_the_foam_fades() {
    let mut demo = pool(true, true);
    demo.add_drop(0.3, -0.2, 0.08, 0.04);
    render(&mut demo, W, H, 6, 1.0 / 60.0);
    let (at_drop, far) = (foam_at(&demo, 0.3, -0.2), foam_at(&demo, -0.7, 0.7));
    let early = demo.water().foam().unwrap().total();
    render(&mut demo, W, H, 180, 1.0 / 60.0);
    let late = demo.water().foam().unwrap().total();
    println!("foam 0.1 s after a hard drop: {at_drop:.3} where it fell, {far:.3} far away; total {early:.4} m², 3 s later {late:.4} m²");
    assert!(at_drop > 0.2 && far == 0.0, "foam {at_drop} at the drop, {far} far away");
    assert!(late < 0.5 * early, "the foam does not fade ({early} -> {late})");
}

#[test]
fn a_ball_dropped_into_the_pool_splashes_foam_around_it() {
    let mut demo = pool(true, true);
    demo.params.set(ParamId::Objects, 1.0);
    demo.params.set(ParamId::Gravity, 1.0);
    demo.set_body_pose(BodyId::named("sphere").unwrap(), Pose::at(Vec3::new(-0.2, 0.6, 0.1)));
    render(&mut demo, W, H, 45, 1.0 / 60.0);
    let near = (0..16)
        .map(|k| {
            let a = k as f32 / 16.0 * std::f32::consts::TAU;
            foam_at(&demo, -0.2 + 0.3 * a.cos(), 0.1 + 0.3 * a.sin())
        })
        .fold(0.0f32, f32::max);
    let far = foam_at(&demo, 0.8, -0.8);
    println!("after a ball fell in: foam up to {near:.3} around it, {far:.3} in a far corner");
    assert!(near > 0.1 && far < 0.01, "splash foam {near} near, {far} far");
}

#[test]
fn both_engines_foam_by_the_same_code_to_the_same_amounts() {
    let run = |float_targets: bool| {
        let mut demo = pool(float_targets, true);
        for (x, z, s) in [(0.3, -0.2, 0.04), (-0.5, 0.4, -0.035), (0.0, 0.9, 0.03)] {
            demo.add_drop(x, z, 0.08, s);
        }
        render(&mut demo, 64, 48, 40, 1.0 / 60.0);
        demo.water().foam().unwrap().amount().to_vec()
    };
    let (gpu, cpu) = (run(true), run(false));
    let largest = gpu.iter().zip(&cpu).map(|(a, b)| (a - b).abs()).fold(0.0f32, f32::max);
    let total: f32 = gpu.iter().sum();
    println!("foam of the GPU engine (its CPU copy) and of the CPU engine: {} cells, sum {total:.2}, largest difference {largest:e}", gpu.len());
    assert!(total > 1.0 && largest < 1e-5, "the engines foam differently ({largest})");
}

#[test]
fn foam_shows_white_on_the_surface_and_off_nothing_is_integrated() {
    let white = |foam: bool| {
        let mut demo = pool(true, foam);
        for (x, z) in [(0.0, 0.0), (0.5, 0.4), (-0.5, -0.3), (0.4, -0.5)] {
            demo.add_drop(x, z, 0.1, 0.045);
        }
        let (w, h) = (2 * W, 2 * H);
        let frame = render(&mut demo, w, h, 8, 1.0 / 60.0);
        let count = (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).filter(|&(x, y)| {
            let p = frame.unit_rgb(x, y);
            p[0] > 0.85 && p[1] > 0.85 && p[2] > 0.85
        });
        (count.count(), demo.water().foam().is_some())
    };
    let ((with, on), (without, off)) = (white(true), white(false));
    println!("white pixels after a hard drop: {with} with foam, {without} without; foam integrated: {on} / {off}");
    assert!(with > 2 * without + 100, "foam does not show ({with} vs {without})");
    assert!(on && !off, "foam integrated with it off");
}

/// With absorbing walls (no waves left to run up them), the foam of a strong drop falls below
/// 1 % of its peak within five time constants; a gentle ring foams nowhere it passes.
#[test]
fn foam_falls_below_one_percent_of_its_peak_after_five_time_constants_and_a_gentle_ring_makes_none() {
    let mut demo = pool(true, true);
    demo.params.set(ParamId::AbsorbingWalls, 1.0);
    demo.add_drop(0.0, 0.0, 0.08, 0.04);
    let mut peak = 0.0f64;
    for _ in 0..30 {
        render(&mut demo, 32, 24, 1, 1.0 / 60.0);
        peak = peak.max(demo.water().foam().unwrap().total());
    }
    render(&mut demo, 32, 24, 450, 1.0 / 60.0); // 7.5 s = 5 x 1.5 s
    let left = demo.water().foam().unwrap().total();
    let mut gentle = pool(true, true);
    gentle.add_drop(-0.6, -0.6, 0.04, 0.003);
    render(&mut gentle, 32, 24, 60, 1.0 / 60.0);
    let (passed, at_drop) = (foam_at(&gentle, 0.0, 0.0).max(foam_at(&gentle, -0.6, 0.2)), foam_at(&gentle, -0.6, -0.6));
    println!(
        "strong drop: peak {peak:.4} m², {left:.6} m² after 5 time constants ({:.3} %); a gentle ring: {passed} where it passed, {at_drop:.3} where it fell",
        left / peak * 100.0
    );
    assert!(left < 0.01 * peak, "foam {left} of a {peak} peak after 5 time constants");
    assert!(passed < 1e-4, "a gentle ring foamed where it passed ({passed})");
}

/// A ball dragged along the surface leaves a trail of foam behind it.
#[test]
fn a_sphere_dragged_through_the_surface_leaves_foam_behind_it() {
    let mut demo = pool(true, true);
    demo.params.set(ParamId::Objects, 1.0);
    demo.params.set(ParamId::Gravity, 0.0);
    for i in 0..=60 {
        let x = -0.6 + 1.2 * i as f32 / 60.0;
        demo.set_body_pose(BodyId::named("sphere").unwrap(), Pose::at(Vec3::new(x, 0.0, 0.0)));
        render(&mut demo, 32, 24, 1, 1.0 / 60.0);
    }
    let trail =
        [-0.3f32, 0.0, 0.3].map(|x| (-6..=6).map(|k| foam_at(&demo, x, k as f32 * 0.05)).fold(0.0f32, f32::max));
    let aside = foam_at(&demo, 0.0, -0.8);
    println!("after dragging the ball from x = -0.6 to 0.6: foam along its path {trail:?}, off it {aside}");
    assert!(trail.iter().all(|&f| f > 0.05) && aside < 0.01, "trail {trail:?}, aside {aside}");
}

/// Foam follows the fixed steps, not the frames: one second at 30, 60 and 144 frames/s
/// leaves the same foam (to float rounding, 1e-6).
#[test]
fn foam_is_the_same_at_30_60_and_144_frames_per_second() {
    let run = |fps: u32| {
        let mut demo = pool(true, true);
        demo.add_drop(0.2, 0.1, 0.08, 0.04);
        render(&mut demo, 32, 24, fps, 1.0 / fps as f32);
        demo.water().foam().unwrap().amount().to_vec()
    };
    let (a, b, c) = (run(30), run(60), run(144));
    let diff = |x: &[f32], y: &[f32]| x.iter().zip(y).map(|(p, q)| (p - q).abs()).fold(0.0f32, f32::max);
    println!(
        "foam after 1 s: sum {:.2}; largest difference 30 vs 60 {:e}, 60 vs 144 {:e}",
        a.iter().sum::<f32>(),
        diff(&a, &b),
        diff(&b, &c)
    );
    assert!(a.iter().sum::<f32>() > 1.0 && diff(&a, &b) < 1e-6 && diff(&b, &c) < 1e-6);
}
