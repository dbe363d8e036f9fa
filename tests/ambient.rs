//! Ambient waves on the GPU (lavapipe in CI): the picture moves with simulated time only
//! (paused, it stands; 30 and 144 frames/s give the same frame after the same second), the
//! simulation's own state never sees them, and a floating duck rides them.

mod common;

use common::render;
use wavepool::demo::{DemoOptions, WaterDemo};
use wavepool::params::ParamId;

const W: u32 = 240;
const H: u32 = 180;

/// An empty pool with ambient waves of `model` (1 sines, 2 modes).
fn pool_with(model: f32) -> WaterDemo {
    let mut demo = common::demo(DemoOptions::default());
    demo.params.set(ParamId::Objects, 0.0);
    demo.params.set(ParamId::Quality, 1.0);
    demo.params.set(ParamId::Ambient, model);
    demo
}

#[test]
fn ambient_waves_move_the_picture_with_simulated_time_only() {
    for (model, name) in [(1.0, "sines"), (2.0, "modes")] {
        let mut calm = pool_with(0.0);
        let still = render(&mut calm, W, H, 60, 1.0 / 60.0);
        // One second at 30 and at 144 frames/s: the same 120 fixed steps, the same surface.
        let mut slow = pool_with(model);
        let at_30 = render(&mut slow, W, H, 30, 1.0 / 30.0);
        let mut fast = pool_with(model);
        let at_144 = render(&mut fast, W, H, 144, 1.0 / 144.0);
        // Later, and paused for a while.
        let later = render(&mut slow, W, H, 15, 1.0 / 30.0);
        slow.params.set(ParamId::Paused, 1.0);
        let paused_a = render(&mut slow, W, H, 1, 1.0 / 30.0);
        let paused_b = render(&mut slow, W, H, 20, 1.0 / 30.0);
        let all = common::Rect::ALL;
        let (vs_calm, rates, moving, paused) = (
            at_30.changed_fraction(&still, all, 8),
            at_30.mean_abs_diff(&at_144, all),
            at_30.changed_fraction(&later, all, 8),
            paused_a.mean_abs_diff(&paused_b, all),
        );
        println!(
            "{name}: {:.1} % of pixels differ from calm water; 30 vs 144 frames/s after 1 s: {rates:.3}/255 mean \
             difference; 0.5 s later {:.1} % changed; paused for 20 frames: {paused:.3}/255",
            vs_calm * 100.0,
            moving * 100.0
        );
        assert!(vs_calm > 0.02, "{name}: the ambient waves do not show ({:.2} %)", vs_calm * 100.0);
        assert!(rates < 0.05, "{name}: 30 and 144 frames/s differ by {rates}/255");
        assert!(moving > 0.02, "{name}: the waves do not move ({:.2} %)", moving * 100.0);
        assert!(paused < 0.01, "{name}: paused, the picture still changes ({paused}/255)");
    }
}

#[test]
fn the_simulation_never_sees_the_ambient_waves() {
    let g = common::gpu();
    let run = |model: f32| {
        let mut demo = pool_with(model);
        demo.add_drop(0.2, -0.3, 0.06, 0.015);
        render(&mut demo, 64, 48, 40, 1.0 / 60.0);
        demo.water().read_state(&g.device, &g.queue)
    };
    let (without, with) = (run(0.0), run(1.0));
    let largest =
        without.iter().zip(&with).map(|(a, b)| (a[0] - b[0]).abs().max((a[1] - b[1]).abs())).fold(0.0f32, f32::max);
    let peak = without.iter().map(|c| c[0].abs()).fold(0.0f32, f32::max);
    println!("state with and without ambient waves: largest difference {largest:e} (ripple peak {peak:.4} m)");
    assert!(peak > 1e-3 && largest == 0.0, "the simulation changed with ambient waves: {largest}");
}

#[test]
fn a_floating_duck_rides_the_ambient_waves() {
    let heave = |model: f32| {
        let mut demo = pool_with(model);
        demo.params.set(ParamId::Objects, 2.0); // the duck
        demo.params.set(ParamId::WaveHeight, 0.03);
        render(&mut demo, 64, 48, 120, 1.0 / 60.0); // settle for 2 s
        let mut ys = Vec::new();
        for _ in 0..120 {
            render(&mut demo, 64, 48, 1, 1.0 / 60.0);
            ys.push(demo.duck().expect("the duck is in the pool").position.y);
        }
        let mean = ys.iter().sum::<f32>() / ys.len() as f32;
        (ys.iter().map(|y| (y - mean).powi(2)).sum::<f32>() / ys.len() as f32).sqrt()
    };
    let (calm, sines, modes) = (heave(0.0), heave(1.0), heave(2.0));
    println!(
        "the duck's heave (std of its height over 2 s): calm {:.2} mm, sines {:.2} mm, modes {:.2} mm",
        calm * 1e3,
        sines * 1e3,
        modes * 1e3
    );
    assert!(calm < 0.5e-3, "the duck moves on calm water ({calm} m)");
    assert!(sines > 1e-3 && modes > 1e-3, "the duck does not ride the waves ({sines} / {modes} m)");
}

/// The height and normals debug views show the surface that is drawn: on calm water with
/// ambient waves they are no longer the flat rest colour.
#[test]
fn the_height_and_normals_views_show_the_ambient_waves() {
    for (view, name) in [(1.0, "height"), (2.0, "normals")] {
        let frame = |model: f32| {
            let mut demo = pool_with(model);
            demo.params.set(ParamId::DebugView, view);
            demo.params.set(ParamId::DebugInset, 0.0);
            render(&mut demo, W, H, 10, 1.0 / 60.0)
        };
        let (calm, waves) = (frame(0.0), frame(1.0));
        // The view is the centred square (H pixels); compare inside it.
        let square = common::Rect(0.5 - 0.5 * H as f32 / W as f32 + 0.02, 0.02, H as f32 / W as f32 - 0.04, 0.96);
        let changed = waves.changed_fraction(&calm, square, 8);
        println!("{name} view: {:.1} % of the pool's square changed by ambient sines", changed * 100.0);
        assert!(changed > 0.3, "{name} view does not show the ambient waves ({:.1} %)", changed * 100.0);
    }
}
