//! Held fingertips: a fingertip on a sleeping body that no awake body can reach within the
//! step is not detected (`detect`), its contacts held as they were (crate README, Sleeping).

use rapier3d::parry::bounding_volume::Aabb;
use rapier3d::prelude::{ColliderHandle, QueryFilter, QueryPipeline, Vector};

use super::{Geom, Scene, detect_tip};
use crate::boundary::raw;
use crate::counters::SoftCounters;
use crate::fast_hash::{FastMap, FastSet};
use crate::tip_record::TipRecord;

/// Which fingertips a detection looked at: every one, or (when some sleep) those in `tips`.
#[derive(Debug, Clone, Default)]
pub(crate) struct Detected {
    /// Every fingertip was detected (none held).
    pub all: bool,
    /// The fingertips detected, in handle order (meaningful when `all` is false).
    pub tips: Vec<ColliderHandle>,
    /// The sleeping fingertips within reach of an awake body (`disturbed`).
    pub(super) disturbed: FastSet<ColliderHandle>,
    /// The fastest linear [m/s] and angular [rad/s] motion of the world (`fastest_motion`).
    pub(super) fastest: (f32, f32),
}

impl Detected {
    /// Whether the contacts owned by fingertip `tip` were left as they were (`held`).
    pub(crate) fn held(&self, tip: ColliderHandle) -> bool {
        !self.all
            && self
                .tips
                .binary_search_by_key(&raw(tip), |h| raw(*h))
                .is_err()
    }
}

/// The fingertip that detects a contact between `a` (a fingertip) and `b`: for a pair of
/// fingertips the one with the smaller handle (`Tip::contact_with`), else `a`.
pub(crate) fn owner(
    tips: &FastMap<ColliderHandle, TipRecord>,
    a: ColliderHandle,
    b: ColliderHandle,
) -> ColliderHandle {
    if tips.contains_key(&b) && raw(b) < raw(a) {
        b
    } else {
        a
    }
}

/// Whether fingertip `h` is on a sleeping dynamic body: its contacts are held (`detect`).
pub(super) fn asleep(scene: &Scene<'_>, h: ColliderHandle) -> bool {
    scene
        .colliders
        .get(h)
        .and_then(|c| c.parent())
        .and_then(|b| scene.bodies.get(b))
        .is_some_and(|rb| rb.is_dynamic() && rb.is_sleeping())
}

/// The sleeping fingertips that an awake body may reach within the step, written to `out`:
/// each awake body's colliders' AABBs, swept over `dt` \[s\] and grown by the largest
/// prediction distance a pair with a sleeping fingertip can have (`Tip::prediction` with the
/// fingertip still: `0.05 R + 1.5 (|v| + |w| R + 2 |g| dt) dt`, `R` the largest fingertip
/// radius, plus the 1 % of R of rounding room), queried in the broad phase's BVH. A sleeping
/// fingertip's BVH leaf holds its current AABB (it has not moved since it fell asleep), so
/// every pair the fingertip's own detection would find with an awake body is found here. The
/// cost is the awake bodies' neighbourhoods', not the sleeping fingertips'.
pub(super) fn disturbed(
    scene: &Scene<'_>,
    qp: &QueryPipeline<'_>,
    tips: &FastMap<ColliderHandle, TipRecord>,
    dt: f32,
    out: &mut FastSet<ColliderHandle>,
) {
    out.clear();
    let r = scene.max_radius;
    let fall = scene.gravity * dt;
    for handle in scene.islands.active_bodies() {
        let Some(rb) = scene.bodies.get(handle) else {
            continue;
        };
        let (v, w) = (rb.linvel(), rb.angvel());
        let grow = 0.06 * r + 1.5 * (v.length() + w.length() * r + 2.0 * fall) * dt;
        let sweep = v * dt;
        for &ch in rb.colliders() {
            let Some(co) = scene.colliders.get(ch) else {
                continue;
            };
            let aabb = co.compute_aabb();
            let lo = aabb.mins.min(aabb.mins + sweep) - Vector::splat(grow);
            let hi = aabb.maxs.max(aabb.maxs + sweep) + Vector::splat(grow);
            for (h, _) in qp.intersect_aabb_conservative(Aabb::new(lo, hi)) {
                if h != ch && tips.contains_key(&h) && asleep(scene, h) {
                    out.insert(h);
                }
            }
        }
    }
}

/// Detects the held fingertip `tip_h` after all (its body was woken within the step,
/// `Step::wake_touched`): its contacts are appended to `out` (the caller sorts them) and it
/// joins `detected`. Returns whether it was held.
#[allow(clippy::too_many_arguments)]
pub(crate) fn detect_woken(
    scene: &Scene<'_>,
    tips: &FastMap<ColliderHandle, TipRecord>,
    tip_h: ColliderHandle,
    dt: f64,
    out: &mut Vec<Geom>,
    candidates: &mut Vec<(ColliderHandle, f32)>,
    detected: &mut Detected,
    counters: &mut SoftCounters,
) -> bool {
    let Err(at) = detected.tips.binary_search_by_key(&raw(tip_h), |h| raw(*h)) else {
        return false;
    };
    if detected.all {
        return false;
    }
    let Some(&groups) = tips.get(&tip_h).map(|t| &t.groups) else {
        return false;
    };
    detected.tips.insert(at, tip_h);
    counters.held_tips = counters.held_tips.saturating_sub(1);
    let qp = scene.broad_phase.as_query_pipeline(
        scene.narrow_phase.query_dispatcher(),
        scene.bodies,
        scene.colliders,
        QueryFilter::default(),
    );
    let fastest = detected.fastest;
    detect_tip(
        scene,
        &qp,
        tips,
        (tip_h, groups),
        dt,
        fastest,
        candidates,
        out,
        counters,
    );
    true
}
