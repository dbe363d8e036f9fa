// Resampling: this grid's state from the bound state of another size over the same pool, so
// a change of resolution keeps the waves. Both grids are cell-centred. Shrinking averages the
// source cells each new cell covers (a box filter, so short waves fade instead of aliasing);
// growing interpolates bilinearly. Height and velocity only: the normals pass runs next.

// A source cell, clamped to the source grid (walls mirror, as in cell()).
fn source_cell(p: vec2<i32>, source_n: i32) -> vec2<f32> {
    return textureLoad(state, clamp(p, vec2<i32>(0), vec2<i32>(source_n - 1)), 0).xy;
}

@fragment
fn fs_resample(in: FullscreenOut) -> @location(0) vec4<f32> {
    let p = texel(in.position);
    let source_n = i32(textureDimensions(state).x);
    let n = i32(sim.grid.x);
    if (source_n >= n) {
        let f = source_n / n; // sizes are powers of two
        var sum = vec2<f32>(0.0);
        for (var j = 0; j < f; j++) {
            for (var i = 0; i < f; i++) {
                sum += source_cell(p * f + vec2<i32>(i, j), source_n);
            }
        }
        return vec4<f32>(sum / f32(f * f), 0.0, 0.0);
    }
    // Position of this cell's centre in source texels.
    let q = (vec2<f32>(p) + 0.5) * f32(source_n) / f32(n) - 0.5;
    let base = floor(q);
    let t = q - base;
    let i = vec2<i32>(base);
    let a = mix(source_cell(i, source_n), source_cell(i + vec2<i32>(1, 0), source_n), t.x);
    let b = mix(source_cell(i + vec2<i32>(0, 1), source_n), source_cell(i + vec2<i32>(1, 1), source_n), t.x);
    return vec4<f32>(mix(a, b, t.y), 0.0, 0.0);
}
