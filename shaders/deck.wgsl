// The deck around the pool: coping stones along the opening and square paving slabs beyond,
// lit by the sun and the sky, fading into the horizon's haze with
// distance (aerial perspective: the air between adds the sky's colour and hides the ground).
// Joints are filtered over the pixel's footprint, so far slabs blend instead of shimmering.

// The stones and their light are in deck_shade.wgsl (part of every scene pass).

// Its vertices go through the pool's vs_pool (pool.wgsl, joined ahead of this file).

@fragment
fn fs_deck(in: PoolOut) -> @location(0) vec4<f32> {
    let p = in.world;
    let from_edge = max(abs(p.x), abs(p.z)) - half_width();
    // Coping: pale stone blocks along the edge; slabs: warmer, each a little different.
    let along = coping_along(p);
    let slab_uv = p.xz + vec2<f32>(half_width() + COPING_WIDTH);
    let slab_tint = 0.9 + 0.2 * hash31(vec3<f32>(floor(slab_uv / SLAB_SIZE), 0.3));
    let slab = vec3<f32>(0.095, 0.062, 0.042) * slab_tint * mix(0.55, 1.0, joints(slab_uv, SLAB_SIZE, 0.012));
    let stone = coping_stone(along) * mix(0.55, 1.0, joints(vec2<f32>(along, 0.25), 0.5, 0.01));
    // The coping's outer edge, averaged over the pixel's footprint (no stair-steps).
    let edge_width = max(fwidth(from_edge), 1.0e-5);
    let coping = 1.0 - smoothstep(COPING_WIDTH - 0.5 * edge_width, COPING_WIDTH + 0.5 * edge_width, from_edge);
    let lit = deck_lit(mix(slab, stone, coping), p);
    // Seen through air only (the camera stays above the deck); in the flat water's textures
    // only the reflection holds it (it is above the plane), with alpha 0 as everything there.
    if (CLIP_SIDE < 0) {
        discard;
    }
    return vec4<f32>(finish(lit).rgb, select(1.0, 0.0, CLIP_SIDE > 0));
}
