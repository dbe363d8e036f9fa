//! Input to the demo: pointer presses and drags (drops, orbiting, dragging a body or the
//! split view's divider), the wheel and keys.

use glam::{Vec2, Vec3};

use super::{BodyId, WaterDemo};
use crate::camera::Pick;
use crate::params::ParamId;
use crate::physics::Pose;
use crate::render::RenderMode;
use crate::scene;
use crate::sea::{self, SceneKind};
use crate::sim::Drop;

/// Keys the core understands; shells map their key events to these.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Key {
    /// Pause or resume the water.
    Space,
    /// Put the sun behind the camera.
    L,
    /// Toggle gravity on the sphere.
    G,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Drag {
    None,
    Orbit {
        last: Vec2,
    },
    Water {
        last: Vec2,
    },
    Body {
        id: BodyId,
        offset: Vec3,
        plane_normal: Vec3,
        plane_point: Vec3,
    },
    /// The split view's divider.
    Divider,
}

/// How near (pixels) to the split view's divider a press grabs it.
pub const DIVIDER_GRAB_PX: f32 = 12.0;

impl WaterDemo {
    /// Sets the size (pixels) of the viewport that pointer coordinates refer to.
    pub fn set_viewport(&mut self, width: u32, height: u32) {
        self.viewport = Vec2::new(width.max(1) as f32, height.max(1) as f32);
    }

    /// Queues a drop at pool coordinates (m) with radius (m) and strength (m); values are
    /// clamped into the parameter ranges. In the open sea the drop falls in its patch of
    /// simulated water (sea coordinates, m), radius and strength grown as the patch is wider
    /// than the pool (`sea::patch_scale`).
    pub fn add_drop(&mut self, x: f32, z: f32, radius: f32, strength: f32) {
        let r = crate::params::spec(ParamId::DropRadius).sanitise(radius);
        let s = crate::params::spec(ParamId::DropStrength).sanitise(strength);
        if !(x.is_finite() && z.is_finite()) {
            return;
        }
        let (w, k) = (sea::PATCH_HALF_WIDTH, sea::patch_scale());
        let (radius, strength) = (r * k, s * k * sea::PATCH_DROP_HEIGHT);
        if self.drop_in_sea(Drop { x: x.clamp(-w, w), z: z.clamp(-w, w), radius, strength }) {
            return;
        }
        let w = scene::HALF_WIDTH;
        self.water.add_drop(Drop { x: x.clamp(-w, w), z: z.clamp(-w, w), radius: r, strength: s });
    }

    /// What lies under pixel p: the water of the scene drawn (the pool's, or the sea's patch).
    fn pick_water(&self, p: Vec2) -> Pick {
        if self.drawn_scene() == SceneKind::Sea {
            return self.camera.pick_within(p, self.viewport, sea::PATCH_HALF_WIDTH);
        }
        self.camera.pick(p, self.viewport)
    }

    /// A drop with the current radius and strength parameters.
    pub(super) fn click_drop(&mut self, x: f32, z: f32) {
        self.add_drop(x, z, self.params.get(ParamId::DropRadius), self.params.get(ParamId::DropStrength));
    }

    /// The nearest body under pixel (x, y) and the point hit (m), if any.
    pub fn pick_body(&self, pixel: Vec2) -> Option<(BodyId, Vec3)> {
        let ray = self.camera.ray(pixel, self.viewport);
        let value = |name: &str| self.params.get_by_name(name).expect("a body kind reads its own parameters");
        let mut nearest: Option<(BodyId, f32)> = None;
        for id in BodyId::all().filter(|&id| self.shows(id)) {
            let t = (id.kind().pick)(&self.body(id).pose, &value, ray.origin, ray.dir);
            if let Some(t) = t.filter(|&t| nearest.is_none_or(|(_, best)| t < best)) {
                nearest = Some((id, t));
            }
        }
        nearest.map(|(id, t)| (id, ray.origin + ray.dir * t))
    }

    /// Whether a press at column `x` (pixels) grabs the split view's divider (shown only in
    /// the split view with the camera above the water).
    pub fn over_divider(&self, x: f32) -> bool {
        self.params.choice::<RenderMode>(ParamId::RenderMode) == RenderMode::Split
            && (x - self.params.get(ParamId::Split) * self.viewport.x).abs() <= DIVIDER_GRAB_PX
            && self.flat_water_drawn()
    }

    /// Pointer pressed at pixel (x, y): on the split view's divider moves it; on a body (in
    /// the pool or the sea) starts moving it, on the water starts drawing ripples, elsewhere
    /// starts orbiting.
    pub fn pointer_down(&mut self, x: f32, y: f32) {
        let p = Vec2::new(x, y);
        if self.drawn_scene() == SceneKind::Sea {
            if let Some((id, hit, centre)) = self.pick_sea_body(p) {
                let plane_normal = (self.camera.eye() - hit).normalize();
                self.drag = Drag::Body { id, offset: centre - hit, plane_normal, plane_point: hit };
                return;
            }
            self.drag = match self.pick_water(p) {
                Pick::Water { x, z } => {
                    self.click_drop(x, z);
                    Drag::Water { last: p }
                }
                Pick::Nothing => Drag::Orbit { last: p },
            };
            return;
        }
        if self.over_divider(x) {
            self.drag = Drag::Divider;
            return;
        }
        if let Some((id, hit)) = self.pick_body(p) {
            let centre = self.bodies[id.0].motion.pose.position;
            let plane_normal = (self.camera.eye() - hit).normalize();
            self.drag = Drag::Body { id, offset: centre - hit, plane_normal, plane_point: hit };
            return;
        }
        self.drag = match self.camera.pick(p, self.viewport) {
            Pick::Water { x, z } => {
                self.click_drop(x, z);
                Drag::Water { last: p }
            }
            Pick::Nothing => Drag::Orbit { last: p },
        };
    }

    pub fn pointer_move(&mut self, x: f32, y: f32) {
        let p = Vec2::new(x, y);
        match self.drag {
            Drag::None => {}
            Drag::Divider => {
                self.params.set(ParamId::Split, x / self.viewport.x.max(1.0));
            }
            Drag::Orbit { last } => {
                let d = p - last;
                self.camera.orbit(d.x, d.y);
                self.drag = Drag::Orbit { last: p };
            }
            Drag::Water { last } => {
                // Drops along the stroke, about one per drop radius, so fast drags draw lines.
                let from = self.pick_water(last);
                let to = self.pick_water(p);
                if let (Pick::Water { x: x0, z: z0 }, Pick::Water { x: x1, z: z1 }) = (from, to) {
                    let scale = if self.drawn_scene() == SceneKind::Sea { sea::patch_scale() } else { 1.0 };
                    let r = self.params.get(ParamId::DropRadius) * scale;
                    let length = Vec2::new(x1 - x0, z1 - z0).length();
                    let count = ((length / r).ceil() as u32).clamp(1, 16);
                    for i in 1..=count {
                        let t = i as f32 / count as f32;
                        self.click_drop(x0 + (x1 - x0) * t, z0 + (z1 - z0) * t);
                    }
                } else if let Pick::Water { x, z } = to {
                    self.click_drop(x, z);
                }
                self.drag = Drag::Water { last: p };
            }
            Drag::Body { id, offset, plane_normal, plane_point } => {
                let ray = self.camera.ray(p, self.viewport);
                let denom = ray.dir.dot(plane_normal);
                if denom.abs() > 1e-5 {
                    let t = (plane_point - ray.origin).dot(plane_normal) / denom;
                    if t > 0.0 && self.drawn_scene() == SceneKind::Sea {
                        self.set_sea_body(id, ray.origin + ray.dir * t + offset, Vec3::ZERO);
                    } else if t > 0.0 {
                        let rotation = self.bodies[id.0].motion.pose.rotation;
                        self.set_body_pose(id, Pose { position: ray.origin + ray.dir * t + offset, rotation });
                    }
                }
            }
        }
    }

    pub fn pointer_up(&mut self) {
        self.drag = Drag::None;
    }

    /// Mouse wheel or pinch: positive moves the camera away.
    pub fn zoom(&mut self, amount: f32) {
        self.camera.zoom((amount * 0.1).clamp(-2.0, 2.0).exp());
    }

    pub fn key(&mut self, key: Key) {
        match key {
            Key::Space => {
                let paused = self.params.flag(ParamId::Paused);
                self.params.set(ParamId::Paused, if paused { 0.0 } else { 1.0 });
            }
            Key::G => {
                // Gravity on the sphere and the duck.
                let on = self.params.flag(ParamId::Gravity);
                self.params.set(ParamId::Gravity, if on { 0.0 } else { 1.0 });
            }
            Key::L => {
                let (azimuth, elevation) = scene::direction_angles(self.camera.back());
                self.params.set(ParamId::SunAzimuth, azimuth);
                self.params.set(ParamId::SunElevation, elevation);
            }
        }
    }
}
