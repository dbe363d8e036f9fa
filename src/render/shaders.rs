//! The scene's WGSL: the parts every scene pass (water, pool, deck, bodies, caustics, sky,
//! flat water, debug view) is built from, and the constants they read from Rust, so the two
//! cannot disagree.

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
/// How the pool lights a surface drawn directly and what lies between it and the eye (what
/// the bodies' meshes ask of the scene they are in).
pub const POOL_SEEN: &str = crate::wgsl!("scene_seen.wgsl");
pub const SKY: &str = crate::wgsl!("sky.wgsl");
pub const POOL: &str = crate::wgsl!("pool.wgsl");
pub const WATER: &str = crate::wgsl!("water.wgsl");
pub const CAUSTICS: &str = crate::wgsl!("caustics.wgsl");
pub const DEBUG_VIEW: &str = crate::wgsl!("debug_view.wgsl");

/// Everything a scene pass of `features` starts from: the variant's constants, the numbers of
/// the features the scene shows (water's refractive index, optics, ambient waves, flat water,
/// sky, deck, tiles' glaze, caustics mips), the shared WGSL (maths, ray helpers, the scene's bindings and
/// shading) and the bodies' (their kinds' code, and the code asking the kinds present). The pass adds its own file after it.
/// `target`: the format the scene is finally drawn in; without hardware sRGB encoding the
/// shaders encode (ENCODE_SRGB, a constant: software rasterisers run both sides of a branch).
pub fn scene_prelude(features: Features, target: wgpu::TextureFormat) -> String {
    scene_prelude_in(features, target, POOL_SEEN)
}

/// [`scene_prelude`] for a scene of its own (the open sea): `seen` says how that scene lights
/// a surface drawn directly and what lies between it and the eye, in place of the pool's
/// [`POOL_SEEN`] (`object_colour`, `lit_under`, `seen_directly`).
pub fn scene_prelude_in(features: Features, target: wgpu::TextureFormat, seen: &str) -> String {
    let numbers = format!(
        "const IOR_WATER: f32 = {:?};\nconst ENCODE_SRGB: bool = {};\n",
        crate::world::IOR_WATER,
        !target.is_srgb()
    );
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
