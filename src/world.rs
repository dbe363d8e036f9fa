//! The physical world, in metres: a pool's shape, the sphere and the sun.
//! The water rests at y = 0; a pool spans x, z in [-half_width, half_width].

use glam::Vec3;

/// A pool's box (m): half its side, the floor's depth below the rest level and the rim's
/// height above it. A value of the scene that has the pool, handed to what simulates, draws
/// and floats bodies in it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PoolShape {
    pub half_width: f32,
    pub depth: f32,
    pub rim: f32,
}

/// The classic pool.
impl Default for PoolShape {
    fn default() -> Self {
        Self::CLASSIC
    }
}

impl PoolShape {
    /// The demo's pool: 2 m x 2 m, 1 m deep, its rim a sixth of a metre above the water. It is
    /// also the unit the simulation's sponge and bounds are written for (`sim::scale_of`), and
    /// the pool the bodies' table entries assume: their start poses, the balls' drawn clamp
    /// (`bodies::sphere::drawn`) and the floor a body denser than water rests on.
    pub const CLASSIC: PoolShape = PoolShape { half_width: 1.0, depth: 1.0, rim: 1.0 / 6.0 };
}
/// Refractive index of water (air is 1).
pub const IOR_WATER: f32 = 1.333;

/// Unit vector towards the sun from an azimuth and an elevation in degrees.
/// Azimuth 0 looks along +z, 90 along +x.
pub fn sun_direction(azimuth_deg: f32, elevation_deg: f32) -> Vec3 {
    let (az, el) = (azimuth_deg.to_radians(), elevation_deg.to_radians());
    Vec3::new(el.cos() * az.sin(), el.sin(), el.cos() * az.cos()).normalize()
}

/// Azimuth and elevation (degrees) of a direction: the inverse of [`sun_direction`].
pub fn direction_angles(dir: Vec3) -> (f32, f32) {
    let d = dir.normalize();
    (d.x.atan2(d.z).to_degrees(), d.y.clamp(-1.0, 1.0).asin().to_degrees())
}

/// Direction sunlight travels after refraction through a calm surface (points down).
pub fn refracted_sun(sun: Vec3) -> Vec3 {
    refract(-sun, Vec3::Y, 1.0 / IOR_WATER).unwrap_or(Vec3::NEG_Y)
}

/// Snell's law for a unit incident direction and unit normal facing against it;
/// `eta` = n_from / n_to. `None` on total internal reflection.
pub fn refract(incident: Vec3, normal: Vec3, eta: f32) -> Option<Vec3> {
    let cos_i = -normal.dot(incident);
    let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    (k >= 0.0).then(|| (incident * eta + normal * (eta * cos_i - k.sqrt())).normalize())
}

/// A ball in the pool.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// Centre (m).
    pub centre: Vec3,
    /// Radius (m).
    pub radius: f32,
}

impl Sphere {
    /// Keeps the sphere inside `pool`'s box and not above its rim by more than its size.
    pub fn clamp_to_pool(&mut self, pool: PoolShape) {
        let r = self.radius;
        let lim = pool.half_width - r;
        self.centre.x = self.centre.x.clamp(-lim, lim);
        self.centre.z = self.centre.z.clamp(-lim, lim);
        self.centre.y = self.centre.y.clamp(-pool.depth + r, pool.rim + 2.0 * r);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sun_angles_round_trip() {
        let d = sun_direction(35.0, 55.0);
        assert!((d.length() - 1.0).abs() < 1e-6);
        let (az, el) = direction_angles(d);
        assert!((az - 35.0).abs() < 1e-3 && (el - 55.0).abs() < 1e-3);
    }

    #[test]
    fn refraction_bends_towards_the_normal_by_snell() {
        let sun = sun_direction(0.0, 30.0);
        let r = refracted_sun(sun);
        let sin_i = (1.0 - sun.y * sun.y).sqrt();
        let sin_t = (1.0 - r.y * r.y).sqrt();
        assert!((sin_i - IOR_WATER * sin_t).abs() < 1e-5);
        assert!(r.y < 0.0);
    }
}
