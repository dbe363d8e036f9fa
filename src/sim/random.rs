//! Seeded random numbers for tools and tests.

use super::plan::Drop;

/// A small deterministic random generator (SplitMix64) for seeded drops in tools and tests.
#[derive(Clone, Debug)]
pub struct SplitMix64(pub u64);

impl SplitMix64 {
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f32, hi: f32) -> f32 {
        let unit = (self.next_u64() >> 40) as f32 / (1u64 << 24) as f32;
        lo + (hi - lo) * unit
    }
}

/// `count` drops at seeded random places in the pool (within 90 % of the half width),
/// of the given radius (m) and strength (m), alternating in sign like rain and splashes.
pub fn random_drops(seed: u64, count: u32, half_width: f32, radius: f32, strength: f32) -> Vec<Drop> {
    let mut rng = SplitMix64(seed);
    (0..count)
        .map(|i| Drop {
            x: rng.range(-0.9, 0.9) * half_width,
            z: rng.range(-0.9, 0.9) * half_width,
            radius,
            strength: if i % 2 == 0 { strength } else { -strength },
        })
        .collect()
}
