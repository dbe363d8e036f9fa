// Drops and bodies. Each drop adds a smooth cosine bump h += s * (1 - cos(pi * (1 - d/r))) / 2
// inside its radius r; the CPU computes the bumps' mean over the grid and it is subtracted
// everywhere, so a drop adds no net water. A moving body pushes the surface by the change of
// the water column it displaces (displaced_column in sim.rs): up ahead of and above it, down
// behind it; the volume it takes up in the water is accounted for by the rest level the mean
// is held at (sim_normals.wgsl).

// Column (m) of an ellipsoid below the rest level over pool point x, each depth y weighted by
// exp(y / L): integral of exp(y / L) dy over the part of the vertical line inside it.
fn displaced_column(x: vec2<f32>, first: i32) -> f32 {
    let centre = sim.hulls[first].xyz;
    let to_unit = mat3x3<f32>(sim.hulls[first + 1].xyz, sim.hulls[first + 2].xyz, sim.hulls[first + 3].xyz);
    let u0 = to_unit * (vec3<f32>(x.x, 0.0, x.y) - centre);
    let d = to_unit[1];
    let a = dot(d, d);
    let b = dot(u0, d);
    let c = dot(u0, u0) - 1.0;
    let disc = b * b - a * c;
    if (disc <= 0.0 || a <= 0.0) {
        return 0.0;
    }
    let s = sqrt(disc);
    let y0 = (-b - s) / a;
    let y1 = min((-b + s) / a, 0.0);
    if (y1 <= y0) {
        return 0.0;
    }
    let depth = sim.bodies.z;
    return depth * (exp(y1 / depth) - exp(y0 / depth));
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
