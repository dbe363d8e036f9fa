//! The scene uniforms every scene pass reads (group 0, binding 0), written once per frame
//! from the [`View`].

use glam::{Mat4, Vec3};

use super::{Renderer, View};
use crate::ambient::MAX_AMBIENT_WAVES;
use crate::bodies::{BodyId, UNIFORM_SLOTS};
use crate::optics;
use crate::sim::HeightField;
use crate::world;

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub(super) struct SceneUniforms {
    pub(super) view_proj: [[f32; 4]; 4],
    pub(super) inv_view_proj: [[f32; 4]; 4],
    pub(super) eye: [f32; 4],
    pub(super) sun: [f32; 4],
    pub(super) refracted_sun: [f32; 4],
    pub(super) pool: [f32; 4],
    pub(super) water: [f32; 4],
    pub(super) output: [f32; 4],
    pub(super) optics: [f32; 4],
    pub(super) absorption: [f32; 4],
    pub(super) scatter: [f32; 4],
    pub(super) ior: [f32; 4],
    pub(super) ambient_header: [f32; 4],
    pub(super) ambient_waves: [[f32; 4]; MAX_AMBIENT_WAVES],
    pub(super) flat: [f32; 4],
    pub(super) sun_light: [f32; 4],
    pub(super) sky_light: [f32; 4],
    pub(super) floor_bounce: [f32; 4],
    pub(super) horizon: [[f32; 4]; super::deck::HORIZON_TERMS],
    pub(super) bodies: [[f32; 4]; UNIFORM_SLOTS],
}

/// Every kind's share of the uniform's `bodies` array, for the drawn bodies of `view`.
fn bodies_uniform(view: &View) -> [[f32; 4]; UNIFORM_SLOTS] {
    let mut out = [[0.0; 4]; UNIFORM_SLOTS];
    let mut at = 0;
    for id in BodyId::all() {
        let kind = id.kind();
        (kind.uniform)(view.bodies[id.0].as_ref(), &mut out[at..at + kind.uniform_slots]);
        at += kind.uniform_slots;
    }
    out
}

impl Renderer {
    /// Writes this frame's uniforms and repaints the sky if the sun moved.
    /// Call once per submission, before the scene's passes.
    pub fn prepare(
        &mut self,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        view: &View,
        water: &HeightField,
    ) {
        self.sky_cube.update(queue, encoder, view.sun);
        let daylight = *self.sky_cube.daylight();
        if self.horizon.0 != daylight.sun {
            self.horizon = (daylight.sun, super::deck::horizon_fit(&daylight));
        }
        let refracted = world::refracted_sun(view.sun);
        let n = water.size() as f32;
        let u = SceneUniforms {
            view_proj: view.view_proj.to_cols_array_2d(),
            inv_view_proj: view.view_proj.inverse().to_cols_array_2d(),
            eye: view.eye.extend(1.0).to_array(),
            sun: [view.sun.x, view.sun.y, view.sun.z, 0.0],
            refracted_sun: refracted.extend(0.0).to_array(),
            pool: [self.settings.pool.half_width, self.settings.pool.depth, self.settings.pool.rim, view.tile_gloss],
            water: [n, 1.0 / n, view.caustic_contrast, self.settings.caustics_format().1],
            output: [
                0.0,
                view.debug.map_or(0.0, |d| d.texture as u32 as f32),
                if self.body_outlines { 1.0 } else { 0.0 },
                0.0,
            ],
            optics: {
                let (edge, core) = optics::sun_disk_cosines(view.optics.sun_size);
                [view.optics.shininess, edge, core, 0.0]
            },
            absorption: view.optics.absorption.extend(0.0).to_array(),
            scatter: view.optics.scatter.extend(0.0).to_array(),
            ior: {
                let [r, g, b] = optics::channel_iors(view.optics.dispersion);
                [r, g, b, view.optics.dispersion]
            },
            ambient_header: view.ambient.header,
            ambient_waves: view.ambient.waves,
            flat: view.flat.map_or([0.0; 4], |f| f.uniform()),
            // The exposure parameter, and the part the camera adapts to this sky by itself.
            sun_light: daylight.sun_light.extend(2f32.powf(view.exposure + daylight.adapted_exposure())).to_array(),
            sky_light: daylight.ambient.extend(if view.deck { 1.0 } else { 0.0 }).to_array(),
            // The calm floor's light (the refracted sun's and the sky's under the water) times
            // the tiles' mean albedo: what it sends back up (light_under_water).
            floor_bounce: (self.floor_albedo
                * (daylight.sun_light * -refracted.y + daylight.ambient * crate::sky::UNDERWATER_SKY))
                .extend(0.0)
                .to_array(),
            horizon: self.horizon.1,
            bodies: bodies_uniform(view),
        };
        queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&u));
        self.frame_uniforms = u;
    }

    /// Writes this frame's uniforms (from the last [`Renderer::prepare`], so call it after the
    /// scene's own `prepare` in the same frame) as seen by another
    /// camera into `buffer`: one that sees only what is above the water (the flat water's
    /// mirrored camera), so nothing is dimmed by water on the way (no absorption, no
    /// scattering).
    pub fn write_uniforms_above_water(&self, queue: &wgpu::Queue, buffer: &wgpu::Buffer, view_proj: Mat4, eye: Vec3) {
        let u = SceneUniforms {
            view_proj: view_proj.to_cols_array_2d(),
            inv_view_proj: view_proj.inverse().to_cols_array_2d(),
            eye: eye.extend(1.0).to_array(),
            absorption: [0.0; 4],
            scatter: [0.0; 4],
            ..self.frame_uniforms
        };
        queue.write_buffer(buffer, 0, bytemuck::bytes_of(&u));
    }
}
