//! Hard case 1: quasi-static squeeze. A dynamic fingertip ball (R = 10 mm, E = 3 MPa,
//! nu = 0.49, e = 1) between a fixed floor and a kinematic plate moving down at 1 mm/s, from
//! rest at x = 0.02 to x = 0.8 per contact (the set-up of
//! `softgrip-rapier/tests/quasi_static_squeeze.rs`, [`PlateSqueeze`], at half its plate speed).

use std::time::{Duration, Instant};

use softgrip_law::Level;
use softgrip_rapier::SoftAccuracy;

use crate::fe::{fe_at, fe_curve};
use softgrip_testkit::scenes::{PlateSqueeze, fingertip};

/// Fingertip radius \[m\].
pub const RADIUS: f64 = softgrip_testkit::scenes::RADIUS;
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
    /// Simulated time \[s\].
    pub sim_time: f64,
    /// Wall time of the steps.
    pub wall: Duration,
}

/// Runs the squeeze with `level` and `accuracy`.
pub fn squeeze(level: Level, accuracy: SoftAccuracy) -> SqueezeResult {
    const R: f64 = RADIUS;
    let tip = fingertip(level, 1.0)
        .build()
        .expect("invariant: valid fingertip");
    let mut s = PlateSqueeze::new(tip);
    s.world.soft.set_accuracy(accuracy);
    let e_star = s.law.params().effective_modulus();

    let fe = fe_curve();
    let dt = s.world.physics.integration_parameters.dt as f64;
    let (mut law_error, mut fe_error, mut samples) = (0.0f64, 0.0f64, 0);
    let mut wall = Duration::ZERO;
    loop {
        if 2.0 * R - (s.plate_bottom() - SPEED * dt) > 2.0 * X_END * R {
            break;
        }
        s.lower_plate(SPEED * dt);
        let t = Instant::now();
        s.world.step();
        wall += t.elapsed();
        let delta = (2.0 * R - s.plate_bottom()) / 2.0;
        let x = delta / R;
        if x < X_FROM {
            continue;
        }
        let contacts = s.world.soft.contacts();
        let force_on = |other| {
            contacts
                .iter()
                .find(|c| c.other == other)
                .map_or(0.0, |c| c.normal_force)
        };
        let (top, bottom) = (force_on(s.plate), force_on(s.floor));
        let f_law = s.law.response(delta).force;
        law_error = law_error
            .max((top / f_law - 1.0).abs())
            .max((bottom / f_law - 1.0).abs());
        if let Some(f_fe) = fe_at(&fe, x) {
            fe_error = fe_error.max((top / (e_star * R * R) / f_fe - 1.0).abs());
        }
        samples += 1;
    }
    let c = s.world.soft.counters();
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
