//! The floating bodies as one table of kinds: what each is made of (hull ellipsoids, density,
//! centre of mass), where it starts, where the water is sampled for it, how a ray picks it,
//! and its parameters. The demo keeps one [`Body`] per kind and loops over the table; the
//! `objects` parameter says which are in the pool (bit `i` for kind `i`).

pub mod duck;
pub mod sphere;

use glam::Vec3;

use crate::param_spec::{Control, ParamSpec};
use crate::physics::{Ellipsoid, FloatingBody, Pose};
use crate::sim::{HullSlot, MAX_HULL_MOVES, MAX_PROBES};

/// A parameter's value by its name (the app reads them from its table).
pub type Values<'a> = &'a dyn Fn(&str) -> f32;

/// One kind of floating body.
pub struct BodyKind {
    /// Its name among the `objects` choices.
    pub name: &'static str,
    /// Its own parameters (listed after `objects` in the table, in the order of [`KINDS`]).
    pub params: &'static [ParamSpec],
    /// How many ellipsoids its hull has (what [`BodyKind::hull`] returns).
    pub hull_parts: usize,
    /// Its hull in its own frame (m), for the parameters' values.
    pub hull: fn(Values) -> Vec<Ellipsoid>,
    /// Mass per volume (kg/m³).
    pub density: fn(Values) -> f32,
    /// Centre of mass in its own frame (m).
    pub centre_of_mass: Vec3,
    /// Where it starts (and returns to on reset).
    pub start: fn(Values) -> Pose,
    /// Radius (m) of the ring around it on which the water is sampled for its buoyancy: just
    /// outside its waterline, so the water it pushes up itself counts little.
    pub probe_ring: fn(Values) -> f32,
    /// Radius (m) of a ball standing in for it when it bumps into another body.
    pub bump_radius: fn(Values) -> f32,
    /// Distance along a ray (origin, unit dir) to where it hits the body at `pose`, if it does.
    pub pick: fn(&Pose, Values, Vec3, Vec3) -> Option<f32>,
}

/// Every kind, in the order of their bits in `objects` and of their parameters in the table.
pub const KINDS: [BodyKind; 2] = [sphere::KIND, duck::KIND];

/// Points on the ring around each body where the water is sampled for its buoyancy.
pub const PROBES_PER_BODY: usize = 8;

/// Every kind's hull ellipsoids together: the most hull moves one step of the water takes.
pub const HULL_MOVES: usize = {
    let mut n = 0;
    let mut i = 0;
    while i < KINDS.len() {
        n += KINDS[i].hull_parts;
        i += 1;
    }
    n
};

// The simulation's capacity for the bodies' pushes and probes holds the table.
const _: () = assert!(HULL_MOVES <= MAX_HULL_MOVES && KINDS.len() * PROBES_PER_BODY <= MAX_PROBES);

/// A body in the pool: the index of its kind in [`KINDS`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct BodyId(pub usize);

impl BodyId {
    /// Every body, one per kind.
    pub fn all() -> impl Iterator<Item = BodyId> {
        (0..KINDS.len()).map(BodyId)
    }

    /// The body of the kind called `name` ("sphere", "duck").
    pub fn named(name: &str) -> Option<BodyId> {
        KINDS.iter().position(|k| k.name == name).map(BodyId)
    }

    pub fn kind(self) -> &'static BodyKind {
        &KINDS[self.0]
    }

    /// Its bit in the `objects` parameter.
    pub fn bit(self) -> u32 {
        1 << self.0
    }
}

/// One body's state: its motion, its hull as the water last took it in (`None`: not in the
/// pool), and its volume under water after the last step (m³).
#[derive(Clone, Debug)]
pub struct Body {
    pub motion: FloatingBody,
    pub pushed: Option<Vec<HullSlot>>,
    pub submerged: f32,
}

impl Body {
    /// At rest at `pose`, not yet felt by the water.
    pub fn at(pose: Pose) -> Self {
        Self { motion: FloatingBody::at(pose), pushed: None, submerged: 0.0 }
    }
}

/// Which bodies float in the pool. (The parameter table, `params::table`, lists it first of
/// the Objects group; the kinds' own parameters follow.)
pub const PARAMS: &[ParamSpec] = &[ParamSpec {
    name: "objects",
    label: "Objects",
    group: "Objects",
    unit: "",
    control: Control::Choice { values: &[0.0, 1.0, 2.0, 3.0], names: &["none", "sphere", "duck", "both"] },
    default: 3.0,
    help: "What floats in the pool: nothing, the sphere, a rubber duck, or both.",
}];
