// Scene bindings and the shading every scene pass shares: water sampling, pool tiles,
// caustic light, the sphere and the duck, the sky, and tracing a ray through air or water to what it hits.
// Compiled per feature set: HAS_SPHERE, HAS_DUCK, HAS_CAUSTICS, FRESNEL_MODEL, SPECULAR_MODEL and
// SHOW_REFLECTANCE are constants written ahead of this file (render/variants.rs), so the code
// of what is not in the pool, or of a model not chosen, compiles away.

struct Scene {
    view_proj: mat4x4<f32>,
    inv_view_proj: mat4x4<f32>,
    eye: vec4<f32>,            // xyz camera position (m)
    sun: vec4<f32>,            // xyz unit vector towards the sun; w sun strength
    refracted_sun: vec4<f32>,  // xyz unit direction sunlight travels after a flat surface (downwards)
    sphere: vec4<f32>,         // xyz centre (m), w radius (m); radius 0 = no sphere
    pool: vec4<f32>,           // x half width W (m), y depth D (m), z rim height R above rest (m)
    water: vec4<f32>,          // x grid cells per side N, y 1/N, z caustics on (0/1), w light per unit
                               // stored in the caustics map (1 for float maps, more for 8-bit)
    output: vec4<f32>,         // x = 1: encode sRGB in the shader (target is not an sRGB format);
                               // y debug view (0 none, see debug_view.wgsl)
    optics: vec4<f32>,         // x highlight exponent s, y and z cosines of the sun disk's edge
                               // and core (optics::sun_disk_cosines)
    absorption: vec4<f32>,     // xyz Beer–Lambert absorption of the water per channel (1/m)
    scatter: vec4<f32>,        // xyz light the water scatters towards the eye (linear units)
    ior: vec4<f32>,            // xyz water's refractive index for red, green, blue light (with
                               // dispersion; green is IOR_WATER), w the dispersion factor
    duck_pose: mat4x4<f32>,    // the duck's frame: rotation in columns 0-2, position (m) in column 3
    duck_bound: vec4<f32>,     // xyz centre (m) and w radius (m) of a ball holding the duck; 0 = no duck
    // Per traced duck part (ellipsoid; see duck.rs): centre and semi-axes in the duck's frame (m),
    // and linear colour.
    duck_parts: array<vec4<f32>, 3 * DUCK_PARTS>,
    ambient_header: vec4<f32>, // x waves in ambient_waves, y Gerstner's c = Q / sum(a k)
    // Per ambient wave (ambient.rs): kx, kz (rad/m), amplitude (m), phase at this frame's time.
    ambient_waves: array<vec4<f32>, MAX_AMBIENT_WAVES>,
    flat: vec4<f32>,           // flat water (flat.rs): x plane height (m), y largest texture shift
                               // (fraction of the screen), z dUdV scroll (tiles), w soft edge (m)
    sun_light: vec4<f32>,      // rgb the sun's light on a surface facing it (sky.rs, scene units);
                               // w exposure factor 2^EV before the tone curve
    sky_light: vec4<f32>,      // rgb the sky's light on a surface facing up (albedo factor);
                               // w 1 with the deck around the pool, 0 cut-away
};

@group(0) @binding(0) var<uniform> scene: Scene;
// Simulation state per cell: (height m, vertical velocity m/s, normal.x, normal.z).
@group(0) @binding(1) var water_state: texture_2d<f32>;
// The FFT ocean's surface per texel (height m, dh/dx, dh/dz, dDx/dz), tiling the pool
// (AMBIENT_FFT), and with choppiness its displacement (Dx, Dz m, dDx/dx, dDz/dz) at rest points.
@group(0) @binding(2) var ambient_map: texture_2d<f32>;
@group(0) @binding(3) var ambient_displacement: texture_2d<f32>;

@group(1) @binding(0) var caustics_map: texture_2d<f32>;
@group(1) @binding(1) var tile_texture: texture_2d<f32>;
@group(1) @binding(2) var sky_cube: texture_cube<f32>;
@group(1) @binding(3) var clamp_sampler: sampler;
@group(1) @binding(4) var repeat_sampler: sampler;
// Exact Fresnel reflectance at FRESNEL_TABLE_SIZE angles 0-90°: row 0 from air, row 1 from water.
@group(1) @binding(5) var fresnel_table: texture_2d<f32>;
// Foam amount (0-1) per cell of the CPU field that integrates it (sim/foam.rs), when on.
@group(1) @binding(6) var foam_map: texture_2d<f32>;
// The ambient waves' spectrum for the debug view: log10 amplitude (m) per wavevector cell
// (ambient.rs spectrum_image).
@group(1) @binding(7) var ambient_spectrum: texture_2d<f32>;
// The flat water's dUdV map (flat.rs dudv_map): slopes dH/du, dH/dv in red and green (0.5 flat,
// 0 and 1 the largest, DUDV_SLOPE), tiling DUDV_TILES times across the pool.
@group(1) @binding(8) var dudv_map: texture_2d<f32>;

// How far the sun's highlight is spread for the pixel being shaded (1: not at all; see
// sun_specular); the water surface sets it from how much its normal varies within the pixel.
var<private> specular_spread: f32 = 1.0;
// Mip level of the caustics lookup (caustics_at) for the pixel being shaded: at least
// CAUSTICS_MIN_LOD, more where the pixel covers more of the floor (set by pool_colour_at_hit).
var<private> caustics_lod: f32 = CAUSTICS_MIN_LOD;

// The sun's and the sky's light (sky.rs: Preetham's sky, the sun through the air).
fn sun_light() -> vec3<f32> { return scene.sun_light.rgb; }
fn sky_light() -> vec3<f32> { return scene.sky_light.rgb; }

// The sky's light on a point at height y: under the water only what comes in through the
// opening above and the surface (UNDERWATER_SKY of it), so the sun's caustics stand out.
fn sky_light_at(y: f32) -> vec3<f32> {
    return sky_light() * select(1.0, UNDERWATER_SKY, y < 0.0);
}

const SPHERE_ALBEDO: vec3<f32> = vec3<f32>(0.66, 0.64, 0.60);
// The sphere's clear coat: exponent and peak (times the sun's light) of its highlight.
const SPHERE_GLOSS: f32 = 300.0;
const SPHERE_SHINE: f32 = 60.0;
const FOAM_ALBEDO: vec3<f32> = vec3<f32>(0.9, 0.92, 0.93);

fn half_width() -> f32 { return scene.pool.x; }
fn depth() -> f32 { return scene.pool.y; }
fn rim() -> f32 { return scene.pool.z; }

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
    let bubbles = 0.6 * value_noise(vec3<f32>(p.xz * 90.0, 0.0)) + 0.4 * value_noise(vec3<f32>(p.xz * 23.0, 3.7));
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

// Where the flat-surface refracted sunbeam through p entered the water (xz, m): the
// caustics map is indexed by this point.
fn light_entry(p: vec3<f32>) -> vec2<f32> {
    let r = scene.refracted_sun.xyz;
    return p.xz - r.xz * (p.y / r.y);
}

fn caustics_uv(entry: vec2<f32>) -> vec2<f32> {
    let m = entry / half_width();
    return vec2<f32>(m.x * 0.5 + 0.5, 0.5 - m.y * 0.5);
}

// The caustics map at uv over the pixel's footprint on the floor (caustics_lod: at least
// CAUSTICS_MIN_LOD, where lines focused into one texel are blended about two wide): one
// trilinear fetch from its mip chain (render/caustics_mips.rs).
fn caustics_at(uv: vec2<f32>) -> vec4<f32> {
    return textureSampleLevel(caustics_map, clamp_sampler, uv, caustics_lod);
}

// 1 when the straight ray from the surface point p towards the sun clears the pool rim.
fn rim_visibility(p: vec3<f32>) -> f32 {
    let s = scene.sun.xyz;
    let w = half_width();
    let tx = (sign(s.x) * w - p.x) / select(s.x, 1.0e-6, abs(s.x) < 1.0e-6);
    let tz = (sign(s.z) * w - p.z) / select(s.z, 1.0e-6, abs(s.z) < 1.0e-6);
    let t = max(min(abs(tx), abs(tz)), 0.0);
    let height = p.y + t * s.y;
    return smoothstep(rim() - 0.02, rim() + 0.02, height);
}

// What a ray hits on an object: distance (NO_HIT for nothing), outward normal, colour.
struct ObjectHit {
    t: f32,
    normal: vec3<f32>,
    albedo: vec3<f32>,
};

fn duck_rotation() -> mat3x3<f32> {
    return mat3x3<f32>(scene.duck_pose[0].xyz, scene.duck_pose[1].xyz, scene.duck_pose[2].xyz);
}

// Whether the segment origin + t dir, t in [0, t_max], comes near the duck at all.
fn near_duck(origin: vec3<f32>, dir: vec3<f32>, t_max: f32) -> bool {
    if (!HAS_DUCK || scene.duck_bound.w <= 0.0) {
        return false;
    }
    let t = clamp(dot(scene.duck_bound.xyz - origin, dir), 0.0, t_max);
    return distance(origin + dir * t, scene.duck_bound.xyz) < scene.duck_bound.w;
}

// Nearest hit of a ray with the duck. Each part is a unit ball stretched by its semi-axes, so
// the ray is taken into the duck's frame and divided by them: there the hit is a ray-sphere
// test with the same t, and the normal is the unit-ball point divided by the semi-axes.
fn intersect_duck(origin: vec3<f32>, dir: vec3<f32>) -> ObjectHit {
    var hit = ObjectHit(NO_HIT, vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(0.0));
    if (!HAS_DUCK) {
        return hit;
    }
    if (!near_duck(origin, dir, NO_HIT)) {
        return hit;
    }
    let to_duck = transpose(duck_rotation());
    let o_duck = to_duck * (origin - scene.duck_pose[3].xyz);
    let d_duck = to_duck * dir;
    for (var i = 0; i < DUCK_PARTS; i++) {
        let radii = scene.duck_parts[3 * i + 1].xyz;
        let o = (o_duck - scene.duck_parts[3 * i].xyz) / radii;
        let d = d_duck / radii;
        let a = dot(d, d);
        let b = dot(o, d);
        let disc = b * b - a * (dot(o, o) - 1.0);
        if (disc >= 0.0) {
            let t = (-b - sqrt(disc)) / a;
            if (t > 1.0e-4 && t < hit.t) {
                hit.t = t;
                hit.normal = normalize(duck_rotation() * ((o + d * t) / radii));
                hit.albedo = scene.duck_parts[3 * i + 2].rgb;
            }
        }
    }
    return hit;
}

// Light the duck lets through along a segment, like sphere_visibility: per part, how close
// the segment passes to its centre in the part's unit-ball space.
fn duck_visibility(origin: vec3<f32>, dir: vec3<f32>, t_max: f32) -> f32 {
    if (!HAS_DUCK) {
        return 1.0;
    }
    if (!near_duck(origin, dir, t_max)) {
        return 1.0;
    }
    let to_duck = transpose(duck_rotation());
    let o_duck = to_duck * (origin - scene.duck_pose[3].xyz);
    let d_duck = to_duck * dir;
    var light = 1.0;
    for (var i = 0; i < DUCK_PARTS; i++) {
        let radii = scene.duck_parts[3 * i + 1].xyz;
        let o = (o_duck - scene.duck_parts[3 * i].xyz) / radii;
        let d = d_duck / radii;
        let t = clamp(-dot(o, d) / dot(d, d), 0.0, t_max);
        light *= smoothstep(0.85, 1.1, length(o + d * t));
    }
    return light;
}

// Light both objects let through towards the sun from p (above the water).
fn objects_visibility(p: vec3<f32>, dir: vec3<f32>, t_max: f32) -> f32 {
    var light = 1.0;
    if (HAS_SPHERE) {
        light = sphere_visibility(p, dir, t_max, scene.sphere.xyz, scene.sphere.w);
    }
    if (HAS_DUCK) {
        light *= duck_visibility(p, dir, t_max);
    }
    return light;
}

// Nearest distance along a ray to the sphere, or NO_HIT (always, when there is no sphere).
fn hit_sphere(origin: vec3<f32>, dir: vec3<f32>) -> f32 {
    if (!HAS_SPHERE) {
        return NO_HIT;
    }
    return intersect_sphere(origin, dir, scene.sphere.xyz, scene.sphere.w);
}

// Sunlight reaching an underwater point p, relative to a flat calm surface (1 = calm).
// with_sphere_shadow: whether the objects' shadows are included (not for the objects themselves).
fn underwater_light(p: vec3<f32>, with_sphere_shadow: bool) -> f32 {
    let entry = light_entry(p);
    let inside = all(abs(entry) <= vec2<f32>(half_width()));
    if (!inside) {
        return 0.0;
    }
    if (HAS_CAUSTICS) {
        let c = caustics_at(caustics_uv(entry)) * scene.water.w;
        return select(c.r, c.g, with_sphere_shadow);
    }
    // Caustics off: a calm surface, with the same rim and sphere shadows.
    let surface = vec3<f32>(entry.x, 0.0, entry.y);
    var light = rim_visibility(surface);
    if (FLAT_CAUSTICS) {
        // Seed 000's fake caustics: follow the calm refracted sunbeam back up through the
        // flat water's normal there; where it leaves towards the sun the floor is bright, where
        // the normal tilts it away, darker. No focusing: a highlight pattern, not caustics.
        let n = flat_normal(entry);
        let to_source = refract(-scene.refracted_sun.xyz, -n, IOR_WATER / IOR_AIR);
        light *= 0.6 + 0.9 * pow(max(dot(to_source, scene.sun.xyz), 0.0), 1500.0);
    }
    if (with_sphere_shadow && (HAS_SPHERE || HAS_DUCK)) {
        let r = scene.refracted_sun.xyz;
        light *= objects_visibility(surface, r, distance(surface, p));
        light *= objects_visibility(surface, scene.sun.xyz, 10.0);
    }
    return light;
}

// Underwater light per colour channel. With dispersion the caustics map holds each channel's
// own light (drawn with its own index of refraction, shadows included) and green's without
// the objects' shadows in alpha; without, every channel has underwater_light's.
fn underwater_light_rgb(p: vec3<f32>, with_sphere_shadow: bool) -> vec3<f32> {
    if (HAS_DISPERSION && HAS_CAUSTICS) {
        let entry = light_entry(p);
        if (!all(abs(entry) <= vec2<f32>(half_width()))) {
            return vec3<f32>(0.0);
        }
        let c = caustics_at(caustics_uv(entry)) * scene.water.w;
        return select(vec3<f32>(c.a), c.rgb, with_sphere_shadow);
    }
    return vec3<f32>(underwater_light(p, with_sphere_shadow));
}

// Analytic ambient occlusion of a sphere seen from a point with normal n:
// the sphere's projected solid angle, cos(theta) * (r / d)^2.
fn sphere_occlusion(p: vec3<f32>, n: vec3<f32>) -> f32 {
    let r = scene.sphere.w;
    if (!HAS_SPHERE || r <= 0.0) {
        return 0.0;
    }
    let to_centre = scene.sphere.xyz - p;
    let d2 = dot(to_centre, to_centre);
    let cos_t = max(dot(n, to_centre * inverseSqrt(d2)), 0.0);
    return clamp(cos_t * r * r / d2, 0.0, 1.0);
}

// Inward normal of the pool face nearest to p (floor or one of the four walls).
// Written with select rather than branches: it runs per pixel for two rays.
fn pool_normal(p: vec3<f32>) -> vec3<f32> {
    let w = half_width();
    let dx = w - abs(p.x);
    let dz = w - abs(p.z);
    let dy = p.y + depth();
    let wall = select(vec3<f32>(0.0, 0.0, -sign(p.z)), vec3<f32>(-sign(p.x), 0.0, 0.0), dx < dz);
    return select(wall, vec3<f32>(0.0, 1.0, 0.0), dy <= dx && dy <= dz);
}

// Texture coordinates (m) of the tiles at p on the face with inward normal n.
fn tile_uv(p: vec3<f32>, n: vec3<f32>) -> vec2<f32> {
    let wall = select(vec2<f32>(p.x, -p.y), vec2<f32>(p.z, -p.y), abs(n.x) > 0.5);
    return select(wall, p.xz, abs(n.y) > 0.5);
}

// Lit colour (linear RGB) of the pool's tiles at p with inward normal n and tile colour
// albedo, before any water attenuation between p and the viewer. Under the rest level the
// sun arrives refracted, through the caustics; above it, directly.
fn pool_colour(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>) -> vec3<f32> {
    if (HAS_DISPERSION && p.y < 0.0) {
        // Each colour through its own caustics.
        let direct_rgb = max(dot(n, -scene.refracted_sun.xyz), 0.0) * underwater_light_rgb(p, true);
        let ambient = sky_light_at(p.y) * (1.0 - 0.9 * sphere_occlusion(p, n));
        return albedo * (ambient + direct_rgb * sun_light());
    }
    var direct: f32;
    if (p.y < 0.0) {
        direct = max(dot(n, -scene.refracted_sun.xyz), 0.0) * underwater_light(p, true);
    } else {
        direct = max(dot(n, scene.sun.xyz), 0.0) * objects_visibility(p, scene.sun.xyz, 10.0);
    }
    let ambient = sky_light_at(p.y) * (1.0 - 0.9 * sphere_occlusion(p, n));
    return albedo * (ambient + direct * sun_light());
}

// Distance (m) along a ray from inside the pool box to where it leaves it (the tile it
// would hit, or the opening above the rim).
fn pool_exit_distance(origin: vec3<f32>, dir: vec3<f32>) -> f32 {
    let w = half_width();
    let box = intersect_box(origin, dir, vec3<f32>(-w, -depth(), -w), vec3<f32>(w, rim(), w));
    return max(box.y, 0.0);
}

// Mip level for the tiles seen at `hit` through this pixel, from how fast the tile
// coordinates change across the screen. Call in uniform control flow (it uses derivatives).
fn tile_lod(hit: vec3<f32>) -> f32 {
    let uv = tile_uv(hit, pool_normal(hit));
    let footprint = max(length(dpdx(uv)), length(dpdy(uv))) * f32(textureDimensions(tile_texture).x);
    return clamp(log2(max(footprint, 1.0)), 0.0, 12.0);
}

// pool_colour for a traced ray hit, at a mip level the caller worked out with tile_lod.
fn pool_colour_at_hit(p: vec3<f32>, lod: f32) -> vec3<f32> {
    // The tiles' footprint (2^lod texels of a map of a metre) in caustics texels.
    let footprint = exp2(lod) / f32(textureDimensions(tile_texture).x) * f32(textureDimensions(caustics_map).x) / (2.0 * half_width());
    caustics_lod = max(CAUSTICS_MIN_LOD, log2(max(footprint, 1.0e-3)));
    let n = pool_normal(p);
    let albedo = textureSampleLevel(tile_texture, repeat_sampler, tile_uv(p, n), lod).rgb;
    return pool_colour(p, n, albedo);
}

// Lit colour of an object (sphere or duck) at surface point p with outward normal n: diffuse
// sunlight (through the caustics under water),
// ambient darkened where the floor and walls are close (ambient occlusion).
fn object_colour(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>) -> vec3<f32> {
    var direct: f32;
    if (p.y < 0.0) {
        direct = max(dot(n, -scene.refracted_sun.xyz), 0.0) * underwater_light(p, false);
    } else {
        direct = max(dot(n, scene.sun.xyz), 0.0);
    }
    // Occlusion by the floor and walls falls off with distance from each plane.
    let w = half_width();
    var occlusion = max(-n.y, 0.0) * exp(-4.0 * (p.y + depth()));
    occlusion += max(n.x, 0.0) * exp(-4.0 * (w - p.x)) + max(-n.x, 0.0) * exp(-4.0 * (p.x + w));
    occlusion += max(n.z, 0.0) * exp(-4.0 * (w - p.z)) + max(-n.z, 0.0) * exp(-4.0 * (p.z + w));
    let ambient = sky_light_at(p.y) * (1.0 - 0.6 * clamp(occlusion, 0.0, 1.0));
    return albedo * (ambient + direct * sun_light());
}

// The sphere, seen along dir: diffuse paint under a clear coat. Within a few centimetres above
// the rest level it is wet (darker paint, a stronger coat); above the water the coat mirrors
// the sky and the sun by Schlick's Fresnel (r0 = 0.04, a lacquer's index of about 1.5).
fn sphere_colour(p: vec3<f32>, dir: vec3<f32>) -> vec3<f32> {
    let n = normalize(p - scene.sphere.xyz);
    let wet = 1.0 - smoothstep(0.0, 0.04, p.y);
    var colour = object_colour(p, n, SPHERE_ALBEDO * mix(1.0, 0.72, wet));
    let fresnel = 0.04 + 0.96 * pow(1.0 - max(dot(-dir, n), 0.0), 5.0);
    let r = reflect(dir, n);
    // The sky in the coat, and the sun's highlight on it (a glossy lobe, cos^SPHERE_GLOSS).
    let highlight = sun_light() * SPHERE_SHINE * pow(max(dot(r, scene.sun.xyz), 0.0), SPHERE_GLOSS);
    let coat = fresnel * (1.0 + wet) * (sky_colour(r) + highlight);
    return colour + select(vec3<f32>(0.0), coat, p.y > 0.0);
}

// The duck's rubber: diffuse like the sphere plus a broad glossy highlight of the sun,
// seen along dir, where the sun reaches it directly.
fn duck_colour(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>, dir: vec3<f32>) -> vec3<f32> {
    var colour = object_colour(p, n, albedo);
    if (p.y >= 0.0) {
        let gloss = pow(max(dot(reflect(dir, n), scene.sun.xyz), 0.0), 40.0);
        colour += sun_light() * 0.35 * gloss;
    }
    return colour;
}

// The sky cubemap (radiance / SKY_RANGE) plus the sun's disk (the sun_size parameter across,
// HDR so its reflections stay bright), dimmed where the cubemap's alpha says clouds cover it.
fn sky_colour(dir: vec3<f32>) -> vec3<f32> {
    let sky = textureSampleLevel(sky_cube, clamp_sampler, dir, 0.0);
    let disk = smoothstep(scene.optics.y, scene.optics.z, dot(dir, scene.sun.xyz));
    // Seen in rippled water the disk is spread as the highlight is (specular_spread), so it
    // does not sparkle from pixel to pixel.
    let spread = specular_spread * specular_spread;
    return sky.rgb * SKY_RANGE + sun_light() * SUN_DISK_RADIANCE * spread * disk * (1.0 - 0.8 * sky.a);
}

// Specular reflection of the sun on water, sharper and brighter than the cubemap's disk
// can hold at its resolution: the glitter on ripples. dir: a ray leaving the surface into
// the air. Phong: cos^s of the angle between dir (the mirrored view ray) and the sun.
// Blinn-Phong: cos^s of the angle between the surface normal and the half vector of the
// directions to the eye and to the sun, for a mirrored ray (`normal` given; a ray refracted
// out of the water passes a zero normal and keeps Phong's lobe).
fn sun_specular(dir: vec3<f32>, normal: vec3<f32>) -> vec3<f32> {
    var lobe = max(dot(dir, scene.sun.xyz), 0.0);
    if (SPECULAR_MODEL == SPECULAR_BLINN_PHONG) {
        let to_eye = -reflect(dir, normal);
        let half_vector = normalize(to_eye + scene.sun.xyz);
        lobe = select(lobe, max(dot(normal, half_vector), 0.0), dot(normal, normal) > 0.5);
    }
    // Toksvig: where the normals vary within the pixel the lobe widens (specular_spread < 1)
    // and its peak falls, instead of sparkling from pixel to pixel. By the square root of the
    // energy-keeping factor (s' + 2) / (s + 2): the glitter of sub-pixel ripples stays bright.
    let s = scene.optics.x * specular_spread;
    return sun_light() * SUN_GLINT * sqrt((s + 2.0) / (scene.optics.x + 2.0)) * pow(lobe, s);
}

// Fresnel reflectance by this variant's model (FRESNEL_MODEL; the formulas, their sources and
// the tests that hold these pixels to them are in optics.rs). cos_i: cosine of the incidence
// angle; eta: n_from / n_to. Below the surface the approximations take the angle on the air
// side (Snell); total internal reflection stays exact.
fn reflectance(cos_i: f32, eta: f32) -> f32 {
    if (FRESNEL_MODEL == FRESNEL_EXACT) {
        return fresnel(cos_i, eta);
    }
    let ci = clamp(cos_i, 0.0, 1.0);
    let sin_t2 = eta * eta * (1.0 - ci * ci);
    if (sin_t2 >= 1.0) {
        return 1.0;
    }
    let c = select(ci, sqrt(1.0 - sin_t2), eta > 1.0);
    if (FRESNEL_MODEL == FRESNEL_TABLE) {
        // Indexed by the air-side angle (optics::fresnel_table); linear interpolation between
        // the two texels around it, by hand: 32-bit float textures are not filterable everywhere.
        let u = acos(c) / (0.5 * PI) * f32(FRESNEL_TABLE_SIZE - 1);
        let i = min(i32(floor(u)), FRESNEL_TABLE_SIZE - 2);
        let row = select(0, 1, eta > 1.0);
        let a = textureLoad(fresnel_table, vec2<i32>(i, row), 0).r;
        let b = textureLoad(fresnel_table, vec2<i32>(i + 1, row), 0).r;
        return a + (b - a) * (u - f32(i));
    }
    if (FRESNEL_MODEL == FRESNEL_SCHLICK) {
        return SCHLICK_R0 + (1.0 - SCHLICK_R0) * pow(1.0 - c, 5.0);
    }
    if (FRESNEL_MODEL == FRESNEL_INVERSE_POWER) {
        return 1.0 / pow(1.0 + c, INVERSE_POWER_EXPONENT);
    }
    if (FRESNEL_MODEL == FRESNEL_CLAMPED_POWER) {
        return clamp(pow(1.0 - c, CLAMPED_POWER_EXPONENT), CLAMPED_POWER_MIN, CLAMPED_POWER_MAX);
    }
    return 1.0 - c;
}

// Light leaving `far` as it arrives at `near` through the water between them. Beer–Lambert:
// each channel keeps α = exp(-a d) of itself over d metres (red dies first, so long paths turn
// blue-green). With in-scattering (HAS_SCATTERING; seed 001, after Baboud and Décoret) the
// water adds the light it scatters towards the eye, filling in what it absorbed:
// α L + (1 - α) L_s; with VIEW_COLOUR L_s is tinted by the path's angle as seed 002 does.
fn through_water(colour: vec3<f32>, near: vec3<f32>, far: vec3<f32>) -> vec3<f32> {
    let alpha = exp(-scene.absorption.xyz * water_path(near, far, half_width(), depth()));
    if (!HAS_SCATTERING) {
        return colour * alpha;
    }
    var scattered = scene.scatter.xyz;
    if (VIEW_COLOUR) {
        let path = far - near;
        scattered *= mix(GRAZING_TINT, vec3<f32>(1.0), abs(path.y) / max(length(path), 1.0e-6));
    }
    return colour * alpha + (1.0 - alpha) * scattered;
}

// What a ray starting in the water sees: the sphere or the pool's inside, dimmed by the
// water it crossed (Beer–Lambert). t_exit: pool_exit_distance of the ray; lod: tile mip
// level (see tile_lod).
fn trace_water(origin: vec3<f32>, dir: vec3<f32>, t_exit: f32, lod: f32) -> vec3<f32> {
    var t = t_exit;
    var colour: vec3<f32>;
    let ts = hit_sphere(origin, dir);
    let duck = intersect_duck(origin, dir);
    if (duck.t < t && duck.t < ts) {
        t = duck.t;
        colour = duck_colour(origin + dir * t, duck.normal, duck.albedo, dir);
    } else if (ts < t) {
        t = ts;
        colour = sphere_colour(origin + dir * t, dir);
    } else {
        let hit = origin + dir * t;
        colour = pool_colour_at_hit(hit, lod);
    }
    return through_water(colour, origin, origin + dir * t);
}

// A ray leaving the surface into the air, folded back up if it still points down (a
// reflection off a steep wave); a zero vector (refract's total internal reflection) gives
// straight up, so that its colour stays finite even where its weight is zero.
fn upward(dir: vec3<f32>) -> vec3<f32> {
    return normalize(vec3<f32>(dir.x, max(abs(dir.y), 1.0e-4), dir.z));
}

// What a ray starting at the surface and going up through air (see upward) sees: the
// sphere, the pool walls above the water line, or the sky. normal: the surface normal the
// ray was mirrored at (zero for a refracted ray; see sun_specular); t_exit:
// pool_exit_distance of the ray; lod: tile mip level (see tile_lod).
fn trace_air(origin: vec3<f32>, dir: vec3<f32>, normal: vec3<f32>, t_exit: f32, lod: f32) -> vec3<f32> {
    let ts = hit_sphere(origin, dir);
    let t = t_exit;
    let duck = intersect_duck(origin, dir);
    if (duck.t < t && duck.t < ts) {
        return duck_colour(origin + dir * duck.t, duck.normal, duck.albedo, dir);
    }
    if (ts < t) {
        return sphere_colour(origin + dir * ts, dir);
    }
    let hit = origin + dir * t;
    if (hit.y < rim() - 1.0e-3) {
        return pool_colour_at_hit(hit, lod);
    }
    return sky_colour(dir) + sun_specular(dir, normal);
}

// Final colour written to the target: scene light times the exposure through a filmic curve
// (Narkowicz's fit of the ACES film response: a toe that keeps shade dark, a shoulder that
// rolls bright caustics and glints off to white instead of clipping); sRGB-encoded in the
// shader when the target format does not do it in hardware (WebGPU canvases are plain UNORM).
fn tone_map(c: vec3<f32>) -> vec3<f32> {
    let x = c * scene.sun_light.w * EXPOSURE_SCALE;
    return (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
}

// Debug values in [0, 1] per channel as the colour that displays as them (stored as v * 255):
// no tone curve.
fn as_displayed(v: vec3<f32>) -> vec4<f32> {
    let g = clamp(v, vec3<f32>(0.0), vec3<f32>(1.0));
    if (scene.output.x > 0.5) {
        return vec4<f32>(g, 1.0);
    }
    return vec4<f32>(srgb_to_linear(g), 1.0);
}

// A surface point p seen directly (pool, sphere, duck), of lit colour `colour`, as written to
// the target: dimmed by the water between it and the eye. In the flat water's textures
// (CLIP_SIDE, flat.rs) only the side of the water plane the texture keeps; the refraction
// texture holds the water path in alpha (m / FLAT_PATH_SCALE), the reflection 0 (the sky, 1,
// is where the sun's highlight may show).
fn seen_directly(colour: vec3<f32>, p: vec3<f32>) -> vec4<f32> {
    var out = finish(through_water(colour, scene.eye.xyz, p));
    if (CLIP_SIDE != 0) {
        if (f32(CLIP_SIDE) * (p.y - scene.flat.x) < 0.0) {
            discard;
        }
        let path = water_path(scene.eye.xyz, p, half_width(), depth()) / FLAT_PATH_SCALE;
        out.a = select(0.0, min(path, 1.0), CLIP_SIDE < 0);
    }
    return out;
}

fn finish(c: vec3<f32>) -> vec4<f32> {
    let mapped = clamp(tone_map(max(c, vec3<f32>(0.0))), vec3<f32>(0.0), vec3<f32>(1.0));
    if (scene.output.x > 0.5) {
        return vec4<f32>(linear_to_srgb(mapped), 1.0);
    }
    return vec4<f32>(mapped, 1.0);
}
