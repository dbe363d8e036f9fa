// The beach ball (bodies/ball.rs): a sphere of thin plastic in six gores of colour around its
// axis, with white caps, turned with its pose. Traced like the sphere (hit, the light it
// blocks, the ambient light it takes from the pool near it), its vinyl under a glossy coat;
// drawn directly as a unit mesh scaled and moved to its centre, its outline blended in
// (ball_edge). Uniform (BALL_SLOT on): centre
// and radius (0: no ball), then the three columns of its rotation.

const BALL_GORES: array<vec3<f32>, 6> = array<vec3<f32>, 6>(
    vec3<f32>(0.80, 0.05, 0.04),
    vec3<f32>(0.95, 0.92, 0.90),
    vec3<f32>(0.98, 0.60, 0.02),
    vec3<f32>(0.95, 0.92, 0.90),
    vec3<f32>(0.04, 0.22, 0.75),
    vec3<f32>(0.95, 0.92, 0.90),
);
const BALL_CAP: vec3<f32> = vec3<f32>(0.95, 0.92, 0.90);

fn ball_uniform() -> vec4<f32> {
    return scene.bodies[BALL_SLOT];
}

fn ball_turn() -> mat3x3<f32> {
    return mat3x3<f32>(scene.bodies[BALL_SLOT + 1].xyz, scene.bodies[BALL_SLOT + 2].xyz, scene.bodies[BALL_SLOT + 3].xyz);
}

// The plastic's colour at outward normal n (world): its gore around the ball's own axis, or
// the white cap near a pole.
fn ball_albedo(n: vec3<f32>) -> vec3<f32> {
    let local = transpose(ball_turn()) * n;
    if (abs(local.y) > 0.9) {
        return BALL_CAP;
    }
    let gore = i32(floor((atan2(local.z, local.x) / (2.0 * PI) + 0.5) * 6.0)) % 6;
    return BALL_GORES[gore];
}

fn ball_hit(origin: vec3<f32>, dir: vec3<f32>) -> ObjectHit {
    let u = ball_uniform();
    let t = intersect_sphere(origin, dir, u.xyz, u.w);
    let n = normalize(origin + dir * min(t, 1.0e3) - u.xyz);
    return ObjectHit(t, n, ball_albedo(n), ray_sphere_gap(origin, dir, u.xyz, u.w));
}

// Signed distance (m) from the ball's surface, negative inside (bodies_field).
fn ball_field(p: vec3<f32>) -> f32 {
    let u = ball_uniform();
    return distance(p, u.xyz) - u.w;
}

fn ball_light(origin: vec3<f32>, dir: vec3<f32>, t_max: f32, t_lit: f32) -> f32 {
    let u = ball_uniform();
    return sphere_visibility(origin, dir, t_max, t_lit, u.xyz, u.w);
}

// Diffuse vinyl under a glossy coat (clear_coat) above the water, wet and darker within
// BALL_WET_BAND above the rest level (under, direct: see coated_colour).
const BALL_GLOSS: f32 = 80.0;
const BALL_SHINE: f32 = 15.0;
const BALL_WET_ALBEDO: f32 = 0.75;
const BALL_WET_BAND: f32 = 0.03;

fn ball_shade(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>, dir: vec3<f32>, under: bool, direct: bool) -> vec3<f32> {
    return coated_colour(p, n, albedo, dir, under, direct, Coat(BALL_WET_BAND, BALL_WET_ALBEDO, BALL_GLOSS, BALL_SHINE));
}

// The ambient light the ball takes from a point with normal n (sphere_occlusion_of).
fn ball_occlusion(p: vec3<f32>, n: vec3<f32>) -> f32 {
    return sphere_occlusion_of(p, n, ball_uniform());
}

struct BallOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
};

@vertex
fn vs_ball(@location(0) unit: vec3<f32>) -> BallOut {
    var out: BallOut;
    out.world = ball_uniform().xyz + unit * ball_uniform().w;
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

@fragment
fn fs_ball(in: BallOut) -> @location(0) vec4<f32> {
    let n = normalize(in.world - ball_uniform().xyz);
    let view = normalize(in.world - scene.eye.xyz);
    return seen_directly(ball_shade(in.world, n, ball_albedo(n), view, lit_under(in.world), true), in.world);
}

// The ball's outline, blended over what lies behind (ball_edge).
@vertex
fn vs_ball_edge(@location(0) unit: vec3<f32>) -> BallOut {
    var out: BallOut;
    out.world = grown_rim(ball_uniform().xyz + unit * ball_uniform().w, unit, ball_uniform().w * (BALL_EDGE_GROWTH - 1.0));
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

@fragment
fn fs_ball_edge(in: BallOut) -> @location(0) vec4<f32> {
    let edge = ball_edge(in.world, ball_uniform());
    if (edge.hidden) {
        return vec4<f32>(0.0); // not discarded: see grown_rim
    }
    let p = edge.point;
    let n = normalize(p - ball_uniform().xyz);
    let out = seen_directly(ball_shade(p, n, ball_albedo(n), normalize(p - scene.eye.xyz), lit_under(p), true), p);
    return vec4<f32>(out.rgb, edge.cover);
}
