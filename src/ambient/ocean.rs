//! Tessendorf's FFT ocean: a wave spectrum (Phillips, or JONSWAP) sampled once on the lattice
//! of waves that tile a square 2W wide (wavevectors k = (π/W)(m, n); the pool's tile is the
//! pool, the open sea's cascades have tiles of their own: [`Band`]) with seeded Gaussian noise,
//! h(k, t) advanced analytically, and the surface h(x) = Σ h(k, t) e^{i k·x} made by an
//! inverse FFT.
//!
//! The inverse FFT is `fft.rs`'s. Lengths in metres, times in seconds.

use super::fft::mul;
pub use super::fft::{fft_plan, inverse_fft_2d, inverse_fft_2d_by, stockham_gather, Complex, CPU_RADIX, GPU_RADIX};
use super::{angular_frequency_in, AmbientSettings, Spectrum, G, LONGEST_WAVELENGTH};
use crate::sim::SplitMix64;
use crate::world::PoolShape;

fn add(a: Complex, b: Complex) -> Complex {
    [a[0] + b[0], a[1] + b[1]]
}

fn conj(a: Complex) -> Complex {
    [a[0], -a[1]]
}

/// The shortest wave the lattice holds, in grid cells (4: a wave of 4 cells is still drawn
/// as a wave by bilinear sampling, one of 2 would be a checkerboard).
pub const SHORTEST_WAVE_CELLS: f32 = 4.0;
/// JONSWAP's peak enhancement γ and widths σ below and above the peak (Hasselmann et al. 1973).
const JONSWAP_GAMMA: f32 = 3.3;
const JONSWAP_SIGMA: (f32, f32) = (0.07, 0.09);
/// The fetch (m) the pool's JONSWAP peak is computed for: the pool stands for a patch of a lake
/// the wind has crossed this far (with the pool's own 2 m the peak would be 2 cm ripples).
pub const JONSWAP_FETCH: f32 = 100.0;

/// The waves one lattice holds: a square tile 2 × `half_tile` wide (m) that repeats, the
/// wavelengths from `longest` down to `shortest` (m) on water `depth` deep (m), and the seed of
/// their random amplitudes and phases, and the distance the wind has blown over the water
/// (`fetch`, m: JONSWAP's peak). It holds the wavelengths from `shortest` up to, not
/// including, `longest`. `shared_with`: the `longest` of other lattices (m; 0 for none) that
/// hold the same waves: a wave shorter than k of them is held by k + 1 lattices, each with
/// 1/(k + 1) of its energy.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Band {
    pub half_tile: f32,
    pub longest: f32,
    pub shortest: f32,
    pub depth: f32,
    pub seed: u64,
    pub fetch: f32,
    pub shared_with: [f32; 2],
}

impl Band {
    /// A pool's: the pool itself is the tile, from [`LONGEST_WAVELENGTH`] down to
    /// [`SHORTEST_WAVE_CELLS`] cells of a `size`² lattice.
    pub fn pool(size: usize, pool: PoolShape) -> Self {
        Self {
            half_tile: pool.half_width,
            longest: LONGEST_WAVELENGTH,
            shortest: SHORTEST_WAVE_CELLS * 2.0 * pool.half_width / size as f32,
            depth: pool.depth,
            seed: 0x0cea_4f17,
            fetch: JONSWAP_FETCH,
            shared_with: [0.0; 2],
        }
    }

    /// Wavenumber (rad/m) of lattice index `i` (0..`size`) along one axis: indices past
    /// `size`/2 are negative.
    pub fn k(&self, i: usize, size: usize) -> f32 {
        let m = if i < size / 2 { i as i32 } else { i as i32 - size as i32 };
        m as f32 * std::f32::consts::PI / self.half_tile
    }

    /// Angular frequency (rad/s) of a wave of wavenumber `k` here.
    pub fn omega(&self, k: f32) -> f32 {
        angular_frequency_in(k, self.depth)
    }

    /// The share of the spectrum's energy this lattice holds at `wavelength` (m).
    pub fn share(&self, wavelength: f32) -> f32 {
        1.0 / (1 + self.shared_with.iter().filter(|&&longest| wavelength < longest).count()) as f32
    }
}

/// The spectrum sampled on a lattice (the pool's, or one of the sea's cascades), and how it moves.
#[derive(Clone, Debug, PartialEq)]
pub struct Ocean {
    /// Lattice points per side (a power of two).
    pub size: usize,
    /// The tile and the wavelengths the lattice holds.
    pub band: Band,
    /// Per lattice point, row-major with index (m mod N, n mod N) for k = (π/W)(m, n), W the
    /// band's `half_tile`:
    /// h0(k) and conj(h0(−k)), the amplitudes at t = 0 (m).
    pub h0: Vec<[f32; 4]>,
    /// Choppiness λ: the water at rest point x₀ is carried to x₀ − λ D(x₀), with
    /// D = Σ −i k̂ h(k) e^{i k·x} (for one wave a cos(k·x): D = a k̂ sin(k·x), so crests sharpen
    /// as Gerstner's do). 0: the height field alone.
    pub choppiness: f32,
}

/// The largest choppiness: beyond about this the steepest parts of a 3 cm sea fold over.
pub const MAX_CHOPPINESS: f32 = 3.0;
/// Newton steps that find the rest point of the choppy surface above a point
/// (x₀ − λ D(x₀) = x), each at most [`CHOP_STEP_LIMIT`] long.
pub const CHOP_NEWTON_STEPS: usize = 4;
/// The longest Newton step (m), and the steepest slope the choppy surface reports: where the
/// sea folds over (det J ≤ 0) the solve would run off; this keeps every number finite.
pub const CHOP_STEP_LIMIT: f32 = 0.05;
pub const CHOP_SLOPE_LIMIT: f32 = 4.0;

/// Wavenumber (rad/m) of `pool`'s lattice index `i` (0..N) along one axis: indices past N/2
/// are negative.
pub fn lattice_k(i: usize, size: usize, pool: PoolShape) -> f32 {
    Band::pool(size, pool).k(i, size)
}

/// The spectrum's density (m⁴ per unit of k², up to a scale) at wavevector (kx, kz), zero
/// outside the band the lattice and the pool hold and outside the spread around the wind.
fn density(kx: f32, kz: f32, settings: &AmbientSettings, band: &Band) -> f32 {
    let k = (kx * kx + kz * kz).sqrt();
    // Wavelengths from `shortest` up to, not including, `longest`: bands that meet there hold
    // the wave on their edge once.
    let (k_min, k_max) = (std::f32::consts::TAU / band.longest, std::f32::consts::TAU / band.shortest);
    if k <= k_min || k > k_max {
        return 0.0;
    }
    // Travelling downwind, within the spread of directions.
    let wind = settings.wind_direction_deg.to_radians();
    let off = (kz.atan2(kx) - wind + std::f32::consts::PI).rem_euclid(std::f32::consts::TAU) - std::f32::consts::PI;
    if off.abs() > settings.spread_deg.to_radians().max(1e-3) {
        return 0.0;
    }
    let align = off.cos();
    band.share(std::f32::consts::TAU / k)
        * match settings.spectrum {
            Spectrum::Phillips => {
                // exp(−1/(kL)²)/k⁴ (k̂·ŵ)², L = V²/g.
                let l = settings.wind_speed * settings.wind_speed / G;
                (-1.0 / (k * l).powi(2)).exp() / k.powi(4) * align * align
            }
            Spectrum::Jonswap => {
                // S(ω) = g²/ω⁵ exp(−5/4 (ω_p/ω)⁴) γ^r, r = exp(−(ω − ω_p)²/(2σ²ω_p²)), the
                // fetch-limited peak ω_p = 22 (g²/(U F))^(1/3); per unit k²: S(ω) dω/dk / k,
                // with cos² spreading.
                let omega_p = 22.0 * (G * G / (settings.wind_speed * band.fetch)).cbrt();
                let omega = band.omega(k);
                let sigma = if omega <= omega_p { JONSWAP_SIGMA.0 } else { JONSWAP_SIGMA.1 };
                let r = (-(omega - omega_p).powi(2) / (2.0 * sigma * sigma * omega_p * omega_p)).exp();
                let s = G * G / omega.powi(5) * (-1.25 * (omega_p / omega).powi(4)).exp() * JONSWAP_GAMMA.powf(r);
                let dk = 1e-3 * k;
                let domega_dk = (band.omega(k + dk) - band.omega(k - dk)) / (2.0 * dk);
                s * domega_dk / k * align * align
            }
        }
}

/// A standard normal number (Box–Muller).
fn gaussian(rng: &mut SplitMix64) -> f32 {
    let u = rng.range(1e-7, 1.0);
    let v = rng.range(0.0, 1.0);
    (-2.0 * u.ln()).sqrt() * (std::f32::consts::TAU * v).cos()
}

impl Ocean {
    /// The lattice of `size`² points for `settings`, scaled so that the significant height
    /// (4 × the surface's standard deviation, averaged over time) is the asked one.
    pub fn new(settings: &AmbientSettings, size: usize) -> Self {
        let mut ocean = Self::unscaled(settings, size, Band::pool(size, settings.basin));
        let variance = ocean.variance();
        if variance > 0.0 {
            ocean.scale(settings.significant_height / 4.0 / variance.sqrt() as f32);
        }
        ocean
    }

    /// The lattice of `size`² points for `band`, with the spectrum's own (arbitrary) scale.
    pub fn unscaled(settings: &AmbientSettings, size: usize, band: Band) -> Self {
        assert!(size.is_power_of_two() && size >= 8, "lattice size {size}");
        let mut rng = SplitMix64(band.seed);
        let mut amplitude = vec![[0.0f32; 2]; size * size];
        // The lattice's spacing in k (rad/m): lattices of different tiles then hold the same
        // energy per unit of k², whatever their density of waves.
        let dk = band.k(1, size);
        for j in 0..size {
            for i in 0..size {
                let (kx, kz) = (band.k(i, size), band.k(j, size));
                // h0 = (ξr + i ξi)/√2 · √(S(k) Δk²); the scale comes later.
                let a = density(kx, kz, settings, &band).max(0.0).sqrt() * dk / std::f32::consts::SQRT_2;
                amplitude[j * size + i] = [gaussian(&mut rng) * a, gaussian(&mut rng) * a];
            }
        }
        let negative = |i: usize| (size - i) % size;
        let h0: Vec<[f32; 4]> = (0..size * size)
            .map(|idx| {
                let (i, j) = (idx % size, idx / size);
                let minus = conj(amplitude[negative(j) * size + negative(i)]);
                let here = amplitude[idx];
                [here[0], here[1], minus[0], minus[1]]
            })
            .collect();
        Self { size, band, h0, choppiness: settings.choppiness.clamp(0.0, MAX_CHOPPINESS) }
    }

    /// The surface's variance averaged over time (m²): Σ |h0(k)|² + |h0(−k)|².
    pub fn variance(&self) -> f64 {
        self.h0.iter().map(|a| (a.iter().map(|v| v * v).sum::<f32>()) as f64).sum()
    }

    /// Multiplies every amplitude by `factor`.
    pub fn scale(&mut self, factor: f32) {
        for a in &mut self.h0 {
            for v in a.iter_mut() {
                *v *= factor;
            }
        }
    }

    /// Wavenumbers (rad/m) of lattice index `idx`.
    fn k_at(&self, idx: usize) -> (f32, f32) {
        (self.band.k(idx % self.size, self.size), self.band.k(idx / self.size, self.size))
    }

    /// The number of lattice points with a wave on them.
    pub fn wave_count(&self) -> usize {
        self.h0.iter().filter(|a| a.iter().any(|v| *v != 0.0)).count()
    }

    /// h(k, t) = h0(k) e^{−iωt} + conj(h0(−k)) e^{iωt} at lattice index `idx`: the first
    /// term travels along k, the second against it; the sum is Hermitian (a real surface).
    pub fn amplitude(&self, idx: usize, t: f64) -> Complex {
        let (kx, kz) = self.k_at(idx);
        let omega = self.band.omega((kx * kx + kz * kz).sqrt()) as f64;
        let phase = (omega * t).rem_euclid(std::f64::consts::TAU) as f32;
        let turn = [phase.cos(), phase.sin()];
        let a = self.h0[idx];
        add(mul([a[0], a[1]], conj(turn)), mul([a[2], a[3]], turn))
    }

    /// The spectrum as the GPU takes it: per lattice point h0(k) e^{−iωT} and
    /// conj(h0(−k)) e^{iωT} at the epoch T (s; phases in f64), each multiplied by e^{i k·x₀}
    /// so that the inverse FFT's sample (0, 0) lies at the first texel's centre
    /// x₀ = −W + Δ/2. Re-based every [`EPOCH_SECONDS`], so that the time the GPU advances it
    /// by in f32 stays short (the phase ωt keeps its precision in long sessions).
    pub fn epoch_spectrum(&self, epoch: f64) -> Vec<[f32; 4]> {
        let n = self.size;
        let x0 = -self.band.half_tile + self.band.half_tile / n as f32;
        (0..n * n)
            .map(|idx| {
                let (kx, kz) = self.k_at(idx);
                let shift = [(kx * x0 + kz * x0).cos(), (kx * x0 + kz * x0).sin()];
                let omega = self.band.omega((kx * kx + kz * kz).sqrt()) as f64;
                let phase = (omega * epoch).rem_euclid(std::f64::consts::TAU) as f32;
                let turn = [phase.cos(), phase.sin()];
                let a = self.h0[idx];
                let here = mul(mul([a[0], a[1]], conj(turn)), shift);
                let minus = mul(mul([a[2], a[3]], turn), shift);
                [here[0], here[1], minus[0], minus[1]]
            })
            .collect()
    }

    /// The spectrum of the fields the renderer reads at time `t`: the surface's (see
    /// [`advance`]), or with `choppy` the displacement's (see [`advance_choppy`]).
    pub fn fields_spectrum(&self, t: f64, choppy: bool) -> Vec<[f32; 4]> {
        let epoch = epoch_of(t);
        let dt = (t - epoch) as f32;
        let step = if choppy { advance_choppy } else { advance };
        self.epoch_spectrum(epoch)
            .into_iter()
            .enumerate()
            .map(|(idx, a)| {
                let (kx, kz) = self.k_at(idx);
                step(a, kx, kz, self.band.omega((kx * kx + kz * kz).sqrt()) * dt)
            })
            .collect()
    }

    /// The surface on the lattice's texels at time `t`: per texel (row-major, x along rows,
    /// centres at −W + (i + ½)Δ) the height (m), slopes ∂h/∂x, ∂h/∂z and ∂Dx/∂z.
    pub fn surface(&self, t: f64) -> Vec<[f32; 4]> {
        inverse_fft_2d(self.fields_spectrum(t, false), self.size)
    }

    /// The displacement on the same texels: Dx, Dz (m) and ∂Dx/∂x, ∂Dz/∂z.
    pub fn displacement(&self, t: f64) -> Vec<[f32; 4]> {
        inverse_fft_2d(self.fields_spectrum(t, true), self.size)
    }

    /// Every field at a rest point (x, z), summed wave by wave: h, ∂h/∂x, ∂h/∂z, Dx, Dz,
    /// ∂Dx/∂x, ∂Dx/∂z, ∂Dz/∂z. (A field with spectrum m(k) h(k) is Re(m h e^{ik·x}).)
    pub fn fields_at(&self, x: f32, z: f32, t: f64) -> [f32; 8] {
        let mut out = [0.0f32; 8];
        for (idx, a) in self.h0.iter().enumerate() {
            if a.iter().all(|v| *v == 0.0) {
                continue;
            }
            let (kx, kz) = self.k_at(idx);
            let k = (kx * kx + kz * kz).sqrt();
            let v = mul(self.amplitude(idx, t), [(kx * x + kz * z).cos(), (kx * x + kz * z).sin()]);
            let terms = [
                v[0],
                -kx * v[1],
                -kz * v[1],
                kx / k * v[1],
                kz / k * v[1],
                kx * kx / k * v[0],
                kx * kz / k * v[0],
                kz * kz / k * v[0],
            ];
            for (o, t) in out.iter_mut().zip(terms) {
                *o += t;
            }
        }
        out
    }

    /// Height (m) and slopes at a point (x, z) (m), summed wave by wave (no grid): the tests'
    /// closed form (the floating bodies take the same sums through [`Ocean::at`]). With choppiness, the rest point
    /// carried to (x, z) is found first (the shader's `ocean_at` takes the same steps on its
    /// maps) and the slopes are J⁻¹∇₀h, J = I − λ ∂D/∂x₀.
    pub fn sample(&self, x: f32, z: f32, t: f64) -> [f32; 3] {
        choppy_surface(self.choppiness, |x0, z0| self.fields_at(x0, z0, t), x, z)
    }

    /// The waves at time `t` (s), to sample at many points: see [`OceanNow`].
    pub fn at(&self, t: f64) -> OceanNow {
        let n = self.size;
        let waves = (0..n * n)
            .filter(|&idx| self.h0[idx].iter().any(|v| *v != 0.0))
            .map(|idx| {
                let (kx, kz) = self.k_at(idx);
                let k = (kx * kx + kz * kz).sqrt();
                NowWave {
                    cell: [idx % n, idx / n],
                    amplitude: self.amplitude(idx, t),
                    k: [kx, kz, kx / k, kz / k, kx * kx / k, kx * kz / k, kz * kz / k],
                }
            })
            .collect();
        OceanNow { size: n, half_tile: self.band.half_tile, choppiness: self.choppiness, waves }
    }
}

/// The choppy surface above (x, z) from the fields at rest points (`fields`, as
/// [`Ocean::fields_at`]): Newton's method finds the rest point carried to (x, z), then the
/// height there and the slopes J⁻¹∇₀h, J = I − λ ∂D/∂x₀ (the shader's `ocean_at` takes the same
/// steps on its maps). Without choppiness, the fields at (x, z) themselves.
fn choppy_surface(lambda: f32, fields: impl Fn(f32, f32) -> [f32; 8], x: f32, z: f32) -> [f32; 3] {
    if lambda <= 0.0 {
        let f = fields(x, z);
        return [f[0], f[1], f[2]];
    }
    let jacobian = |f: &[f32; 8]| [1.0 - lambda * f[5], -lambda * f[6], 1.0 - lambda * f[7]];
    let (mut x0, mut z0) = (x, z);
    for _ in 0..CHOP_NEWTON_STEPS {
        let f = fields(x0, z0);
        let step = folded_solve(jacobian(&f), [x0 - lambda * f[3] - x, z0 - lambda * f[4] - z], CHOP_STEP_LIMIT);
        (x0, z0) = (x0 - step[0], z0 - step[1]);
    }
    let f = fields(x0, z0);
    let slope = folded_solve(jacobian(&f), [f[1], f[2]], CHOP_SLOPE_LIMIT);
    [f[0], slope[0], slope[1]]
}

/// One wave of [`OceanNow`]: its lattice cell, h(k, t), and kx, kz, k̂x, k̂z, kx²/k, kx kz/k,
/// kz²/k (rad/m), the factors of its eight fields.
#[derive(Clone, Copy, Debug)]
struct NowWave {
    cell: [usize; 2],
    amplitude: Complex,
    k: [f32; 7],
}

/// The ocean at one moment, for sampling many points (the floating bodies' probes, every
/// frame): each wave's h(k, t) computed once, and e^{ik·x} = e^{ikx x} e^{ikz z} taken from
/// two tables of e^{i m (π/W) x} (the lattice's wavenumbers are whole multiples of π/W, W
/// half its tile), so a
/// point costs two table builds and a few products per wave instead of two sines and two
/// cosines per wave. Same sums as [`Ocean::fields_at`] (the tests hold them together).
#[derive(Clone, Debug)]
pub struct OceanNow {
    size: usize,
    /// Half the side of the lattice's tile (m).
    half_tile: f32,
    choppiness: f32,
    waves: Vec<NowWave>,
}

impl OceanNow {
    /// e^{i kx(i) x} for every lattice index i along an axis (m), built by repeated products in
    /// f64 from e^{i (π/W) x}.
    fn axis_table(&self, x: f32) -> Vec<Complex> {
        let n = self.size;
        let step = std::f64::consts::PI / self.half_tile as f64 * x as f64;
        let base = (step.cos(), step.sin());
        let mut table = vec![[0.0f32; 2]; n];
        let mut power = (1.0f64, 0.0f64);
        for m in 0..=n / 2 {
            table[m % n] = [power.0 as f32, power.1 as f32];
            if m > 0 {
                table[n - m] = [power.0 as f32, -power.1 as f32];
            }
            power = (power.0 * base.0 - power.1 * base.1, power.0 * base.1 + power.1 * base.0);
        }
        table
    }

    /// Every field at a rest point (x, z), as [`Ocean::fields_at`].
    pub fn fields_at(&self, x: f32, z: f32) -> [f32; 8] {
        let (along_x, along_z) = (self.axis_table(x), self.axis_table(z));
        let mut out = [0.0f32; 8];
        for w in &self.waves {
            let v = mul(w.amplitude, mul(along_x[w.cell[0]], along_z[w.cell[1]]));
            let k = &w.k;
            let terms =
                [v[0], -k[0] * v[1], -k[1] * v[1], k[2] * v[1], k[3] * v[1], k[4] * v[0], k[5] * v[0], k[6] * v[0]];
            for (o, t) in out.iter_mut().zip(terms) {
                *o += t;
            }
        }
        out
    }

    /// Choppiness λ its displacement is carried by.
    pub fn choppiness(&self) -> f32 {
        self.choppiness
    }

    /// Height (m) and slopes at (x, z) (m), as [`Ocean::sample`].
    pub fn sample(&self, x: f32, z: f32) -> [f32; 3] {
        choppy_surface(self.choppiness, |x0, z0| self.fields_at(x0, z0), x, z)
    }
}

/// J⁻¹ v for the choppy surface's symmetric Jacobian J = (xx, xz, zz), its length held to
/// `limit` and its determinant away from 0 (where the sea folds over), so it stays finite.
/// (scene.wgsl `folded_solve` is the same.)
pub fn folded_solve(j: [f32; 3], v: [f32; 2], limit: f32) -> [f32; 2] {
    let det = j[0] * j[2] - j[1] * j[1];
    let det = if det.abs() < 1e-6 { 1e-6 } else { det };
    let s = [(j[2] * v[0] - j[1] * v[1]) / det, (j[0] * v[1] - j[1] * v[0]) / det];
    let length = (s[0] * s[0] + s[1] * s[1]).sqrt();
    if length > limit {
        [s[0] * limit / length, s[1] * limit / length]
    } else {
        s
    }
}

/// How often (s) the spectrum given to the GPU is re-based ([`Ocean::epoch_spectrum`]).
pub const EPOCH_SECONDS: f64 = 16.0;

/// The epoch of time `t` (s): the last multiple of [`EPOCH_SECONDS`].
pub fn epoch_of(t: f64) -> f64 {
    (t / EPOCH_SECONDS).floor() * EPOCH_SECONDS
}

/// The spectrum pass (shaders/ambient_fft.wgsl, `fs_ocean_spectrum`) for one lattice point:
/// `a` from [`Ocean::epoch_spectrum`] advanced by the phase ω dt (rad) of the time past its
/// epoch, h = a₀ e^{−iω dt} + a₁ e^{iω dt}, packed as two complex signals (re, im, re, im):
/// h + i (i kx h) and i kz h, whose inverse FFTs are h + i ∂h/∂x and ∂h/∂z (real fields come
/// out as the real and imaginary parts).
pub fn advance(a: [f32; 4], kx: f32, kz: f32, phase: f32) -> [f32; 4] {
    let h = advanced(a, phase);
    // The second signal also carries ∂Dx/∂z (spectrum (kx kz / k) h) in its imaginary part.
    let c = kz + kx * kz * inverse_k(kx, kz);
    [h[0] - kx * h[0], h[1] - kx * h[1], -c * h[1], c * h[0]]
}

/// The choppy spectrum pass (`fs_ocean_choppy_spectrum`): Dx + i Dz and ∂Dx/∂x + i ∂Dz/∂z,
/// from Dx = −i (kx/k) h, Dz = −i (kz/k) h and their derivatives (kx²/k) h, (kz²/k) h.
pub fn advance_choppy(a: [f32; 4], kx: f32, kz: f32, phase: f32) -> [f32; 4] {
    let h = advanced(a, phase);
    let r = inverse_k(kx, kz);
    let d = mul([kz * r, -kx * r], h);
    let j = mul([kx * kx * r, kz * kz * r], h);
    [d[0], d[1], j[0], j[1]]
}

/// h = a₀ e^{−iω dt} + a₁ e^{iω dt}, `phase` = ω dt.
fn advanced(a: [f32; 4], phase: f32) -> Complex {
    let turn = [phase.cos(), phase.sin()];
    add(mul([a[0], a[1]], conj(turn)), mul([a[2], a[3]], turn))
}

/// 1/k, and 0 at k = 0 (where there is no wave).
fn inverse_k(kx: f32, kz: f32) -> f32 {
    let k = (kx * kx + kz * kz).sqrt();
    if k > 0.0 {
        1.0 / k
    } else {
        0.0
    }
}
