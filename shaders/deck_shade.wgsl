// The deck's stones, lit: shared by the deck's own pass (deck.wgsl) and by the passes that
// draw what is seen through the pool's opening, which blend the coping into the pixels the
// opening's edge crosses (deck_edge), so the edge is not a staircase of whole pixels.

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

// Position along the opening's edge that the coping stones are laid by (m).
fn coping_along(p: vec3<f32>) -> f32 {
    return select(p.z, p.x, abs(p.z) > abs(p.x));
}

// A coping stone's own colour: pale, each block a little different.
fn coping_stone(along: f32) -> vec3<f32> {
    return vec3<f32>(0.60, 0.57, 0.52) * (0.9 + 0.2 * hash31(vec3<f32>(floor(along / 0.5), 0.0, 0.3)));
}

// Ground of `albedo` at p under the open sky and the sun, fading into the horizon's haze with
// distance (the deck is above the water and its objects: no shadows cast on it).
fn deck_lit(albedo: vec3<f32>, p: vec3<f32>) -> vec3<f32> {
    let colour = albedo * (sky_light() + max(scene.sun.y, 0.0) * sun_light());
    let to_p = p - scene.eye.xyz;
    let haze = 1.0 - exp(-length(to_p) / HAZE_DISTANCE * 0.69);
    let horizon = sky_colour(normalize(vec3<f32>(to_p.x, 0.0, to_p.z) + vec3<f32>(0.0, 0.02, 0.0)));
    return mix(colour, horizon, haze);
}

// Where the pixel's ray (eye to `world`) crosses the deck's plane (xyz) and the share of the
// pixel the deck covers there (w): the part of the pixel's footprint past the opening's edge,
// a ramp one footprint wide. 0 with no deck, or where the eye is not above it. Call it in
// uniform control flow (it takes a screen derivative).
fn deck_edge(world: vec3<f32>) -> vec4<f32> {
    let dir = world - scene.eye.xyz;
    let q = scene.eye.xyz + dir * max((rim() - scene.eye.y) / min(dir.y, -1.0e-6), 0.0);
    let inside = half_width() - max(abs(q.x), abs(q.z));
    let cover = clamp(0.5 - inside / max(fwidth(inside), 1.0e-6), 0.0, 1.0);
    let seen = HAS_DECK && CLIP_SIDE == 0 && scene.eye.y > rim() && dir.y < 0.0;
    return vec4<f32>(q, select(0.0, cover, seen));
}

// `out` (a finished pixel seen through the opening) with the coping blended in by `edge`
// (deck_edge). Software rasterisers shade this for every pixel seen through the opening, so
// it is the coping's light without the joints and the haze, which a pixel on the edge does
// not show (the haze is under 13 % within the 12 m the camera keeps to).
fn with_deck_edge(out: vec4<f32>, edge: vec4<f32>) -> vec4<f32> {
    if (edge.w <= 0.0) {
        return out;
    }
    let light = sky_light() + max(scene.sun.y, 0.0) * sun_light();
    let coping = finish(coping_stone(coping_along(edge.xyz)) * light);
    return vec4<f32>(mix(out.rgb, coping.rgb, edge.w), out.a);
}
