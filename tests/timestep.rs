//! Frame-rate independence: the core advances in fixed steps of simulated time, so driving
//! it at 30, 60 or 144 frames per second to the same simulated time, with the same drops at
//! the same simulated times, gives the same water.

mod common;

use wavepool::demo::{DemoOptions, STEPS_PER_SECOND};
use wavepool::headless::OffscreenTarget;

fn run(fps: f64, until: f64) -> Vec<[f32; 4]> {
    let g = common::gpu();
    let mut demo =
        common::demo(DemoOptions { sim_size: 128, caustics_size: 256, surface_grid: 32, ..DemoOptions::default() });
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
    }
    assert!(drops.is_empty());
    assert!((demo.sim_time() - until).abs() < 1e-9, "{fps} fps stopped at {} s", demo.sim_time());
    demo.water().read_state(&g.device, &g.queue)
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
