// Pool floor and walls seen directly (above the water line, or from below the surface):
// tiles lit by the sun, through the caustics map under water, dimmed by any water
// between the eye and the tile.

struct PoolOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
};

@vertex
fn vs_pool(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>) -> PoolOut {
    var out: PoolOut;
    out.clip = scene.view_proj * vec4<f32>(position, 1.0);
    out.world = position;
    out.normal = normal;
    return out;
}

@fragment
fn fs_pool(in: PoolOut) -> @location(0) vec4<f32> {
    let edge = deck_edge(in.world);
    let n = normalize(in.normal);
    let texel = textureSample(tile_texture, repeat_sampler, tile_uv(in.world, n));
    // Derivatives (tile_lod) in uniform control flow only (WebGPU refuses them elsewhere).
    var lod = 0.0;
    if (HAS_GLAZE) {
        lod = tile_lod(in.world);
    }
    if (HAS_CAUSTICS) {
        // The caustics map read at the level of the pixel's footprint on it: a wall seen
        // from the side (the cut-away's, from under the water) squeezes the map's lines,
        // stretched down it by the steep sunbeam, to under a pixel.
        let texels = caustics_uv(light_entry(in.world)) * f32(textureDimensions(caustics_map).x);
        let footprint = max(length(dpdx(texels)), length(dpdy(texels)));
        caustics_lod = max(CAUSTICS_MIN_LOD, log2(max(footprint, 1.0e-3)));
    }
    // How much of the pixel a wall covers above its bottom edge (for the view from under the
    // floor's level, below).
    let above_bottom = clamp((in.world.y + depth()) / max(fwidth(in.world.y), 1.0e-6), 0.0, 1.0);
    let under = lit_under(in.world);
    // The objects' shadow above the water (under it the caustics map holds it), for the tile's
    // colour and its glaze.
    var sun_through = 1.0;
    if (!under) {
        sun_through = objects_visibility(in.world, scene.sun.xyz, 10.0, 0.0);
    }
    // The coves face up into the pool: from under the floor's level (the cut-away's open water)
    // the floor's slab hides them, and the walls are seen flat to their bottom edge. (The flat
    // water's mirror texture, CLIP_SIDE, is drawn from the eye's mirror image: coved as seen.)
    let lit_normal = select(n, coved_normal(in.world), CLIP_SIDE != 0 || scene.eye.y > -depth());
    var colour = pool_colour(in.world, lit_normal, texel.rgb, under, sun_through);
    if (HAS_GLAZE && !under) {
        colour += tile_glaze(in.world, n, texel.a, lod, sun_through);
    }
    if (!HAS_DECK && CLIP_SIDE == 0 && scene.eye.y < 0.0) {
        return seen_from_open_water(colour, in.world, above_bottom);
    }
    // Seen directly from above the deck, the pool is above the water: nothing dims the edge.
    return seen_directly(with_deck_edge(colour, edge), in.world);
}

// The cut-away seen from under the water, the eye in the open water round the box: what lies
// above the water's level is seen through the open water's surface, past its critical angle
// (the pool's rim stood over the surface's faded edge in pale slivers), so not at all; and
// with the eye under the floor's level the walls' bottom edge, against the open water, is
// blended into it by the share of the pixel the wall covers (`cover`), not a staircase.
fn seen_from_open_water(colour: vec3<f32>, p: vec3<f32>, cover: f32) -> vec4<f32> {
    if (p.y > 0.0) {
        discard;
    }
    let seen = through_water(colour, scene.eye.xyz, p);
    let behind = water_backdrop(normalize(p - scene.eye.xyz));
    return finish(mix(behind, seen, select(1.0, cover, scene.eye.y < -depth())));
}
