// The floating bodies in the open sea (render/sea_bodies.rs): the sea's answers to what every
// body's mesh asks of the scene it is in, in place of the pool's (scene_seen.wgsl). A body is
// lit by the sun and by the sky above it, and from below by the little light the deep water
// sends back up; it is seen through the haze like the sea around it. Its part under the water
// is hidden by the sea's surface, drawn after it, so it is always lit as above the water.

fn lit_under(p: vec3<f32>) -> bool {
    return false;
}

// Lit colour at p (outward normal n): the sky's light on the upper hemisphere of the normal,
// the deep water's on the lower, and the sun's on the side facing it.
fn object_colour(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>, under: bool) -> vec3<f32> {
    let up = 0.5 + 0.5 * n.y;
    let ambient = sky_light() * up + deep_water() * (1.0 - up);
    return albedo * (ambient + max(dot(n, scene.sun.xyz), 0.0) * sun_light());
}

// The colour at p as written to the target, through the haze between it and the eye.
fn seen_directly(colour: vec3<f32>, p: vec3<f32>) -> vec4<f32> {
    let to_point = p - sea.eye.xyz;
    let dist = length(to_point);
    return finish(through_haze(colour, to_point / dist, dist));
}
