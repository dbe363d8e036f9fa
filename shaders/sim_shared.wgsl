// Bindings and cell addressing shared by the simulation passes. The state texture holds,
// per cell: (height above rest h in m, vertical velocity v in m/s, normal.x, normal.z).
// Cells are N x N over the pool's square; texel i sits at x = -W + (i + 0.5) * dx.

struct Sim {
    grid: vec4<f32>,        // x N, y 1/N, z cell size dx (m), w pool half width W (m)
    step: vec4<f32>,        // x dt (s), y c^2 dt / dx^2 (1/s), z velocity damping per step exp(-k dt),
                            // w sponge damping rate at the walls (1/s; 0: reflecting walls)
    bounds: vec4<f32>,      // x largest |height| (m), y largest |velocity| (m/s), z sponge width (m)
    drops_info: vec4<f32>,  // x number of drops, y uniform height correction (m) keeping volume
    drops: array<vec4<f32>, MAX_DROPS>, // per drop: centre x, z (m), radius (m), strength (m)
    bodies: vec4<f32>,      // x number of hull moves, y rest level the mean is held at (m),
                            // z depth over which a body's push fades (m)
    // Per step of the frame (4), per hull move (3), 8 entries: before, then after the move,
    // each the ellipsoid's centre (m) and the three columns of the matrix taking offsets from
    // it into the unit ball.
    hulls: array<vec4<f32>, HULL_SLOTS>,
};

@group(0) @binding(0) var<uniform> sim: Sim;
@group(0) @binding(1) var state: texture_2d<f32>;
// One texel: the mean height of the state before this frame's normals pass (m).
@group(0) @binding(2) var mean_level: texture_2d<f32>;

// Cell value with clamped addressing: a cell beyond the wall mirrors the edge cell,
// which makes the walls reflecting (zero normal gradient).
fn cell(p: vec2<i32>) -> vec4<f32> {
    let n = i32(sim.grid.x);
    return textureLoad(state, clamp(p, vec2<i32>(0), vec2<i32>(n - 1)), 0);
}

fn cell_centre(p: vec2<i32>) -> vec2<f32> {
    return ((vec2<f32>(p) + 0.5) * sim.grid.y * 2.0 - 1.0) * sim.grid.w;
}

// The absorbing walls' damping layer at pool point x (m): 0 beyond the sponge width from every
// wall, rising quadratically to 1 at the wall (sponge_profile in sim.rs).
fn sponge_profile(x: vec2<f32>) -> f32 {
    let from_wall = sim.grid.w - max(abs(x.x), abs(x.y));
    let t = max(1.0 - from_wall / sim.bounds.z, 0.0);
    return t * t;
}

fn texel(position: vec4<f32>) -> vec2<i32> {
    return vec2<i32>(floor(position.xy));
}

// A finite value clamped to [-limit, limit]; NaN and infinity become 0 (rest), so a bad
// value can never spread through the grid.
fn bounded(x: f32, limit: f32) -> f32 {
    return clamp(select(0.0, x, abs(x) <= 3.0e38), -limit, limit);
}

// Height bounded around the rest level (which bodies in the water raise).
fn bounded_height(h: f32) -> f32 {
    return bounded(h - sim.bodies.y, sim.bounds.x) + sim.bodies.y;
}
