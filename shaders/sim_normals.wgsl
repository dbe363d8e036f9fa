// Surface normals from central differences of the height: n ~ (-dh/dx, 1, -dh/dz).
// Run once per frame after the steps; only x and z are stored (y follows from unit length).
// It also brings the mean height back to the rest level (see sim_mean.wgsl): 0, raised by
// the volume of any bodies in the water over the pool's area.

@fragment
fn fs_normals(in: FullscreenOut) -> @location(0) vec4<f32> {
    let p = texel(in.position);
    let c = cell(p);
    let two_dx = 2.0 * sim.grid.z;
    let slope_x = (cell(p + vec2<i32>(1, 0)).x - cell(p - vec2<i32>(1, 0)).x) / two_dx;
    let slope_z = (cell(p + vec2<i32>(0, 1)).x - cell(p - vec2<i32>(0, 1)).x) / two_dx;
    let n = normalize(vec3<f32>(-slope_x, 1.0, -slope_z));
    // Hold the mean level at the rest level (the correction cancels in the slopes above).
    let mean = textureLoad(mean_level, vec2<i32>(0, 0), 0).x;
    return vec4<f32>(c.x - (mean - sim.bodies.y), c.y, n.x, n.z);
}
