// The rubber duck (bodies/duck.rs): its traced parts, ellipsoids in the duck's frame, hit and
// shading the scene's rays, and its mesh drawn directly, turned and moved to its pose. Its
// uniform (DUCK_SLOT on): the frame's rotation in slots 0-2, position in slot 3 (w: the scale
// its mesh is drawn at), a ball holding it in slot 4 (radius 0: no duck), then per part centre,
// semi-axes (both scaled) and colour.

fn duck_rotation() -> mat3x3<f32> {
    return mat3x3<f32>(scene.bodies[DUCK_SLOT].xyz, scene.bodies[DUCK_SLOT + 1].xyz, scene.bodies[DUCK_SLOT + 2].xyz);
}

// Whether the segment origin + t dir, t in [0, t_max], comes near the duck at all.
fn near_duck(origin: vec3<f32>, dir: vec3<f32>, t_max: f32) -> bool {
    let bound = scene.bodies[DUCK_SLOT + 4];
    if (bound.w <= 0.0) {
        return false;
    }
    let t = clamp(dot(bound.xyz - origin, dir), 0.0, t_max);
    return distance(origin + dir * t, bound.xyz) < bound.w;
}

// What a ray (in the duck's frame) does near traced part i, in the part's unit-ball space:
// where it enters (m along the ray; where it misses, where it passes nearest, so that the
// distance runs on smoothly past the outline) and whether it does, how near the ray (its
// t >= 0 half) passes the centre (1: on the outline), and the point there.
struct DuckPartRay {
    enter: f32,
    hits: bool,
    miss: f32,
    point: vec3<f32>,
};

fn duck_part_ray(o_duck: vec3<f32>, d_duck: vec3<f32>, i: i32) -> DuckPartRay {
    let radii = scene.bodies[DUCK_SLOT + 5 + 3 * i + 1].xyz;
    let o = (o_duck - scene.bodies[DUCK_SLOT + 5 + 3 * i].xyz) / radii;
    let d = d_duck / radii;
    let a = dot(d, d);
    let b = dot(o, d);
    let disc = b * b - a * (dot(o, o) - 1.0);
    let enter = (-b - sqrt(max(disc, 0.0))) / a;
    return DuckPartRay(enter, disc >= 0.0 && enter > 0.0, length(o - d * min(b / a, 0.0)), o + d * enter);
}

// Nearest hit of a ray with the duck: each part's duck_part_ray, its normal the unit-ball
// point divided by the semi-axes. Its gap (m): far outside the ball holding the duck that
// ball's; nearer, the least of the parts', each its unit-ball miss times its shortest
// semi-axis (a bound, under the gap in metres, whose slope differs from part to part; the
// blends that read it divide it by its own change to the next pixel). The parts are traced
// from a quarter of the ball's radius outside it, so that the gap runs on smoothly where a
// blend reads it.
fn duck_hit(origin: vec3<f32>, dir: vec3<f32>) -> ObjectHit {
    let bound = scene.bodies[DUCK_SLOT + 4];
    var hit = ObjectHit(NO_HIT, vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(0.0), ray_sphere_gap(origin, dir, bound.xyz, bound.w));
    if (hit.gap >= 0.25 * bound.w) {
        return hit;
    }
    let to_duck = transpose(duck_rotation());
    let o_duck = to_duck * (origin - scene.bodies[DUCK_SLOT + 3].xyz);
    let d_duck = to_duck * dir;
    hit.gap = NO_HIT;
    for (var i = 0; i < DUCK_PARTS; i++) {
        let r = duck_part_ray(o_duck, d_duck, i);
        let radii = scene.bodies[DUCK_SLOT + 5 + 3 * i + 1].xyz;
        hit.gap = min(hit.gap, (r.miss - 1.0) * min(radii.x, min(radii.y, radii.z)));
        if (r.hits && r.enter > 1.0e-4 && r.enter < hit.t) {
            hit.t = r.enter;
            hit.normal = normalize(duck_rotation() * (r.point / scene.bodies[DUCK_SLOT + 5 + 3 * i + 1].xyz));
            hit.albedo = scene.bodies[DUCK_SLOT + 5 + 3 * i + 2].rgb;
        }
    }
    return hit;
}

// Light the duck lets through along a segment, like sphere_visibility: per part, how close
// the segment passes to its centre in the part's unit-ball space (duck_parts_light, written by
// bodies/duck.rs: the product over the parts, written out), its penumbra an eighth of the
// part's size where the point lit touches it and SHADOW_SPREAD wider per metre between them
// (t_lit: where along the line the point lit lies). Unlike sphere_visibility it has no early
// return far from the duck: on a software rasteriser, which runs every branch anyway, the
// branch cost more than the parts.
fn duck_light(origin: vec3<f32>, dir: vec3<f32>, t_max: f32, t_lit: f32) -> f32 {
    let to_duck = transpose(duck_rotation());
    let o_duck = to_duck * (origin - scene.bodies[DUCK_SLOT + 3].xyz);
    let bound = scene.bodies[DUCK_SLOT + 4];
    let t = clamp(dot(bound.xyz - origin, dir), 0.0, t_max);
    // A part's penumbra widens by its longest radius over its mean one (up to 1.5) times
    // SHADOW_SPREAD per metre, beyond the bound by a hair at contact.
    let reach = bound.w + abs(t_lit - t) * SHADOW_SPREAD * 1.5 + 0.01;
    let near = bound.w > 0.0 && distance(origin + dir * t, bound.xyz) < reach;
    return select(1.0, duck_parts_light(o_duck, to_duck * dir, t_max, t_lit), near);
}

// Light part i lets through along the segment o_duck + t d_duck, t in [0, t_max] (the duck's
// frame, t in m along the segment): soft, by how close the segment passes to the part's centre
// in its unit-ball space, over a penumbra that widens with the distance to the point lit.
fn duck_part_light(o_duck: vec3<f32>, d_duck: vec3<f32>, t_max: f32, t_lit: f32, i: i32) -> f32 {
    let radii = scene.bodies[DUCK_SLOT + 5 + 3 * i + 1].xyz;
    let o = (o_duck - scene.bodies[DUCK_SLOT + 5 + 3 * i].xyz) / radii;
    let d = d_duck / radii;
    let t = clamp(-dot(o, d) / dot(d, d), 0.0, t_max);
    let half = 0.125 + abs(t_lit - t) * SHADOW_SPREAD * 3.0 / (radii.x + radii.y + radii.z);
    return smoothstep(0.975 - half, 0.975 + half, length(o + d * t));
}

// Signed distance (m) from traced part i of a point `local` in the duck's frame, to first
// order: its unit-ball distance |o| - 1 over that distance's gradient in metres, |o / radii| /
// |o| (exact on a sphere, within a hair of it near an ellipsoid's surface, where a waterline's
// fade and a crease's blend read it).
fn duck_part_distance(local: vec3<f32>, i: i32) -> f32 {
    let radii = scene.bodies[DUCK_SLOT + 5 + 3 * i + 1].xyz;
    let o = (local - scene.bodies[DUCK_SLOT + 5 + 3 * i].xyz) / radii;
    let r = length(o);
    let gradient = length(o / radii) / max(r, 1.0e-6);
    return select((r - 1.0) / gradient, -min(radii.x, min(radii.y, radii.z)), r < 1.0e-3);
}

// Signed distance (m) from the duck's traced parts, negative inside one (bodies_field); outside
// the bounding sphere, 1 m more than the distance from that: far from any waterline.
fn duck_field(p: vec3<f32>) -> f32 {
    let bound = scene.bodies[DUCK_SLOT + 4];
    let outside = distance(p, bound.xyz) - bound.w;
    if (bound.w <= 0.0 || outside > 0.0) {
        return max(outside, 0.0) + 1.0;
    }
    let local = transpose(duck_rotation()) * (p - scene.bodies[DUCK_SLOT + 3].xyz);
    var d = NO_HIT;
    for (var i = 0; i < DUCK_PARTS; i++) {
        d = min(d, duck_part_distance(local, i));
    }
    return d;
}

// Nothing for the pool's ambient light: the duck is small next to it.
fn duck_occlusion(p: vec3<f32>, n: vec3<f32>) -> f32 {
    return 0.0;
}

// The duck's vinyl: diffuse like the sphere under a softer coat (clear_coat: the sky mirrored
// by Fresnel, a broad highlight of the sun), seen along dir; darker and glossier within
// DUCK_WET_BAND above the rest level, where it rides the ripples (under, direct: see coated_colour).
const DUCK_GLOSS: f32 = 60.0;
const DUCK_SHINE: f32 = 12.0;
const DUCK_WET_ALBEDO: f32 = 0.75;
const DUCK_WET_BAND: f32 = 0.015;

fn duck_shade(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>, dir: vec3<f32>, under: bool, direct: bool) -> vec3<f32> {
    return coated_colour(p, n, albedo, dir, under, direct, Coat(DUCK_WET_BAND, DUCK_WET_ALBEDO, DUCK_GLOSS, DUCK_SHINE));
}

// The duck seen directly.
struct DuckOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) colour: vec3<f32>,
    // Which part of the mesh (DuckVertex::part): a traced part's index, then the eyes'.
    @location(3) @interpolate(flat) part: u32,
};

@vertex
fn vs_duck(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>, @location(2) colour: vec3<f32>, @location(3) part: u32) -> DuckOut {
    return duck_vertex(position, normal, colour, part);
}

fn duck_vertex(position: vec3<f32>, normal: vec3<f32>, colour: vec3<f32>, part: u32) -> DuckOut {
    var out: DuckOut;
    out.world = duck_rotation() * (position * scene.bodies[DUCK_SLOT + 3].w) + scene.bodies[DUCK_SLOT + 3].xyz;
    out.normal = duck_rotation() * normal;
    out.colour = colour;
    out.part = part;
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    return out;
}

// Where another traced part meets the one drawn (a crease), the two are blended by the share
// of the pixel the other covers: its distance from the point drawn against that distance's
// change to the next pixel (all of it where the drawn facet lies inside the other). Each is
// shaded on its own: shading a mixed normal once kept the stair-steps where the coat's
// highlight differs across the crease. The eyes, drawn on the head, keep their own colour;
// scene.output.z 0 turns the blend off, as the outlines (for tests to compare with).
@fragment
fn fs_duck(in: DuckOut) -> @location(0) vec4<f32> {
    let view = normalize(in.world - scene.eye.xyz);
    let under = lit_under(in.world);
    let colour = duck_shade(in.world, normalize(in.normal), in.colour, view, under, true);
    let local = transpose(duck_rotation()) * (in.world - scene.bodies[DUCK_SLOT + 3].xyz);
    var other = -1;
    var share = 0.0;
    for (var i = 0; i < DUCK_PARTS; i++) {
        let d = duck_part_distance(local, i);
        let covers = clamp(0.5 - d / max(fwidth(d), 1.0e-6), 0.0, 1.0);
        if (u32(i) != in.part && covers > share) {
            other = i;
            share = covers;
        }
    }
    if (other < 0 || in.part >= u32(DUCK_PARTS) || scene.output.z <= 0.0) {
        return seen_directly(colour, in.world);
    }
    let radii = scene.bodies[DUCK_SLOT + 5 + 3 * other + 1].xyz;
    let o = (local - scene.bodies[DUCK_SLOT + 5 + 3 * other].xyz) / radii;
    let n = normalize(duck_rotation() * (o / radii));
    let albedo = scene.bodies[DUCK_SLOT + 5 + 3 * other + 2].rgb;
    let met = duck_shade(in.world, n, albedo, view, under, true);
    return seen_directly(mix(colour, met, share), in.world);
}
