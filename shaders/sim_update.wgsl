// One step of the damped 2-D wave equation h_tt = c^2 (h_xx + h_zz) - k h_t on the grid,
// semi-implicit Euler: v += dt c^2 lap(h) / dx^2, v *= exp(-k dt), h += dt v.
// Stable while c dt / dx <= 1/sqrt(2) (CFL); the CPU picks substeps to keep it so.
// Height and velocity are clamped to fixed bounds (NaN becomes rest): bounded under any input.
// Absorbing walls: both (height measured from the rest level) also decay by exp(-sigma dt) in
// a layer along the walls, with sigma rising from 0 to the sponge rate at the wall, so
// outgoing waves die instead of reflecting.

@fragment
fn fs_update(in: FullscreenOut) -> @location(0) vec4<f32> {
    let p = texel(in.position);
    let c = cell(p);
    let neighbours = cell(p + vec2<i32>(1, 0)).x + cell(p - vec2<i32>(1, 0)).x
        + cell(p + vec2<i32>(0, 1)).x + cell(p - vec2<i32>(0, 1)).x;
    let laplacian = neighbours - 4.0 * c.x;
    let absorb = exp(-sim.step.w * sponge_profile(cell_centre(p)) * sim.step.x);
    let v = bounded((c.y + sim.step.y * laplacian) * sim.step.z * absorb, sim.bounds.y);
    let level = sim.bodies.y;
    let h = bounded((c.x - level + sim.step.x * v) * absorb, sim.bounds.x) + level;
    return vec4<f32>(h, v, c.z, c.w);
}
