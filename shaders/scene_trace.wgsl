// Tracing rays through water and air to what they hit (the pool's faces: their normals, tile
// coordinates and coved corners), and the colour as displayed (tone curve, sRGB).

// What a ray starting in the water sees: a body or the pool's inside, dimmed by the
// water it crossed (Beer–Lambert); what it hits is lit as under the water. t_exit: pool_exit_distance of the ray; lod: tile mip
// level (see tile_lod).
fn trace_water(origin: vec3<f32>, dir: vec3<f32>, t_exit: f32, lod: f32) -> vec3<f32> {
    var t = t_exit;
    var colour: vec3<f32>;
    let body = hit_bodies(origin, dir);
    if (body.t < t) {
        t = body.t;
        colour = body_colour(body, origin + dir * t, dir, true);
    } else {
        let hit = origin + dir * t;
        colour = pool_colour_at_hit(hit, lod, true);
    }
    return through_water(colour, origin, origin + dir * t);
}

// Inward normal of the pool face nearest to p (floor or one of the four walls).
// Written with select rather than branches: it runs per pixel for two rays.
fn pool_normal(p: vec3<f32>) -> vec3<f32> {
    let w = half_width();
    let dx = w - abs(p.x);
    let dz = w - abs(p.z);
    let dy = p.y + depth();
    let wall = select(vec3<f32>(0.0, 0.0, -sign(p.z)), vec3<f32>(-sign(p.x), 0.0, 0.0), dx < dz);
    return select(wall, vec3<f32>(0.0, 1.0, 0.0), dy <= dx && dy <= dz);
}

// Texture coordinates (m) of the tiles at p on the face with inward normal n.
fn tile_uv(p: vec3<f32>, n: vec3<f32>) -> vec2<f32> {
    let wall = select(vec2<f32>(p.x, -p.y), vec2<f32>(p.z, -p.y), abs(n.x) > 0.5);
    return select(wall, p.xz, abs(n.y) > 0.5);
}

// The normal the pool's inside is lit by at p, on one of its faces: its corners are coved,
// the tiles turning from one face to the next on a quarter circle of POOL_COVE_RADIUS (m), so
// within that of a corner the normal turns from one face's to the other's, each face's share
// growing as p nears it. Seen through the water, a floor's edge against a wall in shade then
// darkens over a few pixels instead of stepping from lit to dark at a pixel's edge.
fn coved_normal(p: vec3<f32>) -> vec3<f32> {
    let r = POOL_COVE_RADIUS;
    let w = half_width();
    let near = max(vec3<f32>(r) - vec3<f32>(w - abs(p.x), p.y + depth(), w - abs(p.z)), vec3<f32>(0.0));
    let n = vec3<f32>(-sign(p.x), 1.0, -sign(p.z)) * near;
    return select(pool_normal(p), normalize(n), dot(n, n) > 1.0e-10);
}

// A ray leaving the surface into the air, folded back up if it still points down (a
// reflection off a steep wave); a zero vector (refract's total internal reflection) gives
// straight up, so that its colour stays finite even where its weight is zero.
fn upward(dir: vec3<f32>) -> vec3<f32> {
    return normalize(vec3<f32>(dir.x, max(abs(dir.y), 1.0e-4), dir.z));
}

// What a ray starting at the surface and going up through air (see upward) sees: a body,
// the pool walls above the water line, or the sky; what it hits is lit as above the water. normal: the surface normal the
// ray was mirrored at (zero for a refracted ray; see sun_specular); t_exit:
// pool_exit_distance of the ray; lod: tile mip level (see tile_lod).
fn trace_air(origin: vec3<f32>, dir: vec3<f32>, normal: vec3<f32>, t_exit: f32, lod: f32) -> vec3<f32> {
    let t = t_exit;
    let body = hit_bodies(origin, dir);
    if (body.t < t) {
        return body_colour(body, origin + dir * body.t, dir, false);
    }
    let hit = origin + dir * t;
    if (hit.y < rim() - 1.0e-3) {
        return pool_colour_at_hit(hit, lod, false);
    }
    return sky_colour(dir) + sun_specular(dir, normal);
}

// Final colour written to the target: scene light times the exposure through a filmic curve
// (Narkowicz's fit of the ACES film response: a toe that keeps shade dark, a shoulder that
// rolls bright caustics and glints off to white instead of clipping); sRGB-encoded in the
// shader when the target format does not do it in hardware (WebGPU canvases are plain UNORM).
fn tone_map(c: vec3<f32>) -> vec3<f32> {
    let x = c * scene.sun_light.w * EXPOSURE_SCALE;
    return (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
}

// Debug values in [0, 1] per channel as the colour that displays as them (stored as v * 255):
// no tone curve.
fn as_displayed(v: vec3<f32>) -> vec4<f32> {
    let g = clamp(v, vec3<f32>(0.0), vec3<f32>(1.0));
    if (ENCODE_SRGB) {
        return vec4<f32>(g, 1.0);
    }
    return vec4<f32>(srgb_to_linear(g), 1.0);
}

fn finish(c: vec3<f32>) -> vec4<f32> {
    let mapped = clamp(tone_map(max(c, vec3<f32>(0.0))), vec3<f32>(0.0), vec3<f32>(1.0));
    if (ENCODE_SRGB) {
        return vec4<f32>(linear_to_srgb(mapped), 1.0);
    }
    return vec4<f32>(mapped, 1.0);
}
