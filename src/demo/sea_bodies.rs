//! The floating bodies in the open sea: the pool's kinds, each enlarged as the sea's patch is
//! ([`sea::patch_scale`]: against a patch that much wider than the pool a body looks as it
//! does there, and floats as high). They ride the cascades' waves (read from the frame's
//! lattices on the CPU) plus the patch's ripples, and push the patch's water as they heave and
//! drift: their wakes run out across it and fade in its absorbing border. They keep over the
//! patch's calm middle, inside that border.

use glam::{Vec2, Vec3};

use super::{WaterDemo, STEP_DT};
use crate::bodies::{Body, BodyId, BodyView, KINDS, PROBES_PER_BODY};
use crate::params::ParamId;
use crate::physics::{Bounds, Ellipsoid, FloatingBody, Pose, Shape, WaterPlane};
use crate::sea;
use crate::sim::{BodyCoupling, SPONGE_WIDTH};

/// The box the sea's bodies keep in (m): the pool's enlarged with the patch, inside the patch's
/// absorbing border (where the water would swallow their pushes).
pub fn sea_bounds() -> Bounds {
    let (s, pool) = (sea::patch_scale(), Bounds::pool());
    let inner = sea::PATCH_HALF_WIDTH - SPONGE_WIDTH * s;
    Bounds { least: Vec3::new(-inner, pool.least.y * s, -inner), most: Vec3::new(inner, pool.most.y * s, inner) }
}

/// `PROBES_PER_BODY` points on a ring of `radius` (m) round `centre`: where the water is read
/// for a body's buoyancy.
pub(super) fn ring(centre: Vec2, radius: f32) -> impl Iterator<Item = Vec2> {
    (0..PROBES_PER_BODY).map(move |i| {
        let a = std::f32::consts::TAU * i as f32 / PROBES_PER_BODY as f32;
        centre + radius * Vec2::new(a.cos(), a.sin())
    })
}

impl WaterDemo {
    /// Every kind's hull in the sea: its ellipsoids enlarged (in its own frame, m).
    fn sea_hulls(&self) -> Vec<Vec<Ellipsoid>> {
        let s = sea::patch_scale();
        BodyId::all().map(|id| self.hull(id).into_iter().map(|e| e.scaled(s)).collect()).collect()
    }

    /// Every body at its start in the sea: the pool's start enlarged, upright at its floating
    /// height (the pool's, enlarged: a body that much larger floats as much higher).
    pub(super) fn sea_bodies_at_start(&self) -> Vec<Body> {
        let s = sea::patch_scale();
        BodyId::all()
            .map(|id| {
                let value = |name: &str| self.value(name);
                let start = (id.kind().start)(&value);
                let hull = self.hull(id);
                let shape = Shape {
                    hull: &hull,
                    centre_of_mass: id.kind().centre_of_mass,
                    density: (id.kind().density)(&value),
                };
                let at = Vec3::new(start.position.x, shape.floating_height(0.0), start.position.z) * s;
                Body::at(Pose { position: at, rotation: start.rotation })
            })
            .collect()
    }

    /// Moves the sea's bodies through `steps` fixed steps on the water under them: the waves of
    /// this frame (`layers`, `SeaWaves::layers`) and the patch's ripples as the frame starts
    /// (its probes, sampled last frame on the rings then). Then tells the patch how their
    /// hulls moved in each step, to push its water by, and where to sample it for next frame.
    pub(super) fn step_sea_bodies(&mut self, steps: u32, layers: [&[[f32; 4]]; 2]) {
        let s = sea::patch_scale();
        let shown: Vec<BodyId> = BodyId::all().filter(|&id| self.shows(id)).collect();
        let hulls = self.sea_hulls();
        let value = |name: &str| self.value(name);
        let shapes: Vec<Shape> = BodyId::all()
            .map(|id| Shape {
                hull: &hulls[id.0],
                centre_of_mass: id.kind().centre_of_mass * s,
                density: (id.kind().density)(&value),
            })
            .collect();
        let rings: Vec<f32> = BodyId::all().map(|id| (id.kind().probe_ring)(&value) * s).collect();
        let bump: Vec<f32> = BodyId::all().map(|id| (id.kind().bump_radius)(&value) * s).collect();
        let gravity = self.params.flag(ParamId::Gravity);
        let Some(sea) = self.sea.as_mut() else { return };
        let planes: Vec<WaterPlane> = BodyId::all()
            .map(|id| {
                let p = sea.bodies[id.0].motion.pose.position;
                let ripples =
                    sea.patch.probes().and_then(|r| r.heights.get(id.0 * PROBES_PER_BODY..)?.get(..PROBES_PER_BODY));
                let heights: Vec<f32> = ring(Vec2::new(p.x, p.z), rings[id.0])
                    .enumerate()
                    .map(|(i, q)| sea.waves.height_on(layers, q.x, q.y) + ripples.map_or(0.0, |r| r[i]))
                    .collect();
                WaterPlane::from_ring(&heights, rings[id.0])
            })
            .collect();
        let bounds = sea_bounds();
        let mut moves = Vec::with_capacity(steps as usize);
        for _ in 0..steps {
            for &id in &shown {
                let body = &mut sea.bodies[id.0];
                body.submerged = body.motion.step(&shapes[id.0], gravity, &planes[id.0], STEP_DT, &bounds);
            }
            super::bodies::bump_apart(&mut sea.bodies, &shown, &bump, &|id| shapes[id.0].mass());
            let mut step = Vec::new();
            for id in BodyId::all() {
                let body = &mut sea.bodies[id.0];
                bounds.keep(&mut body.motion.pose, &hulls[id.0]);
                if shown.contains(&id) {
                    body.take_moves(&hulls[id.0], &mut step);
                } else {
                    body.pushed = None;
                }
            }
            moves.push(step);
        }
        let probes = BodyId::all()
            .flat_map(|id| {
                let p = sea.bodies[id.0].motion.pose.position;
                ring(Vec2::new(p.x, p.z), rings[id.0])
            })
            .collect();
        // The open sea's level stays: the water a body pushes aside spreads out past the patch.
        sea.patch.set_bodies(BodyCoupling { moves, rest_level: 0.0, probes });
    }

    /// The sea's bodies as the renderer draws them, if shown: each the pool's body at the pose
    /// shrunk into the pool, enlarged back (so its drawing is the pool's, larger).
    pub(super) fn sea_drawn_bodies(&self) -> [Option<BodyView>; KINDS.len()] {
        let s = sea::patch_scale();
        let value = |name: &str| self.value(name);
        std::array::from_fn(|k| {
            let (id, sea) = (BodyId(k), self.sea.as_ref()?);
            let pose = sea.bodies[k].motion.pose;
            let shrunk = Pose { position: pose.position / s, rotation: pose.rotation };
            self.shows(id).then(|| (id.kind().drawn)(&shrunk, &value).enlarged(s))
        })
    }

    /// A body's motion in the sea, once the sea has been drawn (for tests).
    pub fn sea_body(&self, id: BodyId) -> Option<&FloatingBody> {
        self.sea.as_ref().map(|s| &s.bodies[id.0].motion)
    }

    /// Puts a body of the sea somewhere (kept over the patch's middle) and sets it moving at
    /// `velocity` (m/s), once the sea has been drawn (for tests).
    #[doc(hidden)]
    pub fn set_sea_body(&mut self, id: BodyId, position: Vec3, velocity: Vec3) {
        let hull = &self.sea_hulls()[id.0];
        if let Some(sea) = self.sea.as_mut().filter(|_| position.is_finite() && velocity.is_finite()) {
            let motion = &mut sea.bodies[id.0].motion;
            motion.pose.position = position;
            sea_bounds().keep(&mut motion.pose, hull);
            motion.velocity = velocity;
        }
    }
}
