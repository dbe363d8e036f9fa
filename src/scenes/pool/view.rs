//! From the parameters to what the renderer draws of the pool: the [`View`] of a frame, the
//! ambient waves, the flat water's settings.

use super::PoolScene;
use crate::ambient::{AmbientSettings, AmbientWaves};
use crate::params::{ParamId, Params};
use crate::render::flat::FlatView;
use crate::render::RenderMode;
use crate::render::{AmbientView, DebugChoice, DebugView, View};
use crate::scenes::{common_view, Shared};
use crate::sim;

impl PoolScene {
    /// Remakes the ambient waves if their parameters changed.
    pub(super) fn refresh_ambient(&mut self, p: &Params) {
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
            basin: self.shape,
        };
        if settings != self.ambient_settings {
            self.ambient = AmbientWaves::new(&settings);
            self.ambient_settings = settings;
            self.spectrum_shown = false;
        }
    }

    /// The pool's picture of this frame.
    pub(super) fn view(&self, sh: Shared<'_>) -> View {
        let p = sh.params;
        View {
            bodies: self.drawn_bodies(sh),
            caustics: p.flag(ParamId::Caustics),
            caustic_contrast: p.get(ParamId::CausticContrast),
            ambient: {
                let (waves, header) = self.ambient.uniform(sh.sim_time());
                AmbientView { model: self.ambient.model, waves, header }
            },
            foam: self.water.foam().is_some(),
            debug: (p.choice::<DebugChoice>(ParamId::DebugView).texture())
                .map(|texture| DebugView { texture, inset: p.flag(ParamId::DebugInset) }),
            flat: self.flat_view(sh),
            deck: Self::on_deck(p),
            ..common_view(sh, &self.camera)
        }
    }

    /// The flat water settings in the parameters (`None` when ray-traced).
    pub(super) fn flat_view(&self, sh: Shared<'_>) -> Option<FlatView> {
        let p = sh.params;
        let mode = p.choice::<RenderMode>(ParamId::RenderMode);
        let scroll = p.get(ParamId::DudvSpeed) as f64 * sh.sim_time();
        (mode != RenderMode::RayTraced).then(|| FlatView {
            mode,
            split: p.get(ParamId::Split),
            distortion: p.choice(ParamId::FlatDistortion),
            strength: p.get(ParamId::FlatStrength),
            move_factor: (scroll - scroll.floor()) as f32,
            resolution: p.get(ParamId::FlatResolution),
            caustics: p.choice(ParamId::FlatCaustics),
            soft_edge: p.get(ParamId::FlatSoftEdge),
            plane: self.submerged_volume(p) / sim::pool_area(self.shape.half_width),
        })
    }

    /// Whether the flat water is drawn now: flat or split chosen and the camera above the
    /// water (it is an above-water technique; under water the ray tracer draws).
    pub fn flat_water_drawn(&self, sh: Shared<'_>) -> bool {
        crate::render::flat_shown(&self.view(sh)).is_some()
    }

    /// Why the chosen flat water is not drawn, if it is not (for the page and the viewer): the
    /// id of its message (`page_words`, the catalogues).
    pub fn flat_water_note(&self, sh: Shared<'_>) -> Option<&'static str> {
        let mode = sh.params.choice::<RenderMode>(ParamId::RenderMode);
        (mode != RenderMode::RayTraced && !self.flat_water_drawn(sh)).then_some("note-flat-under-water")
    }
}
