//! Hard case 6, overshoot: a fingertip on a kinematic finger is pressed into a fixed box past
//! the singularity of chi_L (x = 0.9; the `fit` level's validity ends at x = 0.81) to x = 0.95,
//! then released. The force stays finite and monotonic, equals the law's documented extension,
//! the excursion is flagged, and the simulation goes on.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use rapier3d::prelude::*;
use softgrip_law::{Level, Regime};

#[test]
fn pressing_past_chi_l_singularity_to_x095_is_finite_monotonic_and_flagged() {
    let r = 0.01;
    let mut world = softgrip_rapier::SoftWorld::new();
    world
        .physics
        .colliders
        .insert(ColliderBuilder::cuboid(0.1, 0.05, 0.1).translation(Vector::new(0.0, -0.05, 0.0)));
    let tip = common::tip(r, 0.59e6, Level::fit(), 1.0, 0.8);
    let law = tip.law().clone();
    let y = |x: f64| (r - x * r) as f32;
    let (finger, _) = common::kinematic_tip(&mut world, Vector::new(0.0, y(0.5), 0.0), tip);
    let steps = 90;
    let xs: Vec<f64> = (1..=steps)
        .map(|i| 0.5 + 0.45 * i as f64 / steps as f64)
        .collect();
    let (mut prev, mut worst, mut worst_extended, mut extended_steps) = (0.0f64, 0.0f64, 0.0f64, 0);
    for &x in &xs {
        common::move_to(&mut world, finger, Vector::new(0.0, y(x), 0.0));
        world.step();
        assert!(common::all_finite(&world));
        let c = world.soft.contacts().first().expect("contact").clone();
        assert!(
            c.normal_force.is_finite() && c.normal_force > prev,
            "not monotonic at x = {x}"
        );
        prev = c.normal_force;
        let err = (c.normal_force / law.response(c.delta).force - 1.0).abs();
        if c.x > law.x_max() {
            worst_extended = worst_extended.max(err);
            assert_eq!(c.regime, Regime::Extended);
            assert!(c.validity_excursion());
            extended_steps += 1;
        } else {
            worst = worst.max(err);
            assert_eq!(c.regime, Regime::Valid);
        }
    }
    let at_095 = prev;
    let counters = *world.soft.counters();
    // Release: back out of contact, the simulation continues.
    for i in 1..=30 {
        let x = 0.95 - 1.0 * i as f64 / 30.0;
        common::move_to(&mut world, finger, Vector::new(0.0, y(x), 0.0));
        world.step();
        assert!(common::all_finite(&world));
    }
    println!(
        "overshoot to x = 0.95: F = {at_095:.1} N (law's extension {:.1} N, F at x_max = {:.1} N), worst |F/law - 1| = {worst:.2e} in the range, {worst_extended:.2e} past it, {extended_steps} flagged steps, excursions counted {}",
        law.response(0.95 * r).force,
        law.force_max(),
        counters.validity_excursions
    );
    // The README states 0.30 % in the range, 1.09 % in the extension (the barrier's
    // curvature: the step's force lags the end-of-step law by about K d_delta / 2F as the finger
    // moves 0.005 R a step) and 29 flagged steps.
    assert!(worst < 0.005, "{worst}, README: 0.30 %");
    assert!(worst_extended < 0.015, "{worst_extended}, README: 1.09 %");
    // The barrier: past x_max the force grows to about 10 times F(x_max) at x = 0.95.
    assert!(
        (at_095 / 7434.1 - 1.0).abs() < 1e-3,
        "{at_095}, README: 7434 N"
    );
    assert!((26..=32).contains(&extended_steps), "README: 29");
    // The counter counts evaluations at the start of a step, the readout flags its end: the
    // first flagged step started inside the range.
    assert!(extended_steps > 20 && counters.validity_excursions + 1 >= extended_steps);
    assert!(world.soft.contacts().is_empty());
}
