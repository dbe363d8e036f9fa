// Water sampled for the bodies: texel i of a one-row target gets the state (height m,
// velocity m/s, normal x, z) at probe point i, bilinearly. The row is read back
// asynchronously, so buoyancy never makes a frame wait for the GPU.

@fragment
fn fs_probe(in: FullscreenOut) -> @location(0) vec4<f32> {
    let i = i32(floor(in.position.x));
    let pair = sim.probes[i / 2];
    let x = select(pair.xy, pair.zw, i % 2 == 1);
    return sample_state(x);
}
