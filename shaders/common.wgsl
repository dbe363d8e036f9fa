// Pure helpers of the pool scene (no bindings): ray intersections, Fresnel, paths through water.
// Units: metres. The pool spans x, z in [-W, W], y in [-D, R]; water rests at y = 0.
// IOR_WATER is written ahead of it from the Rust constant (render::shaders); PI and the
// colour helpers are in math.wgsl.

const IOR_AIR: f32 = 1.0;
const NO_HIT: f32 = 1.0e9;

// Entry and exit distances of a ray through an axis-aligned box (slab method).
// Returns (t_near, t_far); the ray misses when t_near > t_far.
fn intersect_box(origin: vec3<f32>, dir: vec3<f32>, box_min: vec3<f32>, box_max: vec3<f32>) -> vec2<f32> {
    let inv = 1.0 / dir;
    let t0 = (box_min - origin) * inv;
    let t1 = (box_max - origin) * inv;
    let t_small = min(t0, t1);
    let t_big = max(t0, t1);
    let t_near = max(max(t_small.x, t_small.y), t_small.z);
    let t_far = min(min(t_big.x, t_big.y), t_big.z);
    return vec2<f32>(t_near, t_far);
}

// How far (m) the ray origin + t unit dir, t >= 0, passes outside a sphere: its nearest
// approach to the centre less the radius, negative where it passes inside (NO_HIT for a
// radius of 0: no sphere). It runs on smoothly across the outline (an edge's blend reads it).
fn ray_sphere_gap(origin: vec3<f32>, dir: vec3<f32>, centre: vec3<f32>, radius: f32) -> f32 {
    let t = max(dot(centre - origin, dir), 0.0);
    return select(NO_HIT, distance(origin + dir * t, centre) - radius, radius > 0.0);
}

// Nearest positive distance along a ray to a sphere's surface, or NO_HIT.
fn intersect_sphere(origin: vec3<f32>, dir: vec3<f32>, centre: vec3<f32>, radius: f32) -> f32 {
    let oc = origin - centre;
    let b = dot(oc, dir);
    let c = dot(oc, oc) - radius * radius;
    let disc = b * b - c;
    if (radius <= 0.0 || disc < 0.0) {
        return NO_HIT;
    }
    let s = sqrt(disc);
    let t = -b - s;
    if (t > 1.0e-4) {
        return t;
    }
    let t2 = -b + s;
    return select(NO_HIT, t2, t2 > 1.0e-4 && c > 0.0);
}

// Fraction of light a sphere lets through along the segment origin + t*dir, t in [0, t_max], to
// the point it lights, t_lit along the same line (t_max for a beam the segment follows down, 0
// where the segment starts at the point lit and runs towards the sun, negative where the light
// goes on past the origin): 0 when the segment passes through the sphere's core, 1 when it
// misses, soft in between. The penumbra grows with the distance from the sphere to the point
// lit, SHADOW_SPREAD per metre (the sun's disk, and the spread of directions the ripples give
// the light), from a tenth of the radius where the sphere nearly touches it: a contact shadow.
const SHADOW_SPREAD: f32 = 0.1;

fn sphere_visibility(origin: vec3<f32>, dir: vec3<f32>, t_max: f32, t_lit: f32, centre: vec3<f32>, radius: f32) -> f32 {
    if (radius <= 0.0) {
        return 1.0;
    }
    let t = clamp(dot(centre - origin, dir), 0.0, t_max);
    let closest = distance(origin + dir * t, centre);
    let half = radius * 0.1 + abs(t_lit - t) * SHADOW_SPREAD;
    return smoothstep(radius - half, radius + half, closest);
}

// Reflectance of a smooth dielectric for unpolarised light (exact Fresnel equations).
// cos_i: cosine of the incidence angle; eta: n_from / n_to. Total internal reflection gives 1.
fn fresnel(cos_i: f32, eta: f32) -> f32 {
    let ci = clamp(cos_i, 0.0, 1.0);
    let sin_t2 = eta * eta * (1.0 - ci * ci);
    if (sin_t2 >= 1.0) {
        return 1.0;
    }
    let ct = sqrt(1.0 - sin_t2);
    let rs = (eta * ci - ct) / (eta * ci + ct);
    let rp = (ci - eta * ct) / (ci + eta * ct);
    return 0.5 * (rs * rs + rp * rp);
}

// Length (m) of the straight segment a -> b that lies inside the water volume
// (the pool box below the rest level), for Beer–Lambert attenuation.
fn water_path(a: vec3<f32>, b: vec3<f32>, half_width: f32, depth: f32) -> f32 {
    let d = b - a;
    let len = length(d);
    if (len < 1.0e-6) {
        return 0.0;
    }
    let dir = d / len;
    let t = intersect_box(a, dir, vec3<f32>(-half_width, -depth, -half_width), vec3<f32>(half_width, 0.0, half_width));
    let t0 = max(t.x, 0.0);
    let t1 = min(t.y, len);
    return max(t1 - t0, 0.0);
}

// Analytic ambient occlusion of a ball (xyz centre, w radius; radius 0: none) seen from p with
// normal n: its projected solid angle, cos(theta) * (r / d)^2.
fn sphere_occlusion_of(p: vec3<f32>, n: vec3<f32>, ball: vec4<f32>) -> f32 {
    let r = ball.w;
    if (r <= 0.0) {
        return 0.0;
    }
    let to_centre = ball.xyz - p;
    let d2 = dot(to_centre, to_centre);
    let cos_t = max(dot(n, to_centre * inverseSqrt(d2)), 0.0);
    return clamp(cos_t * r * r / d2, 0.0, 1.0);
}
