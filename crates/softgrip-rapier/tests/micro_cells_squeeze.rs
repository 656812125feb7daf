//! Hard case 3, stiff and tiny: a fixed cell (R = 15.4 um, E* = 42.2 MPa) and a live cell
//! (R = 14.2 um, E* = 20.8 kPa) squeezed between two micro-plates to x = 0.7 per contact. The
//! force of each contact stays within 1 % of the law at the half plate approach.
//!
//! The cells float in their medium (no gravity: a cell's weight, ~1e-10 N, is below the force
//! resolution that matters here). The cell is a dynamic ball at the origin and the plates move
//! symmetrically, so every coordinate stays within a few R of the origin where f32 resolves
//! ~1e-12 m (1e-7 R).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use rapier3d::prelude::*;
use softgrip_law::Level;
use softgrip_rapier::{Preset, SoftFingertip, SoftWorld};

struct Result {
    /// Against the law at the half approach of the plates' actual (f32) poses.
    worst: f64,
    /// Against the law at the half approach the test asked for (f64).
    worst_requested: f64,
    x_reached: f64,
    samples: usize,
}

fn squeeze(preset: Preset, length_unit: f32, offset: f64) -> Result {
    let r = preset.measured_radius().unwrap();
    let mut world = SoftWorld::new();
    world.physics.gravity = Vector::ZERO;
    world.physics.integration_parameters.length_unit = length_unit;
    let tip = SoftFingertip::builder(r)
        .preset(preset)
        .level(Level::fit())
        .restitution(1.0)
        .friction(0.0)
        .build()
        .unwrap();
    let law = tip.law().clone();
    common::dynamic_tip(
        &mut world,
        Vector::new(offset as f32, offset as f32, 0.0),
        1050.0,
        tip,
    );
    let half = 0.5 * r;
    let x0 = 0.005; // initial compression ratio per contact
    let plate_y = |x: f64| r - x * r + half;
    let at =
        |sign: f64, x: f64| Vector::new(offset as f32, (offset + sign * plate_y(x)) as f32, 0.0);
    let mut plates = Vec::new();
    for sign in [1.0, -1.0] {
        let body = world
            .physics
            .bodies
            .insert(RigidBodyBuilder::kinematic_position_based().translation(at(sign, x0)));
        let co = world.physics.colliders.insert_with_parent(
            ColliderBuilder::cuboid((4.0 * r) as f32, half as f32, (4.0 * r) as f32),
            body,
            &mut world.physics.bodies,
        );
        plates.push((body, co, sign));
    }
    let steps = 300;
    let (mut worst, mut worst_requested, mut samples, mut x_reached) = (0.0f64, 0.0f64, 0, 0.0);
    for i in 1..=steps {
        let x_target = x0 + (0.7 - x0) * i as f64 / steps as f64;
        for &(body, _, sign) in &plates {
            common::move_to(&mut world, body, at(sign, x_target));
        }
        world.step();
        assert!(common::all_finite(&world));
        let top = world.physics.bodies[plates[0].0].translation().y as f64 - half;
        let bottom = world.physics.bodies[plates[1].0].translation().y as f64 + half;
        let delta = (2.0 * r - (top - bottom)) / 2.0;
        let x = delta / r;
        if x < 0.05 {
            continue;
        }
        let f_law = law.response(delta).force;
        let f_requested = law.response(x_target * r).force;
        for &(_, co, _) in &plates {
            let c = world
                .soft
                .contacts()
                .iter()
                .find(|c| c.other == co)
                .expect("plate contact");
            worst = worst.max((c.normal_force / f_law - 1.0).abs());
            worst_requested = worst_requested.max((c.normal_force / f_requested - 1.0).abs());
        }
        samples += 1;
        x_reached = x;
    }
    Result {
        worst,
        worst_requested,
        x_reached,
        samples,
    }
}

#[test]
fn fixed_and_live_cells_squeezed_to_x07_match_law_within_1_percent() {
    for preset in [Preset::FixedCell, Preset::LiveCell] {
        let r = preset.measured_radius().unwrap() as f32;
        for (name, unit) in [("R", r), ("1 m", 1.0)] {
            let res = squeeze(preset, unit, 0.0);
            println!(
                "{}: length_unit = {name}: {} samples to x = {:.3}, worst |F/F_law - 1| = {:.2e} (actual poses), {:.2e} (requested)",
                preset.name(),
                res.samples,
                res.x_reached,
                res.worst,
                res.worst_requested
            );
            assert!(res.x_reached > 0.699);
            // The READMEs state a worst 0.096 % ("within 0.1 % of the law"); was 1 %.
            assert!(res.worst < 0.002, "{} at length_unit {name}", preset.name());
            assert!(res.worst_requested < 0.002);
        }
    }
}

/// The f32 limit: the same squeeze away from the origin. A coordinate c is stored to ~6e-8 c,
/// so the plates' poses (not the law) carry the error: at 1 m a pose is off by up to 6e-8 m,
/// 8 % of a cell's compression at x = 0.05. The force still matches the law at the geometry
/// rapier actually holds; it no longer matches the geometry that was asked for.
#[test]
fn cell_force_error_grows_with_distance_from_origin_f32_limit() {
    let mut errors = Vec::new();
    for offset in [1e-2, 1e-1, 1.0] {
        let res = squeeze(Preset::LiveCell, 14.2e-6, offset);
        println!(
            "live-cell at {offset} m from the origin (x >= 0.05): worst |F/F_law - 1| = {:.2e} at the actual poses, {:.2e} at the requested poses",
            res.worst, res.worst_requested
        );
        assert!(res.worst < 0.01);
        errors.push(res.worst_requested);
    }
    assert!(errors[0] < 0.01);
    assert!(errors[2] > 0.01); // past the f32 limit: stated in the README
    // The README states 0.11 % / 0.41 % / 4.3 % at 1 cm / 10 cm / 1 m.
    assert!(errors[0] < 0.0022 && errors[1] < 0.008, "{errors:?}");
    assert!((0.02..=0.09).contains(&errors[2]), "{errors:?}");
}
