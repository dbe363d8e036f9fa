//! The island in the sea: foam in its shallows and up its sand, its mirror image, the caustics
//! on its floor, its land's detail close up, its outline against the sky.

use super::*;

/// Where the eye's ray through pixel (x, y) of a `size` frame meets the mean sea plane (x, z in
/// m), if it does.
fn rest_point(d: &WaterDemo, size: (u32, u32), x: u32, y: u32) -> Option<Vec2> {
    let inverse = d.camera().view_projection(size.0 as f32 / size.1 as f32).inverse();
    let ndc = Vec2::new((x as f32 + 0.5) / size.0 as f32 * 2.0 - 1.0, 1.0 - (y as f32 + 0.5) / size.1 as f32 * 2.0);
    let far = inverse * Vec4::new(ndc.x, ndc.y, 1.0, 1.0);
    let eye = d.camera().eye();
    let dir = (far.truncate() / far.w - eye).normalize();
    (dir.y < 0.0).then(|| {
        let p = eye + dir * (eye.y / -dir.y);
        Vec2::new(p.x, p.z)
    })
}

/// The water's depth (m) at a point of the sea plane: the island's ground under it.
fn depth_at(p: Vec2) -> f32 {
    -island::height(p, island::Place::Offshore)
}

/// The first point, walking out from the island's middle towards the origin, where `found`.
fn out_from_the_island(found: impl Fn(Vec2) -> bool) -> Vec2 {
    let centre = Vec2::from(island::CENTRE);
    let out = -centre.normalize();
    (0..400).map(|r| centre + out * r as f32).find(|&p| found(p)).expect("such a point off the island")
}

/// A sea demo (set up further by `setup`) looking `pitch` degrees down from `distance` m at
/// `spot` on the water, only the shore's foam drawn if `shore`.
fn sea_over(spot: Vec2, (pitch, distance): (f32, f32), shore: bool, setup: impl FnOnce(&mut WaterDemo)) -> WaterDemo {
    let mut d = demo(DemoOptions::default());
    d.params.set(ParamId::Scene, 1.0);
    d.params.set(ParamId::SeaObjects, 0.0);
    setup(&mut d);
    d.sync_scene();
    (d.camera_mut().pitch, d.camera_mut().distance, d.camera_mut().yaw) = (pitch, distance, 20.0);
    d.camera_mut().target = Vec3::new(spot.x, 0.0, spot.y);
    d.camera_mut().clamp();
    d.set_sea_foam(false, false, shore);
    d
}

#[test]
fn the_shore_foams_in_the_shallows_and_nowhere_in_deep_water() {
    // Seen from 60 m above the coast, where the island's ground first dips under the sea on the
    // way out from its middle towards the origin.
    let coast = out_from_the_island(|p| island::height(p, island::Place::Offshore) < 0.0);
    let mut frames = Vec::new();
    let mut d = demo(DemoOptions::default());
    for shore in [true, false] {
        d = sea_over(coast, (55.0, 70.0), shore, |_| {});
        frames.push(render(&mut d, SIZE.0, SIZE.1, 5, 1.0 / 60.0));
    }
    let share = |a: usize, b: usize| 100.0 * a as f64 / b.max(1) as f64;
    let (mut foamed, mut foamed_shallow, mut deep, mut deep_foamed, mut edge, mut edge_foamed) = (0, 0, 0, 0, 0, 0);
    // The sand the waves run up (ground up to 1.5 m above the rest level) and the land above
    // the highest crests (1.2 m) and the swash (SWASH_HEIGHT, 0.2 m), with a margin.
    let (mut swash, mut swash_foamed, mut high, mut high_foamed) = (0, 0, 0, 0);
    for (x, y) in Area::ALL.pixels(&frames[0]) {
        let Some(depth) = rest_point(&d, SIZE, x, y).map(depth_at) else { continue };
        let whiter = frames[0].unit_luma(x, y) > frames[1].unit_luma(x, y) + 0.05;
        foamed += usize::from(whiter);
        // The waves (1.2 m significant height) lift and lower the water over the rest plane.
        foamed_shallow += usize::from(whiter && depth < island::SHORE_FOAM_DEPTH + 1.2);
        deep += usize::from(depth > 5.0);
        deep_foamed += usize::from(whiter && depth > 5.0);
        edge += usize::from(depth > 0.0 && depth < 0.5);
        edge_foamed += usize::from(whiter && depth > 0.0 && depth < 0.5);
        swash += usize::from(depth < 0.0 && depth > -1.5);
        swash_foamed += usize::from(whiter && depth < 0.0 && depth > -1.5);
        high += usize::from(depth < -2.0);
        high_foamed += usize::from(whiter && depth < -2.0);
    }
    println!(
        "the swash: {:.1} % of the sand up to 1.5 m foamed, {high_foamed} of {high} pixels of land above 2 m",
        share(swash_foamed, swash)
    );
    println!(
        "{foamed} pixels foamed: {:.1} % of them over the shallows; {:.1} % of the water within 0.5 m of the \
         line foamed; {deep_foamed} of {deep} pixels of deep water",
        share(foamed_shallow, foamed),
        share(edge_foamed, edge)
    );
    assert!(foamed > 100 && edge > 50, "the coast is not in view: {foamed} foamed, {edge} at the waterline");
    assert!(share(foamed_shallow, foamed) > 95.0, "foam away from the shallows");
    assert!(share(edge_foamed, edge) > 30.0, "the waterline does not foam");
    assert!(deep > 1000 && deep_foamed == 0, "foam on deep water: {deep_foamed}");
    // The foam runs up the sand by the water (the waves' own foam over it alone: 9.5 %; with the
    // swash 17.7 %, 2026-11-30), never up the land.
    assert!(swash > 1000 && share(swash_foamed, swash) > 13.0, "no swash up the sand");
    assert!(high > 1000 && high_foamed == 0, "foam on the land above the waves: {high_foamed}");
}

#[test]
fn the_island_is_mirrored_in_the_sea_below_it() {
    // The lesson's view of the island, drawn with it and without it.
    let mut frames = Vec::new();
    let mut d = demo(DemoOptions::default());
    for shown in [1.0, 0.0] {
        d = demo(DemoOptions::default());
        d.apply_preset(wavepool::presets::find("sea").expect("the sea preset"));
        d.params.set(ParamId::SeaIsland, shown);
        d.sync_scene();
        frames.push(render(&mut d, SIZE.0, SIZE.1, 2, 1.0 / 60.0));
    }
    let changed = |x: u32, y: u32| {
        let (a, b) = (frames[0].unit_rgb(x, y), frames[1].unit_rgb(x, y));
        (0..3).map(|c| (a[c] - b[c]).abs()).fold(0.0, f32::max) > 4.0 / 255.0
    };
    // The island's columns: where it stands over the horizon.
    let row = horizon_row(&d, SIZE.1).floor() as u32;
    let island_columns: Vec<bool> = (0..SIZE.0).map(|x| (0..row.saturating_sub(2)).any(|y| changed(x, y))).collect();
    // Deep water (the floor out of sight) under the horizon: in those columns, and in those
    // clear of them by 10 pixels.
    let (mut under, mut under_changed, mut clear, mut clear_changed) = (0, 0, 0, 0);
    for x in 0..SIZE.0 {
        let near = (x.saturating_sub(10)..(x + 10).min(SIZE.0)).any(|c| island_columns[c as usize]);
        for y in row + 2..SIZE.1 {
            let deep = rest_point(&d, SIZE, x, y).is_some_and(|p| depth_at(p) > island::SEE_DEPTH);
            if !deep {
                continue;
            }
            if island_columns[x as usize] && y < row + SIZE.1 / 6 {
                under += 1;
                under_changed += usize::from(changed(x, y));
            } else if !near {
                clear += 1;
                clear_changed += usize::from(changed(x, y));
            }
        }
    }
    let share = |a: usize, b: usize| 100.0 * a as f64 / b.max(1) as f64;
    let columns = island_columns.iter().filter(|&&c| c).count();
    println!(
        "island over {columns} columns; hiding it changes {:.1} % of the deep water below it and {:.2} % elsewhere",
        share(under_changed, under),
        share(clear_changed, clear)
    );
    assert!(columns > SIZE.0 as usize / 10, "the island is not in view");
    assert!(under > 200 && share(under_changed, under) > 40.0, "no mirror image of the island");
    assert!(clear > 1000 && share(clear_changed, clear) < 0.5, "hiding the island changes the open sea");
}

#[test]
fn the_waves_focus_sunlight_into_caustics_on_the_shallows_floor() {
    // Looking down 60° at water about 5 m deep off the island's coast, the sun 70° up.
    let spot = out_from_the_island(|p| depth_at(p) > 5.0);
    let mut frames = Vec::new();
    let mut d = demo(DemoOptions::default());
    for caustics in [1.0, 0.0] {
        d = sea_over(spot, (60.0, 25.0), false, |d| {
            d.params.set(ParamId::SunElevation, 70.0);
            d.params.set(ParamId::Caustics, caustics);
        });
        frames.push(render(&mut d, SIZE.0, SIZE.1, 5, 1.0 / 60.0));
    }
    // Over water 2-10 m deep, the floor's light with the caustics against without, pixel by
    // pixel: focused here, spread thin there, about as much in all.
    let ratios: Vec<f64> = Area::ALL
        .pixels(&frames[0])
        .into_iter()
        .filter(|&(x, y)| rest_point(&d, SIZE, x, y).map(depth_at).is_some_and(|depth| depth > 2.0 && depth < 10.0))
        .map(|(x, y)| (frames[0].unit_luma(x, y) / frames[1].unit_luma(x, y).max(1e-3)) as f64)
        .collect();
    let n = ratios.len().max(1) as f64;
    let mean = ratios.iter().sum::<f64>() / n;
    let spread = (ratios.iter().map(|r| (r - mean).powi(2)).sum::<f64>() / n).sqrt();
    let brightest = ratios.iter().cloned().fold(0.0, f64::max);
    println!(
        "{} pixels over 2-10 m of water: their luma with caustics over without, mean {mean:.3}, std {spread:.3}, \
         brightest {brightest:.2}",
        ratios.len()
    );
    assert!(ratios.len() > 5000, "the shallows are not in view");
    assert!(spread > 0.08 && brightest > 1.3, "no caustics on the floor");
    // 1/|det| taken at the surface rather than over the floor averages a little over 1.
    assert!(mean > 0.85 && mean < 1.15, "caustics should move light, not make it");
}

#[test]
fn a_click_in_the_shallows_lights_the_sand_under_it_with_the_ripples_caustics() {
    // The island at the shore, its shallows across the patch; looking down 60° from 25 m at the
    // patch's middle (about 6 m of water), the sun 70° up. The same sea clicked and unclicked,
    // with the floor's caustics and without: how much the ripples change the water's light.
    let mut changes = Vec::new();
    for caustics in [1.0, 0.0] {
        let (mut frames, mut view) = (Vec::new(), None);
        for click in [true, false] {
            let mut d = sea_over(Vec2::ZERO, (60.0, 25.0), false, |d| {
                d.params.set(ParamId::SeaIsland, 2.0);
                d.params.set(ParamId::SunElevation, 70.0);
                d.params.set(ParamId::Caustics, caustics);
            });
            render(&mut d, SIZE.0, SIZE.1, 1, 1.0 / 60.0);
            if click {
                d.pointer_down(SIZE.0 as f32 / 2.0, SIZE.1 as f32 / 2.0);
                d.pointer_up();
            }
            frames.push(render(&mut d, SIZE.0, SIZE.1, 45, 1.0 / 60.0));
            view = Some(d);
        }
        let view = view.expect("a demo");
        let near = Area(0.2, 0.2, 0.8, 0.8).pixels(&frames[0]);
        let depth =
            |&(x, y): &(u32, u32)| rest_point(&view, SIZE, x, y).map(|p| -island::height(p, island::Place::Shore));
        let shallow: Vec<_> = near.into_iter().filter(|p| depth(p).is_some_and(|d| d > 1.0 && d < 12.0)).collect();
        let mean = shallow
            .iter()
            .map(|&(x, y)| (frames[0].unit_luma(x, y) - frames[1].unit_luma(x, y)).abs() as f64)
            .sum::<f64>()
            / shallow.len().max(1) as f64;
        changes.push((mean, shallow.len()));
    }
    println!(
        "the ripples change the luma of {} pixels over 1-12 m of water by {:.4} on average with the floor's caustics, \
         {:.4} without",
        changes[0].1, changes[0].0, changes[1].0
    );
    assert!(changes[0].1 > 5000, "the shallows are not in view");
    assert!(changes[0].0 > 2.0 * changes[1].0, "the ripples' caustics do not show on the sand");
}

#[test]
fn the_beach_close_up_shows_detail_finer_than_its_map() {
    // Looking down 40° from 12 m at the land 6 m in from the coast, about 1 m above the sea
    // (the island's map has a texel every 2.5 m: shaded from it alone the land is smooth there).
    let coast = out_from_the_island(|p| island::height(p, island::Place::Offshore) < 0.0);
    let beach = coast + (Vec2::from(island::CENTRE) - coast).normalize() * 6.0;
    let mut d = sea_over(beach, (40.0, 12.0), false, |_| {});
    let frame = render(&mut d, SIZE.0, SIZE.1, 2, 1.0 / 60.0);
    const LAND_ABOVE: f32 = 1.5;
    // Measured (2026-11-30): shaded from the map alone the rms below is 0.19; with the detail
    // (land.wgsl's land_detail) 1.83.
    const GRAIN_AT_LEAST: f64 = 0.8;
    // The land's pixels: where the eye's ray has gone under the ground before the sea plane,
    // with the ground there above the highest crests (1.2 m), so that no wave is among them.
    let land: Vec<bool> = (0..SIZE.0 * SIZE.1)
        .map(|i| {
            let p = rest_point(&d, SIZE, i % SIZE.0, i / SIZE.0);
            p.is_some_and(|p| island::height(p, island::Place::Offshore) > LAND_ABOVE)
        })
        .collect();
    // Over land pixels whose 11x11 neighbourhood is land: luma less its neighbourhood's mean
    // (the detail finer than 11 pixels, half a metre or so here; a slope's even shade cancels
    // in the mean).
    const R: u32 = 5;
    let side = 2 * R + 1;
    let mut residuals = Vec::new();
    for y in R..SIZE.1 - R {
        for x in R..SIZE.0 - R {
            let around = (0..side * side).map(|i| (x + i % side - R, y + i / side - R));
            if !around.clone().all(|(u, v)| land[(v * SIZE.0 + u) as usize]) {
                continue;
            }
            let mean = around.map(|(u, v)| frame.luma(u, v)).sum::<f64>() / (side * side) as f64;
            residuals.push(frame.luma(x, y) - mean);
        }
    }
    let grain = (residuals.iter().map(|r| r * r).sum::<f64>() / residuals.len().max(1) as f64).sqrt();
    println!("{} land pixels: luma off its 11x11 mean, rms {grain:.2} (of 255)", residuals.len());
    assert!(residuals.len() > 5000, "the land is not in view");
    assert!(grain > GRAIN_AT_LEAST, "the land is as smooth as its map");
}

/// The island's outline against the sky is blended, not stair-stepped: in each column it
/// stands in, the first pixel from the top that the island changes, against the same frame
/// without it, is mostly sky with some land (its luma 5 to 50 % of the way from the sky's to
/// the land's two rows down) in a good share of them: the pixels whose middles lie within half
/// a pixel over the outline take its land's share. On 2026-12-01 in 42 of 119 columns; with
/// the outline's blend left out in none of 118 (the first pixel changed is land, 60 % of the
/// way and more).
#[test]
fn the_islands_outline_against_the_sky_is_blended_not_stepped() {
    let mut frames = Vec::new();
    let mut row = 0;
    for shown in [1.0, 0.0] {
        let mut d = demo(DemoOptions::default());
        d.apply_preset(wavepool::presets::find("sea").expect("the sea preset"));
        d.params.set(ParamId::SeaIsland, shown);
        d.sync_scene();
        frames.push(render(&mut d, SIZE.0, SIZE.1, 2, 1.0 / 60.0));
        row = horizon_row(&d, SIZE.1).floor() as u32;
    }
    let (mut columns, mut blended) = (0, 0);
    for x in 0..SIZE.0 {
        let Some(y) = (0..row.saturating_sub(4)).find(|&y| (frames[0].luma(x, y) - frames[1].luma(x, y)).abs() > 4.0)
        else {
            continue;
        };
        let (sky, land, edge) = (frames[1].luma(x, y), frames[0].luma(x, y + 2), frames[0].luma(x, y));
        if (sky - land).abs() < 20.0 {
            continue;
        }
        columns += 1;
        let along = (edge - sky) / (land - sky);
        blended += usize::from(along > 0.05 && along < 0.5);
    }
    let share = 100.0 * blended as f64 / columns.max(1) as f64;
    println!("the island's outline: {blended} of {columns} columns with a blended pixel over it ({share:.0} %)");
    assert!(columns > SIZE.0 as usize / 10, "the island is not in view: {columns} columns");
    assert!(share > 20.0, "the island's outline is stepped: {share:.0} % of its columns blended");
}
