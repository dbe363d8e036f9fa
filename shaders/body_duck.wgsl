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

// Nearest hit of a ray with the duck. Each part is a unit ball stretched by its semi-axes, so
// the ray is taken into the duck's frame and divided by them: there the hit is a ray-sphere
// test with the same t, and the normal is the unit-ball point divided by the semi-axes.
fn duck_hit(origin: vec3<f32>, dir: vec3<f32>) -> ObjectHit {
    var hit = ObjectHit(NO_HIT, vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(0.0));
    if (!near_duck(origin, dir, NO_HIT)) {
        return hit;
    }
    let to_duck = transpose(duck_rotation());
    let o_duck = to_duck * (origin - scene.bodies[DUCK_SLOT + 3].xyz);
    let d_duck = to_duck * dir;
    for (var i = 0; i < DUCK_PARTS; i++) {
        let radii = scene.bodies[DUCK_SLOT + 5 + 3 * i + 1].xyz;
        let o = (o_duck - scene.bodies[DUCK_SLOT + 5 + 3 * i].xyz) / radii;
        let d = d_duck / radii;
        let a = dot(d, d);
        let b = dot(o, d);
        let disc = b * b - a * (dot(o, o) - 1.0);
        if (disc >= 0.0) {
            let t = (-b - sqrt(disc)) / a;
            if (t > 1.0e-4 && t < hit.t) {
                hit.t = t;
                hit.normal = normalize(duck_rotation() * ((o + d * t) / radii));
                hit.albedo = scene.bodies[DUCK_SLOT + 5 + 3 * i + 2].rgb;
            }
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

// Signed distance (m) from the duck's traced parts, negative inside one (bodies_field): per
// part, to first order, its unit-ball distance |o| - 1 over that distance's gradient in metres,
// |o / radii| / |o| (exact on a sphere, within a hair of it near an ellipsoid's surface, where a
// waterline's fade reads it); outside the bounding sphere, 1 m more than the distance from
// that: far from any waterline.
fn duck_field(p: vec3<f32>) -> f32 {
    let bound = scene.bodies[DUCK_SLOT + 4];
    let outside = distance(p, bound.xyz) - bound.w;
    if (bound.w <= 0.0 || outside > 0.0) {
        return max(outside, 0.0) + 1.0;
    }
    let local = transpose(duck_rotation()) * (p - scene.bodies[DUCK_SLOT + 3].xyz);
    var d = NO_HIT;
    for (var i = 0; i < DUCK_PARTS; i++) {
        let radii = scene.bodies[DUCK_SLOT + 5 + 3 * i + 1].xyz;
        let o = (local - scene.bodies[DUCK_SLOT + 5 + 3 * i].xyz) / radii;
        let r = length(o);
        let gradient = length(o / radii) / max(r, 1.0e-6);
        d = min(d, select((r - 1.0) / gradient, -min(radii.x, min(radii.y, radii.z)), r < 1.0e-3));
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

@fragment
fn fs_duck(in: DuckOut) -> @location(0) vec4<f32> {
    let view = normalize(in.world - scene.eye.xyz);
    return seen_directly(duck_shade(in.world, normalize(in.normal), in.colour, view, lit_under(in.world), true), in.world);
}

// The duck's edges without stair-steps: its outline mesh (its traced parts, coarse), each part
// grown by DUCK_EDGE_GROWTH (m, in the duck's frame) along its normals, is drawn after
// everything else, and where a
// part's edge crosses the pixel that part is blended over what was drawn, by the share of the
// pixel it covers, from its own grown fragment (where grown parts overlap, once). Two edges:
// - an outline: the pixel's ray passes the part's centre at m in its unit-ball space (1 on its
//   outline), against m's change to the next pixel; the nearest such part in front of
//   whatever the ray hits, coloured at its outline's point nearest the ray;
// - a crease, where two parts meet: the part the ray enters second, by how far behind the
//   first it enters against that distance's change to the next pixel.
const DUCK_EDGE_GROWTH: f32 = 0.016;

@vertex
fn vs_duck_edge(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>, @location(2) colour: vec3<f32>, @location(3) part: u32) -> DuckOut {
    return duck_vertex(position + normal * DUCK_EDGE_GROWTH, normal, colour, part);
}

// What a ray does near a part, in its unit-ball space: where it enters (m along the ray; where
// it misses, where it passes nearest, so that the distance runs on smoothly past the outline)
// and whether it does, how near it passes the centre (1: on the outline), and the point there.
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
    return DuckPartRay(enter, disc >= 0.0 && enter > 0.0, length(o - d * (b / a)), o + d * enter);
}

@fragment
fn fs_duck_edge(in: DuckOut) -> @location(0) vec4<f32> {
    let eye = scene.eye.xyz;
    let dir = normalize(in.world - eye);
    let to_duck = transpose(duck_rotation());
    let o_duck = to_duck * (eye - scene.bodies[DUCK_SLOT + 3].xyz);
    let d_duck = to_duck * dir;
    // The two parts the ray enters first: where (m along it) and that distance's change to
    // the next pixel across and down.
    var first = vec4<f32>(NO_HIT, 0.0, 0.0, -1.0);
    var second = first;
    for (var i = 0; i < DUCK_PARTS; i++) {
        let r = duck_part_ray(o_duck, d_duck, i);
        let entry = vec4<f32>(r.enter, dpdx(r.enter), dpdy(r.enter), f32(i));
        if (r.hits && r.enter < first.x) {
            second = first;
            first = entry;
        } else if (r.hits && r.enter < second.x) {
            second = entry;
        }
    }
    // The nearest outline crossing the pixel in front of what the ray hits: the share of the
    // pixel its part covers.
    var part = -1;
    var cover = 0.0;
    var along = NO_HIT;
    var inside = 1.0; // how near the centre the middle of the covered share passes (unit ball)
    for (var i = 0; i < DUCK_PARTS; i++) {
        let r = duck_part_ray(o_duck, d_duck, i);
        let spread = max(fwidth(r.miss), 1.0e-6);
        let share = clamp(0.5 - (r.miss - 1.0) / spread, 0.0, 1.0);
        let in_front = f32(i) == first.w || r.enter < first.x;
        if (share > 0.0 && share < 1.0 && in_front && r.enter > 0.0 && r.enter < along) {
            part = i;
            cover = share;
            along = r.enter;
            inside = clamp(1.0 - 0.5 * share * spread, 0.0, 1.0);
        }
    }
    // Else the crease where the second part the ray enters meets the first.
    if (part < 0 && second.w >= 0.0) {
        let change = abs(second.y - first.y) + abs(second.z - first.z);
        cover = clamp(0.5 - (second.x - first.x) / max(change, 1.0e-6), 0.0, 1.0);
        part = select(-1, i32(second.w), cover > 0.0);
    }
    if (part < 0 || u32(part) != in.part) {
        discard;
    }
    // On an outline, coloured where the middle of its covered share sees the part (the outline
    // itself faces away from the eye, where the coat mirrors most); on a crease where the ray enters.
    let r = duck_part_ray(o_duck, d_duck, part);
    let radii = scene.bodies[DUCK_SLOT + 5 + 3 * part + 1].xyz;
    let ahead = normalize(d_duck / radii);
    let side = normalize(r.point - dot(r.point, ahead) * ahead);
    let covered = side * inside - ahead * sqrt(1.0 - inside * inside);
    let unit = select(normalize(r.point), covered, along < NO_HIT);
    let p = duck_rotation() * (scene.bodies[DUCK_SLOT + 5 + 3 * part].xyz + unit * radii) + scene.bodies[DUCK_SLOT + 3].xyz;
    // Across the water from the eye the water's own pass has the pixel.
    if ((p.y < 0.0) != (eye.y < 0.0)) {
        discard;
    }
    let n = normalize(duck_rotation() * (unit / radii));
    let albedo = scene.bodies[DUCK_SLOT + 5 + 3 * part + 2].rgb;
    let out = seen_directly(duck_shade(p, n, albedo, normalize(p - eye), lit_under(p), true), p);
    return vec4<f32>(out.rgb, cover);
}
