// Sky background: each pixel's view ray, reconstructed from the inverse view-projection,
// looked up in the sky cubemap. In the cut-away setting with the eye under the water's level
// the background is the water instead (water_backdrop).

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

// What an eye in open water sees along dir where nothing is in the way: the sky's light that
// came down through the surface, dimmed by the water it crossed (Beer–Lambert) over a path that is
// short looking up and long looking down, plus what the water scatters (if it does). The
// cut-away's cross-section then reads as a view from under the water, not a box in the sky.
fn water_backdrop(dir: vec3<f32>) -> vec3<f32> {
    let path = mix(BACKDROP_PATH_DOWN, BACKDROP_PATH_UP, smoothstep(-0.6, 1.0, dir.y));
    let alpha = exp(-scene.absorption.xyz * path);
    var colour = sky_light_at(true) * alpha;
    if (HAS_SCATTERING) {
        colour += (1.0 - alpha) * scene.scatter.xyz;
    }
    return colour;
}
