//! The resting fast path (`SoftContacts::set_rest_replay`, crate README "Resting steps
//! replayed") changes nothing: the same scene stepped with it on and off gives bit-identical
//! poses, velocities, readouts and counts at every step, through motion, rest and
//! disturbances, and it does replay steps at rest.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use rapier3d::prelude::*;
use softgrip_rapier::{SoftCounters, SoftWorld};
use softgrip_testkit::resting::{PITCH, resting_grid_with};
use softgrip_testkit::scenes::{DENSITY, RADIUS};

/// Everything observable of `world` after a step, as bits (the readout through its `Debug`
/// form, which prints each `f64` so that it reads back to the same bits).
fn state(world: &SoftWorld) -> (Vec<u32>, String) {
    let mut bits = Vec::new();
    for (h, rb) in world.physics.bodies.iter() {
        let (i, g) = h.into_raw_parts();
        bits.extend([i, g, rb.is_sleeping() as u32]);
        let p = rb.position();
        bits.extend(p.translation.to_array().map(f32::to_bits));
        bits.extend(p.rotation.to_array().map(f32::to_bits));
        bits.extend(rb.linvel().to_array().map(f32::to_bits));
        bits.extend(rb.angvel().to_array().map(f32::to_bits));
    }
    let readings: Vec<_> = world.soft.contacts().iter().map(|c| c.reading()).collect();
    (bits, format!("{readings:?}"))
}

/// The counts of `c`: its times and `replayed_steps` zeroed.
fn counts(c: &SoftCounters) -> SoftCounters {
    SoftCounters {
        replayed_steps: 0,
        detect_time: Default::default(),
        solve_time: Default::default(),
        pipeline_time: Default::default(),
        step_time: Default::default(),
        rows_time: Default::default(),
        supports_time: Default::default(),
        law_time: Default::default(),
        soft_solve_time: Default::default(),
        apply_time: Default::default(),
        readout_time: Default::default(),
        ..*c
    }
}

/// Nine balls (never asleep) dropped 0.5 mm onto the ground, then, while they rest: a ball
/// pushed down at 0.05 m/s, a tenth ball dropped 2 mm beside the grid, the accuracy changed,
/// the ground moved down 0.1 mm, a ball's gravity scale changed (a ball pushed sideways would
/// roll on for ever: nothing in the scene resists rolling). `replay`: the fast path on.
/// Returns the state after every step and the counters at the end of each phase.
fn run(replay: bool) -> (Vec<(Vec<u32>, String)>, Vec<SoftCounters>) {
    let mut world = resting_grid_with(9, PITCH, true, false);
    world.soft.set_rest_replay(replay);
    assert_eq!(world.soft.rest_replay(), replay);
    let balls: Vec<RigidBodyHandle> = world
        .physics
        .bodies
        .iter()
        .filter(|(_, rb)| rb.is_dynamic())
        .map(|(h, _)| h)
        .collect();
    for &b in &balls {
        let rb = &mut world.physics.bodies[b];
        let t = rb.translation() + Vector::new(0.0, 0.0005, 0.0);
        rb.set_translation(t, true);
    }
    let ground = world
        .physics
        .colliders
        .iter()
        .find(|(_, c)| c.parent().is_none())
        .unwrap()
        .0;
    let tip = world
        .soft
        .fingertip(world.physics.bodies[balls[0]].colliders()[0])
        .unwrap()
        .clone();
    let mut out = Vec::new();
    let mut phases = Vec::new();
    for step in 0..1500 {
        match step {
            300 => world.physics.bodies[balls[4]].set_linvel(Vector::new(0.0, -0.05, 0.0), true),
            600 => {
                // A tenth ball dropped 2 mm onto a free spot of the ground.
                let at =
                    world.physics.bodies[balls[2]].translation() + Vector::new(PITCH, 0.002, 0.0);
                let b = world
                    .physics
                    .bodies
                    .insert(RigidBodyBuilder::dynamic().translation(at));
                let c = world.physics.colliders.insert_with_parent(
                    ColliderBuilder::ball(RADIUS as f32).density(DENSITY),
                    b,
                    &mut world.physics.bodies,
                );
                world.register(c, tip.clone()).unwrap();
            }
            900 => world
                .soft
                .set_accuracy(softgrip_rapier::SoftAccuracy::try_new(0.04).unwrap()),
            1000 => {
                let co = &mut world.physics.colliders[ground];
                let t = co.translation() - Vector::new(0.0, 0.0001, 0.0);
                co.set_translation(t);
            }
            1200 => world.physics.bodies[balls[7]].set_gravity_scale(1.5, true),
            _ => {}
        }
        if [300, 600, 900, 1000, 1200].contains(&step) {
            phases.push(*world.soft.counters());
        }
        world.step();
        assert!(
            world.soft.fault().is_none(),
            "step {step}: {:?}",
            world.soft.fault()
        );
        out.push(state(&world));
    }
    phases.push(*world.soft.counters());
    (out, phases)
}

#[test]
fn replayed_resting_steps_are_bit_identical_to_computed_ones() {
    let (on, phases_on) = run(true);
    let (off, phases_off) = run(false);
    for (step, (a, b)) in on.iter().zip(&off).enumerate() {
        assert_eq!(a.0, b.0, "step {step}: bodies differ with the fast path on");
        assert_eq!(
            a.1, b.1,
            "step {step}: readouts differ with the fast path on"
        );
    }
    let replayed: Vec<u64> = phases_on.iter().map(|c| c.replayed_steps).collect();
    println!("replayed steps at the phases' ends: {replayed:?}");
    for (a, b) in phases_on.iter().zip(&phases_off) {
        assert_eq!(counts(a), counts(b), "counts differ with the fast path on");
        assert_eq!(b.replayed_steps, 0);
    }
    // Each resting phase replays most of its steps (each settles within about 100 steps).
    let per_phase: Vec<u64> = std::iter::once(replayed[0])
        .chain(replayed.windows(2).map(|w| w[1] - w[0]))
        .collect();
    println!("replayed per phase: {per_phase:?}");
    for (k, &r) in per_phase.iter().enumerate() {
        assert!(r >= 50, "phase {k}: only {r} steps replayed");
    }
}
