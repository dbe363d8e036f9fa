// The scene's bindings and uniforms, shared by every scene pass, with the shading in the parts
// joined after it (render/shaders.rs): scene_surface (water sampling), scene_light (caustic
// light, pool tiles), glaze (the tiles' glaze above the water), scene_bodies (the sphere and the duck), scene_optics (sky, highlight,
// Fresnel, absorption) and scene_trace (rays through air or water, the displayed colour).
// Compiled per feature set: HAS_<BODY> per kind of body, HAS_CAUSTICS, FRESNEL_MODEL, SPECULAR_MODEL and
// SHOW_REFLECTANCE are constants written ahead of this file (render::Features::wgsl), so the code
// of what is not in the pool, or of a model not chosen, compiles away.

struct Scene {
    view_proj: mat4x4<f32>,
    inv_view_proj: mat4x4<f32>,
    eye: vec4<f32>,            // xyz camera position (m)
    sun: vec4<f32>,            // xyz unit vector towards the sun; w sun strength
    refracted_sun: vec4<f32>,  // xyz unit direction sunlight travels after a flat surface (downwards)
    pool: vec4<f32>,           // x half width W (m), y depth D (m), z rim height R above rest (m),
                               // w the tiles' gloss (glaze.wgsl)
    water: vec4<f32>,          // x grid cells per side N, y 1/N, z caustic contrast (a power), w light per unit
                               // stored in the caustics map (1 for float maps, more for 8-bit)
    output: vec4<f32>,         // x unused (the sRGB encoding is the constant ENCODE_SRGB);
                               // y debug view (0 none, see debug_view.wgsl), z the bodies'
                               // outlines and waterlines blended (0/1)
    optics: vec4<f32>,         // x highlight exponent s, y and z cosines of the sun disk's edge
                               // and core (optics::sun_disk_cosines)
    absorption: vec4<f32>,     // xyz Beer–Lambert absorption of the water per channel (1/m)
    scatter: vec4<f32>,        // xyz light the water scatters towards the eye (linear units)
    ior: vec4<f32>,            // xyz water's refractive index for red, green, blue light (with
                               // dispersion; green is IOR_WATER), w the dispersion factor
    ambient_header: vec4<f32>, // x waves in ambient_waves, y Gerstner's c = Q / sum(a k)
    // Per ambient wave (ambient.rs): kx, kz (rad/m), amplitude (m), phase at this frame's time.
    ambient_waves: array<vec4<f32>, MAX_AMBIENT_WAVES>,
    flat: vec4<f32>,           // flat water (flat.rs): x plane height (m), y largest texture shift
                               // (fraction of the screen), z dUdV scroll (tiles), w soft edge (m)
    sun_light: vec4<f32>,      // rgb the sun's light on a surface facing it (sky.rs, scene units);
                               // w exposure factor 2^EV before the tone curve
    sky_light: vec4<f32>,      // rgb the sky's light on a surface facing up (albedo factor);
                               // w 1 with the deck around the pool, 0 cut-away
    floor_bounce: vec4<f32>,   // rgb the calm floor's light times the tiles' mean albedo (scene units)
    horizon: array<vec4<f32>, HORIZON_TERMS>, // the sky at the horizon (deck.rs: horizon_fit)
    // Each kind of body's share (bodies::wgsl: <NAME>_SLOT on; see its body_<name>.wgsl).
    bodies: array<vec4<f32>, BODY_SLOTS>,
};

@group(0) @binding(0) var<uniform> scene: Scene;
// Simulation state per cell: (height m, vertical velocity m/s, normal.x, normal.z).
@group(0) @binding(1) var water_state: texture_2d<f32>;
// The FFT ocean's surface per texel (height m, dh/dx, dh/dz, dDx/dz), tiling the pool
// (AMBIENT_FFT), and with choppiness its displacement (Dx, Dz m, dDx/dx, dDz/dz) at rest points.
@group(0) @binding(2) var ambient_map: texture_2d<f32>;
@group(0) @binding(3) var ambient_displacement: texture_2d<f32>;

@group(1) @binding(0) var caustics_map: texture_2d<f32>;
@group(1) @binding(1) var tile_texture: texture_2d<f32>;
@group(1) @binding(2) var sky_cube: texture_cube<f32>;
@group(1) @binding(3) var clamp_sampler: sampler;
@group(1) @binding(4) var repeat_sampler: sampler;
// Exact Fresnel reflectance at FRESNEL_TABLE_SIZE angles 0-90°: row 0 from air, row 1 from water.
@group(1) @binding(5) var fresnel_table: texture_2d<f32>;
// Foam amount (0-1) per cell of the CPU field that integrates it (sim/foam.rs), when on.
@group(1) @binding(6) var foam_map: texture_2d<f32>;
// The ambient waves' spectrum for the debug view: log10 amplitude (m) per wavevector cell
// (ambient.rs spectrum_image).
@group(1) @binding(7) var ambient_spectrum: texture_2d<f32>;
// The flat water's dUdV map (flat.rs dudv_map): slopes dH/du, dH/dv in red and green (0.5 flat,
// 0 and 1 the largest, DUDV_SLOPE), tiling DUDV_TILES times across the pool.
@group(1) @binding(8) var dudv_map: texture_2d<f32>;

// How far the sun's highlight is spread for the pixel being shaded (1: not at all; see
// sun_specular); the water surface sets it from how much its normal varies within the pixel.
var<private> specular_spread: f32 = 1.0;
// Mip level of the caustics lookup (caustics_under) for the pixel being shaded: at least
// CAUSTICS_MIN_LOD, more where the pixel covers more of the floor (set by pool_colour_at_hit).
var<private> caustics_lod: f32 = CAUSTICS_MIN_LOD;
// Tile levels the water surface added for its normal's turning within the pixel (fs_surface):
// the tiles' grout needs them, the caustics map is read without them (pool_colour_at_hit).
var<private> tile_turning: f32 = 0.0;

// The sun's and the sky's light (sky.rs: Preetham's sky, the sun through the air).
fn sun_light() -> vec3<f32> { return scene.sun_light.rgb; }
fn sky_light() -> vec3<f32> { return scene.sky_light.rgb; }

// The sky's light on a point above or under the water's rest level: under it only what comes
// in through the opening above and the surface (UNDERWATER_SKY of it), so the sun's caustics
// stand out.
fn sky_light_at(under: bool) -> vec3<f32> {
    return sky_light() * select(1.0, UNDERWATER_SKY, under);
}

const FOAM_ALBEDO: vec3<f32> = vec3<f32>(0.9, 0.92, 0.93);

fn half_width() -> f32 { return scene.pool.x; }
fn depth() -> f32 { return scene.pool.y; }
fn rim() -> f32 { return scene.pool.z; }
