//! A dynamic fingertip ball between a fixed floor and a kinematic plate, squeezed slowly to
//! x = 0.8 per contact: the contact force equals the law's F(x) at every sample. The scene is
//! `softgrip_testkit::scenes::PlateSqueeze`, the one the benchmark tables squeeze.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_law::Level;
use softgrip_testkit::scenes::{PlateSqueeze, RADIUS as R, fingertip};

/// Worst errors of a squeeze at `speed` [m/s] (plate approach) with restitution `e`: (vs the
/// law at half the approach, vs the law at the readout's delta, x reached, substeps total).
fn squeeze(restitution: f64, speed: f64, tolerance: f64) -> (f64, f64, f64, u64) {
    // Starts at rest, already squeezed to x0 = 0.02 per contact, at equilibrium under gravity:
    // an elastic (e = 1) ball that the plate hits at 2 mm/s rings for a while (physically
    // right: nothing damps it), which is not the quasi-static squeeze this test is about.
    let mut s = PlateSqueeze::new(fingertip(Level::fit(), restitution).build().unwrap());

    let dt = s.world.physics.integration_parameters.dt as f64;
    let (mut worst, mut worst_geom, mut samples) = (0.0f64, 0.0f64, 0);
    let mut x_reached = 0.0;
    for _ in 0..2000 {
        let plate_bottom_next = s.plate_bottom() - speed * dt;
        if 2.0 * R - plate_bottom_next > 1.6 * R {
            break;
        }
        s.lower_plate(speed * dt);
        s.world.step();
        let approach = 2.0 * R - s.plate_bottom();
        let delta = approach / 2.0;
        let x = delta / R;
        let top = s.world.soft.contacts().iter().find(|c| c.other == s.plate);
        let bottom = s.world.soft.contacts().iter().find(|c| c.other == s.floor);
        if x < 0.05 {
            continue;
        }
        let (top, bottom) = (top.expect("top contact"), bottom.expect("bottom contact"));
        let f_law = s.law.response(delta).force;
        let err = (top.normal_force / f_law - 1.0).abs();
        let err_b = (bottom.normal_force / f_law - 1.0).abs();
        // Against the law at the readout's own compression (the end-of-step geometry).
        let err_geom = (top.normal_force / s.law.response(top.delta).force - 1.0).abs();
        worst = worst.max(err).max(err_b);
        worst_geom = worst_geom.max(err_geom);
        samples += 1;
        x_reached = x;
        assert!(
            err < tolerance && err_b < tolerance,
            "x = {x:.4}: top {} N, bottom {} N, law {f_law} N",
            top.normal_force,
            bottom.normal_force
        );
    }
    assert!(samples > 10);
    (
        worst,
        worst_geom,
        x_reached,
        s.world.soft.counters().substeps_total,
    )
}

#[test]
fn quasi_static_squeeze_matches_law() {
    let (worst, worst_geom, x_reached, substeps) = squeeze(1.0, 0.002, 0.005);
    println!(
        "quasi-static squeeze (e = 1, 2 mm/s): to x = {x_reached:.3}, worst |F/F_law - 1| = {worst:.2e} (half approach), {worst_geom:.2e} (readout delta); substeps total {substeps}"
    );
    assert!(x_reached > 0.79);
    // The READMEs state 0.41 % vs the law at half the approach (every sample is asserted
    // < 0.5 % above: the imbalance m g / 2F of the ball's weight) and 0.05 % vs the law at the
    // readout's delta: 0.1 % on that one (was 0.5 %, which a 10x regression passed).
    assert!(worst < 0.005);
    assert!(worst_geom < 0.001, "{worst_geom}, README: 0.05 %");
}

/// A dissipative fingertip (e = 0.5 at 1 m/s) squeezed at 5 mm/s reads the elastic law: the
/// Hunt-Crossley damping adds `alpha d delta/dt` ~ 0.3 % at most (it no longer depends on the
/// contact's approach speed).
#[test]
fn slow_squeeze_with_dissipation_reads_elastic_law() {
    let (worst, worst_geom, x_reached, substeps) = squeeze(0.5, 0.005, 0.01);
    println!(
        "squeeze (e = 0.5, 5 mm/s): to x = {x_reached:.3}, worst |F/F_law - 1| = {worst:.2e} (half approach), {worst_geom:.2e} (readout delta); substeps total {substeps}"
    );
    assert!(x_reached > 0.79);
    // The README states 0.35 % and 0.33 % (the damping's alpha d delta/dt); was 1 %.
    assert!(
        worst < 0.005 && worst_geom < 0.005,
        "{worst} {worst_geom}, README: 0.35 %, 0.33 %"
    );
}
