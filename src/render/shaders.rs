//! The scene's shared WGSL: the parts every scene's shading is built from (maths, rays, the
//! scene's bindings, light, optics, bodies), and the constants they read from Rust, so the two
//! cannot disagree. A scene adds how it lights what is seen directly and its own passes.

use super::features::Features;
use crate::gpu;

pub const COMMON: &str = crate::wgsl!("common.wgsl");
/// The scene's shared shading, in parts of one concept each (see `shaders/scene.wgsl`).
pub const SCENE: [&str; 8] = [
    crate::wgsl!("scene.wgsl"),
    crate::wgsl!("scene_surface.wgsl"),
    crate::wgsl!("scene_light.wgsl"),
    crate::wgsl!("glaze.wgsl"),
    crate::wgsl!("scene_bodies.wgsl"),
    crate::wgsl!("scene_optics.wgsl"),
    crate::wgsl!("scene_trace.wgsl"),
    crate::wgsl!("deck_shade.wgsl"),
];

/// Everything a scene pass of `features` starts from: the variant's constants, the numbers of
/// the features the scene shows (water's refractive index, optics, ambient waves, flat water,
/// sky, deck, tiles' glaze, caustics mips), the shared WGSL (maths, ray helpers, the scene's
/// bindings and shading) and the bodies' (their kinds' code, and the code asking the kinds
/// present). `seen` says how the scene lights a surface drawn directly and what lies between
/// it and the eye (`object_colour`, `lit_under`, `seen_directly`: the pool's
/// `shaders/pool/scene_seen.wgsl`, the sea's own). The pass adds its own file after it.
/// `target`: the format the scene is finally drawn in; without hardware sRGB encoding the
/// shaders encode (ENCODE_SRGB, a constant: software rasterisers run both sides of a branch).
pub fn scene_prelude_in(features: Features, target: wgpu::TextureFormat, seen: &str) -> String {
    let numbers = format!(
        "const IOR_WATER: f32 = {:?};\nconst ENCODE_SRGB: bool = {};\n",
        crate::world::IOR_WATER,
        !target.is_srgb()
    ) + &crate::optics::water_surface_wgsl();
    [
        features.wgsl(),
        numbers,
        super::scene_constants().join("\n"),
        gpu::wgsl::MATH.to_owned(),
        COMMON.to_owned(),
        SCENE.join("\n"),
        seen.to_owned(),
        crate::bodies::wgsl(features.bodies as u32),
    ]
    .join("\n")
}
