//! A dipper's own frequency, amplitude and phase, set for it alone (Falstad's "edit source"):
//! the move tool picks a dipper, and these three settings then show under the controls. They
//! are not in the parameter table (there are up to four dippers, each with its own); they
//! travel in the sketch, with the dippers moved.

use super::medium::Dipper;
use super::{TankSettings, TANK_AMPLITUDE, TANK_FREQUENCY};
use crate::param_spec::{slider, Control, ParamSpec};

/// One dipper's own settings: frequency (Hz), amplitude (m), phase (rad; a lag is negative).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tuning {
    pub frequency: f32,
    pub amplitude: f32,
    pub phase: f32,
}

impl Tuning {
    /// What `dipper` does now in a tank of `settings`: the set frequency and amplitude with
    /// its row's detune, share and phase.
    pub fn of(dipper: &Dipper, settings: &TankSettings) -> Self {
        let phase = (dipper.phase + std::f32::consts::PI).rem_euclid(std::f32::consts::TAU) - std::f32::consts::PI;
        Self { frequency: settings.frequency + dipper.detune, amplitude: settings.amplitude * dipper.amplitude, phase }
    }

    /// Makes `dipper` run at these settings in a tank of `settings` (its detune against the set
    /// frequency, its amplitude as a share of the set amplitude, which is never 0).
    pub fn apply(&self, dipper: &mut Dipper, settings: &TankSettings) {
        dipper.detune = self.frequency - settings.frequency;
        dipper.amplitude = self.amplitude / settings.amplitude.max(TANK_AMPLITUDE.min() * 1e-3);
        dipper.phase = self.phase;
    }

    /// Its settings as (spec, value in the spec's unit).
    pub fn values(&self) -> [(&'static ParamSpec, f32); 3] {
        [
            (&DIPPER_FREQUENCY, self.frequency),
            (&DIPPER_AMPLITUDE, self.amplitude * 1e3),
            (&DIPPER_PHASE, self.phase.to_degrees()),
        ]
    }

    /// These settings with the one named `name` set to `value` (in its spec's unit, clamped to
    /// its range), or `None` if no setting has that name.
    pub fn with(mut self, name: &str, value: f32) -> Option<Self> {
        let spec = [&DIPPER_FREQUENCY, &DIPPER_AMPLITUDE, &DIPPER_PHASE].into_iter().find(|s| s.name == name)?;
        let value = spec.sanitise(value);
        match name {
            "frequency" => self.frequency = value,
            "amplitude" => self.amplitude = value * 1e-3,
            _ => self.phase = value.to_radians(),
        }
        Some(self)
    }
}

/// The group the picked dipper's settings show in.
pub const DIPPER_GROUP: &str = "Dipper";

pub const DIPPER_FREQUENCY: ParamSpec = ParamSpec {
    name: "frequency",
    label: "Its frequency",
    group: DIPPER_GROUP,
    unit: "Hz",
    control: match TANK_FREQUENCY.control {
        Control::Slider { min, max, .. } => slider(min, max, 0.05),
        other => other,
    },
    default: TANK_FREQUENCY.default,
    help: "How often this dipper goes up and down. Two dippers a little apart in frequency beat: their still lines sweep across the tray.",
};

pub const DIPPER_AMPLITUDE: ParamSpec = ParamSpec {
    name: "amplitude",
    label: "Its amplitude",
    group: DIPPER_GROUP,
    unit: "mm",
    control: match TANK_AMPLITUDE.control {
        Control::Slider { max, step, .. } => slider(0.0, max, step),
        other => other,
    },
    default: TANK_AMPLITUDE.default,
    help: "How far this dipper moves the water (0 stills it). Where the waves of a strong and a weak dipper meet crest to trough, they cancel only in part.",
};

pub const DIPPER_PHASE: ParamSpec = ParamSpec {
    name: "phase",
    label: "Its phase",
    group: DIPPER_GROUP,
    unit: "°",
    control: slider(-180.0, 180.0, 5.0),
    default: 0.0,
    help: "How far this dipper runs ahead of the set phase (a whole cycle is 360°; negative: it lags). Two dippers 180° apart send crest against trough: the middle line between them is still.",
};
