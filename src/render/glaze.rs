//! The tiles' glaze: a clear coat over each tile (not over the grout) that mirrors a little of
//! the light, by Fresnel's law for the coat against air (`shaders/glaze.wgsl`): the sky, and
//! the sun as a soft highlight, on tile faces that round off at their edges. The tile
//! texture's alpha is where the glaze is (`textures::tile_mips`), so far away, where a texel
//! spans tiles and grout, its mip levels average the gloss as they average the colour.

use crate::param_spec::{Control, ParamSpec};

/// Refractive index of a ceramic glaze (a glass): it mirrors 4.3 % of the light at normal
/// incidence in air, 0.45 % under water.
pub const GLAZE_IOR: f32 = 1.52;
/// Exponent of the glaze's highlight lobe (Blinn–Phong on the half vector): a coat a little
/// rough, its highlight about 15° across.
pub const GLAZE_SHININESS: f32 = 60.0;
/// Share of each half tile, from its edge, over which the face rounds off.
pub const GLAZE_ROUNDING: f32 = 0.3;
/// Slope of the face at the tile's very edge (1: 45°).
pub const GLAZE_EDGE_SLOPE: f32 = 1.2;

/// The glaze's numbers for the scene's WGSL, and the tiles' (their size, their coves).
pub fn wgsl_constants() -> String {
    format!(
        "const GLAZE_IOR: f32 = {GLAZE_IOR:?};\nconst GLAZE_SHININESS: f32 = {GLAZE_SHININESS:?};\n\
         const GLAZE_ROUNDING: f32 = {GLAZE_ROUNDING:?};\nconst GLAZE_EDGE_SLOPE: f32 = {GLAZE_EDGE_SLOPE:?};\n\
         const TILES_PER_METRE: f32 = {:?};\nconst POOL_COVE_RADIUS: f32 = {:?};\n",
        crate::textures::TILES_PER_METRE as f32,
        crate::textures::POOL_COVE_RADIUS
    )
}

/// How glossy the tiles are. (The parameter table, `params::table`, lists them in this order.)
pub const PARAMS: &[ParamSpec] = &[ParamSpec {
    name: "tile_gloss",
    label: "Tile gloss",
    group: "Light",
    unit: "",
    control: Control::Slider { min: 0.0, max: 1.0, step: 0.05 },
    default: 1.0,
    help: "How much the tiles' glaze mirrors: 1 a ceramic glaze (the sky and the sun's highlight on the tiles above the water, most at their rounded edges), 0 matte tiles.",
}];
