//! The floating bodies (the sphere and the duck) in the demo: their start poses, hulls and
//! densities from the parameters, their steps against the water and the water's answer.

use glam::{Quat, Vec2, Vec3};

use super::{Drag, WaterDemo, STEP_DT};
use crate::ambient::AmbientModel;
use crate::duck;
use crate::params::ParamId;
use crate::physics::{self, Ellipsoid, FloatingBody, Pose, Shape, WaterPlane};
use crate::scene::{self, Sphere};
use crate::sim::{self, BodyCoupling, HullMove, HullSlot};

/// Where the sphere starts (m).
pub(super) const START_SPHERE_CENTRE: Vec3 = Vec3::new(-0.35, -0.45, 0.3);
/// Where the duck starts (x, z in m; it starts at its floating height) and where it looks
/// (turn about the vertical, radians; 0 is along +x).
pub(super) const START_DUCK_XZ: Vec2 = Vec2::new(0.35, -0.3);
pub(super) const START_DUCK_TURN: f32 = 2.4;
/// Points on the ring around each body where the water is sampled for its buoyancy.
pub(super) const PROBES_PER_BODY: usize = 8;
/// Radius (m) of the ring on which a body feels the ambient waves (about the duck's and a
/// small sphere's waterline).
pub(super) const AMBIENT_RING_RADIUS: f32 = 0.05;

/// The things that float in the pool.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BodyId {
    Sphere = 0,
    Duck = 1,
}

impl BodyId {
    pub const ALL: [BodyId; 2] = [BodyId::Sphere, BodyId::Duck];
}

impl WaterDemo {
    pub(super) fn place_duck_at_start(&mut self) {
        let y = duck::shape(self.params.get(ParamId::DuckDensity)).floating_height(0.0);
        let pose = Pose {
            position: Vec3::new(START_DUCK_XZ.x, y, START_DUCK_XZ.y),
            rotation: Quat::from_rotation_y(START_DUCK_TURN),
        };
        self.bodies[BodyId::Duck as usize] = FloatingBody::at(pose);
    }

    /// Whether a body is in the pool (the `objects` parameter: none, sphere, duck, both).
    pub fn shows(&self, id: BodyId) -> bool {
        let objects = self.params.get(ParamId::Objects) as u32;
        objects & (1 << id as u32) != 0
    }

    /// The sphere, if shown.
    pub fn sphere(&self) -> Option<Sphere> {
        self.shows(BodyId::Sphere).then(|| {
            let mut s = Sphere { centre: self.bodies[0].pose.position, radius: self.params.get(ParamId::SphereRadius) };
            s.clamp_to_pool();
            s
        })
    }

    /// The duck's pose, if shown.
    pub fn duck(&self) -> Option<Pose> {
        self.shows(BodyId::Duck).then_some(self.bodies[BodyId::Duck as usize].pose)
    }

    /// A body's motion (shown or not).
    pub fn body(&self, id: BodyId) -> &FloatingBody {
        &self.bodies[id as usize]
    }

    pub fn set_sphere_centre(&mut self, centre: Vec3) {
        self.set_body_pose(BodyId::Sphere, Pose::at(centre));
    }

    /// Puts a body somewhere (kept inside the pool) and stops it.
    pub fn set_body_pose(&mut self, id: BodyId, pose: Pose) {
        if pose.position.is_finite() && pose.rotation.is_finite() {
            let mut pose = Pose { position: pose.position, rotation: pose.rotation.normalize() };
            physics::keep_in_pool(&mut pose, &self.hull(id));
            self.bodies[id as usize] = FloatingBody::at(pose);
        }
    }

    /// A body's hull ellipsoids, in its own frame.
    pub(super) fn hull(&self, id: BodyId) -> Vec<Ellipsoid> {
        match id {
            BodyId::Sphere => {
                vec![Ellipsoid { centre: Vec3::ZERO, radii: Vec3::splat(self.params.get(ParamId::SphereRadius)) }]
            }
            BodyId::Duck => duck::HULL.to_vec(),
        }
    }

    pub(super) fn density(&self, id: BodyId) -> f32 {
        match id {
            BodyId::Sphere => self.params.get(ParamId::SphereDensity),
            BodyId::Duck => self.params.get(ParamId::DuckDensity),
        }
    }

    pub(super) fn centre_of_mass(id: BodyId) -> Vec3 {
        match id {
            BodyId::Sphere => Vec3::ZERO,
            BodyId::Duck => duck::CENTRE_OF_MASS,
        }
    }

    /// Radius (m) of the ring around a body on which the water is sampled for it: just
    /// outside its waterline, so the water it pushes up itself counts little.
    pub(super) fn ring_radius(&self, id: BodyId) -> f32 {
        match id {
            BodyId::Sphere => self.params.get(ParamId::SphereRadius) * 1.1 + 0.02,
            BodyId::Duck => 0.3,
        }
    }

    /// Radius (m) of a ball standing in for a body when the two bump into each other.
    pub(super) fn bump_radius(&self, id: BodyId) -> f32 {
        match id {
            BodyId::Sphere => self.params.get(ParamId::SphereRadius),
            BodyId::Duck => 0.13,
        }
    }

    /// Frames between the water heights the bodies last used and the frame that used them:
    /// 1, the heights of the water as the frame starts (sampled on the CPU at the end of the
    /// frame before, see [`HeightField::probes`]); `None` before the first frame.
    pub fn probe_latency(&self) -> Option<u64> {
        self.probe_latency
    }

    /// Volume (m³) of the bodies under water after the last step.
    pub fn submerged_volume(&self) -> f32 {
        BodyId::ALL.iter().filter(|&&id| self.shows(id)).map(|&id| self.submerged[id as usize]).sum()
    }

    /// The water plane under each body from the newest probe heights plus the ambient waves
    /// there now (flat at the rest level before any probes have arrived).
    pub(super) fn water_planes(&mut self) -> [WaterPlane; 2] {
        let frame = self.water.frames() + 1;
        let level = self.submerged_volume() / sim::pool_area(scene::HALF_WIDTH);
        let mut planes = [WaterPlane::flat(level); 2];
        let t = self.sim_time();
        // The ambient surface now, made once for both bodies' probes.
        let mut ambient_now = None;
        if let Some(samples) = self.water.probes() {
            self.probe_latency = Some(frame.saturating_sub(samples.frame));
            for id in BodyId::ALL {
                let k = id as usize * PROBES_PER_BODY;
                if let Some(heights) = samples.heights.get(k..k + PROBES_PER_BODY) {
                    let points = &samples.points[k..k + PROBES_PER_BODY];
                    let radius = points[0].distance(points[PROBES_PER_BODY / 2]) / 2.0;
                    planes[id as usize] = WaterPlane::from_ring(heights, radius);
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
                        planes[id as usize] = planes[id as usize].plus(waves);
                    }
                }
            }
        }
        planes
    }

    /// Moves the bodies through `steps` fixed steps on the water planes under them; a body
    /// held by the pointer stays put. The two bump off each other. Returns, per step, how the
    /// bodies' hulls moved in it, to push the water by.
    pub(super) fn step_bodies(&mut self, steps: u32) -> Vec<Vec<HullMove>> {
        let planes = self.water_planes();
        let gravity = self.params.flag(ParamId::Gravity);
        let held = match self.drag {
            Drag::Body { id, .. } => Some(id),
            _ => None,
        };
        let hulls = [self.hull(BodyId::Sphere), self.hull(BodyId::Duck)];
        let shapes = BodyId::ALL.map(|id| Shape {
            hull: &hulls[id as usize],
            centre_of_mass: Self::centre_of_mass(id),
            density: self.density(id),
        });
        let both = self.shows(BodyId::Sphere) && self.shows(BodyId::Duck);
        let mut pushes = Vec::with_capacity(steps as usize);
        for _ in 0..steps.max(1) {
            for id in BodyId::ALL {
                let k = id as usize;
                let body = &mut self.bodies[k];
                self.submerged[k] = if held == Some(id) || steps == 0 {
                    if held == Some(id) {
                        body.hold();
                    }
                    shapes[k].submerged(&body.pose, &planes[k]).0
                } else {
                    body.step(&shapes[k], gravity, &planes[k], STEP_DT)
                };
            }
            if both {
                let mass = |id: BodyId| if held == Some(id) { f32::INFINITY } else { shapes[id as usize].mass() };
                let (ms, md) = (mass(BodyId::Sphere), mass(BodyId::Duck));
                let (rs, rd) = (self.bump_radius(BodyId::Sphere), self.bump_radius(BodyId::Duck));
                let [sphere, duck] = &mut self.bodies;
                physics::separate(sphere, rs, ms, duck, rd, md);
                for (k, id) in BodyId::ALL.iter().enumerate() {
                    physics::keep_in_pool(&mut self.bodies[k].pose, &hulls[*id as usize]);
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
        for id in BodyId::ALL {
            let k = id as usize;
            if !self.shows(id) {
                self.pushed[k] = None;
                continue;
            }
            let pose = self.bodies[k].pose;
            let current: Vec<HullSlot> = self.hull(id).iter().map(|e| e.hull_slot(&pose)).collect();
            if let Some(previous) = &self.pushed[k] {
                if !previous.iter().zip(&current).any(|(before, now)| now.moved_from(before)) {
                    continue;
                }
                moves.extend(previous.iter().zip(&current).map(|(&from, &to)| HullMove { from, to }));
            }
            self.pushed[k] = Some(current);
        }
        moves
    }

    /// Tells the water what the bodies did this frame: how their hulls moved in each step
    /// (`pushes`), the rest level their submerged volume raises, and where to sample heights
    /// for the next frames.
    pub(super) fn couple_water(&mut self, pushes: Vec<Vec<HullMove>>) {
        let mut probes = Vec::with_capacity(2 * PROBES_PER_BODY);
        for id in BodyId::ALL {
            let k = id as usize;
            let pose = self.bodies[k].pose;
            if self.shows(id) && self.pushed[k].is_none() {
                self.pushed[k] = Some(self.hull(id).iter().map(|e| e.hull_slot(&pose)).collect());
            }
            let radius = self.ring_radius(id);
            for i in 0..PROBES_PER_BODY {
                let a = std::f32::consts::TAU * i as f32 / PROBES_PER_BODY as f32;
                probes.push(Vec2::new(pose.position.x, pose.position.z) + radius * Vec2::new(a.cos(), a.sin()));
            }
        }
        let rest_level = self.submerged_volume() / sim::pool_area(scene::HALF_WIDTH);
        self.water.set_bodies(BodyCoupling { moves: pushes, rest_level, probes });
    }
}
