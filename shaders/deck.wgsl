// The deck around the pool: coping stones along the opening and square paving slabs beyond,
// lit by the sun and the sky, fading into the horizon's haze with
// distance (aerial perspective: the air between adds the sky's colour and hides the ground).
// Joints are filtered over the pixel's footprint, so far slabs blend instead of shimmering.

// 1 inside a slab, 0 on a joint of `joint` m, averaged over the pixel's footprint.
fn joints(uv: vec2<f32>, size: f32, joint: f32) -> f32 {
    let cell = uv / size;
    let width = max(fwidth(cell), vec2<f32>(1.0e-5));
    let d = abs(fract(cell) - 0.5);           // 0.5 at the joint
    let edge = 0.5 - 0.5 * joint / size;
    let open = 1.0 - smoothstep(vec2<f32>(edge) - width, vec2<f32>(edge) + width, d);
    // Wider than a joint per pixel: the average of slab and joint.
    let far = 1.0 - joint / size;
    return mix(open.x * open.y, far * far, clamp(max(width.x, width.y) * 4.0 - 1.0, 0.0, 1.0));
}

// Its vertices go through the pool's vs_pool (pool.wgsl, joined ahead of this file).

@fragment
fn fs_deck(in: PoolOut) -> @location(0) vec4<f32> {
    let p = in.world;
    let from_edge = max(abs(p.x), abs(p.z)) - half_width();
    // Coping: pale stone blocks along the edge; slabs: warmer, each a little different.
    let along = select(p.z, p.x, abs(p.z) > abs(p.x));
    let slab_uv = p.xz + vec2<f32>(half_width() + COPING_WIDTH);
    let slab_tint = 0.9 + 0.2 * hash31(vec3<f32>(floor(slab_uv / SLAB_SIZE), 0.3));
    let coping_tint = 0.9 + 0.2 * hash31(vec3<f32>(floor(along / 0.5), 0.0, 0.3));
    let slab = vec3<f32>(0.095, 0.062, 0.042) * slab_tint * mix(0.55, 1.0, joints(slab_uv, SLAB_SIZE, 0.012));
    let stone = vec3<f32>(0.60, 0.57, 0.52) * coping_tint * mix(0.55, 1.0, joints(vec2<f32>(along, 0.25), 0.5, 0.01));
    // The coping's outer edge, averaged over the pixel's footprint (no stair-steps).
    let edge_width = max(fwidth(from_edge), 1.0e-5);
    let coping = 1.0 - smoothstep(COPING_WIDTH - 0.5 * edge_width, COPING_WIDTH + 0.5 * edge_width, from_edge);
    let albedo = mix(slab, stone, coping);
    // The open sky and the sun (the deck is above the water and its objects: no shadows cast on it).
    let colour = albedo * (sky_light() + max(scene.sun.y, 0.0) * sun_light());
    let to_p = p - scene.eye.xyz;
    let haze = 1.0 - exp(-length(to_p) / HAZE_DISTANCE * 0.69);
    let horizon = sky_colour(normalize(vec3<f32>(to_p.x, 0.0, to_p.z) + vec3<f32>(0.0, 0.02, 0.0)));
    // Seen through air only (the camera stays above the deck); in the flat water's textures
    // only the reflection holds it (it is above the plane), with alpha 0 as everything there.
    if (CLIP_SIDE < 0) {
        discard;
    }
    return vec4<f32>(finish(mix(colour, horizon, haze)).rgb, select(1.0, 0.0, CLIP_SIDE > 0));
}
