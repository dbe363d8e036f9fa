//! The open sea's waves (issue: `scene=sea`): one spectrum shared among five FFT lattices
//! (cascades) whose tiles are incommensurate (256, 181.5, 128.3, 61.7 and 15.1 m) and turned by
//! their own angles. A single lattice repeats its tile exactly, which the eye finds at once on
//! a sea seen to the horizon. Here the wavelengths that carry most of the energy (from 128.3 m
//! down to 16 m) are held a third by each of the three long lattices, so no one lattice's
//! repeat can make the sum repeat; the shorter ones by one lattice each, whose tile is about
//! four times its band's longest wave (the lattice's first rings, coarse in k, hold nothing).
//! Along a kilometre in any direction the sum repeats no more than a sea off any lattice does
//! by chance (the tests measure its autocorrelation), where one lattice repeats its tile
//! exactly.
//!
//! Each cascade is an [`Ocean`] on its own [`Band`]; per wavelength the shares of the
//! cascades holding it add up to one, and the five are scaled together to the asked
//! significant height. Lengths in metres, angles in degrees where named so.

use super::ocean::{Band, Ocean, OceanNow, SHORTEST_WAVE_CELLS};
use super::AmbientSettings;

/// One cascade's lattice: its tile's side, the longest and the shortest wave it holds (0 for
/// [`SHORTEST_WAVE_CELLS`] cells), the other lattices holding the same waves (their longest;
/// 0 for none) and its turn from the world's axes (degrees).
struct CascadeSpec {
    tile: f32,
    longest: f32,
    shortest: f32,
    shared_with: [f32; 2],
    angle_deg: f32,
}

/// The long tiles (m), which share the energetic waves.
const LONG: [f32; 3] = [256.0, 181.5, 128.3];
/// Where the long lattices' waves end and the next cascade's begin (m): four of the longest
/// tile's cells of a 64² lattice.
const LONG_SHORTEST: f32 = 16.0;
/// Where the middle cascade's waves end and the last one's begin (m).
const MIDDLE_SHORTEST: f32 = 3.9;

/// The cascades, longest first. The tiles' ratios are far from small fractions, and the turns
/// keep the long tiles' lattices apart.
const CASCADES: [CascadeSpec; 5] = [
    CascadeSpec {
        tile: LONG[0],
        longest: LONG[0],
        shortest: LONG_SHORTEST,
        shared_with: [LONG[1], LONG[2]],
        angle_deg: 21.7,
    },
    CascadeSpec {
        tile: LONG[1],
        longest: LONG[1],
        shortest: LONG_SHORTEST,
        shared_with: [LONG[0], LONG[2]],
        angle_deg: 57.3,
    },
    CascadeSpec {
        tile: LONG[2],
        longest: LONG[2],
        shortest: LONG_SHORTEST,
        shared_with: [LONG[0], LONG[1]],
        angle_deg: 96.7,
    },
    CascadeSpec {
        tile: 61.7,
        longest: LONG_SHORTEST,
        shortest: MIDDLE_SHORTEST,
        shared_with: [0.0; 2],
        angle_deg: 104.9,
    },
    CascadeSpec { tile: 15.1, longest: MIDDLE_SHORTEST, shortest: 0.0, shared_with: [0.0; 2], angle_deg: 33.1 },
];
/// How many cascades the sea sums.
pub const CASCADE_COUNT: usize = CASCADES.len();
/// The cascades whose folding crests break into whitecaps: the first this many, all but the
/// finest, whose folds (on waves a few metres long) drew slivers of foam down the faces of the
/// storm's waves.
pub const BREAKING_CASCADES: usize = CASCADE_COUNT - 1;
/// Side of each cascade's tile (m).
pub const CASCADE_TILES: [f32; 5] =
    [CASCADES[0].tile, CASCADES[1].tile, CASCADES[2].tile, CASCADES[3].tile, CASCADES[4].tile];
/// Depth (m) of the open sea's water: deep for every wave the cascades hold.
pub const SEA_DEPTH: f32 = 200.0;
/// The distance (m) the wind has blown over the open sea (JONSWAP's peak).
pub const SEA_FETCH: f32 = 50_000.0;
/// Whitecaps where the choppy surface's Jacobian determinant falls below this: the water is
/// squeezed to this share of its area at rest, about to fold over and break.
pub const WHITECAP_JACOBIAN: f32 = 0.3;
/// The foam's cover fades in over this much below [`WHITECAP_JACOBIAN`] and out over twice
/// this above it (`whitecap_cover` in shaders/sea/waves.wgsl).
pub const WHITECAP_SOFTNESS: f32 = 0.15;
/// The Jacobian above which the water carries no whitecap foam at all: the cover's outer edge.
pub const WHITECAP_EDGE: f32 = WHITECAP_JACOBIAN + 2.0 * WHITECAP_SOFTNESS;
/// The Jacobian below which whitecaps are seen: the cover is about a quarter there (0.26 with
/// these constants), and the lace of a thinner cover shows as a few specks. A sea that never
/// folds this far draws no whitecaps ([`SeaWaves::may_break`]): gated at the outer edge, the
/// default sea (8 m/s) took the whitecaps' shading, about a sixth more of lavapipe's (+14 to
/// +22 % in three rounds), and drew not one pixel of foam in 5 s.
pub const WHITECAP_SEEN: f32 = WHITECAP_JACOBIAN + WHITECAP_SOFTNESS;
// `may_break`'s bound holds for a norm up to 1/√2, which the gate must lie within; and the
// gate lies inside the cover (past its outer edge there is nothing to see).
const _: () = assert!(WHITECAP_SEEN >= 0.25 && WHITECAP_SEEN < WHITECAP_EDGE);

/// A lattice of `n`² texels over a tile 2 `half_tile` wide (texel (i, j) centred at
/// −W + (i + ½)Δ, the tile repeating), bilinear at (u, v) in its frame (m).
fn lattice_at(texels: &[[f32; 4]], n: usize, half_tile: f32, u: f32, v: f32) -> [f32; 4] {
    let texel = 2.0 * half_tile / n as f32;
    let (fu, fv) = ((u + half_tile) / texel - 0.5, (v + half_tile) / texel - 0.5);
    let (iu, iv) = (fu.floor(), fv.floor());
    let (su, sv) = (fu - iu, fv - iv);
    let wrap = |i: f32| (i as i64).rem_euclid(n as i64) as usize;
    let (u0, u1, v0, v1) = (wrap(iu), wrap(iu + 1.0), wrap(iv), wrap(iv + 1.0));
    let mut out = [0.0; 4];
    for (k, o) in out.iter_mut().enumerate() {
        let row = |v: usize| texels[v * n + u0][k] * (1.0 - su) + texels[v * n + u1][k] * su;
        *o = row(v0) * (1.0 - sv) + row(v1) * sv;
    }
    out
}

/// One cascade: its lattice and how far it is turned from the world's axes.
#[derive(Clone, Debug)]
pub struct Cascade {
    pub ocean: Ocean,
    pub angle: f32,
}

impl Cascade {
    /// World (x, z) in the cascade's own frame.
    fn local(&self, x: f32, z: f32) -> (f32, f32) {
        let (s, c) = self.angle.sin_cos();
        (c * x + s * z, -s * x + c * z)
    }

    /// A vector of the cascade's frame (x, z) in the world's.
    fn to_world(&self, x: f32, z: f32) -> (f32, f32) {
        let (s, c) = self.angle.sin_cos();
        (c * x - s * z, s * x + c * z)
    }
}

/// The sea's waves: the cascades, summed.
#[derive(Clone, Debug)]
pub struct SeaWaves {
    pub cascades: Vec<Cascade>,
}

impl SeaWaves {
    /// The cascades of `size`² points each for `settings` (its wind, spectrum and spread; its
    /// significant height is the whole sea's).
    pub fn new(settings: &AmbientSettings, size: usize) -> Self {
        assert!(size >= 64, "a {size}² lattice cannot hold the long cascades' waves down to {LONG_SHORTEST} m");
        let mut cascades: Vec<Cascade> = CASCADES
            .iter()
            .enumerate()
            .map(|(i, spec)| {
                let shortest =
                    if spec.shortest > 0.0 { spec.shortest } else { SHORTEST_WAVE_CELLS * spec.tile / size as f32 };
                let band = Band {
                    half_tile: spec.tile / 2.0,
                    longest: spec.longest,
                    shortest,
                    depth: SEA_DEPTH,
                    seed: 0x5ea0 + i as u64,
                    fetch: SEA_FETCH,
                    shared_with: spec.shared_with,
                };
                // The wind in the cascade's frame.
                let local =
                    AmbientSettings { wind_direction_deg: settings.wind_direction_deg - spec.angle_deg, ..*settings };
                Cascade { ocean: Ocean::unscaled(&local, size, band), angle: spec.angle_deg.to_radians() }
            })
            .collect();
        let variance: f64 = cascades.iter().map(|c| c.ocean.variance()).sum();
        if variance > 0.0 {
            let factor = settings.significant_height / 4.0 / variance.sqrt() as f32;
            for c in &mut cascades {
                c.ocean.scale(factor);
            }
        }
        Self { cascades }
    }

    /// Height (m) and slopes ∂h/∂x, ∂h/∂z of the sea at world (x, z) and time `t` (s), summed
    /// wave by wave (no choppiness; the tests' reference).
    pub fn sample(&self, x: f32, z: f32, t: f64) -> [f32; 3] {
        self.cascades.iter().fold([0.0; 3], |sum, c| {
            let (u, v) = c.local(x, z);
            let f = c.ocean.fields_at(u, v, t);
            let (sx, sz) = c.to_world(f[1], f[2]);
            [sum[0] + f[0], sum[1] + sx, sum[2] + sz]
        })
    }

    /// The Jacobian determinant of the horizontal map x₀ ↦ x₀ − λ D(x₀) at world rest point
    /// (x, z), time `t`: 1 where the water keeps its area, below 1 where the choppy waves
    /// squeeze it (their crests), ≤ 0 where it folds over. D and its derivatives are all five
    /// cascades' summed (the whitecaps' cover takes only the [`BREAKING_CASCADES`]); λ is their
    /// choppiness.
    pub fn jacobian(&self, x: f32, z: f32, t: f64) -> f32 {
        // λ ∂D/∂x₀ summed over the cascades in the world's frame: xx, xz, zz.
        let mut d = [0.0f32; 3];
        for c in &self.cascades {
            let (u, v) = c.local(x, z);
            let f = c.ocean.fields_at(u, v, t);
            // The cascade's tensor M = [[xx, xz], [xz, zz]] turned to the world: Rᵀ M R.
            let (s, co) = c.angle.sin_cos();
            let lambda = c.ocean.choppiness;
            let (xx, xz, zz) = (lambda * f[5], lambda * f[6], lambda * f[7]);
            d[0] += co * co * xx - 2.0 * s * co * xz + s * s * zz;
            d[1] += s * co * (xx - zz) + (co * co - s * s) * xz;
            d[2] += s * s * xx + 2.0 * s * co * xz + co * co * zz;
        }
        (1.0 - d[0]) * (1.0 - d[2]) - d[1] * d[1]
    }

    /// Height (m) of the choppy sea above world (x, z), read from the cascades' lattices of
    /// one moment (`layers`, as [`SeaWaves::layers`] gives them) between their texels: the
    /// rest point carried there is x₀ ≈ x + λ D(x) (one fixed-point step), its height the
    /// cascades' summed there. Cheap enough for every floating body's probes each frame.
    pub fn height_on(&self, layers: [&[[f32; 4]]; 2], x: f32, z: f32) -> f32 {
        let [surface, displacement] = layers;
        let lattice = |texels: &[[f32; 4]], i: usize, c: &Cascade, x: f32, z: f32| {
            let (n, (u, v)) = (c.ocean.size, c.local(x, z));
            lattice_at(&texels[i * n * n..(i + 1) * n * n], n, c.ocean.band.half_tile, u, v)
        };
        let (mut x0, mut z0) = (x, z);
        for (i, c) in self.cascades.iter().enumerate() {
            let d = lattice(displacement, i, c, x, z);
            let (dx, dz) = c.to_world(d[0], d[1]);
            (x0, z0) = (x0 + c.ocean.choppiness * dx, z0 + c.ocean.choppiness * dz);
        }
        self.cascades.iter().enumerate().map(|(i, c)| lattice(surface, i, c, x0, z0)[0]).sum()
    }

    /// The cascades' lattices at time `t` (s), one after the other (cascade i's texel (x, z)
    /// at (i N + z) N + x), as the GPU's array texture holds them: their surface (h, ∂h/∂x,
    /// ∂h/∂z, ∂Dx/∂z) and displacement (Dx, Dz, ∂Dx/∂x, ∂Dz/∂z), each in the cascade's own
    /// frame. Without choppiness the displacement is zero and not computed.
    pub fn layers(&self, t: f64) -> [Vec<[f32; 4]>; 2] {
        let mut out = [Vec::new(), Vec::new()];
        for c in &self.cascades {
            let n = c.ocean.size;
            out[0].extend(c.ocean.surface(t));
            if c.ocean.choppiness > 0.0 {
                out[1].extend(c.ocean.displacement(t));
            } else {
                out[1].extend(std::iter::repeat_n([0.0; 4], n * n));
            }
        }
        out
    }

    /// The sea at time `t` (s), to sample at a few points: see [`SeaNow`].
    pub fn at(&self, t: f64) -> SeaNow {
        SeaNow { cascades: self.cascades.iter().map(|c| (c.ocean.at(t), c.angle)).collect() }
    }

    /// Whether the choppy waves can break anywhere: the Jacobian det(I − M) of the map
    /// x₀ ↦ x₀ − λ D (M symmetric, Frobenius norm s) is at least (1 − s/√2)² while s ≤ 1/√2
    /// (then at least 1/4; past it (1 − s²)/2), so whitecaps (seen below [`WHITECAP_SEEN`], at
    /// least 1/4) need s past √2 (1 − √WHITECAP_SEEN), about a half. M is the
    /// cascades' λ ∂D/∂x₀ summed; taking them as independent, s seldom passes 3.5 times its
    /// rms, from the lattices at one time (`layers`, as [`SeaWaves::layers`] gives them: the
    /// sea's statistics do not change with time). Only the [`BREAKING_CASCADES`] count, as in
    /// the shader's cover.
    pub fn may_break(&self, layers: &[Vec<[f32; 4]>; 2]) -> bool {
        let [surface, displacement] = layers;
        let lattice = surface.len() / self.cascades.len().max(1);
        let mean_square: f64 = self
            .cascades
            .iter()
            .take(BREAKING_CASCADES)
            .enumerate()
            .map(|(i, c)| {
                let lambda = c.ocean.choppiness as f64;
                let texels = (i * lattice..(i + 1) * lattice).map(|k| {
                    let (xx, zz, xz) = (displacement[k][2] as f64, displacement[k][3] as f64, surface[k][3] as f64);
                    lambda * lambda * (xx * xx + zz * zz + 2.0 * xz * xz)
                });
                texels.sum::<f64>() / lattice as f64
            })
            .sum();
        let edge = std::f64::consts::SQRT_2 * (1.0 - (WHITECAP_SEEN as f64).sqrt());
        3.5 * mean_square.sqrt() > edge
    }

    /// Each cascade's slope variance (mean of (∂h/∂x)² + (∂h/∂z)²) over a surface's layers of
    /// `count` cascades ([`SeaWaves::layers`]).
    pub fn slope_variances(surface: &[[f32; 4]], count: usize) -> Vec<f32> {
        surface
            .chunks_exact((surface.len() / count.max(1)).max(1))
            .map(|layer| {
                let sum: f64 = layer.iter().map(|t| (t[1] * t[1] + t[2] * t[2]) as f64).sum();
                (sum / layer.len() as f64) as f32
            })
            .collect()
    }

    /// Each cascade's share of the surface's variance.
    pub fn variance_shares(&self) -> Vec<f64> {
        let all: f64 = self.cascades.iter().map(|c| c.ocean.variance()).sum();
        self.cascades.iter().map(|c| c.ocean.variance() / all).collect()
    }
}

/// The sea at one moment ([`SeaWaves::at`]), for sampling a few points each frame (the
/// floating bodies' probes): each cascade's waves summed one by one at the point
/// ([`OceanNow`]), so the CPU needs no lattice. The GPU's lattices give the same sea between
/// their texels to their interpolation's error.
#[derive(Clone, Debug)]
pub struct SeaNow {
    /// Each cascade's waves and its turn (rad).
    cascades: Vec<(OceanNow, f32)>,
}

impl SeaNow {
    /// Height (m) of the choppy sea above world (x, z): the rest point carried there is
    /// x₀ ≈ x + λ D(x) (one fixed-point step, as [`SeaWaves::height_on`]), its height the
    /// cascades' summed there.
    pub fn height(&self, x: f32, z: f32) -> f32 {
        let in_frame = |angle: f32, x: f32, z: f32| {
            let (s, c) = angle.sin_cos();
            (c * x + s * z, -s * x + c * z)
        };
        let (mut x0, mut z0) = (x, z);
        for (now, angle) in &self.cascades {
            if now.choppiness() > 0.0 {
                let (u, v) = in_frame(*angle, x, z);
                let f = now.fields_at(u, v);
                let (s, c) = angle.sin_cos();
                let (dx, dz) = (c * f[3] - s * f[4], s * f[3] + c * f[4]);
                (x0, z0) = (x0 + now.choppiness() * dx, z0 + now.choppiness() * dz);
            }
        }
        self.cascades
            .iter()
            .map(|(now, angle)| {
                let (u, v) = in_frame(*angle, x0, z0);
                now.fields_at(u, v)[0]
            })
            .sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ambient::{AmbientModel, Spectrum};

    fn breeze() -> AmbientSettings {
        AmbientSettings {
            model: AmbientModel::Fft,
            wind_speed: 8.0,
            wind_direction_deg: 30.0,
            significant_height: 1.0,
            spread_deg: 60.0,
            spectrum: Spectrum::Phillips,
            fft_size: 64,
            ..Default::default()
        }
    }

    /// The normalised autocorrelation of `h` (samples a metre apart) at each lag from 40 to
    /// 500 m.
    fn correlations(h: &[f32]) -> Vec<f64> {
        let mean = h.iter().map(|&v| v as f64).sum::<f64>() / h.len() as f64;
        let d: Vec<f64> = h.iter().map(|&v| v as f64 - mean).collect();
        let power = d.iter().map(|v| v * v).sum::<f64>() / d.len() as f64;
        (FIRST_LAG..=LAST_LAG)
            .map(|lag| {
                let n = d.len() - lag;
                d[..n].iter().zip(&d[lag..]).map(|(a, b)| a * b).sum::<f64>() / n as f64 / power
            })
            .collect()
    }

    /// The lags (m) the tests look for a repeat at: past the waves' own likeness at short lags,
    /// up to half the kilometre.
    const FIRST_LAG: usize = 40;
    const LAST_LAG: usize = 500;
    /// Parallel kilometres averaged, 137 m apart sideways: a tile's repeat shows on each at
    /// the same lag, a chance likeness on one alone.
    const LINES: usize = 8;

    /// The height of `waves` (world wavevectors (rad/m) and amplitudes: Re(a e^{ik·x})) every
    /// metre along a kilometre in `direction` (degrees), from a point `aside` m to its left of
    /// the origin: each wave turned on by its step's phase (in f64), not a sine per point.
    fn line(waves: &[([f32; 2], [f32; 2])], direction: f32, aside: f32) -> Vec<f32> {
        let (s, c) = (direction as f64).to_radians().sin_cos();
        let start = [-aside as f64 * s, aside as f64 * c];
        let mut out = vec![0.0f64; 1001];
        for (k, a) in waves {
            let (k, a) = (k.map(f64::from), a.map(f64::from));
            let (z, w) = (k[0] * start[0] + k[1] * start[1], k[0] * c + k[1] * s);
            let (mut re, mut im) = (z.cos(), z.sin());
            let (step_re, step_im) = (w.cos(), w.sin());
            for o in out.iter_mut() {
                *o += a[0] * re - a[1] * im;
                (re, im) = (re * step_re - im * step_im, re * step_im + im * step_re);
            }
        }
        out.into_iter().map(|v| v as f32).collect()
    }

    /// The largest autocorrelation of `waves` along kilometres in `direction` (averaged over
    /// [`LINES`] parallel ones) at lags from 40 to 500 m, and its lag.
    fn largest_correlation(waves: &[([f32; 2], [f32; 2])], direction: f32) -> (f64, f32) {
        let mut mean = vec![0.0; LAST_LAG - FIRST_LAG + 1];
        for k in 0..LINES {
            for (m, r) in mean.iter_mut().zip(correlations(&line(waves, direction, k as f32 * 137.0))) {
                *m += r / LINES as f64;
            }
        }
        let (at, r) = mean.iter().enumerate().fold((0, f64::MIN), |a, (i, &r)| if r > a.1 { (i, r) } else { a });
        (r, (FIRST_LAG + at) as f32)
    }

    /// The largest autocorrelation of `waves` along 24 directions (every 7.5°), and its
    /// direction and lag.
    fn worst_repeat(waves: &[([f32; 2], [f32; 2])]) -> (f64, f32, f32) {
        (0..24)
            .map(|i| i as f32 * 7.5)
            .map(|direction| {
                let (r, lag) = largest_correlation(waves, direction);
                (r, direction, lag)
            })
            .fold((f64::MIN, 0.0, 0.0), |a, b| if b.0 > a.0 { b } else { a })
    }

    /// `sea`'s waves at t = 0 in the world's frame, each wavevector moved to a random place
    /// within `jitter` of its lattice cell: with 1, a sea with the same spectrum that cannot
    /// repeat; with 0, the sea itself.
    #[allow(clippy::type_complexity)]
    fn off_the_lattice(sea: &SeaWaves, jitter: f32) -> Vec<([f32; 2], [f32; 2])> {
        let mut rng = crate::sim::SplitMix64(7);
        let mut waves = Vec::new();
        for c in &sea.cascades {
            let (n, band) = (c.ocean.size, c.ocean.band);
            let dk = band.k(1, n);
            for idx in 0..n * n {
                if c.ocean.h0[idx].iter().all(|v| *v == 0.0) {
                    continue;
                }
                let kx = band.k(idx % n, n) + jitter * rng.range(-0.5, 0.5) * dk;
                let kz = band.k(idx / n, n) + jitter * rng.range(-0.5, 0.5) * dk;
                let (wx, wz) = c.to_world(kx, kz);
                waves.push(([wx, wz], c.ocean.amplitude(idx, 0.0)));
            }
        }
        waves
    }

    #[test]
    fn the_sea_repeats_nowhere_along_a_kilometre_where_one_tile_would() {
        let sea = SeaWaves::new(&breeze(), 64);
        println!("variance shares of the cascades: {:.3?}", sea.variance_shares());
        let (r, direction, lag) = worst_repeat(&off_the_lattice(&sea, 0.0));
        println!("the cascades: largest autocorrelation {r:.3}, along {direction}° at {lag} m");
        // What the measure gives by chance on a sea that cannot repeat.
        let (chance, at_direction, at_lag) = worst_repeat(&off_the_lattice(&sea, 1.0));
        println!("the same waves off the lattice: {chance:.3}, along {at_direction}° at {at_lag} m");
        // One lattice holding the whole spectrum, unturned: its tile shows at 256 m.
        let band = Band {
            half_tile: 128.0,
            longest: 256.0,
            shortest: 16.0,
            depth: SEA_DEPTH,
            seed: 1,
            fetch: SEA_FETCH,
            shared_with: [0.0; 2],
        };
        let one = Cascade { ocean: Ocean::unscaled(&breeze(), 64, band), angle: 0.0 };
        let one_waves: Vec<_> = (0..64 * 64)
            .filter(|&idx| one.ocean.h0[idx].iter().any(|v| *v != 0.0))
            .map(|idx| ([band.k(idx % 64, 64), band.k(idx / 64, 64)], one.ocean.amplitude(idx, 0.0)))
            .collect();
        let (one_r, one_lag) = largest_correlation(&one_waves, 0.0);
        println!("one tile along its axis: {one_r:.3} at {one_lag} m");
        assert!(one_r > 0.9 && (one_lag - 256.0).abs() < 2.0, "one tile: {one_r:.3} at {one_lag} m");
        // Each lattice repeats exactly along its own lattice vectors (the 181.5 m one's (2, 1)
        // lies 405.8 m along 30.7°), so the sum repeats there by that lattice's share of the
        // variance, plus what chance finds (one line alone finds a likeness of about 0.5
        // somewhere by chance; eight averaged, about 0.2): no peak above the 0.5.
        let share = sea.variance_shares().into_iter().fold(0.0, f64::max);
        println!("largest share of one lattice {share:.3}; bound min(0.5, share + 0.1)");
        assert!(r < 0.5 && r < share + 0.1, "the sea repeats along {direction}° at {lag} m: autocorrelation {r:.3}");
    }

    #[test]
    fn the_lattices_give_the_height_between_their_texels() {
        // Without choppiness the lattices' height is the waves' summed one by one.
        let sea = SeaWaves::new(&AmbientSettings { choppiness: 0.0, ..breeze() }, 64);
        let t = 3.7;
        let layers = sea.layers(t);
        let (mut error, mut total) = (0.0f64, 0.0f64);
        for k in 0..200 {
            let (x, z) = (k as f32 * 7.31 - 700.0, (k * k % 97) as f32 * 5.17 - 250.0);
            let exact = sea.sample(x, z, t)[0];
            let read = sea.height_on([&layers[0], &layers[1]], x, z);
            error += ((read - exact) as f64).powi(2);
            total += (exact as f64).powi(2);
        }
        let relative = (error / total).sqrt();
        println!("rms error of the lattices' height between texels: {:.1}% of the height's rms", 100.0 * relative);
        assert!(relative < 0.1, "{relative}");
    }

    #[test]
    fn the_sums_at_a_point_give_the_lattices_choppy_sea() {
        // The floating bodies' sea (each wave summed at the point) against the renderer's
        // (the lattices between their texels), both carried by the choppy displacement.
        let sea = SeaWaves::new(&breeze(), 64);
        let t = 5.2;
        let (layers, now) = (sea.layers(t), sea.at(t));
        let (mut error, mut total) = (0.0f64, 0.0f64);
        for k in 0..200 {
            let (x, z) = (k as f32 * 6.13 - 600.0, (k * k % 89) as f32 * 4.71 - 200.0);
            let read = sea.height_on([&layers[0], &layers[1]], x, z);
            error += ((now.height(x, z) - read) as f64).powi(2);
            total += (read as f64).powi(2);
        }
        let relative = (error / total).sqrt();
        println!("rms difference of the choppy sea summed at points from its lattices': {:.1}%", 100.0 * relative);
        assert!(relative < 0.1, "{relative}");
    }

    /// Whitecaps (the Jacobian below [`WHITECAP_JACOBIAN`]) on a choppy storm sea, none on a
    /// calm one: the share of 1,600 points over a 500 m patch.
    #[test]
    fn a_storm_has_whitecaps_and_calm_water_none() {
        let caps = |wind_speed: f32, significant_height: f32| {
            let settings = AmbientSettings {
                wind_speed,
                significant_height,
                choppiness: 1.5,
                spectrum: Spectrum::Jonswap,
                ..breeze()
            };
            let sea = SeaWaves::new(&settings, 64);
            let points = (0..40 * 40).map(|i| ((i % 40) as f32 * 12.7, (i / 40) as f32 * 12.3));
            let (mut capped, mut lowest) = (0, f32::MAX);
            for (x, z) in points {
                let j = sea.jacobian(x, z, 5.0);
                lowest = lowest.min(j);
                capped += (j < WHITECAP_JACOBIAN) as u32;
            }
            (capped as f32 / 1600.0, lowest, sea.may_break(&sea.layers(0.0)))
        };
        let (storm, storm_lowest, storm_breaks) = caps(20.0, 6.0);
        let (calm, calm_lowest, calm_breaks) = caps(3.0, 0.1);
        println!(
            "whitecaps: storm {:.1} % (lowest Jacobian {storm_lowest:.2}, may break: {storm_breaks}), \
             calm {:.1} % ({calm_lowest:.2}, may break: {calm_breaks})",
            storm * 100.0,
            calm * 100.0
        );
        assert!(storm > 0.01 && storm_breaks, "a storm with {:.2} % whitecaps", storm * 100.0);
        assert!(calm == 0.0 && !calm_breaks, "calm water with whitecaps");
    }

    #[test]
    fn the_cascades_share_the_spectrum_without_counting_a_wave_twice() {
        let sea = SeaWaves::new(&breeze(), 64);
        // Every wave lies in its own cascade's band, and the bands meet without overlapping.
        for (i, c) in sea.cascades.iter().enumerate() {
            let (lo, hi) =
                (std::f32::consts::TAU / c.ocean.band.longest, std::f32::consts::TAU / c.ocean.band.shortest);
            let n = c.ocean.size;
            for (idx, a) in c.ocean.h0.iter().enumerate() {
                if a.iter().any(|v| *v != 0.0) {
                    let k = c.ocean.band.k(idx % n, n).hypot(c.ocean.band.k(idx / n, n));
                    assert!(k > lo && k <= hi * 1.0001, "cascade {i}: a wave at k {k} outside {lo}..{hi}");
                }
            }
        }
        // Per wavelength, the shares of the cascades holding it add up to one.
        for wavelength in [1.0f32, 3.0, 3.9, 10.0, 16.0, 17.0, 40.0, 120.0, 128.3, 150.0, 181.5, 200.0, 250.0] {
            let held: f32 = sea
                .cascades
                .iter()
                .map(|c| &c.ocean.band)
                .filter(|b| wavelength < b.longest && wavelength >= b.shortest)
                .map(|b| b.share(wavelength))
                .sum();
            assert!((held - 1.0).abs() < 1e-6, "a {wavelength} m wave is held {held} times");
        }
        // The significant height is the asked one: 4 × the standard deviation over a patch.
        let heights: Vec<f64> =
            (0..40 * 40).map(|i| sea.sample((i % 40) as f32 * 13.1, (i / 40) as f32 * 11.7, 3.0)[0] as f64).collect();
        let mean = heights.iter().sum::<f64>() / heights.len() as f64;
        let sd = (heights.iter().map(|h| (h - mean) * (h - mean)).sum::<f64>() / heights.len() as f64).sqrt();
        println!("significant height over a 500 m patch: {:.3} m (asked 1.0)", 4.0 * sd);
        assert!((4.0 * sd - 1.0).abs() < 0.25, "significant height {:.3} m", 4.0 * sd);
    }
}
