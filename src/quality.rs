//! Automatic resolution: the scene is drawn at a lower resolution (and scaled up to the
//! target) while frames take longer than a budget, and back at full resolution when there is
//! headroom. Pure bookkeeping on frame intervals; the renderer does the drawing.

/// Render scales (fraction of the target's width and height) the automatic quality steps
/// through, from full resolution down. Each step down saves 25-40 % of the pixels.
pub const SCALES: [f32; 5] = [1.0, 0.85, 0.7, 0.6, 0.5];
/// Frames to let pass after a change of scale before judging the new one.
const SETTLE_FRAMES: u32 = 2;
/// Frame intervals each decision looks at (their median).
const SAMPLES: usize = 5;
/// Step down when the median frame is this much over budget ...
const SLOW: f32 = 1.2;
/// ... and up when it is under this fraction of it: one step up adds at most 46 % pixels
/// (0.85 / 0.7 squared), so a frame at 0.6 of the budget stays under it and the scale does
/// not oscillate.
const FAST: f32 = 0.6;

/// Chooses the render scale from the intervals between drawn frames.
#[derive(Clone, Debug, PartialEq)]
pub struct ResolutionGovernor {
    /// Index into [`SCALES`].
    level: usize,
    samples: Vec<f32>,
    settle: u32,
}

impl Default for ResolutionGovernor {
    fn default() -> Self {
        Self { level: 0, samples: Vec::with_capacity(SAMPLES), settle: SETTLE_FRAMES }
    }
}

impl ResolutionGovernor {
    /// The scale to draw the next frame at.
    pub fn scale(&self) -> f32 {
        SCALES[self.level]
    }

    /// Takes the interval (s) between the last two drawn frames and the budget (s) a frame
    /// should fit in. A slow frame rate steps down as far as the pixel count suggests (frame
    /// time taken to scale with pixels), a fast one steps up one level at a time.
    pub fn observe(&mut self, interval: f32, budget: f32) {
        if !(interval.is_finite() && interval > 0.0 && budget > 0.0) {
            return;
        }
        if self.settle > 0 {
            self.settle -= 1;
            return;
        }
        self.samples.push(interval);
        if self.samples.len() < SAMPLES {
            return;
        }
        self.samples.sort_by(f32::total_cmp);
        let median = self.samples[SAMPLES / 2];
        self.samples.clear();
        let last = SCALES.len() - 1;
        let level = if median > SLOW * budget && self.level < last {
            // Pixels, and so time, go with scale squared.
            let wanted = self.scale() * (budget / median).sqrt();
            SCALES.iter().position(|&s| s <= wanted).unwrap_or(last).max(self.level + 1)
        } else if median < FAST * budget && self.level > 0 {
            self.level - 1
        } else {
            self.level
        };
        if level != self.level {
            self.level = level;
            self.settle = SETTLE_FRAMES;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(governor: &mut ResolutionGovernor, frame_at_full: f32, budget: f32, frames: usize) -> Vec<f32> {
        (0..frames)
            .map(|_| {
                let s = governor.scale();
                governor.observe(frame_at_full * s * s, budget);
                governor.scale()
            })
            .collect()
    }

    #[test]
    fn slow_frames_lower_the_scale_and_fast_ones_raise_it_without_oscillating() {
        let budget = 1.0 / 30.0;
        let mut g = ResolutionGovernor::default();
        // Frames of 0.3 s at full resolution: far over budget, down to the floor.
        let scales = run(&mut g, 0.3, budget, 40);
        println!("0.3 s frames: scales {scales:?}");
        assert_eq!(g.scale(), 0.5);
        // Frames of 50 ms at full resolution: 0.7 (24.5 ms) fits, 0.85 (36 ms) does not.
        let scales = run(&mut g, 0.05, budget, 200);
        println!("50 ms frames: settled at {}", g.scale());
        let tail = &scales[100..];
        assert!(tail.iter().all(|&s| s == tail[0]), "oscillates: {tail:?}");
        assert!(tail[0] >= 0.6 && tail[0] <= 0.7, "settled at {}", tail[0]);
        // Fast frames: back to full resolution.
        run(&mut g, 0.01, budget, 60);
        assert_eq!(g.scale(), 1.0);
    }

    #[test]
    fn bad_intervals_are_ignored() {
        let mut g = ResolutionGovernor::default();
        for v in [f32::NAN, f32::INFINITY, -1.0, 0.0] {
            for _ in 0..20 {
                g.observe(v, 1.0 / 30.0);
            }
        }
        assert_eq!(g.scale(), 1.0);
    }
}
