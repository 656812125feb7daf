//! Fingertips that fall asleep in the same step leave rapier's awake island cleared
//! (`step::stale_island`): rapier 0.36.1 leaves it empty but set when several of its islands
//! sleep at once, and runs its solver on no body every step after (crate README, "Where a
//! resting step's time goes"). The plugin carries a collider-less body through it for one
//! step and removes it; these tests check that this happens once per fall asleep, leaves no
//! body behind and changes nothing the user sees.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use rapier3d::prelude::*;
use softgrip_rapier::SoftWorld;
use softgrip_testkit::resting::{PITCH, resting_grid_with};

/// The grid's balls, in insertion order.
fn balls(world: &SoftWorld) -> Vec<RigidBodyHandle> {
    let bodies = &world.physics.bodies;
    bodies
        .iter()
        .filter(|(_, rb)| rb.is_dynamic())
        .map(|(h, _)| h)
        .collect()
}

/// Each ball's position and rotation, bit for bit.
fn poses(world: &SoftWorld, balls: &[RigidBodyHandle]) -> Vec<[u32; 7]> {
    balls
        .iter()
        .map(|&h| {
            let p = world.physics.bodies[h].position();
            let (t, r) = (p.translation, p.rotation);
            [t.x, t.y, t.z, r.x, r.y, r.z, r.w].map(f32::to_bits)
        })
        .collect()
}

/// The soft contacts' forces \[N\], bit for bit.
fn forces(world: &SoftWorld) -> Vec<u64> {
    let contacts = world.soft.contacts();
    contacts
        .iter()
        .map(|c| c.reading.normal_force.to_bits())
        .collect()
}

/// Ten fingertips at the grid's pitch, allowed to sleep, settled 120 steps (asleep from
/// about step 30, all in the same step: identical balls).
fn settled_ten() -> (SoftWorld, Vec<RigidBodyHandle>) {
    let mut world = resting_grid_with(10, PITCH, true, true);
    let balls = balls(&world);
    assert_eq!(balls.len(), 10);
    for _ in 0..120 {
        world.step();
    }
    (world, balls)
}

#[test]
fn ten_fingertips_asleep_together_clear_the_awake_island_once() {
    let (mut world, balls) = settled_ten();
    let bodies = world.physics.bodies.len();
    assert_eq!(
        bodies, 10,
        "ten balls (the ground is a collider without a body)"
    );
    assert!(balls.iter().all(|&h| world.physics.bodies[h].is_sleeping()));
    assert_eq!(world.physics.islands.num_active_bodies(), 0);
    // One step carried the body through the emptied awake island, then removed it.
    assert_eq!(world.soft.counters().awake_islands_cleared, 1);
    let (p, f) = (poses(&world, &balls), forces(&world));
    assert_eq!(f.len(), 10);
    for _ in 0..200 {
        world.step();
    }
    assert!(world.try_step().is_ok());
    // Nothing moved, nothing was added, and the clearing did not repeat.
    assert_eq!(world.physics.bodies.len(), bodies);
    assert_eq!(world.physics.islands.num_active_bodies(), 0);
    assert_eq!(world.soft.counters().awake_islands_cleared, 1);
    assert_eq!(poses(&world, &balls), p);
    assert_eq!(forces(&world), f);
    assert_eq!(world.soft.counters().woken, 0);
}

#[test]
fn a_fingertip_woken_among_sleeping_ones_sleeps_again_and_clears_again() {
    let (mut world, balls) = settled_ten();
    let before = poses(&world, &balls);
    // Tossed up 0.14 m/s (about 1 mm high) from its rest: it wakes, lands, settles.
    let hit = &mut world.physics.bodies[balls[0]];
    hit.set_linvel(Vector::new(0.0, 0.14, 0.0), true);
    let mut woke = false;
    for _ in 0..240 {
        world.step();
        woke |= !world.physics.bodies[balls[0]].is_sleeping();
    }
    assert!(woke, "the tossed fingertip never woke");
    // It moved; every ball is asleep again, and the island emptied by that was cleared.
    let after = poses(&world, &balls);
    assert_ne!(after[0], before[0]);
    assert!(balls.iter().all(|&h| world.physics.bodies[h].is_sleeping()));
    assert_eq!(world.physics.islands.num_active_bodies(), 0);
    assert_eq!(world.soft.counters().awake_islands_cleared, 2);
    // The others were not touched, and no body was added.
    assert_eq!(after[1..], before[1..]);
    assert_eq!(world.physics.bodies.len(), 10);
}
