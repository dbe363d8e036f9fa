//! The scene's WGSL: the parts every scene pass (water, pool, deck, bodies, caustics, sky,
//! flat water, debug view) is built from, and the constants they read from Rust, so the two
//! cannot disagree.

use super::variants::Features;
use crate::gpu;

pub const COMMON: &str = include_str!("../../shaders/common.wgsl");
/// The scene's shared shading, in parts of one concept each (see `shaders/scene.wgsl`).
pub const SCENE: [&str; 7] = [
    include_str!("../../shaders/scene.wgsl"),
    include_str!("../../shaders/scene_surface.wgsl"),
    include_str!("../../shaders/scene_light.wgsl"),
    include_str!("../../shaders/scene_bodies.wgsl"),
    include_str!("../../shaders/scene_optics.wgsl"),
    include_str!("../../shaders/scene_trace.wgsl"),
    include_str!("../../shaders/deck_shade.wgsl"),
];
pub const SKY: &str = include_str!("../../shaders/sky.wgsl");
pub const POOL: &str = include_str!("../../shaders/pool.wgsl");
pub const WATER: &str = include_str!("../../shaders/water.wgsl");
pub const CAUSTICS: &str = include_str!("../../shaders/caustics.wgsl");
pub const DEBUG_VIEW: &str = include_str!("../../shaders/debug_view.wgsl");

/// Everything a scene pass of `features` starts from: the variant's constants, the numbers of
/// the features the scene shows (water's refractive index, optics, ambient waves, flat water,
/// sky, deck, caustics mips), the shared WGSL (maths, ray helpers, the scene's bindings and
/// shading) and the bodies' (their kinds' code, and the code asking the kinds present). The pass adds its own file after it.
/// `target`: the format the scene is finally drawn in; without hardware sRGB encoding the
/// shaders encode (ENCODE_SRGB, a constant: software rasterisers run both sides of a branch).
pub fn scene_prelude(features: Features, target: wgpu::TextureFormat) -> String {
    let numbers = format!(
        "const IOR_WATER: f32 = {:?};\nconst ENCODE_SRGB: bool = {};\n",
        crate::scene::IOR_WATER,
        !target.is_srgb()
    );
    [
        features.wgsl(),
        numbers,
        crate::optics::wgsl_constants(),
        crate::ambient::wgsl_constants(),
        super::flat::wgsl_constants(),
        crate::sky::Daylight::wgsl_constants(),
        super::deck::wgsl_constants(),
        super::caustics_mips::CausticsMips::wgsl_constants(),
        gpu::wgsl::MATH.to_owned(),
        COMMON.to_owned(),
        SCENE.join("\n"),
        crate::bodies::wgsl(features.bodies as u32),
    ]
    .join("\n")
}
