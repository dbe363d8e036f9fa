//! Aliasing against a supersampled reference (issue 46), and flicker at rest. Not a test: it
//! prints figures. Run with `cargo bench --bench aliasing` (lavapipe here, about a minute).
//!
//! For each view: the demo is run for a second after seeded drops (as `wavepool render`), then
//! paused, so the water, the waves and the bodies hold still. The frame is drawn at 800×600
//! twice (flicker at rest: how many pixels differ between the two) and once at 3200×2400,
//! which is box-filtered down to 800×600 in linear light: the reference a perfect filter would
//! give. Reported: the mean absolute difference in luma (Rec. 709, 0–255) between the frame
//! and the reference and its 99th percentile, over the whole frame and over a 40-pixel band
//! round each body's waterline (its probe ring, just outside the waterline, projected), over
//! the rest of the pool's water (the opening's square at the rest level, projected) and
//! elsewhere. With them the water's contrast: the 95th over the 50th percentile of luma over
//! the pool's water, where the floor's caustics show (the pool's views; the default view also
//! under the sun it had before 2026-11-28, for comparison in the same run). And the sparkle
//! share (tests/support/picture.rs) of the frame and of the reference: a frame filtered as
//! the reference is sparkles as much; one far under it is blurred past it (a filter's change
//! that lowers the sparkle but moves the frame further from the reference took detail the
//! reference keeps).
// Tests read results back and wait for the GPU (clippy.toml: not in the frame path).
#![allow(clippy::disallowed_methods)]

use glam::{Vec2, Vec3};
use serde_json::json;
use wavepool::bodies::BodyId;
use wavepool::demo::{DemoOptions, WaterDemo};
use wavepool::headless::{write_png, HeadlessGpu, OffscreenTarget, OFFSCREEN_FORMAT};
use wavepool::params::ParamId;
use wavepool::presets;
use wavepool::scenes::SceneKind;
use wavepool::world::PoolShape;

#[path = "../tests/support/picture.rs"]
mod picture;

const SIZE: (u32, u32) = (800, 600);
/// The reference is drawn this many times larger on each side.
const SUPERSAMPLE: u32 = 4;
/// Half the width of the band round a waterline (pixels).
const BAND: f32 = 20.0;

/// sRGB byte to linear light, and back.
fn linear(c: u8) -> f64 {
    let c = c as f64 / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

fn encoded(l: f64) -> f64 {
    let c = if l <= 0.0031308 { l * 12.92 } else { 1.055 * l.powf(1.0 / 2.4) - 0.055 };
    (c * 255.0).clamp(0.0, 255.0)
}

fn luma(rgb: [f64; 3]) -> f64 {
    0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]
}

/// Lumas of an RGBA8 frame.
fn lumas(rgba: &[u8]) -> Vec<f64> {
    rgba.chunks(4).map(|p| luma([p[0] as f64, p[1] as f64, p[2] as f64])).collect()
}

/// Lumas of a frame `k` times larger each way, box-filtered down in linear light.
fn downsampled_lumas(rgba: &[u8], (w, h): (u32, u32), k: u32) -> (Vec<f64>, Vec<u8>) {
    let big_w = (w * k) as usize;
    let mut out = Vec::with_capacity((w * h) as usize);
    let mut png = Vec::with_capacity((w * h * 4) as usize);
    for y in 0..h as usize {
        for x in 0..w as usize {
            let mut sum = [0.0; 3];
            for dy in 0..k as usize {
                for dx in 0..k as usize {
                    let i = ((y * k as usize + dy) * big_w + x * k as usize + dx) * 4;
                    for c in 0..3 {
                        sum[c] += linear(rgba[i + c]);
                    }
                }
            }
            let n = (k * k) as f64;
            let rgb = sum.map(|s| encoded(s / n));
            png.extend(rgb.map(|c| c.round() as u8));
            png.push(255);
            out.push(luma(rgb));
        }
    }
    (out, png)
}

/// Mean and 99th percentile of |a - b| over the pixels `keep` selects.
fn difference(a: &[f64], b: &[f64], keep: impl Fn(usize) -> bool) -> (f64, f64, usize) {
    let mut d: Vec<f64> = (0..a.len()).filter(|&i| keep(i)).map(|i| (a[i] - b[i]).abs()).collect();
    if d.is_empty() {
        return (f64::NAN, f64::NAN, 0);
    }
    d.sort_by(f64::total_cmp);
    let mean = d.iter().sum::<f64>() / d.len() as f64;
    (mean, d[((d.len() - 1) as f64 * 0.99) as usize], d.len())
}

/// Pixels within BAND of each shown body's waterline: its probe ring at the water's level,
/// projected (64 points a ring, joined).
fn waterline_band(demo: &WaterDemo) -> Vec<bool> {
    let value = |name: &str| demo.params.get_by_name(name).unwrap_or(0.0);
    let sea = demo.drawn_scene() == SceneKind::Sea;
    let scale = if sea { wavepool::sea::patch_scale() } else { 1.0 };
    let mut rings: Vec<Vec<Vec2>> = Vec::new();
    for id in BodyId::all() {
        let centre = if sea {
            if !demo.in_sea(id) {
                continue;
            }
            demo.sea_body(id).map(|b| b.pose.position)
        } else {
            demo.shows(id).then(|| demo.body(id).pose.position)
        };
        let Some(centre) = centre else { continue };
        let radius = (id.kind().probe_ring)(&value) * scale;
        let level = if sea { demo.sea_height_at(centre.x, centre.z).unwrap_or(0.0) } else { 0.0 };
        let size = Vec2::new(SIZE.0 as f32, SIZE.1 as f32);
        let ring: Vec<Vec2> = (0..=64)
            .filter_map(|i| {
                let a = i as f32 / 64.0 * std::f32::consts::TAU;
                demo.camera().project(Vec3::new(centre.x + radius * a.cos(), level, centre.z + radius * a.sin()), size)
            })
            .collect();
        rings.push(ring);
    }
    let mut band = vec![false; (SIZE.0 * SIZE.1) as usize];
    for ring in &rings {
        for seg in ring.windows(2) {
            let (a, b) = (seg[0], seg[1]);
            let lo = a.min(b) - Vec2::splat(BAND);
            let hi = a.max(b) + Vec2::splat(BAND);
            for y in lo.y.max(0.0) as u32..(hi.y.min(SIZE.1 as f32 - 1.0).max(0.0) as u32 + 1) {
                for x in lo.x.max(0.0) as u32..(hi.x.min(SIZE.0 as f32 - 1.0).max(0.0) as u32 + 1) {
                    let p = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
                    let t = ((p - a).dot(b - a) / (b - a).length_squared().max(1e-6)).clamp(0.0, 1.0);
                    if p.distance(a + (b - a) * t) <= BAND {
                        band[(y * SIZE.0 + x) as usize] = true;
                    }
                }
            }
        }
    }
    band
}

/// Pixels of the pool's water: inside the opening's square at the rest level, projected (the
/// pool's views only; none in the sea).
fn pool_water(demo: &WaterDemo) -> Vec<bool> {
    let size = Vec2::new(SIZE.0 as f32, SIZE.1 as f32);
    let w = PoolShape::CLASSIC.half_width;
    let corners: Vec<Vec2> = [(-w, -w), (w, -w), (w, w), (-w, w)]
        .iter()
        .filter_map(|&(x, z)| demo.camera().project(Vec3::new(x, 0.0, z), size))
        .collect();
    let sea = demo.drawn_scene() == SceneKind::Sea;
    let inside = |p: Vec2| {
        let side = |a: Vec2, b: Vec2| (b - a).perp_dot(p - a);
        let signs: Vec<f32> = (0..4).map(|i| side(corners[i], corners[(i + 1) % 4])).collect();
        signs.iter().all(|&s| s >= 0.0) || signs.iter().all(|&s| s <= 0.0)
    };
    (0..SIZE.0 * SIZE.1)
        .map(|i| !sea && corners.len() == 4 && inside(Vec2::new((i % SIZE.0) as f32 + 0.5, (i / SIZE.0) as f32 + 0.5)))
        .collect()
}

/// The `q` quantile (0-1) of the lumas `keep` selects.
fn percentile(lumas: &[f64], keep: impl Fn(usize) -> bool, q: f64) -> f64 {
    let mut v: Vec<f64> = (0..lumas.len()).filter(|&i| keep(i)).map(|i| lumas[i]).collect();
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[((v.len() - 1) as f64 * q) as usize]
}

fn draw(gpu: &HeadlessGpu, demo: &mut WaterDemo, (w, h): (u32, u32)) -> Vec<u8> {
    let target = OffscreenTarget::new(&gpu.device, w, h);
    demo.frame(&gpu.device, &gpu.queue, &target.view, target.size(), 1.0 / 60.0);
    target.read_rgba(&gpu.device, &gpu.queue)
}

/// One view: its preset, its values, and the camera's pitch (degrees; negative: from under the
/// water) where it is not the scene's own.
fn measure(gpu: &HeadlessGpu, name: &str, preset: Option<&str>, sets: &[(&str, f32)], pitch: Option<f32>) {
    let mut demo = WaterDemo::new(&gpu.device, &gpu.queue, OFFSCREEN_FORMAT, DemoOptions::default());
    if let Some(p) = preset {
        demo.apply_preset(presets::find(p).expect("a preset"));
    }
    for (param, v) in sets {
        demo.params.set_by_name(param, *v).expect("a parameter");
    }
    demo.params.set(ParamId::Quality, 1.0);
    demo.sync_scene();
    if let Some(p) = pitch {
        demo.camera_mut().pitch = p;
    }
    demo.add_random_drops(1, 12);
    let target = OffscreenTarget::new(&gpu.device, SIZE.0, SIZE.1);
    for _ in 0..60 {
        demo.frame(&gpu.device, &gpu.queue, &target.view, target.size(), 1.0 / 60.0);
    }
    demo.params.set(ParamId::Paused, 1.0);
    let first = draw(gpu, &mut demo, SIZE);
    let second = draw(gpu, &mut demo, SIZE);
    let big = draw(gpu, &mut demo, (SIZE.0 * SUPERSAMPLE, SIZE.1 * SUPERSAMPLE));
    let again = draw(gpu, &mut demo, SIZE);
    let flicker = first.chunks(4).zip(second.chunks(4)).filter(|(a, b)| a[..3] != b[..3]).count();
    let moved = first.chunks(4).zip(again.chunks(4)).filter(|(a, b)| a[..3] != b[..3]).count();
    let (reference, reference_png) = downsampled_lumas(&big, SIZE, SUPERSAMPLE);
    let frame = lumas(&first);
    let band = waterline_band(&demo);
    let whole = difference(&frame, &reference, |_| true);
    let water = pool_water(&demo);
    let near = difference(&frame, &reference, |i| band[i]);
    let in_water = difference(&frame, &reference, |i| water[i] && !band[i]);
    let rest = difference(&frame, &reference, |i| !band[i] && !water[i]);
    let (median, p95) = (percentile(&frame, |i| water[i], 0.5), percentile(&frame, |i| water[i], 0.95));
    if let Ok(dir) = std::env::var("ALIASING_PNGS") {
        let _ = write_png(std::path::Path::new(&format!("{dir}/{name}.png")), SIZE.0, SIZE.1, &first);
        let _ = write_png(std::path::Path::new(&format!("{dir}/{name}-reference.png")), SIZE.0, SIZE.1, &reference_png);
    }
    let r = |v: f64| (v * 100.0).round() / 100.0;
    let sparkle = |rgba: &[u8]| {
        let img = picture::Image::new(SIZE.0, SIZE.1, rgba.to_vec());
        (picture::sparkle_share(&img, picture::Rect { x: 0, y: 0, w: SIZE.0, h: SIZE.1 }) * 1.0e5).round() / 1.0e3
    };
    println!(
        "{}",
        json!({
            "view": name,
            "frame": { "mean": r(whole.0), "p99": r(whole.1) },
            "waterlines": { "mean": r(near.0), "p99": r(near.1), "pixels": near.2 },
            "the_rest_of_the_pool": { "mean": r(in_water.0), "p99": r(in_water.1), "pixels": in_water.2 },
            "elsewhere": { "mean": r(rest.0), "p99": r(rest.1) },
            "water_contrast_p95_p50": (p95 / median * 1000.0).round() / 1000.0,
            "water_luma_median": r(median),
            "sparkle_percent": { "frame": sparkle(&first), "reference": sparkle(&reference_png) },
            "flicker_at_rest_pixels": flicker,
            "changed_after_the_large_frame_pixels": moved,
        })
    );
}

fn main() {
    let gpu = HeadlessGpu::new().expect("a GPU adapter (lavapipe: apt-get install mesa-vulkan-drivers)");
    eprintln!("aliasing against {SUPERSAMPLE}x{SUPERSAMPLE} supersampling on {}", gpu.describe());
    measure(&gpu, "default", None, &[], None);
    measure(&gpu, "default, the sun before 2026-11-28", None, &[("sun_azimuth", 35.0), ("sun_elevation", 55.0)], None);
    measure(&gpu, "classic", Some("classic"), &[], None);
    measure(&gpu, "under the water (the cut-away, 25 degrees below)", None, &[("setting", 1.0)], Some(-25.0));
    measure(&gpu, "sea", Some("sea"), &[], None);
    measure(&gpu, "storm", Some("storm"), &[], None);
}
