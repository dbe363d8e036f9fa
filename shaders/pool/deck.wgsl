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
    // The coping's outer edge, averaged over the pixel's footprint (no stair-steps).
    let edge_width = max(fwidth(from_edge), 1.0e-5);
    let coping = 1.0 - smoothstep(COPING_WIDTH - 0.5 * edge_width, COPING_WIDTH + 0.5 * edge_width, from_edge);
    // The pixel's own material, tinted per block and with its joints: blocks along the edge
    // on the coping, slabs beyond. One set of them per pixel (software rasterisers would
    // shade both); on the edge it is blended with the other's plain colour.
    let on_coping = coping > 0.5;
    let uv = select(p.xz + vec2<f32>(half_width() + COPING_WIDTH), vec2<f32>(coping_along(p), 0.25), on_coping);
    let size = select(SLAB_SIZE, COPING_BLOCK, on_coping);
    let own = select(SLAB, STONE, on_coping) * block_tint(uv, size) * mix(0.55, 1.0, joints(uv, size, select(0.012, 0.01, on_coping)));
    let other = select(STONE, SLAB, on_coping);
    let lit = deck_lit(mix(other, own, select(1.0 - coping, coping, on_coping)), p);
    // Seen through air only (the camera stays above the deck); in the flat water's textures
    // only the reflection holds it (it is above the plane), with alpha 0 as everything there.
    if (CLIP_SIDE < 0) {
        discard;
    }
    return vec4<f32>(finish(lit).rgb, select(1.0, 0.0, CLIP_SIDE > 0));
}
