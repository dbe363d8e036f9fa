//! The floating bodies in the demo, one per kind of `bodies::KINDS`: placed at their starts,
//! stepped against the water planes under them, kept apart, and the water's answer to them.
//! Nothing here names a kind: what differs between kinds is in their table entries.

use glam::{Vec2, Vec3};

use super::{Drag, WaterDemo, STEP_DT};
use crate::ambient::AmbientModel;
use crate::bodies::{Body, BodyId, BodyView, KINDS, PROBES_PER_BODY};
use crate::params::ParamId;
use crate::physics::{self, Ellipsoid, FloatingBody, Pose, Shape, WaterPlane};
use crate::scene::{self, Sphere};
use crate::sim::{self, BodyCoupling, HullMove};

/// Radius (m) of the ring on which a body feels the ambient waves (about the duck's and a
/// small sphere's waterline).
pub(super) const AMBIENT_RING_RADIUS: f32 = 0.05;

impl WaterDemo {
    /// A parameter's value by name, for the body kinds' table entries.
    pub(super) fn value(&self, name: &str) -> f32 {
        self.params.get_by_name(name).expect("a body kind reads its own parameters")
    }

    /// Every body at its start, at rest, not yet felt by the water (its submerged volume
    /// kept until the next step measures it again).
    pub(super) fn place_bodies_at_start(&mut self) {
        let value = |name: &str| self.value(name);
        let bodies: Vec<Body> = BodyId::all()
            .map(|id| Body {
                submerged: self.bodies.get(id.0).map_or(0.0, |b| b.submerged),
                ..Body::at((id.kind().start)(&value))
            })
            .collect();
        self.bodies = bodies;
    }

    /// Whether a body is in the pool (its bit in the `objects` parameter).
    pub fn shows(&self, id: BodyId) -> bool {
        let objects = self.params.get(ParamId::Objects) as u32;
        objects & id.bit() != 0
    }

    /// Every kind's body as the renderer draws it, if shown.
    pub(super) fn drawn_bodies(&self) -> [Option<BodyView>; KINDS.len()] {
        let value = |name: &str| self.value(name);
        std::array::from_fn(|k| {
            let id = BodyId(k);
            self.shows(id).then(|| (id.kind().drawn)(&self.bodies[k].motion.pose, &value))
        })
    }

    /// The sphere as drawn, if shown.
    pub fn sphere(&self) -> Option<Sphere> {
        let id = BodyId::named("sphere")?;
        self.shows(id)
            .then(|| crate::bodies::sphere::drawn(&self.bodies[id.0].motion.pose, self.value("sphere_radius")))
    }

    /// The duck's pose, if shown.
    pub fn duck(&self) -> Option<Pose> {
        let id = BodyId::named("duck")?;
        self.shows(id).then_some(self.bodies[id.0].motion.pose)
    }

    /// A body's motion (shown or not).
    pub fn body(&self, id: BodyId) -> &FloatingBody {
        &self.bodies[id.0].motion
    }

    pub fn set_sphere_centre(&mut self, centre: Vec3) {
        if let Some(id) = BodyId::named("sphere") {
            self.set_body_pose(id, Pose::at(centre));
        }
    }

    /// Puts a body somewhere (kept inside the pool) and stops it.
    pub fn set_body_pose(&mut self, id: BodyId, pose: Pose) {
        if pose.position.is_finite() && pose.rotation.is_finite() {
            let mut pose = Pose { position: pose.position, rotation: pose.rotation.normalize() };
            physics::keep_in_pool(&mut pose, &self.hull(id));
            self.bodies[id.0].motion = FloatingBody::at(pose);
        }
    }

    /// A body's hull ellipsoids, in its own frame.
    pub(super) fn hull(&self, id: BodyId) -> Vec<Ellipsoid> {
        (id.kind().hull)(&|name: &str| self.value(name))
    }

    /// Frames between the water heights the bodies last used and the frame that used them:
    /// 1, the heights of the water as the frame starts (sampled on the CPU at the end of the
    /// frame before, see [`HeightField::probes`]); `None` before the first frame.
    pub fn probe_latency(&self) -> Option<u64> {
        self.probe_latency
    }

    /// Volume (m³) of the bodies under water after the last step.
    pub fn submerged_volume(&self) -> f32 {
        BodyId::all().filter(|&id| self.shows(id)).map(|id| self.bodies[id.0].submerged).sum()
    }

    /// The water plane under each body from the newest probe heights plus the ambient waves
    /// there now (flat at the rest level before any probes have arrived).
    pub(super) fn water_planes(&mut self) -> Vec<WaterPlane> {
        let frame = self.water.frames() + 1;
        let level = self.submerged_volume() / sim::pool_area(scene::HALF_WIDTH);
        let mut planes = vec![WaterPlane::flat(level); self.bodies.len()];
        let t = self.sim_time();
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
    pub(super) fn step_bodies(&mut self, steps: u32) -> Vec<Vec<HullMove>> {
        let planes = self.water_planes();
        let gravity = self.params.flag(ParamId::Gravity);
        let held = match self.drag {
            Drag::Body { id, .. } => Some(id),
            _ => None,
        };
        let value = |name: &str| self.value(name);
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
        let shown: Vec<BodyId> = BodyId::all().filter(|&id| self.shows(id)).collect();
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
                    body.motion.step(&shapes[k], gravity, &planes[k], STEP_DT, &physics::Bounds::pool())
                };
            }
            if shown.len() > 1 {
                let mass = |id: BodyId| if held == Some(id) { f32::INFINITY } else { shapes[id.0].mass() };
                bump_apart(&mut self.bodies, &shown, &bump, &mass);
                for id in BodyId::all() {
                    physics::keep_in_pool(&mut self.bodies[id.0].motion.pose, &hulls[id.0]);
                }
            }
            if steps > 0 {
                pushes.push(self.take_pushes());
            }
        }
        pushes
    }

    /// How each body's hull moved since the water last took it in; records where it is now.
    /// A body that just appeared only records its place (the rest level accounts for it).
    pub(super) fn take_pushes(&mut self) -> Vec<HullMove> {
        let mut moves = Vec::new();
        for id in BodyId::all() {
            if self.shows(id) {
                let hull = self.hull(id);
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
    pub(super) fn couple_water(&mut self, pushes: Vec<Vec<HullMove>>) {
        let mut probes = Vec::with_capacity(self.bodies.len() * PROBES_PER_BODY);
        for id in BodyId::all() {
            let pose = self.bodies[id.0].motion.pose;
            if self.shows(id) && self.bodies[id.0].pushed.is_none() {
                self.bodies[id.0].pushed = Some(self.hull(id).iter().map(|e| e.hull_slot(&pose)).collect());
            }
            let radius = (id.kind().probe_ring)(&|name: &str| self.value(name));
            probes.extend(ring(Vec2::new(pose.position.x, pose.position.z), radius));
        }
        let rest_level = self.submerged_volume() / sim::pool_area(scene::HALF_WIDTH);
        self.water.set_bodies(BodyCoupling { moves: pushes, rest_level, probes });
    }
}

/// Pushes every two of the `shown` bodies apart where their bumping balls (radii `bump`, m, by
/// kind) overlap, the lighter more (`mass`, kg; infinite for one held in place).
pub(super) fn bump_apart(bodies: &mut [Body], shown: &[BodyId], bump: &[f32], mass: &dyn Fn(BodyId) -> f32) {
    for (i, &a) in shown.iter().enumerate() {
        for &b in &shown[i + 1..] {
            let (first, second) = bodies.split_at_mut(b.0);
            let (a_motion, b_motion) = (&mut first[a.0].motion, &mut second[0].motion);
            physics::separate(a_motion, bump[a.0], mass(a), b_motion, bump[b.0], mass(b));
        }
    }
}

/// `PROBES_PER_BODY` points on a ring of `radius` (m) round `centre`: where the water is read
/// for a body's buoyancy.
pub(super) fn ring(centre: Vec2, radius: f32) -> impl Iterator<Item = Vec2> {
    (0..PROBES_PER_BODY).map(move |i| {
        let a = std::f32::consts::TAU * i as f32 / PROBES_PER_BODY as f32;
        centre + radius * Vec2::new(a.cos(), a.sin())
    })
}
