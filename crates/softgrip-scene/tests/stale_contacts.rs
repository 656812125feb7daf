//! rapier's own contacts in a scene should be the shapes' contacts of that step, never a pair's
//! old points carried along (issue 25, "other objects"; softgrip-rapier README, "rapier's
//! settings", and Limits, "Stale rigid contacts").
//!
//! rapier 0.36 recycles a contact pair whose relative pose moved less than
//! `normalized_contact_recycle_distance * length_unit` (0.05 m at its defaults) since the pair's
//! last full narrow-phase update: it keeps the old points and normal and only moves `dist` along
//! that normal. At a gripper's scale that is the size of the object. Measured (session 30): the
//! shipped parallel gripper asked for 20 N on a 2 kg ball (its 20 N motor gives each pad 10 N,
//! too little to lift it) slid its fingers up and off the ball while a recycled contact (its points
//! frozen, one at the ball's equator and one on the finger, 8 cm apart by then) held each finger
//! with 10 N for 20 steps, the finger up to 25 mm from the ball;
//! then the fingers shut in one step and the pads met each other at 141 N. Scenes keep rapier's
//! default for now: with recycling off, six of `driven_into_table`'s jams and three of
//! `hand_scenes`' checks move past their bounds (listed in the ignore reason below).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use softgrip_scene::PlainRun;
use softgrip_scene::softgrip_rapier::rapier3d::parry::query;

/// The largest true distance \[m\] between the two shapes of a rapier contact pair that carried
/// an impulse in the step, over the whole run of the parallel gripper squeezing a ball of
/// `density` \[kg/m³\] at `force` N per pad; `recycling` overrides rapier's contact recycling
/// (`None`: the scene's own setting).
fn widest_acting_gap(density: f64, force: f64, recycling: Option<bool>) -> f32 {
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
    let mut widest = 0.0f32;
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
            widest = widest.max(gap);
        }
    }
    widest
}

/// What this measures is rapier's and what it measured (session 30, release): with recycling
/// as rapier has it, a contact acted across 0.0250 m (the finger's cuboid and the ball, their
/// shapes' true distance at the end of the step); with it off, across 0.62 mm (a speculative
/// contact within rapier's prediction distance, its bodies having moved in the step).
#[test]
fn recycled_contacts_act_across_a_gap_and_fresh_ones_do_not() {
    let recycled = widest_acting_gap(30558.0, 20.0, Some(true));
    let fresh = widest_acting_gap(30558.0, 20.0, Some(false));
    println!("widest acting gap: recycled {recycled} m, fresh {fresh} m");
    assert!(recycled > 0.01, "recycled {recycled} m");
    assert!(fresh < 2e-3, "fresh {fresh} m");
}

/// The gripper on a 2 kg ball at 20 N through the scene as loaded: no rapier contact should act
/// across more than 2 mm (rapier's prediction distance is 2 cm at its defaults; the step's own
/// motion is below 1 mm here).
#[test]
#[ignore = "open (session 30): scenes keep rapier's contact recycling, and a recycled contact acts across 0.025 m here; with `contact_recycling = false` in `Scene::empty_world` this passes (0.62 mm), but six jams of `driven_into_table` leave their bounds (the Panda arm flings a link at 3.2 m/s, the gripper pushed into the table presses 8.6 N, the hand's links fly at 0.53 m/s, the pads-pressing descent takes 8118 substeps, the hand's box descent throws the box 8.9 m) and its wall drag without pads no longer diverges, and in `hand_scenes` the box and cylinder holds creep 3.8 / 5.3 um and a cylinder joint's effort is 1.9 % off J^T F; at a recycle distance of 1 mm or 5 mm four or five of those jams still fail; softgrip-rapier README, Limits, \"Stale rigid contacts\""]
fn no_rapier_contact_acts_across_a_gap() {
    let gap = widest_acting_gap(30558.0, 20.0, None);
    assert!(gap < 2e-3, "a contact acted across {gap} m");
}
