//! The open sea (`scene` = sea): water to the horizon under the same sky as the pool, its waves
//! the FFT cascades of [`crate::ambient::cascades`], drawn on a grid projected from the screen
//! onto the sea plane (scenes/sea/render/mod.rs), with a height fog that takes water and sky to one colour
//! at the horizon. This file holds the scene's choice, its parameters and its camera's limits.
//! Lengths in metres, angles in degrees.

pub mod island;

use glam::Vec3;

use crate::ambient::cascades::{BREAKING_CASCADES, CASCADE_COUNT, WHITECAP_EDGE, WHITECAP_JACOBIAN, WHITECAP_SOFTNESS};
use crate::ambient::{AmbientModel, AmbientSettings, Spectrum};
use crate::camera::{CameraLimits, OrbitCamera};
use crate::param_spec::{slider, Control, ParamSpec};

crate::choices! {
    /// Which scene is drawn: the pool, the open sea or the ripple tank (the `scene` parameter).
    #[derive(Default)]
    pub enum SceneKind {
        #[default]
        Pool = "pool",
        Sea = "sea",
        Tank = "tank",
    }
}

crate::choices! {
    /// Whether the sea has an island, and where (the `sea_island` parameter).
    pub enum IslandChoice {
        None = "none",
        Offshore = "offshore",
        Shore = "shore",
    }
}

impl IslandChoice {
    /// Where the island stands, if there is one.
    pub fn place(self) -> Option<island::Place> {
        match self {
            IslandChoice::None => None,
            IslandChoice::Offshore => Some(island::Place::Offshore),
            IslandChoice::Shore => Some(island::Place::Shore),
        }
    }
}

/// The sea's camera: from a few metres to 600 m from its target on the water, looking down at
/// least 2° (the horizon stays in view from any height), with a far plane past the grid's
/// reach ([`GRID_FAR`]).
pub const SEA_LIMITS: CameraLimits =
    CameraLimits { pitch: (2.0, 89.0), distance: (3.0, 600.0), near: 0.25, far: 30_000.0 };

/// How far the projected grid reaches over the sea (m, horizontally): inside the far plane. Past
/// it the sky pass draws the sea at infinity, where the fog has taken it.
pub const GRID_FAR: f32 = 0.9 * SEA_LIMITS.far;
const _: () = assert!(GRID_FAR < SEA_LIMITS.far);
/// Screen pixels per cell of the projected grid, and the most cells across and down.
pub const GRID_CELL_PX: f32 = 8.0;
pub const GRID_MAX_CELLS: (u32, u32) = (160, 120);
/// Lattice points per side of each cascade.
pub const SEA_LATTICE: usize = 64;
/// Absorption (1/m) of clear sea water at red, green and blue light (pure water's, about 650,
/// 530 and 450 nm), and the share of light its molecules and particles scatter back (1/m).
pub const SEA_ABSORPTION: [f32; 3] = [0.35, 0.05, 0.015];
pub const SEA_BACKSCATTER: f32 = 0.002;
/// What the water's particles scatter out of a beam (1/m, all colours): with the absorption,
/// how far down the floor can be seen (a few tens of metres in clear coastal water).
pub const SEA_SCATTERING: f32 = 0.05;

/// The deep sea's albedo per channel: as a diffuse reflector it sends back about a third of
/// b_b / (a + b_b) of the light falling on it (Gordon's approximation of the irradiance
/// reflectance below the surface).
pub fn deep_water_albedo() -> [f32; 3] {
    SEA_ABSORPTION.map(|a| 0.33 * SEA_BACKSCATTER / (a + SEA_BACKSCATTER))
}

/// How far under the horizon (rad, about 2°) a ray down to the sea takes the haze of the ray
/// as far above it, so that water and sky meet in one colour there.
pub const HORIZON_HAZE_BAND: f32 = 0.035;
/// In a gale the wind tears spray off the crests, and the air just over the sea turns murky
/// (Beaufort 8 and up: "spray affects visibility"): the band widens to this (rad, about 4.6°)
/// as the wind rises over [`SPRAY_WINDS`] (m/s), so that a storm's dark sea fades into its
/// sky instead of meeting it in a line.
pub const SPRAY_HAZE_BAND: f32 = 0.08;
/// The winds (m/s) over which the band widens from the calm sea's to the gale's.
pub const SPRAY_WINDS: (f32, f32) = (12.0, 20.0);

/// The band under the horizon (rad) where the sea takes the sky's haze, for `wind` (m/s).
pub fn horizon_haze_band(wind: f32) -> f32 {
    let (calm, gale) = SPRAY_WINDS;
    let t = ((wind - calm) / (gale - calm)).clamp(0.0, 1.0);
    HORIZON_HAZE_BAND + (SPRAY_HAZE_BAND - HORIZON_HAZE_BAND) * t * t * (3.0 - 2.0 * t)
}

/// The fog's scale height (m): its density falls by e every this much above the sea.
pub const FOG_HEIGHT: f32 = 100.0;
/// The eye's clearance over the highest crest (m): the camera never goes into a wave.
pub const EYE_OVER_CRESTS: f32 = 1.0;

/// The patch of sea round the camera's target where the pool's wave equation runs, so that a
/// click makes ripples there: its half width (m), cells per side, depth (m; its ripples run at
/// shallow water's sqrt(g d)) and the fading of its ripples (1/s). Its walls absorb (the
/// pool's sponge, grown with the patch to 4 m), so the ripples run out and do not come back.
/// At 0.6 m deep they run at 2.4 m/s: the pool's default 0.6 m/s in a pool enlarged 16 times,
/// by Froude's similarity (speeds grow as the root of the lengths), as its bodies are, so
/// that a body and the ripples it makes keep the pool's timing (and a ripple about 4 m long on
/// deep water runs about as fast).
pub const PATCH_HALF_WIDTH: f32 = 16.0;
pub const PATCH_CELLS: u32 = 256;
pub const PATCH_DEPTH: f32 = 0.6;
pub const PATCH_DAMPING: f32 = 0.05;

/// The speed of the patch's ripples (m/s): shallow water's sqrt(g d).
pub fn patch_wave_speed() -> f32 {
    (crate::physics::GRAVITY * PATCH_DEPTH).sqrt()
}

/// How much larger a click's drop is in the patch than in the pool: its radius grows with the
/// patch's width against the pool's (a click looks the same size against either); its height
/// [`PATCH_DROP_HEIGHT`] times more, so that the rings stand out of a sea whose waves are as
/// steep as they.
pub fn patch_scale() -> f32 {
    PATCH_HALF_WIDTH / crate::world::PoolShape::CLASSIC.half_width
}
pub const PATCH_DROP_HEIGHT: f32 = 3.0;

/// The view the sea starts with (yaw °, pitch °, distance m): 40 m from a target on the water,
/// 9° above the horizon, looking towards the island.
pub const DEFAULT_VIEW: [f32; 3] = [160.0, 9.0, 40.0];

/// The camera the sea starts with ([`DEFAULT_VIEW`]).
pub fn default_camera() -> OrbitCamera {
    let [yaw, pitch, distance] = DEFAULT_VIEW;
    OrbitCamera { yaw, pitch, distance, target: Vec3::ZERO, fov_y: 45.0, limits: SEA_LIMITS }
}

/// The sea's settings, from its parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeaSettings {
    /// Wind speed (m/s) and the direction it blows towards (degrees from +x towards +z).
    pub wind_speed: f32,
    pub wind_direction: f32,
    /// Significant wave height H_s (m).
    pub wave_height: f32,
    /// Choppiness λ of the cascades (0: heights only).
    pub choppiness: f32,
    /// The fog's distance at sea level (m): light over it is dimmed to 1/e; `None`: no fog.
    pub fog_distance: Option<f32>,
    /// Where the island ([`island`]) stands in the sea, if it does.
    pub island: Option<island::Place>,
    /// Whether the projected grid's cells are outlined on the water (a debug view).
    pub grid_lines: bool,
}

impl Default for SeaSettings {
    /// Every setting at its parameter's default.
    fn default() -> Self {
        Self {
            wind_speed: SEA_WIND.default,
            wind_direction: SEA_WIND_DIRECTION.default,
            wave_height: SEA_WAVE_HEIGHT.default,
            choppiness: SEA_CHOPPINESS.default,
            fog_distance: (SEA_FOG.default >= 0.5).then_some(SEA_FOG_DISTANCE.default),
            island: IslandChoice::from(SEA_ISLAND.default).place(),
            grid_lines: SEA_GRID.default >= 0.5,
        }
    }
}

impl SeaSettings {
    /// The waves' settings for [`crate::ambient::cascades::SeaWaves::new`]: a JONSWAP sea.
    pub fn waves(&self) -> AmbientSettings {
        AmbientSettings {
            model: AmbientModel::Fft,
            wind_speed: self.wind_speed,
            wind_direction_deg: self.wind_direction,
            significant_height: self.wave_height,
            spread_deg: 60.0,
            spectrum: Spectrum::Jonswap,
            fft_size: SEA_LATTICE,
            choppiness: self.choppiness,
            ..Default::default()
        }
    }

    /// About the highest a crest stands above the mean level (m): a sea's largest waves are
    /// about twice its significant height from trough to crest.
    pub fn crest_bound(&self) -> f32 {
        self.wave_height
    }
}

/// The scene's choice (the pool's parameters stay as they are while the sea is shown).
pub const SCENE_PARAMS: &[ParamSpec] = &[ParamSpec {
    name: "scene",
    label: "Scene",
    group: "Scene",
    unit: "",
    control: Control::Choice { values: SceneKind::VALUES, names: SceneKind::NAMES },
    default: 0.0,
    help: "The pool, the open sea to the horizon under the same sky, or the ripple tank of the school lab with its lamp and screen.",
}];

/// The sea's own parameters (shown only with `scene` sea).
pub const PARAMS: &[ParamSpec] = &[
    SEA_WIND,
    SEA_WIND_DIRECTION,
    SEA_WAVE_HEIGHT,
    SEA_CHOPPINESS,
    SEA_FOG,
    SEA_FOG_DISTANCE,
    SEA_ISLAND,
    SEA_OBJECTS,
    SEA_GRID,
];

/// The `sea_wind` parameter.
pub const SEA_WIND: ParamSpec = ParamSpec {
    name: "sea_wind",
    label: "Wind",
    group: "Scene",
    unit: "m/s",
    control: slider(2.0, 25.0, 0.5),
    default: 8.0,
    help: "Wind speed over the sea: stronger wind puts the waves' energy at longer wavelengths.",
};

/// The `sea_wind_direction` parameter.
pub const SEA_WIND_DIRECTION: ParamSpec = ParamSpec {
    name: "sea_wind_direction",
    label: "Wind direction",
    group: "Scene",
    unit: "°",
    control: slider(0.0, 360.0, 1.0),
    default: 30.0,
    help: "Direction the wind blows towards, from +x towards +z.",
};

/// The `sea_wave_height` parameter.
pub const SEA_WAVE_HEIGHT: ParamSpec = ParamSpec {
    name: "sea_wave_height",
    label: "Wave height",
    group: "Scene",
    unit: "m",
    control: slider(0.1, 8.0, 0.1),
    default: 1.2,
    help: "Significant wave height: four standard deviations of the sea's height (about the mean of the highest third of the waves).",
};

/// The `sea_choppiness` parameter.
pub const SEA_CHOPPINESS: ParamSpec = ParamSpec {
    name: "sea_choppiness",
    label: "Choppiness",
    group: "Scene",
    unit: "",
    control: slider(0.0, 2.0, 0.05),
    default: 1.0,
    help: "How far the water is carried sideways towards the crests, sharpening them (Tessendorf's lambda).",
};

/// The `sea_fog` parameter.
pub const SEA_FOG: ParamSpec = ParamSpec {
    name: "sea_fog",
    label: "Fog",
    group: "Scene",
    unit: "",
    control: Control::Toggle,
    default: 1.0,
    help: "Haze over the sea, thinning with height, taking water and sky to one colour at the horizon.",
};

/// The `sea_fog_distance` parameter.
pub const SEA_FOG_DISTANCE: ParamSpec = ParamSpec {
    name: "sea_fog_distance",
    label: "Fog distance",
    group: "Scene",
    unit: "m",
    control: slider(500.0, 20_000.0, 100.0),
    default: 4000.0,
    help: "Distance over which the haze at sea level dims light to 37 %.",
};

/// The `sea_island` parameter.
pub const SEA_ISLAND: ParamSpec = ParamSpec {
    name: "sea_island",
    label: "Island",
    group: "Scene",
    unit: "",
    control: Control::Choice { values: IslandChoice::VALUES, names: IslandChoice::NAMES },
    default: 1.0,
    help: "An island with beaches, seen through the shallows round it, where the waves foam along the shore: offshore in the haze, or at the shore, its shallows under the patch where clicks make ripples and the ripples' caustics light the sand.",
};

/// The `sea_objects` parameter.
pub const SEA_OBJECTS: ParamSpec = ParamSpec {
    name: "sea_objects",
    label: "Objects",
    group: "Objects",
    unit: "",
    control: crate::bodies::OBJECT_CHOICES,
    default: 2.0,
    help: "What floats in the sea: the pool's sphere, duck and beach ball, as much larger as the patch of simulated water is than the pool. They ride the waves and leave wakes in the patch.",
};

/// The `sea_grid` parameter.
pub const SEA_GRID: ParamSpec = ParamSpec {
    name: "sea_grid",
    label: "Show the grid",
    group: "Scene",
    unit: "",
    control: Control::Toggle,
    default: 0.0,
    help: "Outline the cells of the grid the sea is drawn on: it is laid over the screen and projected onto the water, so its cells stay about the same size on screen, small near you and long towards the horizon.",
};

/// Which variant of the sea's shaders a frame needs: a feature left out costs nothing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SeaVariant {
    /// The island's shallows and mirror image, and where it stands.
    pub island: Option<island::Place>,
    /// The grid's cells outlined.
    pub grid_lines: bool,
    /// Whitecaps: the waves can break (`SeaWaves::may_break`), so the grid's vertices pass the
    /// breaking cascades' carry gradient for each pixel to find its foam's cover.
    pub whitecaps: bool,
    /// The whitecaps kept over time (where the device renders into float textures).
    pub whitecap_map: bool,
    /// The waves' caustics on the shallows' floor (with the island and the `caustics`
    /// parameter).
    pub shallow_caustics: bool,
    /// The floating bodies mirrored in the water: the reflected ray traced to them, on the
    /// grid's cells that can show them.
    pub mirrored_bodies: bool,
}

/// The whitecaps' albedo: foam sends back most of the light falling on it.
pub const WHITECAP_ALBEDO: f32 = 0.75;
/// The whitecaps are kept over time on a map of the sea round the origin (the clicks' patch):
/// its half width (m) and texels a side (2 m each), and the time (s) their foam takes to fade
/// to 1/e: long enough that a broken crest leaves a trail of lace thinning behind it (1 s left
/// the storm's water bare between breaking crests, judged too sparse for a gale, 2026-11-30).
pub const WHITECAP_MAP_HALF_WIDTH: f32 = 128.0;
pub const WHITECAP_MAP_TEXELS: u32 = 128;
pub const WHITECAP_LIFETIME: f32 = 2.5;

/// The sea's WGSL constants for `variant` (`ISLAND`, `GRID_LINES`, `WHITECAPS`, `WHITECAP_MAP`,
/// `SHALLOW_CAUSTICS`, `MIRRORED_BODIES`).
pub fn wgsl_constants(variant: SeaVariant) -> String {
    let SeaVariant { island, grid_lines, whitecaps, whitecap_map, shallow_caustics, mirrored_bodies } = variant;
    let [r, g, b] = deep_water_albedo();
    let [ar, ag, ab] = SEA_ABSORPTION;
    let absorption = format!(
        "const SEA_ABSORPTION: vec3<f32> = vec3<f32>({ar:?}, {ag:?}, {ab:?});\nconst SEA_SCATTERING: f32 = {SEA_SCATTERING:?};\n"
    );
    let switches = format!(
        "const ISLAND: bool = {};\nconst GRID_LINES: bool = {grid_lines};\nconst WHITECAPS: bool = {whitecaps};\n\
         const WHITECAP_MAP: bool = {whitecap_map};\n\
         const SHALLOW_CAUSTICS: bool = {shallow_caustics};\nconst MIRRORED_BODIES: bool = {mirrored_bodies};\n\
         const WHITECAP_MAP_HALF_WIDTH: f32 = {WHITECAP_MAP_HALF_WIDTH:?};\nconst WHITECAP_MAP_TEXELS: u32 = {WHITECAP_MAP_TEXELS}u;\n",
        island.is_some()
    );
    // The patch's absorbing border (m), where its ripples are drawn fading out.
    let sponge = crate::sim::SPONGE_WIDTH * patch_scale();
    let island = switches + &island::wgsl_constants(island.unwrap_or(island::Place::Offshore));
    absorption
        + &island
        + &format!(
            "const GRID_FAR: f32 = {GRID_FAR:?};\nconst SEA_LATTICE: i32 = {SEA_LATTICE};\n\
         const PATCH_HALF_WIDTH: f32 = {PATCH_HALF_WIDTH:?};\nconst PATCH_SPONGE: f32 = {sponge:?};\nconst WHITECAP_JACOBIAN: f32 = {WHITECAP_JACOBIAN:?};\nconst WHITECAP_SOFTNESS: f32 = {WHITECAP_SOFTNESS:?};\nconst WHITECAP_EDGE: f32 = {WHITECAP_EDGE:?};\n\
         const WHITECAP_ALBEDO: f32 = {WHITECAP_ALBEDO:?};\nconst CASCADES: i32 = {CASCADE_COUNT};\nconst BREAKING_CASCADES: i32 = {BREAKING_CASCADES};\n\
         const DEEP_WATER_ALBEDO: vec3<f32> = vec3<f32>({r:?}, {g:?}, {b:?});\n"
        )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sea_camera_starts_above_the_crests() {
        let camera = default_camera();
        assert!(camera.eye().y > SeaSettings::default().crest_bound());
    }
}
