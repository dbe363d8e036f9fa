//! From the parameters to what the renderer draws: the [`View`] of a frame, the ambient
//! waves, the render scale, the flat water's settings.

use glam::Vec3;

use super::WaterDemo;
use crate::ambient::{AmbientSettings, AmbientWaves};

use crate::params::ParamId;
use crate::render::flat::FlatView;
use crate::render::RenderMode;
use crate::render::{AmbientView, DebugChoice, DebugView, Optics, Setting, View};
use crate::scene;
use crate::sim;

impl WaterDemo {
    /// Remakes the ambient waves if their parameters changed.
    pub(super) fn refresh_ambient(&mut self) {
        let p = &self.params;
        let settings = AmbientSettings {
            model: p.choice(ParamId::Ambient),
            wind_speed: p.get(ParamId::WindSpeed),
            wind_direction_deg: p.get(ParamId::WindDirection),
            significant_height: p.get(ParamId::WaveHeight),
            spread_deg: p.get(ParamId::WaveSpread),
            steepness: p.get(ParamId::Steepness),
            spectrum: p.choice(ParamId::Spectrum),
            fft_size: p.get(ParamId::FftSize) as usize,
            choppiness: p.get(ParamId::Choppiness),
        };
        if settings != self.ambient_settings {
            self.ambient = AmbientWaves::new(&settings);
            self.ambient_settings = settings;
            self.spectrum_shown = false;
        }
    }

    /// Fraction of the target's width and height the scene was last drawn at (see the
    /// `quality` parameter).
    pub fn render_scale(&self) -> f32 {
        self.render_scale
    }

    /// The render scale for this frame: the `quality` parameter's, or with `quality` auto,
    /// the governor's after it has seen `frame_time` (s, the time since the last frame).
    pub(super) fn choose_render_scale(&mut self, frame_time: f32) {
        let quality = self.params.get(ParamId::Quality);
        self.render_scale = if quality > 0.0 {
            quality
        } else {
            self.governor.observe(frame_time, self.params.get(ParamId::FrameBudget) / 1000.0);
            self.governor.scale()
        };
    }

    pub(super) fn view(&self) -> View {
        View {
            view_proj: self.camera.view_projection(self.viewport.x / self.viewport.y),
            eye: self.camera.eye(),
            sun: self.sun(),
            bodies: self.drawn_bodies(),
            caustics: self.params.flag(ParamId::Caustics),
            optics: Optics {
                fresnel: self.params.choice(ParamId::Fresnel),
                specular: self.params.choice(ParamId::Specular),
                shininess: self.params.get(ParamId::Shininess),
                sun_size: self.params.get(ParamId::SunSize),
                show_reflectance: self.params.choice::<DebugChoice>(ParamId::DebugView) == DebugChoice::Reflectance,
                absorption: Vec3::new(
                    self.params.get(ParamId::AbsorptionRed),
                    self.params.get(ParamId::AbsorptionGreen),
                    self.params.get(ParamId::AbsorptionBlue),
                ),
                scatter: Vec3::new(
                    self.params.get(ParamId::ScatterRed),
                    self.params.get(ParamId::ScatterGreen),
                    self.params.get(ParamId::ScatterBlue),
                ),
                view_colour: self.params.flag(ParamId::ViewColour),
                dispersion: self.params.get(ParamId::Dispersion),
            },
            ambient: {
                let (waves, header) = self.ambient.uniform(self.sim_time());
                AmbientView { model: self.ambient.model, waves, header }
            },
            foam: self.water.foam().is_some(),
            debug: (self.params.choice::<DebugChoice>(ParamId::DebugView).texture())
                .map(|texture| DebugView { texture, inset: self.params.flag(ParamId::DebugInset) }),
            render_scale: self.render_scale,
            flat: self.flat_view(),
            exposure: self.params.get(ParamId::Exposure),
            deck: self.on_deck(),
            tile_gloss: self.params.get(ParamId::TileGloss),
        }
    }

    /// Whether the pool is sunk in the deck (`setting` deck) rather than the cut-away box.
    pub(super) fn on_deck(&self) -> bool {
        self.params.choice::<Setting>(ParamId::Setting) == Setting::Deck
    }

    /// The flat water settings in the parameters (`None` when ray-traced).
    pub(super) fn flat_view(&self) -> Option<FlatView> {
        let mode = self.params.choice::<RenderMode>(ParamId::RenderMode);
        let scroll = self.params.get(ParamId::DudvSpeed) as f64 * self.sim_time();
        (mode != RenderMode::RayTraced).then(|| FlatView {
            mode,
            split: self.params.get(ParamId::Split),
            distortion: self.params.choice(ParamId::FlatDistortion),
            strength: self.params.get(ParamId::FlatStrength),
            move_factor: (scroll - scroll.floor()) as f32,
            resolution: self.params.get(ParamId::FlatResolution),
            caustics: self.params.choice(ParamId::FlatCaustics),
            soft_edge: self.params.get(ParamId::FlatSoftEdge),
            plane: self.submerged_volume() / sim::pool_area(scene::HALF_WIDTH),
        })
    }

    /// The flat water's reflection texture, once flat water has been drawn (for tests).
    #[doc(hidden)]
    pub fn flat_reflection_texture(&self) -> Option<&wgpu::Texture> {
        self.renderer.flat_reflection_texture()
    }

    /// Whether the flat water is drawn now: flat or split chosen and the camera above the
    /// water (it is an above-water technique; under water the ray tracer draws).
    pub fn flat_water_drawn(&self) -> bool {
        crate::render::flat_shown(&self.view()).is_some()
    }

    /// Why the chosen flat water is not drawn, if it is not (for the page and the viewer).
    pub fn flat_water_note(&self) -> Option<&'static str> {
        let mode = self.params.choice::<RenderMode>(ParamId::RenderMode);
        (mode != RenderMode::RayTraced && !self.flat_water_drawn())
            .then_some("Flat water is an above-water technique: under the water the ray tracer draws.")
    }
}
