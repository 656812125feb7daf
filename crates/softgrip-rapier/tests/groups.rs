//! The coupled solve's group sizes (issue 23 item 6): fingertips resting on a plane apart from
//! each other are independent contacts, each a group of one, whatever N. Before session 10 a
//! grid of resting balls 10 mm apart (within the detection's prediction distance of each
//! other) was one dense group of every ball (N = 1000: 2936 rows, 0.47-0.92 s per step).
//! `SoftCounters::largest_group` reads the most soft rows any solve coupled.
//!
//! `cargo test -p softgrip-rapier --test groups -- --nocapture` prints the numbers.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use rapier3d::prelude::*;
use softgrip_law::{Level, Material};
use softgrip_rapier::{SoftFingertip, SoftWorld};

const RADIUS: f64 = 0.01;
const DENSITY: f32 = 1070.0;

fn tip() -> SoftFingertip {
    SoftFingertip::builder(RADIUS)
        .material(Material::try_new(3.0e6, 0.49).unwrap())
        .level(Level::auto())
        .restitution(0.5)
        .build()
        .unwrap()
}

/// `n` balls on a square grid of `pitch` \[m\] (centre to centre) on a fixed ground, each at
/// its resting depth; `steps` steps; the largest group any solve coupled.
fn resting_grid(n: usize, pitch: f32, steps: usize) -> (u64, usize) {
    let mut world = SoftWorld::new();
    let side = (n as f64).sqrt().ceil() as usize;
    let half = 0.5 * side as f32 * pitch + pitch;
    world.physics.colliders.insert(
        ColliderBuilder::cuboid(half, 0.01, half).translation(Vector::new(0.0, -0.01, 0.0)),
    );
    let mass = DENSITY as f64 * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3);
    let rest = tip().law().compression_for_force(mass * 9.81).unwrap();
    for i in 0..n {
        let (row, col) = (i / side, i % side);
        let x = (col as f32 - 0.5 * (side - 1) as f32) * pitch;
        let z = (row as f32 - 0.5 * (side - 1) as f32) * pitch;
        let body = world.physics.bodies.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(x, (RADIUS - rest) as f32, z))
                .can_sleep(false),
        );
        let ball = world.physics.colliders.insert_with_parent(
            ColliderBuilder::ball(RADIUS as f32).density(DENSITY),
            body,
            &mut world.physics.bodies,
        );
        world.register(ball, tip()).unwrap();
    }
    for _ in 0..steps {
        world.step();
    }
    let touching = world
        .soft
        .contacts()
        .iter()
        .filter(|c| c.delta > 0.0)
        .count();
    (world.soft.counters().largest_group, touching)
}

#[test]
fn resting_fingertips_apart_are_groups_of_one() {
    // Gaps of 10 mm (pitch 3 R, the benchmarks' grid) and of 2 mm, within the detection's
    // prediction distance of the neighbours.
    for (n, pitch) in [(100, 0.03), (400, 0.03), (100, 0.022)] {
        let (largest, touching) = resting_grid(n, pitch, 60);
        println!("{n} resting tips, pitch {pitch} m: largest group {largest}, {touching} contacts");
        assert_eq!(touching, n, "each ball rests on the ground");
        assert_eq!(
            largest, 1,
            "{n} tips at pitch {pitch}: coupled into a group of {largest}"
        );
    }
}

#[test]
fn touching_fingertips_are_one_group() {
    // The counter reads a real coupling: a row of balls touching each other (pitch 2 R less
    // 0.5 mm) couples every ball's ground contact and every ball-ball contact into one group.
    let (largest, touching) = resting_grid(4, 0.0195, 30);
    println!("4 touching tips in a 2 x 2 square: largest group {largest}, {touching} contacts");
    assert!(largest >= 8, "largest group {largest}");
}
