//! The feature set of a shader variant: what a frame shows that costs shader work, written
//! into the shaders as constants (see `variants.rs` for why constants, not uniforms).

use super::render_mode::Distortion;
use crate::ambient::AmbientModel;
use crate::optics::{FresnelModel, SpecularModel};

/// What a frame shows that costs shader work: the shader constants of a variant.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Features {
    /// The kinds of body in the pool, bit `i` for `bodies::KINDS[i]` (traced in reflections
    /// and refractions, casting shadows, drawn).
    pub bodies: u8,
    /// Light under water comes from the caustics map (else from a calm surface).
    pub caustics: bool,
    /// The Fresnel reflectance model of the water surface.
    pub fresnel: FresnelModel,
    /// The shape of the sun's highlight on the water.
    pub specular: SpecularModel,
    /// The surface shows its reflectance as grey (the `reflectance` debug view).
    pub show_reflectance: bool,
    /// The water scatters light towards the eye (in-scattering).
    pub scattering: bool,
    /// ... tinted by the path's angle.
    pub view_colour: bool,
    /// Red, green and blue light refract by their own indices (the `dispersion` parameter).
    pub dispersion: bool,
    /// The ambient waves added to the simulated surface.
    pub ambient: AmbientModel,
    /// The FFT ocean carries its water sideways (choppiness above 0).
    pub choppy: bool,
    /// Foam on the surface.
    pub foam: bool,
    /// Drawing a flat-water texture: +1 keeps only what is above the water plane (the
    /// reflection, drawn by the mirrored camera), -1 only what is below it (the refraction);
    /// 0 everything (every other pass).
    pub clip: i8,
    /// Under flat water the pool is lit by seed 000's fake caustics (the refraction texture).
    pub flat_caustics: bool,
    /// What the flat water's normal comes from (its plane and its fake caustics).
    pub flat_distortion: Distortion,
    /// The pool is sunk in the paved deck: what is seen through the opening blends the
    /// coping in along its edge.
    pub deck: bool,
    /// The tiles are glazed (glaze.rs): they mirror the sun and the sky a little. Only the
    /// pool's pass reads it, but like every flag it keys all the scene's pipelines: turning
    /// `tile_gloss` on or off builds the variant's pipelines once.
    pub glaze: bool,
}

impl Features {
    /// The WGSL constants that select this variant (`HAS_CAUSTICS`,
    /// `FRESNEL_MODEL`, `SPECULAR_MODEL`, `SHOW_REFLECTANCE`, `HAS_SCATTERING`, `VIEW_COLOUR`,
    /// `HAS_DISPERSION`, `AMBIENT_MODEL`, `AMBIENT_CHOPPY`, `HAS_FOAM`, `HAS_DECK`, `CLIP_SIDE`,
    /// `FLAT_CAUSTICS`, `FLAT_DISTORTION`, `HAS_GLAZE`; the bodies' `HAS_<BODY>` are in `bodies::wgsl`).
    pub fn wgsl(&self) -> String {
        let flat = format!(
            "const CLIP_SIDE: i32 = {};\nconst FLAT_CAUSTICS: bool = {};\nconst FLAT_DISTORTION: u32 = {}u;\n",
            self.clip, self.flat_caustics, self.flat_distortion as u32
        );
        flat + &format!(
            "const HAS_CAUSTICS: bool = {};\n\
             const FRESNEL_MODEL: u32 = {}u;\nconst SPECULAR_MODEL: u32 = {}u;\nconst SHOW_REFLECTANCE: bool = {};\n\
             const HAS_SCATTERING: bool = {};\nconst VIEW_COLOUR: bool = {};\nconst HAS_DISPERSION: bool = {};\n\
             const AMBIENT_MODEL: u32 = {}u;\nconst AMBIENT_CHOPPY: bool = {};\nconst HAS_FOAM: bool = {};\n\
             const HAS_DECK: bool = {};\nconst HAS_GLAZE: bool = {};\n",
            self.caustics,
            self.fresnel as u32,
            self.specular as u32,
            self.show_reflectance,
            self.scattering,
            self.view_colour,
            self.dispersion,
            self.ambient as u32,
            self.choppy,
            self.foam,
            self.deck,
            self.glaze
        )
    }
}

impl Features {
    /// The same without the objects.
    pub fn without_objects(self) -> Self {
        Self { bodies: 0, ..self }
    }
}
