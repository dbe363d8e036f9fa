// The water's surface as the scene sees it: bilinear lookups of the simulation's maps, foam,
// the ambient waves added on top (sines, modes, Gerstner, the FFT ocean), the surface normal.

// The four texels around pool point xz (m) of an n x n map whose texels tile the pool, and the
// weights between them. Bilinear lookups are done by hand with textureLoad, so that 32-bit
// float maps need no filterable-float support.
struct MapTaps {
    i0: vec2<i32>,
    i1: vec2<i32>,
    f: vec2<f32>,
};

// Texel coordinates of xz on an n x n map (texel centres at whole numbers).
fn map_point(xz: vec2<f32>, n: f32) -> vec2<f32> {
    return (xz / half_width() * 0.5 + 0.5) * n - 0.5;
}

// Taps held at the map's edge (the simulation's state, the foam: nothing lies past the walls).
fn clamped_taps(xz: vec2<f32>, n: vec2<i32>) -> MapTaps {
    let p = map_point(xz, f32(n.x));
    let base = floor(p);
    let i0 = clamp(vec2<i32>(base), vec2<i32>(0), n - 1);
    let i1 = clamp(vec2<i32>(base) + 1, vec2<i32>(0), n - 1);
    return MapTaps(i0, i1, p - base);
}

// Taps that wrap round (the FFT ocean's maps: its waves are periodic over the pool's width).
fn wrapped_taps(xz: vec2<f32>, n: i32) -> MapTaps {
    let p = map_point(xz, f32(n));
    let base = floor(p);
    let i0 = ((vec2<i32>(base) % n) + n) % n;
    return MapTaps(i0, (i0 + 1) % n, p - base);
}

// The map's texels at the taps, blended by their weights.
fn bilinear_load(map: texture_2d<f32>, t: MapTaps) -> vec4<f32> {
    let a = textureLoad(map, t.i0, 0);
    let b = textureLoad(map, vec2<i32>(t.i1.x, t.i0.y), 0);
    let c = textureLoad(map, vec2<i32>(t.i0.x, t.i1.y), 0);
    let d = textureLoad(map, t.i1, 0);
    return mix(mix(a, b, t.f.x), mix(c, d, t.f.x), t.f.y);
}

// The simulation state (height, velocity, slopes) at pool point xz (m), with the ambient waves.
fn water_at(xz: vec2<f32>) -> vec4<f32> {
    let t = clamped_taps(xz, vec2<i32>(i32(scene.water.x)));
    let simulated = bilinear_load(water_state, t);
    if (AMBIENT_MODEL != AMBIENT_NONE) {
        return with_ambient(simulated, xz);
    }
    return simulated;
}

// Foam amount at pool point xz (m).
fn foam_at(xz: vec2<f32>) -> f32 {
    let t = clamped_taps(xz, vec2<i32>(textureDimensions(foam_map)));
    return bilinear_load(foam_map, t).r;
}

// Foam over the surface colour at p: the amount as bubbly coverage (scattered bubbles where
// thin, solid white where thick) that hides what lies behind; lit by the sky and the sun
// seen from above, a shadow seen from below.
fn with_foam(colour: vec3<f32>, p: vec3<f32>, from_above: bool) -> vec3<f32> {
    let amount = foam_at(p.xz);
    let bubbles = 0.6 * value_noise_2d(p.xz * 90.0, 0.0) + 0.4 * value_noise_2d(p.xz * 23.0, 3.7);
    let coverage = smoothstep(bubbles - 0.1, bubbles + 0.1, 1.4 * amount);
    let lit = FOAM_ALBEDO * (sky_light() + max(scene.sun.y, 0.0) * sun_light());
    return select(colour * (1.0 - 0.8 * coverage), mix(colour, lit, coverage), from_above);
}

// Height (m) and slopes dh/dx, dh/dz of the ambient waves at xz (the formulas of ambient.rs:
// Finch's sharpened travelling sines, the basin's standing modes, Gerstner waves, or the FFT
// ocean's map).
fn ambient_at(xz: vec2<f32>) -> vec3<f32> {
    if (AMBIENT_MODEL == AMBIENT_FFT) {
        return ocean_at(xz);
    }
    if (AMBIENT_MODEL == AMBIENT_GERSTNER) {
        return gerstner_at(xz);
    }
    var sum = vec3<f32>(0.0);
    let count = i32(scene.ambient_header.x);
    for (var i = 0; i < MAX_AMBIENT_WAVES; i++) {
        if (i >= count) {
            break;
        }
        let w = scene.ambient_waves[i];
        if (AMBIENT_MODEL == AMBIENT_SINES) {
            let theta = w.x * xz.x + w.y * xz.y + w.w;
            let s = (sin(theta) + 1.0) * 0.5;
            let dh = 2.0 * w.z * s * cos(theta);
            sum += vec3<f32>(2.0 * w.z * (s * s - SHARP_SINE_MEAN), dh * w.x, dh * w.y);
        } else {
            let u = w.x * (xz.x + half_width());
            let v = w.y * (xz.y + half_width());
            let c = w.z * cos(w.w);
            sum += vec3<f32>(c * cos(u) * cos(v), -c * w.x * sin(u) * cos(v), -c * w.y * cos(u) * sin(v));
        }
    }
    return sum;
}

// The FFT ocean's maps at taps from `ocean_taps`: height and slopes, and the displacement.
fn ocean_taps(xz: vec2<f32>) -> MapTaps {
    return wrapped_taps(xz, i32(textureDimensions(ambient_map).x));
}

fn ocean_surface(t: MapTaps) -> vec4<f32> {
    return bilinear_load(ambient_map, t);
}

fn ocean_displacement(t: MapTaps) -> vec4<f32> {
    return bilinear_load(ambient_displacement, t);
}

// J^-1 v for the choppy surface's Jacobian (xx, xz, zz), its length held to `limit` and its
// determinant away from 0 (where the sea folds over), so it stays finite (ocean.rs folded_solve).
fn folded_solve(j: vec3<f32>, v: vec2<f32>, limit: f32) -> vec2<f32> {
    var det = j.x * j.z - j.y * j.y;
    det = select(det, 1.0e-6, abs(det) < 1.0e-6);
    let s = vec2<f32>(j.z * v.x - j.y * v.y, j.x * v.y - j.y * v.x) / det;
    return s * min(1.0, limit / max(length(s), 1.0e-12));
}

// The FFT ocean above xz. With choppiness (AMBIENT_CHOPPY, lambda in ambient_header.z) the
// water at rest point x0 is carried to x0 - lambda D(x0): Newton's method finds the x0
// carried to xz (J = I - lambda dD/dx0), then the height there and the slopes J^-1 grad h
// (as ocean.rs `sample`).
fn ocean_at(xz: vec2<f32>) -> vec3<f32> {
    if (AMBIENT_CHOPPY) {
        let lambda = scene.ambient_header.z;
        var x0 = xz;
        for (var i = 0; i < CHOP_NEWTON_STEPS; i++) {
            let taps = ocean_taps(x0);
            let s = ocean_surface(taps);
            let d = ocean_displacement(taps);
            let j = vec3<f32>(1.0 - lambda * d.z, -lambda * s.w, 1.0 - lambda * d.w);
            x0 -= folded_solve(j, x0 - lambda * d.xy - xz, CHOP_STEP_LIMIT);
        }
        let taps = ocean_taps(x0);
        let s = ocean_surface(taps);
        let d = ocean_displacement(taps);
        let j = vec3<f32>(1.0 - lambda * d.z, -lambda * s.w, 1.0 - lambda * d.w);
        return vec3<f32>(s.x, folded_solve(j, s.yz, CHOP_SLOPE_LIMIT));
    }
    return ocean_surface(ocean_taps(xz)).xyz;
}

// Gerstner waves at rest point x0: the horizontal displacement D (m), the motion's Jacobian
// J = I - sum(b cos t K K^T) as (xx, xz, zz) and the height; b = c a / k, t = K.x0 + phase.
struct GerstnerPoint {
    displacement: vec2<f32>,
    jacobian: vec3<f32>,
    height: f32,
    gradient: vec2<f32>,  // dh/dx0
};

fn gerstner_point(x0: vec2<f32>) -> GerstnerPoint {
    var g = GerstnerPoint(vec2<f32>(0.0), vec3<f32>(1.0, 0.0, 1.0), 0.0, vec2<f32>(0.0));
    let c = scene.ambient_header.y;
    let count = i32(scene.ambient_header.x);
    for (var i = 0; i < MAX_AMBIENT_WAVES; i++) {
        if (i >= count) {
            break;
        }
        let w = scene.ambient_waves[i];
        let theta = dot(w.xy, x0) + w.w;
        let s = sin(theta);
        let co = cos(theta);
        let b = c * w.z / length(w.xy);
        g.displacement += b * s * w.xy;
        g.jacobian -= b * co * vec3<f32>(w.x * w.x, w.x * w.y, w.y * w.y);
        g.height += w.z * co;
        g.gradient -= w.z * s * w.xy;
    }
    return g;
}

// J^-1 v for a symmetric 2x2 matrix J given as (xx, xz, zz).
fn symmetric_solve(j: vec3<f32>, v: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(j.z * v.x - j.y * v.y, j.x * v.y - j.y * v.x) / (j.x * j.z - j.y * j.y);
}

// The Gerstner surface above xz: Newton's method finds the rest point x0 the waves carry to
// xz (x0 - D(x0) = xz), then the height there and the slopes J^-1 grad h (as ambient.rs).
fn gerstner_at(xz: vec2<f32>) -> vec3<f32> {
    var x0 = xz;
    for (var i = 0; i < GERSTNER_NEWTON_STEPS; i++) {
        let g = gerstner_point(x0);
        x0 -= symmetric_solve(g.jacobian, x0 - g.displacement - xz);
    }
    let g = gerstner_point(x0);
    return vec3<f32>(g.height, symmetric_solve(g.jacobian, g.gradient));
}

// The simulated state with the ambient waves added: heights summed, slopes summed (the
// state's normal is (-dh/dx, 1, -dh/dz) normalised), the velocity left as simulated.
fn with_ambient(state: vec4<f32>, xz: vec2<f32>) -> vec4<f32> {
    let ambient = ambient_at(xz);
    let n = water_normal(state);
    let slope = vec2<f32>(-n.x, -n.z) / max(n.y, 1.0e-4) + ambient.yz;
    let total = normalize(vec3<f32>(-slope.x, 1.0, -slope.y));
    return vec4<f32>(state.x + ambient.x, state.y, total.x, total.z);
}

fn water_normal(state: vec4<f32>) -> vec3<f32> {
    let t = state.zw;
    return vec3<f32>(t.x, sqrt(max(1.0 - dot(t, t), 0.0)), t.y);
}

// The flat water's normal at xz (m): the simulated surface's (FLAT_RIPPLES), or the dUdV
// map's read as seed 000 does (its own distortion, read at a scrolled place, offsets where it is
// read again, so the pattern churns instead of sliding).
fn flat_normal(xz: vec2<f32>) -> vec3<f32> {
    if (FLAT_DISTORTION == FLAT_RIPPLES) {
        return water_normal(water_at(xz));
    }
    let t = xz * (DUDV_TILES / (2.0 * half_width()));
    let scroll = scene.flat.z;
    let first = textureSampleLevel(dudv_map, repeat_sampler, t + vec2<f32>(scroll, 0.0), 0.0).rg * 2.0 - 1.0;
    let s = textureSampleLevel(dudv_map, repeat_sampler, t + 0.1 * first + vec2<f32>(0.0, scroll), 0.0).rg * 2.0 - 1.0;
    return normalize(vec3<f32>(-s.x * DUDV_SLOPE, 1.0, -s.y * DUDV_SLOPE));
}
