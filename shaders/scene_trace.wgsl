// Tracing rays through water and air to what they hit, and the colour as displayed (tone
// curve, sRGB).

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
