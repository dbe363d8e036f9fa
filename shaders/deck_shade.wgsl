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

// The coping's pale stone and the paving's warm slabs (albedo), each block a little different
// (block_tint); coping blocks are COPING_BLOCK m long.
const STONE: vec3<f32> = vec3<f32>(0.60, 0.57, 0.52);
const SLAB: vec3<f32> = vec3<f32>(0.095, 0.062, 0.042);
const COPING_BLOCK: f32 = 0.5;

// A block's tint (0.9 to 1.1) from its cell on a grid of `size` m.
fn block_tint(uv: vec2<f32>, size: f32) -> f32 {
    return 0.9 + 0.2 * hash31(vec3<f32>(floor(uv / size), 0.3));
}

// A coping stone's own colour.
fn coping_stone(along: f32) -> vec3<f32> {
    return STONE * block_tint(vec2<f32>(along, 0.25), COPING_BLOCK);
}

// Ground of `albedo` at p under the open sky and the sun, fading into the horizon's haze with
// distance (the deck is above the water and its objects: no shadows cast on it).
fn deck_lit(albedo: vec3<f32>, p: vec3<f32>) -> vec3<f32> {
    let colour = albedo * (sky_light() + max(scene.sun.y, 0.0) * sun_light());
    let to_p = p - scene.eye.xyz;
    let haze = 1.0 - exp(-length(to_p) / HAZE_DISTANCE * 0.69);
    return mix(colour, horizon_colour(to_p.xz), haze);
}

// The sky's colour at the horizon towards `towards` (horizontal, any length), as the sky cube
// holds it: render/deck.rs's fit, a polynomial in √(1 − cos) of the angle from the sun.
fn horizon_colour(towards: vec2<f32>) -> vec3<f32> {
    let h = &scene.horizon;
    let dir = normalize(vec3<f32>(towards.x, HORIZON_LIFT * length(towards), towards.y));
    let x = sqrt(max(1.0 - dot(dir, scene.sun.xyz), 0.0)) * (*h)[0].w + (*h)[1].w;
    // Horner's rule, written out (a loop indexes the uniform array at run time).
    let colour = (*h)[0].rgb + x * ((*h)[1].rgb + x * ((*h)[2].rgb + x * ((*h)[3].rgb + x * (*h)[4].rgb)));
    return clamp(colour, vec3<f32>(0.0), vec3<f32>(SKY_RANGE));
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

// `colour` (the scene light of a pixel seen through the opening, before the tone curve) with
// the coping's blended in by `edge` (deck_edge). Software rasterisers shade this for every
// pixel seen through the opening (both sides of any branch, so none is taken), so it is the
// coping's light without the joints and the haze, which a pixel on the edge does not show (the
// haze is under 13 % within the 12 m the camera keeps to), blended before the one tone curve.
fn with_deck_edge(colour: vec3<f32>, edge: vec4<f32>) -> vec3<f32> {
    let light = sky_light() + max(scene.sun.y, 0.0) * sun_light();
    return mix(colour, coping_stone(coping_along(edge.xyz)) * light, edge.w);
}
