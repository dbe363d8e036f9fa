//! Figures of a picture for issue 27 (our picture against Evan Wallace's classic WebGL Water):
//! pure functions on an RGBA8 image and a rectangle of it, no browser and no GPU. Used by the
//! look benchmark (benches/look.rs) and the aliasing one (benches/aliasing.rs); tested in tests/picture_stats.rs (`cargo test --test
//! picture_stats`), not here: the benchmark compiles this file with `cfg(test)` but without
//! its test functions, so a test module here would warn there.
//!
//! - colourfulness after Hasler and Süsstrunk (2003), on 0-255 values: rg = R - G,
//!   yb = (R + G) / 2 - B, M = sqrt(σ_rg² + σ_yb²) + 0.3 sqrt(μ_rg² + μ_yb²) (σ: population
//!   standard deviation; a grey picture gives 0, the paper calls about 33 "moderately
//!   colourful", 59 "quite", 82 "highly");
//! - luma: Rec. 709, 0.2126 R + 0.7152 G + 0.0722 B on 0-255; its standard deviation;
//! - sparkle share: the share of pixels whose luma differs from the median of their 3x3
//!   neighbourhood (the pixel and its 8 neighbours) by more than 40 (of 255), counted over the
//!   rectangle's interior pixels (those whose neighbourhood lies inside it);
//! - luma percentile ratio, e.g. the 95th over the 50th: the floor's caustic contrast.
#![allow(dead_code)]

use serde_json::{json, Value};

/// A picture: RGBA8 sRGB, rows top to bottom, 4 bytes a pixel (alpha is ignored): a frame
/// rendered natively, a browser's screenshot. The one picture type of the tests.
#[derive(Clone, Debug)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub rgba: Vec<u8>,
}

impl Image {
    pub fn new(width: u32, height: u32, rgba: Vec<u8>) -> Self {
        assert_eq!(rgba.len(), width as usize * height as usize * 4, "RGBA8 data of {width}x{height}");
        Self { width, height, rgba }
    }

    /// A PNG's pixels (a browser's screenshot).
    pub fn decode(png_bytes: &[u8]) -> Self {
        let mut decoder = png::Decoder::new(std::io::Cursor::new(png_bytes));
        decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
        let mut reader = decoder.read_info().expect("png header");
        let mut buf = vec![0; reader.output_buffer_size().expect("png size")];
        let info = reader.next_frame(&mut buf).expect("png frame");
        buf.truncate(info.buffer_size());
        let rgba = match info.color_type {
            png::ColorType::Rgba => buf,
            png::ColorType::Rgb => buf.chunks(3).flat_map(|p| [p[0], p[1], p[2], 255]).collect(),
            other => panic!("unexpected screenshot colour type {other:?}"),
        };
        Self { width: info.width, height: info.height, rgba }
    }

    /// With WAVEPOOL_DUMP_FRAMES=DIR, writes the picture there as `name`.png, to look at what a
    /// test saw.
    pub fn dump(&self, name: &str) {
        if let Some(dir) = std::env::var_os("WAVEPOOL_DUMP_FRAMES") {
            let dir = std::path::PathBuf::from(dir);
            let _ = std::fs::create_dir_all(&dir);
            let path = dir.join(format!("{name}.png"));
            wavepool::headless::write_png(&path, self.width, self.height, &self.rgba).expect("dump a picture");
        }
    }

    /// The pixels (off the border) where this picture differs from `stepped`, the same frame
    /// drawn without some blending, by more than 2 in a channel: each with whether its luma
    /// lies within the range of `stepped`'s 3 × 3 round it (±2/255), and that range (0-1).
    /// A blended edge changes only pixels on the edge, to a colour between its two sides.
    pub fn blended_against(&self, stepped: &Image) -> Vec<Blended> {
        let mut out = Vec::new();
        for y in 1..self.height - 1 {
            for x in 1..self.width - 1 {
                if self.pixel(x, y).iter().zip(stepped.pixel(x, y)).all(|(a, b)| a.abs_diff(b) <= 2) {
                    continue;
                }
                let around = (0..9).map(|k| stepped.unit_luma(x + k % 3 - 1, y + k / 3 - 1));
                let (lo, hi) = around.fold((f32::MAX, f32::MIN), |(lo, hi), l| (lo.min(l), hi.max(l)));
                let between = (lo - 2.0 / 255.0..=hi + 2.0 / 255.0).contains(&self.unit_luma(x, y));
                out.push(Blended { x, y, between, contrast: hi - lo });
            }
        }
        out
    }

    /// The whole picture as a rectangle.
    pub fn full(&self) -> Rect {
        Rect { x: 0, y: 0, w: self.width, h: self.height }
    }

    /// (R, G, B) at (x, y), 0-255.
    pub fn rgb(&self, x: u32, y: u32) -> [f64; 3] {
        let i = (y as usize * self.width as usize + x as usize) * 4;
        [self.rgba[i] as f64, self.rgba[i + 1] as f64, self.rgba[i + 2] as f64]
    }

    /// Rec. 709 luma at (x, y), 0-255.
    pub fn luma(&self, x: u32, y: u32) -> f64 {
        luma(self.rgb(x, y))
    }

    /// (R, G, B) at (x, y) as 0-1.
    pub fn unit_rgb(&self, x: u32, y: u32) -> [f32; 3] {
        let i = ((y * self.width + x) * 4) as usize;
        [self.rgba[i] as f32 / 255.0, self.rgba[i + 1] as f32 / 255.0, self.rgba[i + 2] as f32 / 255.0]
    }

    /// Rec. 709 luma at (x, y) as 0-1, summed in f32 (as the native tests' bounds were set).
    pub fn unit_luma(&self, x: u32, y: u32) -> f32 {
        let [r, g, b] = self.unit_rgb(x, y);
        let [wr, wg, wb] = REC709.map(|w| w as f32);
        wr * r + wg * g + wb * b
    }

    /// The bytes (R, G, B) at (x, y), clamped into the picture.
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 3] {
        let i = ((y.min(self.height - 1) * self.width + x.min(self.width - 1)) * 4) as usize;
        [self.rgba[i], self.rgba[i + 1], self.rgba[i + 2]]
    }

    /// The pixels of a region, row by row (clamped into the picture).
    pub fn region(&self, r: impl Region) -> Vec<[u8; 3]> {
        let r = r.on(self);
        (r.y..r.y + r.h).flat_map(|y| (r.x..r.x + r.w).map(move |x| (x, y))).map(|(x, y)| self.pixel(x, y)).collect()
    }

    /// Lumas of a rectangle, row by row.
    fn lumas(&self, r: Rect) -> Vec<f64> {
        let r = r.within(self);
        (r.y..r.y + r.h).flat_map(|y| (r.x..r.x + r.w).map(move |x| (x, y))).map(|(x, y)| self.luma(x, y)).collect()
    }

    /// Mean colour over a region, 0-255.
    pub fn mean(&self, r: impl Region) -> [f64; 3] {
        let px = self.region(r);
        let mut m = [0.0; 3];
        for p in &px {
            for c in 0..3 {
                m[c] += p[c] as f64 / px.len() as f64;
            }
        }
        m
    }

    /// Mean colour over a region as 0-1.
    pub fn mean_colour(&self, r: impl Region) -> [f32; 3] {
        let mut sum = [0.0f64; 3];
        let pts = r.on(self).points();
        for &(x, y) in &pts {
            let p = self.unit_rgb(x, y);
            for k in 0..3 {
                sum[k] += p[k] as f64;
            }
        }
        sum.map(|s| (s / pts.len() as f64) as f32)
    }

    /// Mean and variance of luma as 0-1 over a region.
    pub fn luma_stats(&self, r: impl Region) -> (f64, f64) {
        let values: Vec<f64> = r.on(self).points().iter().map(|&(x, y)| self.unit_luma(x, y) as f64).collect();
        let mean = values.iter().sum::<f64>() / values.len() as f64;
        let var = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / values.len() as f64;
        (mean, var)
    }

    /// Standard deviation of luma (0-255) over a region: 0 for a flat fill.
    pub fn luma_spread(&self, r: impl Region) -> f64 {
        let lumas: Vec<f64> = self.region(r).iter().map(|p| luma(p.map(f64::from))).collect();
        mean_and_std(lumas.into_iter()).1
    }

    /// Mean absolute difference per channel (0-255) against `other` over a region.
    pub fn mean_abs_diff(&self, other: &Image, r: impl Region) -> f64 {
        let (a, b) = (self.region(&r), other.region(&r));
        let sum: u64 = a.iter().zip(&b).flat_map(|(p, q)| (0..3).map(move |k| p[k].abs_diff(q[k]) as u64)).sum();
        sum as f64 / (a.len() * 3) as f64
    }

    /// Share of the region's pixels where any channel differs from `other`'s by more than
    /// `threshold` (0-255).
    pub fn changed_fraction(&self, other: &Image, r: impl Region, threshold: u8) -> f64 {
        let (a, b) = (self.region(&r), other.region(&r));
        let changed = a.iter().zip(&b).filter(|(p, q)| (0..3).any(|k| p[k].abs_diff(q[k]) > threshold)).count();
        changed as f64 / a.len() as f64
    }
}

/// A part of a picture, in pixels ([`Rect`]) or in fractions of its size ([`Area`]).
pub trait Region {
    /// The pixels it covers on `img`.
    fn on(&self, img: &Image) -> Rect;
}

/// As it is: reading past the picture's edge repeats the edge's pixels.
impl Region for Rect {
    fn on(&self, _img: &Image) -> Rect {
        *self
    }
}

impl<R: Region> Region for &R {
    fn on(&self, img: &Image) -> Rect {
        (*self).on(img)
    }
}

/// A rectangle in fractions of the picture: x0, y0 (top left) to x1, y1.
#[derive(Clone, Copy, Debug)]
pub struct Area(pub f32, pub f32, pub f32, pub f32);

impl Area {
    pub const ALL: Area = Area(0.0, 0.0, 1.0, 1.0);

    /// The coordinates of its pixels on `img`, row by row.
    pub fn pixels(&self, img: &Image) -> Vec<(u32, u32)> {
        self.on(img).points()
    }

    /// A square of half-size `r` (fraction of the width) around a pixel of `img`.
    pub fn around(px: f32, py: f32, img: &Image, r: f32) -> Area {
        let (cx, cy) = (px / img.width as f32, py / img.height as f32);
        let ry = r * img.width as f32 / img.height as f32;
        Area(cx - r, cy - ry, cx + r, cy + ry)
    }
}

impl Region for Area {
    fn on(&self, img: &Image) -> Rect {
        let (x0, x1) = ((self.0 * img.width as f32) as u32, ((self.2 * img.width as f32) as u32).min(img.width));
        let (y0, y1) = ((self.1 * img.height as f32) as u32, ((self.3 * img.height as f32) as u32).min(img.height));
        Rect { x: x0, y: y0, w: x1.saturating_sub(x0), h: y1.saturating_sub(y0) }
    }
}

/// Rec. 709 luma's weights of R, G and B.
pub const REC709: [f64; 3] = [0.2126, 0.7152, 0.0722];

/// A pixel a blend changed (`Image::blended_against`).
#[derive(Clone, Copy, Debug)]
pub struct Blended {
    pub x: u32,
    pub y: u32,
    pub between: bool,
    pub contrast: f32,
}

/// Rec. 709 luma of sRGB-encoded (R, G, B), 0-255: 0.2126 R + 0.7152 G + 0.0722 B.
pub fn luma([r, g, b]: [f64; 3]) -> f64 {
    REC709[0] * r + REC709[1] * g + REC709[2] * b
}

/// A rectangle of pixels (left, top, width, height); clipped to the picture where used.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rect {
    pub x: u32,
    pub y: u32,
    pub w: u32,
    pub h: u32,
}

impl Rect {
    /// The square of side `fraction` of the shorter side of a `width` x `height` picture, in
    /// its middle (0.4: "the middle 40 % square").
    pub fn centred_square(width: u32, height: u32, fraction: f64) -> Self {
        let side = ((width.min(height) as f64 * fraction).round() as u32).clamp(1, width.min(height).max(1));
        Self { x: (width - side) / 2, y: (height - side) / 2, w: side, h: side }
    }

    /// This rectangle clipped to the picture.
    fn within(self, img: &Image) -> Self {
        let x = self.x.min(img.width);
        let y = self.y.min(img.height);
        Self { x, y, w: self.w.min(img.width - x), h: self.h.min(img.height - y) }
    }

    pub fn pixels(self) -> u64 {
        self.w as u64 * self.h as u64
    }

    /// Its pixels' coordinates, row by row.
    pub fn points(self) -> Vec<(u32, u32)> {
        (self.y..self.y + self.h).flat_map(|y| (self.x..self.x + self.w).map(move |x| (x, y))).collect()
    }

    /// From a JS `{left, top, width, height}` (CSS px).
    pub fn from_js(v: &Value) -> Self {
        let f = |k: &str| v[k].as_f64().unwrap_or_else(|| panic!("rect field {k} in {v}"));
        Self { x: f("left").max(0.0) as u32, y: f("top").max(0.0) as u32, w: f("width") as u32, h: f("height") as u32 }
    }

    /// The left and right halves, leaving out `gap` px either side of the middle (the split
    /// view's divider and its grip).
    pub fn halves(self, gap: u32) -> (Self, Self) {
        let half = self.w / 2;
        (Self { w: half - gap, ..self }, Self { x: self.x + half + gap, w: self.w - half - gap, ..self })
    }

    /// A square of side `2 * half` around (cx, cy).
    pub fn around(cx: f64, cy: f64, half: u32) -> Self {
        Self { x: (cx as u32).saturating_sub(half), y: (cy as u32).saturating_sub(half), w: 2 * half, h: 2 * half }
    }
}

fn mean_and_std(values: impl Iterator<Item = f64> + Clone) -> (f64, f64) {
    let n = values.clone().count().max(1) as f64;
    let mean = values.clone().sum::<f64>() / n;
    let var = values.map(|v| (v - mean).powi(2)).sum::<f64>() / n;
    (mean, var.sqrt())
}

/// Hasler and Süsstrunk's colourfulness M of the rectangle (0 for grey).
pub fn colourfulness(img: &Image, r: Rect) -> f64 {
    let r = r.within(img);
    let pixels: Vec<[f64; 3]> =
        (r.y..r.y + r.h).flat_map(|y| (r.x..r.x + r.w).map(move |x| (x, y))).map(|(x, y)| img.rgb(x, y)).collect();
    let (mean_rg, std_rg) = mean_and_std(pixels.iter().map(|p| p[0] - p[1]));
    let (mean_yb, std_yb) = mean_and_std(pixels.iter().map(|p| 0.5 * (p[0] + p[1]) - p[2]));
    (std_rg.powi(2) + std_yb.powi(2)).sqrt() + 0.3 * (mean_rg.powi(2) + mean_yb.powi(2)).sqrt()
}

/// Mean and standard deviation of Rec. 709 luma (0-255) over the rectangle.
pub fn luma_mean_std(img: &Image, r: Rect) -> (f64, f64) {
    mean_and_std(img.lumas(r).into_iter())
}

/// Standard deviation of Rec. 709 luma (0-255) over the rectangle.
pub fn luma_std(img: &Image, r: Rect) -> f64 {
    luma_mean_std(img, r).1
}

/// Luma difference (0-255) from the 3x3 median beyond which a pixel counts as a sparkle.
pub const SPARKLE_THRESHOLD: f64 = 40.0;

/// Share of the rectangle's interior pixels whose luma differs from the median of their 3x3
/// neighbourhood by more than [`SPARKLE_THRESHOLD`]; 0 for a rectangle without interior.
pub fn sparkle_share(img: &Image, r: Rect) -> f64 {
    let r = r.within(img);
    if r.w < 3 || r.h < 3 {
        return 0.0;
    }
    let lumas = img.lumas(r);
    let at = |x: u32, y: u32| lumas[(y * r.w + x) as usize];
    let mut sparkles = 0u64;
    let mut window = [0.0f64; 9];
    for y in 1..r.h - 1 {
        for x in 1..r.w - 1 {
            for (i, slot) in window.iter_mut().enumerate() {
                *slot = at(x + i as u32 % 3 - 1, y + i as u32 / 3 - 1);
            }
            window.sort_unstable_by(f64::total_cmp);
            if (at(x, y) - window[4]).abs() > SPARKLE_THRESHOLD {
                sparkles += 1;
            }
        }
    }
    sparkles as f64 / ((r.w - 2) as u64 * (r.h - 2) as u64) as f64
}

/// The `p`th percentile (0-100) of sorted values, interpolated linearly between neighbouring
/// ranks (as numpy's default); NaN for no values.
fn percentile(sorted: &[f64], p: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let rank = (p.clamp(0.0, 100.0) / 100.0) * (sorted.len() - 1) as f64;
    let (below, above) = (rank.floor() as usize, rank.ceil() as usize);
    sorted[below] + (sorted[above] - sorted[below]) * (rank - below as f64)
}

/// The `p`th luma percentile (0-100) over the rectangle, 0-255.
pub fn luma_percentile(img: &Image, r: Rect, p: f64) -> f64 {
    let mut lumas = img.lumas(r);
    lumas.sort_unstable_by(f64::total_cmp);
    percentile(&lumas, p)
}

/// The `p_hi`th luma percentile over the `p_lo`th (e.g. 95, 50: the caustic contrast); infinite
/// when the lower one is 0 and the upper is not, NaN when both are.
pub fn luma_percentile_ratio(img: &Image, r: Rect, p_hi: f64, p_lo: f64) -> f64 {
    let mut lumas = img.lumas(r);
    lumas.sort_unstable_by(f64::total_cmp);
    percentile(&lumas, p_hi) / percentile(&lumas, p_lo)
}

/// The figures of one picture (a rectangle of it), and optionally the caustic contrast of a
/// floor rectangle.
#[derive(Clone, Debug, PartialEq)]
pub struct PictureStats {
    /// The rectangle measured.
    pub rect: Rect,
    pub colourfulness: f64,
    pub luma_mean: f64,
    pub luma_std: f64,
    pub sparkle_share: f64,
    /// 95th / 50th luma percentile over `floor` (see [`PictureStats::with_caustic_contrast`]).
    pub caustic_contrast: Option<f64>,
    pub floor: Option<Rect>,
}

impl PictureStats {
    /// Colourfulness, luma mean and standard deviation and sparkle share of `r`.
    pub fn of(img: &Image, r: Rect) -> Self {
        let r = r.within(img);
        let (luma_mean, luma_std) = luma_mean_std(img, r);
        Self {
            rect: r,
            colourfulness: colourfulness(img, r),
            luma_mean,
            luma_std,
            sparkle_share: sparkle_share(img, r),
            caustic_contrast: None,
            floor: None,
        }
    }

    /// Adds the caustic contrast (95th / 50th luma percentile) over `floor`.
    pub fn with_caustic_contrast(mut self, img: &Image, floor: Rect) -> Self {
        let floor = floor.within(img);
        self.caustic_contrast = Some(luma_percentile_ratio(img, floor, 95.0, 50.0));
        self.floor = Some(floor);
        self
    }

    /// The figures as JSON, rounded to 4 significant decimals (non-finite ratios as null).
    pub fn to_json(&self) -> Value {
        let round = |x: f64| (x * 1e4).round() / 1e4;
        let rect = |r: Rect| json!([r.x, r.y, r.w, r.h]);
        json!({
            "rect": rect(self.rect),
            "colourfulness": round(self.colourfulness),
            "luma_mean": round(self.luma_mean),
            "luma_std": round(self.luma_std),
            "sparkle_share": round(self.sparkle_share),
            "caustic_contrast": self.caustic_contrast.filter(|c| c.is_finite()).map(round),
            "floor_rect": self.floor.map(rect),
        })
    }
}
