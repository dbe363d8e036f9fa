// One step of the damped 2-D wave equation h_tt = c^2 (h_xx + h_zz) - k h_t on the grid,
// semi-implicit Euler: v += dt c^2 lap(h) / dx^2 - d lap(lap(v)), v *= exp(-k dt), h += dt v.
// Stable while c dt / dx <= 1/sqrt(2) (CFL); the CPU picks substeps to keep it so. The
// velocity's hyperdiffusion d (SHORT_RIPPLE_DAMPING in sim/plan.rs) damps the ripples a few
// cells long, which the five-point Laplacian carries too slowly to keep up with their ring.
// Height and velocity are clamped to fixed bounds (NaN becomes rest): bounded under any input.
// Absorbing walls: both (height measured from the rest level) also decay by exp(-sigma dt) in
// a layer along the walls, with sigma rising from 0 to the sponge rate at the wall, so
// outgoing waves die instead of reflecting.

@fragment
fn fs_update(in: FullscreenOut) -> @location(0) vec4<f32> {
    let p = texel(in.position);
    let c = cell(p);
    let neighbours = cell(p + vec2<i32>(1, 0)).xy + cell(p - vec2<i32>(1, 0)).xy
        + cell(p + vec2<i32>(0, 1)).xy + cell(p - vec2<i32>(0, 1)).xy;
    let laplacian = neighbours.x - 4.0 * c.x;
    let diagonals = cell(p + vec2<i32>(1, 1)).y + cell(p + vec2<i32>(-1, 1)).y
        + cell(p + vec2<i32>(1, -1)).y + cell(p + vec2<i32>(-1, -1)).y;
    let twos = cell(p + vec2<i32>(2, 0)).y + cell(p - vec2<i32>(2, 0)).y
        + cell(p + vec2<i32>(0, 2)).y + cell(p - vec2<i32>(0, 2)).y;
    // The 13-point biharmonic of the velocity (20 at the cell, -8 beside, 2 diagonal, 1 two away).
    let biharmonic = 20.0 * c.y - 8.0 * neighbours.y + 2.0 * diagonals + twos;
    let absorb = exp(-sim.step.w * sponge_profile(cell_centre(p)) * sim.step.x);
    let v = bounded((c.y + sim.step.y * laplacian - sim.bounds.w * biharmonic) * sim.step.z * absorb, sim.bounds.y);
    let level = sim.bodies.y;
    let h = bounded((c.x - level + sim.step.x * v) * absorb, sim.bounds.x) + level;
    return vec4<f32>(h, v, c.z, c.w);
}
