//! The simulation's parameters (see `params::table` for the whole table).

use crate::param_spec::{slider, Control, ParamSpec};

/// The water's own parameters: wave speed, damping, absorbing walls. (The parameter table, `params::table`, lists them in this order.)
pub const WATER: &[ParamSpec] = &[
    ParamSpec {
        name: "wave_speed",
        label: "Wave speed",
        group: "Water",
        unit: "m/s",
        control: slider(0.1, 2.0, 0.05),
        default: 0.6,
        help: "Speed c of ripples in the wave equation h_tt = c² ∇²h.",
    },
    ParamSpec {
        name: "damping",
        label: "Damping",
        group: "Water",
        unit: "1/s",
        control: slider(0.0, 5.0, 0.05),
        default: 0.5,
        help: "Rate k at which waves lose energy (amplitude decays as exp(-k t / 2)).",
    },
    ParamSpec {
        name: "absorbing_walls",
        label: "Absorbing walls",
        group: "Water",
        unit: "",
        control: Control::Toggle,
        default: 0.0,
        help: "Walls swallow waves in a damping layer along them instead of reflecting them.",
    },
];

/// The drops a click makes. (The parameter table, `params::table`, lists them in this order.)
pub const DROPS: &[ParamSpec] = &[
    ParamSpec {
        name: "drop_radius",
        label: "Drop radius",
        group: "Drops",
        unit: "m",
        control: slider(0.01, 0.3, 0.005),
        default: 0.04,
        help: "Radius of the cosine bump a click or drag adds.",
    },
    ParamSpec {
        name: "drop_strength",
        label: "Drop strength",
        group: "Drops",
        unit: "m",
        control: slider(-0.05, 0.05, 0.001),
        default: 0.012,
        help: "Height of the bump at its centre (negative pushes the water down).",
    },
    ParamSpec {
        name: "start_drops",
        label: "Drops at start",
        group: "Drops",
        unit: "",
        control: slider(0.0, 40.0, 1.0),
        default: 20.0,
        help: "Drops that fall on the pool when the page opens, so its rings and the caustics they cast show at once (0: the water starts calm).",
    },
];

/// The grid's resolution and pausing. (The parameter table, `params::table`, lists them in this order.)
pub const RUN: &[ParamSpec] = &[
    ParamSpec {
        name: "sim_size",
        label: "Grid resolution",
        group: "Simulation",
        unit: "cells",
        control: Control::Choice { values: &[128.0, 256.0, 512.0, 1024.0], names: &[] },
        default: 256.0,
        help: "Cells per side of the simulation grid; a change resamples the water, it does not reset it.",
    },
    ParamSpec {
        name: "paused",
        label: "Paused",
        group: "Simulation",
        unit: "",
        control: Control::Toggle,
        default: 0.0,
        help: "Freeze the water (space bar).",
    },
];
