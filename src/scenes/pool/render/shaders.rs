//! The pool's WGSL (`shaders/pool/`): how the pool lights what is seen directly, and its
//! passes' files (the water surface, the pool's box, the deck, the caustics map, the sky, flat
//! water, the debug view), each added after [`scene_prelude`].

use crate::render::scene_parts::scene_prelude_in;
use crate::render::Features;

/// How the pool lights a surface drawn directly and what lies between it and the eye (what
/// the bodies' meshes ask of the scene they are in).
pub const POOL_SEEN: &str = crate::wgsl!("pool/scene_seen.wgsl");
pub const SKY: &str = crate::wgsl!("pool/sky.wgsl");
pub const POOL: &str = crate::wgsl!("pool/pool.wgsl");
/// The deck around the pool (after [`POOL`], whose types it shares).
pub const DECK: &str = crate::wgsl!("pool/deck.wgsl");
pub const WATER: &str = crate::wgsl!("pool/water.wgsl");
pub const CAUSTICS: &str = crate::wgsl!("pool/caustics.wgsl");
pub const FLAT_WATER: &str = crate::wgsl!("pool/flat_water.wgsl");
pub const DEBUG_VIEW: &str = crate::wgsl!("pool/debug_view.wgsl");

/// Everything a pool pass of `features` starts from: the shared scene's WGSL
/// (`render::shaders::scene_prelude_in`) with the pool's [`POOL_SEEN`]. `target`: the format
/// the scene is finally drawn in.
pub fn scene_prelude(features: Features, target: wgpu::TextureFormat) -> String {
    scene_prelude_in(features, target, POOL_SEEN)
}
