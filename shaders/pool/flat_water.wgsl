// Flat water (seeds 000, 002, 003): a plane at rest level that shows two pictures drawn
// beforehand, the scene mirrored in the plane (reflection) and the scene under it
// (refraction, already dimmed by Beer–Lambert along the unbent path), read at the plane's own
// screen position shifted by a distortion, and blended by the Fresnel reflectance of the
// distortion's normal. Nothing is traced: reflections do not bend with distance, the
// refraction is not bent at all, and there is no Snell's window.

@group(2) @binding(0) var reflection_texture: texture_2d<f32>;
@group(2) @binding(1) var refraction_texture: texture_2d<f32>;

struct FlatOut {
    @builtin(position) position: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) clip: vec4<f32>,
};

@vertex
fn vs_flat(@location(0) grid: vec2<f32>) -> FlatOut {
    var out: FlatOut;
    out.world = vec3<f32>(grid.x * half_width(), scene.flat.x, grid.y * half_width());
    out.clip = scene.view_proj * vec4<f32>(out.world, 1.0);
    out.position = out.clip;
    return out;
}

// A texel of a texture drawn by the scene passes, back in linear light.
fn linear_texel(t: vec4<f32>) -> vec3<f32> {
    return select(t.rgb, srgb_to_linear(t.rgb), ENCODE_SRGB);
}

@fragment
fn fs_flat(in: FlatOut) -> @location(0) vec4<f32> {
    // Screen position as texture coordinates (seed 000: clip.xy / w / 2 + 0.5, y down here).
    let uv = vec2<f32>(in.clip.x, -in.clip.y) / in.clip.w * 0.5 + 0.5;
    let n = flat_normal(in.world.xz);
    // Seed 002: shallow water (short paths) is shifted less, so the walls' seam stays put.
    let still = textureSampleLevel(refraction_texture, clamp_sampler, uv, 0.0);
    let soft = select(1.0, clamp(still.a * FLAT_PATH_SCALE / max(scene.flat.w, 1.0e-4), 0.0, 1.0), scene.flat.w > 0.0);
    let reference = select(FLAT_REFERENCE_SLOPE, RIPPLE_REFERENCE_SLOPE, FLAT_DISTORTION == FLAT_RIPPLES);
    let shift = n.xz / reference * scene.flat.y * soft;
    var under = textureSampleLevel(refraction_texture, clamp_sampler, uv + shift, 0.0);
    // Seed 002: a shifted lookup that lands on nothing under the water (alpha 0) keeps the
    // unshifted texel instead of pulling the rim's picture in.
    under = select(under, still, under.a <= 0.0);
    let mirrored = textureSampleLevel(reflection_texture, clamp_sampler, uv + shift, 0.0);
    let view = normalize(in.world - scene.eye.xyz);
    let r = reflectance(dot(-view, n), IOR_AIR / IOR_WATER);
    // The sun's highlight only where the reflection shows sky (alpha 1).
    let glint = sun_specular(reflect(view, n), n) * mirrored.a;
    let colour = mix(linear_texel(under), linear_texel(mirrored), r) + r * glint;
    // The textures are tone-mapped already: only the highlight is rolled off here.
    let mapped = clamp(colour, vec3<f32>(0.0), vec3<f32>(1.0));
    return vec4<f32>(select(mapped, linear_to_srgb(mapped), ENCODE_SRGB), 1.0);
}
