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

    /// Whether the ellipsoid lies wholly above the rest level (y = 0), where it pushes no water.
    pub fn above_water(&self) -> bool {
        let to_world = self.unit_from_world.inverse();
        // Its lowest point: the centre less its support downwards.
        self.centre.y - to_world.row(1).length() > 0.0
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

    /// The cells whose centres lie within the ellipsoids' reach and a cell past it (plus the cell
    /// around each end).
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
        // A cell past the reach each way: the push is averaged over cells (displaced_column).
        (lo, hi) = (lo - dx, hi + dx);
        let last = n as f32 - 1.0;
        let index = |v: f32| ((v + half_width) / dx - 0.5).clamp(0.0, last);
        Self {
            x: (index(lo.x).floor() as u32, index(hi.x).ceil() as u32),
            z: (index(lo.y).floor() as u32, index(hi.y).ceil() as u32),
        }
    }

    /// Whether the two share a cell.
    pub fn overlaps(&self, other: &Self) -> bool {
        self.x.0 <= other.x.1 && other.x.0 <= self.x.1 && self.z.0 <= other.z.1 && other.z.0 <= self.z.1
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
    DISPLACEMENT_DEPTH * super::scale_of(half_width)
}
/// Area of the pool's water surface (m²) for a half width of 1 m; scale by half width².
pub fn pool_area(half_width: f32) -> f32 {
    4.0 * half_width * half_width
}

/// How much water (m, a column height) a body's ellipsoid pushes up over the cell `dx` (m) wide
/// centred on (x, z): the part of the vertical line through the cell inside the ellipsoid and
/// below the rest level, each depth y weighted by exp(y / `depth`) ([`displacement_depth`]). A
/// body moving from `from` to `to` raises the surface by column(to) - column(from): water ahead
/// of it and above it rises and falls behind it, fully submerged too (weaker the deeper it is),
/// and a body entering the water pushes its volume out around itself.
///
/// The column is averaged over the cell: taken at the cell's centre, a bobbing body's push
/// stopped at its waterline as a step, and a waterline near the hull's silhouette jumped as it
/// crossed a cell; both rang at the grid's own scale (dark specks round a bobbing duck). So the
/// chord's ends are spread by how much they change across the cell, and the chord's length at
/// the silhouette too ([`cell_mean_sqrt`], [`cell_mean_weight`]). (`shaders/sim_drop.wgsl`
/// mirrors this.)
pub fn displaced_column(x: f32, z: f32, hull: &HullSlot, depth: f32, dx: f32) -> f32 {
    let m = hull.unit_from_world;
    let u0 = m * (Vec3::new(x, 0.0, z) - hull.centre);
    let d = m.col(1);
    let (a, b, c) = (d.dot(d), u0.dot(d), u0.dot(u0) - 1.0);
    if a <= 0.0 {
        return 0.0;
    }
    // The chord's ends y = (-b ± s) / a with s² = b² - a c, and their change across the cell.
    let disc_slope = |along: Vec3| 2.0 * (b * along.dot(d) - a * u0.dot(along));
    let (gx, gz) = (disc_slope(m.col(0)), disc_slope(m.col(2)));
    let s = cell_mean_sqrt(b * b - a * c, 0.5 * dx * (gx.abs() + gz.abs()));
    if s <= 0.0 {
        return 0.0;
    }
    let (bx, bz) = (m.col(0).dot(d), m.col(2).dot(d));
    let (sx, sz) = (gx / (2.0 * s), gz / (2.0 * s));
    let end_spread = |sign: f32| 0.5 * dx * ((sign * sx - bx).abs() + (sign * sz - bz).abs()) / a;
    let top = cell_mean_weight((-b + s) / a, end_spread(1.0), depth);
    let bottom = cell_mean_weight((-b - s) / a, end_spread(-1.0), depth);
    (depth * (top - bottom)).max(0.0)
}

/// The mean of sqrt(max(t, 0)) for t spread evenly over `disc` ± `spread`: (P^3/2 - Q^3/2) /
/// (3 spread) with P, Q the range's ends clamped at 0, written so that it needs no division by a
/// spread of 0 and loses no precision to one much smaller than `disc`.
/// (`cell_mean_sqrt` in `shaders/sim_drop.wgsl`.)
fn cell_mean_sqrt(disc: f32, spread: f32) -> f32 {
    let (p, q) = ((disc + spread).max(0.0), (disc - spread).max(0.0));
    if q > 0.0 {
        // P - Q = 2 spread: 2 (P + sqrt(PQ) + Q) / (3 (sqrt P + sqrt Q)).
        2.0 * (p + (p * q).sqrt() + q) / (3.0 * (p.sqrt() + q.sqrt()))
    } else {
        p * p.sqrt() / (3.0 * spread).max(f32::MIN_POSITIVE)
    }
}

/// The mean of exp(min(t, 0) / `depth`) for t spread evenly over `y` ± `spread` (m): a chord's
/// end's weight (1 above the rest level), averaged over a cell. (e^u - 1) / u is taken from its
/// series where u is small, so that a narrow spread loses no precision.
/// (`cell_mean_weight` in `shaders/sim_drop.wgsl`.)
fn cell_mean_weight(y: f32, spread: f32, depth: f32) -> f32 {
    let (lo, hi) = (y - spread, y + spread);
    let (a, b) = (lo.min(0.0), hi.min(0.0));
    let u = (b - a) / depth;
    // Mean of exp(t / depth) over the part below the rest level, [a, b].
    let below = if u < 0.1 {
        (a / depth).exp() * (1.0 + u * (0.5 + u * (1.0 / 6.0 + u * (1.0 / 24.0 + u / 120.0))))
    } else {
        ((b / depth).exp() - (a / depth).exp()) / u
    };
    let share_below = (-lo / (2.0 * spread).max(f32::MIN_POSITIVE)).clamp(0.0, 1.0);
    share_below * below + (1.0 - share_below)
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
/// the chain goes from the first's start to the last's end). Then a move that starts and ends
/// above the water (the duck's head, mostly) is left out: it pushes nothing. (Left out only
/// after the chains are joined, so that a part dipping into the water on the way still chains.)
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
    for step in &mut moves {
        step.retain(|m| !(m.from.above_water() && m.to.above_water()));
    }
    moves
}

#[cfg(test)]
mod tests {
    use super::{cell_mean_sqrt, cell_mean_weight};

    #[test]
    fn the_cells_mean_square_root_is_the_mean_of_its_samples() {
        for &(disc, spread) in &[(4.0, 0.0), (4.0, 1e-6), (1.0, 0.5), (0.2, 0.5), (-0.2, 0.5), (-1.0, 0.5), (0.0, 0.0)]
        {
            let samples = 100_000;
            let mean = (0..samples)
                .map(|k| {
                    let t = disc + spread * (2.0 * (k as f64 + 0.5) / samples as f64 - 1.0);
                    t.max(0.0).sqrt()
                })
                .sum::<f64>()
                / samples as f64;
            let ours = cell_mean_sqrt(disc as f32, spread as f32) as f64;
            println!("disc {disc} ± {spread}: {ours:.6} against {mean:.6} sampled");
            assert!((ours - mean).abs() < 1e-5, "disc {disc} ± {spread}: {ours} against {mean}");
        }
    }

    #[test]
    fn a_chord_ends_mean_weight_is_the_mean_of_its_samples() {
        let depth = 0.1;
        for &(y, spread) in &[
            (-0.05, 0.0),
            (-0.05, 1e-6),
            (-0.05, 0.001),
            (0.002, 0.005),
            (-0.002, 0.005),
            (-0.3, 0.5),
            (0.2, 0.1),
            (0.0, 0.0),
        ] {
            let samples = 100_000;
            let mean = (0..samples)
                .map(|k| {
                    let t: f64 = y + spread * (2.0 * (k as f64 + 0.5) / samples as f64 - 1.0);
                    (t.min(0.0) / depth).exp()
                })
                .sum::<f64>()
                / samples as f64;
            let ours = cell_mean_weight(y as f32, spread as f32, depth as f32) as f64;
            println!("y {y} ± {spread}: {ours:.7} against {mean:.7} sampled");
            assert!((ours - mean).abs() < 1e-6, "y {y} ± {spread}: {ours} against {mean}");
        }
    }
}
