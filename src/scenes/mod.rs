//! The scenes the demo shows, each in a home of its own: the pool (`scenes/pool/`), the open
//! sea (`scenes/sea/`) and the ripple tank (`scenes/tank/`). A scene owns what differs between scenes: its camera and limits, its
//! state (water, waves, bodies), its stepping, what a press or a drag does in it, its picture
//! and the names of its frame's stages. The demo (`demo/`) keeps what they share: the
//! parameters, the clock, the governors, the renderer, the pointer.
//!
//! This file is the registry: the one place that names every scene ([`Scenes::get`]). Adding a
//! scene is a folder beside `pool/` and `sea/`, a choice of the `scene` parameter and an arm
//! here (docs/ARCHITECTURE.md, Recipes: "A scene").

pub mod pool;
pub mod sea;
pub mod tank;

use glam::{Vec2, Vec3};

use crate::bodies::BodyId;
use crate::camera::{OrbitCamera, Pick};
use crate::gpu::FrameContext;
use crate::params::{ParamId, Params};
use crate::render::{DebugChoice, Optics, Renderer, View};
pub use crate::sea::SceneKind;
use crate::sim::Drop;

/// Fixed simulation steps per simulated second.
pub const STEPS_PER_SECOND: u32 = 120;
/// Simulated seconds per step.
pub const STEP_DT: f32 = 1.0 / STEPS_PER_SECOND as f32;

/// Stages of a frame, for timing: each is the index of its mark (`StageTimer::mark`). What
/// each stage does is the scene's ([`Scene::stage_names`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stage {
    Start,
    AfterSimulation,
    /// After the waves that move on their own: the pool's FFT ocean, the sea's cascades.
    AfterWaves,
    /// After the maps the picture reads: the pool's caustics, the sea's mirror and whitecaps.
    AfterMaps,
    AfterShading,
}

/// What every scene's hooks are told by the demo: the parameters, the viewport the pointer's
/// pixels refer to (pixels), the steps simulated so far, the render scale of this frame and
/// the body the pointer holds, if any.
#[derive(Clone, Copy)]
pub struct Shared<'a> {
    pub params: &'a Params,
    pub viewport: Vec2,
    pub steps_taken: u64,
    pub render_scale: f32,
    pub held: Option<BodyId>,
}

impl Shared<'_> {
    /// Simulated time so far (s).
    pub fn sim_time(&self) -> f64 {
        self.steps_taken as f64 / STEPS_PER_SECOND as f64
    }

    /// A parameter's value by name, for the body kinds' table entries.
    pub fn value(&self, name: &str) -> f32 {
        self.params.get_by_name(name).expect("a body kind reads its own parameters")
    }

    /// A kind of body's hull ellipsoids at its parameters, in its own frame (m; as the kinds'
    /// table sizes it for the classic pool).
    pub fn hull(&self, id: BodyId) -> Vec<crate::physics::Ellipsoid> {
        (id.kind().hull)(&|name: &str| self.value(name))
    }
}

/// What a scene's frame is given: the frame's target and encoder, the renderer that draws it,
/// the fixed steps it takes and the marks between its stages.
pub struct SceneFrame<'a, 'b> {
    pub cx: FrameContext<'a>,
    pub renderer: &'a mut Renderer,
    pub steps: u32,
    pub mark: &'b mut dyn FnMut(&mut wgpu::CommandEncoder, Stage),
}

/// What the pointer picked that has settings of its own: its title, a message of the page's
/// words with the number it fills in (`"dipper"`, 2: "Dipper 2"), and each setting's spec (its
/// name, label, range and help; not in the parameter table) and value.
#[derive(Clone, Debug)]
pub struct Picked {
    pub title_id: &'static str,
    pub number: u32,
    pub settings: Vec<(&'static crate::param_spec::ParamSpec, f32)>,
}

impl Picked {
    /// The title in English ("Dipper 2").
    pub fn english_title(&self) -> String {
        crate::page_words::english_with(self.title_id, &[("number", self.number.to_string())])
    }
}

/// What one scene does; the demo calls the shown scene's hooks. Lengths in m in the scene's own
/// coordinates, pixels from the viewport's top left corner.
pub trait Scene {
    /// The scene's camera (each scene keeps its own, within its own limits, while away).
    fn camera(&self) -> &OrbitCamera;
    fn camera_mut(&mut self) -> &mut OrbitCamera;

    /// Brings the scene up to the parameters before a frame or a move of the camera: the
    /// camera's clearance, the waves made from them.
    fn follow_params(&mut self, params: &Params);

    /// Steps the scene by `frame.steps` fixed steps and records its drawing.
    fn encode_frame(&mut self, sh: Shared<'_>, frame: SceneFrame<'_, '_>);

    /// After the frame was submitted: starts the reads it asked for, sums ahead what the next
    /// frame will need.
    fn after_submit(&mut self, _steps_taken: u64) {}

    /// Flattens the water and puts the bodies back where they started, at rest.
    fn reset(&mut self, queue: &wgpu::Queue, sh: Shared<'_>);

    /// Builds one pipeline the next frame will draw with, if one is missing; true when none is.
    fn build_ahead(
        &mut self,
        _sh: Shared<'_>,
        _renderer: &mut Renderer,
        _device: &wgpu::Device,
        _size: (u32, u32),
    ) -> bool {
        true
    }

    /// What each timed stage of a frame does, in the order of the marks between them.
    fn stage_names(&self) -> [&'static str; 4];

    /// What `wavepool bench` times apart in this scene beside its frame's stages: (name, each
    /// run's ms).
    #[cfg(not(target_arch = "wasm32"))]
    fn timed_apart(
        &self,
        _device: &wgpu::Device,
        _queue: &wgpu::Queue,
        _params: &Params,
    ) -> Vec<(&'static str, Vec<f64>)> {
        Vec::new()
    }

    /// Whether the render modes (ray-traced, flat, split) and their costs apply here.
    fn has_render_modes(&self) -> bool {
        false
    }

    /// The water the pointer makes drops in: its half width (m) each way from the origin, and
    /// its name in a warning ("the pool").
    fn drop_area(&self) -> (f32, &'static str);

    /// How much larger a drop is here than the drop parameters say: (radius, strength).
    fn drop_scale(&self) -> (f32, f32) {
        (1.0, 1.0)
    }

    /// Puts `drop` (inside [`Scene::drop_area`]) in the scene's water.
    fn add_drop(&mut self, drop: Drop);

    /// A press of the pointer begins a new stroke: the next [`Scene::add_drop`] does not
    /// continue the last press's.
    fn begin_stroke(&mut self) {}

    /// The parameters the pointer set in the scene since the last call (a placed probe), for
    /// the demo to write into its table.
    fn take_param_edits(&mut self) -> Vec<(crate::params::ParamId, f32)> {
        Vec::new()
    }

    /// What was drawn in the scene with the pointer, as text for a share link ("" if nothing).
    fn sketch(&self) -> String {
        String::new()
    }

    /// Puts back what `text` (from [`Scene::sketch`]) says was drawn, or says why it cannot.
    fn set_sketch(&mut self, text: &str) -> Result<(), String> {
        match text.trim() {
            "" => Ok(()),
            _ => Err("nothing is drawn in this scene".into()),
        }
    }

    /// What the scene's instruments read now: (name, value, unit).
    fn readings(&self) -> Vec<(&'static str, f32, &'static str)> {
        Vec::new()
    }

    /// The thing the pointer picked that has settings of its own (the tank's dipper), if any.
    fn picked(&self) -> Option<Picked> {
        None
    }

    /// Sets the picked thing's setting `name` to `value` (in its unit, clamped to its range),
    /// or says why it cannot.
    fn set_picked(&mut self, _name: &str, _value: f32) -> Result<(), String> {
        Err("nothing is picked here".into())
    }

    /// The nearest body under pixel `pixel`: its id, the point hit and the origin of its frame.
    fn pick_body(&self, sh: Shared<'_>, pixel: Vec2) -> Option<(BodyId, Vec3, Vec3)>;

    /// Puts body `id`'s frame at `position` (dragged), kept where the scene keeps its bodies.
    fn move_body(&mut self, sh: Shared<'_>, id: BodyId, position: Vec3);

    /// Whether a press at column `x` (pixels) grabs a divider of the picture.
    fn grabs_divider(&self, _sh: Shared<'_>, _x: f32) -> bool {
        false
    }

    /// What lies under pixel `pixel`: the scene's water where drops fall, or nothing.
    fn pick_water(&self, viewport: Vec2, pixel: Vec2) -> Pick {
        self.camera().pick_within(pixel, viewport, self.drop_area().0)
    }
}

/// One of each scene, each keeping its state while another is shown.
pub struct Scenes {
    pub pool: pool::PoolScene,
    pub sea: sea::SeaScene,
    pub tank: tank::TankScene,
}

impl Scenes {
    /// The scenes at their starts, drawn by `renderer`: the pool of `shape` with `water`;
    /// `float_targets`: whether the device renders into float textures; `software`: whether it
    /// is a software rasteriser.
    pub fn new(
        (device, renderer): (&wgpu::Device, &Renderer),
        shape: crate::world::PoolShape,
        water: crate::sim::HeightField,
        float_targets: bool,
        software: bool,
    ) -> Self {
        let engine = water.engine();
        Self {
            pool: pool::PoolScene::new((device, renderer), shape, water, float_targets),
            sea: sea::SeaScene::new(engine, float_targets, software),
            tank: tank::TankScene::new(float_targets),
        }
    }

    /// The scene of `kind`.
    pub fn get(&self, kind: SceneKind) -> &dyn Scene {
        match kind {
            SceneKind::Pool => &self.pool,
            SceneKind::Sea => &self.sea,
            SceneKind::Tank => &self.tank,
        }
    }

    pub fn get_mut(&mut self, kind: SceneKind) -> &mut dyn Scene {
        match kind {
            SceneKind::Pool => &mut self.pool,
            SceneKind::Sea => &mut self.sea,
            SceneKind::Tank => &mut self.tank,
        }
    }

    /// Every scene, to reset them all.
    pub fn all_mut(&mut self) -> [&mut dyn Scene; 3] {
        [&mut self.pool, &mut self.sea, &mut self.tank]
    }
}

/// The limits of the camera of the scene of `kind`.
pub fn camera_limits(kind: SceneKind) -> crate::camera::CameraLimits {
    match kind {
        SceneKind::Pool => crate::camera::POOL_LIMITS,
        SceneKind::Sea => crate::sea::SEA_LIMITS,
        SceneKind::Tank => crate::tank::TANK_LIMITS,
    }
}

/// What `name`'s control is shown for: each condition a parameter and the values (of its
/// choices) that show it, all of them to hold; none for a control always shown. A model's own
/// settings need their model (`params::SHOWN_WHEN`); a scene's own parameters need that scene,
/// and the others the scenes that read them (the pool reads every parameter no other scene
/// owns).
pub fn shown_when(name: &str) -> Vec<(&'static str, Vec<f32>)> {
    let owns = |kind: SceneKind| match kind {
        SceneKind::Pool => false,
        SceneKind::Sea => sea::owns(name),
        SceneKind::Tank => tank::owns(name),
    };
    let reads = |kind: SceneKind| match kind {
        SceneKind::Pool => true,
        SceneKind::Sea => sea::reads(name),
        SceneKind::Tank => tank::reads(name),
    };
    let owners: Vec<SceneKind> = SceneKind::ALL.iter().copied().filter(|&k| owns(k)).collect();
    let showing =
        if owners.is_empty() { SceneKind::ALL.iter().copied().filter(|&k| reads(k)).collect() } else { owners };
    let mut conditions = crate::params::model_conditions(name);
    if showing.len() < SceneKind::ALL.len() {
        conditions.push((ParamId::Scene.name(), showing.iter().map(|&k| k.value()).collect()));
    }
    conditions
}

/// What every scene's picture shares: the camera's view, the sun, the optics, the exposure
/// and the render scale; no bodies, caustics, ambient waves, foam, debug view, flat water or
/// deck (a scene adds its own).
pub fn common_view(sh: Shared<'_>, camera: &OrbitCamera) -> View {
    let p = sh.params;
    View {
        view_proj: camera.view_projection(sh.viewport.x / sh.viewport.y),
        eye: camera.eye(),
        sun: sun(p),
        bodies: Default::default(),
        caustics: false,
        caustic_contrast: 1.0,
        optics: Optics {
            fresnel: p.choice(ParamId::Fresnel),
            specular: p.choice(ParamId::Specular),
            shininess: p.get(ParamId::Shininess),
            sun_size: p.get(ParamId::SunSize),
            show_reflectance: p.choice::<DebugChoice>(ParamId::DebugView) == DebugChoice::Reflectance,
            absorption: Vec3::new(
                p.get(ParamId::AbsorptionRed),
                p.get(ParamId::AbsorptionGreen),
                p.get(ParamId::AbsorptionBlue),
            ),
            scatter: Vec3::new(p.get(ParamId::ScatterRed), p.get(ParamId::ScatterGreen), p.get(ParamId::ScatterBlue)),
            view_colour: p.flag(ParamId::ViewColour),
            dispersion: p.get(ParamId::Dispersion),
        },
        ambient: Default::default(),
        foam: false,
        debug: None,
        render_scale: sh.render_scale,
        flat: None,
        exposure: p.get(ParamId::Exposure),
        deck: false,
        tile_gloss: p.get(ParamId::TileGloss),
    }
}

/// Unit vector towards the sun of the parameters.
pub fn sun(params: &Params) -> Vec3 {
    crate::world::sun_direction(params.get(ParamId::SunAzimuth), params.get(ParamId::SunElevation))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_controls_show_in_each_scene_only_what_it_reads() {
        let scene_of = |name: &str| shown_when(name).into_iter().find(|(on, _)| *on == "scene").map(|(_, v)| v);
        assert_eq!(scene_of("wave_speed"), Some(vec![0.0]), "the pool's own");
        assert_eq!(scene_of("sea_wind"), Some(vec![1.0]), "the sea's own");
        assert_eq!(scene_of("sun_elevation"), Some(vec![0.0, 1.0]), "read by the pool and the sea");
        assert_eq!(scene_of("exposure"), None, "read by all three");
        assert_eq!(scene_of("tank_setup"), Some(vec![2.0]), "the tank's own");
        assert_eq!(scene_of("scene"), None);
        assert_eq!(scene_of("objects"), Some(vec![0.0]), "the pool's bodies");
        assert_eq!(scene_of("sea_objects"), Some(vec![1.0]), "the sea's bodies");
        assert_eq!(scene_of("duck_density"), Some(vec![0.0, 1.0]), "a kind's own, read where bodies float");
        assert_eq!(shown_when("wind_speed").len(), 2, "an ambient model's own setting, in the pool");
        let counts: Vec<usize> = SceneKind::ALL
            .iter()
            .map(|k| {
                crate::params::table()
                    .iter()
                    .filter(|p| scene_of(p.name).is_none_or(|v| v.contains(&k.value())))
                    .count()
            })
            .collect();
        println!("controls shown: {counts:?} of {} (pool, sea, tank)", crate::params::table().len());
        assert!(counts.iter().all(|&n| n > 10 && n < crate::params::table().len()));
    }
}
