// Sky background: each pixel's view ray, reconstructed from the inverse view-projection,
// looked up in the sky cubemap. In the cut-away setting with the eye under the water's level
// the background is the water instead (water_backdrop, scene_seen.wgsl).

@fragment
fn fs_sky(in: FullscreenOut) -> @location(0) vec4<f32> {
    let ndc = vec2<f32>(in.uv.x * 2.0 - 1.0, 1.0 - in.uv.y * 2.0);
    let far = scene.inv_view_proj * vec4<f32>(ndc, 1.0, 1.0);
    let near = scene.inv_view_proj * vec4<f32>(ndc, 0.0, 1.0);
    let dir = normalize(far.xyz / far.w - near.xyz / near.w);
    if (!HAS_DECK && CLIP_SIDE == 0 && scene.eye.y < 0.0) {
        return finish(water_backdrop(dir));
    }
    return finish(sky_colour(dir));
}
