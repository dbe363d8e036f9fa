//! Ambient waves: a surface that moves on its own under the interactive ripples, as the
//! seeds teach it (sums of sines, Gerstner waves, the basin's own standing waves, and
//! Tessendorf's FFT ocean in [`ocean`]). It is added to the
//! simulated heightfield where the renderer reads the water (heights and slopes summed) and
//! where the floating bodies feel it; the simulation itself never sees it. Its time is
//! simulated time, so pausing stops it and every frame rate gives the same surface.
//!
//! One set of formulas for both sides: the shader (`ambient_at` in scene_surface.wgsl) evaluates the
//! waves from [`AmbientWaves::uniform`] (the FFT ocean from a map of its surface), the bodies
//! and the tests from [`AmbientWaves::sample`]; each wave's phase is advanced here in f64 so that long runs keep
//! their precision. Lengths in metres, times in seconds, angles in radians unless named `_deg`.

pub mod cascades;
mod fft;
pub mod gpu_ocean;
pub mod ocean;
pub mod params;
mod waves;

use waves::{gerstner, sharp_sine, standing, SHARP_SINE_MEAN};

use crate::sim::SplitMix64;
use crate::world::PoolShape;
use ocean::{Ocean, OceanNow};

crate::choices! {
    /// Which ambient surface, from the `ambient` parameter.
    #[derive(Default)]
    pub enum AmbientModel {
        #[default]
        None = "none",
        /// A few directional travelling waves with sharpened crests, Finch's
        /// h = 2a(((sin θ + 1)/2)^k − mean): no longer one sine's symmetric hump.
        Sines = "sines",
        /// The basin's own standing waves, h = Σ a cos(nπx'/W) cos(mπz'/W) cos(ωt + φ) with x', z'
        /// measured from a wall: every wall is met with zero slope, as a reflecting pool does.
        Modes = "modes",
        /// Gerstner (trochoidal) waves: each point of the surface moves on a circle, the water
        /// gathering under the crests (sharp) and spreading in the troughs (flat). A point at rest
        /// x₀ is at x₀ − Σ c a (K/k) sin θ, height Σ a cos θ, θ = K·x₀ + p, c = Q / Σ a k.
        Gerstner = "gerstner",
        /// Tessendorf's ocean: a wave spectrum on the lattice that tiles the pool, summed by an
        /// inverse FFT every frame ([`ocean`]).
        Fft = "fft",
    }
}

crate::choices! {
    /// The wave spectrum of the FFT ocean, from the `spectrum` parameter.
    #[derive(Default)]
    pub enum Spectrum {
        /// Tessendorf's choice: exp(−1/(kL)²)/k⁴ (k̂·ŵ)², L = V²/g.
        #[default]
        Phillips = "phillips",
        /// Measured seas of limited fetch (Hasselmann 1973): a sharper peak.
        Jonswap = "jonswap",
    }
}

/// Cells per side of the spectrum debug view's image (wavevectors up to ±32π/W rad/m:
/// wavelengths down to 6 cm with the 2 m pool).
pub const SPECTRUM_IMAGE_SIZE: usize = 64;

/// Waves an ambient surface holds (the shader's uniform array has room for this many).
pub const MAX_AMBIENT_WAVES: usize = 16;
/// Travelling waves of the `sines` and `gerstner` models.
const SINE_WAVES: usize = 6;
/// Newton steps that find the rest point of the Gerstner surface above a point (the
/// displacement is a contraction of factor ≤ Q, four steps leave < 2e-6 m even at the largest Q).
pub const GERSTNER_NEWTON_STEPS: usize = 4;
/// Exponent k of Finch's sharpened sine.
pub const CREST_SHARPNESS: f32 = 2.0;
/// Shortest and longest wavelengths (m) of the ambient waves: a pool in a light breeze.
pub const SHORTEST_WAVELENGTH: f32 = 0.2;
pub const LONGEST_WAVELENGTH: f32 = 0.9;
/// Gravity (m/s²).
pub const G: f32 = 9.81;
/// k_m = sqrt(ρ g / σ) for clean water (rad/m): where surface tension weighs as much as
/// gravity in the dispersion relation.
pub const CAPILLARY_WAVENUMBER: f32 = 370.0;

/// Angular frequency (rad/s) of a water wave of wavenumber `k` (rad/m) on water `depth` (m)
/// deep: ω² = g k tanh(k D) (1 + (k/k_m)²), gravity and surface tension. (Beware the widely
/// copied `k * k / KM * KM`: that is k², not (k/k_m)².)
pub fn angular_frequency_in(k: f32, depth: f32) -> f32 {
    let ratio = k / CAPILLARY_WAVENUMBER;
    // tanh(9) = 1 − 3e-8; the cap keeps the shader's copy finite where tanh overflows.
    (G * k * (k * depth).min(9.0).tanh() * (1.0 + ratio * ratio)).sqrt()
}

/// The physical settings of the ambient surface (from the parameter table).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct AmbientSettings {
    pub model: AmbientModel,
    /// Wind speed (m/s): the Phillips spectrum's L = V²/g puts its energy at wavelengths
    /// around 2πL, so stronger wind favours the longer waves.
    pub wind_speed: f32,
    /// Direction the wind blows towards (degrees, from +x towards +z).
    pub wind_direction_deg: f32,
    /// Significant wave height H_s = 4 × standard deviation of the surface (m).
    pub significant_height: f32,
    /// Spread of the waves' directions around the wind (degrees, ±).
    pub spread_deg: f32,
    /// Gerstner steepness Q (0 = sines, 1 = cusps at the crests): Σ Q_i k_i a_i = Q.
    pub steepness: f32,
    /// The FFT ocean's spectrum and lattice points per side (64 or 128).
    pub spectrum: Spectrum,
    pub fft_size: usize,
    /// The FFT ocean's choppiness λ (see [`Ocean::choppiness`]).
    pub choppiness: f32,
    /// The pool the waves are in: the basin's modes fit its width, the FFT ocean tiles it,
    /// every wave runs at the speed its depth gives.
    pub basin: PoolShape,
}

impl AmbientSettings {
    /// `model` with every other setting at its parameter's default (a light breeze: 3 m/s,
    /// 1 cm significant height).
    pub fn default_for(model: AmbientModel) -> Self {
        Self {
            model,
            wind_speed: params::WIND_SPEED.default,
            wind_direction_deg: params::WIND_DIRECTION.default,
            significant_height: params::WAVE_HEIGHT.default,
            spread_deg: params::WAVE_SPREAD.default,
            steepness: params::STEEPNESS.default,
            spectrum: Spectrum::from(params::SPECTRUM.default),
            fft_size: params::FFT_SIZE.default as usize,
            choppiness: params::CHOPPINESS.default,
            basin: PoolShape::CLASSIC,
        }
    }
}

/// One wave of the surface. Sines: h = 2a(((sin(k·x + p) + 1)/2)^k − mean); modes:
/// h = a cos(kx (x + W)) cos(kz (z + W)) cos(p); p advances by −ω t (sines) or ω t (modes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Wave {
    pub kx: f32,
    pub kz: f32,
    pub amplitude: f32,
    pub omega: f32,
    /// Phase at t = 0.
    pub phase: f64,
}

/// The waves of one ambient surface.
#[derive(Clone, Debug, PartialEq)]
pub struct AmbientWaves {
    pub model: AmbientModel,
    pub waves: Vec<Wave>,
    /// Gerstner: Q / Σ a_i k_i; wave i moves the water sideways by this × a_i (m) and
    /// takes Q_i = this × a_i k_i of the steepness.
    pub gerstner_c: f32,
    /// The FFT ocean's spectrum (model `Fft`).
    pub ocean: Option<Ocean>,
    /// The pool the waves are in.
    pub basin: PoolShape,
}

/// The ambient surface at one moment, to sample at many points (the floating bodies' probes,
/// every frame): the waves' phases, or the FFT ocean's amplitudes, computed once
/// ([`OceanNow`]). The same surface as [`AmbientWaves::sample`].
pub struct AmbientNow<'a> {
    waves: &'a AmbientWaves,
    phases: Vec<f32>,
    ocean: Option<OceanNow>,
}

impl AmbientNow<'_> {
    /// Height (m) and slopes dh/dx, dh/dz at (x, z) (m).
    pub fn sample(&self, x: f32, z: f32) -> [f32; 3] {
        match &self.ocean {
            Some(ocean) => ocean.sample(x, z),
            None => self.waves.sum(&self.phases, x, z),
        }
    }
}

/// The Phillips spectrum's shape at wavevector (kx, kz) for wind `settings`, without its
/// scale: exp(−1/(kL)²)/k⁴ · (its alignment with the wind)², L = V²/g.
fn phillips(kx: f32, kz: f32, settings: &AmbientSettings) -> f32 {
    let k = (kx * kx + kz * kz).sqrt().max(1e-6);
    let l = settings.wind_speed * settings.wind_speed / G;
    let wind = settings.wind_direction_deg.to_radians();
    let align = (kx * wind.cos() + kz * wind.sin()) / k;
    (-1.0 / (k * l).powi(2)).exp() / k.powi(4) * align * align
}

impl AmbientWaves {
    /// The wave set for `settings`, the same every time for the same settings (seeded).
    pub fn new(settings: &AmbientSettings) -> Self {
        let mut rng = SplitMix64(0x5eed_a3b1);
        let (k_min, k_max) = (std::f32::consts::TAU / LONGEST_WAVELENGTH, std::f32::consts::TAU / SHORTEST_WAVELENGTH);
        let waves = match settings.model {
            AmbientModel::None => Vec::new(),
            AmbientModel::Fft => {
                let size = settings.fft_size.clamp(8, 256).next_power_of_two();
                let ocean = Some(Ocean::new(settings, size));
                return Self {
                    model: settings.model,
                    waves: Vec::new(),
                    gerstner_c: 0.0,
                    ocean,
                    basin: settings.basin,
                };
            }
            AmbientModel::Sines | AmbientModel::Gerstner => waves::travelling_waves(settings, &mut rng, k_min, k_max),
            AmbientModel::Modes => waves::basin_modes(settings, &mut rng, k_min, k_max),
        };
        let mut set = Self { model: settings.model, waves, gerstner_c: 0.0, ocean: None, basin: settings.basin };
        // Scale to the significant height, measured over the pool and a few instants.
        let hs = set.measured_significant_height();
        if hs > 0.0 {
            let scale = settings.significant_height / hs;
            for w in &mut set.waves {
                w.amplitude *= scale;
            }
        }
        // Gerstner: each wave's share of the steepness Q in proportion to its slope a k, so the
        // waves that shape the surface are the ones that sharpen (Σ Q_i = Q < 1: no loops).
        let slopes: f32 = set.waves.iter().map(|w| w.amplitude * (w.kx * w.kx + w.kz * w.kz).sqrt()).sum();
        if settings.model == AmbientModel::Gerstner && slopes > 0.0 {
            set.gerstner_c = settings.steepness.clamp(0.0, MAX_STEEPNESS) / slopes;
            // The shape changed the heights' spread a little: measure again.
            let hs = set.measured_significant_height();
            if hs > 0.0 {
                let scale = settings.significant_height / hs;
                for w in &mut set.waves {
                    w.amplitude *= scale;
                }
                set.gerstner_c /= scale;
            }
        }
        set
    }

    /// 4 × the standard deviation of the surface over a grid of the pool at a few instants.
    pub fn measured_significant_height(&self) -> f32 {
        let (mut sum, mut sq, mut n) = (0.0f64, 0.0f64, 0.0f64);
        for t in [0.0, 0.37, 1.1, 2.9] {
            for i in 0..40 {
                for j in 0..40 {
                    let w = self.basin.half_width;
                    let x = (i as f32 + 0.5) / 40.0 * 2.0 * w - w;
                    let z = (j as f32 + 0.5) / 40.0 * 2.0 * w - w;
                    let h = self.sample(x, z, t)[0] as f64;
                    sum += h;
                    sq += h * h;
                    n += 1.0;
                }
            }
        }
        let mean = sum / n;
        (4.0 * (sq / n - mean * mean).max(0.0).sqrt()) as f32
    }

    /// Each wave's phase p at simulated time `t` (s), reduced to [0, 2π) in f64.
    pub fn phases(&self, t: f64) -> Vec<f32> {
        let sign = if self.model == AmbientModel::Modes { 1.0 } else { -1.0 };
        self.waves
            .iter()
            .map(|w| (w.phase + sign * w.omega as f64 * t).rem_euclid(std::f64::consts::TAU) as f32)
            .collect()
    }

    /// Height (m) and slopes dh/dx, dh/dz of the ambient surface at (x, z) (m) and simulated
    /// time `t` (s). Same arithmetic as the shader's `ambient_at` (the FFT ocean: its waves
    /// summed one by one, of which the shader's map holds the samples).
    pub fn sample(&self, x: f32, z: f32, t: f64) -> [f32; 3] {
        match &self.ocean {
            Some(ocean) => ocean.sample(x, z, t),
            None => self.sum(&self.phases(t), x, z),
        }
    }

    /// The surface at time `t` (s), to sample at many points: see [`AmbientNow`].
    pub fn at(&self, t: f64) -> AmbientNow<'_> {
        match &self.ocean {
            Some(ocean) => AmbientNow { waves: self, phases: Vec::new(), ocean: Some(ocean.at(t)) },
            None => AmbientNow { waves: self, phases: self.phases(t), ocean: None },
        }
    }

    /// The sines', modes' or Gerstner waves' surface at (x, z) with each wave at `phases`.
    fn sum(&self, phases: &[f32], x: f32, z: f32) -> [f32; 3] {
        if self.model == AmbientModel::Gerstner {
            return gerstner(&self.waves, phases, self.gerstner_c, x, z);
        }
        let mut out = [0.0f32; 3];
        for (w, &p) in self.waves.iter().zip(phases) {
            let [h, dx, dz] = match self.model {
                AmbientModel::Modes => {
                    standing(w.kx, w.kz, w.amplitude, p, x + self.basin.half_width, z + self.basin.half_width)
                }
                _ => sharp_sine(w.kx, w.kz, w.amplitude, p, x, z),
            };
            out = [out[0] + h, out[1] + dx, out[2] + dz];
        }
        out
    }

    /// The shader's view of the waves at simulated time `t`: per wave (kx, kz, amplitude,
    /// phase), [`MAX_AMBIENT_WAVES`] of them (unused ones have zero amplitude), and
    /// (count, Gerstner's c = Q / Σ a k, the FFT's choppiness λ, 0).
    pub fn uniform(&self, t: f64) -> ([[f32; 4]; MAX_AMBIENT_WAVES], [f32; 4]) {
        let mut out = [[0.0; 4]; MAX_AMBIENT_WAVES];
        for ((slot, w), p) in out.iter_mut().zip(&self.waves).zip(self.phases(t)) {
            *slot = [w.kx, w.kz, w.amplitude, p];
        }
        let choppiness = self.ocean.as_ref().map_or(0.0, |o| o.choppiness);
        (out, [self.waves.len().min(MAX_AMBIENT_WAVES) as f32, self.gerstner_c, choppiness, 0.0])
    }

    /// The spectrum debug view's image: [`SPECTRUM_IMAGE_SIZE`]² cells of wavevector space,
    /// (π/W) rad/m apart with k = 0 at cell (N/2, N/2), x along rows, each holding log10 of
    /// the amplitude (m) there (−12 where there is no wave). The FFT ocean: |h0(k)| per
    /// lattice point (the wave travelling along k); the sines and Gerstner waves: each wave's amplitude at its
    /// nearest cell; a standing mode: half its amplitude at (±kx, ±kz), the travelling waves
    /// it is made of.
    pub fn spectrum_image(&self) -> Vec<f32> {
        let n = SPECTRUM_IMAGE_SIZE;
        let mut amplitude = vec![0.0f32; n * n];
        let unit = std::f32::consts::PI / self.basin.half_width;
        let mut add = |kx: f32, kz: f32, a: f32| {
            let (i, j) = ((kx / unit).round() as i32 + n as i32 / 2, (kz / unit).round() as i32 + n as i32 / 2);
            if (0..n as i32).contains(&i) && (0..n as i32).contains(&j) {
                let cell = &mut amplitude[j as usize * n + i as usize];
                *cell = (*cell * *cell + a * a).sqrt();
            }
        };
        if let Some(ocean) = &self.ocean {
            let m = ocean.size;
            for (idx, h) in ocean.h0.iter().enumerate() {
                let (kx, kz) = (ocean::lattice_k(idx % m, m, self.basin), ocean::lattice_k(idx / m, m, self.basin));
                add(kx, kz, (h[0] * h[0] + h[1] * h[1]).sqrt());
            }
        } else {
            for w in &self.waves {
                if self.model == AmbientModel::Modes {
                    for (sx, sz) in [(1.0, 1.0), (1.0, -1.0), (-1.0, 1.0), (-1.0, -1.0)] {
                        add(sx * w.kx, sz * w.kz, 0.5 * w.amplitude);
                    }
                } else {
                    add(w.kx, w.kz, w.amplitude);
                }
            }
        }
        amplitude.iter().map(|&a| if a > 0.0 { a.log10() } else { -12.0 }).collect()
    }
}

/// The largest Gerstner steepness: at Q = 1 the crests become cusps (infinite slope); a
/// little below keeps the surface a function and its normals finite.
pub const MAX_STEEPNESS: f32 = 0.9;

/// WGSL constants of this module, for the passes that use them (the scene's, see
/// `render::shaders::scene_prelude_in`; the FFT's).
pub fn wgsl_constants() -> String {
    format!(
        "const AMBIENT_NONE: u32 = {}u;\nconst AMBIENT_SINES: u32 = {}u;\nconst AMBIENT_MODES: u32 = {}u;\n\
         const AMBIENT_GERSTNER: u32 = {}u;\nconst AMBIENT_FFT: u32 = {}u;\n\
         const MAX_AMBIENT_WAVES: i32 = {};\nconst SHARP_SINE_MEAN: f32 = {:?};\nconst GERSTNER_NEWTON_STEPS: i32 = {};\nconst CHOP_NEWTON_STEPS: i32 = {};\n\
         const CHOP_STEP_LIMIT: f32 = {:?};\nconst CHOP_SLOPE_LIMIT: f32 = {:?};\n\
         const GRAVITY: f32 = {:?};\nconst CAPILLARY_WAVENUMBER: f32 = {:?};\n\
         const AMBIENT_SHORTEST: f32 = {:?};\nconst AMBIENT_LONGEST: f32 = {:?};\n",
        AmbientModel::None as u32,
        AmbientModel::Sines as u32,
        AmbientModel::Modes as u32,
        AmbientModel::Gerstner as u32,
        AmbientModel::Fft as u32,
        MAX_AMBIENT_WAVES,
        SHARP_SINE_MEAN,
        GERSTNER_NEWTON_STEPS,
        ocean::CHOP_NEWTON_STEPS,
        ocean::CHOP_STEP_LIMIT,
        ocean::CHOP_SLOPE_LIMIT,
        G,
        CAPILLARY_WAVENUMBER,
        SHORTEST_WAVELENGTH,
        LONGEST_WAVELENGTH,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On the classic pool's water.
    fn angular_frequency(k: f32) -> f32 {
        angular_frequency_in(k, PoolShape::CLASSIC.depth)
    }

    fn settings(model: AmbientModel) -> AmbientSettings {
        AmbientSettings::default_for(model)
    }

    #[test]
    fn the_surface_made_once_per_frame_is_the_surface_summed_wave_by_wave() {
        let cases = [
            ("sines", settings(AmbientModel::Sines)),
            ("modes", settings(AmbientModel::Modes)),
            ("gerstner", settings(AmbientModel::Gerstner)),
            ("fft 64", settings(AmbientModel::Fft)),
            ("fft 128 choppy", AmbientSettings { fft_size: 128, choppiness: 2.0, ..settings(AmbientModel::Fft) }),
        ];
        for (name, s) in cases {
            let waves = AmbientWaves::new(&s);
            let (mut worst, mut largest) = (0.0f32, 0.0f32);
            for t in [0.7, 1234.56] {
                let now = waves.at(t);
                for i in 0..200 {
                    let (x, z) = (-0.99 + (i % 20) as f32 * 0.099, -0.99 + (i / 20) as f32 * 0.198);
                    let (a, b) = (waves.sample(x, z, t), now.sample(x, z));
                    largest = largest.max(a[0].abs());
                    worst = worst.max((0..3).map(|c| (a[c] - b[c]).abs()).fold(0.0, f32::max));
                }
            }
            println!("{name}: largest height {largest:.2e} m, largest difference (height, slopes) {worst:.2e}");
            assert!(largest > 1e-3, "{name}: no waves");
            assert!(worst < 2e-6, "{name}: the per-frame surface differs by {worst:e}");
        }
    }

    #[test]
    fn the_dispersion_relation_has_gravity_depth_and_surface_tension() {
        // Deep-water gravity waves: ω² = g k; at k_m surface tension doubles it.
        let k = 10.0;
        let deep = (G * k).sqrt();
        println!(
            "ω at k = 10: {:.4} (deep gravity {deep:.4}); at k_m: {:.2}",
            angular_frequency(k),
            angular_frequency(CAPILLARY_WAVENUMBER)
        );
        assert!((angular_frequency(k) / deep - (1.0 + (k / CAPILLARY_WAVENUMBER).powi(2)).sqrt()).abs() < 1e-3);
        let km = CAPILLARY_WAVENUMBER;
        assert!((angular_frequency(km).powi(2) / (2.0 * G * km) - 1.0).abs() < 1e-3);
        // The wrong `k * k / KM * KM` would give ω² = g k (1 + k²): 100x too fast here.
        assert!(angular_frequency(k) < 1.01 * (G * k * 1.01).sqrt());
        // Shallow-ish: a 4 m wave on 1 m of water is slowed by tanh(k D).
        let long = std::f32::consts::PI / 2.0;
        assert!(angular_frequency(long) < 0.96 * (G * long).sqrt());
    }

    #[test]
    fn each_model_has_the_asked_significant_height_and_stays_far_below_the_rim() {
        for model in [AmbientModel::Sines, AmbientModel::Gerstner, AmbientModel::Modes] {
            let waves = AmbientWaves::new(&settings(model));
            let hs = waves.measured_significant_height();
            let highest = (0..2000)
                .map(|i| {
                    let (x, z, t) = ((i % 41) as f32 / 20.0 - 1.0, (i / 41) as f32 / 24.0 - 1.0, i as f64 * 0.013);
                    waves.sample(x, z, t)[0].abs()
                })
                .fold(0.0f32, f32::max);
            let lengths: Vec<String> = waves
                .waves
                .iter()
                .map(|w| format!("{:.2}", std::f32::consts::TAU / (w.kx * w.kx + w.kz * w.kz).sqrt()))
                .collect();
            println!(
                "{model:?}: {} waves, wavelengths {lengths:?} m, H_s {hs:.4} m, highest {highest:.4} m",
                waves.waves.len()
            );
            assert!(!waves.waves.is_empty() && waves.waves.len() <= MAX_AMBIENT_WAVES);
            assert!((hs - 0.01).abs() < 1e-4, "{model:?}: H_s {hs}");
            assert!(highest < 0.03, "{model:?}: {highest} m");
        }
    }

    #[test]
    fn the_modes_meet_every_wall_with_zero_slope_and_the_sines_travel_with_the_wind() {
        let modes = AmbientWaves::new(&settings(AmbientModel::Modes));
        let mut steepest_at_wall = 0.0f32;
        for i in 0..=20 {
            let along = i as f32 / 10.0 - 1.0;
            for t in [0.0, 0.7, 1.9] {
                let [_, dx, _] = modes.sample(PoolShape::CLASSIC.half_width, along, t);
                let [_, dx2, _] = modes.sample(-PoolShape::CLASSIC.half_width, along, t);
                let [_, _, dz] = modes.sample(along, PoolShape::CLASSIC.half_width, t);
                let [_, _, dz2] = modes.sample(along, -PoolShape::CLASSIC.half_width, t);
                steepest_at_wall = steepest_at_wall.max(dx.abs()).max(dx2.abs()).max(dz.abs()).max(dz2.abs());
            }
        }
        let inside = (0..50).map(|i| modes.sample(0.3 - i as f32 * 0.01, 0.1, 0.5)[1].abs()).fold(0.0f32, f32::max);
        println!("modes: steepest slope across a wall {steepest_at_wall:.2e}, inside up to {inside:.3}");
        assert!(steepest_at_wall < 1e-4, "slope {steepest_at_wall} at a wall");
        assert!(inside > 1e-3);
        // The sines' crests move downwind at the phase speed ω/k of their wavelength.
        let sines = AmbientWaves::new(&settings(AmbientModel::Sines));
        let w = sines.waves[0];
        let k = (w.kx * w.kx + w.kz * w.kz).sqrt();
        let speed = w.omega / k;
        let dt = 0.05;
        let moved = speed * dt as f32; // along (kx, kz) / k
        let single = AmbientWaves { waves: vec![w], ..sines.clone() };
        let (x0, z0) = (0.1, -0.2);
        let (x1, z1) = (x0 + moved * w.kx / k, z0 + moved * w.kz / k);
        let (a, b) = (single.sample(x0, z0, 0.0)[0], single.sample(x1, z1, dt)[0]);
        println!(
            "a {:.2} m wave: phase speed {speed:.3} m/s; height {a:.6} here now, {b:.6} downwind {dt} s later",
            std::f32::consts::TAU / k
        );
        assert!((a - b).abs() < 1e-6);
    }
}
