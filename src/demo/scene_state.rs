//! What the shells and the tests read and set of a scene's own state: the pool's water and
//! bodies, the sea's waves, patch and bodies, and switches tests compare with.

use glam::Vec3;

use super::{BodyId, WaterDemo};
use crate::ambient::gpu_ocean::GpuOcean;
use crate::ambient::AmbientWaves;
use crate::physics::{FloatingBody, Pose};
use crate::scenes::pool::PoolScene;
use crate::sea::SeaSettings;
use crate::sim::{HeightField, WaterLevel};
use crate::world::Sphere;

/// The pool's state.
impl WaterDemo {
    pub fn water(&self) -> &HeightField {
        self.scenes.pool.water()
    }

    /// Mean and largest |height| of the pool's water (m), read back asynchronously, a frame or
    /// two old; `None` before the first read has completed.
    pub fn water_level(&self) -> Option<WaterLevel> {
        self.scenes.pool.water().level()
    }

    /// The pool's ambient waves (heights in m at simulated time [`WaterDemo::sim_time`]).
    pub fn ambient(&self) -> &AmbientWaves {
        self.scenes.pool.ambient()
    }

    /// The GPU's FFT ocean, once the FFT ocean has been drawn on the GPU path (for tests).
    pub fn gpu_ocean(&self) -> Option<&GpuOcean> {
        self.scenes.pool.gpu_ocean()
    }

    /// Whether a body is in the pool (its bit in the `objects` parameter).
    pub fn shows(&self, id: BodyId) -> bool {
        PoolScene::shows(&self.params, id)
    }

    /// The pool's sphere as drawn, if shown.
    pub fn sphere(&self) -> Option<Sphere> {
        self.scenes.pool.sphere(shared!(self))
    }

    /// The pool's duck's pose, if shown.
    pub fn duck(&self) -> Option<Pose> {
        self.scenes.pool.duck(&self.params)
    }

    /// A body's motion in the pool (shown or not).
    pub fn body(&self, id: BodyId) -> &FloatingBody {
        self.scenes.pool.body(id)
    }

    pub fn set_sphere_centre(&mut self, centre: Vec3) {
        let sh = shared!(self);
        self.scenes.pool.set_sphere_centre(sh, centre);
    }

    /// Puts a body of the pool somewhere (kept inside the pool) and stops it.
    pub fn set_body_pose(&mut self, id: BodyId, pose: Pose) {
        let sh = shared!(self);
        self.scenes.pool.set_body_pose(sh, id, pose);
    }

    /// See [`PoolScene::probe_latency`].
    pub fn probe_latency(&self) -> Option<u64> {
        self.scenes.pool.probe_latency()
    }

    /// Volume (m³) of the pool's bodies under water after the last step.
    pub fn submerged_volume(&self) -> f32 {
        self.scenes.pool.submerged_volume(&self.params)
    }

    /// The flat water's reflection texture, once flat water has been drawn (for tests).
    #[doc(hidden)]
    pub fn flat_reflection_texture(&self) -> Option<&wgpu::Texture> {
        self.scenes.pool.passes().flat_reflection_texture()
    }

    /// Whether the pool's flat water is drawn now: the pool shown, flat or split chosen and the
    /// camera above the water (it is an above-water technique; under water the ray tracer
    /// draws).
    pub fn flat_water_drawn(&self) -> bool {
        self.scenes.get(self.shown).has_render_modes() && self.scenes.pool.flat_water_drawn(shared!(self))
    }

    /// Why the chosen flat water is not drawn in the pool shown, if it is not (for the page and
    /// the viewer; nothing in a scene without render modes): the id of its message in
    /// `page_words` and the catalogues.
    pub fn flat_water_note(&self) -> Option<&'static str> {
        self.scenes
            .get(self.shown)
            .has_render_modes()
            .then(|| self.scenes.pool.flat_water_note(shared!(self)))
            .flatten()
    }
}

/// The open sea's state.
impl WaterDemo {
    /// The sea's settings in the parameters.
    pub fn sea_settings(&self) -> SeaSettings {
        crate::scenes::sea::sea_settings(&self.params)
    }

    /// Whether a body floats in the sea (its bit in the `sea_objects` parameter).
    pub fn in_sea(&self, id: BodyId) -> bool {
        crate::scenes::sea::in_sea(&self.params, id)
    }

    /// A body's motion in the sea, once the sea has been drawn (for tests).
    pub fn sea_body(&self, id: BodyId) -> Option<&FloatingBody> {
        self.scenes.sea.body(id)
    }

    /// Puts a body of the sea somewhere (kept over the patch's middle) and sets it moving at
    /// `velocity` (m/s), once the sea has been drawn (for tests).
    pub fn set_sea_body(&mut self, id: BodyId, position: Vec3, velocity: Vec3) {
        let sh = shared!(self);
        self.scenes.sea.set_body(sh, id, position, velocity);
    }

    /// Height (m) of the sea's waves above world (x, z) in the last frame drawn (without the
    /// patch's ripples), once the sea has been drawn (for tests).
    pub fn sea_height_at(&self, x: f32, z: f32) -> Option<f32> {
        self.scenes.sea.height_at(x, z)
    }

    /// The sea's patch of simulated water, once the sea has been drawn (for tests).
    pub fn sea_patch(&self) -> Option<&HeightField> {
        self.scenes.sea.patch()
    }

    /// Whether the sea draws its whitecaps, keeps them over time (else its map holds only each
    /// frame's own), and draws its shore's foam (the default: all three) or not (for tests to
    /// compare with).
    #[doc(hidden)]
    pub fn set_sea_foam(&mut self, whitecaps: bool, kept: bool, shore: bool) {
        let extras = &mut self.scenes.sea.extras;
        (extras.whitecaps, extras.kept_whitecaps, extras.shore_foam) = (whitecaps, kept, shore);
    }

    /// Whether the sea mirrors its floating bodies (the default) or not (for tests to compare
    /// with).
    #[doc(hidden)]
    pub fn set_sea_body_mirror(&mut self, on: bool) {
        self.scenes.sea.extras.mirrored_bodies = on;
    }

    /// See [`crate::scenes::sea::SeaScene::set_fft_on_gpu`].
    #[doc(hidden)]
    pub fn set_sea_fft_on_gpu(&mut self, on: bool) {
        self.scenes.sea.set_fft_on_gpu(on);
    }
}

/// The ripple tank's state.
impl WaterDemo {
    pub fn tank(&self) -> &crate::scenes::tank::TankScene {
        &self.scenes.tank
    }
}
