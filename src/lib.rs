//! wavepool: an interactive water pool. A heightfield wave simulation on the GPU, a
//! ray-traced pool with caustics, an orbit camera, and a platform-free core that the
//! browser and native shells drive.

/// A shader's WGSL as the binary holds it: `shaders/<name>` without its comments (build.rs).
#[macro_export]
macro_rules! wgsl {
    ($name:literal) => {
        include_str!(concat!(env!("OUT_DIR"), "/", $name))
    };
}

pub mod ambient;
pub mod bodies;
pub mod camera;
pub mod demo;
pub mod gpu;
#[cfg(not(target_arch = "wasm32"))]
pub mod headless;
pub mod optics;
pub mod page_words;
pub mod param_spec;
pub mod params;
pub mod physics;
pub mod presets;
pub mod quality;
pub mod render;
pub mod scenes;
pub mod sea;
pub mod sim;
pub mod sky;
pub mod tank;
pub mod textures;
pub mod timing;
pub mod util;
#[cfg(target_arch = "wasm32")]
pub mod web;
pub mod world;

pub use demo::{DemoOptions, Key, WaterDemo};
