//! Fresh soft contact geometry at the current poses.
//!
//! Candidates come from rapier's narrow phase (`contact_pairs_with`) and from the broad phase
//! BVH (the fingertip's AABB swept over the step), because rapier's manifolds are one step
//! stale and its AABB margin misses fast impacts. The geometry is then recomputed with
//! `parry::query::contact(other_pose, other_shape, ball_pose, ball, prediction)`: the other
//! shape goes **first** (parry 0.31 returns a wrong distance for ball-then-halfspace), and the
//! contact's `normal1` then points from the other body to the fingertip. For composite shapes
//! (trimesh, compound, heightfield) parry returns the best single contact, so a ball over a
//! shared edge or vertex gives one contact, never one per triangle.

use std::collections::HashMap;

use nalgebra::Vector3;
use rapier3d::parry::bounding_volume::Aabb;
use rapier3d::parry::query;
use rapier3d::prelude::{
    BroadPhaseBvh, ColliderHandle, ColliderSet, NarrowPhase, QueryFilter, RigidBodyHandle,
    RigidBodySet, Vector,
};
use softgrip_law::{ContactLaw, ContactParams};

use crate::counters::SoftCounters;
use crate::fingertip::SoftFingertip;

/// The compression `delta` [m] of the law from parry's signed distance `dist` [m] (negative =
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

/// The law and coefficients of one contact (a fingertip on a rigid body, or two fingertips).
#[derive(Debug, Clone)]
pub(crate) struct Model {
    pub law: ContactLaw,
    /// Hunt-Crossley `zeta = chi v_in` [-].
    pub zeta: f64,
    pub friction: f64,
    /// Effective radius R of the contact [m].
    pub radius: f64,
}

impl Model {
    pub(crate) fn of_tip(tip: &SoftFingertip) -> Self {
        Self {
            law: tip.law().clone(),
            zeta: tip.damping_zeta(),
            friction: tip.friction(),
            radius: tip.radius(),
        }
    }

    /// Two fingertips: combined E*, R and nu (`ContactParams::try_combine`), the first one's
    /// level, the smaller restitution (larger damping) and the geometric mean of the frictions.
    pub(crate) fn of_pair(a: &SoftFingertip, b: &SoftFingertip) -> Option<Self> {
        let p =
            ContactParams::try_combine(a.material(), a.radius(), b.material(), b.radius()).ok()?;
        let law = ContactLaw::try_new(p, a.level()).ok()?;
        Some(Self {
            zeta: a.damping_zeta().max(b.damping_zeta()),
            friction: (a.friction() * b.friction()).sqrt(),
            radius: p.radius(),
            law,
        })
    }
}

/// One soft contact at the current poses.
#[derive(Debug, Clone)]
pub(crate) struct Geom {
    pub tip: ColliderHandle,
    pub other: ColliderHandle,
    pub body_tip: Option<RigidBodyHandle>,
    pub body_other: Option<RigidBodyHandle>,
    /// Contact point, midway between the two surfaces (world) [m].
    pub point: Vector3<f64>,
    /// Closest point on the other body's surface (world) [m].
    pub point_other: Vector3<f64>,
    /// Unit normal from the other body to the fingertip (world).
    pub normal: Vector3<f64>,
    /// Signed distance [m], negative = penetration.
    pub dist: f64,
    /// Key of the law: (tip, other) for soft-soft pairs, else the tip alone.
    pub soft_pair: bool,
}

/// Converts a glam `f32` vector into the plugin's `f64` algebra (the one boundary).
#[inline]
pub(crate) fn to_f64(v: Vector) -> Vector3<f64> {
    Vector3::new(v.x as f64, v.y as f64, v.z as f64)
}

/// Converts the plugin's `f64` vector back to rapier's `f32` (the other boundary).
#[inline]
pub(crate) fn to_f32(v: &Vector3<f64>) -> Vector {
    Vector::new(v.x as f32, v.y as f32, v.z as f32)
}

/// Everything the detection reads.
pub(crate) struct Scene<'a> {
    pub bodies: &'a RigidBodySet,
    pub colliders: &'a ColliderSet,
    pub narrow_phase: &'a NarrowPhase,
    pub broad_phase: &'a BroadPhaseBvh,
}

/// Finds the soft contacts of every fingertip in `tips`, within a prediction distance that
/// covers the step `dt` [s], and writes them to `out`.
pub(crate) fn detect(
    scene: &Scene<'_>,
    tips: &HashMap<ColliderHandle, SoftFingertip>,
    dt: f64,
    out: &mut Vec<Geom>,
    counters: &mut SoftCounters,
) {
    out.clear();
    let qp = scene.broad_phase.as_query_pipeline(
        scene.narrow_phase.query_dispatcher(),
        scene.bodies,
        scene.colliders,
        QueryFilter::default(),
    );
    let mut candidates: Vec<ColliderHandle> = Vec::new();
    for (&tip_h, tip) in tips {
        let Some(tip_co) = scene.colliders.get(tip_h) else {
            continue;
        };
        if !tip_co.is_enabled() {
            continue;
        }
        let Some(ball) = tip_co.shape().as_ball() else {
            continue;
        };
        let tip_pose = tip_co.position();
        let centre = tip_pose.translation;
        if !centre.is_finite() {
            counters.non_finite += 1;
            continue;
        }
        let tip_body = tip_co.parent();
        let (v_tip, w_tip) = tip_body
            .and_then(|b| scene.bodies.get(b))
            .map(|rb| (rb.linvel(), rb.angvel()))
            .unwrap_or((Vector::ZERO, Vector::ZERO));
        let r = ball.radius;
        let sweep = v_tip * dt as f32;
        // Conservative reach: the ball, its motion over the step and a margin.
        let reach = r * 1.1 + (v_tip.length() + w_tip.length() * r) * dt as f32;
        let lo = centre.min(centre + sweep) - Vector::splat(reach);
        let hi = centre.max(centre + sweep) + Vector::splat(reach);

        candidates.clear();
        for pair in scene.narrow_phase.contact_pairs_with(tip_h) {
            let other = if pair.collider1 == tip_h {
                pair.collider2
            } else {
                pair.collider1
            };
            if !candidates.contains(&other) {
                candidates.push(other);
            }
        }
        for (h, _) in qp.intersect_aabb_conservative(Aabb::new(lo, hi)) {
            if h != tip_h && !candidates.contains(&h) {
                candidates.push(h);
            }
        }

        for &other_h in &candidates {
            let Some(other_co) = scene.colliders.get(other_h) else {
                continue;
            };
            if other_co.is_sensor() || !other_co.is_enabled() {
                continue;
            }
            if !tip_co.collision_groups().test(other_co.collision_groups()) {
                continue;
            }
            let other_body = other_co.parent();
            if tip_body.is_some() && tip_body == other_body {
                continue;
            }
            let soft_pair = tips.contains_key(&other_h);
            if soft_pair && raw(other_h) < raw(tip_h) {
                // Soft-soft pairs are handled once, from the fingertip with the smaller handle.
                continue;
            }
            let v_other = other_body
                .and_then(|b| scene.bodies.get(b))
                .map(|rb| rb.linvel().length() + rb.angvel().length() * r)
                .unwrap_or(0.0);
            let prediction =
                0.05 * r + (v_tip.length() + w_tip.length() * r + v_other) * dt as f32 * 1.5;
            let c = match query::contact(
                other_co.position(),
                other_co.shape(),
                tip_pose,
                tip_co.shape(),
                prediction,
            ) {
                Ok(Some(c)) => c,
                Ok(None) => continue,
                Err(_) => {
                    counters.unsupported_pairs += 1;
                    continue;
                }
            };
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
                continue;
            }
            let norm = n.norm();
            if !(norm > 0.5) {
                counters.non_finite += 1;
                continue;
            }
            out.push(Geom {
                tip: tip_h,
                other: other_h,
                body_tip: tip_body,
                body_other: other_body,
                point: 0.5 * (p1 + p2),
                point_other: p1,
                normal: n / norm,
                dist,
                soft_pair,
            });
        }
        let _ = tip; // the fingertip's law is looked up by the caller
    }
    // Deterministic order, whatever the hash map's iteration order.
    out.sort_by_key(|g| (raw(g.tip), raw(g.other)));
}

/// A collider handle as a sortable pair (index, generation).
#[inline]
pub(crate) fn raw(h: ColliderHandle) -> (u32, u32) {
    h.into_raw_parts()
}
