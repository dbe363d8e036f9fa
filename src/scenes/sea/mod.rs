//! The open sea (`scene` = sea): its camera, and its frame: the patch of simulated water round
//! the camera's target stepped (the clicks' ripples), the cascades' FFT at the simulated time
//! (on the GPU where it renders into float textures, else on the CPU), both drawn by the sea's
//! own passes (`render/`, on what `render::scene_parts` lends); the bodies ride the waves
//! summed at their probes on the CPU (`bodies.rs`). The feature's parameters, constants and
//! settings are in `crate::sea`.

mod bodies;
mod render;
#[cfg(not(target_arch = "wasm32"))]
mod timings;

pub use bodies::in_sea;

use glam::{Vec2, Vec3};

use super::{common_view, SceneFrame, Shared, Stage, STEPS_PER_SECOND, STEP_DT};
use crate::ambient::cascades::{SeaNow, SeaWaves};
use crate::bodies::BodyId;
use crate::camera::OrbitCamera;
use crate::gpu::FrameContext;
use crate::params::{ParamId, Params};
use crate::render::View;
use crate::sea::{self, island, IslandChoice, SeaSettings, EYE_OVER_CRESTS, SEA_LATTICE};
use crate::sim::{Drop, HeightField, SimEngine, WaveSettings};
use render::{SeaLattices, SeaRenderer, SeaView, SEA_CASCADES};

/// The pool's parameters the sea reads too: the caustics (on the shallows' floor), the clicks'
/// drops, the sun and the exposure, the optics of reflection and highlight, the bodies'
/// gravity, the running and the frame's quality; and the scene's choice. (The kinds of body's
/// own sizes and densities it reads as well.)
const READS_OF_THE_POOL: &[ParamId] = &[
    ParamId::Scene,
    ParamId::Caustics,
    ParamId::DropRadius,
    ParamId::DropStrength,
    ParamId::SunAzimuth,
    ParamId::SunElevation,
    ParamId::SunSize,
    ParamId::Exposure,
    ParamId::Fresnel,
    ParamId::Specular,
    ParamId::Shininess,
    ParamId::Gravity,
    ParamId::Paused,
    ParamId::Quality,
    ParamId::FrameBudget,
];

/// Whether parameter `name` is the sea's own (shown only in the sea).
pub fn owns(name: &str) -> bool {
    sea::PARAMS.iter().any(|p| p.name == name)
}

/// Whether the sea reads parameter `name`, its own or one it shares.
pub fn reads(name: &str) -> bool {
    owns(name)
        || READS_OF_THE_POOL.iter().any(|id| id.name() == name)
        || crate::bodies::kind_params().any(|n| n == name)
}

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
pub struct SeaExtras {
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

/// The open sea's state: its camera, and once it has been shown its waves and patch.
pub struct SeaScene {
    pub camera: OrbitCamera,
    /// The waves and the patch, made at the sea's first frame.
    sea: Option<Sea>,
    /// What the sea draws beyond its waves (some of it off only in tests).
    pub extras: SeaExtras,
    /// Drops asked for before the first frame made the patch.
    early_drops: Vec<Drop>,
    /// The engine the patch is simulated on (the pool's).
    engine: SimEngine,
    /// Whether the device renders into float textures.
    float_targets: bool,
    /// Its pipelines and maps, made at its first frame.
    drawing: Option<SeaRenderer>,
    /// Whether the cascades are summed by the GPU's FFT: with float render targets, unless the
    /// adapter is a software rasteriser. There the GPU's passes run on the CPU as well, each
    /// paying for every texel it writes, where the CPU's radix-2 stages sum the cascades ahead
    /// of the next frame beside the drawing (on lavapipe 117–121 against 126–130 ms a frame).
    fft_on_gpu: bool,
}

/// The sea's waves and the settings they were made for, and the patch of simulated water.
struct Sea {
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
    /// frame was expected at: used when it comes then. (Elsewhere the sea's passes run their FFT
    /// on the GPU.)
    ahead: Option<(u64, [Vec<[f32; 4]>; 2])>,
    /// The fixed steps the last frame took (the next is expected to take as many).
    last_steps: u32,
    /// The waves at the last frame's fixed step, to sum at points: where the next frame's
    /// bodies start from (and the tests' sea). `None` once they no longer hold this sea's
    /// waves (new waves, a reset).
    pub(super) now: Option<(u64, SeaNow)>,
    /// The floating bodies in the sea, one per kind (`bodies.rs`).
    pub(super) bodies: Vec<crate::bodies::Body>,
}

impl SeaScene {
    /// The sea before its first frame; its patch will be simulated on `engine`.
    pub fn new(engine: SimEngine, float_targets: bool, software: bool) -> Self {
        Self {
            camera: sea::default_camera(),
            sea: None,
            extras: SeaExtras::default(),
            early_drops: Vec::new(),
            engine,
            float_targets,
            fft_on_gpu: float_targets && !software,
            drawing: None,
        }
    }

    /// Whether the cascades take the GPU's FFT (where the device renders into float textures;
    /// the default except on software rasterisers) or the CPU's (for tests to compare with).
    pub fn set_fft_on_gpu(&mut self, on: bool) {
        self.fft_on_gpu = on && self.float_targets;
    }

    /// The sea for the current parameters: made the first time, its waves made again when
    /// their parameters changed.
    fn sea(&mut self, device: &wgpu::Device, sh: Shared<'_>) -> &mut Sea {
        let settings = sea_settings(sh.params);
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
                let mut patch = HeightField::new_on(device, sea::PATCH_CELLS, sea::PATCH_HALF_WIDTH, self.engine);
                for drop in self.early_drops.drain(..) {
                    patch.add_drop(drop);
                }
                let waves = SeaWaves::new(&settings.waves(), SEA_LATTICE);
                let bodies = bodies::at_start(sh);
                let (may_break, slope_variances) = statistics(&waves);
                let (ahead, last_steps, now) = (None, 0, None);
                self.sea =
                    Some(Sea { settings, waves, may_break, slope_variances, patch, ahead, last_steps, now, bodies });
            }
        }
        self.sea.as_mut().expect("made above")
    }

    /// Height (m) of the sea's waves above world (x, z) in the last frame drawn (without the
    /// patch's ripples), once the sea has been drawn (for tests).
    pub fn height_at(&self, x: f32, z: f32) -> Option<f32> {
        Some(self.sea.as_ref()?.now.as_ref()?.1.height(x, z))
    }

    /// The sea's patch of simulated water, once the sea has been drawn (for tests).
    pub fn patch(&self) -> Option<&HeightField> {
        self.sea.as_ref().map(|s| &s.patch)
    }

    /// What the sea's frame shows: the sea camera, the sun and optics, the sea's bodies.
    fn view(&self, sh: Shared<'_>) -> View {
        View { bodies: self.drawn_bodies(sh), ..common_view(sh, &self.camera) }
    }

    /// What the sea's passes are told of this frame (after its `steps` fixed steps), seen by
    /// `camera`.
    fn drawn<'a>(
        (camera, sea, extras): (&'a OrbitCamera, &'a Sea, SeaExtras),
        sh: Shared<'_>,
        view: &View,
        lattices: SeaLattices<'a>,
        steps: u32,
    ) -> SeaView<'a> {
        let settings = sea_settings(sh.params);
        SeaView {
            camera,
            fog_distance: settings.fog_distance,
            horizon_band: sea::horizon_haze_band(settings.wind_speed),
            choppiness: settings.choppiness,
            crest: settings.crest_bound(),
            cascades: sea.cascades_drawn(),
            lattices,
            patch: &sea.patch,
            whitecaps: extras.whitecaps,
            shore_foam: extras.shore_foam,
            variant: sea::SeaVariant {
                island: settings.island,
                grid_lines: settings.grid_lines,
                whitecaps: sea.may_break,
                whitecap_map: sea.may_break,
                shallow_caustics: settings.island.is_some() && sh.params.flag(ParamId::Caustics),
                mirrored_bodies: extras.mirrored_bodies && view.bodies.iter().any(Option::is_some),
            },
            // Not kept (tests): the map holds only the frame's own foam.
            whitecaps_kept: if extras.kept_whitecaps {
                (-(steps as f32) * STEP_DT / sea::WHITECAP_LIFETIME).exp()
            } else {
                0.0
            },
        }
    }
}

impl super::Scene for SeaScene {
    fn camera(&self) -> &OrbitCamera {
        &self.camera
    }

    fn camera_mut(&mut self) -> &mut OrbitCamera {
        &mut self.camera
    }

    /// Keeps the eye over the crests: by a steeper view, and where the steepest is not enough
    /// (a high sea, the camera near), from farther away; and over the island's land.
    fn follow_params(&mut self, params: &Params) {
        let settings = sea_settings(params);
        let clearance = settings.crest_bound() + EYE_OVER_CRESTS;
        self.camera.keep_eye_above(clearance);
        if let Some(place) = settings.island {
            // The ground under the eye moves as the view steepens; twice is close enough for
            // the hill's slopes.
            for _ in 0..2 {
                let eye = self.camera.eye();
                self.camera.keep_eye_above(island::height(Vec2::new(eye.x, eye.z), place) + EYE_OVER_CRESTS);
            }
        }
        let highest = self.camera.limits.pitch.1.to_radians().sin();
        self.camera.distance = self.camera.distance.max(clearance / highest);
    }

    /// The patch takes the frame's steps (submitted ahead, as the pool's water), the waves are
    /// the simulated time's.
    fn encode_frame(&mut self, sh: Shared<'_>, frame: SceneFrame<'_, '_>) {
        let SceneFrame { cx, renderer, steps, mark } = frame;
        let FrameContext { device, queue, encoder, target, size } = cx;
        let (t, step) = (sh.sim_time(), sh.steps_taken);
        let on_gpu = self.fft_on_gpu;
        let sea = self.sea(device, sh);
        // The waves' lattices for the sea's shader: the GPU's FFT (the sea's passes'), or the
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
        self.step_bodies(sh, (steps, step), &now);
        let view = self.view(sh);
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
        renderer.prepare(queue, encoder, &view, &sea.patch);
        let drawn = Self::drawn((&self.camera, sea, self.extras), sh, &view, lattices, steps);
        // The sea's waves' stage is its cascades' FFT; its maps' stage the island's mirror
        // and the kept whitecaps.
        let mut marks = |encoder: &mut wgpu::CommandEncoder, maps: bool| {
            mark(encoder, if maps { Stage::AfterMaps } else { Stage::AfterWaves })
        };
        let cx = FrameContext { device, queue, encoder: &mut *encoder, target, size };
        render::encode(&mut self.drawing, renderer, cx, (&view, &drawn), &mut marks);
        mark(encoder, Stage::AfterShading);
        let sea = self.sea.as_mut().expect("made above");
        sea.now = Some((step, now));
    }

    /// Where the device renders into no float textures: sums the cascades for the time the
    /// next frame is expected at (as many fixed steps on), while the GPU draws this one, so the
    /// next frame need not wait for them (it sums them itself if it comes at another time).
    fn after_submit(&mut self, steps_taken: u64) {
        if let Some(sea) = self.sea.as_mut().filter(|_| !self.fft_on_gpu) {
            let next = steps_taken + sea.last_steps as u64;
            if sea.ahead.as_ref().is_none_or(|(at, _)| *at != next) {
                // The time sim_time gives at that step.
                sea.ahead = Some((next, sea.waves.layers(next as f64 / STEPS_PER_SECOND as f64)));
            }
        }
    }

    fn reset(&mut self, queue: &wgpu::Queue, sh: Shared<'_>) {
        self.early_drops.clear();
        if let Some(sea) = &mut self.sea {
            sea.patch.reset(queue);
            sea.bodies = bodies::at_start(sh);
            sea.now = None;
        }
    }

    fn stage_names(&self) -> [&'static str; 4] {
        ["simulation", "waves", "maps", "shading"]
    }

    #[cfg(not(target_arch = "wasm32"))]
    fn timed_apart(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        params: &Params,
    ) -> Vec<(&'static str, Vec<f64>)> {
        timings::timed_apart(device, queue, params)
    }

    fn drop_area(&self) -> (f32, &'static str) {
        (sea::PATCH_HALF_WIDTH, "the sea's patch")
    }

    /// A click's drop is larger in the patch than in the pool ([`sea::patch_scale`]).
    fn drop_scale(&self) -> (f32, f32) {
        let k = sea::patch_scale();
        (k, k * sea::PATCH_DROP_HEIGHT)
    }

    /// Kept for the patch until the sea's first frame makes it.
    fn add_drop(&mut self, drop: Drop) {
        match &mut self.sea {
            Some(sea) => {
                sea.patch.add_drop(drop);
            }
            None => self.early_drops.push(drop),
        }
    }

    fn pick_body(&self, sh: Shared<'_>, pixel: Vec2) -> Option<(BodyId, Vec3, Vec3)> {
        self.body_under(sh, pixel)
    }

    fn move_body(&mut self, sh: Shared<'_>, id: BodyId, position: Vec3) {
        self.set_body(sh, id, position, Vec3::ZERO);
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
