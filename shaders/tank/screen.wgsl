// The lamp's image on the screen under the tank: the water's surface as a mesh of its cells
// (ordered for a small vertex cache, render::banded_grid),
// each vertex moved to where the lamp's ray through it lands on the screen. A patch of
// surface whose rays converge (under a crest, which focuses like a lens) lights a smaller
// patch of screen brighter: each fragment adds the ratio of the patch's area under flat
// water to its area now, times the lamp's falloff there (additive blending sums folds).

struct ScreenOut {
    @builtin(position) position: vec4<f32>,
    @location(0) flat_point: vec2<f32>,
    @location(1) light: f32,
};

// `grid`: the point's place in the mesh, -1 to 1 from the first point to the last; a point
// every pic.mesh.y cells.
@vertex
fn vs_screen(@location(0) grid: vec2<f32>) -> ScreenOut {
    let p = vec2<i32>(round((grid + 1.0) * 0.5 * (pic.mesh.x - 1.0)) * pic.mesh.y);
    let dx = 2.0 * pic.tray.x / pic.screen.z;
    let xz = (vec2<f32>(p) + 0.5) * dx - pic.tray.x;
    let h = cell_of(p).x;
    let slope = vec2<f32>(cell_of(p + vec2<i32>(1, 0)).x - cell_of(p - vec2<i32>(1, 0)).x,
        cell_of(p + vec2<i32>(0, 1)).x - cell_of(p - vec2<i32>(0, 1)).x) / (2.0 * dx);
    let lit = on_screen(vec3<f32>(xz.x, h, xz.y), normalize(vec3<f32>(-slope.x, 1.0, -slope.y)));
    let flat_lit = on_screen(vec3<f32>(xz.x, 0.0, xz.y), vec3<f32>(0.0, 1.0, 0.0));
    var out: ScreenOut;
    out.position = vec4<f32>(lit.xy / pic.screen.x, 0.0, 1.0);
    out.flat_point = flat_lit.xy;
    // A barrier casts its shadow; so does light the water turns back.
    out.light = select(lit.z, 0.0, is_wall(p));
    return out;
}

@fragment
fn fs_screen(in: ScreenOut) -> @location(0) vec4<f32> {
    let texel = 2.0 * pic.screen.x / pic.view.w;
    let flat_area = abs(determinant(mat2x2<f32>(dpdx(in.flat_point), dpdy(in.flat_point))));
    let drop = pic.tray.z + pic.tray.y + pic.tray.w;
    let r = length(vec3<f32>(in.flat_point.x, drop, in.flat_point.y));
    let falloff = pow(drop / r, 3.0);
    let light = in.light * falloff * flat_area / (texel * texel) * pic.screen.w;
    return vec4<f32>(light, light, light, 1.0);
}
