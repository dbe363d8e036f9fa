// Mean water level and largest wave without reading the whole grid back: each pass folds 2x2
// blocks of the level above, starting from the state's heights, until one texel holds
// x = the pool's mean height (m) and y = its largest |height| (m). The normals pass subtracts
// the mean, which holds the level at rest against clamping and rounding; the texel is also
// copied out (asynchronously) for statistics.

@group(0) @binding(0) var finer: texture_2d<f32>;

fn block(p: vec2<i32>) -> array<vec4<f32>, 4> {
    return array<vec4<f32>, 4>(
        textureLoad(finer, p, 0),
        textureLoad(finer, p + vec2<i32>(1, 0), 0),
        textureLoad(finer, p + vec2<i32>(0, 1), 0),
        textureLoad(finer, p + vec2<i32>(1, 1), 0),
    );
}

// First level: reads the state (height in x).
@fragment
fn fs_reduce_state(in: FullscreenOut) -> @location(0) vec4<f32> {
    let b = block(vec2<i32>(floor(in.position.xy)) * 2);
    let mean = ((b[0].x + b[1].x) + (b[2].x + b[3].x)) * 0.25;
    let peak = max(max(abs(b[0].x), abs(b[1].x)), max(abs(b[2].x), abs(b[3].x)));
    return vec4<f32>(mean, peak, 0.0, 0.0);
}

// Further levels: read (mean, peak) pairs.
@fragment
fn fs_reduce_level(in: FullscreenOut) -> @location(0) vec4<f32> {
    let b = block(vec2<i32>(floor(in.position.xy)) * 2);
    let mean = ((b[0].x + b[1].x) + (b[2].x + b[3].x)) * 0.25;
    let peak = max(max(b[0].y, b[1].y), max(b[2].y, b[3].y));
    return vec4<f32>(mean, peak, 0.0, 0.0);
}
