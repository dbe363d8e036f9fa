//! Automatic quality, from the intervals between drawn frames: the resolution the scene is
//! drawn at ([`ResolutionGovernor`]: lower while frames take longer than a budget, back up
//! when there is headroom) and the most simulation steps a frame may take ([`StepGovernor`]:
//! as many as keep the water in real time, unless the steps themselves push the frame rate
//! under its floor). Pure bookkeeping; the renderer and the simulation do the work.

use crate::param_spec::{slider, Control, ParamSpec};
use std::collections::VecDeque;

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

/// Frames of (steps, interval) the step governor fits its cost model to.
const STEP_HISTORY: usize = 40;
/// Frames of one step count needed for their median to count.
const STEP_GROUP: usize = 3;
/// Least frames between two probes of the step cost.
const PROBE_EVERY: u32 = 60;
/// Where drawing alone takes near the target interval, steps may still make a frame this many
/// times as long as drawing alone (and a single step count is probed upwards below this many
/// targets).
const STEP_SHARE_NEAR_TARGET: f32 = 1.5;

/// The most fixed simulation steps a frame may take. Models a frame's interval as
/// `b + c * steps` (b: drawing and everything else, c: one step; both in s), fitted to the
/// medians of recent frames grouped by the steps they took, and allows the most steps whose
/// frame still fits the target interval (1/10 s: 10 frames/s), or 1.5 b where drawing alone
/// comes near the target (else a frame drawn in 0.099 s would get one step, 1/12 of real time,
/// and one drawn in 0.101 s all of them). Where even one step misses the target, steps are not
/// what makes frames slow, so all `max` are allowed (more simulated time per frame at little
/// cost). Without two step counts to compare, a frame rate under the
/// target with every allowed step taken is probed by allowing a third fewer for a few frames.
/// Frames never take more than `max` steps, so their cost cannot spiral.
#[derive(Clone, Debug)]
pub struct StepGovernor {
    max: u32,
    target: f32,
    cap: u32,
    /// Steps the frame being drawn took (its interval arrives with the next frame).
    pending: Option<u32>,
    history: VecDeque<(u32, f32)>,
    since_probe: u32,
}

impl StepGovernor {
    /// `max`: hard cap of steps a frame; `target`: the longest frame interval (s) steps may
    /// push the frame rate to.
    pub fn new(max: u32, target: f32) -> Self {
        Self {
            max: max.max(1),
            target,
            cap: max.max(1),
            pending: None,
            history: VecDeque::with_capacity(STEP_HISTORY),
            since_probe: PROBE_EVERY,
        }
    }

    /// Steps the next frame may take.
    pub fn cap(&self) -> u32 {
        self.cap
    }

    /// Takes the interval (s) that ended with this frame (the previous frame's cost), then the
    /// steps this frame takes are passed to [`StepGovernor::took`].
    pub fn observe(&mut self, interval: f32) {
        self.since_probe = self.since_probe.saturating_add(1);
        let Some(steps) = self.pending.take() else { return };
        if !(interval.is_finite() && interval > 0.0) {
            return;
        }
        if self.history.len() == STEP_HISTORY {
            self.history.pop_front();
        }
        self.history.push_back((steps, interval));
        self.decide();
    }

    /// The steps the frame now being drawn took.
    pub fn took(&mut self, steps: u32) {
        self.pending = Some(steps);
    }

    /// Median interval of each step count with enough frames, fewest steps first.
    fn groups(&self) -> Vec<(u32, f32)> {
        let mut counts: Vec<u32> = self.history.iter().map(|&(n, _)| n).collect();
        counts.sort_unstable();
        counts.dedup();
        counts
            .into_iter()
            .filter_map(|n| {
                let mut t: Vec<f32> = self.history.iter().filter(|&&(m, _)| m == n).map(|&(_, t)| t).collect();
                (t.len() >= STEP_GROUP).then(|| {
                    t.sort_by(f32::total_cmp);
                    (n, t[t.len() / 2])
                })
            })
            .collect()
    }

    fn decide(&mut self) {
        let groups = self.groups();
        if let (Some(&(na, ta)), Some(&(nb, tb))) = (groups.first(), groups.last()) {
            if nb > na {
                let c = ((tb - ta) / (nb - na) as f32).max(0.0);
                let b = ta - c * na as f32;
                let budget = self.target.max(STEP_SHARE_NEAR_TARGET * b);
                self.cap = if c <= 0.0 || b + c > self.target {
                    self.max
                } else {
                    (((budget - b) / c).floor() as u32).clamp(1, self.max)
                };
                return;
            }
            // One step count only: probe when frames are slow and take every step allowed.
            if na == self.cap && na > 1 && ta > self.target && self.since_probe >= PROBE_EVERY {
                self.cap = (na - na.div_ceil(3)).max(1);
                self.since_probe = 0;
            } else if na == self.cap && self.cap < self.max && ta < STEP_SHARE_NEAR_TARGET * self.target {
                self.cap += 1;
            }
        }
    }
}

/// The scene's resolution and the frame budget the automatic one keeps. (The parameter table, `params::table`, lists them in this order.)
pub const PARAMS: &[ParamSpec] = &[
    ParamSpec {
        name: "quality",
        label: "Resolution",
        group: "Display",
        unit: "",
        control: Control::Choice {
            values: &[0.0, 0.5, 0.6, 0.7, 0.85, 1.0],
            names: &["auto", "50%", "60%", "70%", "85%", "100%"],
        },
        default: 0.0,
        help: "Scale of the scene's resolution: fixed, or auto (lowered in steps down to 50% while frames take longer than the frame budget, raised again when there is headroom).",
    },
    ParamSpec {
        name: "frame_budget",
        label: "Frame budget",
        group: "Display",
        unit: "ms",
        control: slider(10.0, 200.0, 1.0),
        default: 33.0,
        help: "Time a frame should take at most; with automatic resolution, slower frames lower the resolution.",
    },
];

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

    /// A device whose frame interval is `base + per_step * steps` (s), rounded up to the
    /// display's 1/60 s ticks; the water advances through a `FixedStep` capped by the governor.
    /// Returns (steps cap at the end, mean interval, simulated s per wall s) over the last
    /// 200 of 400 frames.
    fn device(base: f32, per_step: f32) -> (u32, f32, f32) {
        let (dt, max, target) = (1.0 / 120.0, 12, 0.1);
        let mut governor = StepGovernor::new(max, target);
        let mut clock = crate::sim::FixedStep::new(dt, max);
        let tick = 1.0 / 60.0;
        let (mut steps, mut wall, mut simulated) = (0, 0.0, 0.0);
        for frame in 0..400 {
            let interval = ((base + per_step * steps as f32) / tick).ceil() * tick;
            governor.observe(interval);
            clock.max_steps = governor.cap();
            steps = clock.advance(interval);
            governor.took(steps);
            if frame >= 200 {
                wall += interval;
                simulated += steps as f32 * dt;
            }
        }
        (governor.cap(), wall / 200.0, simulated / wall)
    }

    #[test]
    fn steps_keep_real_time_unless_they_push_the_frame_rate_under_ten() {
        // Cheap steps: 60 frames/s, two steps each, real time.
        let (cap, interval, speed) = device(0.010, 0.001);
        println!("cheap steps: cap {cap}, {:.0} ms frames, speed {speed:.2}", interval * 1000.0);
        assert!((speed - 1.0).abs() < 0.02 && interval < 0.02);
        // Drawing 33 ms and 7 ms a step (a 256^2 grid on a software rasteriser): twelve steps
        // would make 117 ms frames; the cap settles where frames stay within 0.1 s.
        let (cap, interval, speed) = device(0.033, 0.007);
        println!("costly steps: cap {cap}, {:.0} ms frames, speed {speed:.2}", interval * 1000.0);
        assert!(interval <= 0.101 && (7..=10).contains(&cap) && speed > 0.65, "cap {cap}");
        // Slow drawing (150 ms) and cheap steps: fewer steps would not bring 10 frames/s, so
        // every frame takes all twelve (0.1 s of water a frame).
        let (cap, interval, speed) = device(0.150, 0.002);
        println!("slow drawing: cap {cap}, {:.0} ms frames, speed {speed:.2}", interval * 1000.0);
        assert!(cap == 12 && (speed - 0.1 / interval).abs() < 0.02, "cap {cap}, speed {speed}");
        // Drawing just under the target (95 ms, cheap steps, as the FFT ocean in headless
        // Chromium): not one step a frame (speed 0.09), but frames up to 1.5 times the drawing.
        let (cap, interval, speed) = device(0.095, 0.002);
        println!("drawing near the target: cap {cap}, {:.0} ms frames, speed {speed:.2}", interval * 1000.0);
        assert!(cap == 12 && speed > 0.65, "cap {cap}, speed {speed}");
    }
}
