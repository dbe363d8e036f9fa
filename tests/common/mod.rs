//! Helpers shared by the GPU tests: one headless device per test binary (lavapipe in CI),
//! frame rendering and pixel statistics.
#![allow(dead_code)]

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

/// A rendered frame: RGBA8 sRGB, top row first.
pub struct Frame {
    pub width: u32,
    pub height: u32,
    pub rgba: Vec<u8>,
}

impl Frame {
    pub fn pixel(&self, x: u32, y: u32) -> [f32; 3] {
        let i = ((y * self.width + x) * 4) as usize;
        [self.rgba[i] as f32 / 255.0, self.rgba[i + 1] as f32 / 255.0, self.rgba[i + 2] as f32 / 255.0]
    }

    /// Rec. 709 luma of the sRGB-encoded pixel.
    pub fn luma(&self, x: u32, y: u32) -> f32 {
        let [r, g, b] = self.pixel(x, y);
        0.2126 * r + 0.7152 * g + 0.0722 * b
    }

    /// Mean colour over a rectangle given in fractions of the frame.
    pub fn mean_colour(&self, rect: Rect) -> [f32; 3] {
        let mut sum = [0.0f64; 3];
        let pts = rect.pixels(self);
        for &(x, y) in &pts {
            let p = self.pixel(x, y);
            for k in 0..3 {
                sum[k] += p[k] as f64;
            }
        }
        sum.map(|s| (s / pts.len() as f64) as f32)
    }

    /// Mean and variance of luma over a rectangle.
    pub fn luma_stats(&self, rect: Rect) -> (f64, f64) {
        let pts = rect.pixels(self);
        let values: Vec<f64> = pts.iter().map(|&(x, y)| self.luma(x, y) as f64).collect();
        let mean = values.iter().sum::<f64>() / values.len() as f64;
        let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / values.len() as f64;
        (mean, var)
    }

    /// Mean absolute difference per channel (0..255) against another frame over a rectangle.
    pub fn mean_abs_diff(&self, other: &Frame, rect: Rect) -> f64 {
        let pts = rect.pixels(self);
        let mut sum = 0u64;
        for &(x, y) in &pts {
            let i = ((y * self.width + x) * 4) as usize;
            for k in 0..3 {
                sum += (self.rgba[i + k] as i32 - other.rgba[i + k] as i32).unsigned_abs() as u64;
            }
        }
        sum as f64 / (pts.len() * 3) as f64
    }
}

impl Frame {
    /// Fraction of pixels in a rectangle where any channel differs by more than `threshold` (0..255).
    pub fn changed_fraction(&self, other: &Frame, rect: Rect, threshold: u8) -> f64 {
        let pts = rect.pixels(self);
        let changed = pts
            .iter()
            .filter(|&&(x, y)| {
                let i = ((y * self.width + x) * 4) as usize;
                (0..3).any(|k| self.rgba[i + k].abs_diff(other.rgba[i + k]) > threshold)
            })
            .count();
        changed as f64 / pts.len() as f64
    }
}

/// A rectangle in fractions of the frame: x0, y0 (top-left) to x1, y1.
#[derive(Clone, Copy, Debug)]
pub struct Rect(pub f32, pub f32, pub f32, pub f32);

impl Rect {
    pub const ALL: Rect = Rect(0.0, 0.0, 1.0, 1.0);

    pub fn pixels(&self, f: &Frame) -> Vec<(u32, u32)> {
        let (x0, x1) = ((self.0 * f.width as f32) as u32, ((self.2 * f.width as f32) as u32).min(f.width));
        let (y0, y1) = ((self.1 * f.height as f32) as u32, ((self.3 * f.height as f32) as u32).min(f.height));
        (y0..y1).flat_map(|y| (x0..x1).map(move |x| (x, y))).collect()
    }

    /// A square of half-size `r` (fraction of the width) around a pixel.
    pub fn around(px: f32, py: f32, f: &Frame, r: f32) -> Rect {
        let (cx, cy) = (px / f.width as f32, py / f.height as f32);
        let ry = r * f.width as f32 / f.height as f32;
        Rect(cx - r, cy - ry, cx + r, cy + ry)
    }
}

/// Renders `frames` frames of `frame_time` seconds and returns the last.
pub fn render(demo: &mut WaterDemo, width: u32, height: u32, frames: u32, frame_time: f32) -> Frame {
    let g = gpu();
    let target = OffscreenTarget::new(&g.device, width, height);
    for _ in 0..frames {
        demo.frame(&g.device, &g.queue, &target.view, target.size(), frame_time);
    }
    let frame = Frame { width, height, rgba: target.read_rgba(&g.device, &g.queue) };
    dump(&frame);
    frame
}

/// With WAVEPOOL_DUMP_FRAMES=DIR, every rendered test frame is also written there as PNG
/// (named by test thread and a counter), to look at what a failing test saw.
fn dump(frame: &Frame) {
    use std::sync::atomic::{AtomicU32, Ordering};
    static COUNTER: AtomicU32 = AtomicU32::new(0);
    if let Some(dir) = std::env::var_os("WAVEPOOL_DUMP_FRAMES") {
        let dir = std::path::PathBuf::from(dir);
        let _ = std::fs::create_dir_all(&dir);
        let thread = std::thread::current().name().unwrap_or("main").replace("::", "-");
        let n = COUNTER.fetch_add(1, Ordering::SeqCst);
        let path = dir.join(format!("{thread}-{n}.png"));
        wavepool::headless::write_png(&path, frame.width, frame.height, &frame.rgba).expect("dump frame");
    }
}
