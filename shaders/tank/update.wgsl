// One update of the ripple tank's shallow water: h_tt = div(c^2 grad h), c^2 = g d per cell,
// the flux across each face the mean of its two cells' c^2 (none into a wall or out of the
// tray: such faces are 0), so waves slow and bend over a plate and stop at a barrier.
// Semi-implicit Euler: v += dt / dx^2 * sum(face c^2 * (h_n - h)), h += dt v; both decay on
// the beaches. Dippers and the bar set their cells to A sin(phase) (a pulse: A (1 - cos) / 2). The CPU reference is
// tank/cpu.rs.

struct Update {
    grid: vec4<f32>,    // x cells per side, y dx (m), z dt (s), w half width (m)
    wave: vec4<f32>,    // x phase at the update's end (rad), y amplitude (m), z omega (rad/s), w dippers
    bar: vec4<f32>,     // x z (m), y half thickness (m), z 1 if a bar, w drops
    bounds: vec4<f32>,  // x largest |h| (m), y largest |v| (m/s), z the bar's half length (m),
                        // w 1 if the sources make one pulse (a raised cosine), 0 a steady sine
    dippers: array<vec4<f32>, MAX_DIPPERS>, // centre x, z (m), radius (m), phase (rad)
    dipper_amplitudes: vec4<f32>, // each dipper's amplitude as a share of wave.y
    drops: array<vec4<f32>, MAX_TANK_DROPS>, // centre x, z (m), radius (m), height (m)
};

@group(0) @binding(0) var<uniform> u: Update;
// The state: h (m), v (m/s), the intensity h^2 averaged over the last INTENSITY_TIME s (m^2).
@group(0) @binding(1) var state: texture_2d<f32>;
// Per cell: c^2 (m^2/s^2) of its east face (+x) and of its north face (+z), the beach's
// damping rate (1/s), its kind (0 water, 1 wall, 2 plate).
@group(0) @binding(2) var medium: texture_2d<f32>;

fn centre(p: vec2<i32>) -> vec2<f32> {
    return (vec2<f32>(p) + 0.5) * u.grid.y - u.grid.w;
}

fn bounded(x: f32, limit: f32) -> f32 {
    return clamp(select(0.0, x, abs(x) <= 3.0e38), -limit, limit);
}

// The phase of the source covering point x and its amplitude (m), or a negative phase where
// none does.
fn source_phase(x: vec2<f32>) -> vec2<f32> {
    for (var k = 0; k < i32(u.wave.w); k++) {
        let d = u.dippers[k];
        let r = x - d.xy;
        if dot(r, r) <= d.z * d.z {
            return vec2<f32>(u.wave.x + d.w, u.wave.y * u.dipper_amplitudes[k]);
        }
    }
    if u.bar.z > 0.0 && abs(x.y - u.bar.x) <= u.bar.y && abs(x.x) <= u.bounds.z {
        return vec2<f32>(u.wave.x, u.wave.y);
    }
    return vec2<f32>(-1.0, 0.0);
}

@fragment
fn fs_update(in: FullscreenOut) -> @location(0) vec4<f32> {
    let p = vec2<i32>(in.position.xy);
    let last = vec2<i32>(i32(u.grid.x) - 1);
    let m = textureLoad(medium, p, 0);
    if m.w == WALL {
        return vec4<f32>(0.0);
    }
    let west = select(0.0, textureLoad(medium, max(p - vec2<i32>(1, 0), vec2<i32>(0)), 0).x, p.x > 0);
    let south = select(0.0, textureLoad(medium, max(p - vec2<i32>(0, 1), vec2<i32>(0)), 0).y, p.y > 0);
    let c = textureLoad(state, p, 0);
    let flux = m.x * (textureLoad(state, min(p + vec2<i32>(1, 0), last), 0).x - c.x)
        + west * (textureLoad(state, max(p - vec2<i32>(1, 0), vec2<i32>(0)), 0).x - c.x)
        + m.y * (textureLoad(state, min(p + vec2<i32>(0, 1), last), 0).x - c.x)
        + south * (textureLoad(state, max(p - vec2<i32>(0, 1), vec2<i32>(0)), 0).x - c.x);
    let absorb = exp(-m.z * u.grid.z);
    var v = (c.y + u.grid.z / (u.grid.y * u.grid.y) * flux) * absorb;
    var h = (c.x + u.grid.z * v) * absorb;
    let source = source_phase(centre(p));
    let phase = source.x;
    if phase >= 0.0 && u.bounds.w > 0.5 {
        h = 0.5 * source.y * (1.0 - cos(phase));
        v = 0.5 * source.y * u.wave.z * sin(phase);
    } else if phase >= 0.0 {
        h = source.y * sin(phase);
        v = source.y * u.wave.z * cos(phase);
    }
    h = bounded(h, u.bounds.x);
    let averaged = c.z + (h * h - c.z) * (u.grid.z / INTENSITY_TIME);
    return vec4<f32>(h, bounded(v, u.bounds.y), averaged, 0.0);
}

// A raised cosine of `radius` at distance `r`.
fn cosine_bump(r: f32, radius: f32) -> f32 {
    return 0.5 + 0.5 * cos(PI * min(r / radius, 1.0));
}

// The update's drops added to the water (not to walls), before it: raised cosines less a
// quarter of ones twice as wide, which add no water (tank/cpu.rs drop_bump).
@fragment
fn fs_drops(in: FullscreenOut) -> @location(0) vec4<f32> {
    let p = vec2<i32>(in.position.xy);
    var c = textureLoad(state, p, 0);
    if textureLoad(medium, p, 0).w == WALL {
        return c;
    }
    let x = centre(p);
    for (var k = 0; k < i32(u.bar.w); k++) {
        let d = u.drops[k];
        let r = length(x - d.xy);
        c.x += d.w * (cosine_bump(r, d.z) - 0.25 * cosine_bump(r, 2.0 * d.z));
    }
    c.x = bounded(c.x, u.bounds.x);
    return c;
}
