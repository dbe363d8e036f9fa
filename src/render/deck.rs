//! The paved deck the pool is sunk in (the `setting` parameter's default): a ring of ground at
//! the rim's height from the pool's opening out to [`DECK_EXTENT`], coping stones along the
//! opening, paving slabs beyond, fading into the sky's haze with distance (drawn by the pool's
//! passes with `shaders/pool/deck.wgsl`; the haze's shading, `deck_shade.wgsl`, is shared).

use glam::{Mat4, Vec2, Vec3};

use crate::param_spec::{Control, ParamSpec};
use crate::sim::MAX_HEIGHT;
use crate::sky::Daylight;
use crate::util::push_triangle;
use crate::world::PoolShape;

/// How far the deck reaches from the pool's centre (m): past any frame the camera can show.
pub const DECK_EXTENT: f32 = 400.0;
/// Width of the band of coping stones around the opening (m).
pub const COPING_WIDTH: f32 = 0.3;
/// Side of a paving slab (m).
pub const SLAB_SIZE: f32 = 0.6;
/// Distance over which the deck fades half-way into the horizon's haze (m).
pub const HAZE_DISTANCE: f32 = 60.0;
/// Clearance of the camera's eye above the deck (m): it never goes under the paving.
pub const EYE_CLEARANCE: f32 = 0.15;

/// In the cut-away setting with the eye under the water's level the background is open water
/// (`water_backdrop`, pool/scene_seen.wgsl): the light from the surface seen through this much water (m)
/// looking straight up, and through this much looking down, blended between.
const BACKDROP_PATH_UP: f32 = 3.0;
const BACKDROP_PATH_DOWN: f32 = 12.0;
/// Seen from under it, the water's surface fades into that open water over this much (m) before
/// a side the cut-away leaves open: the water goes on there, and the surface's edge, its
/// vertices riding the waves, does not stand out as a ragged line.
const CUT_EDGE_FADE: f32 = 0.2;

/// Height of the direction the haze's colour is taken in, per unit across (a hair above the
/// horizon, where the cube's texels look).
const HORIZON_LIFT: f32 = 0.01;
/// Terms of the polynomial the haze's colour is written as ([`horizon_fit`]).
pub const HORIZON_TERMS: usize = 5; // written out in horizon_colour (deck_shade.wgsl)

/// The deck's WGSL constants.
pub fn wgsl_constants() -> String {
    format!(
        "const COPING_WIDTH: f32 = {COPING_WIDTH:?};\nconst SLAB_SIZE: f32 = {SLAB_SIZE:?};\n\
         const HAZE_DISTANCE: f32 = {HAZE_DISTANCE:?};\nconst HORIZON_TERMS: u32 = {HORIZON_TERMS};\n\
         const HORIZON_LIFT: f32 = {HORIZON_LIFT:?};\nconst BACKDROP_PATH_UP: f32 = {BACKDROP_PATH_UP:?};\n\
         const BACKDROP_PATH_DOWN: f32 = {BACKDROP_PATH_DOWN:?};\nconst CUT_EDGE_FADE: f32 = {CUT_EDGE_FADE:?};\n"
    )
}

/// The sky at the horizon, the colour the deck fades into, as the sky cube holds it (scene
/// units; the shader clips it at SKY_RANGE as the cube does), written as a polynomial in x, the
/// distance to the sun's direction, s = √(1 − cos γ) = √2 sin(γ/2) for the angle γ between
/// them, mapped onto [-1, 1] over the horizon: the sky, Perez's smooth function of γ, needs few
/// terms in it (in the azimuth's cosine the glow around a low sun needed twelve for 1 %; an
/// arccosine for γ itself cost lavapipe 1.3 ms). Coefficients of x^0 up to x^4 in rgb; w of the
/// first two: x = s w0 + w1. Least squares over directions spaced evenly in azimuth. The deck's
/// pixels sum it in four multiply-adds and a square root, where a cube lookup cost lavapipe's
/// default frame 5 ms.
pub fn horizon_fit(daylight: &Daylight) -> [[f32; 4]; HORIZON_TERMS] {
    let towards_sun = Vec2::new(daylight.sun.x, daylight.sun.z).try_normalize().unwrap_or(Vec2::X);
    let direction = |azimuth: f32| {
        let d = towards_sun.rotate(Vec2::from_angle(azimuth));
        // The cube's texels at the horizon look a hair above it (sky_cube.wgsl).
        Vec3::new(d.x, HORIZON_LIFT, d.y).normalize()
    };
    let distance = |azimuth: f32| (1.0 - direction(azimuth).dot(daylight.sun)).max(0.0).sqrt();
    let (near, far) = (distance(0.0), distance(std::f32::consts::PI));
    // With the sun overhead s is the same all round: a constant, x = 0.
    let span = (far - near).max(1.0e-2);
    let (scale, offset) = (2.0 / span, -(far + near) / span);
    const SAMPLES: usize = 64;
    let mut normal = [[0.0f64; HORIZON_TERMS]; HORIZON_TERMS];
    let mut right = [[0.0f64; 3]; HORIZON_TERMS];
    for k in 0..SAMPLES {
        let azimuth = std::f32::consts::PI * (k as f32 + 0.5) / SAMPLES as f32;
        let x = (distance(azimuth) * scale + offset) as f64;
        let colour = daylight.radiance(direction(azimuth));
        let powers: [f64; HORIZON_TERMS] = std::array::from_fn(|i| x.powi(i as i32));
        for i in 0..HORIZON_TERMS {
            for j in 0..HORIZON_TERMS {
                normal[i][j] += powers[i] * powers[j];
            }
            for (c, value) in colour.to_array().into_iter().enumerate() {
                right[i][c] += powers[i] * value as f64;
            }
        }
    }
    // A little ridge keeps the sun overhead (every x the same) solvable: its terms in x vanish.
    for (i, row) in normal.iter_mut().enumerate() {
        row[i] += 1.0e-9 * SAMPLES as f64;
    }
    let solved = solve(normal, right);
    let mut out = [[0.0; 4]; HORIZON_TERMS];
    for (row, coefficients) in out.iter_mut().zip(solved) {
        *row = [coefficients[0] as f32, coefficients[1] as f32, coefficients[2] as f32, 0.0];
    }
    out[0][3] = scale;
    out[1][3] = offset;
    out
}

/// Solves a x = b for a symmetric positive definite a (the normal equations), three right-hand
/// sides at once, by Gaussian elimination.
fn solve(mut a: [[f64; HORIZON_TERMS]; HORIZON_TERMS], mut b: [[f64; 3]; HORIZON_TERMS]) -> [[f64; 3]; HORIZON_TERMS] {
    for col in 0..HORIZON_TERMS {
        let (pivot, pivot_b) = (a[col], b[col]);
        for row in col + 1..HORIZON_TERMS {
            let f = a[row][col] / pivot[col];
            for (x, p) in a[row].iter_mut().zip(pivot).skip(col) {
                *x -= f * p;
            }
            for (x, p) in b[row].iter_mut().zip(pivot_b) {
                *x -= f * p;
            }
        }
    }
    let mut x = [[0.0; 3]; HORIZON_TERMS];
    for row in (0..HORIZON_TERMS).rev() {
        for c in 0..3 {
            let rest: f64 = (row + 1..HORIZON_TERMS).map(|k| a[row][k] * x[k][c]).sum();
            x[row][c] = (b[row][c] - rest) / a[row][row];
        }
    }
    x
}

/// With the deck the eye stays above the paving, so the pool's walls are seen directly only
/// above the lowest the water can fall (m): the simulation's bound (2 `MAX_HEIGHT`, see
/// `sim::plan`) and the ambient waves' deepest trough (under 5 cm at their largest height), with
/// a margin. Below it the pool shows only through the water, whose shader traces it. Software
/// rasterisers test depth after shading (SwiftShader without the `EarlyFragmentTests` mode,
/// which WGSL cannot ask for), so a floor drawn under the water would cost its full shading.
pub const DRY_BAND_BOTTOM: f32 = -(2.0 * MAX_HEIGHT + 0.1);

/// How many rows (pixels, from the top) of a `size` target seen through `view_proj` from `eye`
/// can show the sky past the deck: a ray misses the deck only above the horizon, beyond
/// [`DECK_EXTENT`], or where the deck lies past the far plane. Sampled every other row at nine
/// columns (a row's rays reach farthest at its ends), plus a margin of [`SKY_ROWS_MARGIN`]; the
/// sky's pass is held to them (software rasterisers shade every pixel a pass covers, hidden or
/// not).
pub fn sky_rows(view_proj: Mat4, eye: Vec3, size: (u32, u32), rim: f32) -> u32 {
    let inverse = view_proj.inverse();
    let at = |x: f32, y: f32| Vec2::new(x / size.0 as f32 * 2.0 - 1.0, 1.0 - y / size.1 as f32 * 2.0);
    let lowest = (0..=size.1.div_ceil(2)).rev().map(|k| (2 * k).min(size.1)).find(|&y| {
        (0..=8).any(|i| shows_sky(view_proj, inverse, (eye, rim), at(size.0 as f32 * i as f32 / 8.0, y as f32)))
    });
    lowest.map_or(0, |y| (y + SKY_ROWS_MARGIN).min(size.1))
}

/// Whether the ray through `ndc` (x, y in -1..1) from `eye` misses the deck: above the horizon,
/// beyond [`DECK_EXTENT`], or meeting the deck (at the `rim`'s height, m) past the far plane.
/// `inverse`: `view_proj`'s.
fn shows_sky(view_proj: Mat4, inverse: Mat4, (eye, rim): (Vec3, f32), ndc: Vec2) -> bool {
    let dir = inverse.project_point3(ndc.extend(1.0)) - eye;
    if dir.y >= 0.0 {
        return true;
    }
    let hit = eye + dir * ((rim - eye.y) / dir.y);
    hit.x.abs().max(hit.z.abs()) > DECK_EXTENT || view_proj.project_point3(hit).z > 1.0
}

/// Rows added under the lowest sampled row that shows the sky (pixels).
const SKY_ROWS_MARGIN: u32 = 4;

/// The deck as four quads around the opening at the rim's height, facing up, with the pool
/// mesh's vertex layout (position, normal).
pub fn deck_ring(pool: PoolShape) -> (Vec<[f32; 6]>, Vec<u32>) {
    let (w, e, y) = (pool.half_width, DECK_EXTENT, pool.rim);
    let inner = [Vec3::new(-w, y, -w), Vec3::new(w, y, -w), Vec3::new(w, y, w), Vec3::new(-w, y, w)];
    let outer = [Vec3::new(-e, y, -e), Vec3::new(e, y, -e), Vec3::new(e, y, e), Vec3::new(-e, y, e)];
    let positions: Vec<Vec3> = inner.iter().chain(outer.iter()).copied().collect();
    let vertices = positions.iter().map(|p| [p.x, p.y, p.z, 0.0, 1.0, 0.0]).collect();
    let mut indices = Vec::new();
    for i in 0..4u32 {
        let j = (i + 1) % 4;
        push_triangle(&mut indices, &positions, [i, j, 4 + j], Vec3::Y);
        push_triangle(&mut indices, &positions, [i, 4 + j, 4 + i], Vec3::Y);
    }
    (vertices, indices)
}

crate::choices! {
    /// Where the pool is (the `setting` parameter): sunk in the paved deck, or the classic's
    /// cut-away box.
    pub enum Setting {
        Deck = "deck",
        Cutaway = "cutaway",
    }
}

/// Where the pool is: in the deck or the cut-away box. (The parameter table, `params::table`, lists them in this order.)
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        name: "setting",
        label: "Setting",
        group: "Light",
        unit: "",
        control: Control::Choice { values: Setting::VALUES, names: Setting::NAMES },
        default: 0.0,
        help: "Where the pool is: sunk in a paved deck under the sky, or the classic's cut-away box, open at the near walls so you see the water's cross-section.",
    },
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sky::SKY_RANGE;

    #[test]
    fn the_sky_is_drawn_in_every_row_where_a_pixel_can_see_past_the_deck() {
        use crate::camera::OrbitCamera;
        let size = (800, 600);
        // The default view, low ones across the deck (held above it, as the demo holds them), a
        // high one and one from the far limit.
        let views = [(-25.0, 34.0, 3.4), (-25.0, 2.0, 3.4), (60.0, 5.0, 12.0), (150.0, 60.0, 12.0), (10.0, 1.0, 1.5)];
        for (yaw, pitch, distance) in views {
            let mut camera = OrbitCamera { yaw, pitch, distance, ..OrbitCamera::default() };
            camera.keep_eye_above(PoolShape::CLASSIC.rim + EYE_CLEARANCE);
            let view_proj = camera.view_projection(size.0 as f32 / size.1 as f32);
            let rows = sky_rows(view_proj, camera.eye(), size, PoolShape::CLASSIC.rim);
            // Every pixel of every other column (sky_rows samples nine).
            let inverse = view_proj.inverse();
            let mut lowest_sky: Option<u32> = None;
            for y in 0..size.1 {
                for x in (0..size.0).step_by(2) {
                    let ndc = Vec2::new(
                        (x as f32 + 0.5) / size.0 as f32 * 2.0 - 1.0,
                        1.0 - (y as f32 + 0.5) / size.1 as f32 * 2.0,
                    );
                    let sky = shows_sky(view_proj, inverse, (camera.eye(), PoolShape::CLASSIC.rim), ndc);
                    if sky {
                        lowest_sky = Some(y);
                    }
                }
            }
            println!("view ({yaw}°, {pitch}°, {distance} m): sky rows {rows}, lowest pixel showing sky {lowest_sky:?}");
            match lowest_sky {
                Some(y) => assert!(y < rows, "a pixel in row {y} shows the sky, but only {rows} rows are drawn"),
                None => assert!(rows <= SKY_ROWS_MARGIN, "{rows} rows drawn with no sky in view"),
            }
            // The pass is held to what shows: no more than a few rows past the last sky pixel.
            assert!(rows <= lowest_sky.map_or(0, |y| y + 1) + 2 * SKY_ROWS_MARGIN, "{rows} rows for {lowest_sky:?}");
        }
    }

    #[test]
    fn the_water_never_falls_below_the_dry_band_the_deck_shows_the_pool_in() {
        use crate::ambient::{params, AmbientModel, AmbientSettings, AmbientWaves};
        let spec = |name: &str| params::PARAMS.iter().find(|p| p.name == name).expect("an ambient parameter");
        let w = PoolShape::CLASSIC.half_width;
        let mut deepest = 0.0f32;
        for model in [AmbientModel::Sines, AmbientModel::Modes, AmbientModel::Gerstner, AmbientModel::Fft] {
            for wind in [spec("wind_speed").min(), spec("wind_speed").max()] {
                let settings = AmbientSettings {
                    wind_speed: wind,
                    significant_height: spec("wave_height").max(),
                    fft_size: spec("fft_size").max() as usize,
                    ..AmbientSettings::default_for(model)
                };
                let waves = AmbientWaves::new(&settings);
                for step in 0..24 {
                    let t = step as f64 * 0.83;
                    for j in 0..=16 {
                        for i in 0..=16 {
                            let (x, z) = (w * (i as f32 / 8.0 - 1.0), w * (j as f32 / 8.0 - 1.0));
                            deepest = deepest.min(waves.sample(x, z, t)[0]);
                        }
                    }
                }
            }
        }
        let lowest = -2.0 * MAX_HEIGHT + deepest;
        println!(
            "deepest ambient trough {:.4} m at the largest wave height; lowest water {:.4} m; dry band from {:.4} m",
            deepest, lowest, DRY_BAND_BOTTOM
        );
        assert!(
            lowest > DRY_BAND_BOTTOM + 0.02,
            "the water can fall to {lowest} m, under the dry band's {DRY_BAND_BOTTOM} m"
        );
    }

    /// The fit's colour towards horizontal direction d, as deck_shade.wgsl's horizon_colour.
    fn fitted(fit: &[[f32; 4]; HORIZON_TERMS], d: Vec2, sun: Vec3) -> Vec3 {
        let distance = (1.0 - Vec3::new(d.x, HORIZON_LIFT, d.y).normalize().dot(sun)).max(0.0).sqrt();
        let c = distance * fit[0][3] + fit[1][3];
        let colour = fit.iter().rev().fold(Vec3::ZERO, |sum, term| sum * c + Vec3::new(term[0], term[1], term[2]));
        colour.clamp(Vec3::ZERO, Vec3::splat(SKY_RANGE))
    }

    #[test]
    fn the_hazes_colour_is_the_skys_at_the_horizon_all_round_for_any_sun() {
        let mut worst: f32 = 0.0;
        for elevation in [10.0f32, 25.0, 55.0, 80.0, 90.0] {
            for sun_azimuth in [-150.0f32, 35.0, 120.0] {
                let (e, a) = (elevation.to_radians(), sun_azimuth.to_radians());
                let daylight = Daylight::new(Vec3::new(e.cos() * a.cos(), e.sin(), e.cos() * a.sin()));
                let fit = horizon_fit(&daylight);
                for k in 0..360 {
                    let d = Vec2::from_angle((k as f32).to_radians());
                    let sky = daylight.radiance(Vec3::new(d.x, HORIZON_LIFT, d.y)).min(Vec3::splat(SKY_RANGE));
                    // Error relative to the sky's brightest channel there.
                    let error = (fitted(&fit, d, daylight.sun) - sky).abs().max_element() / sky.max_element();
                    worst = worst.max(error);
                }
            }
        }
        println!("largest error of the horizon's fit: {:.2} % of the sky's brightest channel", worst * 100.0);
        assert!(worst < 0.02, "the haze's colour is off the sky's by {:.1} %", worst * 100.0);
    }
}
