// How the pool lights a surface drawn directly (its walls, a body) and what lies between it
// and the eye: the pool's answers to what every body's mesh asks (object_colour, lit_under,
// seen_directly). A scene drawing the bodies elsewhere brings its own in place of this file
// (render::shaders::scene_prelude_in).

// Lit colour of an object (sphere or duck) at surface point p with outward normal n: diffuse
// sunlight (through the caustics under water), ambient from the sky above and, on the
// side facing down, from the water below (light_from_water, and the sky it mirrors), darkened where the floor and walls
// are close (ambient occlusion). under: whether p
// is under the water's rest level; a traced ray's hits are on its own side, and passing that
// side as a constant compiles the other side's light away (software rasterisers run every
// branch); a surface drawn directly passes p.y < 0. drawn: drawn directly, not seen along a
// traced ray, where the floor it faces lights it as it is lit (floor_seen): in the water's
// traced rays that read cost lavapipe's default frame 0.9 ms.
fn object_colour(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>, under: bool, drawn: bool) -> vec3<f32> {
    var direct: f32;
    var from_around = sky_light_at(under);
    if (under) {
        direct = max(dot(n, -scene.refracted_sun.xyz), 0.0) * underwater_light(p, false);
        from_around = light_under_water(p, n, drawn);
    } else {
        direct = max(dot(n, scene.sun.xyz), 0.0);
        let up = upward_share(n);
        let below = light_from_water() + sky_light() * WATER_HEMISPHERE_REFLECTANCE;
        from_around = from_around * up + below * (1.0 - up);
    }
    // Occlusion by the floor and walls falls off with distance from each plane.
    let w = half_width();
    var occlusion = max(-n.y, 0.0) * exp(-4.0 * (p.y + depth()));
    occlusion += max(n.x, 0.0) * exp(-4.0 * (w - p.x)) + max(-n.x, 0.0) * exp(-4.0 * (p.x + w));
    occlusion += max(n.z, 0.0) * exp(-4.0 * (w - p.z)) + max(-n.z, 0.0) * exp(-4.0 * (p.z + w));
    let ambient = from_around * (1.0 - 0.6 * clamp(occlusion, 0.0, 1.0));
    return albedo * (ambient + direct * sun_light());
}

// The light a surface just above the water sees coming up out of it: the calm floor's at the
// rest level (light_up_from_floor), the share that leaves the water (WATER_ESCAPE, from
// optics.rs, as WATER_HEMISPHERE_REFLECTANCE: about 0.53 and 0.066). Bluer and dimmer than the
// sky's. (The sky the water mirrors is object_colour's.)
fn light_from_water() -> vec3<f32> {
    return light_up_from_floor(0.0) * WATER_ESCAPE;
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

// Whether a body's point p lies across the water's rest level from the eye: there the water's
// own pass draws it, seen through the surface (the bodies' outlines leave it).
fn across_water(p: vec3<f32>) -> bool {
    return (p.y < 0.0) != (scene.eye.y < 0.0);
}

// Whether a point p of a surface drawn directly (the pool's walls, a body) is lit as under the
// water. With the deck the eye stays above the water, and what it sees directly is above the
// surface (the water's own pass draws what lies under it): never, a constant, so software
// rasterisers do not shade the caustics for every such pixel as well. The flat water's
// refraction texture (CLIP_SIDE) shows what is under the plane: there by the rest level.
fn lit_under(p: vec3<f32>) -> bool {
    return (!HAS_DECK || CLIP_SIDE != 0) && p.y < 0.0;
}

// What an eye in open water sees along dir where nothing is in the way: the sky's light that
// came down through the surface, dimmed by the water it crossed (Beer–Lambert) over a path that is
// short looking up and long looking down, plus what the water scatters (if it does). The
// cut-away's cross-section then reads as a view from under the water, not a box in the sky.
fn water_backdrop(dir: vec3<f32>) -> vec3<f32> {
    let path = mix(BACKDROP_PATH_DOWN, BACKDROP_PATH_UP, smoothstep(-0.6, 1.0, dir.y));
    let alpha = exp(-scene.absorption.xyz * path);
    var colour = sky_light_at(true) * alpha;
    if (HAS_SCATTERING) {
        colour += (1.0 - alpha) * scene.scatter.xyz;
    }
    return colour;
}
