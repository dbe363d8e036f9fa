// The floating bodies in the open sea (scenes/sea/render/bodies.rs): the sea's answers to what every
// body's mesh asks of the scene it is in, in place of the pool's (scene_seen.wgsl). A body is
// lit by the sun and by the sky above it, and from below by the little light the deep water
// sends back up; it is seen through the haze like the sea around it. Its part under the water
// is hidden by the sea's surface, drawn after it, so it is always lit as above the water. The
// water mirrors the bodies (MIRRORED_BODIES): its reflected rays are traced to them; where the
// shallows reach the patch (ISLAND_AT_PATCH) they shade the floor.

fn lit_under(p: vec3<f32>) -> bool {
    return false;
}

// Lit colour at p (outward normal n): the sky's light on the upper hemisphere of the normal,
// the deep water's on the lower, and the sun's on the side facing it (under, drawn: lit alike).
fn object_colour(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>, under: bool, drawn: bool) -> vec3<f32> {
    let up = 0.5 + 0.5 * n.y;
    let ambient = sky_light() * up + deep_water() * (1.0 - up);
    return albedo * (ambient + max(dot(n, scene.sun.xyz), 0.0) * sun_light());
}

// The light coming up out of the sea, as object_colour takes it from below.
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
// sea_colour's): the body the ray hits, lit as seen in a mirror, or else `behind` (the
// island's image, or nothing).
fn mirrored_bodies(p: vec3<f32>, r: vec3<f32>, behind: vec4<f32>) -> vec4<f32> {
    let up = vec3<f32>(r.x, abs(r.y), r.z);
    let hit = hit_bodies(p, up);
    if (hit.t >= NO_HIT) {
        return behind;
    }
    return vec4<f32>(body_colour(hit, p + up * hit.t, up, false), 1.0);
}

// The share of the sun's light on the floor `depth` m under the surface point p (seen along
// unit v through normal n) that the bodies let through: the ray from that floor point to the
// sun, bent into the water at a level surface, past their parts (their soft shadows).
fn bodies_shade_on_floor(p: vec3<f32>, v: vec3<f32>, n: vec3<f32>, depth: f32) -> f32 {
    let down = refract(v, n, IOR_AIR / IOR_WATER);
    let floor = p + down * (depth / max(-down.y, 0.2));
    let to_sun = -refract(-scene.sun.xyz, vec3<f32>(0.0, 1.0, 0.0), IOR_AIR / IOR_WATER);
    return objects_visibility(floor, to_sun, FAR_AWAY, 0.0);
}
