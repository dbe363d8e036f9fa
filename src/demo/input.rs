//! Input to the demo: pointer presses and drags (drops, orbiting, dragging a body or the
//! split view's divider), the wheel and keys.

use glam::{Vec2, Vec3};

use super::{BodyId, WaterDemo};
use crate::camera::Pick;
use crate::params::ParamId;
use crate::scenes::SceneKind;
use crate::sim::{random_drops, Drop};
use crate::world;

/// Seed of the drops the pool starts with: every start shows the same first picture.
pub const START_DROPS_SEED: u64 = 2011;

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

impl Drag {
    /// The body held, if any.
    pub(super) fn held(&self) -> Option<BodyId> {
        match self {
            Drag::Body { id, .. } => Some(*id),
            _ => None,
        }
    }
}

impl WaterDemo {
    /// Sets the size (pixels) of the viewport that pointer coordinates refer to.
    pub fn set_viewport(&mut self, width: u32, height: u32) {
        self.viewport = Vec2::new(width.max(1) as f32, height.max(1) as f32);
    }

    /// Queues a drop at (x, z) in the shown scene's water (m, clamped into its
    /// [`WaterDemo::drop_area`]) with radius (m) and strength (m), clamped into the parameter
    /// ranges and then grown as the scene grows a click's drop (the sea's patch is wider than
    /// the pool).
    pub fn add_drop(&mut self, x: f32, z: f32, radius: f32, strength: f32) {
        let r = crate::params::spec(ParamId::DropRadius).sanitise(radius);
        let s = crate::params::spec(ParamId::DropStrength).sanitise(strength);
        if !(x.is_finite() && z.is_finite()) {
            return;
        }
        let scene = self.scenes.get_mut(self.shown);
        let ((w, _), (kr, ks)) = (scene.drop_area(), scene.drop_scale());
        scene.add_drop(Drop { x: x.clamp(-w, w), z: z.clamp(-w, w), radius: r * kr, strength: s * ks });
        for (id, value) in scene.take_param_edits() {
            self.params.set(id, value);
        }
    }

    /// Drops the pool's water with the drops it starts with (`start_drops`, seeded, each at
    /// the drop parameters' radius and strength, alternately raising and lowering the water,
    /// as the classic's twenty at its start); the other scenes start as they are (the sea moves
    /// of itself and the tank's lessons start still).
    pub fn add_start_drops(&mut self) {
        self.sync_scene();
        if self.shown != SceneKind::Pool {
            return;
        }
        let count = self.params.get(ParamId::StartDrops).round() as u32;
        self.add_random_drops(START_DROPS_SEED, count);
    }

    /// `count` drops at places seeded by `seed` over the shown scene's water (in the sea its
    /// patch, where a drop grows as the patch is wider), at the drop parameters' radius and
    /// strength, alternately raising and lowering the water.
    pub fn add_random_drops(&mut self, seed: u64, count: u32) {
        let (over, _) = self.drop_area();
        let (radius, strength) = (self.params.get(ParamId::DropRadius), self.params.get(ParamId::DropStrength));
        self.begin_stroke();
        for d in random_drops(seed, count, over, radius, strength) {
            self.add_drop(d.x, d.z, d.radius, d.strength);
        }
    }

    /// Tells the shown scene that what comes next is not the last stroke's continuation (a
    /// press of the pointer, a drop from a script).
    pub fn begin_stroke(&mut self) {
        self.scenes.get_mut(self.shown).begin_stroke();
    }

    /// What was drawn in the shown scene with the pointer, as text for a share link.
    pub fn sketch(&self) -> String {
        self.scenes.get(self.shown).sketch()
    }

    /// Puts back what `text` says was drawn in the shown scene, or says why it cannot.
    pub fn set_sketch(&mut self, text: &str) -> Result<(), String> {
        self.sync_scene();
        self.scenes.get_mut(self.shown).set_sketch(text)
    }

    /// What the shown scene's instruments read now: (name, value, unit).
    pub fn readings(&self) -> Vec<(&'static str, f32, &'static str)> {
        self.scenes.get(self.shown).readings()
    }

    /// What the pointer picked in the shown scene that has settings of its own (a dipper).
    pub fn picked(&self) -> Option<crate::scenes::Picked> {
        self.scenes.get(self.shown).picked()
    }

    /// Sets the picked thing's setting `name` to `value`, or says why it cannot.
    pub fn set_picked(&mut self, name: &str, value: f32) -> Result<(), String> {
        self.sync_scene();
        self.scenes.get_mut(self.shown).set_picked(name, value)
    }

    /// A drop with the current radius and strength parameters.
    fn click_drop(&mut self, x: f32, z: f32) {
        self.add_drop(x, z, self.params.get(ParamId::DropRadius), self.params.get(ParamId::DropStrength));
    }

    /// The nearest body under pixel (x, y) and the point hit (m), if any.
    pub fn pick_body(&self, pixel: Vec2) -> Option<(BodyId, Vec3)> {
        self.scenes.get(self.shown).pick_body(shared!(self), pixel).map(|(id, hit, _)| (id, hit))
    }

    /// Whether a press at column `x` (pixels) grabs a divider of the picture (the pool's split
    /// view's).
    pub fn over_divider(&self, x: f32) -> bool {
        self.scenes.get(self.shown).grabs_divider(shared!(self), x)
    }

    /// Pointer pressed at pixel (x, y): on a divider moves it; on a body starts moving it, on
    /// the water starts drawing ripples, elsewhere starts orbiting.
    pub fn pointer_down(&mut self, x: f32, y: f32) {
        let p = Vec2::new(x, y);
        if self.over_divider(x) {
            self.drag = Drag::Divider;
            return;
        }
        let scene = self.scenes.get(self.shown);
        if let Some((id, hit, centre)) = scene.pick_body(shared!(self), p) {
            let plane_normal = (scene.camera().eye() - hit).normalize();
            self.drag = Drag::Body { id, offset: centre - hit, plane_normal, plane_point: hit };
            return;
        }
        self.drag = match scene.pick_water(self.viewport, p) {
            Pick::Water { x, z } => {
                self.scenes.get_mut(self.shown).begin_stroke();
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
                self.camera_mut().orbit(d.x, d.y);
                self.drag = Drag::Orbit { last: p };
            }
            Drag::Water { last } => {
                // Drops along the stroke, about one per drop radius, so fast drags draw lines.
                let scene = self.scenes.get(self.shown);
                let from = scene.pick_water(self.viewport, last);
                let to = scene.pick_water(self.viewport, p);
                if let (Pick::Water { x: x0, z: z0 }, Pick::Water { x: x1, z: z1 }) = (from, to) {
                    let r = self.params.get(ParamId::DropRadius) * scene.drop_scale().0;
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
                let ray = self.camera().ray(p, self.viewport);
                let denom = ray.dir.dot(plane_normal);
                if denom.abs() > 1e-5 {
                    let t = (plane_point - ray.origin).dot(plane_normal) / denom;
                    if t > 0.0 {
                        let sh = shared!(self);
                        self.scenes.get_mut(self.shown).move_body(sh, id, ray.origin + ray.dir * t + offset);
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
        self.camera_mut().zoom((amount * 0.1).clamp(-2.0, 2.0).exp());
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
                let (azimuth, elevation) = world::direction_angles(self.camera().back());
                self.params.set(ParamId::SunAzimuth, azimuth);
                self.params.set(ParamId::SunElevation, elevation);
            }
        }
    }
}
