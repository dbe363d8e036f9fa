//! Rigid-body motion of the sphere: gravity, buoyancy from the submerged volume, water and air
//! drag, and bounces off the floor and walls. Advanced in the simulation's fixed steps, so it
//! behaves the same at any frame rate. Heights are relative to the water at rest (y = 0, m).

use glam::Vec3;

use crate::scene::{self, Sphere};

/// Gravitational acceleration (m/s²).
pub const GRAVITY: f32 = 9.81;
/// Density of water (kg/m³).
pub const WATER_DENSITY: f32 = 1000.0;
/// Drag coefficient of a sphere at the Reynolds numbers of a pool toy.
const DRAG_COEFFICIENT: f32 = 0.47;
/// Extra linear damping in water (1/s), standing in for the energy lost to waves.
const WAVE_DAMPING: f32 = 1.5;
/// Fraction of the normal speed kept in a bounce.
const RESTITUTION: f32 = 0.35;

/// Volume (m³) of a sphere of radius `r` below the plane y = 0 when its centre is at `y`:
/// a spherical cap of height h = r - y, V = π h² (3r - h) / 3.
pub fn submerged_volume(r: f32, y: f32) -> f32 {
    let h = (r - y).clamp(0.0, 2.0 * r);
    std::f32::consts::PI * h * h * (3.0 * r - h) / 3.0
}

/// Height of the centre (m) at which a sphere of `density` (kg/m³) floats at rest:
/// the submerged volume equals the sphere's mass over the water density (bisection).
pub fn floating_height(r: f32, density: f32) -> f32 {
    let target = density / WATER_DENSITY * 4.0 / 3.0 * std::f32::consts::PI * r * r * r;
    let (mut lo, mut hi) = (-r, r);
    if submerged_volume(r, lo) <= target {
        return -scene::DEPTH + r; // sinks
    }
    for _ in 0..40 {
        let mid = 0.5 * (lo + hi);
        if submerged_volume(r, mid) > target {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The sphere's velocity; its position lives in the demo (it is also dragged by hand).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SphereBody {
    /// Velocity (m/s).
    pub velocity: Vec3,
}

impl SphereBody {
    /// Advances `sphere` by one step of `dt` seconds with gravity on or off.
    /// Without gravity the sphere only coasts to a stop under drag.
    pub fn step(&mut self, sphere: &mut Sphere, density: f32, gravity: bool, dt: f32) {
        let r = sphere.radius;
        let volume = 4.0 / 3.0 * std::f32::consts::PI * r * r * r;
        let mass = density * volume;
        let submerged = submerged_volume(r, sphere.centre.y) / volume;
        let mut force = Vec3::ZERO;
        if gravity {
            force.y += (WATER_DENSITY * submerged * volume - mass) * GRAVITY;
        }
        // Quadratic drag in water and air, by the wetted share of the cross-section.
        let speed = self.velocity.length();
        let fluid_density = WATER_DENSITY * submerged + 1.2 * (1.0 - submerged);
        let area = std::f32::consts::PI * r * r;
        force -= 0.5 * fluid_density * DRAG_COEFFICIENT * area * speed * self.velocity;
        // Semi-implicit Euler; the linear damping is applied exactly so it cannot overshoot.
        self.velocity += force / mass * dt;
        self.velocity *= (-WAVE_DAMPING * submerged * dt).exp();
        if !self.velocity.is_finite() {
            self.velocity = Vec3::ZERO;
        }
        let wanted = sphere.centre + self.velocity * dt;
        sphere.centre = wanted;
        sphere.clamp_to_pool();
        // Bounce off whatever clamped the sphere (floor, walls, or the height limit).
        for axis in 0..3 {
            if (sphere.centre[axis] - wanted[axis]).abs() > 1e-6 {
                self.velocity[axis] *= -RESTITUTION;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cap_volume_spans_zero_to_the_whole_sphere() {
        let r = 0.25;
        let whole = 4.0 / 3.0 * std::f32::consts::PI * r * r * r;
        assert_eq!(submerged_volume(r, r + 0.1), 0.0);
        assert!((submerged_volume(r, 0.0) - whole / 2.0).abs() < 1e-6);
        assert!((submerged_volume(r, -r - 0.1) - whole).abs() < 1e-6);
    }

    #[test]
    fn a_released_sphere_settles_at_its_floating_line() {
        let r = 0.25;
        for density in [300.0, 500.0, 800.0] {
            let mut sphere = Sphere { centre: Vec3::new(0.0, 0.5, 0.0), radius: r };
            let mut body = SphereBody::default();
            for _ in 0..120 * 20 {
                body.step(&mut sphere, density, true, 1.0 / 120.0);
            }
            let expected = floating_height(r, density);
            assert!(
                (sphere.centre.y - expected).abs() < 0.01 && body.velocity.length() < 0.01,
                "density {density}: rest at {} m, expected {expected} m, speed {}",
                sphere.centre.y,
                body.velocity.length()
            );
        }
    }

    #[test]
    fn a_dense_sphere_sinks_to_the_floor() {
        let mut sphere = Sphere { centre: Vec3::new(0.2, 0.0, 0.0), radius: 0.2 };
        let mut body = SphereBody::default();
        for _ in 0..120 * 10 {
            body.step(&mut sphere, 1500.0, true, 1.0 / 120.0);
        }
        assert!((sphere.centre.y - (-scene::DEPTH + 0.2)).abs() < 1e-3, "{}", sphere.centre.y);
    }
}
