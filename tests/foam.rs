//! Foam (lavapipe in CI): a hard drop breaks and foams where it fell and nowhere else, a ball
//! dropped into the pool splashes foam around it, both engines (the GPU engine's CPU shadow
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
    demo.set_body_pose(BodyId::Sphere, Pose::at(Vec3::new(-0.2, 0.6, 0.1)));
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
    println!("foam of the GPU engine (its CPU shadow) and of the CPU engine: {} cells, sum {total:.2}, largest difference {largest:e}", gpu.len());
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
            let p = frame.pixel(x, y);
            p[0] > 0.85 && p[1] > 0.85 && p[2] > 0.85
        });
        (count.count(), demo.water().foam().is_some())
    };
    let ((with, on), (without, off)) = (white(true), white(false));
    println!("white pixels after a hard drop: {with} with foam, {without} without; foam integrated: {on} / {off}");
    assert!(with > 2 * without + 100, "foam does not show ({with} vs {without})");
    assert!(on && !off, "foam integrated with it off");
}
