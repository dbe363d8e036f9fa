//! How the floating bodies and the water meet: the ellipsoids that push the water, the
//! column of water each displaces, the cells a push touches, and the heights sampled back for
//! buoyancy. Lengths in metres.

use glam::{Mat3, Vec2, Vec3};

/// One ellipsoid of a body as the displacement pass takes it: its centre (m) and the matrix
/// taking offsets from the centre (m) into the unit ball.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HullSlot {
    pub centre: Vec3,
    pub unit_from_world: Mat3,
}

/// How far (m) an ellipsoid's centre must move before it pushes the water. A body floating at
/// rest jitters by less; its small moves wait and join a later push (from where it last
/// pushed to where it is), so nothing is lost and a still body runs no pass.
pub const PUSH_MIN_MOVE: f32 = 2.0e-4;

impl HullSlot {
    /// Whether the ellipsoid has moved far enough from `before` to push the water: its centre
    /// by more than [`PUSH_MIN_MOVE`], or its orientation or shape by about as much at its surface.
    pub fn moved_from(&self, before: &HullSlot) -> bool {
        let turned = (self.unit_from_world - before.unit_from_world).to_cols_array();
        self.centre.distance(before.centre) > PUSH_MIN_MOVE || turned.iter().any(|d| d.abs() > 50.0 * PUSH_MIN_MOVE)
    }

    /// The ellipsoid's reach over the pool (m): its half extents along x and z (it pushes no
    /// water outside centre ± reach).
    pub fn reach(&self) -> Vec2 {
        let to_world = self.unit_from_world.inverse();
        // Support of the ellipsoid along x and z: the length of that row of the matrix.
        Vec2::new(to_world.row(0).length(), to_world.row(2).length())
    }
}

/// Cells of an `n` x `n` grid: columns `x.0..=x.1`, rows `z.0..=z.1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CellRange {
    pub x: (u32, u32),
    pub z: (u32, u32),
}

impl CellRange {
    pub fn all(n: u32) -> Self {
        Self { x: (0, n - 1), z: (0, n - 1) }
    }

    /// The cells whose centres lie within the ellipsoids' reach (plus the cell around each end).
    pub fn under(hulls: &[HullSlot], n: u32, half_width: f32) -> Self {
        let (mut lo, mut hi) = (Vec2::splat(f32::INFINITY), Vec2::splat(f32::NEG_INFINITY));
        for hull in hulls {
            let c = Vec2::new(hull.centre.x, hull.centre.z);
            lo = lo.min(c - hull.reach());
            hi = hi.max(c + hull.reach());
        }
        if !(lo.is_finite() && hi.is_finite()) {
            return Self::all(n);
        }
        let dx = 2.0 * half_width / n as f32;
        let last = n as f32 - 1.0;
        let index = |v: f32| ((v + half_width) / dx - 0.5).clamp(0.0, last);
        Self {
            x: (index(lo.x).floor() as u32, index(hi.x).ceil() as u32),
            z: (index(lo.y).floor() as u32, index(hi.y).ceil() as u32),
        }
    }

    /// The smallest range holding both.
    pub fn union(self, other: Self) -> Self {
        Self {
            x: (self.x.0.min(other.x.0), self.x.1.max(other.x.1)),
            z: (self.z.0.min(other.z.0), self.z.1.max(other.z.1)),
        }
    }

    pub fn cells(&self) -> u32 {
        (self.x.1 + 1 - self.x.0) * (self.z.1 + 1 - self.z.0)
    }
}

/// An ellipsoid's move since the water last took the bodies in (see [`displaced_column`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HullMove {
    pub from: HullSlot,
    pub to: HullSlot,
}

/// Most ellipsoid moves one step passes to the water: room for the hulls of every kind of
/// body (`bodies::HULL_MOVES`, checked there; the drop pass loops over those passed only).
pub const MAX_HULL_MOVES: usize = 8;
/// Steps of one frame whose body moves are applied each before its own step (later steps' moves
/// are added to the last), so that the water is pushed the same at any frame rate.
pub const MAX_PUSH_STEPS: usize = 4;
/// Cells per side of the CPU copy of the water the GPU engine keeps for the bodies' buoyancy
/// (at most; a smaller grid keeps its own size). It gets the same drops, pushes and steps, so
/// it holds the same waves at a resolution that still resolves everything a body of 0.2 m or
/// more responds to, for about 0.1 ms per step.
pub const CPU_COPY_SIZE: u32 = 128;
/// Most points the water is sampled at for the bodies each frame: room for a ring around a
/// body of every kind (`bodies::PROBES_PER_BODY` each, checked there).
pub const MAX_PROBES: usize = 48;
/// Depth (m) over which a body's push on the surface fades in the pool (see
/// [`displaced_column`]); a wider field's grows with it ([`displacement_depth`]).
pub const DISPLACEMENT_DEPTH: f32 = 0.1;

/// The depth a body's push fades over in a field of `half_width` (m): the pool's, grown with
/// the field as its bodies are (the open sea's patch holds bodies as much larger).
pub fn displacement_depth(half_width: f32) -> f32 {
    DISPLACEMENT_DEPTH * super::plan::scale_of(half_width)
}
/// Area of the pool's water surface (m²) for a half width of 1 m; scale by half width².
pub fn pool_area(half_width: f32) -> f32 {
    4.0 * half_width * half_width
}

/// How much water (m, a column height) a body's ellipsoid pushes up at pool point (x, z): the
/// part of the vertical line through (x, z) inside the ellipsoid and below the rest level,
/// each depth y weighted by exp(y / `depth`) ([`displacement_depth`]). A body moving from `from` to `to`
/// raises the surface by column(to) - column(from): water ahead of it and above it rises and
/// falls behind it, fully submerged too (weaker the deeper it is), and a body entering the
/// water pushes its volume out around itself. (`shaders/sim_drop.wgsl` mirrors this.)
pub fn displaced_column(x: f32, z: f32, hull: &HullSlot, depth: f32) -> f32 {
    let u0 = hull.unit_from_world * (Vec3::new(x, 0.0, z) - hull.centre);
    let d = hull.unit_from_world.col(1);
    let (a, b, c) = (d.dot(d), u0.dot(d), u0.dot(u0) - 1.0);
    let disc = b * b - a * c;
    if disc <= 0.0 || a <= 0.0 {
        return 0.0;
    }
    let s = disc.sqrt();
    let y0 = (-b - s) / a;
    let y1 = ((-b + s) / a).min(0.0);
    if y1 <= y0 {
        return 0.0;
    }
    depth * ((y1 / depth).exp() - (y0 / depth).exp())
}

/// What the bodies in the pool do to the water in a frame, set before
/// [`HeightField::encode`](super::HeightField::encode).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BodyCoupling {
    /// Per step of the frame, the ellipsoid moves to push the water by before that step (at
    /// most [`MAX_HULL_MOVES`] per step, [`MAX_PUSH_STEPS`] steps).
    pub moves: Vec<Vec<HullMove>>,
    /// Mean height (m) the water is held at: the bodies' submerged volume over the pool's
    /// area, because that volume of water has been pushed up into the surface.
    pub rest_level: f32,
    /// Points (x, z in m) to sample the water at for the bodies' buoyancy (at most
    /// [`MAX_PROBES`]); see [`HeightField::probes`](super::HeightField::probes).
    pub probes: Vec<Vec2>,
}

/// Heights sampled for the bodies.
#[derive(Clone, Debug, PartialEq)]
pub struct ProbeSamples {
    /// The points (x, z in m) asked for.
    pub points: Vec<Vec2>,
    /// Water height at each (m).
    pub heights: Vec<f32>,
    /// Frame ([`HeightField::frames`](super::HeightField::frames)) whose water they were
    /// sampled from.
    pub frame: u64,
}

/// At most [`MAX_PUSH_STEPS`] steps of at most [`MAX_HULL_MOVES`] moves: the moves of later
/// steps join the last step's (an ellipsoid's moves chain: where one ends the next starts, so
/// the chain goes from the first's start to the last's end).
pub(super) fn merge_push_steps(mut moves: Vec<Vec<HullMove>>) -> Vec<Vec<HullMove>> {
    for step in &mut moves {
        step.truncate(MAX_HULL_MOVES);
    }
    while moves.len() > MAX_PUSH_STEPS {
        let later = moves.pop().expect("more than one step");
        if let Some(last) = moves.last_mut() {
            for l in later {
                if let Some(m) = last.iter_mut().find(|m| m.to == l.from) {
                    m.to = l.to;
                } else if last.len() < MAX_HULL_MOVES {
                    last.push(l);
                }
            }
        }
    }
    moves
}
