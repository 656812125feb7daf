//! Hard case 2: elastic bounce at dt = 1/60 s. The fingertip ball (R = 10 mm, E = 3 MPa,
//! nu = 0.49, e = 1) dropped from 10 cm onto a rigid half-space, against a 1-DOF RK4
//! integration of `m delta'' = m g - F(delta)` at a step of 1e-7 s.

use std::time::{Duration, Instant};

use rapier3d::prelude::*;
use softgrip_law::{ContactLaw, Level, Material};
use softgrip_rapier::{SoftAccuracy, SoftFingertip, SoftWorld};

/// Fingertip radius [m].
pub const RADIUS: f64 = 0.01;
/// Gravity [m/s^2].
pub const G: f64 = 9.81;
/// Drop height of the ball's lowest point [m].
pub const DROP: f64 = 0.1;
/// Simulated time of a run [s]: three and a half bounce periods.
pub const SIM_TIME: f64 = 1.0;

/// First impact of the 1-DOF reference.
#[derive(Debug, Clone, Copy)]
pub struct Impact {
    /// Peak normal force [N].
    pub peak_force: f64,
    /// Contact duration [s].
    pub duration: f64,
}

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

/// 1-DOF reference from first touch at `v0` [m/s] to separation: RK4 on
/// `delta'' = g - F(delta) / m` at h = 1e-7 s.
pub fn reference(law: &ContactLaw, mass: f64, v0: f64) -> Impact {
    let h = 1e-7;
    let acc = |d: f64| G - law.response(d).force / mass;
    let (mut d, mut v, mut t, mut peak) = (0.0f64, v0, 0.0, 0.0f64);
    loop {
        let (k1d, k1v) = (v, acc(d));
        let (k2d, k2v) = (v + 0.5 * h * k1v, acc(d + 0.5 * h * k1d));
        let (k3d, k3v) = (v + 0.5 * h * k2v, acc(d + 0.5 * h * k2d));
        let (k4d, k4v) = (v + h * k3v, acc(d + h * k3d));
        let d_next = d + h / 6.0 * (k1d + 2.0 * k2d + 2.0 * k3d + k4d);
        v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        if d_next <= 0.0 {
            // Separation inside the step: linear interpolation of the crossing.
            t += h * d / (d - d_next);
            return Impact {
                peak_force: peak,
                duration: t,
            };
        }
        d = d_next;
        t += h;
        peak = peak.max(law.response(d).force);
    }
}

/// Runs the drop with `level` and `accuracy` for [`SIM_TIME`].
pub fn bounce(level: Level, accuracy: SoftAccuracy) -> BounceResult {
    const R: f64 = RADIUS;
    let mut world = SoftWorld::new();
    world.soft.set_accuracy(accuracy);
    world
        .colliders
        .insert(ColliderBuilder::new(SharedShape::halfspace(Vector::Y)));
    let body = world.bodies.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, (R + DROP) as f32, 0.0))
            .can_sleep(false),
    );
    let ball = world.colliders.insert_with_parent(
        ColliderBuilder::ball(R as f32)
            .density(1070.0)
            .friction(0.0),
        body,
        &mut world.bodies,
    );
    let tip = SoftFingertip::builder(R)
        .material(Material::try_new(3.0e6, 0.49).expect("invariant: valid material"))
        .level(level)
        .restitution(1.0)
        .friction(0.0)
        .build()
        .expect("invariant: valid fingertip");
    let law = tip.law().clone();
    world
        .register(ball, tip)
        .expect("invariant: a ball of the fingertip's radius");
    let mass = world.bodies[body].mass() as f64;
    let dt = world.params.dt as f64;
    let passes = world.params.num_solver_iterations.max(1) as f64;
    // Energy with the true velocity of rapier's N-pass symplectic Euler in free flight,
    // v + g dt / (2N) (see softgrip-rapier's bounce test): exactly conserved in free flight.
    let energy = |world: &SoftWorld| {
        let rb = &world.bodies[body];
        let vy = rb.linvel().y as f64 - 0.5 * G * dt / passes;
        let y = rb.translation().y as f64;
        0.5 * mass * vy * vy + mass * G * (y - R) + law.energy((R - y).max(0.0))
    };
    let e0 = energy(&world);
    let (mut peak, mut duration, mut v_impact) = (0.0f64, 0.0, 0.0);
    let (mut touched, mut energy_error) = (false, None);
    let mut wall = Duration::ZERO;
    for _ in 0..(SIM_TIME / dt).round() as usize {
        let v_before = -(world.bodies[body].linvel().y as f64 - 0.5 * G * dt / passes);
        let y_before = world.bodies[body].translation().y as f64 - R;
        let t = Instant::now();
        world.step();
        wall += t.elapsed();
        if energy_error.is_some() {
            continue;
        }
        match world.soft.contacts().first() {
            Some(c) => {
                if !touched {
                    // Speed at first touch, from the free fall over the gap before the step.
                    v_impact = (v_before * v_before + 2.0 * G * y_before).sqrt();
                }
                touched = true;
                peak = peak.max(c.peak_normal_force);
                duration += c.contact_duration;
            }
            None if touched => energy_error = Some(energy(&world) / e0 - 1.0),
            None => {}
        }
    }
    let c = world.soft.counters();
    BounceResult {
        impact: Impact {
            peak_force: peak,
            duration,
        },
        reference: reference(&law, mass, v_impact),
        energy_error: energy_error.unwrap_or(f64::NAN),
        substeps: c.substeps_total,
        steps: c.steps,
        wall,
    }
}
