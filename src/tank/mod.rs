//! The ripple tank (`scene` = tank): a shallow glass-bottomed tray of water as the school lab
//! has it, a lamp above and a white screen below. Its waves follow the shallow-water wave
//! equation with a speed per cell, c = sqrt(g d), so water over a glass plate (shallower) runs
//! slower and bends them; barriers are cells the water cannot enter. Lengths in metres (the
//! parameters in millimetres where a lab's ruler would say so), times in seconds.
//!
//! This module holds the tank's parameters and settings, the apparatus' geometry
//! ([`medium`]: depth and walls per cell, the sources), the step arithmetic the GPU and the
//! CPU share ([`plan`]), the CPU reference ([`cpu`]) and the GPU engine ([`gpu`]). Its scene,
//! view and picture are `scenes/tank/`.

pub mod cpu;
pub mod gpu;
pub mod medium;
pub mod plan;
pub mod probe;
pub mod tuning;

use crate::camera::CameraLimits;
use crate::param_spec::{slider, Control, ParamSpec};

crate::choices! {
    /// The lab's set-up (the `tank_setup` parameter): what makes the waves and what stands
    /// in their way.
    #[derive(Default)]
    pub enum Setup {
        #[default]
        Dipper = "dipper",
        TwoDippers = "two_dippers",
        PlaneWave = "plane_wave",
        SingleSlit = "single_slit",
        DoubleSlit = "double_slit",
        Refraction = "refraction",
        Lens = "lens",
        Doppler = "doppler",
        Reflection = "reflection",
        Standing = "standing",
        Prism = "prism",
    }
}

crate::choices! {
    /// What a click or a drag in the tank does (the `tank_tool` parameter): drop pulses into
    /// the water, draw walls, erase (make open water again), place the probe, or lay a ruler.
    #[derive(Default)]
    pub enum Tool {
        #[default]
        Drops = "drops",
        Walls = "walls",
        Erase = "erase",
        Probe = "probe",
        Ruler = "ruler",
        Move = "move",
    }
}

crate::choices! {
    /// What the tank's picture shows (the `tank_view` parameter): the lamp's image on the
    /// screen below, the heights as colour, or the time-averaged intensity (h²).
    #[derive(Default)]
    pub enum TankView {
        #[default]
        Screen = "screen",
        Heights = "heights",
        Intensity = "intensity",
    }
}

crate::choices! {
    /// How the tank is seen (the `tank_look` parameter): the screen view (the paper under the
    /// tank, from above, as the class looks at it), the apparatus in 3D, or the two side by side.
    #[derive(Default)]
    pub enum Look {
        #[default]
        Screen = "screen",
        Apparatus = "apparatus",
        Split = "split",
    }
}

/// The apparatus view's start for the default tray and lamp (yaw °, pitch °, distance m): from
/// in front and a little to the side, 24° up, the lamp and the paper in the picture.
pub const APPARATUS_VIEW: [f32; 3] = [205.0, 24.0, 2.6];

/// The tank's camera: from straight above to 20° over the bench, 0.2 to 5 m from the tray.
pub const TANK_LIMITS: CameraLimits = CameraLimits { pitch: (20.0, 89.0), distance: (0.2, 5.0), near: 0.01, far: 20.0 };

/// The camera's start for the default tray (yaw °, pitch °, distance m): straight above it,
/// the bar's side at the bottom of the picture, the tray and its frame filling 90 % of the
/// picture's height (a larger tray moves the camera back in proportion).
pub const START_VIEW: [f32; 3] = [180.0, 89.0, 0.83];

/// Cells along each side of the tray.
pub const TANK_CELLS: u32 = 256;
/// The white screen's distance under the tray's glass bottom (m).
pub const SCREEN_BELOW: f32 = 0.5;
/// Width of the beaches along the walls, as a share of the tray's side, and their damping
/// rate at the wall in units of c / width (the pool's sponge profile: quadratic).
pub const BEACH_SHARE: f32 = 0.1;
pub const BEACH_STRENGTH: f32 = 12.0;
/// A dipper's radius (m), at least this many cells.
pub const DIPPER_RADIUS: f32 = 0.004;
pub const DIPPER_MIN_CELLS: f32 = 1.5;
/// The most point dippers.
pub const MAX_DIPPERS: usize = 4;
/// The most drops a click batch puts in at once.
pub const MAX_TANK_DROPS: usize = 4;
/// Bounds on the state: |h| (m) and |v| (m/s); beyond them a cell is clamped, NaN is rest.
pub const MAX_TANK_HEIGHT: f32 = 0.01;
pub const MAX_TANK_VELOCITY: f32 = 2.0;
/// A light damping of every wave (1/s, of the velocity and the height alike): the water's
/// viscosity and the tray's friction, which in a lab keep the waves trapped between the bar
/// and a wall (or a barrier) from building up at a resonance.
pub const TANK_DAMPING: f32 = 0.3;
/// The time (s) over which the intensity h² is averaged: a few periods of the slowest dipper.
pub const INTENSITY_TIME: f32 = 1.0;
/// Depth left over a glass plate, as a share of the tray's water depth.
pub const PLATE_DEPTH_SHARE: f32 = 0.35;
/// The probe's samples kept: one a fixed step, about four seconds.
pub const PROBE_SAMPLES: u32 = 512;
/// The least swing (m) the probe reads a frequency from: still water's rounding is far less.
pub const PROBE_LEAST_SWING: f32 = 1.0e-6;

/// The tank's settings, from its parameters (lengths in m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TankSettings {
    pub setup: Setup,
    /// How the tank is seen.
    pub look: Look,
    /// The tray's side (m) and its water's depth (m).
    pub size: f32,
    pub depth: f32,
    /// How many dippers stand in a row (the `two_dippers` set-up), and how far each one's
    /// phase lags its neighbour's on the −x side (rad): a phased array.
    pub dippers: u32,
    pub phase_step: f32,
    /// How much faster (Hz) each dipper in the row runs than its −x neighbour, and its
    /// amplitude as a share of that neighbour's.
    pub detune: f32,
    pub amplitude_ratio: f32,
    /// The dippers' frequency (Hz) and amplitude (m).
    pub frequency: f32,
    pub amplitude: f32,
    /// A slit's width and the spacing of two slits' (or two dippers') centres (m).
    pub slit_width: f32,
    pub slit_spacing: f32,
    /// The lamp's height over the water (m).
    pub lamp_height: f32,
    /// The moving dipper's speed (m/s).
    pub source_speed: f32,
    /// The strobe's flashes per second (Hz; 0: no strobe, the picture follows the water).
    pub strobe: f32,
    /// What the pointer does in the tray.
    pub tool: Tool,
    /// Whether the slits' directions d sin θ = m λ are drawn over the picture.
    pub lines: bool,
    /// Beaches along the walls that swallow the waves, or reflecting walls.
    pub beaches: bool,
    /// Whether the sources make one pulse (when switched on or reset) instead of a steady wave.
    pub pulse: bool,
    /// The probe, if shown: where it stands (x, z in m).
    pub probe: Option<(f32, f32)>,
    /// The intensity graph's line, if shown: its z (m).
    pub graph: Option<f32>,
}

impl Default for TankSettings {
    /// Every setting at its parameter's default.
    fn default() -> Self {
        Self {
            setup: Setup::from(TANK_SETUP.default),
            look: Look::from(TANK_LOOK.default),
            size: TANK_SIZE.default,
            depth: TANK_DEPTH.default * 1e-3,
            dippers: TANK_DIPPERS.default as u32,
            phase_step: TANK_PHASE.default.to_radians(),
            detune: TANK_DETUNE.default,
            amplitude_ratio: TANK_AMPLITUDE_RATIO.default,
            frequency: TANK_FREQUENCY.default,
            amplitude: TANK_AMPLITUDE.default * 1e-3,
            slit_width: TANK_SLIT_WIDTH.default * 1e-3,
            slit_spacing: TANK_SLIT_SPACING.default * 1e-3,
            lamp_height: TANK_LAMP_HEIGHT.default,
            source_speed: TANK_SOURCE_SPEED.default,
            strobe: TANK_STROBE.default,
            tool: Tool::from(TANK_TOOL.default),
            lines: TANK_LINES.default >= 0.5,
            beaches: TANK_BEACHES.default >= 0.5,
            pulse: TANK_PULSE.default >= 0.5,
            probe: (TANK_PROBE.default >= 0.5).then_some((TANK_PROBE_X.default * 1e-3, TANK_PROBE_Z.default * 1e-3)),
            graph: (TANK_GRAPH.default >= 0.5).then_some(TANK_GRAPH_Z.default * 1e-3),
        }
    }
}

impl TankSettings {
    /// The waves' speed in the open tray (m/s): shallow water's sqrt(g d).
    pub fn wave_speed(&self) -> f32 {
        (crate::physics::GRAVITY * self.depth).sqrt()
    }

    /// The dippers' wavelength in the open tray (m).
    pub fn wavelength(&self) -> f32 {
        self.wave_speed() / self.frequency
    }

    /// Half the tray's side (m): the tray spans [-half, half] each way.
    pub fn half_width(&self) -> f32 {
        0.5 * self.size
    }

    /// How much larger the tray's image is on the screen than the tray: the lamp's rays
    /// spread from its height over the water to the screen (through water and glass they
    /// bend towards the vertical, which the tray's few millimetres leave out).
    pub fn magnification(&self) -> f32 {
        (self.lamp_height + self.depth + SCREEN_BELOW) / self.lamp_height
    }
}

/// The tank's own parameters (shown only with `scene` tank).
pub const PARAMS: &[ParamSpec] = &[
    TANK_SETUP,
    TANK_LOOK,
    TANK_VIEW,
    TANK_TOOL,
    TANK_FREQUENCY,
    TANK_AMPLITUDE,
    TANK_DIPPERS,
    TANK_PHASE,
    TANK_DETUNE,
    TANK_AMPLITUDE_RATIO,
    TANK_DEPTH,
    TANK_SIZE,
    TANK_SLIT_WIDTH,
    TANK_SLIT_SPACING,
    TANK_LAMP_HEIGHT,
    TANK_SOURCE_SPEED,
    TANK_STROBE,
    TANK_LINES,
    TANK_BEACHES,
    TANK_PULSE,
    TANK_PROBE,
    TANK_PROBE_X,
    TANK_PROBE_Z,
    TANK_GRAPH,
    TANK_GRAPH_Z,
];

pub const TANK_SETUP: ParamSpec = ParamSpec {
    name: "tank_setup",
    label: "Set-up",
    group: "Tank",
    unit: "",
    control: Control::Choice { values: Setup::VALUES, names: Setup::NAMES },
    default: 0.0,
    help: "What is in the tank: one dipper, two dippers, a straight bar making plane waves, the bar behind a barrier with one or two slits, the bar and a glass plate whose straight edge bends the waves (refraction), a lens-shaped plate that brings them to a focus, a dipper moving across the tank (Doppler), a curved wall that reflects the bar's waves to a focus (a parabolic mirror), a straight wall facing the bar (standing waves), or a glass prism that turns the bar's waves aside.",
};

pub const TANK_LOOK: ParamSpec = ParamSpec {
    name: "tank_look",
    label: "Look",
    group: "Tank",
    unit: "",
    control: Control::Choice { values: Look::VALUES, names: Look::NAMES },
    default: 0.0,
    help: "The screen view shows the paper under the tank from above, as the class looks at it; the apparatus shows the lab's tank in 3D: the lamp over the tray, the water, its frame on its legs and the paper on the bench below with the lamp's image on it (drag to walk round it); split shows the two side by side.",
};

pub const TANK_VIEW: ParamSpec = ParamSpec {
    name: "tank_view",
    label: "View",
    group: "Tank",
    unit: "",
    control: Control::Choice { values: TankView::VALUES, names: TankView::NAMES },
    default: 0.0,
    help: "What the picture shows: the lamp's light on the screen under the tank (each crest focuses it like a lens into a bright line), the water's height as colour, or the intensity: the height squared, averaged over about the last second.",
};

pub const TANK_TOOL: ParamSpec = ParamSpec {
    name: "tank_tool",
    label: "Pointer",
    group: "Tank",
    unit: "",
    control: Control::Choice { values: Tool::VALUES, names: Tool::NAMES },
    default: 0.0,
    help: "What a click or a drag on the tray does: drop small pulses into the water, draw straight walls the waves cannot cross, from where you press to where you let go (a barrier of your own, a reflector, a box), erase back to open water, put the probe where you click, lay a ruler from where you press to where you let go (its length is shown under the tank: lay it across ten crests to measure a wavelength), or move a dipper or the bar: press on it and drag (the dipper you press on then shows its own frequency, amplitude and phase).",
};

/// The pen that draws and erases walls: its radius (m), at least this many cells.
pub const PEN_RADIUS: f32 = 0.002;
pub const PEN_MIN_CELLS: f32 = 0.75;

pub const TANK_FREQUENCY: ParamSpec = ParamSpec {
    name: "tank_frequency",
    label: "Frequency",
    group: "Tank",
    unit: "Hz",
    control: slider(2.0, 25.0, 0.5),
    default: 10.0,
    help: "How often the dippers (or the bar) go up and down. The wavelength is the speed over the frequency.",
};

pub const TANK_DIPPERS: ParamSpec = ParamSpec {
    name: "tank_dippers",
    label: "Dippers",
    group: "Tank",
    unit: "",
    control: slider(1.0, 4.0, 1.0),
    default: 2.0,
    help: "How many dippers stand in a row in the two-dipper set-up, the slit spacing apart.",
};

pub const TANK_PHASE: ParamSpec = ParamSpec {
    name: "tank_phase",
    label: "Phase step",
    group: "Tank",
    unit: "°",
    control: slider(-180.0, 180.0, 5.0),
    default: 0.0,
    help: "How far each dipper in the row lags its neighbour (a whole cycle is 360°). The waves add up where the lag is made up by the path: the beam turns towards the lagging end, by sin θ = (step/360°) λ / spacing. This is how a phased-array radar or an ultrasound probe steers its beam without moving.",
};

pub const TANK_DETUNE: ParamSpec = ParamSpec {
    name: "tank_detune",
    label: "Detune",
    group: "Tank",
    unit: "Hz",
    control: slider(-2.0, 2.0, 0.05),
    default: 0.0,
    help: "How much faster each dipper in the row runs than the one before it. Two dippers then beat: where their waves met crest to crest they soon meet crest to trough, and the still lines sweep across the tray as many times a second; a row of four sweeps its beam.",
};

pub const TANK_AMPLITUDE_RATIO: ParamSpec = ParamSpec {
    name: "tank_amplitude_ratio",
    label: "Amplitude ratio",
    group: "Tank",
    unit: "",
    control: slider(0.0, 1.0, 0.05),
    default: 1.0,
    help: "How far each dipper in the row moves the water, as a share of the one before it. With two dippers of unequal strength the still lines are no longer still: where crest meets trough the waves cancel only in part.",
};

pub const TANK_AMPLITUDE: ParamSpec = ParamSpec {
    name: "tank_amplitude",
    label: "Amplitude",
    group: "Tank",
    unit: "mm",
    control: slider(0.02, 1.0, 0.01),
    default: 0.3,
    help: "How far the dippers move the water up and down. A fraction of a millimetre is enough: each crest then focuses the lamp's light near the screen, as in a well-set lab tank; higher waves focus it above the screen, and the lines there break up.",
};

pub const TANK_DEPTH: ParamSpec = ParamSpec {
    name: "tank_depth",
    label: "Water depth",
    group: "Tank",
    unit: "mm",
    control: slider(5.0, 40.0, 1.0),
    default: 10.0,
    help: "The water's depth. Here the waves run at shallow water's speed sqrt(g d), faster in deeper water; over a glass plate the water is shallower, so the waves slow there and bend. (A real tank's centimetre ripples are not long against the depth and are pulled by surface tension too, so they run slower and their speed depends on the wavelength; these do not. Each lesson uses one frequency, and what it shows depends only on the wavelengths, so it holds.)",
};

pub const TANK_SIZE: ParamSpec = ParamSpec {
    name: "tank_size",
    label: "Tray size",
    group: "Tank",
    unit: "m",
    control: slider(0.4, 1.2, 0.05),
    default: 0.6,
    help: "The side of the square tray.",
};

pub const TANK_SLIT_WIDTH: ParamSpec = ParamSpec {
    name: "tank_slit_width",
    label: "Slit width",
    group: "Tank",
    unit: "mm",
    control: slider(5.0, 100.0, 1.0),
    default: 20.0,
    help: "The width of each gap in the barrier.",
};

pub const TANK_SLIT_SPACING: ParamSpec = ParamSpec {
    name: "tank_slit_spacing",
    label: "Slit spacing",
    group: "Tank",
    unit: "mm",
    control: slider(20.0, 300.0, 1.0),
    default: 90.0,
    help: "The distance between the centres of the two slits, or of the two dippers.",
};

pub const TANK_LAMP_HEIGHT: ParamSpec = ParamSpec {
    name: "tank_lamp_height",
    label: "Lamp height",
    group: "Tank",
    unit: "m",
    control: slider(0.3, 2.0, 0.05),
    default: 1.0,
    help:
        "The lamp's height over the water. The screen lies 0.5 m under the tray; a lower lamp spreads the image wider.",
};

pub const TANK_SOURCE_SPEED: ParamSpec = ParamSpec {
    name: "tank_source_speed",
    label: "Dipper speed",
    group: "Tank",
    unit: "m/s",
    control: slider(0.0, 0.6, 0.01),
    default: 0.12,
    help: "How fast the dipper of the Doppler set-up moves across the tank. Ahead of it the waves crowd together, behind it they spread out; faster than the waves (about 0.31 m/s in 10 mm of water), it leaves a bow wave, a V as behind a boat.",
};

pub const TANK_STROBE: ParamSpec = ParamSpec {
    name: "tank_strobe",
    label: "Strobe",
    group: "Tank",
    unit: "Hz",
    control: slider(0.0, 30.0, 0.1),
    default: 0.0,
    help: "Light the tank with flashes this many times a second (0: a steady lamp). At the dippers' frequency every flash finds the waves in the same place, so the pattern stands still and can be measured; a little off it, the waves creep slowly forward or back.",
};

pub const TANK_LINES: ParamSpec = ParamSpec {
    name: "tank_lines",
    label: "Slit lines",
    group: "Tank",
    unit: "",
    control: Control::Toggle,
    default: 0.0,
    help: "Draw, from between the slits, the directions where theory puts the pattern: for two slits the bright lines, d sin θ = m λ (d the slits' spacing); for one slit the dark ones, w sin θ = m λ (w its width).",
};

/// How wide the slits' lines are drawn (m in the tray).
pub const LINE_WIDTH: f32 = 0.0015;
/// The most lines the picture draws.
pub const MAX_LINES: usize = 16;

pub const TANK_BEACHES: ParamSpec = ParamSpec {
    name: "tank_beaches",
    label: "Beaches",
    group: "Tank",
    unit: "",
    control: Control::Toggle,
    default: 1.0,
    help: "Sloping beaches along the walls that swallow the waves (as the foam or mesh strips of a real tank do), or bare walls that reflect them.",
};

pub const TANK_PULSE: ParamSpec = ParamSpec {
    name: "tank_pulse",
    label: "Single pulse",
    group: "Tank",
    unit: "",
    control: Control::Toggle,
    default: 0.0,
    help: "The dippers (or the bar) make one crest and stop, each time this is switched on or the tank is reset, instead of a steady train of waves: watch a single wave spread, reflect and pass through the slits. All the dippers lift the water at the same moment (a phase step, a detune or a dipper's own phase or frequency does not shape a pulse).",
};

pub const TANK_PROBE: ParamSpec = ParamSpec {
    name: "tank_probe",
    label: "Probe",
    group: "Tank",
    unit: "",
    control: Control::Toggle,
    default: 0.0,
    help: "A probe in the water (the ring) and the graph of its height over the last four seconds in the picture's corner; under the tank, the frequency and the swing it reads. Place it with the Pointer's probe tool or the two sliders below.",
};

pub const TANK_PROBE_X: ParamSpec = ParamSpec {
    name: "tank_probe_x",
    label: "Probe across",
    group: "Tank",
    unit: "mm",
    control: slider(-600.0, 600.0, 1.0),
    default: 0.0,
    help: "The probe's place across the tray, from its middle, to the right as seen from above with the bar at the bottom (kept inside the tray).",
};

pub const TANK_PROBE_Z: ParamSpec = ParamSpec {
    name: "tank_probe_z",
    label: "Probe along",
    group: "Tank",
    unit: "mm",
    control: slider(-600.0, 600.0, 1.0),
    default: 150.0,
    help: "The probe's place along the tray, from its middle towards the far side (kept inside the tray).",
};

pub const TANK_GRAPH: ParamSpec = ParamSpec {
    name: "tank_graph",
    label: "Intensity graph",
    group: "Tank",
    unit: "",
    control: Control::Toggle,
    default: 0.0,
    help: "A line across the tray and over it the graph of the intensity along it (the height squared, averaged over about the last second): where the waves add up and where they cancel, as a screen far from the slits would show.",
};

pub const TANK_GRAPH_Z: ParamSpec = ParamSpec {
    name: "tank_graph_z",
    label: "Graph line",
    group: "Tank",
    unit: "mm",
    control: slider(-600.0, 600.0, 1.0),
    default: 200.0,
    help: "Where the intensity graph's line crosses the tray, from its middle towards the far side (kept inside the tray).",
};
