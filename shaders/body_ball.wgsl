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

// Where outward normal n (world) points on the ball: x how far round its own axis, in gores
// (0..6, 0 the seam between the last gore and the first), y up that axis (-1..1; the white
// caps beyond ±BALL_CAP_EDGE).
const BALL_CAP_EDGE: f32 = 0.9;

fn ball_place(n: vec3<f32>) -> vec2<f32> {
    let local = transpose(ball_turn()) * n;
    return vec2<f32>((atan2(local.z, local.x) / (2.0 * PI) + 0.5) * 6.0, local.y);
}

// The plastic's colour at outward normal n: its gore, or the white cap near a pole.
fn ball_albedo(n: vec3<f32>) -> vec3<f32> {
    let at = ball_place(n);
    if (abs(at.y) > BALL_CAP_EDGE) {
        return BALL_CAP;
    }
    return BALL_GORES[i32(floor(at.x)) % 6];
}

// The plastic's colour over the pixel drawing normal n: each seam between two gores, and the
// caps' edge, blended by the share of the pixel on either side (a ramp one pixel's change
// wide), so that the seams show no stair-steps, as the outline shows none. The pixel's width
// round the axis is read from two places of the seam at 0 (= 6), one of them always free of
// the jump there. Call in uniform control flow (it takes screen derivatives); scene.output.z
// 0 draws each pixel in one colour (the outlines off, for tests to compare with).
fn ball_albedo_in_pixel(n: vec3<f32>) -> vec3<f32> {
    let at = ball_place(n);
    let turned = fract(at.x / 6.0 + 0.5) * 6.0;
    // At most a gore wide: wider, the ramps of two seams would meet at the gore's middle.
    let width = clamp(min(fwidth(at.x), fwidth(turned)), 1.0e-4, 1.0);
    let seam = round(at.x);
    let k = i32(seam) + 6;
    let past = clamp(0.5 + (at.x - seam) / width, 0.0, 1.0);
    let gore = mix(BALL_GORES[(k - 1) % 6], BALL_GORES[k % 6], past);
    let cap = clamp(0.5 + (abs(at.y) - BALL_CAP_EDGE) / max(fwidth(at.y), 1.0e-4), 0.0, 1.0);
    return select(ball_albedo(n), mix(gore, BALL_CAP, cap), scene.output.z > 0.0);
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

// Light the ball lets through along a segment: each wall of thin vinyl it crosses passes
// BALL_WALL_TRANSMITTANCE of the sun's light, diffused (a white film of PVC a tenth of a
// millimetre thick), so that its shadow is lighter than an opaque body's. A segment starting or
// ending inside the ball crosses one wall, any other that passes through it two: the floating
// ball's shadow traced from the water's surface down and up (caustics.wgsl) crosses its bottom
// and its top, about 0.3 in all (which the caustics' contrast power then deepens, as it
// deepens every shadow in the map).
const BALL_WALL_TRANSMITTANCE: f32 = 0.55;

fn ball_light(origin: vec3<f32>, dir: vec3<f32>, t_max: f32, t_lit: f32) -> f32 {
    let u = ball_uniform();
    let inside = f32(distance(origin, u.xyz) < u.w) + f32(distance(origin + dir * t_max, u.xyz) < u.w);
    let walls = max(2.0 - inside, 0.0);
    return mix(pow(BALL_WALL_TRANSMITTANCE, walls), 1.0, sphere_visibility(origin, dir, t_max, t_lit, u.xyz, u.w));
}

// Diffuse vinyl under a glossy coat (clear_coat) above the water, wet and darker within
// BALL_WET_BAND above the rest level (under, direct: see coated_colour), and lit from inside
// through its walls (light_from_inside).
const BALL_GLOSS: f32 = 80.0;
const BALL_SHINE: f32 = 15.0;
const BALL_WET_ALBEDO: f32 = 0.75;
const BALL_WET_BAND: f32 = 0.03;

fn ball_shade(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>, dir: vec3<f32>, under: bool, direct: bool) -> vec3<f32> {
    let coat = Coat(BALL_WET_BAND, BALL_WET_ALBEDO, BALL_GLOSS, BALL_SHINE);
    return coated_colour(p, n, albedo, dir, under, direct, coat) + light_from_inside(albedo, BALL_WALL_TRANSMITTANCE);
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
    return seen_directly(ball_shade(in.world, n, ball_albedo_in_pixel(n), view, lit_under(in.world), true), in.world);
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
    let n = normalize(edge.point - ball_uniform().xyz);
    let albedo = ball_albedo_in_pixel(n);
    if (edge.hidden) {
        return vec4<f32>(0.0); // not discarded: see grown_rim
    }
    let p = edge.point;
    let out = seen_directly(ball_shade(p, n, albedo, normalize(p - scene.eye.xyz), lit_under(p), true), p);
    return vec4<f32>(out.rgb, edge.cover);
}
