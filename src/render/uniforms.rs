//! The scene uniforms every scene pass reads (group 0, binding 0), written once per frame
//! from the [`View`].

use glam::Mat4;

use super::{flat, flat_shown, Renderer, View};
use crate::ambient::MAX_AMBIENT_WAVES;
use crate::bodies::duck;
use crate::optics;
use crate::scene;
use crate::sim::HeightField;

#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
pub(super) struct SceneUniforms {
    pub(super) view_proj: [[f32; 4]; 4],
    pub(super) inv_view_proj: [[f32; 4]; 4],
    pub(super) eye: [f32; 4],
    pub(super) sun: [f32; 4],
    pub(super) refracted_sun: [f32; 4],
    pub(super) sphere: [f32; 4],
    pub(super) pool: [f32; 4],
    pub(super) water: [f32; 4],
    pub(super) output: [f32; 4],
    pub(super) optics: [f32; 4],
    pub(super) absorption: [f32; 4],
    pub(super) scatter: [f32; 4],
    pub(super) ior: [f32; 4],
    pub(super) duck_pose: [[f32; 4]; 4],
    pub(super) duck_bound: [f32; 4],
    pub(super) duck_parts: [[f32; 4]; 3 * duck::TRACED_PARTS.len()],
    pub(super) ambient_header: [f32; 4],
    pub(super) ambient_waves: [[f32; 4]; MAX_AMBIENT_WAVES],
    pub(super) flat: [f32; 4],
    pub(super) sun_light: [f32; 4],
    pub(super) sky_light: [f32; 4],
}

/// The duck's traced parts as the scene shader takes them: per part its centre and semi-axes
/// in the duck's frame (m), and its colour.
pub(super) fn duck_parts() -> [[f32; 4]; 3 * duck::TRACED_PARTS.len()] {
    let mut out = [[0.0; 4]; 3 * duck::TRACED_PARTS.len()];
    for (slots, part) in out.chunks_mut(3).zip(&duck::TRACED_PARTS) {
        slots[0] = part.shape.centre.extend(0.0).to_array();
        slots[1] = part.shape.radii.extend(0.0).to_array();
        slots[2] = part.colour.extend(1.0).to_array();
    }
    out
}

impl Renderer {
    /// Writes this frame's uniforms and repaints the sky if the sun moved.
    /// Call once per submission, before [`Renderer::encode_caustics`] and [`Renderer::encode_scene`].
    pub fn prepare(
        &mut self,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        view: &View,
        water: &HeightField,
    ) {
        self.sky_cube.update(queue, encoder, view.sun);
        let daylight = *self.sky_cube.daylight();
        let sphere = view.sphere.map_or([0.0; 4], |s| [s.centre.x, s.centre.y, s.centre.z, s.radius]);
        let refracted = scene::refracted_sun(view.sun);
        let n = water.size() as f32;
        let u = SceneUniforms {
            view_proj: view.view_proj.to_cols_array_2d(),
            inv_view_proj: view.view_proj.inverse().to_cols_array_2d(),
            eye: view.eye.extend(1.0).to_array(),
            sun: [view.sun.x, view.sun.y, view.sun.z, 0.0],
            refracted_sun: refracted.extend(0.0).to_array(),
            sphere,
            pool: [scene::HALF_WIDTH, scene::DEPTH, scene::RIM, 0.0],
            water: [n, 1.0 / n, if view.caustics { 1.0 } else { 0.0 }, self.settings.caustics_format().1],
            output: [
                if self.settings.target_format.is_srgb() { 0.0 } else { 1.0 },
                view.debug.map_or(0.0, |d| d.texture as u32 as f32),
                0.0,
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
            duck_pose: view
                .duck
                .map_or(Mat4::IDENTITY, |p| Mat4::from_rotation_translation(p.rotation, p.position))
                .to_cols_array_2d(),
            duck_bound: view.duck.map_or([0.0; 4], |p| p.position.extend(duck::bounding_radius()).to_array()),
            duck_parts: duck_parts(),
            ambient_header: view.ambient.header,
            ambient_waves: view.ambient.waves,
            flat: view.flat.map_or([0.0; 4], |f| f.uniform()),
            sun_light: daylight.sun_light.extend(2f32.powf(view.exposure)).to_array(),
            sky_light: daylight.ambient.extend(if view.deck { 1.0 } else { 0.0 }).to_array(),
        };
        queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&u));
        if let Some(f) = flat_shown(view) {
            // The mirrored camera: everything it sees is above the water, so nothing is dimmed
            // by water on the way (no absorption, no scattering).
            let mirrored = view.view_proj * flat::mirror(f.plane);
            let eye = view.eye * glam::Vec3::new(1.0, -1.0, 1.0) + glam::Vec3::new(0.0, 2.0 * f.plane, 0.0);
            let m = SceneUniforms {
                view_proj: mirrored.to_cols_array_2d(),
                inv_view_proj: mirrored.inverse().to_cols_array_2d(),
                eye: eye.extend(1.0).to_array(),
                absorption: [0.0; 4],
                scatter: [0.0; 4],
                ..u
            };
            queue.write_buffer(&self.mirror_uniforms, 0, bytemuck::bytes_of(&m));
        }
    }
}
