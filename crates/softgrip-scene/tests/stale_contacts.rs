//! rapier's own contacts in a scene should be the shapes' contacts of that step, never a pair's
//! old points carried along across a gap (issue 25, "other objects"; softgrip-rapier README,
//! "rapier's settings", and `softgrip_rapier`'s `stale_contacts.rs`).
//!
//! rapier 0.36 recycles a contact pair whose relative pose moved less than
//! `normalized_contact_recycle_distance * length_unit` (0.05 m at its defaults) since the pair's
//! last full narrow-phase update: it keeps the old points and normal and only moves `dist` along
//! that normal. At a gripper's scale that is the size of the object. Measured (session 30,
//! before the plugin checked for it): the shipped parallel gripper asked for 20 N on a 2 kg ball
//! (its 20 N motor gives each pad 10 N, too little to lift it) slid its fingers up and off the
//! ball while a recycled contact (its points frozen, one at the ball's equator and one on the
//! finger, 8 cm apart by then) held each finger with 10 N for 20 steps, the finger up to 25 mm
//! from the ball; then the fingers shut in one step and the pads met each other at 141 N. Since
//! session 31 the plugin hands a pair whose recycled contacts slid and act across a gap back to
//! rapier's full update for a step (`SoftCounters::stale_contacts`); scenes keep rapier's
//! recycling, which their jams need (`driven_into_table`: with recycling off six of its jams
//! leave their bounds).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use softgrip_scene::PlainRun;
use softgrip_scene::softgrip_rapier::rapier3d::parry::query;

/// What the gripper squeezing a ball of `density` \[kg/m³\] at `force` N per pad does over its
/// whole run; `recycling` overrides rapier's contact recycling (`None`: the scene's own).
#[derive(Debug)]
struct Squeeze {
    /// The largest true distance \[m\] between the two shapes of a rapier contact pair that
    /// carried an impulse in a step (their shapes' distance at the end of the step).
    widest_gap: f32,
    /// The largest normal force of a pad over the run \[N\].
    peak_pad: f64,
    /// `SoftCounters::stale_contacts` at the end.
    stale: u64,
}

fn squeeze(density: f64, force: f64, recycling: Option<bool>) -> Squeeze {
    let scene = common::shipped_robot_scene(
        "parallel_gripper_ball",
        &[
            ("density = 1527.9", &format!("density = {density}")),
            ("force = 5.0", &format!("force = {force}")),
        ],
    )
    .unwrap();
    let mut run = PlainRun::new(&scene);
    if let Some(on) = recycling {
        run.world.physics.integration_parameters.contact_recycling = on;
    }
    let (mut widest_gap, mut peak_pad) = (0.0f32, 0.0f64);
    for _ in 0..scene.steps() {
        run.step();
        let w = &run.world.physics;
        for pair in w.narrow_phase.contact_pairs() {
            let impulse: f32 = (pair.manifolds().iter())
                .flat_map(|m| m.points.iter())
                .map(|p| p.data.impulse)
                .sum();
            if !(pair.has_any_active_contact() && impulse > 0.0) {
                continue;
            }
            let (a, b) = (&w.colliders[pair.collider1], &w.colliders[pair.collider2]);
            let gap = query::distance(a.position(), a.shape(), b.position(), b.shape())
                .unwrap()
                .distance;
            widest_gap = widest_gap.max(gap);
        }
        for c in run.world.soft.contacts() {
            peak_pad = peak_pad.max(c.normal_force);
        }
    }
    Squeeze {
        widest_gap,
        peak_pad,
        stale: run.world.soft.counters().stale_contacts,
    }
}

/// The gripper on a 2 kg ball at 20 N (10 N a pad: it cannot lift it, and its fingers slide up
/// and off the ball): no rapier contact acts across more than 2 mm, with recycling as rapier
/// has it and with it off, and the pads never press harder than the motor can push them.
/// Measured (session 31, release and debug alike): with recycling, 1.74 mm (the plugin updated
/// a stale pair afresh 5 times; before it did, 25.0 mm and a pad at 141 N), pads at most
/// 10.00 N; with it off, 0.62 mm (a speculative contact within rapier's prediction distance,
/// its bodies having moved in the step), pads at most 10.00 N.
#[test]
fn no_rapier_contact_acts_across_a_gap() {
    let recycled = squeeze(30558.0, 20.0, None);
    let fresh = squeeze(30558.0, 20.0, Some(false));
    println!("recycled {recycled:?}\nfresh {fresh:?}");
    assert!(recycled.widest_gap < 2e-3, "{recycled:?}");
    assert!(recycled.stale > 0, "{recycled:?}: no pair was found stale");
    assert!(fresh.widest_gap < 2e-3, "{fresh:?}");
    assert_eq!(
        fresh.stale, 0,
        "{fresh:?}: a pair refreshed with recycling off"
    );
    for s in [&recycled, &fresh] {
        assert!(
            s.peak_pad < 11.0,
            "{s:?}: a pad pressed past its motor's 10 N"
        );
    }
}
