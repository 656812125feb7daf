//! rapier's contact points a few millimetres apart and the coupled solve: a box that a
//! fingertip pushes along the table towards a fixed wall slides until it touches the wall,
//! whatever its start gap. rapier 0.36 allows 5 mm of linear error and keeps contact points up
//! to its 2 cm prediction distance. Before session 34 every point within those 5 mm entered
//! the coupled solve as a hard row asking `v(end) >= 0`: the box stopped at its start gap as if
//! it touched the wall, and the pad pushing it was crushed (88.9 N from 1 mm, 230.7 N from
//! 2.5 mm, 744.6 N from 4.5 mm). Session 33's rule (such a point kept in the solve, free to
//! close its gap within the substep) threw the box at 2.2-82 m/s from 2.5-4.5 mm. Now a point
//! further apart than a tenth of that error is rapier's own (`problem::TOUCH_FRACTION`).
//!
//! Start gaps past 5 mm are the long push below (ignored): the pad's force is lost while the
//! box slides along the table, whatever the rule for the wall's points.
//!
//! `cargo test -p softgrip-rapier --test gap_rows -- --nocapture` prints the numbers.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use rapier3d::prelude::*;
use softgrip_law::Level;
use softgrip_rapier::SoftWorld;
use softgrip_testkit::scenes::{RADIUS as R, fingertip};

/// Half extent of the box \[m\] (a 2 cm box of 4 g).
const HALF: f32 = 0.01;

/// One push: the box's gap to the wall \[m\] and its speed \[m/s\] at the end of the hold, and
/// the soft contact's force then \[N\]; `gap` is its start gap \[m\], `press` how far the
/// fingertip goes past the box's start contact and the gap \[m\], `recycling` rapier's
/// contact recycling.
#[derive(Debug, Clone, Copy)]
struct Pushed {
    gap: f64,
    speed: f64,
    force: f64,
}

fn push(gap: f32, press: f64, recycling: bool) -> Pushed {
    let mut world = SoftWorld::new();
    world.physics.integration_parameters.contact_recycling = recycling;
    world
        .physics
        .colliders
        .insert(ColliderBuilder::cuboid(0.2, 0.01, 0.2).translation(Vector::new(0.0, -0.01, 0.0)));
    // The wall's face at x = -HALF - gap.
    world.physics.colliders.insert(
        ColliderBuilder::cuboid(0.01, 0.1, 0.2).translation(Vector::new(
            -HALF - gap - 0.01,
            0.1,
            0.0,
        )),
    );
    let b = world.physics.bodies.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, HALF, 0.0))
            .can_sleep(false),
    );
    world.physics.colliders.insert_with_parent(
        ColliderBuilder::cuboid(HALF, HALF, HALF).density(500.0),
        b,
        &mut world.physics.bodies,
    );
    let start = Vector::new(HALF + R as f32 + 0.001, HALF, 0.0);
    let (tip_body, _) = common::kinematic_tip(
        &mut world,
        start,
        fingertip(Level::Calibrated, 0.5).build().unwrap(),
    );
    for _ in 0..30 {
        world.step();
    }
    // 1 mm to the box, the gap, then `press` into the pad, at 10 mm/s; then 30 steps of hold.
    let dt = world.physics.integration_parameters.dt as f64;
    let travel = 0.001 + gap as f64 + press;
    let steps = (travel / (0.01 * dt)).ceil() as usize;
    for k in 1..=steps + 30 {
        let s = (k.min(steps) as f64 * 0.01 * dt).min(travel) as f32;
        world.physics.bodies[tip_body].set_next_kinematic_translation(start - Vector::X * s);
        world.step();
    }
    let body = &world.physics.bodies[b];
    Pushed {
        gap: (body.translation().x + gap) as f64,
        speed: body.linvel().length() as f64,
        force: world.soft.contacts().iter().map(|c| c.normal_force).sum(),
    }
}

/// How far the fingertip presses past the box's start contact and its gap \[m\].
const PRESS: f64 = 1.5e-3;

/// The box's rest gap to the wall that counts as touching it \[m\]: a tenth of rapier's
/// allowed linear error (`problem::TOUCH_FRACTION`), and 0.1 mm over it.
const TOUCHING: f64 = 0.6e-3;

#[test]
fn a_pushed_box_slides_across_its_gap_to_the_wall_and_rests_there() {
    // The box touching the wall from the start: the pad pressed the whole 1.5 mm.
    let touching = push(0.0, PRESS, true);
    println!("start gap 0: {touching:?}");
    assert!(touching.gap.abs() < 0.1e-3, "{touching:?}");
    // The same, pressed further by the most a touching rest gap leaves.
    let deepest = push(0.0, PRESS + TOUCHING, true);
    println!(
        "start gap 0, pressed {} mm more: {deepest:?}",
        TOUCHING * 1e3
    );
    for recycling in [true, false] {
        for gap_mm in [0.4f32, 1.0, 2.5, 3.5, 4.5] {
            let p = push(gap_mm * 1e-3, PRESS, recycling);
            println!("start gap {gap_mm} mm, recycling {recycling}: {p:?}");
            // At rest within rapier's resting tolerance of the wall, not held short of it.
            assert!(
                p.gap > -0.1e-3 && p.gap < TOUCHING,
                "start gap {gap_mm} mm, recycling {recycling}: the box rests {} mm from the wall",
                p.gap * 1e3
            );
            assert!(
                p.speed < 1e-3,
                "start gap {gap_mm} mm: the box moves at {} m/s",
                p.speed
            );
            // The pad pressed 1.5 mm and the box's rest gap: between its force with the box
            // touching from the start and that pressed by the most a rest gap may leave; not
            // crushed, not let go.
            assert!(
                p.force > 0.99 * touching.force && p.force < 1.01 * deepest.force,
                "start gap {gap_mm} mm, recycling {recycling}: the pad reads {} N, not in {} - {} N",
                p.force,
                touching.force,
                deepest.force
            );
        }
    }
}

/// A longer push: the box slides 5.5-30 mm before it meets the wall. While it slides at the
/// fingertip's 10 mm/s the pad reads about 0.01-0.03 N (the box's friction on the table, right
/// as an impulse) but the fingertip's ball overlaps the box by 0.3-1.1 mm, where the law gives
/// 4-20 N, and at the wall the overlap is not taken up as force: measured (session 34), from
/// 5.5 / 6 / 8 / 12 / 30 mm with rapier's contact recycling on, the box 0.50-0.62 mm from
/// the wall but still moving at 1.3-1.7 cm/s, the pad at 0.019-0.030 N about 2 mm deep;
/// with recycling off, from 30 mm the box is thrown 0.2 m (the rule before session 34: held
/// 4.9 mm from the wall, the pad crushed to 950 N). Found while writing the test above; not
/// understood yet (softgrip-rapier README, Limits).
#[test]
#[ignore = "the pad's force is lost while a pushed box slides (session 34): from 8 mm the pad reads 0.021 N about 2 mm into the box at the wall; softgrip-rapier README, Limits"]
fn a_box_pushed_further_along_the_table_loads_the_pad_at_the_wall() {
    let touching = push(0.0, PRESS, true);
    let deepest = push(0.0, PRESS + TOUCHING, true);
    for recycling in [true, false] {
        for gap_mm in [5.5f32, 8.0, 30.0] {
            let p = push(gap_mm * 1e-3, PRESS, recycling);
            println!("start gap {gap_mm} mm, recycling {recycling}: {p:?}");
            assert!(p.gap > -0.1e-3 && p.gap < TOUCHING, "{gap_mm} mm: {p:?}");
            assert!(p.speed < 1e-3, "{gap_mm} mm: {p:?}");
            assert!(
                p.force > 0.99 * touching.force && p.force < 1.01 * deepest.force,
                "{gap_mm} mm, recycling {recycling}: {p:?}"
            );
        }
    }
}
