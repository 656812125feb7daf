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
//! Session 35: from start gaps past 5 mm the wall never held the box (the pad at 0.02 N, 2 mm
//! into the box at the wall): rapier's contact recycling keeps a manifold's points and their
//! `dist` from the pair's last full update while the pair moves less than 5 cm, and the points
//! were read by that stale `dist` (8 mm from an 8 mm start) instead of the gap at the current
//! poses. Fixed (`step.rs`, `push_pair_points`); from 5.5-12 mm the box now rests at the wall
//! like the shorter pushes. Still open: while the box slides, the fingertip's ball overlaps it
//! by about 1 mm at the table friction's force (the ignored test below).
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

/// One push: the box's gap to the wall \[m\] and its speed \[m/s\] at the end of the hold, the
/// soft contact's force then \[N\], and the largest overlap of the fingertip's ball with the box
/// while the box slid more than 1 mm from the wall \[m\]; `gap` is its start gap \[m\], `press`
/// how far the fingertip goes past the box's start contact and the gap \[m\], `recycling`
/// rapier's contact recycling.
#[derive(Debug, Clone, Copy)]
struct Pushed {
    gap: f64,
    speed: f64,
    force: f64,
    slide_overlap: f64,
}

fn push(gap: f32, press: f64, recycling: bool) -> Pushed {
    push_with(gap, press, recycling, false).0
}

/// [`push`], with a second box between the pushed one and the wall (touching the wall, `gap`
/// from the first) if `second`; also returns the second box's gap to the wall at the end \[m\]
/// (0 without it). The returned `gap` is the pushed box's to what it closes on.
fn push_with(gap: f32, press: f64, recycling: bool, second: bool) -> (Pushed, f64) {
    let mut world = SoftWorld::new();
    world.physics.integration_parameters.contact_recycling = recycling;
    world
        .physics
        .colliders
        .insert(ColliderBuilder::cuboid(0.2, 0.01, 0.2).translation(Vector::new(0.0, -0.01, 0.0)));
    // The wall's face at x = -HALF - gap (and a box's width further with the second box).
    let shift = if second { 2.0 * HALF } else { 0.0 };
    world.physics.colliders.insert(
        ColliderBuilder::cuboid(0.01, 0.1, 0.2).translation(Vector::new(
            -HALF - gap - shift - 0.01,
            0.1,
            0.0,
        )),
    );
    let mut add_box = |x: f32| {
        let b = world.physics.bodies.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(x, HALF, 0.0))
                .can_sleep(false),
        );
        world.physics.colliders.insert_with_parent(
            ColliderBuilder::cuboid(HALF, HALF, HALF).density(500.0),
            b,
            &mut world.physics.bodies,
        );
        b
    };
    let b = add_box(0.0);
    let other = second.then(|| add_box(-gap - 2.0 * HALF));
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
    let mut slide_overlap = 0.0f64;
    for k in 1..=steps + 30 {
        let s = (k.min(steps) as f64 * 0.01 * dt).min(travel) as f32;
        world.physics.bodies[tip_body].set_next_kinematic_translation(start - Vector::X * s);
        world.step();
        let x = world.physics.bodies[b].translation().x;
        if x + gap > 1e-3 {
            let tip = world.physics.bodies[tip_body].translation().x;
            slide_overlap = slide_overlap.max(R - (tip - x - HALF) as f64);
        }
    }
    let body = &world.physics.bodies[b];
    // The second box's gap to the wall, and the pushed box's to it.
    let (second_gap, closes_on) = match other {
        Some(o) => {
            let x = world.physics.bodies[o].translation().x;
            ((x + gap + 2.0 * HALF) as f64, (x + 2.0 * HALF) as f64)
        }
        None => (0.0, -gap as f64),
    };
    let speed = other.map_or(0.0, |o| world.physics.bodies[o].linvel().length() as f64);
    (
        Pushed {
            gap: body.translation().x as f64 - closes_on,
            speed: (body.linvel().length() as f64).max(speed),
            force: world.soft.contacts().iter().map(|c| c.normal_force).sum(),
            slide_overlap,
        },
        second_gap,
    )
}

/// How far the fingertip presses past the box's start contact and its gap \[m\].
const PRESS: f64 = 1.5e-3;

/// The box's rest gap to the wall that counts as touching it \[m\]: a tenth of rapier's
/// allowed linear error (`problem::TOUCH_FRACTION`), and 0.1 mm over it.
const TOUCHING: f64 = 0.6e-3;

/// The pad's force bracket for a box pressed against what it closes on: the box touching the
/// wall from the start (the pad pressed the whole [`PRESS`]), and the same pressed further by
/// the most a touching rest gap ([`TOUCHING`]) leaves.
fn bracket() -> (Pushed, Pushed) {
    (push(0.0, PRESS, true), push(0.0, PRESS + TOUCHING, true))
}

/// Asserts that push `p` (`what` names it) ended at rest within the touch tolerance of what
/// it closes on (not held short of it), slower than `speed` \[m/s\], its pad between the
/// bracket's forces (within 1 %): not crushed, not let go.
fn assert_rests(p: &Pushed, (touching, deepest): &(Pushed, Pushed), speed: f64, what: &str) {
    assert!(
        p.gap > -0.1e-3 && p.gap < TOUCHING,
        "{what}: the box rests {} mm from what it closes on ({p:?})",
        p.gap * 1e3
    );
    assert!(p.speed < speed, "{what}: the box moves at {} m/s", p.speed);
    assert!(
        p.force > 0.99 * touching.force && p.force < 1.01 * deepest.force,
        "{what}: the pad reads {} N, not in {} - {} N",
        p.force,
        touching.force,
        deepest.force
    );
}

#[test]
fn a_pushed_box_slides_across_its_gap_to_the_wall_and_rests_there() {
    let bracket = bracket();
    let (touching, deepest) = &bracket;
    println!("start gap 0: {touching:?}");
    assert!(touching.gap.abs() < 0.1e-3, "{touching:?}");
    println!(
        "start gap 0, pressed {} mm more: {deepest:?}",
        TOUCHING * 1e3
    );
    for recycling in [true, false] {
        for gap_mm in [0.4f32, 1.0, 2.5, 3.5, 4.5, 5.5, 8.0, 12.0] {
            let p = push(gap_mm * 1e-3, PRESS, recycling);
            println!("start gap {gap_mm} mm, recycling {recycling}: {p:?}");
            let what = format!("start gap {gap_mm} mm, recycling {recycling}");
            assert_rests(&p, &bracket, 1e-3, &what);
        }
    }
}

/// The pushed box closes on a second box that rests against the wall: the pair of boxes is a
/// rigid row between two dynamic bodies (`Step::prepare_rigid` queues the bodies a soft
/// contact's body touches), whose recycled points were read by their stale `dist` like the
/// wall's before session 35. Measured (`-- --nocapture`, session 35): from 2.5 / 8 / 12 mm,
/// recycling on and off, the boxes rest 0.02-0.14 mm apart and the second within 0.13 mm of
/// the wall, the pad at 40.0-43.6 N, in the same bracket as one box pressed against the wall;
/// the boxes' stored speeds 0.17-1.38 mm/s (the same rapier-side residue as the slide's,
/// below; bound 2 mm/s). Before the fix (main 7f2d5af), with recycling on, the 8 and 12 mm
/// pushes ended with the pad at 0.013 / 0.015 N and the boxes at 2.8 / 7.9 mm/s.
#[test]
fn a_pushed_box_closes_on_a_second_box_at_the_wall() {
    let bracket = bracket();
    for recycling in [true, false] {
        for gap_mm in [2.5f32, 8.0, 12.0] {
            let (p, second_gap) = push_with(gap_mm * 1e-3, PRESS, recycling, true);
            println!(
                "start gap {gap_mm} mm to the second box, recycling {recycling}: {p:?}, the second box {:.3e} m from the wall",
                second_gap
            );
            let what = format!("{gap_mm} mm to the second box, recycling {recycling}");
            assert_rests(&p, &bracket, 2e-3, &what);
            assert!(
                second_gap > -0.1e-3 && second_gap < TOUCHING,
                "{what}: the second box {second_gap} m from the wall"
            );
        }
    }
}

/// The push while the box slides: at the fingertip's 10 mm/s the pad must carry only the
/// box's friction on the table (mu m g = 0.020 N for the 4 g box at mu 0.5), which the law
/// gives at a few micrometres of compression. Measured (session 35, `-- --include-ignored
/// --nocapture`): the pad reads 0.01-0.03 N, right as a force, but the ball overlaps the box
/// by 0.8-1.4 mm while it slides (the law gives 10-40 N there), and from 30 mm the box ends
/// 0.3 mm from the wall still moving at 1.3 mm/s (rapier's contact recycling on) or is thrown
/// through the fingertip and 0.2 m away when the box meets the wall (recycling off). What
/// the probes showed: each step the coupled solve, which leaves the box's friction under its
/// weight to rapier, lets the pad's overlap go by sending the box away at 4-6 cm/s; rapier's
/// own step then stops it and leaves it moving at +1.2 cm/s towards the fingertip, so the
/// overlap is never taken up. Handing that friction to the solve (its disk `mu j_n` whole,
/// rapier's expected share taken off what the plugin applies) and solving rapier's part from
/// gravity alone each left the overlap as it was. Open (softgrip-rapier README, Limits).
#[test]
#[ignore = "the fingertip overlaps a box it pushes along the table by about 1 mm at friction force (session 35); softgrip-rapier README, Limits"]
fn a_box_pushed_along_the_table_compresses_the_pad_only_as_its_friction_asks() {
    let bracket = bracket();
    for recycling in [true, false] {
        for gap_mm in [8.0f32, 30.0] {
            let p = push(gap_mm * 1e-3, PRESS, recycling);
            println!("start gap {gap_mm} mm, recycling {recycling}: {p:?}");
            // 0.1 mm of the ball's overlap is about 0.6 N on this pad, 30 times the friction.
            assert!(p.slide_overlap < 0.1e-3, "{gap_mm} mm: {p:?}");
            assert_rests(
                &p,
                &bracket,
                1e-3,
                &format!("{gap_mm} mm, recycling {recycling}"),
            );
        }
    }
}
