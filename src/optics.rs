//! Optical models a lesson can switch between: how much of the light meeting the water
//! surface is reflected (Fresnel reflectance: the exact equations and the cheaper curves the
//! seeds use), and the shape of the sun's highlight (Phong or Blinn–Phong). The formulas here
//! are the reference: the surface shader evaluates the same ones (the model is a constant of
//! its variant, so a model not chosen costs nothing), the page and the viewer plot them, and
//! the tests hold the GPU's pixels to them.

use crate::param_spec::{slider, Control, ParamSpec};
use crate::world::IOR_WATER;

crate::choices! {
    /// A Fresnel reflectance model. Each takes the cosine of the incidence angle; below the
    /// surface the approximations take the angle on the air side (Snell) and total internal
    /// reflection stays exact.
    #[derive(Default)]
    pub enum FresnelModel {
        /// The Fresnel equations for unpolarised light, R = (Rs + Rp) / 2 (seed 000, §2.2.2).
        #[default]
        Exact = "exact",
        /// The exact curve sampled into a lookup texture of [`FRESNEL_TABLE_SIZE`] angles per
        /// side, read with linear interpolation (seed 000, §3.2.2: precomputed coefficients in a
        /// 1-D texture indexed by the angle).
        Table = "table",
        /// Schlick: R0 + (1 − R0)(1 − cos θ)⁵, R0 = ((n1 − n2)/(n1 + n2))² (seed 000, §3.2.2).
        Schlick = "schlick",
        /// 1 / (1 + cos θ)⁸ (seed 000, §3.2.2, after Fleck 2007).
        InversePower = "inverse_power",
        /// clamp((1 − cos θ)⁴, 0.05, 0.3) (seed 002's water shader: `pow(1.0 + dot(eye, n), 4.0)`
        /// with the eye vector pointing at the surface).
        ClampedPower = "clamped_power",
        /// 1 − cos θ: the reflected share grows linearly as the view flattens (seed 003, eq. 1).
        Linear = "linear",
    }
}

/// Angles per side of the Fresnel lookup texture (0° to 90° at the texel centres).
pub const FRESNEL_TABLE_SIZE: u32 = 256;
/// Exponent of [`FresnelModel::InversePower`].
pub const INVERSE_POWER_EXPONENT: f32 = 8.0;
/// Exponent and bounds of [`FresnelModel::ClampedPower`].
pub const CLAMPED_POWER_EXPONENT: f32 = 4.0;
pub const CLAMPED_POWER_MIN: f32 = 0.05;
pub const CLAMPED_POWER_MAX: f32 = 0.3;

/// Reflectance at normal incidence between air and water, ((n1 − n2)/(n1 + n2))².
pub fn schlick_r0() -> f32 {
    let r = (1.0 - IOR_WATER) / (1.0 + IOR_WATER);
    r * r
}

/// Water's reflectance for light arriving evenly from the air's whole hemisphere (each
/// direction weighted by its cosine, as an overcast sky or a diffuse surface lights it): the
/// exact curve averaged, 2 ∫ R(θ) cos θ sin θ dθ (about 0.066 at n = 1.333).
pub fn hemisphere_reflectance() -> f32 {
    let steps = 2048;
    let dt = std::f32::consts::FRAC_PI_2 / steps as f32;
    (0..steps)
        .map(|i| {
            let t = (i as f32 + 0.5) * dt;
            2.0 * fresnel_exact(t.cos(), 1.0 / IOR_WATER) * t.cos() * t.sin() * dt
        })
        .sum()
}

/// The share of light arriving evenly at the surface from under the water (cosine-weighted)
/// that leaves it: only the 1 / n² inside the critical angle can, and of that what the surface
/// passes, the same share as from the air (reciprocity): (1 − [`hemisphere_reflectance`]) / n²,
/// about 0.53.
pub fn escape_share() -> f32 {
    (1.0 - hemisphere_reflectance()) / (IOR_WATER * IOR_WATER)
}

/// sin² of the critical angle, 1 / n²: under the water the whole sky is seen in a cone of that
/// half-angle about straight up (Snell's window).
pub fn snell_window_sin2() -> f32 {
    1.0 / (IOR_WATER * IOR_WATER)
}

/// The share of the light round a surface under the water, facing `cos_up` (the cosine of its
/// normal's angle from straight up), that comes through Snell's window: the window's projected
/// solid angle over π, its part behind the surface's horizon left out (Snyder's form factor of a
/// spherical cap seen from a tilted plane). sin² of the critical angle facing up (0.5625), 0.11
/// facing sideways, 0 facing down; the rest of its hemisphere sees the pool, mirrored by the
/// surface past the window or directly. The shader's `snell_window_share` is the same arithmetic.
pub fn snell_window_share(cos_up: f32) -> f32 {
    let s2 = snell_window_sin2();
    let c = cos_up.clamp(-1.0, 1.0);
    if c * c > s2 {
        return s2 * c.max(0.0);
    }
    let s = (1.0 - c * c).max(1.0e-6).sqrt();
    let x = (1.0 / s2 - 1.0).sqrt();
    let y = -x * c / s;
    let sy = s * (1.0 - y * y).max(0.0).sqrt();
    (((c * y.clamp(-1.0, 1.0).acos() - x * sy) * s2 + (sy / x).atan()) / std::f32::consts::PI).max(0.0)
}

/// The WGSL constants of water's surface the scene shaders share (r0 for Schlick's curve, the
/// two hemisphere averages above, Snell's window's sin²).
pub fn water_surface_wgsl() -> String {
    format!(
        "const WATER_R0: f32 = {:?};\nconst WATER_HEMISPHERE_REFLECTANCE: f32 = {:?};\nconst WATER_ESCAPE: f32 = {:?};\n\
         const SNELL_WINDOW_SIN2: f32 = {:?};\n",
        schlick_r0(),
        hemisphere_reflectance(),
        escape_share(),
        snell_window_sin2()
    )
}

/// The exact reflectance for unpolarised light. `cos_i`: cosine of the incidence angle;
/// `eta`: n_from / n_to. Total internal reflection gives 1. Same arithmetic as the shader's
/// `fresnel` (f32).
pub fn fresnel_exact(cos_i: f32, eta: f32) -> f32 {
    let ci = cos_i.clamp(0.0, 1.0);
    let sin_t2 = eta * eta * (1.0 - ci * ci);
    if sin_t2 >= 1.0 {
        return 1.0;
    }
    let ct = (1.0 - sin_t2).sqrt();
    let rs = (eta * ci - ct) / (eta * ci + ct);
    let rp = (ci - eta * ct) / (ci + eta * ct);
    0.5 * (rs * rs + rp * rp)
}

/// The lookup texture's texels, each row [`FRESNEL_TABLE_SIZE`] exact values at air-side
/// angles i/(size − 1) · 90°: row 0 from air into water (η = 1/n, the incidence angle), row 1
/// from water into air (η = n) indexed by the refracted angle in the air, on which the
/// reflectance is smooth right up to the critical angle (by its own angle it climbs to 1
/// within a fraction of a degree, faster than texels can follow).
pub fn fresnel_table() -> Vec<f32> {
    let last = (FRESNEL_TABLE_SIZE - 1) as f32;
    let air_angle = move |i: u32| i as f32 / last * std::f32::consts::FRAC_PI_2;
    let from_air = (0..FRESNEL_TABLE_SIZE).map(move |i| fresnel_exact(air_angle(i).cos(), 1.0 / IOR_WATER));
    let from_water = (0..FRESNEL_TABLE_SIZE).map(move |i| {
        // Snell: sin θ_water = sin θ_air / n.
        let sin_w = air_angle(i).sin() / IOR_WATER;
        fresnel_exact((1.0 - sin_w * sin_w).sqrt(), IOR_WATER)
    });
    from_air.chain(from_water).collect()
}

/// Reflectance by `model` (see [`FresnelModel`]); `table`: [`fresnel_table`], read only by
/// [`FresnelModel::Table`].
pub fn reflectance(model: FresnelModel, cos_i: f32, eta: f32, table: &[f32]) -> f32 {
    let ci = cos_i.clamp(0.0, 1.0);
    let sin_t2 = eta * eta * (1.0 - ci * ci);
    if model == FresnelModel::Exact || sin_t2 >= 1.0 {
        return fresnel_exact(ci, eta);
    }
    // The cosine on the air side: the incidence angle from above, the refracted one from below.
    let c = if eta > 1.0 { (1.0 - sin_t2).sqrt() } else { ci };
    match model {
        FresnelModel::Exact => unreachable!(),
        FresnelModel::Table => {
            let last = (FRESNEL_TABLE_SIZE - 1) as f32;
            let u = c.acos() / std::f32::consts::FRAC_PI_2 * last;
            let i = (u.floor() as usize).min(FRESNEL_TABLE_SIZE as usize - 2);
            let row = if eta > 1.0 { FRESNEL_TABLE_SIZE as usize } else { 0 };
            let (a, b) = (table[row + i], table[row + i + 1]);
            a + (b - a) * (u - i as f32)
        }
        FresnelModel::Schlick => {
            let r0 = schlick_r0();
            r0 + (1.0 - r0) * (1.0 - c).powf(5.0)
        }
        FresnelModel::InversePower => 1.0 / (1.0 + c).powf(INVERSE_POWER_EXPONENT),
        FresnelModel::ClampedPower => {
            (1.0 - c).powf(CLAMPED_POWER_EXPONENT).clamp(CLAMPED_POWER_MIN, CLAMPED_POWER_MAX)
        }
        FresnelModel::Linear => 1.0 - c,
    }
}

/// `samples` reflectances of `model` at incidence angles evenly from 0° to 90°, seen from air
/// (`from_water` false) or from under the water: the curve the page and the viewer plot.
pub fn reflectance_curve(model: FresnelModel, from_water: bool, samples: usize) -> Vec<f32> {
    let table = fresnel_table();
    let eta = if from_water { IOR_WATER } else { 1.0 / IOR_WATER };
    let last = samples.max(2) as f32 - 1.0;
    (0..samples.max(2))
        .map(|i| reflectance(model, (i as f32 / last * std::f32::consts::FRAC_PI_2).cos(), eta, &table))
        .collect()
}

crate::choices! {
    /// The sun's highlight on the water.
    #[derive(Default)]
    pub enum SpecularModel {
        /// cos^s of the angle between the reflected view ray and the sun.
        #[default]
        Phong = "phong",
        /// cos^s of the angle between the normal and the half vector of the view and sun
        /// directions: a wider highlight at the same s, stretched along the view at grazing angles.
        BlinnPhong = "blinn_phong",
    }
}

/// The sun's disk in the sky at the default size ([`DEFAULT_SUN_SIZE_DEG`]): its brightness
/// rises between these cosines of the angle from its centre.
const SUN_DISK_EDGE_COS: f32 = 0.99988;
const SUN_DISK_CORE_COS: f32 = 0.99995;
/// Angular diameter (degrees) of the sun's disk, between the half-brightness points.
pub const DEFAULT_SUN_SIZE_DEG: f32 = 1.5;

/// The disk's (edge, core) cosines for a sun `size_deg` across: 1 − cos θ ≈ θ²/2 grows with
/// the square of the size. Exact at the default size (the f32 arithmetic gives back the
/// constants), so the default frame does not change.
pub fn sun_disk_cosines(size_deg: f32) -> (f32, f32) {
    let k = (size_deg / DEFAULT_SUN_SIZE_DEG) * (size_deg / DEFAULT_SUN_SIZE_DEG);
    (1.0 - (1.0 - SUN_DISK_EDGE_COS) * k, 1.0 - (1.0 - SUN_DISK_CORE_COS) * k)
}

/// Water's refractive index for red, green and blue light less the green one's (n ≈ 1.331,
/// 1.335, 1.337 across the visible range): the spread the `dispersion` parameter scales.
pub const DISPERSION_SPREAD: [f32; 3] = [-0.004, 0.0, 0.002];

/// The refractive indices of red, green and blue light with the spread exaggerated
/// `dispersion` times, green kept at [`IOR_WATER`] so green light bends as without dispersion.
pub fn channel_iors(dispersion: f32) -> [f32; 3] {
    DISPERSION_SPREAD.map(|d| IOR_WATER + d * dispersion)
}

/// With the `view_colour` option, the share of the water's scattered light left along a
/// horizontal path (all of it looking straight down): seed 002 mixes its water colour between
/// (0, 0.05, 0.15) at grazing and (0, 0.1, 0.15) looking down, half the green.
pub const GRAZING_TINT: [f32; 3] = [1.0, 0.5, 1.0];

/// WGSL constants of this module, for the scene's passes (`render::shaders::scene_prelude_in`).
pub fn wgsl_constants() -> String {
    use FresnelModel::*;
    format!(
        "const FRESNEL_EXACT: u32 = {}u;\nconst FRESNEL_TABLE: u32 = {}u;\nconst FRESNEL_SCHLICK: u32 = {}u;\n\
         const FRESNEL_INVERSE_POWER: u32 = {}u;\nconst FRESNEL_CLAMPED_POWER: u32 = {}u;\nconst FRESNEL_LINEAR: u32 = {}u;\n\
         const FRESNEL_TABLE_SIZE: i32 = {};\nconst SCHLICK_R0: f32 = {:?};\nconst INVERSE_POWER_EXPONENT: f32 = {:?};\n\
         const CLAMPED_POWER_EXPONENT: f32 = {:?};\nconst CLAMPED_POWER_MIN: f32 = {:?};\nconst CLAMPED_POWER_MAX: f32 = {:?};\n\
         const SPECULAR_PHONG: u32 = {}u;\nconst SPECULAR_BLINN_PHONG: u32 = {}u;\n\
         const GRAZING_TINT: vec3<f32> = vec3<f32>({:?}, {:?}, {:?});\n",
        Exact as u32,
        Table as u32,
        Schlick as u32,
        InversePower as u32,
        ClampedPower as u32,
        Linear as u32,
        FRESNEL_TABLE_SIZE,
        schlick_r0(),
        INVERSE_POWER_EXPONENT,
        CLAMPED_POWER_EXPONENT,
        CLAMPED_POWER_MIN,
        CLAMPED_POWER_MAX,
        SpecularModel::Phong as u32,
        SpecularModel::BlinnPhong as u32,
        GRAZING_TINT[0],
        GRAZING_TINT[1],
        GRAZING_TINT[2],
    )
}

/// The sun's disk. (The parameter table, `params::table`, lists them in this order.)
pub const SUN_SIZE_PARAMS: &[ParamSpec] = &[ParamSpec {
    name: "sun_size",
    label: "Sun size",
    group: "Light",
    unit: "°",
    control: slider(0.5, 5.0, 0.1),
    default: crate::optics::DEFAULT_SUN_SIZE_DEG,
    help: "Angular diameter of the sun's disk in the sky and in its reflections (the real sun: 0.5°).",
}];

/// How the surface reflects: the Fresnel and specular models, dispersion. (The parameter table, `params::table`, lists them in this order.)
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        name: "fresnel",
        label: "Fresnel model",
        group: "Optics",
        unit: "",
        control: Control::Choice { values: FresnelModel::VALUES, names: FresnelModel::NAMES },
        default: 0.0,
        help: "How much of the light the surface reflects at each angle: the exact Fresnel equations, the same from a lookup texture, Schlick's approximation, 1/(1+cos θ)^8, clamp((1-cos θ)^4, 0.05, 0.3) or 1-cos θ.",
    },
    ParamSpec {
        name: "specular",
        label: "Sun highlight",
        group: "Optics",
        unit: "",
        control: Control::Choice { values: SpecularModel::VALUES, names: SpecularModel::NAMES },
        default: 0.0,
        help: "Shape of the sun's glint on the water: Phong (reflected ray against the sun) or Blinn-Phong (normal against the half vector), wider at the same shininess.",
    },
    ParamSpec {
        name: "shininess",
        label: "Shininess",
        group: "Optics",
        unit: "",
        control: slider(100.0, 10000.0, 100.0),
        default: 3000.0,
        help: "Exponent s of the highlight's cos^s: higher is a smaller, sharper glint.",
    },
    ParamSpec {
        name: "dispersion",
        label: "Dispersion",
        group: "Optics",
        unit: "×",
        control: slider(0.0, 20.0, 0.5),
        default: 0.0,
        help: "Red and blue light bend by their own refractive indices (water: 1.331 red, 1.335 green, 1.337 blue), this many times the real spread: coloured fringes at the caustics' edges and at the rim of Snell's window. 0: off.",
    },
];

/// The water's colour: absorption and scattering per channel, the view's colour. (The parameter table, `params::table`, lists them in this order.)
pub const WATER_COLOUR_PARAMS: &[ParamSpec] = &[
    ParamSpec {
        name: "absorption_red",
        label: "Absorption, red",
        group: "Water colour",
        unit: "1/m",
        control: slider(0.0, 2.0, 0.005),
        default: 1.2,
        help: "Beer-Lambert absorption of red light per metre of water: after d metres exp(-a d) of it is left.",
    },
    ParamSpec {
        name: "absorption_green",
        label: "Absorption, green",
        group: "Water colour",
        unit: "1/m",
        control: slider(0.0, 2.0, 0.005),
        default: 0.24,
        help: "Beer-Lambert absorption of green light per metre of water: after d metres exp(-a d) of it is left.",
    },
    ParamSpec {
        name: "absorption_blue",
        label: "Absorption, blue",
        group: "Water colour",
        unit: "1/m",
        control: slider(0.0, 2.0, 0.005),
        default: 0.10,
        help: "Beer-Lambert absorption of blue light per metre of water: after d metres exp(-a d) of it is left.",
    },
    ParamSpec {
        name: "scatter_red",
        label: "Scattered light, red",
        group: "Water colour",
        unit: "",
        control: slider(0.0, 0.5, 0.005),
        default: 0.0,
        help: "Light the water itself scatters towards you (red, linear units; the sky is about 0.5): it fills in what absorption takes, so deep water turns this colour instead of black. 0 in every channel: off.",
    },
    ParamSpec {
        name: "scatter_green",
        label: "Scattered light, green",
        group: "Water colour",
        unit: "",
        control: slider(0.0, 0.5, 0.005),
        default: 0.0,
        help: "Light the water itself scatters towards you (green, linear units; the sky is about 0.5): it fills in what absorption takes, so deep water turns this colour instead of black. 0 in every channel: off.",
    },
    ParamSpec {
        name: "scatter_blue",
        label: "Scattered light, blue",
        group: "Water colour",
        unit: "",
        control: slider(0.0, 0.5, 0.005),
        default: 0.0,
        help: "Light the water itself scatters towards you (blue, linear units; the sky is about 0.5): it fills in what absorption takes, so deep water turns this colour instead of black. 0 in every channel: off.",
    },
    ParamSpec {
        name: "view_colour",
        label: "Colour by view angle",
        group: "Water colour",
        unit: "",
        control: Control::Toggle,
        default: 0.0,
        help: "The scattered light loses half its green along grazing paths and keeps it looking straight down, as games tint water by the view angle (needs scattered light).",
    },
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_model_stays_between_0_and_1_and_total_internal_reflection_stays_exact() {
        let table = fresnel_table();
        let critical = (1.0 / IOR_WATER).asin();
        for &model in FresnelModel::ALL {
            let above = reflectance_curve(model, false, 91);
            let below = reflectance_curve(model, true, 91);
            println!(
                "{model:?}: from air 0° {:.4}, 45° {:.4}, 80° {:.4}; from water 30° {:.4}, 48° {:.4}",
                above[0], above[45], above[80], below[30], below[48]
            );
            assert!(above.iter().chain(&below).all(|r| (0.0..=1.0).contains(r)), "{model:?} out of [0, 1]");
            // Past the critical angle (48.6°) every model reflects everything.
            let past = (critical + 0.01).cos();
            assert_eq!(reflectance(model, past, IOR_WATER, &table), 1.0, "{model:?} under total internal reflection");
        }
    }

    #[test]
    fn waters_hemisphere_reflectance_and_the_light_that_escapes_from_below_match_a_direct_count() {
        // The escape share counted directly: cosine-weighted directions under the water, each
        // passing 1 − R(θ) from water to air (0 past the critical angle).
        let steps = 4096;
        let dt = std::f32::consts::FRAC_PI_2 / steps as f32;
        let escaped: f32 = (0..steps)
            .map(|i| {
                let t = (i as f32 + 0.5) * dt;
                2.0 * (1.0 - fresnel_exact(t.cos(), IOR_WATER)) * t.cos() * t.sin() * dt
            })
            .sum();
        let (r, e) = (hemisphere_reflectance(), escape_share());
        println!(
            "hemisphere reflectance {r:.4}, escape share {e:.4} (counted from below {escaped:.4}), r0 {:.4}",
            schlick_r0()
        );
        assert!((0.06..0.07).contains(&r), "water's hemisphere reflectance {r}");
        assert!((e - escaped).abs() < 2e-3, "reciprocity: {e} against {escaped}");
    }

    #[test]
    fn the_light_through_snells_window_matches_a_count_of_directions_at_every_tilt() {
        // Cosine-weighted directions round a normal tilted from straight up, counted on a grid
        // of the normal's hemisphere: the share whose direction lies within the critical angle
        // of straight up.
        let critical_cos = (1.0 - snell_window_sin2()).sqrt();
        let (rings, slices) = (512, 1024);
        for deg in [0, 30, 41, 60, 90, 120, 139, 150, 180] {
            let tilt = (deg as f32).to_radians();
            let (st, ct) = tilt.sin_cos();
            let mut counted = 0.0f64;
            for i in 0..rings {
                // Equal steps of sin² of the angle from the normal: each ring carries the same
                // cosine-weighted share.
                let s2 = (i as f64 + 0.5) / rings as f64;
                let (sin_a, cos_a) = (s2.sqrt(), (1.0 - s2).sqrt());
                for j in 0..slices {
                    let phi = (j as f64 + 0.5) / slices as f64 * std::f64::consts::TAU;
                    // The direction in the normal's frame, its height turned by the tilt.
                    let up = cos_a * ct as f64 + sin_a * phi.cos() * st as f64;
                    if up > critical_cos as f64 {
                        counted += 1.0;
                    }
                }
            }
            let counted = (counted / (rings * slices) as f64) as f32;
            let share = snell_window_share(tilt.cos());
            println!("normal {deg:3}° from up: through the window {share:.4} (counted {counted:.4})");
            assert!((share - counted).abs() < 2e-3, "{deg}°: {share} against {counted}");
        }
        assert!((snell_window_share(1.0) - 0.5625).abs() < 1e-3);
    }

    #[test]
    fn the_approximations_are_near_the_exact_curve_where_the_seeds_say() {
        let table = fresnel_table();
        let eta = 1.0 / IOR_WATER;
        let worst = |model, from_deg: i32, to_deg: i32| {
            (from_deg..=to_deg)
                .map(|d| {
                    let c = (d as f32).to_radians().cos();
                    (reflectance(model, c, eta, &table) - fresnel_exact(c, eta)).abs()
                })
                .fold(0.0f32, f32::max)
        };
        let table_err = worst(FresnelModel::Table, 0, 89);
        let schlick_err = worst(FresnelModel::Schlick, 0, 89);
        let schlick_low = worst(FresnelModel::Schlick, 0, 60);
        let inverse_low = worst(FresnelModel::InversePower, 0, 30);
        let linear_low = worst(FresnelModel::Linear, 0, 30);
        println!(
            "largest difference from exact, from air: table {table_err:.5} (0-89°), Schlick {schlick_low:.4} (0-60°) \
             {schlick_err:.4} (0-89°), 1/(1+cos)^8 {inverse_low:.4} (0-30°), 1 - cos {linear_low:.4} (0-30°)"
        );
        assert!(table_err < 2e-3, "the table is {table_err} off");
        // Schlick drifts only towards grazing incidence (most near 85°).
        assert!(schlick_low < 0.012 && schlick_err < 0.07, "Schlick is {schlick_low} / {schlick_err} off");
        assert!(schlick_r0() > 0.0203 && schlick_r0() < 0.0205);
        // The cheap curves are for the look, not the numbers: at normal incidence 1/(1+cos)^8
        // gives 1/256 (exact: 0.020), 1 - cos gives 0.
        assert!(inverse_low < 0.02 && linear_low < 0.15);
    }

    #[test]
    fn the_default_sun_disk_is_the_one_drawn_before_the_parameter() {
        assert_eq!(sun_disk_cosines(DEFAULT_SUN_SIZE_DEG), (0.99988, 0.99995));
        let (edge, core) = sun_disk_cosines(3.0);
        println!("a 3° sun: edge cos {edge}, core cos {core}");
        assert!(edge < 0.99988 && core < 0.99995 && edge < core);
    }
}
