// Drops and bodies. Each drop adds a smooth cosine bump h += s * (1 - cos(pi * (1 - d/r))) / 2
// inside its radius r; the CPU computes the bumps' mean over the grid and it is subtracted
// everywhere, so a drop adds no net water. A moving body pushes the surface by the change of
// the water column it displaces (displaced_column in sim/coupling.rs): up ahead of and above
// it, down behind it; the volume it takes up in the water is accounted for by the rest level
// the mean is held at (sim_normals.wgsl).

// Column (m) of an ellipsoid below the rest level over the cell at pool point x, each depth y
// weighted by exp(y / L): integral of exp(y / L) dy over the part of the vertical line inside
// it. Averaged over the cell, as in sim/coupling.rs: the chord's length at the silhouette
// (cell_mean_sqrt) and its ends' weights (cell_mean_weight), each spread by its change across
// the cell, so that a waterline crosses a cell a little at a time.
fn displaced_column(x: vec2<f32>, first: i32) -> f32 {
    let centre = sim.hulls[first].xyz;
    let m = mat3x3<f32>(sim.hulls[first + 1].xyz, sim.hulls[first + 2].xyz, sim.hulls[first + 3].xyz);
    let u0 = m * (vec3<f32>(x.x, 0.0, x.y) - centre);
    let d = m[1];
    let a = dot(d, d);
    let b = dot(u0, d);
    let c = dot(u0, u0) - 1.0;
    // The chord's ends y = (-b ± s) / a with s² = b² - a c, and their change across the cell.
    let b_slope = vec2<f32>(dot(m[0], d), dot(m[2], d));
    let disc_slope = 2.0 * (b * b_slope - a * vec2<f32>(dot(u0, m[0]), dot(u0, m[2])));
    let half_cell = 0.5 * sim.grid.z;
    let s = cell_mean_sqrt(b * b - a * c, half_cell * (abs(disc_slope.x) + abs(disc_slope.y)));
    let s_slope = disc_slope / (2.0 * max(s, 1e-30));
    let depth = sim.bodies.z;
    let top = cell_mean_weight((-b + s) / a, half_cell * dot(abs(s_slope - b_slope), vec2<f32>(1.0)) / a, depth);
    let bottom = cell_mean_weight((-b - s) / a, half_cell * dot(abs(s_slope + b_slope), vec2<f32>(1.0)) / a, depth);
    return select(max(depth * (top - bottom), 0.0), 0.0, s <= 0.0 || a <= 0.0);
}

// Mean of sqrt(max(t, 0)) for t even over disc ± spread, (P^3/2 - Q^3/2) / (3 spread) with the
// ends P, Q clamped at 0, written with no division by a spread of 0 (as in sim/coupling.rs).
fn cell_mean_sqrt(disc: f32, spread: f32) -> f32 {
    let p = max(disc + spread, 0.0);
    let q = max(disc - spread, 0.0);
    let both = 2.0 * (p + sqrt(p * q) + q) / (3.0 * (sqrt(p) + sqrt(q)) + 1e-30);
    let one_end = p * sqrt(p) / max(3.0 * spread, 1e-30);
    return select(one_end, both, q > 0.0);
}

// Mean of exp(min(t, 0) / depth) for t even over y ± spread: a chord's end's weight, 1 above the
// rest level, over a cell; (e^u - 1) / u from its series where u is small (as in
// sim/coupling.rs).
fn cell_mean_weight(y: f32, spread: f32, depth: f32) -> f32 {
    let lo = min(y - spread, 0.0);
    let hi = min(y + spread, 0.0);
    let u = (hi - lo) / depth;
    let series = exp(lo / depth) * (1.0 + u * (0.5 + u * (1.0 / 6.0 + u * (1.0 / 24.0 + u / 120.0))));
    let below = select((exp(hi / depth) - exp(lo / depth)) / max(u, 1e-30), series, u < 0.1);
    let share_below = clamp((spread - y) / max(2.0 * spread, 1e-30), 0.0, 1.0);
    return share_below * below + 1.0 - share_below;
}

// Which step of the frame this pass comes before: its moves are applied, and the drops
// with step 0 only.
struct Step {
    index: vec4<f32>,
};
@group(1) @binding(0) var<uniform> push_step: Step;

@fragment
fn fs_drop(in: FullscreenOut) -> @location(0) vec4<f32> {
    let p = texel(in.position);
    var s = cell(p);
    let x = cell_centre(p);
    let first_step = push_step.index.x < 0.5;
    let count = select(0, i32(sim.drops_info.x), first_step);
    for (var i = 0; i < count; i++) {
        let drop = sim.drops[i];
        let d = length(x - drop.xy) / drop.z;
        s.x += drop.w * (0.5 - 0.5 * cos(PI * max(1.0 - d, 0.0)));
    }
    let moves = i32(sim.bodies.x);
    let base = i32(push_step.index.x) * STEP_HULL_SLOTS;
    for (var i = 0; i < moves; i++) {
        s.x += displaced_column(x, base + 8 * i + 4) - displaced_column(x, base + 8 * i);
    }
    s.x = bounded_height(s.x - select(0.0, sim.drops_info.y, first_step));
    return s;
}
