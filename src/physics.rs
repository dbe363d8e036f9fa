//! Rigid bodies in the water: gravity, buoyancy from the submerged volume, water and air drag,
//! righting torque, and bounces off the floor and walls. A body's hull is a few ellipsoids,
//! whose volume below a plane has a closed form (an ellipsoid is an affine image of the unit
//! ball, so a plane cuts it in a scaled spherical cap). Advanced in the simulation's fixed
//! steps, so it behaves the same at any frame rate. Heights are relative to the water at rest
//! (y = 0, m).

use glam::{Mat3, Quat, Vec2, Vec3};

use crate::param_spec::{Control, ParamSpec};
use crate::world;

/// Gravitational acceleration (m/s²).
pub const GRAVITY: f32 = 9.81;
/// Density of water (kg/m³).
pub const WATER_DENSITY: f32 = 1000.0;
/// Drag coefficient of a round body at the Reynolds numbers of a pool toy.
const DRAG_COEFFICIENT: f32 = 0.47;
/// Extra linear damping in water (1/s), standing in for the energy lost to waves.
const WAVE_DAMPING: f32 = 6.0;
/// Angular damping in water and in air (1/s).
const SPIN_DAMPING_WATER: f32 = 10.0;
const SPIN_DAMPING_AIR: f32 = 0.3;
/// Fraction of the normal speed kept in a bounce.
const RESTITUTION: f32 = 0.35;

/// An ellipsoid in a body's own frame: centre (m) and semi-axes along the frame's x, y, z (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ellipsoid {
    pub centre: Vec3,
    pub radii: Vec3,
}

/// Where a body is: its frame's origin (m) and orientation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    pub position: Vec3,
    pub rotation: Quat,
}

impl Pose {
    pub fn at(position: Vec3) -> Self {
        Self { position, rotation: Quat::IDENTITY }
    }

    /// A point of the body's frame in the world.
    pub fn to_world(&self, local: Vec3) -> Vec3 {
        self.position + self.rotation * local
    }
}

/// The water surface near a body, as a plane through (x, level, z) below the body with a unit
/// normal; `level` is a height above rest (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaterPlane {
    pub level: f32,
    pub normal: Vec3,
}

impl WaterPlane {
    pub fn flat(level: f32) -> Self {
        Self { level, normal: Vec3::Y }
    }

    /// The plane fitted to heights (m) sampled on a circle of `radius` (m) around a body, at
    /// equal angles starting along +x and turning towards +z: the mean height, and the slope
    /// from the first Fourier coefficient (exact for a plane).
    pub fn from_ring(heights: &[f32], radius: f32) -> Self {
        let n = heights.len().max(1) as f32;
        let level = heights.iter().sum::<f32>() / n;
        let mut slope = Vec2::ZERO;
        for (k, h) in heights.iter().enumerate() {
            let a = std::f32::consts::TAU * k as f32 / n;
            slope += Vec2::new(a.cos(), a.sin()) * (h - level);
        }
        slope *= 2.0 / (n * radius.max(1e-3));
        let slope = slope.clamp_length_max(1.0);
        let plane = Self { level, normal: Vec3::new(-slope.x, 1.0, -slope.y).normalize() };
        if plane.level.is_finite() && plane.normal.is_finite() {
            plane
        } else {
            Self::flat(0.0)
        }
    }
}

impl WaterPlane {
    /// This plane with another surface's added: levels summed, slopes summed (the ambient
    /// waves over the simulated water).
    pub fn plus(self, other: WaterPlane) -> Self {
        let slope = |p: &WaterPlane| Vec2::new(-p.normal.x, -p.normal.z) / p.normal.y.max(1e-3);
        let sum = (slope(&self) + slope(&other)).clamp_length_max(1.0);
        Self { level: self.level + other.level, normal: Vec3::new(-sum.x, 1.0, -sum.y).normalize() }
    }
}

/// Volume of the unit ball on the side u·m̂ < `delta` of a plane at signed distance `delta`
/// from its centre, and the first moment of that part along m̂ (its centroid times volume).
fn unit_ball_below(delta: f32) -> (f32, f32) {
    let d = delta.clamp(-1.0, 1.0);
    let h = 1.0 + d;
    let volume = std::f32::consts::PI * h * h * (3.0 - h) / 3.0;
    let moment = -std::f32::consts::PI * (1.0 - d * d).powi(2) / 4.0;
    (volume, moment)
}

impl Ellipsoid {
    /// The ellipsoid `factor` times larger about its frame's origin.
    pub fn scaled(self, factor: f32) -> Self {
        Self { centre: self.centre * factor, radii: self.radii * factor }
    }

    pub fn volume(&self) -> f32 {
        4.0 / 3.0 * std::f32::consts::PI * self.radii.x * self.radii.y * self.radii.z
    }

    /// World-from-unit-ball matrix of this ellipsoid on a body at `pose` (rotation times scale).
    fn world_from_unit(&self, pose: &Pose) -> Mat3 {
        Mat3::from_quat(pose.rotation) * Mat3::from_diagonal(self.radii)
    }

    /// Volume (m³) below the water plane (taken through the body's x, z) and the centroid of
    /// that volume in the world (m).
    pub fn below(&self, pose: &Pose, water: &WaterPlane) -> (f32, Vec3) {
        let centre = pose.to_world(self.centre);
        let m = self.world_from_unit(pose);
        // Plane n·x = n·p0 through p0 = (x, level, z); in unit-ball coordinates u, points
        // x = centre + M u are below it where (Mᵀ n)·u < n·(p0 - centre).
        let p0 = Vec3::new(pose.position.x, water.level, pose.position.z);
        let along = m.transpose() * water.normal;
        let length = along.length();
        let delta = water.normal.dot(p0 - centre) / length;
        let (unit_volume, unit_moment) = unit_ball_below(delta);
        let volume = unit_volume * self.radii.x * self.radii.y * self.radii.z;
        let centroid =
            if unit_volume > 1e-9 { centre + m * (along / length * (unit_moment / unit_volume)) } else { centre };
        (volume, centroid)
    }

    /// Largest value of dir·x over the ellipsoid on a body at `pose` (its support function).
    pub fn support(&self, pose: &Pose, dir: Vec3) -> f32 {
        dir.dot(pose.to_world(self.centre)) + (self.world_from_unit(pose).transpose() * dir).length()
    }

    /// Distance along a ray (unit `dir`) to where it enters the ellipsoid, if it does ahead.
    pub fn ray_hit(&self, pose: &Pose, origin: Vec3, dir: Vec3) -> Option<f32> {
        let inv = self.world_from_unit(pose).inverse();
        let o = inv * (origin - pose.to_world(self.centre));
        let d = inv * dir;
        let (a, b, c) = (d.dot(d), o.dot(d), o.dot(o) - 1.0);
        let disc = b * b - a * c;
        if disc < 0.0 {
            return None;
        }
        let t = (-b - disc.sqrt()) / a;
        (t > 0.0).then_some(t)
    }

    /// The ellipsoid as the simulation's displacement pass takes it (see `sim::HullSlot`).
    pub fn hull_slot(&self, pose: &Pose) -> crate::sim::HullSlot {
        crate::sim::HullSlot {
            centre: pose.to_world(self.centre),
            unit_from_world: self.world_from_unit(pose).inverse(),
        }
    }
}

/// What a body is made of: hull ellipsoids (in its frame; their volumes are added, so they
/// should barely overlap), its centre of mass (in its frame) and its density (kg/m³).
#[derive(Clone, Copy, Debug)]
pub struct Shape<'a> {
    pub hull: &'a [Ellipsoid],
    pub centre_of_mass: Vec3,
    pub density: f32,
    /// How many times larger than the pool's toy it is (1 in the pool). The dampings of its
    /// motion and its spin (which stand in for the waves a toy sends out) slow as 1/√scale: a body n times larger moves as a
    /// toy filmed √n times slower (Froude's similarity, which gravity waves keep).
    pub scale: f32,
}

impl Shape<'_> {
    pub fn volume(&self) -> f32 {
        self.hull.iter().map(Ellipsoid::volume).sum()
    }

    pub fn mass(&self) -> f32 {
        self.density * self.volume()
    }

    /// Submerged volume (m³) at `pose` under `water`, and its centroid (the centre of buoyancy).
    pub fn submerged(&self, pose: &Pose, water: &WaterPlane) -> (f32, Vec3) {
        let mut volume = 0.0;
        let mut moment = Vec3::ZERO;
        for part in self.hull {
            let (v, c) = part.below(pose, water);
            volume += v;
            moment += c * v;
        }
        (volume, if volume > 1e-9 { moment / volume } else { pose.position })
    }

    /// Height of the frame's origin (m) at which the body, upright, floats at rest on calm
    /// water at `level`: its submerged volume equals its mass over the water's density
    /// (bisection). A body denser than water gives the height at which it rests on the classic
    /// pool's floor (where the kinds' table entries start bodies).
    pub fn floating_height(&self, level: f32) -> f32 {
        let target = self.mass() / WATER_DENSITY;
        let water = WaterPlane::flat(level);
        let bottom = |y: f32| {
            let pose = Pose::at(Vec3::new(0.0, y, 0.0));
            self.hull.iter().map(|p| -p.support(&pose, Vec3::NEG_Y)).fold(f32::INFINITY, f32::min)
        };
        let (mut lo, mut hi) = (level - 2.0, level + 2.0);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if self.submerged(&Pose::at(Vec3::new(0.0, mid, 0.0)), &water).0 > target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let floating = 0.5 * (lo + hi);
        let resting = floating - bottom(floating) - world::PoolShape::CLASSIC.depth;
        floating.max(resting)
    }

    /// Moment of inertia (kg m²) of the body about any axis through its centre of mass,
    /// taken as that of a ball with the hull's mean semi-axis: a body that is not long and thin.
    fn inertia(&self) -> f32 {
        let mean_radius = self.hull.first().map_or(0.1, |p| (p.radii.x + p.radii.y + p.radii.z) / 3.0);
        0.4 * self.mass() * mean_radius * mean_radius
    }
}

/// A body's motion; its pose is also set by hand while it is dragged.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FloatingBody {
    pub pose: Pose,
    /// Velocity of the frame's origin (m/s).
    pub velocity: Vec3,
    /// Angular velocity (rad/s).
    pub spin: Vec3,
}

impl FloatingBody {
    pub fn at(pose: Pose) -> Self {
        Self { pose, velocity: Vec3::ZERO, spin: Vec3::ZERO }
    }

    /// Stops the body where it is.
    pub fn hold(&mut self) {
        self.velocity = Vec3::ZERO;
        self.spin = Vec3::ZERO;
    }

    /// Advances the body one step of `dt` seconds, kept within `bounds`. With gravity, buoyancy pushes along the
    /// water plane's normal with the weight of the water displaced (so a body on a slope drifts
    /// down it) and acts at the centre of buoyancy (so a body tilts with the waves and rights
    /// itself when its centre of mass is low). Without gravity a body only coasts to a stop.
    /// Returns the submerged volume (m³).
    pub fn step(&mut self, shape: &Shape, gravity: bool, water: &WaterPlane, dt: f32, bounds: &Bounds) -> f32 {
        let mass = shape.mass().max(1e-6);
        let volume = shape.volume();
        let (submerged, buoyancy_centre) = shape.submerged(&self.pose, water);
        let wet = (submerged / volume).clamp(0.0, 1.0);
        let mut force = Vec3::ZERO;
        let mut torque = Vec3::ZERO;
        let centre_of_mass = self.pose.to_world(shape.centre_of_mass);
        if gravity {
            force.y -= mass * GRAVITY;
            let buoyancy = water.normal * (WATER_DENSITY * submerged * GRAVITY);
            force += buoyancy;
            torque += (buoyancy_centre - centre_of_mass).cross(buoyancy);
        }
        // Quadratic drag in water and air, by the wetted share of the cross-section.
        let radius = (volume * 3.0 / (4.0 * std::f32::consts::PI)).cbrt();
        let speed = self.velocity.length();
        let fluid_density = WATER_DENSITY * wet + 1.2 * (1.0 - wet);
        let area = std::f32::consts::PI * radius * radius;
        force -= 0.5 * fluid_density * DRAG_COEFFICIENT * area * speed * self.velocity;
        // Semi-implicit Euler; the linear dampings are applied exactly so they cannot overshoot.
        self.velocity += force / mass * dt;
        let slower = shape.scale.max(1e-3).sqrt();
        self.velocity *= (-WAVE_DAMPING * wet * dt / slower).exp();
        self.spin += torque / shape.inertia().max(1e-9) * dt;
        self.spin *= (-(SPIN_DAMPING_WATER * wet + SPIN_DAMPING_AIR) * dt / slower).exp();
        if !self.velocity.is_finite() || !self.spin.is_finite() {
            self.hold();
        }
        // Rotate about the centre of mass, then move.
        let turn = Quat::from_scaled_axis(self.spin * dt);
        let offset = self.pose.rotation * shape.centre_of_mass;
        self.pose.rotation = (turn * self.pose.rotation).normalize();
        self.pose.position += offset - self.pose.rotation * shape.centre_of_mass + self.velocity * dt;
        let bounced = bounds.keep(&mut self.pose, shape.hull);
        for (axis, bounced) in bounced.into_iter().enumerate() {
            if bounced {
                self.velocity[axis] *= -RESTITUTION;
            }
        }
        submerged
    }
}

/// A box a body is kept in (m): the pool's (its floor and walls, and not far above the rim),
/// or the part of the sea's patch whose water takes its pushes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounds {
    pub least: Vec3,
    pub most: Vec3,
}

impl Bounds {
    /// The box of `pool`, up to half a metre over its rim.
    pub fn pool(pool: world::PoolShape) -> Self {
        let w = pool.half_width;
        Self { least: Vec3::new(-w, -pool.depth, -w), most: Vec3::new(w, pool.rim + 0.5, w) }
    }

    /// Moves a body back inside the box, by its hull's support in each direction. Returns, per
    /// axis, whether it had to be moved.
    pub fn keep(&self, pose: &mut Pose, hull: &[Ellipsoid]) -> [bool; 3] {
        let mut moved = [false; 3];
        if !pose.position.is_finite() {
            pose.position = Vec3::ZERO;
        }
        for (axis, (dir, moved)) in Vec3::AXES.into_iter().zip(&mut moved).enumerate() {
            let reach_plus = hull.iter().map(|p| p.support(pose, dir)).fold(f32::NEG_INFINITY, f32::max);
            let reach_minus = hull.iter().map(|p| -p.support(pose, -dir)).fold(f32::INFINITY, f32::min);
            let (lo, hi) = (self.least[axis], self.most[axis]);
            let shift = if reach_minus < lo {
                lo - reach_minus
            } else if reach_plus > hi {
                hi - reach_plus
            } else {
                0.0
            };
            if shift != 0.0 {
                pose.position[axis] += shift;
                *moved = true;
            }
        }
        moved
    }
}

/// Moves a body back inside `pool`'s box ([`Bounds::pool`]).
pub fn keep_in_pool(pose: &mut Pose, hull: &[Ellipsoid], pool: world::PoolShape) -> [bool; 3] {
    Bounds::pool(pool).keep(pose, hull)
}

/// Pushes two bodies, approximated by balls of the given radii (m) around their positions,
/// apart when they overlap, in inverse proportion to their masses (kg; infinite for one held
/// by the pointer), and removes their approach speed but for a little bounce.
pub fn separate(a: &mut FloatingBody, ra: f32, ma: f32, b: &mut FloatingBody, rb: f32, mb: f32) {
    let d = b.pose.position - a.pose.position;
    let dist = d.length();
    let overlap = ra + rb - dist;
    if overlap <= 0.0 || dist < 1e-6 {
        return;
    }
    let n = d / dist;
    let (wa, wb) = (1.0 / ma.max(1e-6), 1.0 / mb.max(1e-6));
    let (sa, sb) = (wa / (wa + wb), wb / (wa + wb));
    a.pose.position -= n * overlap * sa;
    b.pose.position += n * overlap * sb;
    let approach = (a.velocity - b.velocity).dot(n);
    if approach > 0.0 {
        let impulse = approach * (1.0 + RESTITUTION);
        a.velocity -= n * impulse * sa;
        b.velocity += n * impulse * sb;
    }
}

/// Gravity on the bodies. (The parameter table, `params::table`, lists them in this order.)
pub const GRAVITY_PARAMS: &[ParamSpec] = &[ParamSpec {
    name: "gravity",
    label: "Gravity",
    group: "Objects",
    unit: "",
    control: Control::Toggle,
    default: 1.0,
    help: "Let the objects fall, float, bob and drift on the waves (G key); off, they stay where they are put.",
}];

#[cfg(test)]
mod tests {
    use super::*;

    fn ball(r: f32) -> [Ellipsoid; 1] {
        [Ellipsoid { centre: Vec3::ZERO, radii: Vec3::splat(r) }]
    }

    #[test]
    fn cap_volume_spans_zero_to_the_whole_ellipsoid() {
        let e = Ellipsoid { centre: Vec3::ZERO, radii: Vec3::new(0.3, 0.1, 0.2) };
        let water = WaterPlane::flat(0.0);
        let at = |y| Pose::at(Vec3::new(0.0, y, 0.0));
        assert_eq!(e.below(&at(0.2), &water).0, 0.0);
        assert!((e.below(&at(0.0), &water).0 - e.volume() / 2.0).abs() < 1e-6);
        assert!((e.below(&at(-0.2), &water).0 - e.volume()).abs() < 1e-6);
    }

    #[test]
    fn tilted_ellipsoid_volume_and_centroid_match_sampling() {
        // A tilted ellipsoid under a tilted plane, against counting points of a fine lattice.
        let e = Ellipsoid { centre: Vec3::new(0.05, 0.02, 0.0), radii: Vec3::new(0.3, 0.12, 0.2) };
        let pose = Pose { position: Vec3::new(0.1, 0.03, -0.1), rotation: Quat::from_rotation_z(0.5) };
        let water = WaterPlane { level: 0.01, normal: Vec3::new(0.2, 1.0, -0.1).normalize() };
        let (volume, centroid) = e.below(&pose, &water);
        let inv = e.world_from_unit(&pose).inverse();
        let centre = pose.to_world(e.centre);
        let p0 = Vec3::new(pose.position.x, water.level, pose.position.z);
        let (step, mut count, mut sum) = (0.004f32, 0u32, Vec3::ZERO);
        for i in -100..100 {
            for j in -100..100 {
                for k in -100..100 {
                    let p = centre + Vec3::new(i as f32, j as f32, k as f32) * step;
                    if (inv * (p - centre)).length_squared() <= 1.0 && water.normal.dot(p - p0) < 0.0 {
                        count += 1;
                        sum += p;
                    }
                }
            }
        }
        let sampled = count as f32 * step.powi(3);
        assert!((volume - sampled).abs() / sampled < 0.01, "{volume} vs {sampled}");
        assert!((centroid - sum / count as f32).length() < 0.002, "{centroid} vs {}", sum / count as f32);
    }

    #[test]
    fn a_ring_of_heights_gives_back_a_plane() {
        let (slope_x, slope_z) = (0.1, -0.05);
        let heights: Vec<f32> = (0..8)
            .map(|k| {
                let a = std::f32::consts::TAU * k as f32 / 8.0;
                0.02 + 0.3 * (slope_x * a.cos() + slope_z * a.sin())
            })
            .collect();
        let plane = WaterPlane::from_ring(&heights, 0.3);
        assert!((plane.level - 0.02).abs() < 1e-6);
        let expected = Vec3::new(-slope_x, 1.0, -slope_z).normalize();
        assert!((plane.normal - expected).length() < 1e-5, "{}", plane.normal);
    }

    #[test]
    fn a_released_sphere_settles_at_its_floating_line() {
        let r = 0.25;
        let hull = ball(r);
        for density in [300.0, 500.0, 800.0] {
            let shape = Shape { hull: &hull, centre_of_mass: Vec3::ZERO, density, scale: 1.0 };
            let mut body = FloatingBody::at(Pose::at(Vec3::new(0.0, 0.5, 0.0)));
            for _ in 0..120 * 20 {
                body.step(&shape, true, &WaterPlane::flat(0.0), 1.0 / 120.0, &Bounds::pool(world::PoolShape::CLASSIC));
            }
            let expected = shape.floating_height(0.0);
            // The cap formula: pi h^2 (3r - h) / 3 = mass / water density, h = r - y.
            let h = r - expected;
            let cap = std::f32::consts::PI * h * h * (3.0 * r - h) / 3.0;
            assert!((cap - shape.mass() / WATER_DENSITY).abs() < 1e-5);
            assert!(
                (body.pose.position.y - expected).abs() < 0.01 && body.velocity.length() < 0.01,
                "density {density}: rest at {} m, expected {expected} m, speed {}",
                body.pose.position.y,
                body.velocity.length()
            );
        }
    }

    #[test]
    fn a_dense_sphere_sinks_to_the_floor() {
        let hull = ball(0.2);
        let shape = Shape { hull: &hull, centre_of_mass: Vec3::ZERO, density: 1500.0, scale: 1.0 };
        let mut body = FloatingBody::at(Pose::at(Vec3::new(0.2, 0.0, 0.0)));
        for _ in 0..120 * 10 {
            body.step(&shape, true, &WaterPlane::flat(0.0), 1.0 / 120.0, &Bounds::pool(world::PoolShape::CLASSIC));
        }
        let y = body.pose.position.y;
        assert!((y - (-world::PoolShape::CLASSIC.depth + 0.2)).abs() < 1e-3, "{y}");
        assert!((shape.floating_height(0.0) - y).abs() < 1e-3);
    }

    #[test]
    fn a_body_drifts_down_a_sloping_surface() {
        let hull = ball(0.15);
        let shape = Shape { hull: &hull, centre_of_mass: Vec3::ZERO, density: 500.0, scale: 1.0 };
        let y = shape.floating_height(0.0);
        let mut body = FloatingBody::at(Pose::at(Vec3::new(0.0, y, 0.0)));
        // Water rising towards +x: the body slides towards -x.
        let water = WaterPlane { level: 0.0, normal: Vec3::new(-0.05, 1.0, 0.0).normalize() };
        for _ in 0..60 {
            body.step(&shape, true, &water, 1.0 / 120.0, &Bounds::pool(world::PoolShape::CLASSIC));
        }
        assert!(body.velocity.x < -0.01, "{}", body.velocity);
    }
}
