//! The inverse FFT of the FFT ocean: Stockham's autosort, written as a gather (each output from
//! R inputs, radix R) so that one fragment pass can compute one stage on the GPU
//! (shaders/ambient_fft.wgsl); [`inverse_fft_2d`] runs the very same stages on the CPU: it is
//! the reference the tests hold the GPU to, and the path for devices without float render
//! targets.

/// A complex number (re, im) in f32, as the GPU holds it.
pub type Complex = [f32; 2];

pub(super) fn mul(a: Complex, b: Complex) -> Complex {
    [a[0] * b[0] - a[1] * b[1], a[0] * b[1] + a[1] * b[0]]
}

/// The GPU's largest radix: four inputs gathered per output, so a 64-point line takes three
/// stages and 128 points four (few passes: a software rasteriser pays dearly for each; radix 8
/// gathered twice the inputs per output and came out slower on lavapipe, docs/PERFORMANCE.md).
pub const GPU_RADIX: usize = 4;
/// The CPU's: a gather of R inputs costs R products per output, so radix 2 (one product per
/// output a stage, log₂ n stages) does the least work where passes cost nothing.
pub const CPU_RADIX: usize = 2;

/// The stages of an inverse FFT of `n` points (a power of two) along one axis, of radix up to
/// `largest` (a power of two): each stage's radix R (the largest while it divides what is
/// left, then less) and span L, the length of the sums the stages before it made (the
/// product of their radices).
pub fn fft_plan(n: usize, largest: usize) -> Vec<(usize, usize)> {
    assert!(n.is_power_of_two() && n >= 2 && largest.is_power_of_two() && largest >= 2, "an FFT of {n} points");
    let (mut plan, mut span) = (Vec::new(), 1);
    while span < n {
        let radix = largest.min(n / span);
        plan.push((radix, span));
        span *= radix;
    }
    plan
}

/// One output of a stage of Stockham's inverse FFT along a line of `n` values, as a gather:
/// output `o` of the stage of radix R and span L is Σ_s in[i + s n/R] e^{+2πi s r/(RL)}, s < R,
/// with r = o mod RL and i = ⌊o/RL⌋ L + r mod L. Returns i, the inputs' stride n/R and the
/// twiddles' turns (s r mod RL)/RL for each s. After [`fft_plan`]'s stages the output is the
/// inverse DFT Σ X_k e^{+2πi jk/n} in natural order. (shaders/ambient_fft.wgsl gathers the
/// same per texel.)
pub fn stockham_gather(o: usize, (radix, span): (usize, usize), n: usize) -> (usize, usize, Vec<f32>) {
    let block = radix * span;
    let r = o % block;
    let turns = (0..radix).map(|s| ((s * r) % block) as f32 / block as f32).collect();
    ((o / block) * span + r % span, n / radix, turns)
}

/// The inverse 2D DFT of `data` (`n`² points, row-major; two complex signals per point,
/// transformed together): rows, then columns, by [`fft_plan`]'s stages for the CPU.
pub fn inverse_fft_2d(data: Vec<[f32; 4]>, n: usize) -> Vec<[f32; 4]> {
    inverse_fft_2d_by(data, n, &fft_plan(n, CPU_RADIX))
}

/// [`inverse_fft_2d`] by the stages of `plan` (the GPU's, for the tests).
pub fn inverse_fft_2d_by(mut data: Vec<[f32; 4]>, n: usize, plan: &[(usize, usize)]) -> Vec<[f32; 4]> {
    let mut scratch = data.clone();
    for along_rows in [true, false] {
        for &stage in plan {
            for o in 0..n {
                let (i, stride, turns) = stockham_gather(o, stage, n);
                let twiddles: Vec<Complex> =
                    turns.iter().map(|t| (std::f32::consts::TAU * t).sin_cos()).map(|(s, c)| [c, s]).collect();
                for line in 0..n {
                    let at = |k: usize| if along_rows { line * n + k } else { k * n + line };
                    let mut sum = [0.0f32; 4];
                    for (s, w) in twiddles.iter().enumerate() {
                        let x = data[at(i + s * stride)];
                        let (a, b) = (mul(*w, [x[0], x[1]]), mul(*w, [x[2], x[3]]));
                        sum = [sum[0] + a[0], sum[1] + a[1], sum[2] + b[0], sum[3] + b[1]];
                    }
                    scratch[at(o)] = sum;
                }
            }
            std::mem::swap(&mut data, &mut scratch);
        }
    }
    data
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::SplitMix64;

    #[test]
    fn the_stockham_stages_are_the_inverse_dft() {
        for n in [16, 64, 128] {
            for radix in [CPU_RADIX, GPU_RADIX] {
                inverse_fft_matches_the_direct_sum(n, radix);
            }
        }
    }

    fn inverse_fft_matches_the_direct_sum(n: usize, radix: usize) {
        let mut rng = SplitMix64(7);
        let input: Vec<[f32; 4]> = (0..n * n).map(|_| [0; 4].map(|_: i32| rng.range(-1.0, 1.0))).collect();
        let plan = fft_plan(n, radix);
        let fast = inverse_fft_2d_by(input.clone(), n, &plan);
        let mut largest = 0.0f32;
        for (y, x) in [(0, 0), (3, 5), (15, 1), (8, 8)] {
            let mut sum = [0.0f64; 4];
            for (idx, v) in input.iter().enumerate() {
                let (kx, ky) = (idx % n, idx / n);
                let a = std::f64::consts::TAU * ((kx * x + ky * y) as f64) / n as f64;
                let (c, s) = (a.cos(), a.sin());
                let v = v.map(|c| c as f64);
                sum[0] += v[0] * c - v[1] * s;
                sum[1] += v[0] * s + v[1] * c;
                sum[2] += v[2] * c - v[3] * s;
                sum[3] += v[2] * s + v[3] * c;
            }
            for c in 0..4 {
                largest = largest.max((fast[y * n + x][c] - sum[c] as f32).abs());
            }
        }
        // The output's rms is n (n² terms of rms 1): its float rounding grows with it.
        println!("Stockham inverse FFT {n}² by {plan:?}: largest difference from the direct sum {largest:e}");
        assert!(largest < 1e-6 * (n * n) as f32, "{largest}");
    }
}
