// Mean water level without reading anything back: each pass averages 2x2 blocks of the level
// above (starting from the state's heights) until one texel holds the pool's mean height. The
// normals pass subtracts it, which holds the level at rest against clamping and rounding.

@group(0) @binding(0) var finer: texture_2d<f32>;

@fragment
fn fs_reduce(in: FullscreenOut) -> @location(0) vec4<f32> {
    let p = vec2<i32>(floor(in.position.xy)) * 2;
    let a = textureLoad(finer, p, 0).x;
    let b = textureLoad(finer, p + vec2<i32>(1, 0), 0).x;
    let c = textureLoad(finer, p + vec2<i32>(0, 1), 0).x;
    let d = textureLoad(finer, p + vec2<i32>(1, 1), 0).x;
    return vec4<f32>(((a + b) + (c + d)) * 0.25, 0.0, 0.0, 0.0);
}
