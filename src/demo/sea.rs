//! The demo in the open sea (`scene` = sea): its own camera, kept beside the pool's while the
//! other scene is shown, and its frame: the patch of simulated water round the camera's target
//! stepped (the clicks' ripples), the cascades' FFT at the simulated time (on the GPU where it
//! renders into float textures, else on the CPU), both drawn by the renderer's sea pass; the
//! bodies ride the waves summed at their probes on the CPU. The pool's water and bodies wait,
//! as they were.

use super::{FrameContext, Stage, WaterDemo, STEP_DT};
use crate::ambient::cascades::{SeaNow, SeaWaves};
use crate::params::{ParamId, Params};
use crate::render::{AmbientView, SeaLattices, SeaView, View, SEA_CASCADES};
use crate::sea::{self, island, IslandChoice, SceneKind, SeaSettings, EYE_OVER_CRESTS, SEA_LATTICE};
use crate::sim::{Drop, HeightField, WaveSettings};

/// The sea's settings in `params`.
pub fn sea_settings(params: &Params) -> SeaSettings {
    SeaSettings {
        wind_speed: params.get(ParamId::SeaWind),
        wind_direction: params.get(ParamId::SeaWindDirection),
        wave_height: params.get(ParamId::SeaWaveHeight),
        choppiness: params.get(ParamId::SeaChoppiness),
        fog_distance: params.flag(ParamId::SeaFog).then(|| params.get(ParamId::SeaFogDistance)),
        island: params.choice::<IslandChoice>(ParamId::SeaIsland).place(),
        grid_lines: params.flag(ParamId::SeaGrid),
    }
}

/// What the sea draws beyond its waves: all of it by default, some left out by tests to
/// compare with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct SeaExtras {
    /// Whitecaps where the waves break.
    pub whitecaps: bool,
    /// The whitecaps kept over time (else the map holds only each frame's own).
    pub kept_whitecaps: bool,
    /// Foam along the island's shore.
    pub shore_foam: bool,
    /// The floating bodies mirrored in the water.
    pub mirrored_bodies: bool,
}

impl Default for SeaExtras {
    fn default() -> Self {
        Self { whitecaps: true, kept_whitecaps: true, shore_foam: true, mirrored_bodies: true }
    }
}

/// The sea's waves and the settings they were made for, and the patch of simulated water.
pub(super) struct Sea {
    settings: SeaSettings,
    pub(super) waves: SeaWaves,
    /// What its waves are like, from their lattices at one moment (the sea's statistics do
    /// not change with time): whether they can break (`SeaWaves::may_break`; only then are
    /// whitecaps kept) and each cascade's slope variance.
    may_break: bool,
    slope_variances: Vec<f32>,
    pub(super) patch: HeightField,
    /// Where the device renders into no float textures: the cascades summed ahead on the CPU,
    /// after the last frame was submitted (while the GPU drew it), for the fixed step the next
    /// frame was expected at: used when it comes then. (Elsewhere the renderer runs their FFT
    /// on the GPU.)
    ahead: Option<(u64, [Vec<[f32; 4]>; 2])>,
    /// The fixed steps the last frame took (the next is expected to take as many).
    last_steps: u32,
    /// The waves at the last frame's fixed step, to sum at points: where the next frame's
    /// bodies start from (and the tests' sea). `None` once they no longer hold this sea's
    /// waves (new waves, a reset).
    pub(super) now: Option<(u64, SeaNow)>,
    /// The floating bodies in the sea, one per kind (demo/sea_bodies.rs).
    pub(super) bodies: Vec<crate::bodies::Body>,
}

impl WaterDemo {
    /// The scene the `scene` parameter asks for.
    pub fn scene(&self) -> SceneKind {
        self.params.choice(ParamId::Scene)
    }

    /// The scene the last frame drew (its camera is [`WaterDemo::camera`]).
    pub fn drawn_scene(&self) -> SceneKind {
        self.camera_scene
    }

    /// Whether the render modes (ray-traced, flat, split) and their costs apply to the scene
    /// asked for: they are the pool's.
    pub fn render_modes_apply(&self) -> bool {
        self.scene() == SceneKind::Pool
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
            // Over the crests: by a steeper view, and where the steepest is not enough (a
            // high sea, the camera near), from farther away.
            let settings = self.sea_settings();
            let clearance = settings.crest_bound() + EYE_OVER_CRESTS;
            self.camera.keep_eye_above(clearance);
            if let Some(place) = settings.island {
                // And over the land: the ground under the eye moves as the view steepens;
                // twice is close enough for the hill's slopes.
                for _ in 0..2 {
                    let eye = self.camera.eye();
                    self.camera.keep_eye_above(island::height(glam::Vec2::new(eye.x, eye.z), place) + EYE_OVER_CRESTS);
                }
            }
            let highest = self.camera.limits.pitch.1.to_radians().sin();
            self.camera.distance = self.camera.distance.max(clearance / highest);
        }
    }

    /// Starts over from `preset`: its values, then its view on the camera of the scene it
    /// shows (so a sea preset's view is the sea camera's, within the sea's limits).
    pub fn apply_preset(&mut self, preset: &crate::presets::Preset) {
        let mut view = self.camera;
        preset.apply(&mut self.params, &mut view);
        self.sync_scene();
        (self.camera.yaw, self.camera.pitch, self.camera.distance) = (view.yaw, view.pitch, view.distance);
        self.camera.clamp();
    }

    /// The sea's settings in the parameters.
    pub fn sea_settings(&self) -> SeaSettings {
        sea_settings(&self.params)
    }

    /// The sea for the current parameters: made the first time (the patch on the pool's
    /// engine), its waves made again when their parameters changed.
    fn sea(&mut self, device: &wgpu::Device) -> &mut Sea {
        let settings = self.sea_settings();
        match &mut self.sea {
            // The fog is drawn, not in the waves: a change of it makes nothing again.
            Some(sea) if sea.settings.waves() != settings.waves() => {
                sea.waves = SeaWaves::new(&settings.waves(), SEA_LATTICE);
                (sea.may_break, sea.slope_variances) = statistics(&sea.waves);
                sea.ahead = None;
                sea.now = None;
                sea.settings = settings;
            }
            Some(_) => {}
            None => {
                let engine = self.water.engine();
                let mut patch = HeightField::new_on(device, sea::PATCH_CELLS, sea::PATCH_HALF_WIDTH, engine);
                for drop in self.early_sea_drops.drain(..) {
                    patch.add_drop(drop);
                }
                let waves = SeaWaves::new(&settings.waves(), SEA_LATTICE);
                let bodies = self.sea_bodies_at_start();
                let (may_break, slope_variances) = statistics(&waves);
                let (ahead, last_steps, now) = (None, 0, None);
                self.sea =
                    Some(Sea { settings, waves, may_break, slope_variances, patch, ahead, last_steps, now, bodies });
            }
        }
        self.sea.as_mut().expect("made above")
    }

    /// Whether the sea draws its whitecaps, keeps them over time (else its map holds only each
    /// frame's own), and draws its shore's foam (the default: all three) or not (for tests to
    /// compare with).
    #[doc(hidden)]
    pub fn set_sea_foam(&mut self, whitecaps: bool, kept: bool, shore: bool) {
        self.sea_extras = SeaExtras { whitecaps, kept_whitecaps: kept, shore_foam: shore, ..self.sea_extras };
    }

    /// Whether the sea mirrors its floating bodies (the default) or not (for tests to compare
    /// with).
    #[doc(hidden)]
    pub fn set_sea_body_mirror(&mut self, on: bool) {
        self.sea_extras.mirrored_bodies = on;
    }

    /// Whether the sea's cascades take the GPU's FFT (where the device renders into float
    /// textures; the default except on software rasterisers) or the CPU's (for tests to
    /// compare with).
    #[doc(hidden)]
    pub fn set_sea_fft_on_gpu(&mut self, on: bool) {
        self.sea_fft_on_gpu = on && self.ocean_on_gpu;
    }

    /// Puts `drop` (sea coordinates, m) in the sea's patch if the sea is drawn (kept for the
    /// patch until its first frame makes it); false in the pool.
    pub(super) fn drop_in_sea(&mut self, drop: Drop) -> bool {
        if self.camera_scene != SceneKind::Sea {
            return false;
        }
        match &mut self.sea {
            Some(sea) => sea.patch.add_drop(drop),
            None => self.early_sea_drops.push(drop),
        }
        true
    }

    /// After a sea frame was submitted: sums the cascades for the time the next frame is
    /// expected at (as many fixed steps on), while the GPU draws this one, so the next frame
    /// need not wait for them (it sums them itself if it comes at another time).
    pub(super) fn sum_sea_ahead(&mut self) {
        let steps_taken = self.steps_taken;
        let on_cpu = self.camera_scene == SceneKind::Sea && !self.sea_fft_on_gpu;
        if let Some(sea) = self.sea.as_mut().filter(|_| on_cpu) {
            let next = steps_taken + sea.last_steps as u64;
            if sea.ahead.as_ref().is_none_or(|(at, _)| *at != next) {
                // The time sim_time gives at that step.
                sea.ahead = Some((next, sea.waves.layers(next as f64 / super::STEPS_PER_SECOND as f64)));
            }
        }
    }

    /// Flattens the sea's patch (with the pool's water, [`WaterDemo::reset`]).
    pub(super) fn reset_sea(&mut self, queue: &wgpu::Queue) {
        let bodies = self.sea_bodies_at_start();
        if let Some(sea) = &mut self.sea {
            sea.patch.reset(queue);
            sea.bodies = bodies;
            sea.now = None;
        }
    }

    /// Height (m) of the sea's waves above world (x, z) in the last frame drawn (without the
    /// patch's ripples), once the sea has been drawn (for tests).
    pub fn sea_height_at(&self, x: f32, z: f32) -> Option<f32> {
        Some(self.sea.as_ref()?.now.as_ref()?.1.height(x, z))
    }

    /// The sea's patch of simulated water, once the sea has been drawn (for tests).
    pub fn sea_patch(&self) -> Option<&HeightField> {
        self.sea.as_ref().map(|s| &s.patch)
    }

    /// What the sea's frame shows of the scene: the sea camera, the sun and optics, the sea's
    /// bodies; no caustics, ambient waves, foam, flat water or deck (the pool's).
    fn sea_scene_view(&self) -> View {
        let pool = self.view();
        View {
            bodies: self.sea_drawn_bodies(),
            caustics: false,
            ambient: AmbientView::default(),
            foam: false,
            debug: None,
            flat: None,
            deck: false,
            ..pool
        }
    }

    /// [`WaterDemo::encode_frame`] in the sea: the patch takes the frame's steps (submitted
    /// ahead, as the pool's water), the waves are the simulated time's.
    pub(super) fn encode_sea_frame(
        &mut self,
        cx: FrameContext<'_>,
        frame_time: f32,
        mark: &mut dyn FnMut(&mut wgpu::CommandEncoder, Stage),
    ) {
        let FrameContext { device, queue, encoder, target, size } = cx;
        self.choose_render_scale(frame_time);
        let steps = self.take_steps(frame_time);
        let (t, step) = (self.sim_time(), self.steps_taken);
        let settings = self.sea_settings();
        let on_gpu = self.sea_fft_on_gpu;
        let sea = self.sea(device);
        // The waves' lattices for the sea's shader: the GPU's FFT (the renderer's), or the
        // CPU's.
        let texels = if on_gpu {
            None
        } else {
            Some(match sea.ahead.take() {
                Some((at, layers)) if at == step => layers,
                _ => sea.waves.layers(t),
            })
        };
        sea.last_steps = steps;
        let now = sea.waves.at(t);
        self.step_sea_bodies((steps, step), &now);
        let view = self.sea_scene_view();
        let sea = self.sea.as_mut().expect("made above");
        let mut sim_encoder = device.create_command_encoder(&Default::default());
        mark(&mut sim_encoder, Stage::Start);
        let ripples =
            WaveSettings { wave_speed: sea::patch_wave_speed(), damping: sea::PATCH_DAMPING, absorbing_walls: true };
        sea.patch.encode(queue, &mut sim_encoder, steps, STEP_DT, ripples);
        mark(&mut sim_encoder, Stage::AfterSimulation);
        queue.submit([sim_encoder.finish()]);
        sea.patch.after_submit();
        let sea = self.sea.as_ref().expect("made above");
        let oceans: Vec<_> = sea.waves.cascades.iter().map(|c| &c.ocean).collect();
        let lattices = match &texels {
            Some([surface, displacement]) => SeaLattices::Texels([surface, displacement]),
            None => SeaLattices::Fft { oceans: &oceans, t },
        };
        self.renderer.prepare(queue, encoder, &view, &sea.patch);
        let drawn = SeaView {
            camera: &self.camera,
            fog_distance: settings.fog_distance,
            choppiness: settings.choppiness,
            crest: settings.crest_bound(),
            cascades: sea.cascades_drawn(),
            lattices,
            patch: &sea.patch,
            whitecaps: self.sea_extras.whitecaps,
            shore_foam: self.sea_extras.shore_foam,
            variant: sea::SeaVariant {
                island: settings.island,
                grid_lines: settings.grid_lines,
                whitecap_map: sea.may_break,
                shallow_caustics: settings.island.is_some() && self.params.flag(ParamId::Caustics),
                mirrored_bodies: self.sea_extras.mirrored_bodies && view.bodies.iter().any(Option::is_some),
            },
            // Not kept (tests): the map holds only the frame's own foam.
            whitecaps_kept: if self.sea_extras.kept_whitecaps {
                (-(steps as f32) * STEP_DT / sea::WHITECAP_LIFETIME).exp()
            } else {
                0.0
            },
        };
        // The sea's waves' stage is its cascades' FFT; its middle stage the frame's maps: the
        // island's mirror and the kept whitecaps (where the pool's is its caustics).
        let mut marks = |encoder: &mut wgpu::CommandEncoder, maps: bool| {
            mark(encoder, if maps { Stage::AfterCaustics } else { Stage::AfterWaves })
        };
        self.renderer.encode_sea(FrameContext { device, queue, encoder, target, size }, &view, &drawn, &mut marks);
        mark(encoder, Stage::AfterScene);
        let sea = self.sea.as_mut().expect("made above");
        sea.now = Some((step, now));
    }
}

impl Sea {
    /// Per cascade as the renderer takes it: its turn (rad), its tile (m), its slopes' variance.
    fn cascades_drawn(&self) -> [(f32, f32, f32); SEA_CASCADES] {
        let mut cascades = [(0.0, 1.0, 0.0); SEA_CASCADES];
        for (i, c) in self.waves.cascades.iter().enumerate().take(SEA_CASCADES) {
            cascades[i] = (c.angle, 2.0 * c.ocean.band.half_tile, self.slope_variances[i]);
        }
        cascades
    }
}

/// Whether `waves` can break, and each cascade's slope variance: from their lattices at one
/// moment.
fn statistics(waves: &SeaWaves) -> (bool, Vec<f32>) {
    let layers = waves.layers(0.0);
    (waves.may_break(&layers), SeaWaves::slope_variances(&layers[0], waves.cascades.len()))
}
