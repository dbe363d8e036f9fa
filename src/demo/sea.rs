//! The demo in the open sea (`scene` = sea): its own camera, kept beside the pool's while the
//! other scene is shown, and its frame: the cascades summed on the CPU at the simulated time,
//! drawn by the renderer's sea pass. The pool's water and bodies wait, as they were.

use super::{Stage, WaterDemo};
use crate::ambient::cascades::SeaWaves;
use crate::params::ParamId;
use crate::render::{AmbientView, SeaView, View, SEA_CASCADES};
use crate::sea::{SceneKind, SeaSettings, EYE_OVER_CRESTS, SEA_LATTICE};

/// The sea's waves and the settings they were made for.
pub(super) struct Sea {
    settings: SeaSettings,
    waves: SeaWaves,
}

impl WaterDemo {
    /// The scene the `scene` parameter asks for.
    pub fn scene(&self) -> SceneKind {
        SceneKind::from_param(self.params.get(ParamId::Scene))
    }

    /// The scene the last frame drew (its camera is [`WaterDemo::camera`]).
    pub fn drawn_scene(&self) -> SceneKind {
        self.camera_scene
    }

    /// Brings the camera to the scene the parameters ask for: each scene keeps its own, with
    /// its own limits. Call before moving the camera after a change of `scene`.
    pub fn sync_scene(&mut self) {
        let wanted = self.scene();
        if wanted != self.camera_scene {
            std::mem::swap(&mut self.camera, &mut self.other_camera);
            self.camera_scene = wanted;
        }
        if wanted == SceneKind::Sea {
            let crest = self.sea_settings().crest_bound();
            self.camera.keep_eye_above(crest + EYE_OVER_CRESTS);
        }
    }

    fn sea_settings(&self) -> SeaSettings {
        SeaSettings::from_values(|name| self.params.get_by_name(name).expect("a sea parameter"))
    }

    /// The sea's waves for the current parameters, made again when they changed.
    fn sea_waves(&mut self) -> &SeaWaves {
        let settings = self.sea_settings();
        if self.sea.as_ref().is_none_or(|s| s.settings != settings) {
            let waves = SeaWaves::new(&settings.waves(), SEA_LATTICE);
            self.sea = Some(Sea { settings, waves });
        }
        &self.sea.as_ref().expect("made above").waves
    }

    /// What the sea's frame shows of the scene: the sea camera, the sun and optics; no
    /// bodies, caustics, ambient waves, foam, flat water or deck (the pool's).
    fn sea_scene_view(&self) -> View {
        let pool = self.view();
        View {
            bodies: [None; crate::bodies::KINDS.len()],
            caustics: false,
            ambient: AmbientView::default(),
            foam: false,
            debug: None,
            render_scale: 1.0,
            flat: None,
            deck: false,
            ..pool
        }
    }

    /// [`WaterDemo::encode_frame`] in the sea: time runs on (the waves are the simulated
    /// time's), no simulation step is taken.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn encode_sea_frame(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        size: (u32, u32),
        frame_time: f32,
        mark: &mut dyn FnMut(&mut wgpu::CommandEncoder, Stage),
    ) {
        self.take_steps(frame_time);
        let mut sim_encoder = device.create_command_encoder(&Default::default());
        mark(&mut sim_encoder, Stage::Start);
        mark(&mut sim_encoder, Stage::AfterSimulation);
        queue.submit([sim_encoder.finish()]);
        let t = self.sim_time();
        let settings = self.sea_settings();
        let waves = self.sea_waves();
        let [surface, displacement] = waves.atlas(t);
        let variances = SeaWaves::slope_variances(&surface, waves.cascades.len());
        let mut cascades = [(0.0, 1.0, 0.0); SEA_CASCADES];
        for (i, c) in waves.cascades.iter().enumerate().take(SEA_CASCADES) {
            cascades[i] = (c.angle, 2.0 * c.ocean.band.half_tile, variances[i]);
        }
        let view = self.sea_scene_view();
        self.renderer.prepare(queue, encoder, &view, &self.water);
        mark(encoder, Stage::AfterCaustics);
        let sea = SeaView {
            camera: &self.camera,
            fog_distance: settings.fog_distance,
            choppiness: settings.choppiness,
            crest: settings.crest_bound(),
            cascades,
            surface: &surface,
            displacement: &displacement,
        };
        self.renderer.encode_sea(device, queue, encoder, target, size, &view, &sea);
        mark(encoder, Stage::AfterScene);
    }
}
