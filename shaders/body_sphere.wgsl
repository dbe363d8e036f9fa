// The sphere (bodies/sphere.rs): a ball of paint under a clear coat. Traced in the scene's rays
// (hit, the light it blocks, its colour, the ambient light it takes from the pool near it),
// drawn directly as a unit mesh scaled and moved to its centre, and its outline blended in
// (ball_edge).

const SPHERE_ALBEDO: vec3<f32> = vec3<f32>(0.66, 0.64, 0.60);
// The sphere's clear coat: exponent and peak (times the sun's light) of its highlight.
const SPHERE_GLOSS: f32 = 300.0;
const SPHERE_SHINE: f32 = 60.0;
// How far above the rest level (m) the sphere is wet, and the share of its colour left there.
const SPHERE_WET_BAND: f32 = 0.04;
const SPHERE_WET_ALBEDO: f32 = 0.72;

// The sphere's uniform: xyz centre (m), w radius (m).
fn sphere_uniform() -> vec4<f32> {
    return scene.bodies[SPHERE_SLOT];
}

// The sphere's hit for hit_bodies (its colour finds the normal itself).
fn sphere_hit(origin: vec3<f32>, dir: vec3<f32>) -> ObjectHit {
    let u = sphere_uniform();
    let t = intersect_sphere(origin, dir, u.xyz, u.w);
    return ObjectHit(t, vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(0.0), ray_sphere_gap(origin, dir, u.xyz, u.w));
}

// Signed distance (m) from the sphere's surface, negative inside (bodies_field).
fn sphere_field(p: vec3<f32>) -> f32 {
    let u = sphere_uniform();
    return distance(p, u.xyz) - u.w;
}

// Light the sphere lets through along a segment to the point at t_lit (see sphere_visibility).
fn sphere_light(origin: vec3<f32>, dir: vec3<f32>, t_max: f32, t_lit: f32) -> f32 {
    let u = sphere_uniform();
    return sphere_visibility(origin, dir, t_max, t_lit, u.xyz, u.w);
}

fn sphere_shade(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>, dir: vec3<f32>, under: bool, direct: bool) -> vec3<f32> {
    return sphere_colour(p, dir, under, direct);
}

// The sphere, seen along dir: diffuse paint under a clear coat. Within a few centimetres above
// the rest level it is wet (darker paint, a stronger coat); above the water the coat mirrors
// the sky and the sun (clear_coat). under: see object_colour; direct: see coated_colour.
fn sphere_colour(p: vec3<f32>, dir: vec3<f32>, under: bool, direct: bool) -> vec3<f32> {
    let n = normalize(p - sphere_uniform().xyz);
    return coated_colour(p, n, SPHERE_ALBEDO, dir, under, direct, Coat(SPHERE_WET_BAND, SPHERE_WET_ALBEDO, SPHERE_GLOSS, SPHERE_SHINE));
}

// The ambient light the sphere takes from a point with normal n (sphere_occlusion_of).
fn sphere_occlusion(p: vec3<f32>, n: vec3<f32>) -> f32 {
    return sphere_occlusion_of(p, n, sphere_uniform());
}

// The sphere seen directly.
struct SphereOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
};

@vertex
fn vs_sphere(@location(0) unit: vec3<f32>) -> SphereOut {
    var out: SphereOut;
    out.world = sphere_uniform().xyz + unit * sphere_uniform().w;
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

@fragment
fn fs_sphere(in: SphereOut) -> @location(0) vec4<f32> {
    return seen_directly(sphere_colour(in.world, normalize(in.world - scene.eye.xyz), lit_under(in.world), true), in.world);
}

// The sphere's outline, blended over what lies behind (ball_edge).
@vertex
fn vs_sphere_edge(@location(0) unit: vec3<f32>) -> SphereOut {
    var out: SphereOut;
    out.world = grown_rim(sphere_uniform().xyz + unit * sphere_uniform().w, unit, sphere_uniform().w * (BALL_EDGE_GROWTH - 1.0));
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

@fragment
fn fs_sphere_edge(in: SphereOut) -> @location(0) vec4<f32> {
    let edge = ball_edge(in.world, sphere_uniform());
    if (edge.hidden) {
        return vec4<f32>(0.0); // not discarded: see grown_rim
    }
    let p = edge.point;
    let out = seen_directly(sphere_colour(p, normalize(p - scene.eye.xyz), lit_under(p), true), p);
    return vec4<f32>(out.rgb, edge.cover);
}
