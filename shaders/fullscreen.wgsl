// One triangle that covers the whole target; uv runs 0..1 left-to-right, top-to-bottom,
// so uv * size addresses the texel the fragment writes.

struct FullscreenOut {
    @builtin(position) position: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> FullscreenOut {
    let x = f32((index << 1u) & 2u);
    let y = f32(index & 2u);
    var out: FullscreenOut;
    out.position = vec4<f32>(x * 2.0 - 1.0, 1.0 - y * 2.0, 1.0, 1.0);
    out.uv = vec2<f32>(x, y);
    return out;
}
