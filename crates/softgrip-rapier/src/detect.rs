//! Fresh soft contact geometry at the current poses.
//!
//! Candidates come from the broad phase BVH (the fingertip's AABB swept over the step); rapier's
//! narrow phase never computes a fingertip's pairs (its collision groups are `none()`): its
//! manifolds would be one step stale, and its AABB margin misses fast impacts. The geometry is then recomputed with
//! `parry::query::contact(other_pose, other_shape, ball_pose, ball, prediction)`: the other
//! shape goes **first** (parry 0.31 returns a wrong distance for ball-then-halfspace), and the
//! contact's `normal1` then points from the other body to the fingertip. For composite shapes
//! (trimesh, compound, heightfield) parry returns the best single contact, so a ball over a
//! shared edge or vertex gives one contact, never one per triangle.

use nalgebra::Vector3;
use rapier3d::parry::bounding_volume::Aabb;
use rapier3d::parry::query;
use rapier3d::prelude::{
    BroadPhaseBvh, Collider, ColliderHandle, ColliderSet, ImpulseJointSet, InteractionGroups,
    IslandManager, MultibodyJointSet, NarrowPhase, QueryFilter, QueryPipeline, RigidBody,
    RigidBodyHandle, RigidBodySet, Vector,
};

use crate::boundary::{raw, to_f64};
use crate::counters::SoftCounters;
use crate::curvature::{self, Touch};
use crate::fast_hash::FastMap;
use crate::fingertip::SoftFingertip;
use crate::tip_record::TipRecord;

mod held;

pub(crate) use held::{Detected, detect_woken, owner};
use held::{asleep, disturbed};

/// The compression `delta` \[m\] of the law from parry's signed distance `dist` \[m\] (negative =
/// penetration): `delta = -dist`. The one place where the engine's sign convention meets the
/// law's. `delta <= 0` is a gap, which the law reads as "separated".
///
/// ```
/// use softgrip_rapier::compression_from_signed_distance;
/// assert_eq!(compression_from_signed_distance(-0.002), 0.002);
/// assert!(compression_from_signed_distance(0.001) < 0.0);
/// ```
#[inline]
pub fn compression_from_signed_distance(dist: f64) -> f64 {
    -dist
}

/// One soft contact at the current poses.
#[derive(Debug, Clone)]
pub(crate) struct Geom {
    pub tip: ColliderHandle,
    pub other: ColliderHandle,
    pub body_tip: Option<RigidBodyHandle>,
    pub body_other: Option<RigidBodyHandle>,
    /// Contact point, midway between the two surfaces (world) \[m\].
    pub point: Vector3<f64>,
    /// Closest point on the other body's surface (world) \[m\].
    pub point_other: Vector3<f64>,
    /// Unit normal from the other body to the fingertip (world).
    pub normal: Vector3<f64>,
    /// Signed distance \[m\], negative = penetration.
    pub dist: f64,
    /// Key of the law: (tip, other) for soft-soft pairs, else the tip alone.
    pub soft_pair: bool,
    /// What the fingertip touches on a rigid body (`curvature`); a plane for a pair of
    /// fingertips and on a backed fingertip's finger.
    pub touch: Touch,
}

/// Everything the detection reads.
pub(crate) struct Scene<'a> {
    pub bodies: &'a RigidBodySet,
    pub colliders: &'a ColliderSet,
    pub narrow_phase: &'a NarrowPhase,
    pub broad_phase: &'a BroadPhaseBvh,
    /// rapier's islands: the awake bodies (`IslandManager::active_bodies`).
    pub islands: &'a IslandManager,
    /// The fingertips and their collision groups, in handle order.
    pub tip_order: &'a [(ColliderHandle, InteractionGroups)],
    /// The world's gravity magnitude [m/s^2]: what a body at rest gains in speed over the step
    /// bounds its travel too (a ball released just above the ground).
    pub gravity: f32,
    /// The largest registered fingertip radius \[m\] (`disturbed`).
    pub max_radius: f32,
    /// rapier's impulse joints and multibodies: a pair of bodies rapier's narrow phase
    /// filters for their joints is not a soft contact either (`joint_filtered`).
    pub impulse_joints: &'a ImpulseJointSet,
    pub multibody_joints: &'a MultibodyJointSet,
    /// The speed (linear [m/s], angular [rad/s]) the joint motors add to each multibody link
    /// over the step (`multibody::motor_push`), and the share of it this (sub)step takes: a
    /// link's stored velocity is its multibody's now, without the push its motors give it
    /// within rapier's step.
    pub motor_push: (&'a FastMap<RigidBodyHandle, (f32, f32)>, f32),
    /// Pairs of bodies that never touch (`SoftContacts::exclude_pair`).
    pub excluded: &'a crate::excluded::ExcludedPairs,
}

impl Scene<'_> {
    /// The speed [m/s] the joint motors of `body` add over this (sub)step at distance `r`
    /// \[m\] from its centre of mass (0 for a body that is not a motored link).
    fn push_of(&self, body: Option<RigidBodyHandle>, r: f32) -> f32 {
        let (map, scale) = self.motor_push;
        body.and_then(|b| map.get(&b))
            .map_or(0.0, |&(v, w)| (v + w * r) * scale)
    }
}

/// Whether rapier's narrow phase filters every contact between bodies `a` and `b` for the
/// joints that hold them (rapier3d 0.36.1 `geometry/narrow_phase/pair_update.rs`): an impulse
/// joint between them with its contacts disabled (`GenericJoint::contacts_enabled`), two links
/// of one multibody whose self-contacts are off (`Multibody::self_contacts_enabled`: a robot's
/// `self_contacts = false`), or two links joined by a multibody joint with its contacts
/// disabled (a URDF joint's two links, `rapier3d-urdf`'s default). A fingertip's pairs never
/// reach that filter (its collision groups are `none()`), so the plugin applies it: a pad on a
/// finger's link does not press the links its robot keeps from colliding with that link. A
/// pair kept apart by `SoftContacts::exclude_pair` is filtered too.
pub(crate) fn joint_filtered(scene: &Scene<'_>, a: RigidBodyHandle, b: RigidBodyHandle) -> bool {
    if scene.excluded.contains(a, b) {
        return true;
    }
    if (scene.impulse_joints.joints_between(a, b)).any(|(_, j)| !j.data.contacts_enabled) {
        return true;
    }
    let mb = scene.multibody_joints;
    let (Some(la), Some(lb)) = (mb.rigid_body_link(a), mb.rigid_body_link(b)) else {
        return false;
    };
    if la.multibody != lb.multibody {
        return false;
    }
    if (mb.get_multibody(la.multibody)).is_some_and(|m| !m.self_contacts_enabled()) {
        return true;
    }
    (mb.joint_between(a, b)).is_some_and(|(_, _, link)| !link.joint.data.contacts_enabled)
}

/// Finds the soft contacts of every fingertip (`scene.tip_order`; `tips` tells the soft
/// colliders apart), within a prediction distance that
/// covers the step `dt` \[s\], and writes them to `out` (`candidates` is a reused buffer).
///
/// Candidates come from one query of rapier's broad-phase BVH per fingertip, so the cost per
/// fingertip depends on its neighbourhood, not on the scene. The query box is the fingertip's
/// swept AABB grown by the largest prediction distance any pair of this fingertip can have
/// (`0.05 R + 1.5 (|v_tip| + |w_tip| R + v_max + 2 |g| dt) dt`, `v_max` the fastest body of
/// the world, `|g| dt` the speed gravity adds to either side within the step),
/// so it finds every collider whose BVH leaf lies within reach. rapier's narrow-phase pairs
/// (`contact_pairs_with`) are not walked: they are the pairs of the *fattened* leaves
/// (`0.04 length_unit` each, 4 cm at the default length unit: dozens per fingertip in a dense
/// scene), a walk over scattered graph edges that cost more than the rest of the detection, for
/// no candidate within the prediction distance that the query misses. Each candidate's current
/// AABB is then tested against the fingertip's, loosened by the pair's prediction distance (plus
/// 1 % of R of rounding room), before the exact query: the shapes are at least as far apart as
/// their AABBs.
///
/// A fingertip on a sleeping body that no awake body can reach within the step (`disturbed`)
/// is not detected: its contacts are *held* (the caller keeps their readout and memory;
/// `detected` says which fingertips were looked at). Both sides of each of its contacts are
/// immobile (it sleeps only when every contact is with something fixed or asleep, see
/// `bodies::wake_touched`), so its geometry and its law's answer are those of the step it fell
/// asleep in.
///
/// `fastest`: the world's fastest motion ([`fastest_motion`]) if the caller found it at the
/// current state (the step's walk of the body set for the kinematic paths), else found here.
#[allow(clippy::too_many_arguments)]
pub(crate) fn detect(
    scene: &Scene<'_>,
    tips: &FastMap<ColliderHandle, TipRecord>,
    dt: f64,
    fastest: Option<(f32, f32)>,
    out: &mut Vec<Geom>,
    candidates: &mut Vec<(ColliderHandle, f32)>,
    detected: &mut Detected,
    counters: &mut SoftCounters,
) {
    out.clear();
    detected.all = true;
    detected.tips.clear();
    let qp = scene.broad_phase.as_query_pipeline(
        scene.narrow_phase.query_dispatcher(),
        scene.bodies,
        scene.colliders,
        QueryFilter::default(),
    );
    // Found by the caller's walk of the body set when it had one (`fastest`), the same value.
    detected.fastest = fastest.unwrap_or_else(|| fastest_motion(scene.bodies));
    // In handle order: the contacts come out sorted by (fingertip, other).
    for (i, &(tip_h, tip_groups)) in scene.tip_order.iter().enumerate() {
        if asleep(scene, tip_h) {
            if detected.all {
                // The first sleeping fingertip: the ones before it were all detected.
                detected.all = false;
                detected
                    .tips
                    .extend(scene.tip_order[..i].iter().map(|t| t.0));
                disturbed(scene, &qp, tips, dt as f32, &mut detected.disturbed);
            }
            if !detected.disturbed.contains(&tip_h) {
                counters.held_tips += 1;
                continue;
            }
        }
        if !detected.all {
            detected.tips.push(tip_h);
        }
        detect_tip(
            scene,
            &qp,
            tips,
            (tip_h, tip_groups),
            dt,
            detected.fastest,
            candidates,
            out,
            counters,
        );
    }
    // Deterministic order (already sorted: fingertips and candidates in handle order).
    out.sort_by_key(|g| (raw(g.tip), raw(g.other)));
}

/// The contacts of one fingertip (`tip`: its handle and collision groups), pushed to `out` in
/// the handle order of the other colliders; `fastest` is the fastest motion of the world
/// (`fastest_motion`).
#[allow(clippy::too_many_arguments)]
fn detect_tip(
    scene: &Scene<'_>,
    qp: &QueryPipeline<'_>,
    tips: &FastMap<ColliderHandle, TipRecord>,
    (tip_h, tip_groups): (ColliderHandle, InteractionGroups),
    dt: f64,
    (v_max, w_max): (f32, f32),
    candidates: &mut Vec<(ColliderHandle, f32)>,
    out: &mut Vec<Geom>,
    counters: &mut SoftCounters,
) {
    let Some(tip) = Tip::of(scene, tips, tip_h, tip_groups, dt, counters) else {
        return;
    };
    tip.candidates(qp, v_max, w_max, candidates);
    for &(other_h, gap) in candidates.iter() {
        if let Some(g) = tip.contact_with(scene, tips, other_h, gap, counters) {
            out.push(g);
        }
    }
}

/// The largest linear [m/s] and angular [rad/s] speed of any moving body of the world: it
/// bounds the other side's motion in every prediction.
pub(crate) fn fastest_motion(bodies: &RigidBodySet) -> (f32, f32) {
    let mut fastest = (0.0f32, 0.0f32);
    for (_, rb) in bodies.iter() {
        fold_fastest(&mut fastest, rb);
    }
    fastest
}

/// One body's part of [`fastest_motion`] (a moving body: neither fixed nor asleep).
#[inline]
pub(crate) fn fold_fastest((v_max, w_max): &mut (f32, f32), rb: &RigidBody) {
    if !rb.is_fixed() && !rb.is_sleeping() {
        *v_max = v_max.max(rb.linvel().length());
        *w_max = w_max.max(rb.angvel().length());
    }
}

/// One fingertip's side of its pairs in a detection over `dt`.
struct Tip<'a> {
    handle: ColliderHandle,
    /// Its collision groups (moved into the plugin at registration).
    groups: InteractionGroups,
    collider: &'a Collider,
    body: Option<RigidBodyHandle>,
    /// Linear [m/s] and angular [rad/s] velocity of its body (zero without one).
    v: Vector,
    w: Vector,
    /// The speed gravity adds to either side over the step, `|g| dt` [m/s].
    fall: f32,
    /// The speed its body's joint motors add over the step at its radius [m/s]
    /// (`Scene::motor_push`).
    push: f32,
    /// Radius \[m\].
    r: f32,
    /// Its current AABB.
    aabb: Aabb,
    dt: f32,
    /// A backed fingertip's facing, world (`facing_world`).
    facing: Option<Vector3<f64>>,
}

impl<'a> Tip<'a> {
    /// The fingertip `handle`, if its collider exists, is enabled, is a ball and has a finite
    /// centre (a non-finite centre is counted).
    fn of(
        scene: &Scene<'a>,
        tips: &FastMap<ColliderHandle, TipRecord>,
        handle: ColliderHandle,
        groups: InteractionGroups,
        dt: f64,
        counters: &mut SoftCounters,
    ) -> Option<Self> {
        let collider = scene.colliders.get(handle)?;
        if !collider.is_enabled() {
            return None;
        }
        let ball = collider.shape().as_ball()?;
        if !collider.position().translation.is_finite() {
            counters.non_finite += 1;
            return None;
        }
        let body = collider.parent();
        let (v, w) = body
            .and_then(|b| scene.bodies.get(b))
            .map(|rb| (rb.linvel(), rb.angvel()))
            .unwrap_or((Vector::ZERO, Vector::ZERO));
        Some(Self {
            handle,
            groups,
            collider,
            body,
            v,
            w,
            fall: scene.gravity * dt as f32,
            push: scene.push_of(body, ball.radius),
            r: ball.radius,
            aabb: collider.compute_aabb(),
            dt: dt as f32,
            facing: tips
                .get(&handle)
                .and_then(|t| facing_world(&t.fingertip, collider)),
        })
    }

    /// How far apart `other`'s current AABB is from the fingertip's \[m\] (< 0: overlapping).
    /// The shapes are at least that far apart.
    fn gap_to(&self, other: &Collider) -> f32 {
        let other_aabb = other.compute_aabb();
        (other_aabb.mins - self.aabb.maxs)
            .max(self.aabb.mins - other_aabb.maxs)
            .max_element()
    }

    /// The prediction distance \[m\] of a pair whose other side moves at up to `v_other` [m/s]
    /// at the fingertip's radius: `0.05 R + 1.5 (|v_tip| + |w_tip| R + v_other + 2 |g| dt) dt`.
    fn prediction(&self, v_other: f32) -> f32 {
        0.05 * self.r
            + (self.v.length() + self.w.length() * self.r + self.push + v_other + 2.0 * self.fall)
                * self.dt
                * 1.5
    }

    /// The candidate colliders of the fingertip, in handle order, each once, with the gap
    /// between their current AABBs (`gap_to`, computed once per pair), written to `out`: one query of the broad-phase BVH over the swept AABB grown by the largest
    /// prediction distance of its pairs (the other side at up to `v_max` [m/s] and `w_max`
    /// [rad/s]), prefiltered on the query's own iteration by their current AABBs (no second
    /// collider lookup, nothing sorted but the survivors).
    fn candidates(
        &self,
        qp: &QueryPipeline<'_>,
        v_max: f32,
        w_max: f32,
        out: &mut Vec<(ColliderHandle, f32)>,
    ) {
        let centre = self.collider.position().translation;
        let r = self.r;
        let sweep = self.v * self.dt;
        // Conservative reach: the ball, a margin and the largest prediction distance of its
        // pairs, so that every pair within prediction is a candidate.
        let motion = (self.v.length()
            + self.w.length() * r
            + self.push
            + v_max
            + w_max * r
            + 2.0 * self.fall)
            * self.dt
            * 1.5;
        let reach = r * 1.1 + motion;
        let lo = centre.min(centre + sweep) - Vector::splat(reach);
        let hi = centre.max(centre + sweep) + Vector::splat(reach);
        // The largest prediction distance of this fingertip's pairs (`prediction` with the
        // fastest other side), for the prefilter before any per-pair lookup.
        let max_prediction = 0.05 * r + motion;
        out.clear();
        out.extend(
            qp.intersect_aabb_conservative(Aabb::new(lo, hi))
                .filter(|(h, _)| *h != self.handle)
                .map(|(h, co)| (h, self.gap_to(co)))
                .filter(|(_, gap)| *gap <= max_prediction + 0.01 * r),
        );
        // Each candidate once (sort + dedup: linear-logarithmic in the candidates).
        out.sort_unstable_by_key(|(h, _)| raw(*h));
        out.dedup_by_key(|(h, _)| *h);
    }

    /// The contact of the fingertip with the candidate `other_h`, if the pair is one the
    /// plugin handles (not a sensor, not disabled, not the same body, groups that interact,
    /// a soft-soft pair from its smaller handle) and is within its prediction distance;
    /// `gap` is the AABB gap `candidates` found.
    fn contact_with(
        &self,
        scene: &Scene<'_>,
        tips: &FastMap<ColliderHandle, TipRecord>,
        other_h: ColliderHandle,
        gap: f32,
        counters: &mut SoftCounters,
    ) -> Option<Geom> {
        let other_co = scene.colliders.get(other_h)?;
        if other_co.is_sensor() || !other_co.is_enabled() {
            return None;
        }
        let other_body = other_co.parent();
        if self.body.is_some() && self.body == other_body {
            return None;
        }
        if let (Some(a), Some(b)) = (self.body, other_body)
            && joint_filtered(scene, a, b)
        {
            return None;
        }
        // A fingertip's own collision groups are `none()` (moved into its record).
        let other_tip = tips.get(&other_h);
        let soft_pair = other_tip.is_some();
        let other_groups = other_tip.map_or(other_co.collision_groups(), |t| t.groups);
        if !self.groups.test(other_groups) {
            return None;
        }
        if soft_pair && raw(other_h) < raw(self.handle) {
            // Soft-soft pairs are handled once, from the fingertip with the smaller handle.
            return None;
        }
        let v_other = other_body
            .and_then(|b| scene.bodies.get(b))
            .map(|rb| rb.linvel().length() + rb.angvel().length() * self.r)
            .unwrap_or(0.0)
            + scene.push_of(other_body, self.r);
        let prediction = self.prediction(v_other);
        if gap > prediction + 0.01 * self.r {
            return None;
        }
        let c = self.query_contact(other_co, prediction, counters)?;
        let s = surfaces(&c, counters)?;
        // Behind the flat face of a backed fingertip is its rigid finger (`behind_face`).
        let tip_behind = behind_face(self.facing, &(-s.normal));
        if !soft_pair && tip_behind {
            // rapier's own rigid contact (the hooks keep its solver contacts there).
            return None;
        }
        // On a rigid body: what the fingertip touches there; a pair of fingertips: a plane
        // (only the one that is used is computed).
        let touch = if soft_pair {
            Touch::plane(&s.normal)
        } else {
            curvature::counterpart_at(other_co, &s.point_other, &s.normal, f64::from(self.r))
        };
        let g = Geom {
            tip: self.handle,
            other: other_h,
            body_tip: self.body,
            body_other: other_body,
            point: s.point,
            point_other: s.point_other,
            normal: s.normal,
            dist: s.dist,
            soft_pair,
            touch,
        };
        if !soft_pair {
            return Some(g);
        }
        let other_facing = tips
            .get(&other_h)
            .and_then(|t| facing_world(&t.fingertip, other_co));
        let other_behind = behind_face(other_facing, &s.normal);
        match (tip_behind, other_behind) {
            (false, false) => Some(g),
            // The other fingertip is pressed on this one's rigid finger: its own law.
            (true, false) => Some(g.swapped(&s)),
            // This fingertip is pressed on the other's rigid finger: its own law.
            (false, true) => Some(Geom {
                soft_pair: false,
                ..g
            }),
            // Rigid on rigid: rapier's contact.
            (true, true) => None,
        }
    }

    /// parry's contact of the fingertip with `other_co` within `prediction` \[m\], exact for a
    /// rounded shape's border (`rounded`); `None` if there is none or parry does not support
    /// the pair (counted in `counters.unsupported_pairs`).
    fn query_contact(
        &self,
        other_co: &Collider,
        prediction: f32,
        counters: &mut SoftCounters,
    ) -> Option<query::Contact> {
        match query::contact(
            other_co.position(),
            other_co.shape(),
            self.collider.position(),
            self.collider.shape(),
            prediction,
        ) {
            Ok(Some(c)) => crate::rounded::exact_ball_contact(
                other_co.shape(),
                other_co.position(),
                self.collider.position().translation,
                self.r,
                prediction,
                c,
            ),
            Ok(None) => None,
            Err(_) => {
                counters.unsupported_pairs += 1;
                None
            }
        }
    }
}

impl Geom {
    /// The contact as the other fingertip sees it, alone against a rigid body (this one's
    /// finger): the fingertips swapped, the normal negated, the closest point on the other
    /// surface now this fingertip's (`s.point_other` was the other's: the midpoint mirrored).
    fn swapped(self, s: &Surfaces) -> Geom {
        Geom {
            tip: self.other,
            other: self.tip,
            body_tip: self.body_other,
            body_other: self.body_tip,
            point: self.point,
            point_other: 2.0 * s.point - s.point_other,
            normal: -self.normal,
            dist: self.dist,
            soft_pair: false,
            touch: Touch::plane(&(-self.normal)),
        }
    }
}

/// A backed fingertip's facing in world axes: its collider's rotation applied to
/// `SoftFingertip::facing` (`None` for a free fingertip).
pub(crate) fn facing_world(tip: &SoftFingertip, collider: &Collider) -> Option<Vector3<f64>> {
    let [x, y, z] = tip.facing()?;
    let local = Vector::new(x as f32, y as f32, z as f32);
    Some(to_f64(collider.position().rotation * local))
}

/// Whether a contact in direction `dir` (from the fingertip's centre towards the other body,
/// world) is behind the flat face of a fingertip facing `facing` (world; `None`: free, never
/// behind): `dir . facing < 0`, the finger's side. The equator (`dir . facing = 0`) is soft.
#[inline]
pub(crate) fn behind_face(facing: Option<Vector3<f64>>, dir: &Vector3<f64>) -> bool {
    facing.is_some_and(|f| f.dot(dir) < 0.0)
}

/// parry's contact of a pair in the plugin's `f64` algebra.
struct Surfaces {
    /// The point midway between the two surfaces (world) \[m\].
    point: Vector3<f64>,
    /// The closest point on the other body's surface (world) \[m\].
    point_other: Vector3<f64>,
    /// Unit normal from the other body to the fingertip (world).
    normal: Vector3<f64>,
    /// Signed distance \[m\], negative = penetration.
    dist: f64,
}

/// parry's contact (other shape first) as [`Surfaces`]; `None` (counted as non-finite) unless
/// finite with a normal of length > 0.5.
fn surfaces(c: &query::Contact, counters: &mut SoftCounters) -> Option<Surfaces> {
    let (p1, p2, n, dist) = (
        to_f64(c.point1),
        to_f64(c.point2),
        to_f64(c.normal1),
        c.dist as f64,
    );
    if !(p1
        .iter()
        .chain(p2.iter())
        .chain(n.iter())
        .all(|v| v.is_finite())
        && dist.is_finite())
    {
        counters.non_finite += 1;
        return None;
    }
    let norm = n.norm();
    if !(norm > 0.5) {
        counters.non_finite += 1;
        return None;
    }
    Some(Surfaces {
        point: 0.5 * (p1 + p2),
        point_other: p1,
        normal: n / norm,
        dist,
    })
}
