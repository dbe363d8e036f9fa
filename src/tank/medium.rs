//! What the tray holds, cell by cell: the water's depth (so its wave speed), the barriers the
//! water cannot enter, the glass plates that make it shallower and the beaches along the
//! walls; and what makes the waves (dippers, a bar). The GPU and the CPU read the same cells.

use super::{
    Setup, TankSettings, BEACH_SHARE, BEACH_STRENGTH, DIPPER_MIN_CELLS, DIPPER_RADIUS, MAX_DIPPERS, PLATE_DEPTH_SHARE,
    TANK_DAMPING,
};
use crate::physics::GRAVITY;

/// What a cell is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CellKind {
    Water,
    /// A barrier: no water, no flux across its faces.
    Wall,
    /// Water over a glass plate, shallower than the rest.
    Plate,
}

impl CellKind {
    /// The code the shaders read (the medium texture's `w`).
    pub fn code(self) -> f32 {
        match self {
            CellKind::Water => 0.0,
            CellKind::Wall => 1.0,
            CellKind::Plate => 2.0,
        }
    }
}

/// The cells' kind codes as WGSL constants (`WALL`, `PLATE`) for the shaders that read them.
pub fn kind_constants() -> String {
    format!("const WALL: f32 = {:?};\nconst PLATE: f32 = {:?};\n", CellKind::Wall.code(), CellKind::Plate.code())
}

/// A point dipper: centre (m) at time 0, radius (m), phase (rad) against the others, how much
/// faster it runs than the set frequency (Hz), and the velocity it moves with (m/s, x and z)
/// for `travel` (m), after which it starts again (a dipper at rest has no velocity).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dipper {
    pub x: f32,
    pub z: f32,
    pub radius: f32,
    pub phase: f32,
    pub detune: f32,
    /// Its amplitude as a share of the set amplitude.
    pub amplitude: f32,
    pub velocity: [f32; 2],
    pub travel: f32,
}

impl Dipper {
    /// A dipper standing at (x, z) (m).
    pub fn at(x: f32, z: f32, radius: f32) -> Self {
        Self { x, z, radius, phase: 0.0, detune: 0.0, amplitude: 1.0, velocity: [0.0; 2], travel: 0.0 }
    }

    /// Its centre (m) at time `t` (s).
    pub fn centre_at(&self, t: f64) -> (f32, f32) {
        let speed = (self.velocity[0].hypot(self.velocity[1])) as f64;
        if speed == 0.0 {
            return (self.x, self.z);
        }
        let s = (t % (self.travel as f64 / speed)) as f32;
        (self.x + self.velocity[0] * s, self.z + self.velocity[1] * s)
    }
}

/// A straight bar dipper along x at `z` (m), `half_thickness` (m) to either side of it, from
/// -`half_length` to `half_length` (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bar {
    pub z: f32,
    pub half_thickness: f32,
    pub half_length: f32,
}

/// What drives the waves: point dippers, or a bar, all at one frequency and amplitude.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Sources {
    pub dippers: Vec<Dipper>,
    pub bar: Option<Bar>,
}

/// The reflection set-up's parabolic wall: its focal length as a share of the tray's side.
pub const PARABOLA_FOCAL_SHARE: f32 = 0.2;
/// The prism set-up's angle between its faces (°).
pub const PRISM_ANGLE: f32 = 30.0;
/// The standing-wave set-up's wall across the tray: where it stands (z as a share of the side).
pub const STANDING_WALL_SHARE: f32 = 0.15;

/// The lens set-up's plate: two circular arcs of `radius` (m) meeting `thickness` (m) apart
/// on the tray's axis (x = 0), around z = `centre` (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lens {
    pub radius: f32,
    pub thickness: f32,
    pub centre: f32,
}

impl Lens {
    /// The lens of a tray of side `size` (m): about 0.2 m across in the default tray, thin
    /// enough that rays near its rim still leave it (a focus 0.16 to 0.21 m behind it).
    pub fn of(size: f32) -> Self {
        Self { radius: 0.5 * size, thickness: 0.06 * size, centre: -0.15 * size }
    }
}

/// The tray's cells: `cells` x `cells` over a square of side `size` (m); cell (i, j) has its
/// centre at x = -size/2 + (i + 0.5) dx, z = -size/2 + (j + 0.5) dx.
#[derive(Clone, Debug, PartialEq)]
pub struct Medium {
    pub cells: u32,
    pub size: f32,
    /// The open tray's water depth (m).
    pub depth: f32,
    /// Per cell: c² (m²/s², 0 in a wall), the beach's damping rate (1/s), the kind's code, 0.
    pub texels: Vec<[f32; 4]>,
    pub sources: Sources,
    /// The slits of a slit set-up: the barrier's z (m), their number, width and spacing (m).
    pub slits: Option<Slits>,
}

/// A barrier's slits: the barrier's line z (m), how many (one or two), each one's width (m)
/// and the distance between two slits' centres (m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slits {
    pub z: f32,
    pub count: u32,
    pub width: f32,
    pub spacing: f32,
}

impl Slits {
    /// The directions (rad from the barrier's normal, towards +x) of the lines a lesson draws
    /// from between the slits: for two slits the bright ones, d sin θ = m λ; for one the dark
    /// ones, w sin θ = m λ (m ≠ 0); those that exist for wavelength `lambda` (m).
    pub fn directions(&self, lambda: f32) -> Vec<f32> {
        let (first, step) = if self.count == 2 { (0, self.spacing) } else { (1, self.width) };
        (first..)
            .map(|m| m as f32 * lambda / step)
            .take_while(|s| *s < 1.0)
            .flat_map(|s| if s == 0.0 { vec![0.0] } else { vec![-s.asin(), s.asin()] })
            .collect()
    }
}

impl Medium {
    /// An open tray of water `depth` deep, with beaches along its walls if `beaches`.
    pub fn open(cells: u32, size: f32, depth: f32, beaches: bool) -> Self {
        let c2 = GRAVITY * depth;
        let beach = BEACH_SHARE * size;
        let rate = BEACH_STRENGTH * c2.sqrt() / beach;
        let mut medium = Self { cells, size, depth, texels: Vec::new(), sources: Sources::default(), slits: None };
        medium.texels = (0..cells * cells)
            .map(|k| {
                let (x, z) = medium.centre(k % cells, k / cells);
                let from_wall = 0.5 * size - x.abs().max(z.abs());
                let t = if beaches { (1.0 - from_wall / beach).max(0.0) } else { 0.0 };
                [c2, TANK_DAMPING + rate * t * t, CellKind::Water.code(), 0.0]
            })
            .collect();
        medium
    }

    /// The tray of `settings` with its set-up's barriers, plates and sources.
    pub fn of(settings: &TankSettings, cells: u32) -> Self {
        let mut m = Self::open(cells, settings.size, settings.depth, settings.beaches);
        let (l, dx) = (settings.size, m.dx());
        let bar_z = -0.5 * l + BEACH_SHARE * l + 2.0 * dx;
        let barrier_z = bar_z + 0.12 * l;
        // Two slits stay apart: each at most 80 % of their spacing wide.
        let (w, s) = (settings.slit_width, settings.slit_spacing);
        let w = if settings.setup == Setup::DoubleSlit { w.min(0.8 * s) } else { w };
        let radius = DIPPER_RADIUS.max(DIPPER_MIN_CELLS * dx);
        let dipper = |x: f32, z: f32| Dipper::at(x, z, radius);
        match settings.setup {
            Setup::Dipper => m.sources.dippers.push(dipper(0.0, 0.0)),
            Setup::TwoDippers => {
                // A row along x, the spacing apart, each lagging its −x neighbour by the step.
                let n = settings.dippers.clamp(1, MAX_DIPPERS as u32);
                m.sources.dippers.extend((0..n).map(|k| {
                    let x = (k as f32 - 0.5 * (n - 1) as f32) * s;
                    let (phase, detune) = (-(k as f32) * settings.phase_step, k as f32 * settings.detune);
                    Dipper { phase, detune, amplitude: settings.amplitude_ratio.powi(k as i32), ..dipper(x, 0.0) }
                }));
            }
            Setup::Doppler => {
                // Across the middle of the open water, then again from the start.
                let start = -0.5 * l + BEACH_SHARE * l;
                let travel = l - 2.0 * BEACH_SHARE * l;
                let moving = Dipper { velocity: [settings.source_speed, 0.0], travel, ..dipper(start, 0.0) };
                // At rest it stands in the middle.
                m.sources.dippers.push(if settings.source_speed > 0.0 { moving } else { dipper(0.0, 0.0) });
            }
            // The bar spans the tray: its ends, in the side beaches, send no slanting waves across.
            _ => m.sources.bar = Some(Bar { z: bar_z, half_thickness: dx, half_length: 0.5 * l }),
        }
        match settings.setup {
            Setup::SingleSlit => {
                m.barrier(barrier_z, 2.0 * dx, |x| x.abs() < 0.5 * w);
                m.slits = Some(Slits { z: barrier_z, count: 1, width: w, spacing: 0.0 });
            }
            Setup::DoubleSlit => {
                m.barrier(barrier_z, 2.0 * dx, |x| (x.abs() - 0.5 * s).abs() < 0.5 * w);
                m.slits = Some(Slits { z: barrier_z, count: 2, width: w, spacing: s });
            }
            Setup::Refraction => {
                // The plate's straight edge crosses the middle at 30° to the bar.
                let slope = 30f32.to_radians().tan();
                m.paint(|x, z| (z > -0.05 * l + slope * x).then_some(CellKind::Plate));
            }
            Setup::Reflection => {
                // A parabolic wall facing the bar, its focus in the open water before it.
                let (vertex, focal) = (0.5 * l - BEACH_SHARE * l - 0.03 * l, PARABOLA_FOCAL_SHARE * l);
                let thickness = 2.5 * dx;
                m.paint(|x, z| {
                    let on_curve = (z - (vertex - x * x / (4.0 * focal))).abs() < 0.5 * thickness;
                    (on_curve && x.abs() < 0.35 * l).then_some(CellKind::Wall)
                });
            }
            Setup::Standing => m.barrier(STANDING_WALL_SHARE * l, 2.0 * dx, |_| false),
            Setup::Prism => {
                // A right-angled prism: the waves enter its face parallel to the bar and leave
                // by its slanting face (at PRISM_ANGLE to the first), turned aside.
                let (base, side) = (-0.1 * l, 0.5 * l);
                let slope = PRISM_ANGLE.to_radians().tan();
                m.paint(|x, z| {
                    let inside = z > base && x.abs() < 0.5 * side && z < base + slope * (x + 0.5 * side);
                    inside.then_some(CellKind::Plate)
                });
            }
            Setup::Lens => {
                let Lens { radius: r, thickness: t, centre: zc } = Lens::of(l);
                let inside = |x: f32, z: f32, cz: f32| x * x + (z - cz) * (z - cz) < r * r;
                m.paint(|x, z| {
                    (inside(x, z, zc + r - 0.5 * t) && inside(x, z, zc - r + 0.5 * t)).then_some(CellKind::Plate)
                });
            }
            _ => {}
        }
        debug_assert!(m.sources.dippers.len() <= MAX_DIPPERS);
        m
    }

    /// Cell size (m).
    pub fn dx(&self) -> f32 {
        self.size / self.cells as f32
    }

    /// Centre of cell (i, j) (m).
    pub fn centre(&self, i: u32, j: u32) -> (f32, f32) {
        let dx = self.dx();
        (-0.5 * self.size + (i as f32 + 0.5) * dx, -0.5 * self.size + (j as f32 + 0.5) * dx)
    }

    /// The cell holding point (x, z) (m), if in the tray.
    pub fn cell_at(&self, x: f32, z: f32) -> Option<(u32, u32)> {
        let f = |v: f32| ((v + 0.5 * self.size) / self.dx()).floor();
        let (i, j) = (f(x), f(z));
        let n = self.cells as f32;
        (i >= 0.0 && j >= 0.0 && i < n && j < n).then_some((i as u32, j as u32))
    }

    pub fn kind(&self, i: u32, j: u32) -> CellKind {
        match self.texels[(j * self.cells + i) as usize][2] as u32 {
            1 => CellKind::Wall,
            2 => CellKind::Plate,
            _ => CellKind::Water,
        }
    }

    /// What the update reads per cell: c² (m²/s²) of its east face (+x) and of its north face
    /// (+z), each the mean of its two cells' (0 into a wall or out of the tray), the beach's
    /// damping rate (1/s) and the kind's code.
    pub fn faces(&self) -> Vec<[f32; 4]> {
        let n = self.cells;
        let at = |i: u32, j: u32| self.texels[(j * n + i) as usize];
        let face = |a: [f32; 4], b: [f32; 4]| {
            if a[2] == CellKind::Wall.code() || b[2] == CellKind::Wall.code() {
                0.0
            } else {
                0.5 * (a[0] + b[0])
            }
        };
        (0..n * n)
            .map(|k| {
                let (i, j) = (k % n, k / n);
                let m = at(i, j);
                let east = if i + 1 < n { face(m, at(i + 1, j)) } else { 0.0 };
                let north = if j + 1 < n { face(m, at(i, j + 1)) } else { 0.0 };
                [east, north, m[1], m[2]]
            })
            .collect()
    }

    /// The fastest wave speed in the tray (m/s).
    pub fn fastest(&self) -> f32 {
        self.texels.iter().map(|t| t[0]).fold(0.0, f32::max).sqrt()
    }

    /// Makes each cell whose centre `kind_at` gives a kind that kind (a plate leaves
    /// [`PLATE_DEPTH_SHARE`] of the depth over it; a wall none).
    pub fn paint(&mut self, kind_at: impl Fn(f32, f32) -> Option<CellKind>) {
        self.paint_within((0, 0), (self.cells, self.cells), kind_at);
    }

    /// [`Medium::paint`] over the cells from `first` to before `last` (i, j) only.
    fn paint_within(&mut self, first: (u32, u32), last: (u32, u32), kind_at: impl Fn(f32, f32) -> Option<CellKind>) {
        let plate_c2 = GRAVITY * self.depth * PLATE_DEPTH_SHARE;
        for j in first.1..last.1.min(self.cells) {
            for i in first.0..last.0.min(self.cells) {
                let (x, z) = self.centre(i, j);
                let Some(kind) = kind_at(x, z) else { continue };
                let texel = &mut self.texels[(j * self.cells + i) as usize];
                texel[0] = match kind {
                    CellKind::Water => GRAVITY * self.depth,
                    CellKind::Wall => 0.0,
                    CellKind::Plate => plate_c2,
                };
                texel[2] = kind.code();
            }
        }
    }

    /// Paints `kind` (a wall, or open water) on the cells within the pen's radius of the
    /// segment from `a` to `b` (m): a stroke of the pointer's wall tool.
    pub fn stroke(&mut self, a: (f32, f32), b: (f32, f32), kind: CellKind) {
        let radius = super::PEN_RADIUS.max(super::PEN_MIN_CELLS * self.dx());
        let (ab, length2) = ((b.0 - a.0, b.1 - a.1), (b.0 - a.0).powi(2) + (b.1 - a.1).powi(2));
        // Only the cells round the segment: a drag paints many short strokes.
        let index = |v: f32| ((v + 0.5 * self.size) / self.dx()).clamp(0.0, self.cells as f32) as u32;
        let first = (index(a.0.min(b.0) - radius).saturating_sub(1), index(a.1.min(b.1) - radius).saturating_sub(1));
        let last = (index(a.0.max(b.0) + radius) + 2, index(a.1.max(b.1) + radius) + 2);
        self.paint_within(first, last, |x, z| {
            let t = if length2 > 0.0 { (((x - a.0) * ab.0 + (z - a.1) * ab.1) / length2).clamp(0.0, 1.0) } else { 0.0 };
            let (dx, dz) = (x - a.0 - t * ab.0, z - a.1 - t * ab.1);
            (dx * dx + dz * dz <= radius * radius).then_some(kind)
        });
    }

    /// A barrier across the tray: the cells within `thickness` / 2 of line z = `z` (m), except
    /// where `open(x)` leaves a gap.
    pub fn barrier(&mut self, z: f32, thickness: f32, open: impl Fn(f32) -> bool) {
        self.paint(|x, cz| ((cz - z).abs() < 0.5 * thickness && !open(x)).then_some(CellKind::Wall));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_double_slit_leaves_two_gaps_of_the_slit_width_in_its_barrier() {
        let settings = TankSettings { setup: Setup::DoubleSlit, ..Default::default() };
        let m = Medium::of(&settings, 256);
        let row = (0..m.cells).find(|&j| (0..m.cells).any(|i| m.kind(i, j) == CellKind::Wall)).unwrap();
        let open: Vec<u32> = (0..m.cells).filter(|&i| m.kind(i, row) != CellKind::Wall).collect();
        let gaps = open.windows(2).filter(|w| w[1] != w[0] + 1).count() + 1;
        let width = open.len() as f32 * m.dx() / 2.0;
        println!("gaps {gaps}, each {:.1} mm wide (asked {:.1})", width * 1e3, settings.slit_width * 1e3);
        assert_eq!(gaps, 2);
        assert!((width - settings.slit_width).abs() <= m.dx());
    }

    #[test]
    fn the_slits_lines_are_the_bright_directions_of_two_slits_and_the_dark_ones_of_one() {
        let two = Slits { z: 0.0, count: 2, width: 0.02, spacing: 0.09 };
        let lambda = 0.0313;
        let angles = two.directions(lambda);
        println!("two slits: {:?}°", angles.iter().map(|a| a.to_degrees()).collect::<Vec<_>>());
        assert_eq!(angles.len(), 5, "m = 0, ±1, ±2 (3 λ > d)");
        assert!(angles
            .iter()
            .all(|a| ((two.spacing * a.sin() / lambda) - (two.spacing * a.sin() / lambda).round()).abs() < 1e-4));
        let one = Slits { count: 1, width: 0.05, ..two };
        let dark = one.directions(lambda);
        assert_eq!(dark.len(), 2, "m = ±1 only: no line straight ahead");
        assert!((dark[1].sin() * one.width - lambda).abs() < 1e-6);
    }
}
