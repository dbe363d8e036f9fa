//! What a frame's picture depends on besides the water state: the camera, the sun, the
//! objects' poses, the optics and ambient waves as the shaders take them.

use glam::{Mat4, Vec3};

use super::flat::FlatView;
use super::RenderMode;
use super::{DebugView, Features};
use crate::ambient::{AmbientModel, MAX_AMBIENT_WAVES};
use crate::bodies::{BodyId, BodyView, KINDS};
use crate::optics::{FresnelModel, SpecularModel};

/// Everything a frame's picture depends on besides the water state.
#[derive(Clone, Copy, Debug)]
pub struct View {
    pub view_proj: Mat4,
    /// Eye position (m).
    pub eye: Vec3,
    /// Unit vector towards the sun.
    pub sun: Vec3,
    /// Each kind's body (in the order of `bodies::KINDS`) as drawn, if it is in the pool.
    pub bodies: [Option<BodyView>; KINDS.len()],
    pub caustics: bool,
    /// The power the caustics map's light is raised to where it lights the scene
    /// (`caustic_contrast`: 1 the map's own light).
    pub caustic_contrast: f32,
    /// The optical models and their parameters (optics.rs).
    pub optics: Optics,
    /// The ambient waves to add to the simulated surface, at this frame's simulated time.
    pub ambient: AmbientView,
    /// Foam is drawn on the surface (from the map [`Renderer::upload_foam`] filled).
    pub foam: bool,
    /// A view of the simulation's textures drawn over the scene, if any.
    pub debug: Option<DebugView>,
    /// Fraction of the target's width and height the scene is drawn at (0.5-1; below 1 it
    /// is scaled up to the target).
    pub render_scale: f32,
    /// Flat water instead of (or beside) the ray-traced surface; `None`: ray-traced.
    pub flat: Option<FlatView>,
    /// Photographic exposure before the tone curve (EV: +1 doubles the light), on top of the
    /// sky's own ([`crate::sky::Daylight::adapted_exposure`]).
    pub exposure: f32,
    /// The pool is sunk in a paved deck (else the classic's cut-away box in the open).
    pub deck: bool,
    /// How much the tiles' glaze mirrors (0 matte, 1 a ceramic glaze: `glaze.rs`).
    pub tile_gloss: f32,
}

/// The ambient waves as the shader takes them (see ambient.rs).
#[derive(Clone, Copy, Debug, Default)]
pub struct AmbientView {
    pub model: AmbientModel,
    /// Per wave (kx, kz in rad/m, amplitude in m, phase now).
    pub waves: [[f32; 4]; MAX_AMBIENT_WAVES],
    /// (waves, Gerstner's c, the FFT's choppiness, 0); see `AmbientWaves::uniform`.
    pub header: [f32; 4],
}

impl AmbientView {
    /// Whether the FFT ocean carries its water sideways (reads the displacement map).
    pub fn choppy(&self) -> bool {
        self.model == AmbientModel::Fft && self.header[2] > 0.0
    }
}

/// How the water surface reflects (see optics.rs).
#[derive(Clone, Copy, Debug, Default)]
pub struct Optics {
    pub fresnel: FresnelModel,
    pub specular: SpecularModel,
    /// Exponent of the sun highlight's cos^s.
    pub shininess: f32,
    /// Angular diameter of the sun's disk (degrees).
    pub sun_size: f32,
    /// The surface shows its Fresnel reflectance as grey instead of its colour (a debug view).
    pub show_reflectance: bool,
    /// Beer–Lambert absorption of the water per channel (1/m).
    pub absorption: Vec3,
    /// Light the water scatters towards the eye per channel (linear units); zero: none.
    pub scatter: Vec3,
    /// The scattered light is tinted by the path's angle (seed 002).
    pub view_colour: bool,
    /// Times the real spread of water's refractive index across colours (0: one index).
    pub dispersion: f32,
}

/// The flat water settings if flat water is drawn this frame: flat or split mode with the
/// camera above the plane (flat water is an above-water technique; under it the ray tracer
/// draws everything).
pub fn flat_shown(view: &View) -> Option<FlatView> {
    view.flat.filter(|f| f.mode != RenderMode::RayTraced && view.eye.y > f.plane)
}

impl View {
    /// The feature set this view costs, the key of its shader variant.
    pub fn features(&self) -> Features {
        let view = self;
        Features {
            bodies: BodyId::all().filter(|id| view.bodies[id.0].is_some()).map(|id| id.bit() as u8).sum(),
            caustics: view.caustics,
            fresnel: view.optics.fresnel,
            specular: view.optics.specular,
            show_reflectance: view.optics.show_reflectance,
            scattering: view.optics.scatter.max_element() > 0.0,
            view_colour: view.optics.view_colour && view.optics.scatter.max_element() > 0.0,
            dispersion: view.optics.dispersion > 0.0,
            ambient: view.ambient.model,
            choppy: view.ambient.choppy(),
            foam: view.foam,
            deck: view.deck,
            glaze: view.tile_gloss > 0.0,
            ..Features::default()
        }
    }
}
