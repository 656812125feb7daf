//! The coupled solve's group sizes (issue 23 item 6): fingertips resting on a plane apart from
//! each other are independent contacts, each a group of one, whatever N. Before session 10 a
//! grid of resting balls 10 mm apart (within the detection's prediction distance of each
//! other) was one dense group of every ball (N = 1000: 2936 rows, 0.47-0.92 s per step).
//! `SoftCounters::largest_group` reads the most soft rows any solve coupled.
//!
//! `cargo test -p softgrip-rapier --test groups -- --nocapture` prints the numbers.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_testkit::resting::resting_grid;

/// `n` resting balls on a square grid of `pitch` \[m\] (`softgrip_testkit::resting`, the
/// overhead benchmark's scene); `steps` steps; the largest group any solve coupled.
fn resting(n: usize, pitch: f32, steps: usize) -> (u64, usize) {
    let mut world = resting_grid(n, pitch, true);
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
        let (largest, touching) = resting(n, pitch, 60);
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
    let (largest, touching) = resting(4, 0.0195, 30);
    println!("4 touching tips in a 2 x 2 square: largest group {largest}, {touching} contacts");
    assert!(largest >= 8, "largest group {largest}");
}
