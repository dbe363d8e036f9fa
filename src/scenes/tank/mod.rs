//! The ripple tank (`scene` = tank): the school lab's tray of shallow water with its dippers,
//! barriers and glass plates ([`crate::tank`]), a lamp above and a screen below. Its picture
//! is the tray's plane seen through an orbit camera that starts straight above it, as the
//! class looks down at the screen: the lamp's image there, or the heights or the intensity as
//! colour. A click drops a small pulse into the water.

mod render;
pub mod sketch;
mod tools;

use tools::Grab;

use glam::{Vec2, Vec3};

use super::{Picked, SceneFrame, Shared, Stage, STEPS_PER_SECOND, STEP_DT};
use crate::bodies::BodyId;
use crate::camera::OrbitCamera;
use crate::camera::Pick;
use crate::params::{ParamId, Params};
use crate::sim::Drop;
use crate::tank::gpu::TankWater;
use crate::tank::medium::{CellKind, Medium};
use crate::tank::probe::{self, ProbeReading};
use crate::tank::tuning::Tuning;
use crate::tank::{
    plan, Look, Setup, TankSettings, Tool, APPARATUS_VIEW, SCREEN_BELOW, START_VIEW, TANK_CELLS, TANK_LIMITS,
};
pub use render::{TankPicture, SCREEN_TEXELS};
pub use sketch::{Ruler, Sketch, Stroke};

/// A click's drop against the pool's: its radius shrinks with the tray against the pool, its
/// height to the dippers' scale (millimetres, not centimetres).
const DROP_HEIGHT_SCALE: f32 = 0.04;

/// The parameters the tank reads besides its own.
const READS: &[ParamId] = &[
    ParamId::Scene,
    ParamId::DropRadius,
    ParamId::DropStrength,
    ParamId::Exposure,
    ParamId::Paused,
    ParamId::Quality,
    ParamId::FrameBudget,
];

/// Whether parameter `name` is the tank's own (shown only in the tank).
pub fn owns(name: &str) -> bool {
    crate::tank::PARAMS.iter().any(|p| p.name == name)
}

/// Whether the tank reads parameter `name`.
pub fn reads(name: &str) -> bool {
    owns(name) || READS.iter().any(|id| id.name() == name)
}

/// The tank's settings in `params`.
pub fn tank_settings(params: &Params) -> TankSettings {
    // The probe and the graph's line stay a little inside the tray.
    let inner = 0.49 * params.get(ParamId::TankSize);
    TankSettings {
        setup: params.choice::<Setup>(ParamId::TankSetup),
        look: params.choice(ParamId::TankLook),
        size: params.get(ParamId::TankSize),
        depth: params.get(ParamId::TankDepth) * 1e-3,
        dippers: params.get(ParamId::TankDippers).round() as u32,
        phase_step: params.get(ParamId::TankPhase).to_radians(),
        detune: params.get(ParamId::TankDetune),
        amplitude_ratio: params.get(ParamId::TankAmplitudeRatio),
        frequency: params.get(ParamId::TankFrequency),
        amplitude: params.get(ParamId::TankAmplitude) * 1e-3,
        slit_width: params.get(ParamId::TankSlitWidth) * 1e-3,
        slit_spacing: params.get(ParamId::TankSlitSpacing) * 1e-3,
        lamp_height: params.get(ParamId::TankLampHeight),
        source_speed: params.get(ParamId::TankSourceSpeed),
        strobe: params.get(ParamId::TankStrobe),
        tool: params.choice(ParamId::TankTool),
        lines: params.flag(ParamId::TankLines),
        beaches: params.flag(ParamId::TankBeaches),
        pulse: params.flag(ParamId::TankPulse),
        probe: params.flag(ParamId::TankProbe).then(|| {
            let inside = |id| (params.get(id) * 1e-3).clamp(-inner, inner);
            // "Across" counts to the right as the class sees the tray (from above, the bar at
            // the bottom), which is −x.
            (-inside(ParamId::TankProbeX), inside(ParamId::TankProbeZ))
        }),
        graph: params.flag(ParamId::TankGraph).then(|| (params.get(ParamId::TankGraphZ) * 1e-3).clamp(-inner, inner)),
    }
}

/// The camera that shows a tray of `size` (m) whole from straight above ([`START_VIEW`] for
/// the default tray).
pub fn start_camera(size: f32) -> OrbitCamera {
    let [yaw, pitch, distance] = START_VIEW;
    let distance = distance * size / crate::tank::TANK_SIZE.default;
    OrbitCamera { yaw, pitch, distance, target: Vec3::ZERO, fov_y: 45.0, limits: TANK_LIMITS }
}

/// The camera the screen view of `settings` starts from: above the tray, or for the
/// apparatus, from the side with the lamp and the paper in the picture.
pub fn camera_for(settings: &TankSettings) -> OrbitCamera {
    if settings.look == Look::Screen {
        return start_camera(settings.size);
    }
    let [yaw, pitch, distance] = APPARATUS_VIEW;
    let (top, bottom) = (settings.lamp_height, -settings.depth - SCREEN_BELOW);
    let default_span = crate::tank::TANK_LAMP_HEIGHT.default + SCREEN_BELOW;
    let scale = (settings.size / crate::tank::TANK_SIZE.default).max((top - bottom) / default_span);
    let target = Vec3::new(0.0, 0.5 * (top + bottom), 0.0);
    OrbitCamera { yaw, pitch, distance: distance * scale, target, fov_y: 45.0, limits: TANK_LIMITS }
}

/// The split's screen view of a tray of `size` (m) in a part of the picture `aspect` wide
/// over high: from straight above, far enough back that the tray and its frame fit across.
pub fn top_camera(size: f32, aspect: f32) -> OrbitCamera {
    let mut camera = start_camera(size);
    let fit = 0.55 * size / (aspect * (0.5 * camera.fov_y.to_radians()).tan());
    camera.distance = camera.distance.max(fit);
    camera
}

/// The tank's state: its camera, its settings and cells, its water and its picture (made on
/// the first frame, when the device is known).
pub struct TankScene {
    camera: OrbitCamera,
    settings: TankSettings,
    medium: Medium,
    water: Option<TankWater>,
    picture: Option<TankPicture>,
    /// Whether the medium changed since the water last saw it, and whether it is to be built
    /// again before the next frame (a wall's far end dragged: once a frame, not each move).
    medium_changed: bool,
    rebuild_due: bool,
    /// Whether the water is to be stilled before the next frame (a new set-up).
    clear_water: bool,
    drops: Vec<Drop>,
    /// The walls drawn and erased with the pointer, in order: from, to (m) and what was
    /// painted; kept over changes of the set-up.
    strokes: Vec<Stroke>,
    /// The ruler laid with the pointer, if any.
    ruler: Option<Ruler>,
    /// The dippers moved with the pointer (index, place in m), the bar's z (m) if it was moved,
    /// and what is being moved.
    moved: Vec<(usize, (f32, f32))>,
    bar_at: Option<f32>,
    moving: Option<Grab>,
    /// The dippers given settings of their own (index, settings), and the one the move tool
    /// last picked (its settings are the ones shown).
    tuned: Vec<(usize, Tuning)>,
    picked: usize,
    /// Whether the pointer's press is still the one that began the last stroke or ruler.
    stroke_open: bool,
    /// Parameters the pointer set (the probe's place), for the demo's table.
    param_edits: Vec<(ParamId, f32)>,
    /// When the sources' single pulse began (s of simulated time), or is to begin (`None`
    /// with `pulse_due`) at the next frame.
    pulse_start: Option<f64>,
    pulse_due: bool,
    /// What the probe reads, and the intensity graph's largest value along its line (m²),
    /// from the latest read back from the GPU.
    reading: ProbeReading,
    graph_peak: Option<f32>,
    float_targets: bool,
}

/// How far (a share of a drop's radius) a point of the pointer's stroke may lie from the last
/// for the two to be joined by a wall: the demo puts points about one drop radius apart.
const STROKE_JOIN: f32 = 2.5;

impl TankScene {
    /// The tank at its defaults; its water on the GPU where the device renders into
    /// `float_targets`.
    pub fn new(float_targets: bool) -> Self {
        let settings = TankSettings::default();
        Self {
            camera: camera_for(&settings),
            medium: Medium::of(&settings, TANK_CELLS),
            settings,
            water: None,
            picture: None,
            medium_changed: false,
            rebuild_due: false,
            clear_water: false,
            drops: Vec::new(),
            strokes: Vec::new(),
            ruler: None,
            moved: Vec::new(),
            bar_at: None,
            moving: None,
            tuned: Vec::new(),
            picked: 0,
            stroke_open: false,
            param_edits: Vec::new(),
            pulse_start: None,
            pulse_due: true,
            reading: ProbeReading::default(),
            graph_peak: None,
            float_targets,
        }
    }

    /// What the probe reads (from a read of its record a frame or two old).
    pub fn probe_reading(&self) -> ProbeReading {
        self.reading
    }

    /// The ruler laid with the pointer, if any.
    pub fn ruler(&self) -> Option<Ruler> {
        self.ruler
    }

    pub fn settings(&self) -> &TankSettings {
        &self.settings
    }

    /// The tray's cells and sources (as of the last frame while a wall is being dragged).
    pub fn medium(&self) -> &Medium {
        &self.medium
    }

    /// The walls drawn with the pointer.
    pub fn strokes(&self) -> &[Stroke] {
        &self.strokes
    }

    /// The set-up's cells with the pointer's strokes painted over them, and its dippers where
    /// the pointer moved them.
    fn rebuild_medium(&mut self) {
        self.medium = Medium::of(&self.settings, TANK_CELLS);
        for s in &self.strokes {
            self.medium.stroke(s.from, s.to, s.kind);
        }
        self.place_dippers();
        self.medium_changed = true;
    }

    /// Puts the dippers the pointer moved where it left them (a moving dipper starts there),
    /// and gives those tuned their own settings.
    fn place_dippers(&mut self) {
        let dippers = &mut self.medium.sources.dippers;
        for &(k, (x, z)) in &self.moved {
            if let Some(d) = dippers.get_mut(k) {
                (d.x, d.z) = (x, z);
            }
        }
        for (k, own) in &self.tuned {
            if let Some(d) = dippers.get_mut(*k) {
                own.apply(d, &self.settings);
            }
        }
        if let (Some(z), Some(bar)) = (self.bar_at, self.medium.sources.bar.as_mut()) {
            bar.z = z;
        }
    }

    /// Forgets the sources moved and tuned with the pointer.
    fn forget_sources(&mut self) {
        (self.moved, self.tuned, self.bar_at) = (Vec::new(), Vec::new(), None);
    }

    /// Forgets the dippers moved and tuned past the first `count`, and the pick among them.
    fn keep_dippers(&mut self, count: usize) {
        self.moved.retain(|&(k, _)| k < count);
        self.tuned.retain(|&(k, _)| k < count);
        self.picked = self.picked.min(count.saturating_sub(1));
    }

    /// What was drawn with the pointer.
    fn drawn(&self) -> Sketch {
        let (strokes, moved, tuned) = (self.strokes.clone(), self.moved.clone(), self.tuned.clone());
        Sketch { strokes, ruler: self.ruler, moved, bar: self.bar_at, tuned }
    }

    /// The water, once a frame has been drawn.
    pub fn water(&self) -> Option<&TankWater> {
        self.water.as_ref()
    }

    /// The picture's passes and the screen's image, once a frame has been drawn.
    pub fn picture(&self) -> Option<&TankPicture> {
        self.picture.as_ref()
    }
}

impl super::Scene for TankScene {
    fn camera(&self) -> &OrbitCamera {
        &self.camera
    }

    fn camera_mut(&mut self) -> &mut OrbitCamera {
        &mut self.camera
    }

    fn follow_params(&mut self, params: &Params) {
        let (settings, old) = (tank_settings(params), self.settings);
        if settings.size != old.size || settings.look != old.look {
            self.camera = camera_for(&settings);
        }
        let fresh_lab = settings.setup != old.setup || settings.size != old.size;
        if fresh_lab {
            // A new set-up starts a fresh lab: the walls drawn for the last one and its waves go.
            self.strokes.clear();
            self.ruler = None;
            self.forget_sources();
            self.picked = 0;
            self.clear_water = true;
        }
        if fresh_lab || settings.probe != old.probe || settings.graph != old.graph {
            // The probe's record starts afresh (reads in flight are dropped): nothing read yet.
            (self.reading, self.graph_peak) = (ProbeReading::default(), None);
        }
        // A pulse begins when the single pulse is switched on and with each fresh lab.
        self.pulse_due |= settings.pulse && (!old.pulse || fresh_lab);
        self.settings = settings;
        // The cells depend on these only (not on the frequency, the lamp, the strobe, …).
        let cells_of = |s: &TankSettings| {
            let row = (s.dippers, s.phase_step, s.detune, s.amplitude_ratio);
            (s.setup, s.size, s.depth, s.slit_width, s.slit_spacing, s.beaches, s.source_speed, row)
        };
        if settings.dippers < old.dippers {
            self.keep_dippers(settings.dippers as usize);
        }
        if cells_of(&settings) != cells_of(&old) {
            self.rebuild_medium();
        } else {
            // A tuned dipper keeps its own frequency and amplitude when the set ones change.
            self.place_dippers();
        }
    }

    fn encode_frame(&mut self, sh: Shared<'_>, frame: SceneFrame<'_, '_>) {
        let SceneFrame { cx, renderer, steps, mark } = frame;
        let (device, queue) = (cx.device, cx.queue);
        let float_targets = self.float_targets;
        if std::mem::take(&mut self.rebuild_due) {
            self.rebuild_medium();
        }
        let water = self.water.get_or_insert_with(|| TankWater::new(device, queue, &self.medium, float_targets));
        if std::mem::take(&mut self.medium_changed) {
            water.set_medium(queue, &self.medium);
        }
        if std::mem::take(&mut self.clear_water) {
            water.clear(queue);
        }
        let picture = self.picture.get_or_insert_with(|| {
            TankPicture::new(device, renderer.settings().target_format, TANK_CELLS, float_targets)
        });
        let t0 = sh.steps_taken.saturating_sub(steps as u64) as f64 / STEPS_PER_SECOND as f64;
        let mut updates = plan::plan(&self.medium, &self.settings, t0, steps, STEP_DT, &mut self.drops);
        if std::mem::take(&mut self.pulse_due) {
            self.pulse_start = Some(t0);
        }
        if self.settings.pulse {
            plan::shape_pulse(&mut updates, t0, self.pulse_start.unwrap_or(t0));
        }
        if let Some(read) = water.take_read() {
            self.reading = probe::read(&read.heights, STEP_DT);
            self.graph_peak = read.row.map(|(_, row)| row.iter().fold(0.0, |m: f32, &i| m.max(i)));
        }
        let cell = |x: f32, z: f32| self.medium.cell_at(x, z);
        water.probe_at(
            self.settings.probe.and_then(|(x, z)| cell(x, z)),
            plan::updates_per_step(&self.medium, STEP_DT) as usize,
        );
        let dt = updates.first().map_or(0.0, |u| u.grid[2] as f64);
        let flash = plan::strobe_flash(self.settings.strobe, t0, updates.len(), dt);
        mark(cx.encoder, Stage::Start);
        water.encode(device, queue, cx.encoder, &updates, flash);
        let graph_row = self.settings.graph.and_then(|z| cell(0.0, z)).map(|(_, j)| j);
        if self.settings.probe.is_some() || graph_row.is_some() {
            water.record_read(device, cx.encoder, graph_row);
        }
        mark(cx.encoder, Stage::AfterSimulation);
        // No waves move here on their own (the stage of the pool's and the sea's FFT).
        mark(cx.encoder, Stage::AfterWaves);
        let look = self.settings.look;
        let aspect = sh.viewport.x / sh.viewport.y * if look == Look::Split { 0.5 } else { 1.0 };
        let shot = render::Shot {
            view_proj: match look {
                Look::Split => top_camera(self.settings.size, aspect).view_projection(aspect),
                _ => self.camera.view_projection(aspect),
            },
            apparatus_view_proj: self.camera.view_projection(aspect),
            look,
            view: sh.params.choice(ParamId::TankView),
            exposure: 2f32.powf(sh.params.get(ParamId::Exposure)),
            lines: match self.medium.slits {
                Some(slits) if self.settings.lines => Some((slits.z, slits.directions(self.settings.wavelength()))),
                _ => None,
            },
            probe: self.settings.probe.map(|at| (at, self.reading.swing)),
            graph: self.settings.graph.map(|z| (z, self.graph_peak.unwrap_or(0.0))),
            ruler: self.ruler,
            dippers: (self.medium.sources.dippers.iter())
                .map(|d| {
                    let (x, z) = d.centre_at(sh.steps_taken as f64 / STEPS_PER_SECOND as f64);
                    [x, z, d.radius]
                })
                .collect(),
            bar: self.medium.sources.bar.map(|b| [b.z, b.half_thickness, b.half_length]),
        };
        let group = picture.encode_screen(device, queue, cx.encoder, water, &self.settings, &shot);
        mark(cx.encoder, Stage::AfterMaps);
        picture.encode_show(cx.encoder, cx.target, &group, look, cx.size);
        mark(cx.encoder, Stage::AfterShading);
    }

    fn after_submit(&mut self, _steps_taken: u64) {
        if let Some(water) = &self.water {
            water.after_submit();
        }
    }

    /// Still water, the walls drawn with the pointer and the ruler put away, a new pulse.
    fn reset(&mut self, queue: &wgpu::Queue, _sh: Shared<'_>) {
        self.drops.clear();
        (self.reading, self.graph_peak) = (ProbeReading::default(), None);
        (self.stroke_open, self.moving) = (false, None);
        self.ruler = None;
        self.pulse_due = true;
        if self.drawn() != Sketch::default() {
            self.strokes.clear();
            self.forget_sources();
            self.rebuild_medium();
        }
        if let Some(water) = &mut self.water {
            water.clear(queue);
        }
    }

    fn stage_names(&self) -> [&'static str; 4] {
        ["simulation", "waves", "screen", "shading"]
    }

    fn drop_area(&self) -> (f32, &'static str) {
        (self.settings.half_width(), "the tank")
    }

    fn drop_scale(&self) -> (f32, f32) {
        (self.settings.half_width() / crate::world::PoolShape::CLASSIC.half_width, DROP_HEIGHT_SCALE)
    }

    /// A drop, or with the wall or erase tool a stroke from the last point of the pointer's
    /// stroke (if near enough to be the same stroke) to this one.
    fn add_drop(&mut self, drop: Drop) {
        let to = (drop.x, drop.z);
        let continues = std::mem::replace(&mut self.stroke_open, true);
        let kind = match self.settings.tool {
            Tool::Drops => return self.drops.push(drop),
            Tool::Walls => return self.draw_wall(to, continues),
            Tool::Erase => CellKind::Water,
            Tool::Probe => {
                self.param_edits.extend([
                    (ParamId::TankProbe, 1.0),
                    (ParamId::TankProbeX, (-to.0 * 1e3).round()),
                    (ParamId::TankProbeZ, (to.1 * 1e3).round()),
                ]);
                return;
            }
            Tool::Ruler => {
                self.ruler = Some(match self.ruler {
                    Some((from, _)) if continues => (from, to),
                    _ => (to, to),
                });
                return;
            }
            Tool::Move => return self.move_source(to, continues),
        };
        let from = match self.strokes.last() {
            Some(last)
                if continues
                    && last.kind == kind
                    && (last.to.0 - to.0).hypot(last.to.1 - to.1) <= STROKE_JOIN * drop.radius =>
            {
                last.to
            }
            _ => to,
        };
        let stroke = Stroke { from, to, kind };
        self.medium.stroke(from, to, kind);
        self.strokes.push(stroke);
        self.medium_changed = true;
    }

    fn begin_stroke(&mut self) {
        self.stroke_open = false;
    }

    fn take_param_edits(&mut self) -> Vec<(ParamId, f32)> {
        std::mem::take(&mut self.param_edits)
    }

    fn sketch(&self) -> String {
        sketch::format(&self.drawn())
    }

    /// Replaces what was drawn with what `text` says; on an error nothing changes.
    fn set_sketch(&mut self, text: &str) -> Result<(), String> {
        let Sketch { strokes, ruler, moved, bar, tuned } = sketch::parse(text, self.settings.half_width())?;
        (self.strokes, self.ruler, self.moved, self.bar_at, self.tuned) = (strokes, ruler, moved, bar, tuned);
        (self.stroke_open, self.moving) = (false, None);
        self.rebuild_medium();
        Ok(())
    }

    /// With the move tool, the dipper it last picked (the first until one is picked) and its
    /// own frequency, amplitude and phase.
    fn picked(&self) -> Option<Picked> {
        if self.settings.tool != Tool::Move {
            return None;
        }
        let dippers = &self.medium.sources.dippers;
        let k = self.picked.min(dippers.len().checked_sub(1)?);
        let own = Tuning::of(&dippers[k], &self.settings);
        Some(Picked { title_id: "dipper", number: k as u32 + 1, settings: own.values().to_vec() })
    }

    fn set_picked(&mut self, name: &str, value: f32) -> Result<(), String> {
        let dippers = &self.medium.sources.dippers;
        let k = self.picked.min(dippers.len().checked_sub(1).ok_or("this set-up has no dipper")?);
        let own = Tuning::of(&dippers[k], &self.settings);
        let own = own.with(name, value).ok_or_else(|| format!("a dipper has no setting \"{name}\""))?;
        self.tuned.retain(|&(j, _)| j != k);
        self.tuned.push((k, own));
        self.place_dippers();
        Ok(())
    }

    /// The probe's frequency (Hz) and swing (mm), when it is in; the ruler's length (mm),
    /// when one is laid.
    fn readings(&self) -> Vec<(&'static str, f32, &'static str)> {
        let mut out = Vec::new();
        if self.settings.probe.is_some() {
            if let Some(f) = self.reading.frequency {
                out.push(("probe frequency", f, "Hz"));
            }
            out.push(("probe swing", self.reading.swing * 1e3, "mm"));
        }
        if let Some((a, b)) = self.ruler {
            out.push(("ruler", (a.0 - b.0).hypot(a.1 - b.1) * 1e3, "mm"));
        }
        out
    }

    /// In the split, the left half is the apparatus's camera and the right the top view's.
    fn pick_water(&self, viewport: Vec2, pixel: Vec2) -> Pick {
        let w = self.settings.half_width();
        if self.settings.look != Look::Split {
            return self.camera.pick_within(pixel, viewport, w);
        }
        let half = Vec2::new(0.5 * viewport.x, viewport.y);
        if pixel.x < half.x {
            return self.camera.pick_within(pixel, half, w);
        }
        top_camera(self.settings.size, half.x / half.y).pick_within(pixel - Vec2::new(half.x, 0.0), half, w)
    }

    fn pick_body(&self, _sh: Shared<'_>, _pixel: Vec2) -> Option<(BodyId, Vec3, Vec3)> {
        None
    }

    fn move_body(&mut self, _sh: Shared<'_>, _id: BodyId, _position: Vec3) {}
}
