//! The objects' regions of the water surface: where the surface can show an object, it is
//! drawn by a variant that traces it, elsewhere by one that does not (software rasterisers
//! shade every branch, so an object traced everywhere costs every pixel). Each region's draw
//! takes only the band of grid rows or columns that can reach its rectangle: the surface's
//! triangles cost software rasterisers per draw whether or not the scissor keeps any pixel.

use std::ops::Range;

use glam::{Vec3, Vec4Swizzles};

use super::meshes::GridBand;
use crate::bodies::BodyId;
use crate::render::{Features, View};
use crate::sim::MAX_HEIGHT;

/// Margin around an object's region of the water surface, as a fraction of the region's
/// larger side, plus [`REGION_MARGIN_PX`]: waves tilt the surface and bend what it shows by
/// a distance that grows with the distance between the object and the surface it is seen
/// in, which is about the object's size. With 0.15, forty strong drops still draw what tracing
/// the objects everywhere draws but for 3e-5 of the pixels (a test checks it); 0.25 cost 2 ms
/// more of lavapipe's default frame.
const REGION_MARGIN: f32 = 0.15;
const REGION_MARGIN_PX: f32 = 4.0;
/// Above this share of the target the region is not worth a second set of draws.
const REGION_MAX_SHARE: f32 = 0.5;

/// Which variant draws which part of the water surface on a `size` target, as (rectangle x,
/// y, width, height in pixels, features). With the camera above the water an object can be
/// seen, reflected or refracted, only near the screen bound of the column from the surface
/// down to the bottom of the object or of its mirror image, grown by [`REGION_MARGIN`]: there
/// the surface is drawn by a variant with that object, elsewhere by one without. `None`: draw
/// the whole surface with `features` (no objects, the camera under water, or regions too large
/// to gain from).
pub fn surface_regions(view: &View, size: (u32, u32)) -> Option<Vec<([u32; 4], Features)>> {
    let features = view.features();
    let plain = features.without_objects();
    let mut bounds: Vec<(Vec3, f32, Features)> = Vec::new();
    for id in BodyId::all() {
        if let Some(body) = &view.bodies[id.0] {
            let with = Features { bodies: id.bit() as u8, ..plain };
            bounds.push((body.pose.position, (id.kind().bound)(body), with));
        }
    }
    if bounds.is_empty() || view.eye.y < 0.0 {
        return None;
    }
    let (w, h) = (size.0 as f32, size.1 as f32);
    let mut rects = Vec::new();
    for (centre, radius, with) in bounds {
        // From above, the surface shows what is under water refracted (raised towards the
        // surface, straight above itself) and what is above it mirrored: both within the
        // column over the object, from the surface down to its own or its mirror image's bottom.
        let bottom = -(centre.y.abs() + radius);
        let low = Vec3::new(centre.x - radius, bottom, centre.z - radius);
        let high = Vec3::new(centre.x + radius, 0.0, centre.z + radius);
        let [x0, y0, x1, y1] = screen_bounds(view, low, high, size)?;
        let margin = REGION_MARGIN * (x1 - x0).max(y1 - y0) + REGION_MARGIN_PX;
        let pixel = |v: f32, end: f32| v.round().clamp(0.0, end) as u32;
        let rect = [pixel(x0 - margin, w), pixel(y0 - margin, h), pixel(x1 + margin, w), pixel(y1 + margin, h)];
        rects.push((rect, with));
    }
    let parts = partition(&rects, plain, size);
    let covered: u32 = parts.iter().filter(|p| p.1 != plain).map(|p| p.0[2] * p.0[3]).sum();
    (covered as f32 <= REGION_MAX_SHARE * w * h).then_some(parts)
}

/// Cuts a `size` target along the edges of `rects` (x0, y0, x1, y1, each with the features it
/// needs) into rectangles (x, y, width, height) with the features of every rect they lie in
/// (`base` outside all), merging neighbours in a row that need the same.
fn partition(rects: &[([u32; 4], Features)], base: Features, size: (u32, u32)) -> Vec<([u32; 4], Features)> {
    let edges = |a: usize, b: usize, end: u32| {
        let mut v: Vec<u32> = rects.iter().flat_map(|r| [r.0[a], r.0[b]]).chain([0, end]).collect();
        v.sort_unstable();
        v.dedup();
        v
    };
    let (xs, ys) = (edges(0, 2, size.0), edges(1, 3, size.1));
    let mut parts = Vec::new();
    for band in ys.windows(2) {
        let mut run: Option<(u32, u32, Features)> = None;
        for cell in xs.windows(2) {
            let needs = rects
                .iter()
                .filter(|(r, _)| cell[0] >= r[0] && cell[1] <= r[2] && band[0] >= r[1] && band[1] <= r[3])
                .fold(base, |f, (_, with)| Features { bodies: f.bodies | with.bodies, ..f });
            run = match run {
                Some((x0, _, kind)) if kind == needs => Some((x0, cell[1], kind)),
                Some((x0, x1, kind)) => {
                    parts.push(([x0, band[0], x1 - x0, band[1] - band[0]], kind));
                    Some((cell[0], cell[1], needs))
                }
                None => Some((cell[0], cell[1], needs)),
            };
        }
        if let Some((x0, x1, kind)) = run {
            parts.push(([x0, band[0], x1 - x0, band[1] - band[0]], kind));
        }
    }
    parts.retain(|p| p.0[2] > 0 && p.0[3] > 0);
    parts
}

/// How far a grid point of the surface can move from its rest place (m): up and down by the
/// simulation's bound (twice `MAX_HEIGHT`, see `sim::plan`) and the ambient waves' (a few
/// centimetres), sideways by what the Gerstner and choppy FFT waves carry (under 10 cm).
const SURFACE_REACH_UP_DOWN: f32 = 2.0 * MAX_HEIGHT + 0.1;
const SURFACE_REACH_SIDEWAYS: f32 = 0.1;

/// The screen bounds (x0, y0, x1, y1 in pixels of a `size` target, y down) of the box from
/// `low` to `high` (m); `None` when a corner is behind the eye.
fn screen_bounds(view: &View, low: Vec3, high: Vec3, size: (u32, u32)) -> Option<[f32; 4]> {
    let (mut lo, mut hi) = (glam::Vec2::splat(f32::INFINITY), glam::Vec2::splat(f32::NEG_INFINITY));
    for corner in 0..8 {
        let pick = |bit: u32, a: f32, b: f32| if corner & bit == 0 { a } else { b };
        let p = Vec3::new(pick(1, low.x, high.x), pick(2, low.y, high.y), pick(4, low.z, high.z));
        let clip = view.view_proj * p.extend(1.0);
        if clip.w <= 1e-3 {
            return None;
        }
        lo = lo.min(clip.xy() / clip.w);
        hi = hi.max(clip.xy() / clip.w);
    }
    // NDC (y up) to pixels (y down).
    let (w, h) = (size.0 as f32, size.1 as f32);
    Some([(lo.x * 0.5 + 0.5) * w, (0.5 - hi.y * 0.5) * h, (hi.x * 0.5 + 0.5) * w, (0.5 - lo.y * 0.5) * h])
}

/// The band of the `n` x `n` water grid over a pool `half_width` (m) each way (rows or columns,
/// whichever has fewer cells) a draw
/// into `rect` (x, y, width, height in pixels of a `size` target) needs: every row and every
/// column whose strip of the surface, moved as far as any wave can move it, can reach a pixel
/// of the rectangle. `None`: the whole grid (a strip behind the eye).
pub fn grid_band(view: &View, rect: [u32; 4], size: (u32, u32), (n, half_width): (u32, f32)) -> Option<GridBand> {
    let (x0, y0, x1, y1) = (rect[0] as f32, rect[1] as f32, (rect[0] + rect[2]) as f32, (rect[1] + rect[3]) as f32);
    let half = half_width + SURFACE_REACH_SIDEWAYS;
    let reaches = |across: Range<f32>, rows: bool| -> Option<bool> {
        let (side0, side1) = (across.start - SURFACE_REACH_SIDEWAYS, across.end + SURFACE_REACH_SIDEWAYS);
        let (low, high) = if rows {
            (Vec3::new(-half, -SURFACE_REACH_UP_DOWN, side0), Vec3::new(half, SURFACE_REACH_UP_DOWN, side1))
        } else {
            (Vec3::new(side0, -SURFACE_REACH_UP_DOWN, -half), Vec3::new(side1, SURFACE_REACH_UP_DOWN, half))
        };
        let [px0, py0, px1, py1] = screen_bounds(view, low, high, size)?;
        Some(px1 >= x0 && px0 <= x1 && py1 >= y0 && py0 <= y1)
    };
    let cell = 2.0 * half_width / n as f32;
    let strips = |rows: bool| -> Option<Range<u32>> {
        let mut hit: Option<Range<u32>> = None;
        for k in 0..n {
            let across = -half_width + cell * k as f32..-half_width + cell * (k + 1) as f32;
            if reaches(across, rows)? {
                hit = Some(hit.map_or(k..k + 1, |r| r.start..k + 1));
            }
        }
        Some(hit.unwrap_or(0..0))
    };
    let (rows, columns) = (strips(true)?, strips(false)?);
    Some(if rows.len() <= columns.len() { GridBand::Rows(rows) } else { GridBand::Columns(columns) })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_partition_covers_the_target_once_and_gives_each_part_the_objects_it_can_show() {
        let size = (800, 600);
        let base = Features { caustics: true, ..Features::default() };
        let (sphere, duck) = (Features { bodies: 1, ..base }, Features { bodies: 2, ..base });
        let rects = [([100, 100, 300, 250], sphere), ([250, 200, 500, 400], duck)];
        let parts = partition(&rects, base, size);
        let area = |f: Features| parts.iter().filter(|p| p.1 == f).map(|p| p.0[2] * p.0[3]).sum::<u32>();
        let both = Features { bodies: 3, ..base };
        println!(
            "{} rectangles: {} px plain, {} sphere, {} duck, {} both",
            parts.len(),
            area(base),
            area(sphere),
            area(duck),
            area(both)
        );
        assert_eq!(area(base) + area(sphere) + area(duck) + area(both), 800 * 600);
        assert_eq!(area(both), 50 * 50);
        assert_eq!(area(sphere), 200 * 150 - 50 * 50);
        assert_eq!(area(duck), 250 * 200 - 50 * 50);
        assert!(parts.len() <= 16, "{} rectangles", parts.len());
    }
}
