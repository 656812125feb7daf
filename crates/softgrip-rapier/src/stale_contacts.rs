//! rapier's recycled contacts that act across a gap: found before each step, and their pairs
//! handed back to rapier's full contact update.
//!
//! **Why.** rapier 0.36 recycles a contact pair whose relative pose drifted less than
//! `contact_recycle_distance()` (`0.05 * length_unit`, 5 cm at its defaults) since the pair's
//! last full narrow-phase update: its points ride their bodies, its normal and lever arms stay
//! frozen, and only the separation along the frozen normal is tracked. That is what keeps
//! rapier's stacks and jams still (re-linearised arms under large warm-started impulses pump
//! energy: with recycling off, six of `driven_into_table`'s jams leave their bounds), but at a
//! gripper's scale 5 cm is the size of the object: the parallel gripper's finger slid 25 mm up
//! a 2 kg ball while a recycled contact, its two points 8 cm apart, held the finger with 10 N
//! along a normal the ball's surface no longer had; the fingers then shut in one step and the
//! pads met at 141 N (issue 25; `softgrip-scene/tests/stale_contacts.rs`).
//!
//! **The criterion.** A fresh contact's two points are separated along its normal only. A
//! recycled one's points ride their own bodies, so the part of their separation across the
//! frozen normal is how far the two surfaces slid or rolled over each other since the freeze.
//! A pair whose slip passes [`STALE_SLIP`] of the smaller shape's bounding radius `r` (on a
//! ball of radius `r`, a turn of its normal by 0.1 rad) is checked against the shapes
//! themselves (parry's `contact`, one query per such pair): it is stale when the shapes are
//! apart by more than `g = min(STALE_GAP r, allowed_linear_error)` and further apart than its
//! frozen separation says by more than `g` too. That is a force across a gap. A pair pressed
//! or jammed (the shapes overlapping, whatever its normal now is), resting, or sliding on a
//! face (the same separation) keeps rapier's recycling and with it rapier's stability.
//! Checking the normal as well (refreshing a pair whose true normal turned by 0.2 rad) or a
//! gap of `0.01 r` refreshed the links of the three-finger hand jammed 2 cm into each other
//! under its kinematic palm, which then flung (`driven_into_table`); refreshing also where the
//! shapes overlap by more than `g` while the recycled contact sees no overlap (a contact that
//! misses a penetration) put the pads-pressing descent's steps at the substep cap; measured
//! in session 31. Where a recycled contact misses a penetration, rapier's own fresh contacts
//! did no better in the case measured (a block sliding off a ball: 5.8 mm deep fresh, 4.9 mm
//! with this check; `tests/stale_contacts.rs`).
//!
//! **The remedy.** rapier never recycles a pair one of whose colliders asks for the
//! solver-contact hook, so the hook is turned on for the step (by `link_contacts`, which owns
//! the set it turned on) on one collider of each stale pair: the one on a dynamic body (the
//! other may be a table with many pairs), else the first. The plugin's hook leaves such a
//! pair's contacts as rapier computed them. The next step's check reads the fresh contacts
//! and the hook goes off again. Counted in `SoftCounters::stale_contacts`.

use std::collections::HashSet;

use rapier3d::parry::query;
use rapier3d::prelude::{
    ActiveHooks, Collider, ColliderHandle, PhysicsWorld, Pose, RigidBodyHandle, Vector,
};

/// A recycled contact is checked when its points slid across its frozen normal by more than
/// this fraction of the smaller of its two shapes' bounding radii (module docs).
pub(crate) const STALE_SLIP: f32 = 0.1;

/// A checked contact is stale when its shapes are apart, and further apart than it says, by
/// more than this fraction of the smaller bounding radius (at most rapier's allowed linear
/// error; module docs).
pub(crate) const STALE_GAP: f32 = 0.02;

/// The colliders whose pairs must be updated afresh this step: one per stale pair (module
/// docs). Pairs with the solver-contact hook (never recycled by rapier) are skipped, except
/// those whose hook is in `ours` (turned on by the plugin: their contacts were fresh last step
/// and are recycled again once the hook goes off).
pub(crate) fn stale_colliders(
    world: &PhysicsWorld,
    ours: &HashSet<ColliderHandle>,
) -> HashSet<ColliderHandle> {
    let params = &world.integration_parameters;
    let mut out = HashSet::new();
    if !params.contact_recycling {
        return out;
    }
    let prediction = params.prediction_distance();
    let hooked = |c: &Collider, h: ColliderHandle| {
        !ours.contains(&h)
            && c.active_hooks()
                .contains(ActiveHooks::MODIFY_SOLVER_CONTACTS)
    };
    for pair in world.narrow_phase.contact_pairs() {
        let (h1, h2) = (pair.collider1, pair.collider2);
        if out.contains(&h1) || out.contains(&h2) || !pair.has_any_active_contact() {
            continue;
        }
        let (Some(c1), Some(c2)) = (world.colliders.get(h1), world.colliders.get(h2)) else {
            continue;
        };
        if hooked(c1, h1) || hooked(c2, h2) {
            continue;
        }
        let size = (c1.shape().compute_local_bounding_sphere().radius)
            .min(c2.shape().compute_local_bounding_sphere().radius);
        let Some(sep) = slid_separation(world, pair, c1, c2, STALE_SLIP * size) else {
            continue;
        };
        let gap = params.allowed_linear_error().min(STALE_GAP * size);
        let fresh = query::contact(
            c1.position(),
            c1.shape(),
            c2.position(),
            c2.shape(),
            prediction.max(sep + gap),
        );
        let stale = match fresh {
            // A pair of shapes parry cannot answer keeps rapier's contacts.
            Err(_) => false,
            Ok(None) => true,
            Ok(Some(c)) => c.dist > gap && c.dist - sep > gap,
        };
        if stale {
            let dynamic = |c: &Collider| {
                c.parent()
                    .and_then(|b| world.bodies.get(b))
                    .is_some_and(|rb| rb.is_dynamic())
            };
            out.insert(if dynamic(c1) || !dynamic(c2) { h1 } else { h2 });
        }
    }
    out
}

/// The pair's smallest separation along its contacts' frozen normals \[m\] (negative:
/// penetration), if one of its contacts' points slid across its normal by more than `limit`
/// \[m\]; `None` otherwise.
fn slid_separation(
    world: &PhysicsWorld,
    pair: &rapier3d::prelude::ContactPair,
    c1: &Collider,
    c2: &Collider,
    limit: f32,
) -> Option<f32> {
    let pose = |body: Option<RigidBodyHandle>| -> Option<Pose> {
        let rb = world.bodies.get(body?)?;
        Some(
            rb.position()
                .prepend_translation(rb.mass_properties().local_mprops.local_com),
        )
    };
    let (pose1, pose2) = (pose(c1.parent()), pose(c2.parent()));
    let (mut sep, mut slid) = (f32::INFINITY, false);
    for m in pair.manifolds() {
        let n: Vector = m.data.normal;
        let dom = m.data.relative_dominance;
        // The anchors' frames as rapier's narrow phase localised them: a side's body's
        // centre-of-mass frame, or the world for a world-attached side (`pair_update.rs`).
        let p1 = pose1.filter(|_| dom <= 0);
        let p2 = pose2.filter(|_| dom >= 0);
        for sc in &m.data.solver_contacts {
            let a1 = p1.map_or(sc.anchor1, |p| p.transform_point(sc.anchor1));
            let a2 = p2.map_or(sc.anchor2, |p| p.transform_point(sc.anchor2));
            let d = a2 - a1;
            let along = d.dot(n);
            slid |= (d - n * along).length() > limit;
            sep = sep.min(along);
        }
    }
    slid.then_some(sep)
}
