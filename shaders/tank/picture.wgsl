// What the tank's two picture passes share: their uniforms, the water's state and medium, and
// the lamp's ray through the water to the screen.

struct Picture {
    inverse_view_proj: mat4x4<f32>,
    mesh: vec4<f32>,    // x the screen mesh's points per side, y cells between them
    tray: vec4<f32>,    // x half width (m), y water depth (m), z lamp height over the water (m),
                        // w the screen's distance under the glass (m)
    screen: vec4<f32>,  // x the screen image's half extent (m on the screen), y magnification,
                        // z cells per side, w the image's scale (what one unit of light is stored as)
    view: vec4<f32>,    // x view (0 screen, 1 heights, 2 intensity), y amplitude (m), z exposure,
                        // w the screen image's texels per side
    lines: vec4<f32>,   // x how many slit lines, y the z (m) they start from
    line_angles: array<vec4<f32>, LINE_VECS>, // their directions (rad from +z towards +x), 4 a vector
    probe: vec4<f32>,   // x, z (m), z 1 if the probe is in, w its graph's half height (m)
    trace: vec4<f32>,   // x the ring's newest texel, y samples held, z texels, w s between samples
    graph: vec4<f32>,   // x the intensity line's z (m), y 1 if drawn, z its peak (m^2), w 1 if a ruler
    ruler: vec4<f32>,   // its start x, z and end x, z (m)
    apparatus_inverse_view_proj: mat4x4<f32>,
    halves: vec4<f32>,  // the apparatus's part of the target (uv: x from, y width), the screen view's (z, w)
    dippers: array<vec4<f32>, MAX_DIPPERS>, // each dipper's x, z, radius (m), w 1 if there
    bar: vec4<f32>,     // the bar's z, half thickness, half length (m), w 1 if there
};

@group(0) @binding(0) var<uniform> pic: Picture;
@group(0) @binding(1) var state: texture_2d<f32>;
@group(0) @binding(2) var medium: texture_2d<f32>;

fn cell_of(p: vec2<i32>) -> vec4<f32> {
    let n = i32(pic.screen.z);
    return textureLoad(state, clamp(p, vec2<i32>(0), vec2<i32>(n - 1)), 0);
}

fn is_wall(p: vec2<i32>) -> bool {
    let n = i32(pic.screen.z);
    return textureLoad(medium, clamp(p, vec2<i32>(0), vec2<i32>(n - 1)), 0).w == WALL;
}

// Where the lamp's ray through surface point `surface` (m) with unit normal `normal` meets the
// screen (x, z in m; w 0 where the light cannot get through): refracted into the water, down
// to the flat glass bottom, out into the air (the tangential part of the direction grows by
// the index) and on to the screen.
fn on_screen(surface: vec3<f32>, normal: vec3<f32>) -> vec3<f32> {
    let lamp = vec3<f32>(0.0, pic.tray.z, 0.0);
    let t = refract(normalize(surface - lamp), normal, 1.0 / IOR_WATER);
    if t.y >= 0.0 {
        return vec3<f32>(0.0);
    }
    let bottom = surface + t * ((-pic.tray.y - surface.y) / t.y);
    let across = t.xz * IOR_WATER;
    let s2 = dot(across, across);
    if s2 >= 1.0 {
        return vec3<f32>(0.0);
    }
    let a = vec3<f32>(across.x, -sqrt(1.0 - s2), across.y);
    let hit = bottom + a * (-pic.tray.w / a.y);
    return vec3<f32>(hit.x, hit.z, 1.0);
}
