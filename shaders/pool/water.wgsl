// The water surface: the grid displaced by the simulated height. Per fragment, the view ray
// is split at the surface into a reflected and a refracted ray (Snell, n = 1.333); each is
// traced analytically to the pool, the sphere or the sky, and the two are blended by the
// Fresnel reflectance (the exact equations for unpolarised light, or a model a lesson picks).

// Tile levels added per radian the normal turns across a pixel, and at most (fs_surface).
const TILE_LOD_PER_TURN: f32 = 15.0;
const TILE_LOD_TURNING_MAX: f32 = 1.5;

struct SurfaceOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
};

@vertex
fn vs_surface(@location(0) grid: vec2<f32>) -> SurfaceOut {
    var xz = grid * half_width();
    if (AMBIENT_MODEL == AMBIENT_GERSTNER) {
        // Gerstner waves move the water sideways: the grid point goes where the waves carry
        // it (vertices gather under the crests); across a wall the motion fades out over the
        // last 10 cm (it is below Q/k_min = 9 cm), so no vertex leaves the pool or crosses
        // the wall's own. Its height is the surface's there.
        let carry = -gerstner_point(xz).displacement;
        xz += carry * clamp((half_width() - abs(xz)) / 0.1, vec2<f32>(0.0), vec2<f32>(1.0));
    }
    if (AMBIENT_CHOPPY) {
        // The choppy FFT ocean carries its water the same way (by -lambda D).
        let carry = -scene.ambient_header.z * ocean_displacement(ocean_taps(xz)).xy;
        xz += carry * clamp((half_width() - abs(xz)) / 0.1, vec2<f32>(0.0), vec2<f32>(1.0));
    }
    let height = water_at(xz).x;
    var out: SurfaceOut;
    out.world = vec3<f32>(xz.x, height, xz.y);
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

// One fragment shader for both sides, so the grid is drawn once. Front faces are the
// surface seen from above: the reflected ray goes up into the air, the refracted one down
// into the pool. Back faces are seen from below: the refracted ray leaves through Snell's
// window to the sky, the reflected one (all of it beyond the critical angle) stays in the
// water, and everything is dimmed by the water between eye and surface. Both rays are traced
// without branching on the side, so screen derivatives (tile_lod) stay in uniform control flow.
// With the deck the eye stays above the paving, so above the water: every fragment is seen from
// above (a constant: software rasterisers would shade the view from under the water as well),
// and a wave's far slope, turned from the eye, is shaded as its near one.
@fragment
fn fs_surface(in: SurfaceOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    let from_above = HAS_DECK || front;
    let edge = deck_edge(in.world);
    let n = select(-1.0, 1.0, from_above) * water_normal(water_at(in.world.xz));
    // Toksvig's factor from the normal's spread over the pixel (a uniform spread over the
    // screen derivatives has variance |dn|^2 / 12 per axis): the highlight widens where
    // ripples are finer than pixels instead of sparkling from pixel to pixel.
    let dnx = dpdx(n);
    let dny = dpdy(n);
    specular_spread = 1.0 / (1.0 + scene.optics.x * (dot(dnx, dnx) + dot(dny, dny)) / 24.0);
    let eta = select(IOR_WATER / IOR_AIR, IOR_AIR / IOR_WATER, from_above);
    let view = normalize(in.world - scene.eye.xyz);
    let reflected = reflect(view, n);
    let refracted = refract(view, n, eta);
    let air_dir = upward(select(refracted, reflected, from_above));
    let water_dir = select(reflected, refracted, from_above);
    let t_air = pool_exit_distance(in.world, air_dir);
    let t_water = pool_exit_distance(in.world, water_dir);
    // The tiles' level from how their coordinates change across the quad, raised where the
    // normal turns fast across the pixel (ripples finer than the quad's differences see):
    // there the grout, one or two texels wide, would alias into dark specks.
    let turning = min(TILE_LOD_TURNING_MAX, TILE_LOD_PER_TURN * sqrt(dot(dnx, dnx) + dot(dny, dny)));
    tile_turning = turning;
    let lod_air = tile_lod(in.world + air_dir * t_air) + turning;
    let lod_water = tile_lod(in.world + water_dir * t_water) + turning;
    let r = reflectance(dot(-view, n), eta);
    if (SHOW_REFLECTANCE) {
        // Grey; with dispersion each channel's own reflectance (its own critical angle).
        if (HAS_DISPERSION) {
            return as_displayed(vec3<f32>(
                reflectance(dot(-view, n), select(scene.ior.x / IOR_AIR, IOR_AIR / scene.ior.x, from_above)),
                r,
                reflectance(dot(-view, n), select(scene.ior.z / IOR_AIR, IOR_AIR / scene.ior.z, from_above)),
            ));
        }
        return as_displayed(vec3<f32>(r));
    }
    let air_weight = select(1.0 - r, r, from_above);
    let air = trace_air(in.world, air_dir, select(vec3<f32>(0.0), n, from_above), t_air, lod_air);
    var water = trace_water(in.world, water_dir, t_water, lod_water);
    if (!from_above) {
        water = mirror_from_below(in.world, view, n, dnx + dny, lod_water, water);
    }
    var colour = mix(water, air, air_weight);
    if (HAS_DISPERSION) {
        // Red and blue bend by their own indices: traced again, each weighted by its own
        // reflectance, so the refracted picture and the critical angle (the rim of Snell's
        // window) split into colours. Both sides traced, as above, for uniform control flow.
        colour.r = dispersed(in.world, view, n, from_above, scene.ior.x, air, water, lod_air, lod_water).r;
        colour.b = dispersed(in.world, view, n, from_above, scene.ior.z, air, water, lod_air, lod_water).b;
    }
    if (HAS_FOAM) {
        colour = with_foam(colour, in.world, from_above);
    }
    if (!from_above) {
        colour = through_water(colour, scene.eye.xyz, in.world);
        if (!HAS_DECK && CLIP_SIDE == 0) {
            colour = mix(colour, water_backdrop(view), open_side_fade(in.world));
        }
    }
    // Water inside a body (the surface's coarse triangles rise through a hull near its
    // waterline) is not drawn: the body's own pixel, drawn before, stays (its traced rays
    // would start inside the hull). Within a pixel's footprint outside a hull drawn as it is
    // traced, the water covers only its share of the pixel (its alpha, blended over the body
    // drawn before), so the waterline has no stair-steps. Discarded last, so every derivative
    // above was taken with all four pixels of the quad.
    var out = finish(with_deck_edge(colour, edge));
    if (HAS_BODIES) {
        let footprint = max(length(dpdx(in.world)), length(dpdy(in.world)));
        out.a = water_share(in.world, scene.eye.xyz, view, footprint);
        if (out.a < 0.0) {
            discard;
        }
    }
    return out;
}

// Seen from under the water in the cut-away, how far (1 at the edge, 0 from CUT_EDGE_FADE in)
// the surface at p has faded into the open water (water_backdrop) beyond a side left open: one
// whose wall faces away from the eye, culled.
fn open_side_fade(p: vec3<f32>) -> f32 {
    let w = half_width();
    let eye = scene.eye.xyz;
    let open = vec4<bool>((eye.x < -w), (eye.x > w), (eye.z < -w), (eye.z > w));
    let to_side = vec4<f32>(p.x + w, w - p.x, p.z + w, w - p.z);
    let nearest = min(min(select(1.0e3, to_side.x, open.x), select(1.0e3, to_side.y, open.y)), min(select(1.0e3, to_side.z, open.z), select(1.0e3, to_side.w, open.w)));
    return 1.0 - smoothstep(0.0, CUT_EDGE_FADE, nearest);
}

// Seen from below, the water's mirror (the pool reflected, all of it past the critical angle)
// turns twice as fast as the normal and breaks the walls' caustic lines into specks: the
// colour `first` traced along the reflected ray, averaged with two more whose normal is turned
// MIRROR_SPREAD of its change across the pixel (dn) either way, across most of its footprint.
// In the cut-away's view from under the water a quarter either way took the sparkle from
// 1.08 % to 0.86 % of the pixels, 0.45 natively from 0.345 % to 0.250 % (2026-11-30); from
// above the refracted rays turn less and gained nothing (0.43 % to 0.40 %), so only the back
// faces pay (with the deck never: from_above is a constant there).
const MIRROR_SPREAD: f32 = 0.45;
fn mirror_from_below(p: vec3<f32>, view: vec3<f32>, n: vec3<f32>, dn: vec3<f32>, lod: f32, first: vec3<f32>) -> vec3<f32> {
    let a = reflect(view, normalize(n + MIRROR_SPREAD * dn));
    let b = reflect(view, normalize(n - MIRROR_SPREAD * dn));
    let seen_a = trace_water(p, a, pool_exit_distance(p, a), lod);
    let seen_b = trace_water(p, b, pool_exit_distance(p, b), lod);
    return (first + seen_a + seen_b) / 3.0;
}

// The surface's colour for light of refractive index `ior` (dispersion): the ray refracted by
// that index traced (into the water from above, out to the air from below) and blended with
// the reflected light (`air` from above, `water` from below: reflection does not depend on
// the index) by that index's reflectance.
fn dispersed(
    p: vec3<f32>,
    view: vec3<f32>,
    n: vec3<f32>,
    from_above: bool,
    ior: f32,
    air: vec3<f32>,
    water: vec3<f32>,
    lod_air: f32,
    lod_water: f32,
) -> vec3<f32> {
    let eta = select(ior / IOR_AIR, IOR_AIR / ior, from_above);
    let refracted = refract(view, n, eta);
    let into_air = upward(refracted);
    let seen_in_water = trace_water(p, refracted, pool_exit_distance(p, refracted), lod_water);
    let seen_in_air = trace_air(p, into_air, vec3<f32>(0.0), pool_exit_distance(p, into_air), lod_air);
    let r = reflectance(dot(-view, n), eta);
    return select(mix(water, seen_in_air, 1.0 - r), mix(seen_in_water, air, r), from_above);
}
