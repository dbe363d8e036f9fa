//! The orbit camera and picking: which thing in the scene lies under a screen point.

use glam::{Mat4, Vec2, Vec3, Vec4};

/// A camera circling a target point at a distance, looking at it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrbitCamera {
    /// Angle around the vertical axis (degrees).
    pub yaw: f32,
    /// Angle above the horizontal (degrees); negative looks from below the water.
    pub pitch: f32,
    /// Distance from the target (m).
    pub distance: f32,
    /// Point looked at (m).
    pub target: Vec3,
    /// Vertical field of view (degrees).
    pub fov_y: f32,
    /// How far the scene lets the camera go, and its projection's depth range.
    pub limits: CameraLimits,
}

/// What a scene allows its camera: the pitch range (degrees), the distance range from the
/// target (m), and the projection's near and far planes (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraLimits {
    pub pitch: (f32, f32),
    pub distance: (f32, f32),
    pub near: f32,
    pub far: f32,
}

/// The pool's pitch and distance ranges.
pub const PITCH_RANGE: (f32, f32) = (-89.0, 89.0);
pub const DISTANCE_RANGE: (f32, f32) = (1.5, 12.0);
/// The pool's camera limits.
pub const POOL_LIMITS: CameraLimits =
    CameraLimits { pitch: PITCH_RANGE, distance: DISTANCE_RANGE, near: 0.05, far: 100.0 };

impl Default for OrbitCamera {
    fn default() -> Self {
        Self {
            yaw: -25.0,
            pitch: 34.0,
            // Close enough that the water fills half of a 4:3 frame (its colour and caustics
            // are what the picture is about), the coping still whole.
            distance: 3.0,
            target: Vec3::new(0.0, -0.3, 0.0),
            fov_y: 45.0,
            limits: POOL_LIMITS,
        }
    }
}

/// A ray from the eye, direction unit length.
#[derive(Clone, Copy, Debug)]
pub struct Ray {
    pub origin: Vec3,
    pub dir: Vec3,
}

/// What lies under a screen point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pick {
    /// The water surface (at rest level) at x, z (m).
    Water {
        x: f32,
        z: f32,
    },
    Nothing,
}

impl OrbitCamera {
    /// Clamps pitch and distance into their ranges ([`OrbitCamera::limits`]), wraps yaw.
    pub fn clamp(&mut self) {
        let CameraLimits { pitch, distance, .. } = self.limits;
        self.pitch = self.pitch.clamp(pitch.0, pitch.1);
        self.distance = self.distance.clamp(distance.0, distance.1);
        if !self.yaw.is_finite() {
            self.yaw = 0.0;
        }
        self.yaw = (self.yaw + 180.0).rem_euclid(360.0) - 180.0;
    }

    /// Raises the pitch as far as needed for the eye to be at least at `height` (m): the
    /// ground the camera must not go under.
    pub fn keep_eye_above(&mut self, height: f32) {
        let lowest = ((height - self.target.y) / self.distance).clamp(-1.0, 1.0).asin().to_degrees();
        if self.pitch < lowest {
            self.pitch = lowest.min(self.limits.pitch.1);
        }
    }

    /// Rotates by a drag of (dx, dy) pixels.
    pub fn orbit(&mut self, dx: f32, dy: f32) {
        self.yaw -= dx * 0.4;
        self.pitch += dy * 0.4;
        self.clamp();
    }

    /// Zooms by a factor (> 1 moves away).
    pub fn zoom(&mut self, factor: f32) {
        if factor.is_finite() && factor > 0.0 {
            self.distance *= factor;
        }
        self.clamp();
    }

    /// Unit vector from the target towards the eye.
    pub fn back(&self) -> Vec3 {
        let (yaw, pitch) = (self.yaw.to_radians(), self.pitch.to_radians());
        Vec3::new(pitch.cos() * yaw.sin(), pitch.sin(), pitch.cos() * yaw.cos())
    }

    pub fn eye(&self) -> Vec3 {
        self.target + self.back() * self.distance
    }

    pub fn view(&self) -> Mat4 {
        Mat4::look_at_rh(self.eye(), self.target, Vec3::Y)
    }

    pub fn projection(&self, aspect: f32) -> Mat4 {
        Mat4::perspective_rh(self.fov_y.to_radians(), aspect.max(1e-3), self.limits.near, self.limits.far)
    }

    pub fn view_projection(&self, aspect: f32) -> Mat4 {
        self.projection(aspect) * self.view()
    }

    /// Pixel (x, y, y down) where a world point (m) appears in a viewport of `size` pixels,
    /// or `None` when it is behind the camera.
    pub fn project(&self, point: Vec3, size: Vec2) -> Option<Vec2> {
        let clip = self.view_projection(size.x / size.y) * point.extend(1.0);
        (clip.w > 1e-6).then(|| {
            let ndc = clip.truncate() / clip.w;
            Vec2::new((ndc.x * 0.5 + 0.5) * size.x, (0.5 - ndc.y * 0.5) * size.y)
        })
    }

    /// The ray through pixel (x, y) of a viewport of `size` pixels (y down).
    pub fn ray(&self, pixel: Vec2, size: Vec2) -> Ray {
        let ndc = Vec2::new(pixel.x / size.x * 2.0 - 1.0, 1.0 - pixel.y / size.y * 2.0);
        let inv = self.view_projection(size.x / size.y).inverse();
        let near = inv * Vec4::new(ndc.x, ndc.y, 0.0, 1.0);
        let far = inv * Vec4::new(ndc.x, ndc.y, 1.0, 1.0);
        let near = near.truncate() / near.w;
        let far = far.truncate() / far.w;
        Ray { origin: self.eye(), dir: (far - near).normalize() }
    }

    /// What lies under a screen point of water `half_width` (m) each way from the origin (the
    /// pool's, or the open sea's patch of simulated water): the water surface at its rest level
    /// there, or nothing (a scene picks its bodies first).
    pub fn pick_within(&self, pixel: Vec2, size: Vec2, half_width: f32) -> Pick {
        let ray = self.ray(pixel, size);
        let water_t = if ray.dir.y.abs() > 1e-6 { -ray.origin.y / ray.dir.y } else { f32::INFINITY };
        if water_t > 0.0 && water_t.is_finite() {
            let p = ray.origin + ray.dir * water_t;
            if p.x.abs() <= half_width && p.z.abs() <= half_width {
                return Pick::Water { x: p.x, z: p.z };
            }
        }
        Pick::Nothing
    }
}

/// Distance along the ray to the first hit of a sphere, if any.
pub fn ray_sphere(ray: &Ray, centre: Vec3, radius: f32) -> Option<f32> {
    let oc = ray.origin - centre;
    let b = oc.dot(ray.dir);
    let c = oc.dot(oc) - radius * radius;
    let disc = b * b - c;
    if disc < 0.0 {
        return None;
    }
    let t = -b - disc.sqrt();
    (t > 0.0).then_some(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn centre_pixel_looks_at_target() {
        let cam = OrbitCamera::default();
        let ray = cam.ray(Vec2::new(400.0, 300.0), Vec2::new(800.0, 600.0));
        let to_target = (cam.target - cam.eye()).normalize();
        assert!(ray.dir.dot(to_target) > 0.9999);
    }

    #[test]
    fn project_inverts_ray() {
        let cam = OrbitCamera::default();
        let size = Vec2::new(640.0, 480.0);
        let pixel = Vec2::new(123.0, 321.0);
        let ray = cam.ray(pixel, size);
        let back = cam.project(ray.origin + ray.dir * 3.0, size).unwrap();
        assert!((back - pixel).length() < 0.01, "{back:?}");
    }

    #[test]
    fn pick_finds_the_water_and_nothing() {
        let cam = OrbitCamera { yaw: 0.0, pitch: 60.0, distance: 4.0, target: Vec3::ZERO, ..Default::default() };
        let size = Vec2::new(800.0, 600.0);
        match cam.pick_within(Vec2::new(400.0, 300.0), size, 1.0) {
            Pick::Water { x, z } => assert!(x.abs() < 1e-3 && z.abs() < 1e-3),
            other => panic!("expected water, got {other:?}"),
        }
        // The top-left corner looks past the pool into the sky.
        assert_eq!(cam.pick_within(Vec2::new(0.0, 0.0), size, 1.0), Pick::Nothing);
    }

    #[test]
    fn clamps_hold() {
        let mut cam = OrbitCamera::default();
        cam.orbit(0.0, 1.0e6);
        assert_eq!(cam.pitch, PITCH_RANGE.1);
        cam.zoom(1.0e9);
        assert_eq!(cam.distance, DISTANCE_RANGE.1);
        cam.zoom(f32::NAN);
        assert_eq!(cam.distance, DISTANCE_RANGE.1);
        // Another scene's limits: the same camera goes further and not as low.
        cam.limits = CameraLimits { pitch: (2.0, 89.0), distance: (3.0, 600.0), near: 0.25, far: 30_000.0 };
        cam.zoom(1.0e9);
        cam.orbit(0.0, -1.0e6);
        assert_eq!((cam.distance, cam.pitch), (600.0, 2.0));
        // Its far plane: a point 20 km ahead is drawn, where the pool's camera clips it.
        let ahead = cam.eye() - cam.back() * 20_000.0;
        let depth = |c: &OrbitCamera| {
            let clip = c.view_projection(1.0) * ahead.extend(1.0);
            clip.z / clip.w
        };
        assert!(depth(&cam) < 1.0, "20 km ahead is clipped: depth {}", depth(&cam));
        assert!(depth(&OrbitCamera { limits: POOL_LIMITS, ..cam }) > 1.0);
    }
}
