// The open sea's waves (scenes/sea/render/mod.rs): the five FFT cascades read from their maps at a rest
// point (each a turned lattice of its own tile, faded where a footprint outgrows its texels),
// summed into the surface's height, the water's sideways carry and the Jacobian of the choppy
// map that makes whitecaps; and the grid's outline for its debug view.

// A cascade is whole while a footprint spans at most FADE_TEXELS of its texels, gone at twice.
const FADE_TEXELS: f32 = 2.0;
// Its slopes, which the glint magnifies, fade a texel a pixel sooner: its shortest waves (four
// texels) then span four pixels or more, and the sun's glitter path does not speckle.
const SLOPE_FADE_TEXELS: f32 = 1.0;
// Distance (m) standing for "to infinity" along a ray into the sky.
const FAR_AWAY: f32 = 1.0e7;

// Cascade c (its layer of the maps) at local point p (m): one bilinear fetch that wraps round
// its tile (texel centres at -W + (i + 1/2) tile/N, so p / tile + 1/2 in texture units).
fn cascade_texel(map: texture_2d_array<f32>, c: i32, p: vec2<f32>, tile: f32) -> vec4<f32> {
    return textureSampleLevel(map, repeat_sampler, p / tile + 0.5, c, 0.0);
}

// World point (x, z) in cascade c's frame, and a vector of its frame in the world's.
fn to_cascade(c: i32, p: vec2<f32>) -> vec2<f32> {
    let r = sea.cascades[c].xy;
    return vec2<f32>(r.x * p.x + r.y * p.y, -r.y * p.x + r.x * p.y);
}
fn from_cascade(c: i32, v: vec2<f32>) -> vec2<f32> {
    let r = sea.cascades[c].xy;
    return vec2<f32>(r.x * v.x - r.y * v.y, r.y * v.x + r.x * v.y);
}

// How much of cascade c a footprint (m) keeps: 1 while its texels are finer than FADE_TEXELS
// of them, 0 from twice that.
fn cascade_weight(c: i32, footprint: f32) -> f32 {
    return faded(c, footprint, FADE_TEXELS);
}

// How much of cascade c's slopes a pixel's footprint (m) keeps (SLOPE_FADE_TEXELS).
fn slope_weight(c: i32, footprint: f32) -> f32 {
    return faded(c, footprint, SLOPE_FADE_TEXELS);
}

fn faded(c: i32, footprint: f32, whole_to: f32) -> f32 {
    let texels = footprint * f32(SEA_LATTICE) / sea.cascades[c].z;
    return clamp(2.0 - texels / whole_to, 0.0, 1.0);
}

// Adds cascade c's carry gradient to the world's (xx, xz, zz) in t, weighted by w: dDx/dx and
// dDz/dz from its displacement texel, dDx/dz from its surface texel, turned from its frame
// (R^T M R).
fn add_gradient(t: vec3<f32>, c: i32, w: f32, displacement: vec4<f32>, surface: vec4<f32>) -> vec3<f32> {
    let r = sea.cascades[c].xy;
    let m = vec3<f32>(displacement.z, surface.w, displacement.w);
    let turned = vec3<f32>(
        r.x * r.x * m.x - 2.0 * r.y * r.x * m.y + r.y * r.y * m.z,
        r.y * r.x * (m.x - m.z) + (r.x * r.x - r.y * r.y) * m.y,
        r.y * r.y * m.x + 2.0 * r.y * r.x * m.y + r.x * r.x * m.z,
    );
    return t + w * turned;
}

// How much of the water at a point squeezed to `squeezed` of its area the breaking crest
// covers with foam (0-1): none above WHITECAP_EDGE, all where it folds to WHITECAP_JACOBIAN -
// WHITECAP_SOFTNESS.
fn whitecap_cover(squeezed: f32) -> f32 {
    return 1.0 - smoothstep(WHITECAP_JACOBIAN - WHITECAP_SOFTNESS, WHITECAP_EDGE, squeezed);
}

// The cascades at rest point p (m) seen at a footprint of `footprint` m: the height (m), the
// sideways carry D (m; the water moves by -lambda D) and the carry's gradient (add_gradient)
// of the cascades that break into whitecaps.
struct WavesAt {
    height: f32,
    carry: vec2<f32>,
    breaking_gradient: vec3<f32>,
}

// The area (share of its area at rest) the choppy map squeezes the water to, from the carry's
// gradient (xx, xz, zz).
fn squeezed(gradient: vec3<f32>) -> f32 {
    let l = sea.waves.x * gradient;
    return (1.0 - l.x) * (1.0 - l.z) - l.y * l.y;
}

fn waves_at(rest: vec2<f32>, footprint: f32) -> WavesAt {
    var height = 0.0;
    var carry = vec2<f32>(0.0);
    var gradient = vec3<f32>(0.0);
    for (var c = 0; c < CASCADES; c++) {
        let w = cascade_weight(c, footprint);
        let local = to_cascade(c, rest);
        let surface = cascade_texel(sea_surface, c, local, sea.cascades[c].z);
        let displacement = cascade_texel(sea_displacement, c, local, sea.cascades[c].z);
        height += w * surface.x;
        carry += w * from_cascade(c, displacement.xy);
        if c < BREAKING_CASCADES {
            gradient = add_gradient(gradient, c, w, displacement, surface);
        }
    }
    return WavesAt(height, carry, gradient);
}

// The sea's height (m) over rest point `rest`: waves_at's, one fetch a cascade.
fn waves_height(rest: vec2<f32>, footprint: f32) -> f32 {
    var height = 0.0;
    for (var c = 0; c < CASCADES; c++) {
        let surface = cascade_texel(sea_surface, c, to_cascade(c, rest), sea.cascades[c].z);
        height += cascade_weight(c, footprint) * surface.x;
    }
    return height;
}

// The grid's cells outlined (the debug view): how near rest point p lies to a cell's edge (1 on
// it, 0 a pixel away), in the cell coordinates found by taking its ray back onto the screen.
const GRID_LINE_COLOUR: vec3<f32> = vec3<f32>(0.9, 0.7, 0.15);
fn grid_line(p: vec2<f32>) -> f32 {
    let to_point = vec3<f32>(p.x, 0.0, p.y) - sea.eye.xyz;
    let ahead = dot(to_point, sea.forward.xyz);
    let right = dot(to_point, sea.right.xyz) / dot(sea.right.xyz, sea.right.xyz);
    let up = dot(to_point, sea.up.xyz) / dot(sea.up.xyz, sea.up.xyz);
    let g = (vec2<f32>(right, up) / ahead - sea.grid.xz) / (sea.grid.yw - sea.grid.xz) * sea.cells.xy;
    let edge = abs(fract(g + 0.5) - 0.5) / max(fwidth(g), vec2<f32>(1.0e-6));
    return 1.0 - clamp(min(edge.x, edge.y), 0.0, 1.0);
}

