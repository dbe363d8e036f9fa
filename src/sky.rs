//! The daylight sky and the light it gives: Preetham, Shirley and Smits' analytic sky (1999),
//! the sun's colour after the air it crosses, and the sky's ambient light on the scene. One
//! source for the sky cubemap's shader (which evaluates the Perez function with the
//! coefficients made here), the scene's sun and ambient light, and the tests.
//!
//! Perez et al.'s luminance distribution: F(θ, γ) = (1 + A e^{B / cos θ})(1 + C e^{D γ} + E cos² γ),
//! θ the view direction's angle from the zenith, γ its angle to the sun. Each of Y, x, y is its
//! zenith value times F(θ, γ) / F(0, θ_s), with coefficients linear in the turbidity T.

use crate::param_spec::{slider, ParamSpec};
use crate::world::sun_direction;
use glam::Vec3;
use std::sync::OnceLock;

/// Haze of the air (Preetham's turbidity: 2 a clear day, 6 a hazy one).
pub const TURBIDITY: f32 = 2.4;
/// Irradiance of the sun on a surface facing it, at noon (linear scene units: a white
/// surface facing the sun shows this much before the tone curve).
pub const SUN_IRRADIANCE: f32 = 2.2;
/// The sky's light on a horizontal surface relative to the sun's with the sun overhead: a
/// clear sky gives about a fifth of a day's light.
pub const SKY_TO_SUN: f32 = 0.2;
/// Share of the sky's light that reaches points under the water (through the opening and the
/// surface; the pool's walls hide the rest).
pub const UNDERWATER_SKY: f32 = 0.45;
/// Radiance of the sun's disk relative to SUN_IRRADIANCE (its highlight and reflections).
pub const SUN_DISK_RADIANCE: f32 = 120.0;
/// Peak of the sun's highlight on the water relative to the sun's light (its lobe is
/// cos^shininess; sharper than the disk the cubemap holds).
pub const SUN_GLINT: f32 = 150.0;
/// Scene light that the tone curve maps to its middle: the curve takes light x EXPOSURE_SCALE x 2^EV.
pub const EXPOSURE_SCALE: f32 = 0.36;
/// The cubemap stores sky radiance / SKY_RANGE in 8-bit sRGB (values above clip).
pub const SKY_RANGE: f32 = 2.0;

/// Luminance of a linear RGB colour (Rec. 709 weights).
fn luma(c: Vec3) -> f32 {
    c.dot(Vec3::new(0.2126, 0.7152, 0.0722))
}

/// Optical depth of a vertical column of clear air per colour channel (red, green, blue at
/// about 680, 550, 450 nm): Rayleigh scattering 0.0088 λ^-4.05 plus haze 0.05 λ^-1.3 (λ in µm).
const ZENITH_OPTICAL_DEPTH: [f32; 3] = [0.125, 0.208, 0.364];

/// The filmic tone curve (Narkowicz's fit of the ACES film response) the scene's shader
/// applies to scene light times EXPOSURE_SCALE x 2^EV: linear display light in 0-1.
pub fn tone_curve(x: f32) -> f32 {
    (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14)
}

/// The scene light (before exposure) that the tone curve shows as linear display light `y`
/// at exposure `ev`: the inverse of [`tone_curve`], for tests that read light off pixels.
pub fn scene_light(y: f32, ev: f32) -> f32 {
    let y = y.clamp(0.0, 0.999);
    let (a, b, c) = (2.43 * y - 2.51, 0.59 * y - 0.03, 0.14 * y);
    let x = (-b - (b * b - 4.0 * a * c).max(0.0).sqrt()) / (2.0 * a);
    x / (EXPOSURE_SCALE * 2f32.powf(ev))
}

/// A sky for one sun position: what the cube shader and the scene's lighting need.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Daylight {
    /// Unit vector towards the sun.
    pub sun: Vec3,
    /// Perez coefficients A..E for Y, x and y.
    pub perez: [[f32; 5]; 3],
    /// Y, x, y at the zenith divided by F(0, θ_s); Y scaled to scene radiance units.
    pub zenith: [f32; 3],
    /// The sun's light on a surface facing it (linear RGB, scene units).
    pub sun_light: Vec3,
    /// The sky's light on a horizontal surface, as a diffuse surface's colour factor (linear RGB).
    pub ambient: Vec3,
}

fn perez(c: &[f32; 5], cos_theta: f32, gamma: f32) -> f32 {
    (1.0 + c[0] * (c[1] / cos_theta.max(0.01)).exp()) * (1.0 + c[2] * (c[3] * gamma).exp() + c[4] * gamma.cos().powi(2))
}

fn coefficients(t: f32) -> [[f32; 5]; 3] {
    [
        [0.1787 * t - 1.4630, -0.3554 * t + 0.4275, -0.0227 * t + 5.3251, 0.1206 * t - 2.5771, -0.0670 * t + 0.3703],
        [-0.0193 * t - 0.2592, -0.0665 * t + 0.0008, -0.0004 * t + 0.2125, -0.0641 * t - 0.8989, -0.0033 * t + 0.0452],
        [-0.0167 * t - 0.2608, -0.0950 * t + 0.0092, -0.0079 * t + 0.2102, -0.0441 * t - 1.6537, -0.0109 * t + 0.0529],
    ]
}

/// Zenith luminance (kcd/m²) and chromaticity for turbidity t and the sun's zenith angle (rad).
fn zenith_values(t: f32, theta_s: f32) -> [f32; 3] {
    let chi = (4.0 / 9.0 - t / 120.0) * (std::f32::consts::PI - 2.0 * theta_s);
    let y_lum = (4.0453 * t - 4.9710) * chi.tan() - 0.2155 * t + 2.4192;
    let (th, th2, th3) = (theta_s, theta_s * theta_s, theta_s * theta_s * theta_s);
    let x = t * t * (0.00166 * th3 - 0.00375 * th2 + 0.00209 * th)
        + t * (-0.02903 * th3 + 0.06377 * th2 - 0.03202 * th + 0.00394)
        + (0.11693 * th3 - 0.21196 * th2 + 0.06052 * th + 0.25886);
    let y = t * t * (0.00275 * th3 - 0.00610 * th2 + 0.00317 * th)
        + t * (-0.04214 * th3 + 0.08970 * th2 - 0.04153 * th + 0.00516)
        + (0.15346 * th3 - 0.26756 * th2 + 0.06670 * th + 0.26688);
    [y_lum.max(0.0), x, y]
}

/// CIE xyY to linear sRGB.
pub fn xyy_to_rgb(x: f32, y: f32, lum: f32) -> Vec3 {
    let (cx, cz) = (x * lum / y.max(1e-4), (1.0 - x - y) * lum / y.max(1e-4));
    Vec3::new(
        3.2406 * cx - 1.5372 * lum - 0.4986 * cz,
        -0.9689 * cx + 1.8758 * lum + 0.0415 * cz,
        0.0557 * cx - 0.2040 * lum + 1.0570 * cz,
    )
    .max(Vec3::ZERO)
}

/// Relative air mass along a path at `elevation` (rad) above the horizon (Kasten and Young).
fn air_mass(elevation: f32) -> f32 {
    let z = 90.0 - elevation.to_degrees().clamp(0.0, 90.0);
    1.0 / (z.to_radians().cos() + 0.50572 * (96.07995 - z).powf(-1.6364))
}

impl Daylight {
    pub fn new(sun: Vec3) -> Self {
        let mut sky = Self::unscaled(sun.normalize());
        // Sunlight through the air: Beer–Lambert over the air mass, white at the zenith.
        let m = air_mass(sky.sun.y.clamp(0.0, 1.0).asin());
        sky.sun_light = Vec3::from(ZENITH_OPTICAL_DEPTH.map(|tau| (-tau * (m - 1.0)).exp())) * SUN_IRRADIANCE;
        // Scale the sky's luminance so that, with the sun overhead, its light on the ground is
        // SKY_TO_SUN of the sun's; the same scale at every sun position (evenings darken).
        let noon = luma(Self::unscaled(Vec3::Y).irradiance_up());
        sky.zenith[0] *= SKY_TO_SUN * SUN_IRRADIANCE / noon;
        sky.ambient = sky.irradiance_up();
        sky
    }

    /// The sky for a unit vector towards the sun, its luminance in Preetham's kcd/m², no light yet.
    fn unscaled(sun: Vec3) -> Self {
        let theta_s = sun.y.clamp(-1.0, 1.0).acos().min(1.55);
        let perez_c = coefficients(TURBIDITY);
        let z = zenith_values(TURBIDITY, theta_s);
        let zenith = [0, 1, 2].map(|i| z[i] / perez(&perez_c[i], 1.0, theta_s));
        Self { sun, perez: perez_c, zenith, sun_light: Vec3::ZERO, ambient: Vec3::ZERO }
    }

    /// Sky radiance (linear RGB, scene units) in direction `dir` (above the horizon; below it,
    /// the horizon's).
    pub fn radiance(&self, dir: Vec3) -> Vec3 {
        let d = dir.normalize();
        let cos_theta = d.y.max(0.0);
        let gamma = d.dot(self.sun).clamp(-1.0, 1.0).acos();
        let v = [0, 1, 2].map(|i| self.zenith[i] * perez(&self.perez[i], cos_theta, gamma));
        xyy_to_rgb(v[1], v[2], v[0])
    }

    /// (1/π) ∫ L cos θ dω over the upper hemisphere: the factor a diffuse surface facing up
    /// multiplies its albedo by, as the scene's shaders light with `albedo * (ambient + ...)`.
    fn irradiance_up(&self) -> Vec3 {
        // Cosine-weighted directions on a fixed lattice (the mean of L over them is the integral).
        let (rings, steps) = (12, 24);
        let mut sum = Vec3::ZERO;
        for i in 0..rings {
            let u = (i as f32 + 0.5) / rings as f32;
            let (r, y) = (u.sqrt(), (1.0 - u).sqrt());
            for j in 0..steps {
                let a = std::f32::consts::TAU * (j as f32 + 0.5) / steps as f32;
                sum += self.radiance(Vec3::new(r * a.cos(), y, r * a.sin()));
            }
        }
        sum / (rings * steps) as f32
    }

    /// Luminance of the light on a level surface open to this sky (scene units): the sun's on
    /// it and the sky's.
    pub fn open_ground_light(&self) -> f32 {
        luma(self.sun_light) * self.sun.y.max(0.0) + luma(self.ambient)
    }

    /// Exposure (EV) the picture adds to the `exposure` parameter under this sky, as a camera's
    /// automatic exposure does: the stops by which its light on open ground falls short of the
    /// reference sun's ([`EXPOSURE_REFERENCE_ELEVATION`]). So a low sun's scene is exposed as
    /// well as a high one's (the presets add their own stops on top), and a sun moved overhead
    /// in a preset exposed for the evening does not burn the picture out. 0 at 55°, +1.4 at
    /// 20°, -0.1 at 65°, -0.3 at 82°.
    pub fn adapted_exposure(&self) -> f32 {
        static REFERENCE_LIGHT: OnceLock<f32> = OnceLock::new();
        let reference_light = *REFERENCE_LIGHT
            .get_or_init(|| Daylight::new(sun_direction(0.0, EXPOSURE_REFERENCE_ELEVATION)).open_ground_light());
        (reference_light / self.open_ground_light()).log2()
    }

    /// The cube shader's uniform: Perez rows for Y, x, y (A..D; E in the zenith row), the
    /// zenith values and the sun.
    pub fn uniform(&self) -> [[f32; 4]; 5] {
        let p = &self.perez;
        [
            [p[0][0], p[0][1], p[0][2], p[0][3]],
            [p[1][0], p[1][1], p[1][2], p[1][3]],
            [p[2][0], p[2][1], p[2][2], p[2][3]],
            [p[0][4], p[1][4], p[2][4], 0.0],
            [self.zenith[0], self.zenith[1], self.zenith[2], 0.0],
        ]
    }

    /// WGSL constants the sky's shaders share with this file.
    pub fn wgsl_constants() -> String {
        format!(
            "const SKY_RANGE: f32 = {SKY_RANGE:?};\nconst SUN_DISK_RADIANCE: f32 = {SUN_DISK_RADIANCE:?};\n\
             const UNDERWATER_SKY: f32 = {UNDERWATER_SKY:?};\nconst SUN_GLINT: f32 = {SUN_GLINT:?};\nconst EXPOSURE_SCALE: f32 = {EXPOSURE_SCALE:?};\n"
        )
    }
}

/// The sun's elevation (°) whose light the automatic exposure makes every sun's up to: the
/// elevation the presets' own exposures were set under (the light on open ground does not
/// depend on the azimuth).
pub const EXPOSURE_REFERENCE_ELEVATION: f32 = 55.0;

/// Where the sun is: by default high and behind the camera's left shoulder, so that the rim
/// shades only thin strips of the floor and the caustics show over most of it, and from under
/// the water on both walls. A higher sun shades less of the floor but leaves the right wall
/// dark from below: judged blind (2026-11-30) against -40° / 65° and -20° / 72°, this one was
/// best from above and close behind -40° / 65° (its wide band of shadow) from below.
/// (The parameter table, `params::table`, lists them in this order.)
pub const SUN_PARAMS: &[ParamSpec] = &[
    ParamSpec {
        name: "sun_azimuth",
        label: "Sun azimuth",
        group: "Light",
        unit: "°",
        control: slider(-180.0, 180.0, 1.0),
        default: -30.0,
        help: "Compass direction of the sun around the pool.",
    },
    ParamSpec {
        name: "sun_elevation",
        label: "Sun elevation",
        group: "Light",
        unit: "°",
        control: slider(10.0, 90.0, 1.0),
        default: 68.0,
        help: "Height of the sun above the horizon.",
    },
];

/// The picture's exposure before the tone curve. (The parameter table, `params::table`, lists them in this order.)
pub const EXPOSURE_PARAMS: &[ParamSpec] = &[ParamSpec {
    name: "exposure",
    label: "Exposure",
    group: "Light",
    unit: "EV",
    control: slider(-4.0, 4.0, 0.1),
    default: 0.0,
    help: "Brightness of the picture in photographic stops (each +1 doubles the light before the filmic tone curve), on top of the camera's own: a lower sun is exposed for the light it loses.",
}];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::world::sun_direction;

    #[test]
    fn the_noon_sky_is_blue_overhead_brighter_at_the_horizon_and_lights_a_fifth_of_the_sun() {
        let sky = Daylight::new(sun_direction(0.0, 89.0));
        // Away from the sun: the sky overhead there against the horizon below it.
        let zenith = sky.radiance(sun_direction(180.0, 60.0));
        let horizon = sky.radiance(sun_direction(180.0, 2.0));
        println!("zenith {zenith:?} horizon {horizon:?} ambient {:?} sun {:?}", sky.ambient, sky.sun_light);
        assert!(zenith.z > 1.3 * zenith.x, "zenith not blue: {zenith:?}");
        assert!(luma(horizon) > luma(zenith), "horizon not brighter: {horizon:?} vs {zenith:?}");
        let ratio = luma(sky.ambient) / luma(sky.sun_light);
        assert!((ratio - SKY_TO_SUN).abs() < 0.02, "sky/sun {ratio}");
    }

    #[test]
    fn the_tone_curve_is_undone_by_scene_light() {
        for x in [0.0, 0.01, 0.1, 0.5, 1.0, 3.0, 8.0] {
            let y = tone_curve(x * EXPOSURE_SCALE);
            assert!((scene_light(y, 0.0) - x).abs() < 1e-3 * (1.0 + x), "{x} -> {y} -> {}", scene_light(y, 0.0));
        }
    }

    #[test]
    fn a_low_sun_is_warm_and_weaker_and_the_sky_near_it_brighter() {
        let low = Daylight::new(sun_direction(0.0, 12.0));
        let noon = Daylight::new(sun_direction(0.0, 80.0));
        println!("low sun {:?}, noon sun {:?}", low.sun_light, noon.sun_light);
        assert!(low.sun_light.x > 1.8 * low.sun_light.z, "low sun not warm: {:?}", low.sun_light);
        assert!(luma(low.sun_light) < luma(noon.sun_light));
        let towards = low.radiance(sun_direction(0.0, 14.0));
        let away = low.radiance(sun_direction(180.0, 14.0));
        assert!(luma(towards) > 2.0 * luma(away), "no glow round the sun: {towards:?} vs {away:?}");
        for az in [-180.0, -90.0, 0.0, 90.0] {
            for el in [0.0, 5.0, 30.0, 60.0, 90.0] {
                let c = low.radiance(sun_direction(az, el));
                assert!(c.is_finite() && c.max_element() < SKY_RANGE, "{az} {el}: {c:?}");
            }
        }
    }

    #[test]
    fn the_exposure_makes_up_the_light_a_lower_sun_loses() {
        let at = |deg: f32| Daylight::new(sun_direction(35.0, deg)).adapted_exposure();
        let figures: Vec<(f32, f32)> =
            [10.0, 15.0, 20.0, 30.0, 40.0, 55.0, 82.0, 90.0].iter().map(|&e| (e, at(e))).collect();
        println!("sun elevation (°), exposure added (EV): {figures:?}");
        assert!(
            at(EXPOSURE_REFERENCE_ELEVATION).abs() < 1e-4,
            "the reference sun's picture changes by {} EV",
            at(55.0)
        );
        assert!(figures.windows(2).all(|w| w[1].1 < w[0].1), "not falling as the sun rises: {figures:?}");
        // The light on open ground at 20° is about 2.7 times (1.4 stops) less than at 55°.
        assert!((1.2..1.6).contains(&at(20.0)), "{} EV at 20°", at(20.0));
        assert!((-0.5..-0.2).contains(&at(90.0)), "{} EV overhead", at(90.0));
    }
}
