// The white paper under the tank and the bench round it, as the screen view and the apparatus
// both show them: the paper lit by the screen pass's image of the lamp's light.

@group(1) @binding(0) var screen_image: texture_2d<f32>;
@group(1) @binding(1) var screen_sampler: sampler;

const BENCH: vec3<f32> = vec3<f32>(0.05, 0.045, 0.04);
const PAPER: vec3<f32> = vec3<f32>(0.95, 0.92, 0.85);
const ROOM_LIGHT: f32 = 0.12;

// The paper at texel coordinates `uv` of the screen's image: white, as bright as the lamp's
// light there (exposed as a photograph would be); in the tray frame's shadow the room lights
// it a little.
fn paper_at(uv: vec2<f32>) -> vec3<f32> {
    let light = textureSampleLevel(screen_image, screen_sampler, uv, 0.0).x / pic.screen.w;
    return PAPER * (1.0 - exp(-pic.view.z * light) + ROOM_LIGHT);
}
