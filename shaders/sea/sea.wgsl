// The open sea (scenes/sea/render/mod.rs). A grid laid over the screen is projected along the eye's rays
// onto the mean sea plane (capped GRID_FAR away), so its cells stay about the same size in
// pixels from the bow to the horizon; each vertex is then moved by the FFT cascades (heights,
// and the choppy sideways carry x0 - lambda D) and the clicks' ripples (a patch of the pool's
// simulation round the target). Each pixel is lit from the slopes at its rest
// point: the sky mirrored with Fresnel's reflectance, the sun's glint, the deep water's own
// scattered light. A cascade whose texels the pixel's footprint outgrows fades out and its
// slope variance widens the glint instead (Toksvig), so the far sea does not sparkle. A haze
// thinning with height, e^(-y/H), takes water and sky to the sky's horizon colour.

struct Sea {
    eye: vec4<f32>,                // xyz eye (m)
    right: vec4<f32>,              // camera's right times tan(half the field across)
    up: vec4<f32>,                 // camera's up times tan(half the field down)
    forward: vec4<f32>,            // camera's forward
    grid: vec4<f32>,               // the grid's screen rectangle (NDC): x from, x to, y from, y to
    cells: vec4<f32>,              // columns, rows, a cell's angle (rad)
    waves: vec4<f32>,              // choppiness lambda, all cascades' slope variance
    foam: vec4<f32>,               // whitecaps drawn (1) or not (0, for tests), the shore's
                                   // foam drawn or not, the highest crest (m), the share of
                                   // the kept whitecaps left after this frame's steps
    mirror: vec4<f32>,             // 1 / the target's width and height (px): a pixel's place
                                   // in the island's mirror (shaders/sea/island.wgsl)
    fog: vec4<f32>,                // 1 / fog distance (1/m; 0 off), scale height (m), the
                                   // band under the horizon that takes the sky's haze (rad)
    cascades: array<vec4<f32>, CASCADES>, // cos, sin of the turn, tile (m), slope variance
}

@group(2) @binding(0) var<uniform> sea: Sea;
// The five cascades' lattices, a layer each (SEA_LATTICE texels a side, in their own frames):
// height (m), slopes dh/dx, dh/dz, dDx/dz; and the displacement Dx, Dz (m), dDx/dx, dDz/dz.
@group(2) @binding(1) var sea_surface: texture_2d_array<f32>;
@group(2) @binding(2) var sea_displacement: texture_2d_array<f32>;

// The clicks' ripples at rest point p (m): height (m) and slopes dh/dx, dh/dz of the patch of
// simulated water (the scene's water state, scene.water.x cells across PATCH_HALF_WIDTH each
// way), 0 outside it. Their waves are ten cells long and more: they fade as the footprint (m)
// grows from four cells to eight, and across the absorbing border (PATCH_SPONGE m), where what
// the border has not yet taken would otherwise end at the patch's edge.
fn ripples_at(p: vec2<f32>, footprint: f32) -> vec3<f32> {
    let n = i32(scene.water.x);
    let q = (p / PATCH_HALF_WIDTH * 0.5 + 0.5) * f32(n) - 0.5;
    let base = floor(q);
    let i0 = clamp(vec2<i32>(base), vec2<i32>(0), vec2<i32>(n - 1));
    let i1 = clamp(vec2<i32>(base) + 1, vec2<i32>(0), vec2<i32>(n - 1));
    let state = bilinear_load(water_state, MapTaps(i0, i1, q - base));
    let normal = water_normal(state);
    let cells = footprint * f32(n) / (2.0 * PATCH_HALF_WIDTH);
    let from_middle = max(abs(p.x), abs(p.y));
    let border = 1.0 - smoothstep(PATCH_HALF_WIDTH - PATCH_SPONGE, PATCH_HALF_WIDTH, from_middle);
    let keep = clamp(2.0 - cells / 4.0, 0.0, 1.0) * border;
    return keep * vec3<f32>(state.x, -normal.xz / normal.y);
}

// The clicks' ripples' curvature at rest point p (m): their slopes' change over a cell of the
// patch, as (d2h/dx2, d2h/dxdz, d2h/dz2) (1/m), faded with the footprint (m) as ripples_at.
fn ripples_hessian(p: vec2<f32>, footprint: f32) -> vec3<f32> {
    let step = 2.0 * PATCH_HALF_WIDTH / scene.water.x;
    let s = ripples_at(p, footprint).yz;
    let sx = (ripples_at(p + vec2<f32>(step, 0.0), footprint).yz - s) / step;
    let sz = (ripples_at(p + vec2<f32>(0.0, step), footprint).yz - s) / step;
    return vec3<f32>(sx.x, 0.5 * (sx.y + sz.x), sz.y);
}

// Where the eye's ray along dir meets the sea plane (xz, m), at most GRID_FAR away across.
fn rest_point(dir: vec3<f32>) -> vec2<f32> {
    let across = max(length(dir.xz), 1.0e-6);
    let to_plane = select(FAR_AWAY, sea.eye.y / -dir.y, dir.y < 0.0);
    return sea.eye.xz + dir.xz * min(to_plane, GRID_FAR / across);
}

// Optical depth of the haze along `dist` m of a ray from the eye in unit direction dir:
// (1/L) e^(-y0/H) times the integral of e^(-dir.y t / H) over the path, which for a ray into
// the sky is H / dir.y. Just under the horizon (within sea.fog.z rad) a ray down to the
// sea takes at least the depth of the ray as far above it: both sides of the horizon meet in
// the same haze, with no seam, from any height (`skims`: the sea's rays; the land and the
// bodies take their own distance's).
fn haze_depth(dir: vec3<f32>, dist: f32, skims: bool) -> f32 {
    let h = sea.fog.y;
    let k = max(dir.y * dist / h, -40.0);
    let shape = select((1.0 - exp(-k)) / k, 1.0 - 0.5 * k, abs(k) < 1.0e-3);
    let skim = select(0.0, h / max(-dir.y, 1.0e-6) * (1.0 - smoothstep(0.0, sea.fog.z, -dir.y)), skims && dir.y < 0.0);
    return sea.fog.x * exp(-sea.eye.y / h) * max(dist * shape, skim);
}

// Light arriving at the eye from `colour` `dist` m away along dir through the haze, which
// glows with the sky's colour at the horizon in that direction (the deck's fit of it).
fn through_haze(colour: vec3<f32>, dir: vec3<f32>, dist: f32) -> vec3<f32> {
    return mix(horizon_colour(dir.xz), colour, exp(-haze_depth(dir, dist, true)));
}

// The same for what stands on the sea (the land, the bodies): the haze over its own distance.
fn through_air(colour: vec3<f32>, dir: vec3<f32>, dist: f32) -> vec3<f32> {
    return mix(horizon_colour(dir.xz), colour, exp(-haze_depth(dir, dist, false)));
}

// The sun's and the sky's light falling on the level sea.
fn light_on_sea() -> vec3<f32> {
    return sky_light() + sun_light() * max(scene.sun.y, 0.0);
}

// The light the deep water sends back up: what it scatters of the light falling on it.
fn deep_water() -> vec3<f32> {
    return DEEP_WATER_ALBEDO * light_on_sea();
}

// The sea's colour seen along unit v with surface normal n: the mirrored sky (or the island,
// `mirrored`: its colour and coverage) and sun by Fresnel's reflectance, over `under`, the
// light coming up out of the water. rough: the rms slope of the waves too
// small to be drawn here; their facets face the eye by about that much even where the drawn
// surface is seen edge-on, so a rough sea mirrors less at grazing than a smooth one (the sea
// at the horizon is darker than the sky above it).
fn sea_colour(v: vec3<f32>, n: vec3<f32>, rough: f32, under: vec3<f32>, mirrored: vec4<f32>) -> vec3<f32> {
    var r = reflect(v, n);
    r.y = abs(r.y); // a ray mirrored down runs into the next wave: it sees the sky as well
    let f = reflectance(max(dot(-v, n), rough), IOR_AIR / IOR_WATER);
    let seen = mix(sky_colour(r), mirrored.rgb, mirrored.a);
    return mix(under, seen + sun_specular(r, n), f);
}

struct SeaOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) rest: vec2<f32>,
    // The carry gradient of the cascades that break into whitecaps (add_gradient).
    @location(2) carry_gradient: vec3<f32>,
}

// Vertex `index` of the grid's quads (two triangles each), row by row up the screen.
@vertex
fn vs_sea(@builtin(vertex_index) index: u32) -> SeaOut {
    let columns = u32(sea.cells.x);
    let quad = index / 6u;
    let corner = index % 6u;
    let dx = select(0u, 1u, corner == 1u || corner == 2u || corner == 4u);
    let dy = select(0u, 1u, corner == 2u || corner == 4u || corner == 5u);
    let g = vec2<f32>(f32(quad % columns + dx), f32(quad / columns + dy)) / sea.cells.xy;
    let ndc = mix(sea.grid.xz, sea.grid.yw, g);
    let dir = normalize(sea.forward.xyz + ndc.x * sea.right.xyz + ndc.y * sea.up.xyz);
    let rest = rest_point(dir);
    // The cell's length on the water along the ray (m): its angle over the grazing angle.
    let dist = distance(rest, sea.eye.xz);
    let footprint = sea.cells.z * (dist * dist + sea.eye.y * sea.eye.y) / max(sea.eye.y, 0.1);
    let waves = waves_at(rest, footprint);
    var out: SeaOut;
    out.carry_gradient = waves.breaking_gradient;
    let moved = rest - sea.waves.x * waves.carry;
    out.world = vec3<f32>(moved.x, waves.height + ripples_at(rest, footprint).x, moved.y);
    out.rest = rest;
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

@fragment
fn fs_sea(in: SeaOut) -> @location(0) vec4<f32> {
    let footprint = max(length(dpdx(in.rest)), length(dpdy(in.rest)));
    // The pixel's size on the water as drawn (m), for the bodies' waterlines.
    let world_footprint = max(length(dpdx(in.world)), length(dpdy(in.world)));
    var slope = vec2<f32>(0.0);
    var removed = 0.0;
    var finest = vec2<f32>(0.0); // the last cascade's slope in its frame (shallows_caustics)
    for (var c = 0; c < CASCADES; c++) {
        let w = slope_weight(c, footprint);
        let local = to_cascade(c, in.rest);
        let surface = cascade_texel(sea_surface, c, local, sea.cascades[c].z);
        let s = surface.yz;
        finest = s;
        slope += w * from_cascade(c, s);
        removed += (1.0 - w * w) * sea.cascades[c].w;
    }
    // The ripples' fade by the pixel's mean footprint: along a grazing view the longest side
    // would lose rings that are sharp across it.
    slope += ripples_at(in.rest, sqrt(length(dpdx(in.rest)) * length(dpdy(in.rest)))).yz;
    let n = normalize(vec3<f32>(-slope.x, 1.0, -slope.y));
    // The slopes left out, and those varying within the pixel, spread the glint (Toksvig).
    let dn = dot(dpdx(n), dpdx(n)) + dot(dpdy(n), dpdy(n));
    specular_spread = 1.0 / (1.0 + scene.optics.x * (0.5 * removed + dn / 24.0));
    var under = deep_water();
    var foam = 0.0;
    if WHITECAPS {
        var cover = whitecap_cover(squeezed(in.carry_gradient));
        if WHITECAP_MAP {
            cover = max(cover, kept_whitecaps(in.rest));
        }
        foam = foam_lace(cover * sea.foam.x, in.rest, footprint);
    }
    let to_point = in.world - sea.eye.xyz;
    let dist = length(to_point);
    let v = to_point / dist;
    var mirrored = vec4<f32>(0.0);
    if ISLAND {
        mirrored = mirrored_land(in.clip.xy, n, sqrt(removed));
    }
    if MIRRORED_BODIES {
        mirrored = mirrored_bodies(in.world, reflect(v, n), mirrored);
    }
    var floor_depth = NO_HIT; // m under the surface, where the island's floor is in sight
    if ISLAND && on_island_map(in.world.xz) {
        let ground = ground_at(in.world.xz);
        let depth = in.world.y - ground.x;
        floor_depth = depth;
        if depth < SEE_DEPTH {
            var focus = 1.0;
            if SHALLOW_CAUSTICS {
                focus = shallows_caustics(in.rest, finest, depth, footprint);
            }
            if ISLAND_AT_PATCH {
                focus *= bodies_shade_on_floor(in.world, v, n, depth);
            }
            under = seen_through_water(v, n, depth, ground, focus);
        }
        let ripple = finest.x / sqrt(max(sea.cascades[CASCADES - 1].w, 1.0e-8));
        foam = max(foam, shore_foam(depth, in.world.y / max(sea.foam.z, 0.1), ripple) * sea.foam.y);
    }
    if MIRRORED_BODIES && HAS_BODIES_BELOW {
        under = refracted_bodies(in.world, v, n, under, floor_depth);
    }
    let colour = mix(sea_colour(v, n, sqrt(removed), under, mirrored), WHITECAP_ALBEDO * light_on_foam(n), foam);
    var seen = through_haze(colour, v, dist);
    if GRID_LINES {
        seen = mix(seen, GRID_LINE_COLOUR * light_on_sea(), 0.6 * grid_line(in.rest));
    }
    var out = finish(seen);
    // Near the bodies (their own variant, blended by its alpha) the water is not drawn inside
    // a hull, and at the waterline of one drawn as it is traced it covers only its share of
    // the pixel, over the body drawn before, as in the pool (shaders/pool/water.wgsl).
    if MIRRORED_BODIES {
        out.a = water_share(in.world, sea.eye.xyz, v, world_footprint);
        if out.a < 0.0 {
            discard;
        }
    }
    return out;
}

// Where the grid drew nothing: the sky, and between the grid's far edge and the horizon the sea
// at infinity (its mean surface, level), both through the haze.
@fragment
fn fs_sea_sky(in: FullscreenOut) -> @location(0) vec4<f32> {
    let ndc = vec2<f32>(in.uv.x * 2.0 - 1.0, 1.0 - in.uv.y * 2.0);
    let dir = normalize(sea.forward.xyz + ndc.x * sea.right.xyz + ndc.y * sea.up.xyz);
    let below = dir.y < 0.0;
    let level = vec3<f32>(0.0, 1.0, 0.0);
    let colour = select(sky_colour(dir), sea_colour(dir, level, sqrt(sea.waves.y), deep_water(), vec4<f32>(0.0)), below);
    let dist = select(FAR_AWAY, sea.eye.y / -dir.y, below);
    return finish(through_haze(colour, dir, dist));
}
