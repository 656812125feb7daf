//! Hard case 1: quasi-static squeeze. A dynamic fingertip ball (R = 10 mm, E = 3 MPa,
//! nu = 0.49, e = 1) between a fixed floor and a kinematic plate moving down at 1 mm/s, from
//! rest at x = 0.02 to x = 0.8 per contact (the set-up of
//! `softgrip-rapier/tests/quasi_static_squeeze.rs`, at half its plate speed).

use std::time::{Duration, Instant};

use rapier3d::prelude::*;
use softgrip_law::{Level, Material};
use softgrip_rapier::{SoftAccuracy, SoftFingertip, SoftWorld};

use crate::fe::{fe_at, fe_curve};

/// Fingertip radius [m].
pub const RADIUS: f64 = 0.01;
/// Plate speed [m/s].
pub const SPEED: f64 = 0.001;
/// Compression ratio per contact at the end of the squeeze.
pub const X_END: f64 = 0.8;
/// Compression ratio from which the force is compared (below it the two contacts differ by
/// the ball's weight by more than the plugin's error).
pub const X_FROM: f64 = 0.05;

/// What one squeeze measured.
#[derive(Debug, Clone, Copy)]
pub struct SqueezeResult {
    /// Max |F / F_law(delta) - 1| over both contacts, delta = half the plate approach.
    pub law_error: f64,
    /// Max |f / f_FE - 1| of the plate contact, over the FE data's range in x.
    pub fe_error: f64,
    /// Samples compared (one per step from `X_FROM`).
    pub samples: usize,
    /// Substeps over the whole squeeze (equal to the steps when no step was split).
    pub substeps: u64,
    /// Steps.
    pub steps: u64,
    /// Simulated time [s].
    pub sim_time: f64,
    /// Wall time of the steps.
    pub wall: Duration,
}

/// Runs the squeeze with `level` and `accuracy`.
pub fn squeeze(level: Level, accuracy: SoftAccuracy) -> SqueezeResult {
    const R: f64 = RADIUS;
    let mut world = SoftWorld::new();
    world.soft.set_accuracy(accuracy);
    let floor = world
        .colliders
        .insert(ColliderBuilder::cuboid(0.1, 0.01, 0.1).translation(Vector::new(0.0, -0.01, 0.0)));
    let tip = SoftFingertip::builder(R)
        .material(Material::try_new(3.0e6, 0.49).expect("invariant: valid material"))
        .level(level)
        .restitution(1.0)
        .build()
        .expect("invariant: valid fingertip");
    let law = tip.law().clone();
    let e_star = law.params().effective_modulus();
    // At rest, squeezed to x0 = 0.02 per contact, in equilibrium under gravity (an elastic
    // ball hit by the plate would ring: not the quasi-static case).
    let mass = 1070.0 * 4.0 / 3.0 * std::f64::consts::PI * R.powi(3);
    let d0 = 0.02 * R;
    let d_eq = d0 + mass * 9.81 / (2.0 * law.response(d0).stiffness);
    let ball_body = world.bodies.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, (R - d_eq) as f32, 0.0))
            .can_sleep(false),
    );
    let ball = world.colliders.insert_with_parent(
        ColliderBuilder::ball(R as f32).density(1070.0),
        ball_body,
        &mut world.bodies,
    );
    let half = 0.005f32;
    let plate_body = world.bodies.insert(
        RigidBodyBuilder::kinematic_position_based().translation(Vector::new(
            0.0,
            (2.0 * R - 2.0 * d0) as f32 + half,
            0.0,
        )),
    );
    let plate = world.colliders.insert_with_parent(
        ColliderBuilder::cuboid(0.05, half, 0.05),
        plate_body,
        &mut world.bodies,
    );
    world
        .register(ball, tip)
        .expect("invariant: a ball of the fingertip's radius");

    let fe = fe_curve();
    let dt = world.params.dt as f64;
    let (mut law_error, mut fe_error, mut samples) = (0.0f64, 0.0f64, 0);
    let mut wall = Duration::ZERO;
    loop {
        let y = world.bodies[plate_body].translation().y as f64;
        if 2.0 * R - (y - half as f64 - SPEED * dt) > 2.0 * X_END * R {
            break;
        }
        world.bodies[plate_body].set_next_kinematic_translation(Vector::new(
            0.0,
            (y - SPEED * dt) as f32,
            0.0,
        ));
        let t = Instant::now();
        world.step();
        wall += t.elapsed();
        let plate_bottom = world.bodies[plate_body].translation().y as f64 - half as f64;
        let delta = (2.0 * R - plate_bottom) / 2.0;
        let x = delta / R;
        if x < X_FROM {
            continue;
        }
        let contacts = world.soft.contacts();
        let force_on = |other| {
            contacts
                .iter()
                .find(|c| c.other == other)
                .map_or(0.0, |c| c.normal_force)
        };
        let (top, bottom) = (force_on(plate), force_on(floor));
        let f_law = law.response(delta).force;
        law_error = law_error
            .max((top / f_law - 1.0).abs())
            .max((bottom / f_law - 1.0).abs());
        if let Some(f_fe) = fe_at(&fe, x) {
            fe_error = fe_error.max((top / (e_star * R * R) / f_fe - 1.0).abs());
        }
        samples += 1;
    }
    let c = world.soft.counters();
    SqueezeResult {
        law_error,
        fe_error,
        samples,
        substeps: c.substeps_total,
        steps: c.steps,
        sim_time: c.steps as f64 * dt,
        wall,
    }
}
