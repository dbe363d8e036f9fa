// One level of the caustics map's mip chain from the level above: the bilinear fetch at the
// centre of each 2x2 block is their mean (light is averaged, not summed: the map holds light
// per unit area).

@group(0) @binding(0) var level_above: texture_2d<f32>;
@group(0) @binding(1) var level_sampler: sampler;

@fragment
fn fs_caustics_mip(in: FullscreenOut) -> @location(0) vec4<f32> {
    return textureSampleLevel(level_above, level_sampler, in.uv, 0.0);
}
