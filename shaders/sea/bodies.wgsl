// The floating bodies in the open sea (scenes/sea/render/bodies.rs): the sea's answers to what every
// body's mesh asks of the scene it is in, in place of the pool's (scene_seen.wgsl). A body is
// lit by the sun and by the sky above it, and from below by the little light the deep water
// sends back up; it is seen through the haze like the sea around it. Its mesh's part under the
// water is hidden by the sea's surface, drawn after it, so the mesh is lit as above the water.
// The water mirrors the bodies and shows their parts under it (MIRRORED_BODIES): its reflected
// and refracted rays are traced to them, the refracted ones lit as under the water; where the
// shallows reach the patch (ISLAND_AT_PATCH) they shade the floor.

fn lit_under(p: vec3<f32>) -> bool {
    return false;
}

// Lit colour at p (outward normal n): the sky's light on the upper hemisphere of the normal,
// the deep water's on the lower, and the sun's on the side facing it (drawn: lit alike). Under
// the water (a part the water's refracted rays meet: refracted_bodies) the sky's light comes
// straight through the surface only to the normals facing up (Snell's window, about up²); round
// them it is the light the water scatters sideways, which has crossed about UNDERWATER_SIDE_PATH
// (m) of it; and the sun's is bent into the water.
const UNDERWATER_SIDE_PATH: f32 = 3.0;

fn object_colour(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>, under: bool, drawn: bool) -> vec3<f32> {
    let up = upward_share(n);
    var sun = scene.sun.xyz;
    var ambient = sky_light() * up + light_from_water() * (1.0 - up);
    if (under) {
        sun = -scene.refracted_sun.xyz;
        let window = up * up;
        let through = sky_light() * UNDERWATER_SKY;
        let sideways = through * exp(-SEA_ABSORPTION * UNDERWATER_SIDE_PATH);
        ambient = through * window + sideways * (up - window) + light_from_water() * (1.0 - up);
    }
    return albedo * (ambient + max(dot(n, sun), 0.0) * sun_light());
}

// The light coming up out of the sea (its deep water's), lighting a body from below.
fn light_from_water() -> vec3<f32> {
    return deep_water();
}

// Never: the sea's grid, drawn after the bodies with its depth, hides their parts under the
// waves, which move them far from the rest level (the bodies' outlines test depth too).
fn across_water(p: vec3<f32>) -> bool {
    return false;
}

// The colour at p as written to the target, through the haze between it and the eye.
fn seen_directly(colour: vec3<f32>, p: vec3<f32>) -> vec4<f32> {
    let to_point = p - sea.eye.xyz;
    let dist = length(to_point);
    return finish(through_air(colour, to_point / dist, dist));
}

// What the water at p mirrors of the bodies along the reflected ray r (turned up, as
// sea_colour's): the body the ray hits, lit as seen in a mirror, over `behind` (the island's
// image, or nothing) by the share of the pixel it covers. The ray's gap past the bodies
// against that gap's change to the next pixel gives the share, as an outline's pass does;
// just past the outline the colour is the body's a quarter of a pixel inside it, the ray
// turned that far along the gap's fall. So the image's edge is blended, not stair-stepped,
// and where the waves turn the ray fast from pixel to pixel it blurs as much. scene.output.z
// 0: all or nothing (the outlines off, for tests to compare with). Call in uniform control
// flow (screen derivatives).
fn mirrored_bodies(p: vec3<f32>, r: vec3<f32>, behind: vec4<f32>) -> vec4<f32> {
    var dir = vec3<f32>(r.x, abs(r.y), r.z);
    var origin = p;
    let across = dpdx(dir);
    let down = dpdy(dir);
    let across_p = dpdx(p);
    let down_p = dpdy(p);
    var hit = hit_bodies(p, dir);
    let fall = vec2<f32>(dpdx(hit.gap), dpdy(hit.gap));
    let spread = max(abs(fall.x) + abs(fall.y), 1.0e-6);
    var share = clamp(0.5 - hit.gap / spread, 0.0, 1.0);
    if (scene.output.z <= 0.0) {
        share = select(0.0, 1.0, hit.t < NO_HIT);
    }
    if (share <= 0.0) {
        return behind;
    }
    if (hit.t >= NO_HIT) {
        // In pixels along the gap's fall: to the outline and a quarter of a pixel on, the
        // point on the water moved with the ray (the gap's change is both's). Missing still
        // (where the waves bend the rays too fast for the first-order step) leaves the sky.
        let to_body = -fall * ((hit.gap + 0.25 * length(fall)) / max(dot(fall, fall), 1.0e-12));
        dir = normalize(dir + across * to_body.x + down * to_body.y);
        origin = p + across_p * to_body.x + down_p * to_body.y;
        hit = hit_bodies(origin, dir);
        if (hit.t >= NO_HIT) {
            return behind;
        }
    }
    let seen = body_colour(hit, origin + dir * hit.t, dir, false);
    let alpha = share + behind.a * (1.0 - share);
    return vec4<f32>((seen * share + behind.rgb * behind.a * (1.0 - share)) / alpha, alpha);
}

// What the water at p, seen along unit v through normal n, shows of the bodies' parts under
// it (of the kinds floating low: hit_bodies_below) nearer than a floor `floor_depth` m under p:
// the refracted ray traced to them, the part it meets lit under the water and dimmed along the
// light's way down to it and the view's way back (as seen_through_water dims the shallows'
// floor), over `under` (the light out of the water there) by the share of the pixel it covers:
// its gap against the gap's change to the next pixel on the inside of its outline (outside
// it, unlike mirrored_bodies, no second ray: the water). scene.output.z 0: all or nothing.
// Call in uniform control flow (screen derivatives).
fn refracted_bodies(p: vec3<f32>, v: vec3<f32>, n: vec3<f32>, under: vec3<f32>, floor_depth: f32) -> vec3<f32> {
    let down = refract(v, n, IOR_AIR / IOR_WATER);
    let hit = hit_bodies_below(p, down);
    let fall = vec2<f32>(dpdx(hit.gap), dpdy(hit.gap));
    var share = clamp(0.5 - hit.gap / max(abs(fall.x) + abs(fall.y), 1.0e-6), 0.0, 1.0);
    if (scene.output.z <= 0.0) {
        share = 1.0;
    }
    if (hit.t >= min(NO_HIT, floor_depth / max(-down.y, 0.2))) {
        return under;
    }
    let point = p + down * hit.t;
    // The sun's light comes down bent into the water (scene.refracted_sun, as in the pool).
    let sun_down = -scene.refracted_sun.y;
    let path = hit.t + max(p.y - point.y, 0.0) / sun_down;
    let through = exp(-(SEA_ABSORPTION + SEA_SCATTERING) * path);
    return mix(under, body_colour(hit, point, down, true), through * share);
}

// The share of the sun's light on the floor `depth` m under the surface point p (seen along
// unit v through normal n) that the bodies let through: the ray from that floor point to the
// sun, bent into the water at a level surface, past their parts (their soft shadows).
fn bodies_shade_on_floor(p: vec3<f32>, v: vec3<f32>, n: vec3<f32>, depth: f32) -> f32 {
    let down = refract(v, n, IOR_AIR / IOR_WATER);
    let floor = p + down * (depth / max(-down.y, 0.2));
    let to_sun = -scene.refracted_sun.xyz;
    return objects_visibility(floor, to_sun, FAR_AWAY, 0.0);
}
