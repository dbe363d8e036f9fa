//! The floating bodies in the open sea: the pool's kinds, each enlarged as the sea's patch is
//! ([`sea::patch_scale`]: against a patch that much wider than the pool a body looks as it
//! does there, and floats as high). They ride the cascades' waves (read from the frame's
//! lattices on the CPU) plus the patch's ripples, and push the patch's water as they heave and
//! drift: their wakes run out across it and fade in its absorbing border. They keep over the
//! patch's calm middle, inside that border.

use glam::{Vec2, Vec3};

use super::{Sea, SeaScene};
use crate::ambient::cascades::SeaNow;
use crate::bodies::{bump_apart, ring, Body, BodyId, BodyView, AMBIENT_RING_RADIUS, KINDS, PROBES_PER_BODY};
use crate::params::{ParamId, Params};
use crate::physics::{Bounds, Ellipsoid, FloatingBody, Pose, Shape, WaterPlane};
use crate::scenes::{Shared, STEP_DT};
use crate::sea;
use crate::sim::{BodyCoupling, SPONGE_WIDTH};

/// The box the sea's bodies keep in (m): the pool's enlarged with the patch, inside the patch's
/// absorbing border (where the water would swallow their pushes).
pub fn sea_bounds() -> Bounds {
    let (s, pool) = (sea::patch_scale(), Bounds::pool(crate::world::PoolShape::CLASSIC));
    let inner = sea::PATCH_HALF_WIDTH - SPONGE_WIDTH * s;
    Bounds { least: Vec3::new(-inner, pool.least.y * s, -inner), most: Vec3::new(inner, pool.most.y * s, inner) }
}

/// Whether a body floats in the sea (its bit in the `sea_objects` parameter).
pub fn in_sea(params: &Params, id: BodyId) -> bool {
    (params.get(ParamId::SeaObjects) as u32) & id.bit() != 0
}

/// Every kind's hull in the sea: its ellipsoids enlarged (in its own frame, m).
fn hulls(sh: Shared<'_>) -> Vec<Vec<Ellipsoid>> {
    let s = sea::patch_scale();
    BodyId::all().map(|id| sh.hull(id).into_iter().map(|e| e.scaled(s)).collect()).collect()
}

/// Every body at its start in the sea: the pool's start enlarged, upright at its floating
/// height (the pool's, enlarged: a body that much larger floats as much higher).
pub(super) fn at_start(sh: Shared<'_>) -> Vec<Body> {
    let s = sea::patch_scale();
    BodyId::all()
        .map(|id| {
            let value = |name: &str| sh.value(name);
            let start = (id.kind().start)(&value);
            let hull = sh.hull(id);
            let shape = Shape {
                hull: &hull,
                centre_of_mass: id.kind().centre_of_mass,
                density: (id.kind().density)(&value),
                scale: 1.0,
            };
            let at = Vec3::new(start.position.x, shape.floating_height(0.0), start.position.z) * s;
            Body::at(Pose { position: at, rotation: start.rotation })
        })
        .collect()
}

impl SeaScene {
    /// Moves the sea's bodies through this frame's `steps` fixed steps (up to fixed step `step`)
    /// on the water under them: the waves at each step, between the last frame's, if it was
    /// drawn where these steps start, and this frame's (`now`, summed on a ring at each body's
    /// waterline and taken linearly between the two: the same heave at any frame rate), and
    /// the patch's ripples as the frame starts (its probes, sampled last
    /// frame on the kinds' wider rings). Then tells the patch how their hulls moved in each
    /// step, to push its water by, and where to sample it for next frame.
    pub(super) fn step_bodies(&mut self, sh: Shared<'_>, (steps, step): (u32, u64), now: &SeaNow) {
        let s = sea::patch_scale();
        let shown: Vec<BodyId> = BodyId::all().filter(|&id| in_sea(sh.params, id)).collect();
        let hulls = hulls(sh);
        let value = |name: &str| sh.value(name);
        let shapes: Vec<Shape> = BodyId::all()
            .map(|id| Shape {
                hull: &hulls[id.0],
                centre_of_mass: id.kind().centre_of_mass * s,
                density: (id.kind().density)(&value),
                scale: s,
            })
            .collect();
        let rings: Vec<f32> = BodyId::all().map(|id| (id.kind().probe_ring)(&value) * s).collect();
        let bump: Vec<f32> = BodyId::all().map(|id| (id.kind().bump_radius)(&value) * s).collect();
        let gravity = sh.params.flag(ParamId::Gravity);
        let held = sh.held;
        let Some(sea) = self.sea.as_mut() else { return };
        // The waves as this frame's steps start: the last frame's, if it drew them at that step
        // (else this frame's at both ends).
        let started = step.checked_sub(steps as u64);
        let before = match &sea.now {
            Some((at, waves)) if Some(*at) == started => waves,
            _ => now,
        };
        let planes: Vec<[WaterPlane; 2]> = BodyId::all()
            .map(|id| {
                if shown.contains(&id) {
                    water_under(sea, id, rings[id.0], [before, now])
                } else {
                    [WaterPlane::flat(0.0); 2]
                }
            })
            .collect();
        let bounds = sea_bounds();
        let mut moves = Vec::with_capacity(steps as usize);
        for k in 1..=steps {
            let along = k as f32 / steps as f32;
            for &id in &shown {
                let ([from, to], body) = (planes[id.0], &mut sea.bodies[id.0]);
                if held == Some(id) {
                    body.motion.hold();
                    continue;
                }
                let plane = WaterPlane {
                    level: from.level + (to.level - from.level) * along,
                    normal: from.normal.lerp(to.normal, along).normalize(),
                };
                body.submerged = body.motion.step(&shapes[id.0], gravity, &plane, STEP_DT, &bounds);
            }
            bump_apart(&mut sea.bodies, &shown, &bump, &|id| {
                if held == Some(id) {
                    f32::INFINITY
                } else {
                    shapes[id.0].mass()
                }
            });
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
    pub(super) fn drawn_bodies(&self, sh: Shared<'_>) -> [Option<BodyView>; KINDS.len()] {
        let s = sea::patch_scale();
        let value = |name: &str| sh.value(name);
        std::array::from_fn(|k| {
            let (id, sea) = (BodyId(k), self.sea.as_ref()?);
            let pose = sea.bodies[k].motion.pose;
            let shrunk = Pose { position: pose.position / s, rotation: pose.rotation };
            in_sea(sh.params, id).then(|| (id.kind().drawn)(&shrunk, &value).enlarged(s))
        })
    }

    /// The nearest of the sea's bodies under pixel `pixel`: its id, the point hit and its
    /// frame's origin (m). Each kind picks its pool body, the ray shrunk into the pool.
    pub(super) fn body_under(&self, sh: Shared<'_>, pixel: Vec2) -> Option<(BodyId, Vec3, Vec3)> {
        let (ray, s) = (self.camera.ray(pixel, sh.viewport), sea::patch_scale());
        let value = |name: &str| sh.value(name);
        let sea = self.sea.as_ref()?;
        let hits = BodyId::all().filter(|&id| in_sea(sh.params, id)).filter_map(|id| {
            let pose = sea.bodies[id.0].motion.pose;
            let shrunk = Pose { position: pose.position / s, rotation: pose.rotation };
            (id.kind().pick)(&shrunk, &value, ray.origin / s, ray.dir).map(|t| (id, t * s, pose.position))
        });
        let (id, t, centre) = hits.min_by(|a, b| a.1.total_cmp(&b.1))?;
        Some((id, ray.origin + ray.dir * t, centre))
    }

    /// A body's motion in the sea, once the sea has been drawn (for tests).
    pub fn body(&self, id: BodyId) -> Option<&FloatingBody> {
        self.sea.as_ref().map(|s| &s.bodies[id.0].motion)
    }

    /// Puts a body of the sea somewhere (kept over the patch's middle) and sets it moving at
    /// `velocity` (m/s), once the sea has been drawn (dragged, and for tests).
    pub fn set_body(&mut self, sh: Shared<'_>, id: BodyId, position: Vec3, velocity: Vec3) {
        let hull = &hulls(sh)[id.0];
        if let Some(sea) = self.sea.as_mut().filter(|_| position.is_finite() && velocity.is_finite()) {
            let motion = &mut sea.bodies[id.0].motion;
            motion.pose.position = position;
            sea_bounds().keep(&mut motion.pose, hull);
            motion.velocity = velocity;
        }
    }
}

/// The water under body `id` of `sea` as the frame's steps start and as they end (`waves` at
/// those moments): the plane of the waves on a ring at its waterline (as the pool's ambient
/// waves), plus the plane of the patch's ripples on its kind's wider `ring` (m), clear of those
/// the body makes itself (the patch's probes, sampled last frame).
fn water_under(sea: &Sea, id: BodyId, ring_radius: f32, waves: [&SeaNow; 2]) -> [WaterPlane; 2] {
    let p = sea.bodies[id.0].motion.pose.position;
    let ripples = sea.patch.probes().and_then(|r| r.heights.get(id.0 * PROBES_PER_BODY..)?.get(..PROBES_PER_BODY));
    let ripples: Vec<f32> = (0..PROBES_PER_BODY).map(|i| ripples.map_or(0.0, |r| r[i])).collect();
    let ripples = WaterPlane::from_ring(&ripples, ring_radius);
    let waterline = AMBIENT_RING_RADIUS * sea::patch_scale();
    waves.map(|waves| {
        let heights: Vec<f32> = ring(Vec2::new(p.x, p.z), waterline).map(|q| waves.height(q.x, q.y)).collect();
        WaterPlane::from_ring(&heights, waterline).plus(ripples)
    })
}
