//! A fingertip on a jointed body pressing a box that rests on a fixed table (issue 23, item 4):
//! the last link of a two-link finger (two revolute joints with position motors) and a
//! prismatic jaw with a position motor, built as rapier multibodies (reduced coordinates: a
//! URDF hand's default) and, for the finger, as impulse joints.
//!
//! At rest the soft contact must carry the law's force at the compression the geometry gives
//! (the tip's centre against the box's top face), each motor must hold the joint-space
//! projection of the contact force (`J^T F`: the moment of the contact force about the joint's
//! axis, or its component along a prismatic axis), and the box must be still. A squeeze
//! driven by a joint motor's target must follow the law all the way.
//!
//! `cargo test -p softgrip-rapier --test jointed -- --nocapture` prints the numbers.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod jointed_scene;

use jointed_scene::*;

#[test]
fn multibody_finger_presses_a_box_and_holds() {
    let mut s = scene(Build::Multibody, false, PGS, 0.0);
    let h = hold(&mut s, &FINGER, 240);
    assert_held("two-link multibody finger", &h);
}

/// The finger's links under gravity (the motors hold their weight too: the effort is `J^T`
/// of the contact force and of the links' weights).
#[test]
fn multibody_finger_with_heavy_links_holds() {
    let mut s = scene(Build::Multibody, false, PGS, 1.0);
    let h = hold(&mut s, &FINGER, 240);
    assert_held("two-link multibody finger, links under gravity", &h);
}

/// The same finger at rapier's default of one PGS iteration per solver pass: what it does
/// today (crate README, Limits).
#[test]
fn multibody_finger_at_rapiers_default_iterations() {
    let mut s = scene(Build::Multibody, false, 1, 0.0);
    let h = hold(&mut s, &FINGER, 240);
    println!("two-link multibody finger, 1 PGS iteration: {h:?}");
    assert!(h.force > 1.0, "{h:?}");
    assert!(h.law_error < 0.06, "{h:?}");
    for (motor, contact) in &h.efforts {
        assert!((motor / -contact - 1.0).abs() < 1e-2, "{h:?}");
    }
    assert!(h.box_speed < 1e-6, "{h:?}");
}

#[test]
fn multibody_prismatic_jaw_presses_a_box_and_holds() {
    for pgs in [1, PGS] {
        let mut s = scene(Build::Multibody, true, pgs, 0.0);
        let h = hold(&mut s, &[-0.0015], 240);
        assert_held(&format!("prismatic multibody jaw, {pgs} PGS"), &h);
    }
}

/// A prismatic jaw on a fixed base held by one impulse joint (its motor at 2e4 N/m): the jaw is
/// a jointed body to the soft solve (`jointed`: the joint's locked axes hard rows, its motor
/// rapier's compliant row), so the tip carries the law's force and the motor, read from the
/// impulse rapier writes back, holds `J^T F`. (Seen as a free body before session 11.)
#[test]
fn impulse_prismatic_jaw_presses_a_box_and_holds() {
    for pgs in [1, PGS] {
        let mut s = scene(Build::Impulse, true, pgs, 0.0);
        let h = hold(&mut s, &[-0.0015], 240);
        assert_held(&format!("prismatic impulse-jointed jaw, {pgs} PGS"), &h);
    }
}

/// rapier's Gauss-Seidel sweeps per solver pass at which its own solve of the impulse-jointed
/// two-link finger converges (plain rapier: `tests/impulse_chain_plain.rs`), so that the soft
/// solve sees the chain as one jointed assembly (`joint_sweeps::SWEEP_TOLERANCE`).
const CHAIN_PGS: usize = 256;

/// The finger built with impulse joints (a chain of two dynamic links, revolute joints with
/// position motors) at [`CHAIN_PGS`] sweeps: the solve sees the chain as one assembly (the
/// joints' locked axes hard rows, their motors rapier's compliant rows), so the tip carries the
/// law's force and each motor, read from the impulse rapier writes back, holds `J^T F`; the
/// same numbers as the multibody finger.
#[test]
fn impulse_jointed_finger_presses_a_box_and_holds() {
    let mut s = scene(Build::Impulse, false, CHAIN_PGS, 0.0);
    let h = hold(&mut s, &FINGER, 240);
    assert_held(
        &format!("two-link impulse-jointed finger, {CHAIN_PGS} PGS"),
        &h,
    );
    let mut m = scene(Build::Multibody, false, PGS, 0.0);
    let hm = hold(&mut m, &FINGER, 240);
    println!(
        "impulse-jointed vs multibody finger: {:.5} N vs {:.5} N ({:.2e} apart)",
        h.force,
        hm.force,
        (h.force / hm.force - 1.0).abs()
    );
    // The two builds are the same finger: the same force to the law's tolerance.
    assert!((h.force / hm.force - 1.0).abs() < 5e-3, "{h:?} {hm:?}");
}

/// The impulse-jointed finger under gravity: the motors hold the links' weight too.
#[test]
fn impulse_jointed_finger_with_heavy_links_holds() {
    let mut s = scene(Build::Impulse, false, CHAIN_PGS, 1.0);
    let h = hold(&mut s, &FINGER, 240);
    assert_held("two-link impulse-jointed finger, links under gravity", &h);
}

/// The impulse-jointed finger at the fewest sweeps the solve sees it at (214:
/// `rate^sweeps <= 1e-5` with rate 0.948, `joint_sweeps::SWEEP_TOLERANCE`, set on this finger at
/// 200 / 256 sweeps), and with links 10x denser (rate 0.947, seen from 210), which the
/// tolerance was not set on: both hold within the bounds (0.23 % / 3.8e-5 off the law
/// measured).
#[test]
fn impulse_jointed_finger_holds_from_the_fewest_sweeps_it_is_seen_at() {
    for density in [DENSITY, 10.0 * DENSITY] {
        let mut s = scene_with(Build::Impulse, false, 214, (0.0, density));
        let h = hold(&mut s, &FINGER, 240);
        assert_held(
            &format!("impulse-jointed finger, links of {density} kg/m^3, 214 PGS"),
            &h,
        );
    }
}

/// The impulse-jointed finger with the world at the suite's 2 sweeps and 254 more asked by
/// the finger's links alone (`RigidBody::set_additional_pgs_iterations`: rapier runs them for
/// the links' island component, the finger and the box, not the whole world): seen (the
/// members' extra sweeps count), and the same numbers as at 256 for the world.
#[test]
fn impulse_jointed_finger_with_extra_sweeps_on_its_links_holds() {
    let mut s = scene(Build::Impulse, false, PGS, 0.0);
    for j in &s.joints {
        let rb = s.world.physics.bodies.get_mut(j.child).unwrap();
        rb.set_additional_pgs_iterations(CHAIN_PGS - PGS);
    }
    let h = hold(&mut s, &FINGER, 240);
    assert_held(
        &format!(
            "impulse-jointed finger, {PGS} PGS + {} on its links",
            CHAIN_PGS - PGS
        ),
        &h,
    );
}

/// The impulse-jointed finger at 2 sweeps, where rapier's own solve of the chain does not
/// converge: the solve does not see the chain (`joint_sweeps::SWEEP_TOLERANCE`), each link is a free
/// body and the soft impulse on the last one is predicted with its own mass alone. What it
/// does (crate README, Limits): 0.004 N where the law asks 6.3 N, the tip sinks into the box,
/// nothing is thrown, the box still.
#[test]
fn impulse_jointed_finger_at_few_sweeps_is_not_seen() {
    let mut s = scene(Build::Impulse, false, PGS, 0.0);
    let h = hold(&mut s, &FINGER, 240);
    println!("two-link impulse-jointed finger, {PGS} PGS: {h:?}");
    assert!(h.force.is_finite() && h.force < 0.05, "{h:?}");
    assert!(h.law_error > 0.99, "{h:?}");
    assert!(h.box_speed < 1e-6, "{h:?}");
}

/// The squeeze: joint 1's target turns down slowly (by 0.04 rad over 32 s: the tip moves down
/// at about 0.1 mm/s), the force read every step against the law at the geometry's
/// compression in the middle of the step (the mean of its start and end); for the prismatic
/// jaw its target moves down by 2 mm over the same 32 s. Returns the worst `|F / F_law - 1|`
/// past 2 N and the peak force \[N\].
fn squeeze(build: Build, prismatic: bool, pgs: usize) -> (f64, f64) {
    let mut s = scene(build, prismatic, pgs, 0.0);
    let steps = 1920;
    let (mut worst, mut peak) = (0.0f64, 0.0f64);
    let mut before: Option<f64> = None;
    for i in 0..steps {
        let ramp = (i + 1) as f32 / steps as f32;
        if prismatic {
            s.set_targets(&[-0.0003 - 0.002 * ramp]);
        } else {
            s.set_targets(&[-0.01 - 0.04 * ramp, 0.0]);
        }
        s.world.step();
        let Some(c) = s
            .world
            .soft
            .contacts()
            .iter()
            .find(|c| c.other == s.box_col)
        else {
            before = None;
            continue;
        };
        let f = c.normal_force;
        let after = s.geometric_delta();
        // (past 2 N: the first 0.2 mm, where the lag of one step weighs most, measured 0.52 %
        // at 1 N)
        if let Some(b) = before
            && f > 2.0
        {
            let e = (f / s.law.response(0.5 * (b + after)).force - 1.0).abs();
            worst = worst.max(e);
        }
        before = Some(after);
        peak = peak.max(f);
    }
    println!(
        "squeeze by the motor ({build:?}, prismatic {prismatic}, {pgs} PGS): worst |F/F_law - 1| {worst:.3e}, peak {peak:.2} N"
    );
    (worst, peak)
}

#[test]
fn multibody_finger_squeeze_follows_the_law() {
    let (worst, peak) = squeeze(Build::Multibody, false, PGS);
    assert!(peak > 5.0, "{peak}");
    assert!(worst < 5e-3, "{worst}");
}

#[test]
fn impulse_jointed_finger_squeeze_follows_the_law() {
    let (worst, peak) = squeeze(Build::Impulse, false, CHAIN_PGS);
    assert!(peak > 5.0, "{peak}");
    assert!(worst < 5e-3, "{worst}");
}

#[test]
fn impulse_prismatic_jaw_squeeze_follows_the_law() {
    let (worst, peak) = squeeze(Build::Impulse, true, PGS);
    assert!(peak > 5.0, "{peak}");
    assert!(worst < 5e-3, "{worst}");
}
