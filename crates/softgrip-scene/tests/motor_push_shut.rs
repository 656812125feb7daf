//! A position motor's push within rapier's step, seen by the plugin's step prediction (issue
//! 25, "the simulation never explodes"; softgrip-rapier README, Limits, "A motor's push").
//!
//! The shipped parallel gripper asked for 20 N on its box at 20 times its density (2 kg: its
//! 20 N motor gives each pad 10 N, too little to lift it) slides its fingers up the box while
//! the hand lifts; rapier's contacts of the finger links on the box's top edge then hold the
//! fingers still with their pads 18 mm apart, the motor pushing them together at 1.1 m/s per
//! step (`SoftWorld`'s folded motor velocity). Once the fingers clear the box they shut within
//! one step (the joint from 13 mm to -1.2 mm, past its limit). Measured (session 31, before the
//! plugin counted the push there): the pads were not detected in that step (the prediction
//! distance read the links' stored velocities, ~0), nor would their approach have split it (it
//! was capped at the realised closing of a jammed link, 0.03 m/s), so they met only in the next
//! step, 8 mm deep, and a pad read 87.9 N. Now the detection adds the motors' push to a link's
//! speed (`multibody::motor_push`) and a jammed link's open contact whose gap the push closes
//! within the step splits it (`step/split.rs`, `gap_drive_substeps`; 2 substeps in each of the
//! 3 jammed steps): at most 4.44 N in the step they shut in, 13.85 N over the run (at the lift's start, as before), the joint down to
//! 1.4 mm (within its limit).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use softgrip_scene::PlainRun;

/// The largest normal force of a pad over the substeps of the whole run \[N\]
/// (`peak_normal_force`), and the lowest the finger joint went \[m\].
fn shut(density: f64, force: f64) -> (f64, f64) {
    let scene = common::shipped_robot_scene(
        "parallel_gripper_box",
        &[
            ("density = 3125.0", &format!("density = {density}")),
            ("force = 5.0", &format!("force = {force}")),
        ],
    )
    .unwrap();
    let mut run = PlainRun::new(&scene);
    let robot = &scene.robots()[0];
    let h = run.handles.robots[0].1.clone();
    let j = (0..robot.joints().len())
        .find(|&j| robot.joints()[j].kind.moves())
        .unwrap();
    let (mut peak, mut lowest) = (0.0f64, f64::INFINITY);
    for _ in 0..scene.steps() {
        run.step();
        for c in run.world.soft.contacts() {
            peak = peak.max(c.peak_normal_force);
        }
        let q = softgrip_scene::robot::joint_state(robot, &run.world.physics, &h, j, 1.0);
        lowest = lowest.min(q.position);
    }
    (peak, lowest)
}

/// The gripper on its box at 20 times its density, 20 N: no pad passes 15 N (its motor pushes
/// each with at most 10 N; 13.85 N measured at the lift's start, release; 87.9 N when the pads
/// shut on each other unsplit).
#[test]
fn fingers_shutting_past_a_heavy_box_meet_within_their_step() {
    let (peak, lowest) = shut(3125.0 * 20.0, 20.0);
    println!("peak pad {peak} N, finger joint down to {lowest} m");
    assert!(peak < 15.0, "a pad at {peak} N (lowest joint {lowest} m)");
}
