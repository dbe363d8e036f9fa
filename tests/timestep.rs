//! Image-rate independence: the core advances in fixed steps of simulated time, so driving
//! it at 30, 60 or 144 frames per second to the same simulated time, with the same drops at
//! the same simulated times, gives the same water.
// Tests read results back and wait for the GPU (clippy.toml: not in the frame path).
#![allow(clippy::disallowed_methods)]

mod common;

use glam::Vec3;
use wavepool::bodies::sphere;
use wavepool::demo::{BodyId, DemoOptions, STEPS_PER_SECOND};
use wavepool::headless::OffscreenTarget;
use wavepool::params::ParamId;

fn run(fps: f64, until: f64) -> Vec<[f32; 4]> {
    run_with(fps, until, 0.0).0
}

/// Runs to `until` seconds at `fps` with the `objects` parameter; returns the water and the
/// sphere's and duck's positions.
fn run_with(fps: f64, until: f64, objects: f32) -> (Vec<[f32; 4]>, [Vec3; 2]) {
    let g = common::gpu();
    let mut demo =
        common::demo(DemoOptions { sim_size: 128, caustics_size: 256, surface_grid: 32, ..DemoOptions::default() });
    demo.params.set(ParamId::Objects, objects);
    // The sphere released under the water, so that it rises and bobs (it starts at rest at its
    // floating height).
    demo.set_sphere_centre(sphere::CLASSIC_START);
    let target = OffscreenTarget::new(&g.device, 64, 48);
    // Drops at these simulated times (s): multiples of 1/30 s, reached exactly at every rate.
    let mut drops = vec![(0.0, 0.2, -0.3), (0.2, -0.5, 0.1), (0.5, 0.0, 0.6), (0.9, 0.4, 0.4)];
    let steps_until = (until * STEPS_PER_SECOND as f64).round() as u64;
    while demo.steps_taken() < steps_until {
        let now = demo.sim_time();
        while let Some(&(t, x, z)) = drops.first() {
            if (t - now).abs() < 1e-9 {
                demo.add_drop(x, z, 0.08, 0.015);
                drops.remove(0);
            } else {
                assert!(t > now, "the {fps} fps run skipped past the drop at {t} s (now {now} s)");
                break;
            }
        }
        demo.frame(&g.device, &g.queue, &target.view, target.size(), (1.0 / fps) as f32);
        // Image pacing as on a display: the next frame starts once the GPU is done.
        g.device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
    }
    assert!(drops.is_empty());
    assert!((demo.sim_time() - until).abs() < 1e-9, "{fps} fps stopped at {} s", demo.sim_time());
    let bodies =
        [BodyId::named("sphere").unwrap(), BodyId::named("duck").unwrap()].map(|id| demo.body(id).pose.position);
    (demo.water().read_state(&g.device, &g.queue), bodies)
}

#[test]
fn thirty_sixty_and_144_fps_give_the_same_water() {
    let until = 1.5;
    let reference = run(60.0, until);
    let peak = reference.iter().map(|c| c[0].abs()).fold(0.0f32, f32::max);
    assert!(peak > 1e-3, "water should be moving: peak {peak}");
    for fps in [30.0, 144.0] {
        let state = run(fps, until);
        let worst = state
            .iter()
            .zip(&reference)
            .map(|(a, b)| (a[0] - b[0]).abs().max((a[1] - b[1]).abs()))
            .fold(0.0f32, f32::max);
        println!("{fps} fps vs 60 fps at {until} s: largest difference {worst:e} (peak height {peak:e} m)");
        assert!(worst <= 1e-4, "{fps} fps differs from 60 fps by {worst}");
    }
}

/// With the sphere and the duck floating (they take the water's heights once per frame, a
/// frame late, and push it once per frame), the frame rate changes the outcome only slightly:
/// bodies within a centimetre, and the water's root-mean-square difference under 15% of its
/// waves' (near the bodies, where the waves are steep, a millimetre of difference in where a
/// body is shows as several in the height).
#[test]
fn floating_objects_move_alike_at_30_60_and_144_fps() {
    let until = 3.0;
    let (water, bodies) = run_with(60.0, until, 3.0);
    let start = [sphere::CLASSIC_START, Vec3::ZERO];
    assert!((bodies[0] - start[0]).length() > 0.2, "the sphere should have risen: {}", bodies[0]);
    let level = water.iter().map(|c| c[0] as f64).sum::<f64>() / water.len() as f64;
    let rms =
        |f: &dyn Fn(usize) -> f64| ((0..water.len()).map(|i| f(i).powi(2)).sum::<f64>() / water.len() as f64).sqrt();
    let waves = rms(&|i| water[i][0] as f64 - level);
    for fps in [30.0, 144.0] {
        let (state, at) = run_with(fps, until, 3.0);
        let worst = state.iter().zip(&water).map(|(a, b)| (a[0] - b[0]).abs()).fold(0.0f32, f32::max);
        let diff = rms(&|i| (state[i][0] - water[i][0]) as f64);
        let apart = [0, 1].map(|k| (at[k] - bodies[k]).length());
        println!(
            "{fps} fps vs 60 fps at {until} s: bodies {apart:?} m apart; water rms difference {diff:e} m against \
             rms waves {waves:e} m (largest difference {worst:e} m)"
        );
        assert!(apart.iter().all(|&d| d < 0.01), "{fps} fps moves the bodies differently: {apart:?} m");
        assert!(diff < 0.15 * waves, "{fps} fps leaves the water {diff} m (rms) different");
    }
}
