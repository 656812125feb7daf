//! A fingertip pressing an object against rapier's rigid bodies: a box on a fixed table,
//! pressed down by a kinematic fingertip (free and flat-backed); a box on a box on the table;
//! a box pressed sideways against a wall. The soft contact must carry the law's force at its
//! compression (the plugin's solve sees the box's rigid contacts, `src/rigid.rs`), the box
//! must stay put, and nothing may be thrown. Before the rigid contacts were in the solve, the
//! first case read 0 N while the tip sank through the box.
//!
//! `cargo test -p softgrip-rapier --test press_on_table -- --nocapture` prints the numbers.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use rapier3d::prelude::*;
use softgrip_law::{Backing, ContactLaw, Level};
use softgrip_rapier::SoftWorld;
use softgrip_testkit::scenes::{RADIUS as R, fingertip};

/// Half extent of the boxes \[m\].
const HALF: f32 = 0.01;
/// Density of the boxes [kg/m^3] (a 2 cm box of 4 g).
const DENSITY: f32 = 500.0;

struct Press {
    world: SoftWorld,
    tip_body: RigidBodyHandle,
    boxes: Vec<(RigidBodyHandle, ColliderHandle)>,
    law: ContactLaw,
    /// Direction of the tip's travel.
    dir: Vector,
}

/// `stack` boxes on a fixed table (top face y = 0), a kinematic fingertip 1 mm above the top
/// box; with `wall`, the box sits against a fixed wall at x = -HALF and the tip comes from +x
/// instead.
fn scene(stack: usize, wall: bool, backing: Backing) -> Press {
    scene_with(stack, wall, backing, DENSITY)
}

/// [`scene`] with boxes of `density` [kg/m^3].
fn scene_with(stack: usize, wall: bool, backing: Backing, density: f32) -> Press {
    let mut world = SoftWorld::new();
    world
        .physics
        .colliders
        .insert(ColliderBuilder::cuboid(0.2, 0.01, 0.2).translation(Vector::new(0.0, -0.01, 0.0)));
    if wall {
        world.physics.colliders.insert(
            ColliderBuilder::cuboid(0.01, 0.1, 0.2).translation(Vector::new(
                -HALF - 0.01,
                0.1,
                0.0,
            )),
        );
    }
    let mut boxes = Vec::new();
    for k in 0..stack {
        let b = world.physics.bodies.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, HALF * (2 * k + 1) as f32, 0.0))
                .can_sleep(false),
        );
        let c = world.physics.colliders.insert_with_parent(
            ColliderBuilder::cuboid(HALF, HALF, HALF).density(density),
            b,
            &mut world.physics.bodies,
        );
        boxes.push((b, c));
    }
    let top = 2.0 * HALF * stack as f32;
    let (start, dir) = if wall {
        (Vector::new(HALF + R as f32 + 0.001, HALF, 0.0), -Vector::X)
    } else {
        (Vector::new(0.0, top + R as f32 + 0.001, 0.0), -Vector::Y)
    };
    let tip_body = world
        .physics
        .bodies
        .insert(RigidBodyBuilder::kinematic_position_based().translation(start));
    let tip = world.physics.colliders.insert_with_parent(
        ColliderBuilder::ball(R as f32),
        tip_body,
        &mut world.physics.bodies,
    );
    let mut b = fingertip(Level::Calibrated, 0.5).backing(backing);
    if backing != Backing::Free {
        // The pad faces the box (from its flat face towards its pole: the travel).
        b = b.facing([dir.x as f64, dir.y as f64, dir.z as f64]);
    }
    let ft = b.build().unwrap();
    let law = ft.law().clone();
    world.register(tip, ft).unwrap();
    // Let the boxes settle on the table (rapier's own resting penetration).
    for _ in 0..30 {
        world.step();
    }
    Press {
        world,
        tip_body,
        boxes,
        law,
        dir,
    }
}

/// What one press measured.
#[derive(Debug)]
struct Measured {
    /// Worst |F / F_law(delta) - 1| over the hold.
    worst: f64,
    /// The soft contact's force at the end of the hold \[N\].
    force: f64,
    /// The soft contact's friction force (magnitude) at the end of the hold \[N\].
    friction: f64,
    /// Largest displacement of a box from its settled position \[m\].
    moved: f64,
    /// Largest speed of a box (displacement per step, rotation at its corners), over the
    /// whole run [m/s].
    speed: f64,
    /// Largest speed of a box over the second half of the hold [m/s].
    speed_hold: f64,
    /// Largest displacement of a box over the hold, from its position at the hold's start
    /// (the drift) \[m\].
    drift_hold: f64,
    /// Largest displacement of a box over the hold's second half, from its position at the
    /// hold's middle (a drift that goes on once the first half has settled) \[m\].
    drift_late: f64,
}

/// Drives the tip `depth` \[m\] into the top box at 10 mm/s, holds it for `hold` steps (the
/// force is read against the law over the hold), then lifts it off again at 10 mm/s.
fn press(p: &mut Press, depth: f64, hold: usize) -> Measured {
    let dt = p.world.physics.integration_parameters.dt as f64;
    let start = p.world.physics.bodies[p.tip_body].translation();
    let travel = 0.001 + depth;
    let box0: Vec<Vector> = p
        .boxes
        .iter()
        .map(|(b, _)| p.world.physics.bodies[*b].translation())
        .collect();
    let mut last: Vec<Pose> = p
        .boxes
        .iter()
        .map(|(b, _)| *p.world.physics.bodies[*b].position())
        .collect();
    let top_col = p.boxes.last().unwrap().1;
    let mut m = Measured {
        worst: 0.0,
        force: 0.0,
        friction: 0.0,
        moved: 0.0,
        speed: 0.0,
        speed_hold: 0.0,
        drift_hold: 0.0,
        drift_late: 0.0,
    };
    let mut hold0 = box0.clone();
    let mut mid = box0.clone();
    let steps_in = (travel / (0.01 * dt)).ceil() as usize;
    let total = 2 * steps_in + hold;
    for i in 0..total {
        let s = if i < steps_in + hold {
            ((i + 1) as f64 * 0.01 * dt).min(travel)
        } else {
            (travel - (i + 1 - steps_in - hold) as f64 * 0.01 * dt).max(0.0)
        };
        p.world.physics.bodies[p.tip_body].set_next_kinematic_translation(start + p.dir * s as f32);
        p.world.step();
        for (((((b, _), b0), prev), h0), m0) in p
            .boxes
            .iter()
            .zip(&box0)
            .zip(last.iter_mut())
            .zip(hold0.iter_mut())
            .zip(mid.iter_mut())
        {
            let rb = &p.world.physics.bodies[*b];
            let d = (rb.translation() - *b0).length() as f64;
            // The speed from the poses (rapier's stored velocity of a body carries its passes'
            // lag, `a h / (2N)`, see `step.rs`).
            let pose = *rb.position();
            let v = ((pose.translation - prev.translation).length() as f64
                + HALF as f64
                    * (pose.rotation * prev.rotation.inverse())
                        .to_axis_angle()
                        .1
                        .abs() as f64)
                / dt;
            *prev = pose;
            if i == steps_in {
                *h0 = pose.translation;
            }
            if i >= steps_in && i < steps_in + hold {
                m.drift_hold = m.drift_hold.max((pose.translation - *h0).length() as f64);
            }
            if i == steps_in + hold / 2 {
                *m0 = pose.translation;
            }
            if i > steps_in + hold / 2 && i < steps_in + hold {
                m.drift_late = m.drift_late.max((pose.translation - *m0).length() as f64);
            }
            assert!(d.is_finite() && v.is_finite(), "step {i}: {d} {v}");
            m.moved = m.moved.max(d);
            m.speed = m.speed.max(v);
            if i >= steps_in + hold / 2 && i < steps_in + hold {
                m.speed_hold = m.speed_hold.max(v);
            }
        }
        if i >= steps_in + 10 && i < steps_in + hold {
            let c = p
                .world
                .soft
                .contacts()
                .iter()
                .find(|c| c.other == top_col)
                .unwrap_or_else(|| panic!("step {i}: the tip touches the box"));
            let f_law = p.law.response(c.delta).force;
            m.worst = m.worst.max((c.normal_force / f_law - 1.0).abs());
            m.force = c.normal_force;
            m.friction = c.friction_force.iter().map(|f| f * f).sum::<f64>().sqrt();
        }
    }
    m
}

// Measured (`-- --nocapture`): worst |F/F_law - 1| 3.4e-7 (free) / 4.4e-7 (flat), box moved
// 0.04 um, speed 0.7 um/s at most, 0.06 um/s in the hold. The asserted bands leave a factor
// of 10-30; the bug read F = 0 with the tip through the box.
fn assert_box_on_table(m: &Measured) {
    assert!(m.worst < 1e-5, "{m:?}");
    assert!(m.force > 50.0, "{m:?}");
    assert!(m.moved < 1e-6, "{m:?}");
    assert!(m.speed < 1e-5, "{m:?}");
    assert!(m.speed_hold < 1e-6, "{m:?}");
    assert!(m.drift_hold < 1e-6, "{m:?}");
}

#[test]
fn free_tip_presses_a_box_on_the_table() {
    let mut p = scene(1, false, Backing::Free);
    let m = press(&mut p, 0.002, 120);
    println!("free tip, box on the table, 2 mm: {m:?}");
    assert_box_on_table(&m);
}

#[test]
fn flat_tip_presses_a_box_on_the_table() {
    let mut p = scene(1, false, Backing::Flat);
    let m = press(&mut p, 0.002, 120);
    println!("flat-backed tip, box on the table, 2 mm: {m:?}");
    assert_box_on_table(&m);
}

#[test]
fn tip_presses_a_stack_of_two_boxes() {
    for backing in [Backing::Free, Backing::Flat] {
        let mut p = scene(2, false, backing);
        let m = press(&mut p, 0.002, 120);
        println!("{backing:?} tip, two boxes on the table, 2 mm: {m:?}");
        // Measured: worst 7.1e-7 / 7.4e-7, moved 24 um (the lower box settles into the
        // table under the load), speed 0.14 mm/s at most (on contact), 0.11 um/s in the hold.
        assert!(m.worst < 1e-5, "{backing:?}: {m:?}");
        assert!(m.force > 25.0, "{backing:?}: {m:?}");
        assert!(m.moved < 5e-5, "{backing:?}: {m:?}");
        assert!(m.speed < 5e-4, "{backing:?}: {m:?}");
        assert!(m.speed_hold < 1e-6, "{backing:?}: {m:?}");
        assert!(m.drift_hold < 8e-6, "{backing:?}: {m:?}");
    }
}

/// Issue 23 item 4: a box 10x as heavy (40 g) pressed on the table, by a free and a
/// flat-backed tip: the same bands as the 4 g box.
#[test]
fn tip_presses_a_heavy_box_on_the_table() {
    for backing in [Backing::Free, Backing::Flat] {
        let mut p = scene_with(1, false, backing, 10.0 * DENSITY);
        let m = press(&mut p, 0.002, 120);
        println!("{backing:?} tip, heavy (40 g) box on the table, 2 mm: {m:?}");
        assert_box_on_table(&m);
    }
}

/// Issue 23 item 4: a stack of three boxes pressed by the tip; the hold is 2 s (the drift
/// over it is asserted, as the rattle).
#[test]
fn tip_presses_a_stack_of_three_boxes() {
    for backing in [Backing::Free, Backing::Flat] {
        let mut p = scene(3, false, backing);
        // rapier lets each of its contacts sink by up to its allowed linear error (1 mm): the
        // settled stack's top is 1.8 mm below its nominal 60 mm, so the tip starts 1 mm
        // above where the top box is, as over one box.
        let top = p.world.physics.bodies[p.boxes[2].0].translation().y + HALF;
        let start = Vector::new(0.0, top + R as f32 + 0.001, 0.0);
        let tip = &mut p.world.physics.bodies[p.tip_body];
        tip.set_translation(start, true);
        tip.set_next_kinematic_translation(start);
        p.world.step();
        let m = press(&mut p, 0.002, 120);
        println!("{backing:?} tip, three boxes on the table, 2 mm: {m:?}");
        // Measured (free / flat): worst 9.9e-6 / 1.1e-5, 54.5 / 70.2 N, moved 97 um, speed
        // 0.57 mm/s at most (on contact), 0.70 / 0.78 um/s in the hold's second half; over the
        // hold the top box sinks 19 um, in its first half: rapier's stacked contacts settle
        // under the press (two boxes: 3.8 um). Session 21, the spring default: 0.81 / 0.80
        // um/s in the hold's second half, 0.12 / 0.13 um over it (the drift that goes on once
        // the first half has settled; bound 0.5 um).
        assert!(m.worst < 2e-5, "{backing:?}: {m:?}");
        assert!(m.force > 40.0, "{backing:?}: {m:?}");
        assert!(m.moved < 2e-4, "{backing:?}: {m:?}");
        assert!(m.speed < 1e-3, "{backing:?}: {m:?}");
        assert!(m.speed_hold < 1e-6, "{backing:?}: {m:?}");
        assert!(m.drift_hold < 4e-5, "{backing:?}: {m:?}");
        assert!(m.drift_late < 5e-7, "{backing:?}: {m:?}");
    }
}

/// A box on the table pressed sideways into a wall with 60 N: the force follows the law and the
/// box is still in the hold. Before the rigid rows' compliance pulled towards rapier's own part
/// (`src/rigid.rs`, `Scalar::prox`), the least-impulse answer let the wall's friction carry
/// part of the weight rapier carries on the table anyway: the box rattled at ~1.4 cm/s (its
/// centre moved by up to 0.32 mm) and the force was 0.56 % off the law.
///
/// With the default friction (Mindlin's tangential spring since session 19), issue 23 item 4's
/// bounds: the force within 0.1 % of the law over the hold, the box still (< 1 um/s over the
/// hold's second half) and not drifting (< 1 um over the hold, < 0.1 um over its second
/// half); along the wall the tip carries less than the box's weight. The rigid stick keeps
/// the bounds set for it: [`rigid_stick_presses_a_box_against_a_wall`]. Before rapier's part
/// of the table's normal impulses was split per pair of bodies (`rigid::pair_scales`), the
/// spring's run left the box spinning at up to 7.6 rad/s for rapier to stop, the spring held
/// each jump that made (8.3 N along the wall), the box moved at 11 mm/s in the hold and was
/// thrown when the tip withdrew (66 mm, 1.4 m/s). (This was
/// `friction_spring_presses_a_box_against_a_wall` until the spring became the default: the
/// same run.)
// Measured (`-- --nocapture`, session 21, the spring default): worst 3.1e-6, 59.76 N,
// friction 0.0115 N, moved 8.8 um, 1.7 mm/s at most (the approach), 1.2e-8 m/s in the hold's
// second half, drift 0.57 um over the hold (its first steps), 2.1e-9 m over its second half.
#[test]
fn tip_presses_a_box_against_a_wall() {
    let mut p = scene(1, true, Backing::Free);
    let m = press(&mut p, 0.002, 120);
    println!("free tip, box against a wall, 2 mm: {m:?}");
    assert!(m.worst < 1e-3, "{m:?}");
    assert!(m.force > 50.0, "{m:?}");
    assert!(m.moved < 5e-5, "{m:?}");
    assert!(m.speed < 5e-3, "{m:?}");
    // Issue 23's bound is 1 um/s; the spring's run has held 1e-7 since session 19.
    assert!(m.speed_hold < 1e-7, "{m:?}");
    assert!(m.drift_hold < 1e-6, "{m:?}");
    assert!(m.drift_late < 1e-7, "{m:?}");
    let weight = (2.0 * HALF as f64).powi(3) * DENSITY as f64 * 9.81;
    assert!(m.friction < weight, "{m:?} (weight {weight} N)");
}

/// [`tip_presses_a_box_against_a_wall`] with the rigid stick (`set_friction_spring(false)`,
/// the default before session 19), at the bounds set for it.
// Measured (session 14): worst 8.1e-5, 60.69 N, moved 0.22 mm (the approach: the box slides
// until it meets the wall), 1.4 cm/s at most (then), 2.0e-7 m/s in the hold.
#[test]
fn rigid_stick_presses_a_box_against_a_wall() {
    let mut p = scene(1, true, Backing::Free);
    p.world.soft.set_friction_spring(false);
    let m = press(&mut p, 0.002, 120);
    println!("free tip, rigid stick, box against a wall, 2 mm: {m:?}");
    assert!(m.worst < 1e-3, "{m:?}");
    assert!(m.force > 50.0, "{m:?}");
    assert!(m.moved < 5e-4, "{m:?}");
    assert!(m.speed < 0.02, "{m:?}");
    assert!(m.speed_hold < 1e-6, "{m:?}");
}
