// The floating bodies in the scene's rays: hitting the duck's ellipsoids and the sphere, the
// light they block, and their colours (lit, with the sphere's clear coat).

// What a ray hits on an object: distance (NO_HIT for nothing), outward normal, colour.
struct ObjectHit {
    t: f32,
    normal: vec3<f32>,
    albedo: vec3<f32>,
};

fn duck_rotation() -> mat3x3<f32> {
    return mat3x3<f32>(scene.duck_pose[0].xyz, scene.duck_pose[1].xyz, scene.duck_pose[2].xyz);
}

// Whether the segment origin + t dir, t in [0, t_max], comes near the duck at all.
fn near_duck(origin: vec3<f32>, dir: vec3<f32>, t_max: f32) -> bool {
    if (!HAS_DUCK || scene.duck_bound.w <= 0.0) {
        return false;
    }
    let t = clamp(dot(scene.duck_bound.xyz - origin, dir), 0.0, t_max);
    return distance(origin + dir * t, scene.duck_bound.xyz) < scene.duck_bound.w;
}

// Nearest hit of a ray with the duck. Each part is a unit ball stretched by its semi-axes, so
// the ray is taken into the duck's frame and divided by them: there the hit is a ray-sphere
// test with the same t, and the normal is the unit-ball point divided by the semi-axes.
fn intersect_duck(origin: vec3<f32>, dir: vec3<f32>) -> ObjectHit {
    var hit = ObjectHit(NO_HIT, vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(0.0));
    if (!HAS_DUCK) {
        return hit;
    }
    if (!near_duck(origin, dir, NO_HIT)) {
        return hit;
    }
    let to_duck = transpose(duck_rotation());
    let o_duck = to_duck * (origin - scene.duck_pose[3].xyz);
    let d_duck = to_duck * dir;
    for (var i = 0; i < DUCK_PARTS; i++) {
        let radii = scene.duck_parts[3 * i + 1].xyz;
        let o = (o_duck - scene.duck_parts[3 * i].xyz) / radii;
        let d = d_duck / radii;
        let a = dot(d, d);
        let b = dot(o, d);
        let disc = b * b - a * (dot(o, o) - 1.0);
        if (disc >= 0.0) {
            let t = (-b - sqrt(disc)) / a;
            if (t > 1.0e-4 && t < hit.t) {
                hit.t = t;
                hit.normal = normalize(duck_rotation() * ((o + d * t) / radii));
                hit.albedo = scene.duck_parts[3 * i + 2].rgb;
            }
        }
    }
    return hit;
}

// Light the duck lets through along a segment, like sphere_visibility: per part, how close
// the segment passes to its centre in the part's unit-ball space.
fn duck_visibility(origin: vec3<f32>, dir: vec3<f32>, t_max: f32) -> f32 {
    if (!HAS_DUCK) {
        return 1.0;
    }
    if (!near_duck(origin, dir, t_max)) {
        return 1.0;
    }
    let to_duck = transpose(duck_rotation());
    let o_duck = to_duck * (origin - scene.duck_pose[3].xyz);
    let d_duck = to_duck * dir;
    var light = 1.0;
    for (var i = 0; i < DUCK_PARTS; i++) {
        let radii = scene.duck_parts[3 * i + 1].xyz;
        let o = (o_duck - scene.duck_parts[3 * i].xyz) / radii;
        let d = d_duck / radii;
        let t = clamp(-dot(o, d) / dot(d, d), 0.0, t_max);
        light *= smoothstep(0.85, 1.1, length(o + d * t));
    }
    return light;
}

// Light both objects let through towards the sun from p (above the water).
fn objects_visibility(p: vec3<f32>, dir: vec3<f32>, t_max: f32) -> f32 {
    var light = 1.0;
    if (HAS_SPHERE) {
        light = sphere_visibility(p, dir, t_max, scene.sphere.xyz, scene.sphere.w);
    }
    if (HAS_DUCK) {
        light *= duck_visibility(p, dir, t_max);
    }
    return light;
}

// Nearest distance along a ray to the sphere, or NO_HIT (always, when there is no sphere).
fn hit_sphere(origin: vec3<f32>, dir: vec3<f32>) -> f32 {
    if (!HAS_SPHERE) {
        return NO_HIT;
    }
    return intersect_sphere(origin, dir, scene.sphere.xyz, scene.sphere.w);
}


// Lit colour of an object (sphere or duck) at surface point p with outward normal n: diffuse
// sunlight (through the caustics under water),
// ambient darkened where the floor and walls are close (ambient occlusion).
fn object_colour(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>) -> vec3<f32> {
    var direct: f32;
    if (p.y < 0.0) {
        direct = max(dot(n, -scene.refracted_sun.xyz), 0.0) * underwater_light(p, false);
    } else {
        direct = max(dot(n, scene.sun.xyz), 0.0);
    }
    // Occlusion by the floor and walls falls off with distance from each plane.
    let w = half_width();
    var occlusion = max(-n.y, 0.0) * exp(-4.0 * (p.y + depth()));
    occlusion += max(n.x, 0.0) * exp(-4.0 * (w - p.x)) + max(-n.x, 0.0) * exp(-4.0 * (p.x + w));
    occlusion += max(n.z, 0.0) * exp(-4.0 * (w - p.z)) + max(-n.z, 0.0) * exp(-4.0 * (p.z + w));
    let ambient = sky_light_at(p.y) * (1.0 - 0.6 * clamp(occlusion, 0.0, 1.0));
    return albedo * (ambient + direct * sun_light());
}

// The sphere, seen along dir: diffuse paint under a clear coat. Within a few centimetres above
// the rest level it is wet (darker paint, a stronger coat); above the water the coat mirrors
// the sky and the sun by Schlick's Fresnel (r0 = 0.04, a lacquer's index of about 1.5).
fn sphere_colour(p: vec3<f32>, dir: vec3<f32>) -> vec3<f32> {
    let n = normalize(p - scene.sphere.xyz);
    let wet = 1.0 - smoothstep(0.0, 0.04, p.y);
    var colour = object_colour(p, n, SPHERE_ALBEDO * mix(1.0, 0.72, wet));
    let fresnel = 0.04 + 0.96 * pow(1.0 - max(dot(-dir, n), 0.0), 5.0);
    let r = reflect(dir, n);
    // The sky in the coat, and the sun's highlight on it (a glossy lobe, cos^SPHERE_GLOSS).
    let highlight = sun_light() * SPHERE_SHINE * pow(max(dot(r, scene.sun.xyz), 0.0), SPHERE_GLOSS);
    let coat = fresnel * (1.0 + wet) * (sky_colour(r) + highlight);
    return colour + select(vec3<f32>(0.0), coat, p.y > 0.0);
}

// The duck's rubber: diffuse like the sphere plus a broad glossy highlight of the sun,
// seen along dir, where the sun reaches it directly.
fn duck_colour(p: vec3<f32>, n: vec3<f32>, albedo: vec3<f32>, dir: vec3<f32>) -> vec3<f32> {
    var colour = object_colour(p, n, albedo);
    if (p.y >= 0.0) {
        let gloss = pow(max(dot(reflect(dir, n), scene.sun.xyz), 0.0), 40.0);
        colour += sun_light() * 0.35 * gloss;
    }
    return colour;
}
