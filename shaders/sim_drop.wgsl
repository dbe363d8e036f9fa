// Drops: each adds a smooth cosine bump h += s * (1 - cos(pi * (1 - d/r))) / 2 inside its
// radius r. The CPU computes the bumps' mean over the grid and it is subtracted everywhere,
// so a drop adds no net water and the mean level stays at rest.

@fragment
fn fs_drop(in: FullscreenOut) -> @location(0) vec4<f32> {
    let p = texel(in.position);
    var s = cell(p);
    let x = cell_centre(p);
    let count = i32(sim.drops_info.x);
    for (var i = 0; i < count; i++) {
        let drop = sim.drops[i];
        let d = length(x - drop.xy) / drop.z;
        s.x += drop.w * (0.5 - 0.5 * cos(PI * max(1.0 - d, 0.0)));
    }
    s.x = bounded(s.x - sim.drops_info.y, sim.bounds.x);
    return s;
}
