//! The picture figures of issue 27 (colourfulness, luma spread, sparkle share, caustic
//! contrast; tests/support/picture.rs, used by the look benchmark) on small made-up pictures:
//! pure functions, no browser and no GPU.

#[path = "support/picture.rs"]
mod picture;

use picture::{colourfulness, luma_percentile, luma_percentile_ratio, sparkle_share, Image, PictureStats, Rect};

fn filled(width: u32, height: u32, rgb: [u8; 3]) -> Vec<u8> {
    (0..width * height).flat_map(|_| [rgb[0], rgb[1], rgb[2], 255]).collect()
}

#[test]
fn a_flat_grey_picture_has_no_colour_no_spread_and_no_sparkle() {
    let data = filled(16, 12, [128, 128, 128]);
    let img = Image::new(16, 12, data.clone());
    let stats = PictureStats::of(&img, img.full());
    assert_eq!(stats.colourfulness, 0.0);
    assert!(stats.luma_std.abs() < 1e-9, "luma std {}", stats.luma_std);
    assert_eq!(stats.sparkle_share, 0.0);
    assert!((stats.luma_mean - 128.0).abs() < 1e-9);
    assert_eq!(luma_percentile_ratio(&img, img.full(), 95.0, 50.0), 1.0);
}

#[test]
fn one_bright_pixel_in_grey_is_one_sparkle_among_the_interior_pixels() {
    let (w, h) = (10, 8);
    let mut data = filled(w, h, [100, 100, 100]);
    let i = ((4 * w + 5) * 4) as usize;
    data[i..i + 3].copy_from_slice(&[255, 255, 255]);
    let img = Image::new(w, h, data.clone());
    let interior = ((w - 2) * (h - 2)) as f64;
    assert_eq!(sparkle_share(&img, img.full()), 1.0 / interior);
    // Just under the threshold (40 of 255) it is no sparkle.
    data[i..i + 3].copy_from_slice(&[139, 139, 139]);
    assert_eq!(sparkle_share(&Image::new(w, h, data.clone()), Rect { x: 0, y: 0, w, h }), 0.0);
}

#[test]
fn a_red_and_green_checkerboard_is_highly_colourful() {
    let (w, h) = (8, 8);
    let data: Vec<u8> =
        (0..w * h).flat_map(|i| if (i % w + i / w) % 2 == 0 { [255, 0, 0, 255] } else { [0, 255, 0, 255] }).collect();
    let img = Image::new(w, h, data.clone());
    let m = colourfulness(&img, img.full());
    // rg is ±255 (σ 255, mean 0); yb is 127.5 throughout (σ 0): M = 255 + 0.3 x 127.5.
    assert!((m - (255.0 + 0.3 * 127.5)).abs() < 1e-9, "colourfulness {m}");
    assert!(m > 82.0, "beyond the paper's 'highly colourful'");
    // A pattern, not sparkle: each pixel's 3x3 neighbourhood is five of its colour (itself
    // and the diagonals) and four of the other, so it is its own median.
    assert_eq!(sparkle_share(&img, img.full()), 0.0);
}

#[test]
fn percentiles_interpolate_between_ranks_and_the_ratio_divides_them() {
    // Lumas 0, 10, ..., 90 in one row of grey pixels.
    let data: Vec<u8> = (0..10u8).flat_map(|i| [i * 10, i * 10, i * 10, 255]).collect();
    let img = Image::new(10, 1, data.clone());
    assert!((luma_percentile(&img, img.full(), 50.0) - 45.0).abs() < 1e-9);
    assert!((luma_percentile(&img, img.full(), 95.0) - 85.5).abs() < 1e-9);
    assert!((luma_percentile_ratio(&img, img.full(), 95.0, 50.0) - 85.5 / 45.0).abs() < 1e-9);
}

#[test]
fn the_middle_square_and_the_json_name_every_figure() {
    assert_eq!(Rect::centred_square(480, 600, 0.4), Rect { x: 144, y: 204, w: 192, h: 192 });
    let data = filled(4, 4, [0, 0, 0]);
    let img = Image::new(4, 4, data.clone());
    let stats = PictureStats::of(&img, img.full()).with_caustic_contrast(&img, img.full());
    let json = stats.to_json();
    for key in ["colourfulness", "luma_mean", "luma_std", "sparkle_share", "rect", "floor_rect"] {
        assert!(!json[key].is_null(), "{key} in {json}");
    }
    assert!(json["caustic_contrast"].is_null(), "0 / 0 is no contrast: {json}");
}
