// Scales the scene, drawn at a lower resolution by the automatic quality, up to the target:
// one bilinear texel fetch per pixel. The image holds final (tone-mapped, encoded) colours,
// so the filter only blends neighbours; nothing is lit again.

@group(0) @binding(0) var scene_image: texture_2d<f32>;
@group(0) @binding(1) var image_sampler: sampler;

@fragment
fn fs_upscale(in: FullscreenOut) -> @location(0) vec4<f32> {
    return textureSampleLevel(scene_image, image_sampler, in.uv, 0.0);
}
