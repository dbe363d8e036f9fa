//! What the probe reads off its record of heights: the frequency (from the times its wave
//! crosses its mean going up, interpolated between samples) and the swing (half of highest
//! less lowest), as a lab's oscilloscope would.

use super::PROBE_LEAST_SWING;

/// The probe's reading.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ProbeReading {
    /// The wave's frequency (Hz), if at least two whole periods were recorded.
    pub frequency: Option<f32>,
    /// Half of the highest less the lowest height over the record (m).
    pub swing: f32,
}

/// Reads `heights` (m, oldest first, one each `dt` s), from where the waves have arrived:
/// the first sample a quarter as high as the highest (still water before it has no period).
pub fn read(heights: &[f32], dt: f32) -> ProbeReading {
    let highest = heights.iter().fold(0.0f32, |m, &h| m.max(h.abs()));
    let arrived = heights.iter().position(|&h| h.abs() >= 0.25 * highest).unwrap_or(0);
    let heights = &heights[arrived..];
    let (low, high) = heights.iter().fold((f32::MAX, f32::MIN), |(lo, hi), &h| (lo.min(h), hi.max(h)));
    if heights.len() < 3 || high - low < 2.0 * PROBE_LEAST_SWING {
        return ProbeReading { frequency: None, swing: if heights.is_empty() { 0.0 } else { 0.5 * (high - low) } };
    }
    let mean = heights.iter().map(|&h| h as f64).sum::<f64>() / heights.len() as f64;
    // Upward crossings of the mean, each at a fractional sample index; a crossing counts only
    // after the wave has been below the mean by a tenth of the swing (noise does not cross).
    let band = 0.1 * (high - low) as f64;
    let mut crossings = Vec::new();
    let mut armed = false;
    for (k, pair) in heights.windows(2).enumerate() {
        let (a, b) = (pair[0] as f64 - mean, pair[1] as f64 - mean);
        armed |= a < -band;
        if armed && a < 0.0 && b >= 0.0 {
            crossings.push(k as f64 + a / (a - b));
            armed = false;
        }
    }
    let frequency = match (crossings.first(), crossings.last()) {
        (Some(first), Some(last)) if crossings.len() >= 3 => {
            Some(((crossings.len() - 1) as f64 / ((last - first) * dt as f64)) as f32)
        }
        _ => None,
    };
    ProbeReading { frequency, swing: 0.5 * (high - low) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sampled_sine_reads_its_frequency_and_swing() {
        let dt = 1.0 / 120.0;
        for f in [2.0f32, 7.3, 10.0, 25.0] {
            let heights: Vec<f32> =
                (0..512).map(|k| 3e-4 * (std::f32::consts::TAU * f * k as f32 * dt + 0.4).sin()).collect();
            let r = read(&heights, dt);
            let got = r.frequency.expect("a frequency");
            println!("{f} Hz read as {got:.4} Hz, swing {:.3e} m", r.swing);
            assert!((got / f - 1.0).abs() < 2e-3, "{f} Hz read as {got}");
            assert!((r.swing / 3e-4 - 1.0).abs() < 0.05);
        }
        assert_eq!(read(&[0.0; 100], dt).frequency, None, "still water has no frequency");
    }
}
