//! Hard case 2: elastic bounce at dt = 1/60 s. The fingertip ball (R = 10 mm, E = 3 MPa,
//! nu = 0.49, e = 1) dropped from 10 cm onto a rigid half-space, against a 1-DOF RK4
//! integration of `m delta'' = m g - F(delta)` at a step of 1e-7 s.

use std::time::{Duration, Instant};

use softgrip_law::Level;
use softgrip_rapier::SoftAccuracy;

pub use softgrip_testkit::impact::{FirstImpact, Impact, reference};
use softgrip_testkit::scenes::{BallDrop, fingertip};

/// Fingertip radius \[m\].
pub const RADIUS: f64 = softgrip_testkit::scenes::RADIUS;
/// Gravity [m/s^2].
pub const G: f64 = softgrip_testkit::scenes::G;
/// Drop height of the ball's lowest point \[m\].
pub const DROP: f64 = 0.1;
/// Simulated time of a run \[s\]: three and a half bounce periods.
pub const SIM_TIME: f64 = 1.0;

/// What one bounce run measured.
#[derive(Debug, Clone, Copy)]
pub struct BounceResult {
    /// The plugin's first impact.
    pub impact: Impact,
    /// The reference's.
    pub reference: Impact,
    /// Energy after the first impact over the energy at release, minus 1.
    pub energy_error: f64,
    /// Substeps over the run.
    pub substeps: u64,
    /// Steps of the run.
    pub steps: u64,
    /// Wall time of the steps.
    pub wall: Duration,
}

/// Runs the drop with `level` and `accuracy` for [`SIM_TIME`].
pub fn bounce(level: Level, accuracy: SoftAccuracy) -> BounceResult {
    let tip = fingertip(level, 1.0)
        .friction(0.0)
        .build()
        .expect("invariant: valid fingertip");
    let mut s = BallDrop::new(tip, DROP);
    s.world.soft.set_accuracy(accuracy);
    let dt = s.world.physics.integration_parameters.dt as f64;
    // Energy with the true velocity of rapier's N-pass symplectic Euler in free flight
    // (`BallDrop::energy`): exactly conserved in free flight.
    let e0 = s.energy();
    let (mut first, mut energy_error) = (FirstImpact::default(), None);
    let mut wall = Duration::ZERO;
    for _ in 0..(SIM_TIME / dt).round() as usize {
        first.before_step(&s);
        let t = Instant::now();
        s.world.step();
        wall += t.elapsed();
        if energy_error.is_none() && first.after_step(&s) {
            energy_error = Some(s.energy() / e0 - 1.0);
        }
    }
    let c = s.world.soft.counters();
    BounceResult {
        impact: first.impact,
        reference: reference(&s.law, s.mass, first.speed),
        energy_error: energy_error.unwrap_or(f64::NAN),
        substeps: c.substeps_total,
        steps: c.steps,
        wall,
    }
}
