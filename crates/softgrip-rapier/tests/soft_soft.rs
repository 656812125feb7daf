//! Soft-soft contacts (issue 11): two fingertips touching are one pair with the combined law
//! (`ContactParams::try_combine`), reported by **both** fingertips, each with its own normal,
//! the forces equal and opposite. Before, only the fingertip with the smaller handle reported
//! it (the other read 0 N and a zero wrench), so a gripper whose jaws closed on each other
//! never saw the second touch and drove that jaw through the other fingertip.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use rapier3d::prelude::*;
use softgrip_law::{ContactLaw, ContactParams, Level, Material};
use softgrip_rapier::{SoftFingertip, SoftWorld, TipContact};

fn tip(name: &str, r: f64, e: f64, restitution: f64) -> SoftFingertip {
    SoftFingertip::builder(r)
        .name(name)
        .material(Material::try_new(e, 0.49).unwrap())
        .restitution(restitution)
        .build()
        .unwrap()
}

/// The two readouts of one soft-soft pair: exactly opposite normals, equal forces and opposite
/// force vectors (relative 1e-9), the same compression.
fn assert_mirrored(a: &TipContact, b: &TipContact) {
    assert_eq!((a.fingertip, a.other), (b.other, b.fingertip));
    assert_eq!(a.delta, b.delta);
    let (fa, _) = a.wrench_about([0.0; 3]);
    let (fb, _) = b.wrench_about([0.0; 3]);
    let scale = a.normal_force.abs().max(1e-300);
    for i in 0..3 {
        assert_eq!(a.normal[i], -b.normal[i]);
        assert!((fa[i] + fb[i]).abs() <= 1e-9 * scale, "{fa:?} vs {fb:?}");
    }
    assert!((a.normal_force - b.normal_force).abs() <= 1e-9 * scale);
}

#[test]
fn soft_soft_pressed_together_both_report_the_combined_law() {
    let mut world = SoftWorld::new();
    world.physics.gravity = Vector::ZERO;
    let (r1, e1, r2, e2) = (0.012, 0.4e6, 0.01, 0.59e6);
    let (b1, c1) = common::kinematic_tip(&mut world, Vector::ZERO, tip("a", r1, e1, 0.5));
    let (b2, c2) = common::kinematic_tip(
        &mut world,
        Vector::new((r1 + r2) as f32 + 0.001, 0.0, 0.0),
        tip("b", r2, e2, 0.5),
    );
    let combined = ContactLaw::try_new(
        ContactParams::try_combine(
            Material::try_new(e1, 0.49).unwrap(),
            r1,
            Material::try_new(e2, 0.49).unwrap(),
            r2,
        )
        .unwrap(),
        Level::auto(),
    )
    .unwrap();
    // Quasi-static: each fingertip moves towards the other in small steps to a total approach
    // of 0.2 .. 4 mm, then holds for 3 steps; the force is read at rest.
    let mut worst = 0.0f64;
    let mut samples = 0;
    let gap0 = r1 + r2 + 0.001;
    for k in 0..=20 {
        let target = 0.0002 + 0.00019 * k as f64;
        for s in 1..=8 {
            // From the 1 mm gap to the target approach over 5 steps, then held.
            let a = 0.5 * (-0.001 + (target + 0.001) * (s.min(5) as f64 / 5.0));
            common::move_to(&mut world, b1, Vector::new(a as f32, 0.0, 0.0));
            common::move_to(
                &mut world,
                b2,
                Vector::new((gap0 - 0.001 - a) as f32, 0.0, 0.0),
            );
            world.step();
        }
        let gap = (world.physics.bodies[b2].translation().x
            - world.physics.bodies[b1].translation().x) as f64;
        let approach = r1 + r2 - gap;
        let of = |c: ColliderHandle| world.soft.contacts_of(c).cloned().collect::<Vec<_>>();
        let (a, b) = (of(c1), of(c2));
        assert_eq!(
            (a.len(), b.len()),
            (1, 1),
            "both fingertips report the pair"
        );
        assert_mirrored(&a[0], &b[0]);
        // Normals: from the other fingertip to this one.
        assert!(a[0].normal[0] < -0.999 && b[0].normal[0] > 0.999);
        let law = combined.response(approach).force;
        worst = worst.max((a[0].normal_force / law - 1.0).abs());
        samples += 1;
    }
    println!(
        "soft-soft squeeze: {samples} samples, worst {:.4} % vs the combined law",
        worst * 100.0
    );
    assert_eq!(samples, 21);
    // Measured 0.0001 %; the issue asks for 1 %.
    assert!(worst < 1e-4, "worst {worst}");
}

#[test]
fn soft_soft_collision_keeps_momentum() {
    let mut world = SoftWorld::new();
    world.physics.gravity = Vector::ZERO;
    let r = 0.01;
    let (b1, c1) = common::dynamic_tip(&mut world, Vector::ZERO, 1070.0, tip("a", r, 0.59e6, 0.8));
    let (b2, c2) = common::dynamic_tip(
        &mut world,
        Vector::new(0.03, 0.0, 0.0),
        3000.0,
        tip("b", r, 0.3e6, 0.8),
    );
    world.physics.bodies[b1].set_linvel(Vector::new(0.5, 0.0, 0.0), true);
    let momentum = |w: &SoftWorld| -> f64 {
        [b1, b2]
            .iter()
            .map(|&b| w.physics.bodies[b].mass() as f64 * w.physics.bodies[b].linvel().x as f64)
            .sum()
    };
    let p0 = momentum(&world);
    let (mut touched, mut both) = (0, 0);
    for _ in 0..120 {
        world.step();
        assert!(common::all_finite(&world));
        let n1 = world.soft.contacts_of(c1).count();
        let n2 = world.soft.contacts_of(c2).count();
        assert_eq!(n1, n2, "both report or neither");
        touched += n1;
        if n1 == 1 {
            let a = world.soft.contacts_of(c1).next().unwrap().clone();
            let b = world.soft.contacts_of(c2).next().unwrap().clone();
            assert_mirrored(&a, &b);
            both += 1;
        }
    }
    let p1 = momentum(&world);
    let v1 = world.physics.bodies[b1].linvel().x;
    let v2 = world.physics.bodies[b2].linvel().x;
    println!(
        "soft-soft collision: momentum {p0:.6e} -> {p1:.6e} ({:.2e} relative), v = {v1:.4} / {v2:.4} m/s, {both} steps in contact",
        (p1 / p0 - 1.0).abs()
    );
    assert!(touched > 0);
    assert!((p1 / p0 - 1.0).abs() < 1e-5, "{p0} -> {p1}");
    // Separated after the impact: the heavier, softer one moves on faster than the first.
    assert!(v2 > v1 && v2 > 0.0);
    assert_eq!(world.soft.contacts().len(), 0);
}
