// One update of the ripple tank's shallow water: h_tt = div(c^2 grad h), c^2 = g d per cell,
// with the flux across each face c^2 averaged over its two cells and none into a wall, so
// waves slow and bend over a plate and stop at a barrier. Semi-implicit Euler:
// v += dt / dx^2 * sum(face c^2 * (h_n - h)), h += dt v; both decay on the beaches. Dippers
// and the bar set their cells to A sin(phase). The CPU reference is tank/cpu.rs.

struct Update {
    grid: vec4<f32>,    // x cells per side, y dx (m), z dt (s), w half width (m)
    wave: vec4<f32>,    // x phase at the update's end (rad), y amplitude (m), z omega (rad/s), w dippers
    bar: vec4<f32>,     // x z (m), y half thickness (m), z 1 if a bar, w drops
    bounds: vec4<f32>,  // x largest |h| (m), y largest |v| (m/s)
    dippers: array<vec4<f32>, MAX_DIPPERS>, // centre x, z (m), radius (m), phase (rad)
    drops: array<vec4<f32>, MAX_TANK_DROPS>, // centre x, z (m), radius (m), height (m)
};

@group(0) @binding(0) var<uniform> u: Update;
@group(0) @binding(1) var state: texture_2d<f32>;
// Per cell: c^2 (m^2/s^2), beach damping rate (1/s), kind (0 water, 1 wall, 2 plate).
// The state: h (m), v (m/s), the intensity h^2 averaged over the last INTENSITY_TIME s (m^2).
@group(0) @binding(2) var medium: texture_2d<f32>;

fn centre(p: vec2<i32>) -> vec2<f32> {
    return (vec2<f32>(p) + 0.5) * u.grid.y - u.grid.w;
}

fn bounded(x: f32, limit: f32) -> f32 {
    return clamp(select(0.0, x, abs(x) <= 3.0e38), -limit, limit);
}

// The cell's height with this update's drops added (m).
fn raised(p: vec2<i32>) -> f32 {
    var h = textureLoad(state, p, 0).x;
    let x = centre(p);
    for (var k = 0; k < i32(u.bar.w); k++) {
        let d = u.drops[k];
        h += d.w * (0.5 + 0.5 * cos(PI * min(length(x - d.xy) / d.z, 1.0)));
    }
    return h;
}

// The phase of the source covering point x, or a negative number where none does.
fn source_phase(x: vec2<f32>) -> f32 {
    for (var k = 0; k < i32(u.wave.w); k++) {
        let d = u.dippers[k];
        let r = x - d.xy;
        if dot(r, r) <= d.z * d.z {
            return u.wave.x + d.w;
        }
    }
    if u.bar.z > 0.0 && abs(x.y - u.bar.x) <= u.bar.y {
        return u.wave.x;
    }
    return -1.0;
}

@fragment
fn fs_update(in: FullscreenOut) -> @location(0) vec4<f32> {
    let p = vec2<i32>(in.position.xy);
    let n = i32(u.grid.x);
    let m = textureLoad(medium, p, 0);
    if m.z == 1.0 {
        return vec4<f32>(0.0);
    }
    let h = raised(p);
    var flux = 0.0;
    let steps = array<vec2<i32>, 4>(vec2<i32>(1, 0), vec2<i32>(-1, 0), vec2<i32>(0, 1), vec2<i32>(0, -1));
    for (var k = 0; k < 4; k++) {
        let q = p + steps[k];
        if any(q < vec2<i32>(0)) || any(q >= vec2<i32>(n)) {
            continue;
        }
        let mq = textureLoad(medium, q, 0);
        if mq.z == 1.0 {
            continue;
        }
        flux += 0.5 * (m.x + mq.x) * (raised(q) - h);
    }
    let absorb = exp(-m.y * u.grid.z);
    var v = (textureLoad(state, p, 0).y + u.grid.z / (u.grid.y * u.grid.y) * flux) * absorb;
    var hn = (h + u.grid.z * v) * absorb;
    let phase = source_phase(centre(p));
    if phase >= 0.0 {
        hn = u.wave.y * sin(phase);
        v = u.wave.y * u.wave.z * cos(phase);
    }
    hn = bounded(hn, u.bounds.x);
    let intensity = textureLoad(state, p, 0).z;
    let averaged = intensity + (hn * hn - intensity) * (u.grid.z / INTENSITY_TIME);
    return vec4<f32>(hn, bounded(v, u.bounds.y), averaged, 0.0);
}
