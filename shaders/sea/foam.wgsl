// The whitecaps kept over time (scenes/sea/render/foam.rs): foam (0-1) in red over the sea plane
// round the origin, WHITECAP_MAP_TEXELS a side over WHITECAP_MAP_HALF_WIDTH each way, indexed
// by rest point (where the eye's ray meets the mean plane). Each frame a texel keeps its foam
// times sea.foam.w (e^(-steps dt / lifetime): the same fade at every frame rate) or takes the
// foam the waves make there now, whichever is more, so a broken crest leaves a fading trail.

@group(3) @binding(1) var whitecap_map: texture_2d<f32>;

// The kept foam at rest point p: as it fades it thins into streaks and patches (where the
// finest cascade's slope, read at another scale as a pattern of about a metre, is low), and
// it fades out over the map's outer tenth (past it the sea shows the foam of the moment only).
fn kept_whitecaps(p: vec2<f32>) -> f32 {
    let uv = p / (2.0 * WHITECAP_MAP_HALF_WIDTH) + 0.5;
    let from_middle = 2.0 * max(abs(uv.x - 0.5), abs(uv.y - 0.5));
    let fade = 1.0 - smoothstep(0.9, 1.0, from_middle);
    let kept = textureSampleLevel(whitecap_map, clamp_sampler, uv, 0.0).r * fade;
    let finest = CASCADES - 1;
    let slope = cascade_texel(sea_surface, finest, p * 0.45, sea.cascades[finest].z).y;
    let streaks = 0.5 + 0.3 * slope / sqrt(max(sea.cascades[finest].w, 1.0e-8));
    return kept * smoothstep(0.1, 0.7, streaks + kept - 0.5);
}

// A texel of the next map from the current one.
@fragment
fn fs_whitecaps(in: FullscreenOut) -> @location(0) vec4<f32> {
    let p = (in.uv - 0.5) * 2.0 * WHITECAP_MAP_HALF_WIDTH;
    let texel = 2.0 * WHITECAP_MAP_HALF_WIDTH / f32(WHITECAP_MAP_TEXELS);
    let kept = textureSampleLevel(whitecap_map, clamp_sampler, in.uv, 0.0).r * sea.foam.w;
    let now = whitecap(waves_at(p, texel).jacobian);
    return vec4<f32>(max(kept, now), 0.0, 0.0, 1.0);
}
