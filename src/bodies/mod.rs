//! The floating bodies as one table of kinds: what each is made of (hull ellipsoids, density,
//! centre of mass), where it starts, where the water is sampled for it, how a ray picks it,
//! and its parameters. The demo keeps one [`Body`] per kind and loops over the table; the
//! `objects` parameter says which are in the pool (bit `i` for kind `i`).

pub mod ball;
pub mod duck;
pub mod sphere;

use glam::Vec3;

use crate::param_spec::{Control, ParamSpec};
use crate::physics::{Ellipsoid, FloatingBody, Pose};
use crate::sim::{HullMove, HullSlot, MAX_HULL_MOVES, MAX_PROBES};

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
    /// The body as the renderer draws it, from its pose and parameters.
    pub drawn: fn(&Pose, Values) -> BodyView,
    /// Radius (m) of a ball around the drawn body's position holding all of it.
    pub bound: fn(&BodyView) -> f32,
    /// Its share of the scene uniform's `bodies` array (vec4s).
    pub uniform_slots: usize,
    /// Writes its share (`uniform_slots` vec4s) for the drawn body, or for none in the pool.
    pub uniform: fn(Option<&BodyView>, &mut [[f32; 4]]),
    /// Its mesh, drawn with `vs_<name>` and `fs_<name>` of its WGSL.
    pub mesh: fn() -> BodyMesh,
    /// The mesh its outline's pass (`edge`) grows to cover the pixels its outline crosses, with
    /// the same vertex layout: coarser, as only its fragments near the outline do any work.
    pub outline_mesh: fn() -> BodyMesh,
    /// The mesh's vertex layout and stride (bytes).
    pub vertex: &'static [wgpu::VertexAttribute],
    pub vertex_stride: u64,
    /// Its WGSL: `<name>_hit` (an `ObjectHit`, with how far the ray passes outside it: its
    /// `gap`, m, smooth across its outline), `<name>_light` (what it lets through along a segment),
    /// `<name>_shade` (its colour at a point; `direct`: seen directly, not in a traced ray),
    /// `<name>_occlusion`, `<name>_field` (signed distance from its hull, m: negative inside; for a hull of several parts a bound of it) and the mesh's `vs_<name>`, `fs_<name>`; it reads its
    /// uniform at `<NAME>_SLOT`.
    pub wgsl: &'static str,
    /// WGSL its code reads, written from Rust: constants, and code generated from its tables
    /// (the duck's parts written out).
    pub wgsl_constants: fn() -> String,
    /// Whether its WGSL has `vs_<name>_edge` and `fs_<name>_edge`: its outline drawn again
    /// after everything else, blended by the share of each pixel it covers (anti-aliasing).
    pub edge: bool,
    /// Whether its part under the water reaches out past its part above (it floats low): the
    /// open sea's water shows that part through its surface (`hit_bodies_below`). A body
    /// floating high hides it under itself, and tracing it would cost without showing.
    pub seen_below: bool,
}

/// A body as the renderer draws it: where (its pose; the sphere's kept inside the pool), its
/// size parameter where it has one (m; 0 otherwise), and how many times larger than its kind's
/// own frame it is drawn (1 in the pool; the open sea holds the bodies enlarged).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodyView {
    pub pose: Pose,
    pub size: f32,
    pub scale: f32,
}

impl BodyView {
    /// Drawn at its own size at `pose`.
    pub fn at(pose: Pose, size: f32) -> Self {
        Self { pose, size, scale: 1.0 }
    }

    /// The same body `factor` times larger about the world's origin: its place, its size and
    /// its frame (a body of a world `factor` times the pool's).
    pub fn enlarged(self, factor: f32) -> Self {
        let pose = Pose { position: self.pose.position * factor, rotation: self.pose.rotation };
        Self { pose, size: self.size * factor, scale: self.scale * factor }
    }
}

/// A kind's mesh: vertex bytes (laid out as [`BodyKind::vertex`] says) and triangle indices.
pub struct BodyMesh {
    pub vertices: Vec<u8>,
    pub indices: Vec<u32>,
}

/// Every kind, in the order of their bits in `objects` and of their parameters in the table.
pub const KINDS: [BodyKind; 3] = [sphere::KIND, duck::KIND, ball::KIND];

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

/// Vec4s of the scene uniform's `bodies` array: every kind's share.
pub const UNIFORM_SLOTS: usize = {
    let mut n = 0;
    let mut i = 0;
    while i < KINDS.len() {
        n += KINDS[i].uniform_slots;
        i += 1;
    }
    n
};

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

    /// Adds to `moves` how its `hull` moved since the water last took it in, if it moved
    /// enough to push the water ([`HullSlot::moved_from`]), and records where it is now. The
    /// first time it only records its place.
    pub fn take_moves(&mut self, hull: &[Ellipsoid], moves: &mut Vec<HullMove>) {
        let current: Vec<HullSlot> = hull.iter().map(|e| e.hull_slot(&self.motion.pose)).collect();
        if let Some(previous) = &self.pushed {
            if !previous.iter().zip(&current).any(|(before, now)| now.moved_from(before)) {
                return;
            }
            moves.extend(previous.iter().zip(&current).map(|(&from, &to)| HullMove { from, to }));
        }
        self.pushed = Some(current);
    }
}

/// Radius (m) of the ring on which a body feels waves that move on their own (the pool's
/// ambient waves, the sea's cascades): about the duck's and a small sphere's waterline.
pub const AMBIENT_RING_RADIUS: f32 = 0.05;

/// Height (m) of a round body's centre (`radius` m, `density` kg/m³) floating at rest on calm
/// water at the rest level (`Shape::floating_height`): where the sphere and the ball start.
pub fn ball_floating_height(radius: f32, density: f32) -> f32 {
    let hull = [Ellipsoid { centre: Vec3::ZERO, radii: Vec3::splat(radius) }];
    crate::physics::Shape { hull: &hull, centre_of_mass: Vec3::ZERO, density, scale: 1.0 }.floating_height(0.0)
}

/// `PROBES_PER_BODY` points on a ring of `radius` (m) round `centre`: where the water is read
/// for a body's buoyancy.
pub fn ring(centre: glam::Vec2, radius: f32) -> impl Iterator<Item = glam::Vec2> {
    (0..PROBES_PER_BODY).map(move |i| {
        let a = std::f32::consts::TAU * i as f32 / PROBES_PER_BODY as f32;
        centre + radius * glam::Vec2::new(a.cos(), a.sin())
    })
}

/// Pushes every two of the `shown` bodies apart where their bumping balls (radii `bump`, m, by
/// kind) overlap, the lighter more (`mass`, kg; infinite for one held in place).
pub fn bump_apart(bodies: &mut [Body], shown: &[BodyId], bump: &[f32], mass: &dyn Fn(BodyId) -> f32) {
    for (i, &a) in shown.iter().enumerate() {
        for &b in &shown[i + 1..] {
            let (first, second) = bodies.split_at_mut(b.0);
            let (a_motion, b_motion) = (&mut first[a.0].motion, &mut second[0].motion);
            crate::physics::separate(a_motion, bump[a.0], mass(a), b_motion, bump[b.0], mass(b));
        }
    }
}

/// Any set of the kinds, as a choice: bit `i` of its value for kind `i` (the pool's `objects`,
/// the open sea's `sea_objects`).
pub const OBJECT_CHOICES: Control = Control::Choice {
    values: &[0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0],
    names: &["none", "sphere", "duck", "both", "ball", "sphere,ball", "duck,ball", "all"],
};

/// The parameters of the kinds of body (their size and density), read wherever they float.
pub fn kind_params() -> impl Iterator<Item = &'static str> {
    KINDS.iter().flat_map(|k| k.params.iter().map(|p| p.name))
}

/// Which bodies float in the pool. (The parameter table, `params::table`, lists it first of
/// the Objects group; the kinds' own parameters follow.)
pub const PARAMS: &[ParamSpec] = &[ParamSpec {
    name: "objects",
    label: "Objects",
    group: "Objects",
    unit: "",
    control: OBJECT_CHOICES,
    default: 3.0,
    help: "What floats in the pool: any of the sphere, a rubber duck and a beach ball (as a list, e.g. sphere,duck), all or none.",
}];

/// The share of a pixel a water surface covers next to the bodies, for any scene's water
/// (the pool's, the sea's): negative inside a hull (not drawn); at a traced kind's waterline
/// the share within the pixel's footprint of its hull, where the eye's ray meets the hull behind
/// (the water's pipeline blends it over the body drawn before); 1 elsewhere.
const WATER_SHARE: &str = "
fn water_share(p: vec3<f32>, eye: vec3<f32>, dir: vec3<f32>, footprint: f32) -> f32 {
    let field = bodies_field(p);
    if (field.x < 0.0) {
        return -1.0;
    }
    // output.z 0: each pixel wholly in or out (the outlines off, for tests to compare with).
    let share = select(1.0, clamp(field.y / max(footprint, 1.0e-6), 0.0, 1.0), scene.output.z > 0.0);
    // Where the eye's ray passes by the hull (its outline meets the waterline) nothing of the
    // body lies behind to blend with: the pixel is the water's.
    if (share < 1.0 && hit_bodies(eye, dir).t >= NO_HIT) {
        return 1.0;
    }
    return share;
}
";

/// The bodies' WGSL for a scene pass showing the kinds in `present` (bits of [`KINDS`]): per
/// kind `HAS_<NAME>` (false compiles its tracing away), its uniform slot and its code; then
/// the code that asks every kind present: the nearest hit (`hit_bodies`, with the least of
/// the kinds' gaps; `hit_bodies_below`, of the kinds `seen_below`, with `HAS_BODIES_BELOW`), its colour
/// (`body_colour`), the light they let through (`objects_visibility`) and the ambient light
/// they take from a point (`bodies_occlusion`) and the signed distance from the nearest hull
/// (`bodies_field`: x any kind's, the water's surface is not drawn inside one; y of the kinds
/// drawn as traced (`edge`), whose waterline the water fades out at) and `water_share`, what a water surface covers of a pixel.
pub fn wgsl(present: u32) -> String {
    let mut out = format!(
        "const BODY_SLOTS: u32 = {UNIFORM_SLOTS}u;\nconst HAS_BODIES: bool = {};\n",
        present & ((1 << KINDS.len()) - 1) != 0
    );
    let mut slot = 0;
    for (i, kind) in KINDS.iter().enumerate() {
        let upper = kind.name.to_uppercase();
        let has = present & (1 << i) != 0;
        out += &format!(
            "const HAS_{upper}: bool = {has};\nconst {upper}_SLOT: i32 = {slot};\nconst {upper}_KIND: i32 = {i};\n"
        );
        out += &(kind.wgsl_constants)();
        out += kind.wgsl;
        slot += kind.uniform_slots;
    }
    let each = |line: &dyn Fn(&str, &str) -> String| -> String {
        KINDS.iter().map(|k| line(k.name, &k.name.to_uppercase())).collect()
    };
    out += "\nstruct BodyHit {\n    t: f32,\n    kind: i32,\n    normal: vec3<f32>,\n    albedo: vec3<f32>,\n    gap: f32,\n};\n";
    // The nearest hit of every kind present, and of those of them seen below the water.
    out += &format!(
        "const HAS_BODIES_BELOW: bool = {};\n",
        KINDS.iter().enumerate().any(|(i, k)| k.seen_below && present & (1 << i) != 0)
    );
    for (function, only_below) in [("hit_bodies", false), ("hit_bodies_below", true)] {
        let kinds: String = KINDS
            .iter()
            .filter(|k| k.seen_below || !only_below)
            .map(|k| {
                let (name, upper) = (k.name, k.name.to_uppercase());
                format!("    if (HAS_{upper}) {{\n        let h = {name}_hit(origin, dir);\n        let gap = min(best.gap, h.gap);\n        if (h.t < best.t) {{\n            best = BodyHit(h.t, {upper}_KIND, h.normal, h.albedo, 0.0);\n        }}\n        best.gap = gap;\n    }}\n")
            })
            .collect();
        out += &format!(
            "fn {function}(origin: vec3<f32>, dir: vec3<f32>) -> BodyHit {{\n    var best = BodyHit(NO_HIT, -1, vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(0.0), NO_HIT);\n{kinds}    return best;\n}}\n"
        );
    }
    out += &format!(
        "fn body_colour(hit: BodyHit, p: vec3<f32>, dir: vec3<f32>, under: bool) -> vec3<f32> {{\n{}    return vec3<f32>(0.0);\n}}\n",
        each(&|name, upper| format!(
            "    if (HAS_{upper} && hit.kind == {upper}_KIND) {{\n        return {name}_shade(p, hit.normal, hit.albedo, dir, under, false);\n    }}\n"
        ))
    );
    out += &format!(
        "fn objects_visibility(p: vec3<f32>, dir: vec3<f32>, t_max: f32, t_lit: f32) -> f32 {{\n    var light = 1.0;\n{}    return light;\n}}\n",
        each(&|name, upper| format!("    if (HAS_{upper}) {{\n        light *= {name}_light(p, dir, t_max, t_lit);\n    }}\n"))
    );
    out += &format!(
        "fn bodies_field(p: vec3<f32>) -> vec2<f32> {{\n    var d = vec2<f32>(NO_HIT);\n{}    return d;\n}}\n",
        KINDS
            .iter()
            .map(|k| {
                let (name, upper) = (k.name, k.name.to_uppercase());
                let exact = if k.edge { format!("        d.y = min(d.y, {name}_field(p));\n") } else { String::new() };
                format!("    if (HAS_{upper}) {{\n        d.x = min(d.x, {name}_field(p));\n{exact}    }}\n")
            })
            .collect::<String>()
    );
    out += WATER_SHARE;
    out += &format!(
        "fn bodies_occlusion(p: vec3<f32>, n: vec3<f32>) -> f32 {{\n    var o = 0.0;\n{}    return o;\n}}\n",
        each(&|name, upper| format!("    if (HAS_{upper}) {{\n        o += {name}_occlusion(p, n);\n    }}\n"))
    );
    out
}
