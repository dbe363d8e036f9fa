//! The floating bodies in the pool, one per kind of `bodies::KINDS`: placed at their starts,
//! stepped against the water planes under them, kept apart, and the water's answer to them.
//! Nothing here names a kind: what differs between kinds is in their table entries.

use glam::{Vec2, Vec3};

use super::PoolScene;
use crate::ambient::AmbientModel;
use crate::bodies::{bump_apart, ring, Body, BodyId, BodyView, AMBIENT_RING_RADIUS, KINDS, PROBES_PER_BODY};
use crate::params::{ParamId, Params};
use crate::physics::{self, Ellipsoid, FloatingBody, Pose, Shape, WaterPlane};
use crate::scenes::{Shared, STEP_DT};
use crate::sim::{self, BodyCoupling, HullMove};
use crate::world::Sphere;

impl PoolScene {
    /// Every body at its start, at rest, not yet felt by the water (its submerged volume
    /// kept until the next step measures it again).
    pub(super) fn place_bodies_at_start(&mut self, sh: Shared<'_>) {
        let value = |name: &str| sh.value(name);
        let bodies: Vec<Body> = BodyId::all()
            .map(|id| Body {
                submerged: self.bodies.get(id.0).map_or(0.0, |b| b.submerged),
                ..Body::at((id.kind().start)(&value))
            })
            .collect();
        self.bodies = bodies;
    }

    /// Whether a body is in the pool (its bit in the `objects` parameter).
    pub fn shows(params: &Params, id: BodyId) -> bool {
        let objects = params.get(ParamId::Objects) as u32;
        objects & id.bit() != 0
    }

    /// Every kind's body as the renderer draws it, if shown.
    pub(super) fn drawn_bodies(&self, sh: Shared<'_>) -> [Option<BodyView>; KINDS.len()] {
        let value = |name: &str| sh.value(name);
        std::array::from_fn(|k| {
            let id = BodyId(k);
            Self::shows(sh.params, id).then(|| (id.kind().drawn)(&self.bodies[k].motion.pose, &value))
        })
    }

    /// The sphere as drawn, if shown.
    pub fn sphere(&self, sh: Shared<'_>) -> Option<Sphere> {
        let id = BodyId::named("sphere")?;
        Self::shows(sh.params, id)
            .then(|| crate::bodies::sphere::drawn(&self.bodies[id.0].motion.pose, sh.value("sphere_radius")))
    }

    /// The duck's pose, if shown.
    pub fn duck(&self, params: &Params) -> Option<Pose> {
        let id = BodyId::named("duck")?;
        Self::shows(params, id).then_some(self.bodies[id.0].motion.pose)
    }

    /// A body's motion (shown or not).
    pub fn body(&self, id: BodyId) -> &FloatingBody {
        &self.bodies[id.0].motion
    }

    pub fn set_sphere_centre(&mut self, sh: Shared<'_>, centre: Vec3) {
        if let Some(id) = BodyId::named("sphere") {
            self.set_body_pose(sh, id, Pose::at(centre));
        }
    }

    /// Puts a body somewhere (kept inside the pool) and stops it.
    pub fn set_body_pose(&mut self, sh: Shared<'_>, id: BodyId, pose: Pose) {
        if pose.position.is_finite() && pose.rotation.is_finite() {
            let mut pose = Pose { position: pose.position, rotation: pose.rotation.normalize() };
            physics::keep_in_pool(&mut pose, &sh.hull(id), self.shape);
            self.bodies[id.0].motion = FloatingBody::at(pose);
        }
    }

    /// Frames between the water heights the bodies last used and the frame that used them:
    /// 1, the heights of the water as the frame starts (sampled on the CPU at the end of the
    /// frame before, see [`HeightField::probes`]); `None` before the first frame.
    pub fn probe_latency(&self) -> Option<u64> {
        self.probe_latency
    }

    /// Volume (m³) of the bodies under water after the last step.
    pub fn submerged_volume(&self, params: &Params) -> f32 {
        BodyId::all().filter(|&id| Self::shows(params, id)).map(|id| self.bodies[id.0].submerged).sum()
    }

    /// The water plane under each body from the newest probe heights plus the ambient waves
    /// there now (flat at the rest level before any probes have arrived).
    fn water_planes(&mut self, sh: Shared<'_>) -> Vec<WaterPlane> {
        let frame = self.water.frames() + 1;
        let level = self.submerged_volume(sh.params) / sim::pool_area(self.shape.half_width);
        let mut planes = vec![WaterPlane::flat(level); self.bodies.len()];
        let t = sh.sim_time();
        // The ambient surface now, made once for all bodies' probes.
        let mut ambient_now = None;
        if let Some(samples) = self.water.probes() {
            self.probe_latency = Some(frame.saturating_sub(samples.frame));
            for id in BodyId::all() {
                let k = id.0 * PROBES_PER_BODY;
                if let Some(heights) = samples.heights.get(k..k + PROBES_PER_BODY) {
                    let points = &samples.points[k..k + PROBES_PER_BODY];
                    let radius = points[0].distance(points[PROBES_PER_BODY / 2]) / 2.0;
                    planes[id.0] = WaterPlane::from_ring(heights, radius);
                    if self.ambient.model != AmbientModel::None {
                        // The ambient waves on a ring of their own, at the body's waterline:
                        // the simulated water's ring keeps clear of the ripples the body
                        // makes itself (up to 0.3 m), which would average short ambient waves
                        // away or even turn them over (a 0.5 m wave on a 0.3 m ring).
                        let centre = points.iter().fold(Vec2::ZERO, |a, p| a + *p) / PROBES_PER_BODY as f32;
                        let now = ambient_now.get_or_insert_with(|| self.ambient.at(t));
                        let ring: Vec<f32> = (0..PROBES_PER_BODY)
                            .map(|i| {
                                let a = std::f32::consts::TAU * i as f32 / PROBES_PER_BODY as f32;
                                let p = centre + AMBIENT_RING_RADIUS * Vec2::new(a.cos(), a.sin());
                                now.sample(p.x, p.y)[0]
                            })
                            .collect();
                        let waves = WaterPlane::from_ring(&ring, AMBIENT_RING_RADIUS);
                        planes[id.0] = planes[id.0].plus(waves);
                    }
                }
            }
        }
        planes
    }

    /// Moves the bodies through `steps` fixed steps on the water planes under them; a body
    /// held by the pointer stays put. Every two in the pool bump off each other. Returns, per
    /// step, how the bodies' hulls moved in it, to push the water by.
    pub(super) fn step_bodies(&mut self, sh: Shared<'_>, steps: u32) -> Vec<Vec<HullMove>> {
        let planes = self.water_planes(sh);
        let gravity = sh.params.flag(ParamId::Gravity);
        let held = sh.held;
        let value = |name: &str| sh.value(name);
        let hulls: Vec<Vec<Ellipsoid>> = BodyId::all().map(|id| (id.kind().hull)(&value)).collect();
        let shapes: Vec<Shape> = BodyId::all()
            .map(|id| Shape {
                hull: &hulls[id.0],
                centre_of_mass: id.kind().centre_of_mass,
                density: (id.kind().density)(&value),
                scale: 1.0,
            })
            .collect();
        let bump: Vec<f32> = BodyId::all().map(|id| (id.kind().bump_radius)(&value)).collect();
        let shown: Vec<BodyId> = BodyId::all().filter(|&id| Self::shows(sh.params, id)).collect();
        let mut pushes = Vec::with_capacity(steps as usize);
        for _ in 0..steps.max(1) {
            for id in BodyId::all() {
                let (k, body) = (id.0, &mut self.bodies[id.0]);
                body.submerged = if held == Some(id) || steps == 0 {
                    if held == Some(id) {
                        body.motion.hold();
                    }
                    shapes[k].submerged(&body.motion.pose, &planes[k]).0
                } else {
                    body.motion.step(&shapes[k], gravity, &planes[k], STEP_DT, &physics::Bounds::pool(self.shape))
                };
            }
            if shown.len() > 1 {
                let mass = |id: BodyId| if held == Some(id) { f32::INFINITY } else { shapes[id.0].mass() };
                bump_apart(&mut self.bodies, &shown, &bump, &mass);
                for id in BodyId::all() {
                    physics::keep_in_pool(&mut self.bodies[id.0].motion.pose, &hulls[id.0], self.shape);
                }
            }
            if steps > 0 {
                pushes.push(self.take_pushes(sh));
            }
        }
        pushes
    }

    /// How each body's hull moved since the water last took it in; records where it is now.
    /// A body that just appeared only records its place (the rest level accounts for it).
    fn take_pushes(&mut self, sh: Shared<'_>) -> Vec<HullMove> {
        let mut moves = Vec::new();
        for id in BodyId::all() {
            if Self::shows(sh.params, id) {
                let hull = sh.hull(id);
                self.bodies[id.0].take_moves(&hull, &mut moves);
            } else {
                self.bodies[id.0].pushed = None;
            }
        }
        moves
    }

    /// Tells the water what the bodies did this frame: how their hulls moved in each step
    /// (`pushes`), the rest level their submerged volume raises, and where to sample heights
    /// for the next frames.
    pub(super) fn couple_water(&mut self, sh: Shared<'_>, pushes: Vec<Vec<HullMove>>) {
        let mut probes = Vec::with_capacity(self.bodies.len() * PROBES_PER_BODY);
        for id in BodyId::all() {
            let pose = self.bodies[id.0].motion.pose;
            if Self::shows(sh.params, id) && self.bodies[id.0].pushed.is_none() {
                self.bodies[id.0].pushed = Some(sh.hull(id).iter().map(|e| e.hull_slot(&pose)).collect());
            }
            let radius = (id.kind().probe_ring)(&|name: &str| sh.value(name));
            probes.extend(ring(Vec2::new(pose.position.x, pose.position.z), radius));
        }
        let rest_level = self.submerged_volume(sh.params) / sim::pool_area(self.shape.half_width);
        self.water.set_bodies(BodyCoupling { moves: pushes, rest_level, probes });
    }
}

impl PoolScene {
    /// The nearest body under pixel `pixel` and the point hit (m), if any.
    pub fn body_under(&self, sh: Shared<'_>, pixel: Vec2) -> Option<(BodyId, Vec3)> {
        let ray = self.camera.ray(pixel, sh.viewport);
        let value = |name: &str| sh.value(name);
        let mut nearest: Option<(BodyId, f32)> = None;
        for id in BodyId::all().filter(|&id| Self::shows(sh.params, id)) {
            let t = (id.kind().pick)(&self.body(id).pose, &value, ray.origin, ray.dir);
            if let Some(t) = t.filter(|&t| nearest.is_none_or(|(_, best)| t < best)) {
                nearest = Some((id, t));
            }
        }
        nearest.map(|(id, t)| (id, ray.origin + ray.dir * t))
    }
}
