//! Helpers shared by the GPU tests: one headless device per test binary (lavapipe in CI) and
//! frame rendering; the pictures and their statistics are `support/picture.rs`'s.
#![allow(dead_code)]

#[path = "../support/picture.rs"]
pub mod picture;

// For the test files (a binary that takes only some of them leaves the others unused).
#[allow(unused_imports)]
pub use picture::{Area, Image};

use std::sync::OnceLock;

use wavepool::demo::{DemoOptions, WaterDemo};
use wavepool::headless::{HeadlessGpu, OffscreenTarget, OFFSCREEN_FORMAT};

/// The device every test in this binary shares. No adapter is a failure, never a skip.
pub fn gpu() -> &'static HeadlessGpu {
    static GPU: OnceLock<HeadlessGpu> = OnceLock::new();
    GPU.get_or_init(|| match HeadlessGpu::new() {
        Ok(gpu) => gpu,
        Err(e) => panic!("GPU tests need an adapter and none was found: {e}"),
    })
}

pub fn demo(options: DemoOptions) -> WaterDemo {
    let g = gpu();
    WaterDemo::new(&g.device, &g.queue, OFFSCREEN_FORMAT, options)
}

/// Renders `frames` frames of `frame_time` seconds and returns the last.
pub fn render(demo: &mut WaterDemo, width: u32, height: u32, frames: u32, frame_time: f32) -> Image {
    let g = gpu();
    let target = OffscreenTarget::new(&g.device, width, height);
    for _ in 0..frames {
        demo.frame(&g.device, &g.queue, &target.view, target.size(), frame_time);
    }
    let frame = Image::new(width, height, target.read_rgba(&g.device, &g.queue));
    dump(&frame);
    frame
}

/// With WAVEPOOL_DUMP_FRAMES=DIR, every rendered test frame is also written there as PNG
/// (named by test thread and a counter), to look at what a failing test saw.
fn dump(frame: &Image) {
    use std::sync::atomic::{AtomicU32, Ordering};
    static COUNTER: AtomicU32 = AtomicU32::new(0);
    let thread = std::thread::current().name().unwrap_or("main").replace("::", "-");
    frame.dump(&format!("{thread}-{}", COUNTER.fetch_add(1, Ordering::SeqCst)));
}
