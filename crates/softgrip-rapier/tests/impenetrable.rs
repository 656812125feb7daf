//! Past a law's validity a fixed plane stays impenetrable (issue 23, item 5): a soft ball
//! 1000 times heavier than the law's range can hold rests on a halfspace and on a cuboid table
//! with its centre above the surface, its compression short of the law's wall (`x_wall`, the
//! centre at the surface) and settled, every figure finite. Until session 17 the extension was
//! the tangent at `x_max`, frozen past x = 4, and such a ball sank through.
//!
//! `cargo test -p softgrip-rapier --test impenetrable -- --nocapture` prints the numbers.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use rapier3d::prelude::*;
use softgrip_law::{Level, Regime};
use softgrip_rapier::SoftWorld;

/// What a heavy ball's rest looked like.
#[derive(Debug)]
struct Rest {
    /// Lowest centre height above the surface over the run, over R [-].
    lowest: f64,
    /// Compression at the end, over R [-].
    x_end: f64,
    /// The law's x_max and x_wall [-].
    x_max: f64,
    x_wall: f64,
    /// Force at the end over the ball's weight [-].
    force_over_weight: f64,
    /// Compression's spread over the last second, over R [-].
    spread: f64,
    /// The centre's mean speed over the last second \[m/s\] (rapier's stored velocity of a
    /// resting body is not its motion: it carries a part of a step's gravity).
    speed: f64,
    /// Largest substep count of a step in the last second (the barrier's own frequency).
    rest_substeps: u32,
    /// Largest substep count of any step, and the cap hits.
    max_substeps: u32,
    cap_hits: u64,
    /// Steps flagged `Extended` (the readout) and the plugin's excursion count.
    extended_steps: u32,
    excursions: u64,
}

/// Drops a ball of R = 10 mm (E = 0.59 MPa, nu = 0.49, `calibrated`, e = 0.5) whose weight is
/// `load` times the law's force at `x_max`, from touching, on `table` (true: a cuboid table;
/// false: a halfspace), for 3 s at dt = 1/60 s.
fn heavy_ball(load: f64, table: bool) -> Rest {
    let r = 0.01;
    let tip = common::tip(r, 0.59e6, Level::Calibrated, 0.5, 0.8);
    let law = tip.law().clone();
    let weight = load * law.force_max();
    let volume = 4.0 / 3.0 * std::f64::consts::PI * r * r * r;
    let rho = (weight / common::G / volume) as f32;
    let mut world = SoftWorld::new();
    if table {
        world.physics.colliders.insert(
            ColliderBuilder::cuboid(0.2, 0.05, 0.2).translation(Vector::new(0.0, -0.05, 0.0)),
        );
    } else {
        world
            .physics
            .colliders
            .insert(ColliderBuilder::new(SharedShape::halfspace(Vector::Y)));
    }
    let (ball, _) = common::dynamic_tip(&mut world, Vector::new(0.0, r as f32, 0.0), rho, tip);
    let mass = f64::from(world.physics.bodies[ball].mass());
    let dt = f64::from(world.physics.integration_parameters.dt);
    let steps = (3.0 / dt).round() as usize;
    let last_second = steps - (1.0 / dt).round() as usize;
    let mut rest = Rest {
        lowest: f64::INFINITY,
        x_end: 0.0,
        x_max: law.x_max(),
        x_wall: law.x_wall(),
        force_over_weight: 0.0,
        spread: 0.0,
        speed: 0.0,
        rest_substeps: 0,
        max_substeps: 0,
        cap_hits: 0,
        extended_steps: 0,
        excursions: 0,
    };
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut y_start = 0.0;
    for i in 0..steps {
        world.step();
        assert!(common::all_finite(&world), "step {i}");
        let y = f64::from(world.physics.bodies[ball].translation().y);
        rest.lowest = rest.lowest.min(y / r);
        rest.max_substeps = rest.max_substeps.max(world.soft.counters().substeps_last);
        let c = world
            .soft
            .contacts()
            .first()
            .expect("the ball touches")
            .clone();
        assert!(c.normal_force.is_finite() && c.delta.is_finite());
        if c.regime == Regime::Extended {
            rest.extended_steps += 1;
        }
        if i == last_second {
            y_start = y;
        }
        if i >= last_second {
            lo = lo.min(c.x);
            hi = hi.max(c.x);
            rest.rest_substeps = rest.rest_substeps.max(world.soft.counters().substeps_last);
        }
        if i + 1 == steps {
            rest.x_end = c.x;
            rest.force_over_weight = c.normal_force / (mass * common::G);
            rest.speed = (y - y_start).abs() / (dt * (steps - 1 - last_second) as f64);
        }
    }
    rest.spread = hi - lo;
    rest.cap_hits = world.soft.counters().substep_cap_hits;
    rest.excursions = world.soft.counters().validity_excursions;
    rest
}

#[test]
fn a_ball_1000_times_the_range_rests_above_a_halfspace_and_a_table() {
    for table in [false, true] {
        let rest = heavy_ball(1000.0, table);
        let surface = if table { "table" } else { "halfspace" };
        println!("heavy ball (1000 x F(x_max)) on a {surface}: {rest:?}");
        // The centre stays above the surface: the compression stays short of the wall (x = 1
        // for this free sphere), by the margin the barrier needs to hold 1000 F(x_max).
        assert_eq!(rest.x_wall, 1.0);
        assert!(rest.lowest > 0.0, "{rest:?}");
        assert!(
            rest.x_end > rest.x_max && rest.x_end < rest.x_wall,
            "{rest:?}"
        );
        // Settled: the force carries the weight, the compression is still.
        assert!((rest.force_over_weight - 1.0).abs() < 1e-3, "{rest:?}");
        assert!(rest.spread < 1e-4, "{rest:?}");
        assert!(rest.speed < 1e-6, "{rest:?}");
        // Resting on the barrier costs substeps (README: about 400 a step), never the cap.
        assert!(rest.rest_substeps < 1000, "{rest:?}");
        assert!(rest.extended_steps > 0 && rest.excursions > 0, "{rest:?}");
    }
}
