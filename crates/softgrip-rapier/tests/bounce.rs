//! Elastic bounce of a soft ball on rigid ground: energy kept over 10 bounces, first impact
//! against a 1-DOF RK4 reference, and the rebound ratio for e = 0.5.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use rapier3d::prelude::*;
use softgrip_law::{ContactLaw, Level, Material};
use softgrip_rapier::{SoftFingertip, SoftWorld};

const R: f64 = 0.01;
const G: f64 = 9.81;
const H0: f64 = 0.1; // drop height of the ball's lowest point [m]

struct Scene {
    world: SoftWorld,
    body: RigidBodyHandle,
    law: ContactLaw,
    mass: f64,
}

fn scene(restitution: f64) -> Scene {
    scene_from(restitution, H0)
}

/// The ball dropped from `h0` [m] (lowest point above the ground).
fn scene_from(restitution: f64, h0: f64) -> Scene {
    let mut world = SoftWorld::new();
    world
        .colliders
        .insert(ColliderBuilder::new(SharedShape::halfspace(Vector::Y)));
    let body = world.bodies.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, (R + h0) as f32, 0.0))
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
        .material(Material::try_new(3.0e6, 0.49).unwrap())
        .level(Level::fit())
        .restitution(restitution)
        .friction(0.0)
        .build()
        .unwrap();
    let law = tip.law().clone();
    world.register(ball, tip).unwrap();
    let mass = world.bodies[body].mass() as f64;
    Scene {
        world,
        body,
        law,
        mass,
    }
}

/// Energy of the ball, with the true velocity of rapier's N-pass symplectic Euler in free
/// flight: `E = m/2 |v + g dt/(2N)|^2 + m g y + W(delta)` is exactly conserved under
/// constant gravity.
fn energy(s: &Scene) -> f64 {
    let rb = &s.world.bodies[s.body];
    let dt = s.world.params.dt as f64;
    let v = rb.linvel();
    let n = s.world.params.num_solver_iterations as f64;
    let vy = v.y as f64 - 0.5 * G * dt / n; // v + g dt / (2N) with g = -G y
    let y = rb.translation().y as f64;
    let delta = (R - y).max(0.0);
    0.5 * s.mass * (vy * vy + (v.x * v.x + v.z * v.z) as f64)
        + s.mass * G * (y - R)
        + s.law.energy(delta)
}

/// 1-DOF reference: m y'' = F(R - y) - m g, RK4 at a tiny step, from contact to separation.
fn reference(law: &ContactLaw, m: f64, v0: f64) -> (f64, f64, f64) {
    let h = 1e-7;
    let (mut d, mut v) = (0.0f64, v0); // compression, d' = -y' (v > 0 compressing)
    let acc = |d: f64| -(law.response(d).force) / m + G; // d'' = -F/m + g
    let (mut t, mut peak_f, mut peak_d) = (0.0, 0.0f64, 0.0f64);
    loop {
        let (k1d, k1v) = (v, acc(d));
        let (k2d, k2v) = (v + 0.5 * h * k1v, acc(d + 0.5 * h * k1d));
        let (k3d, k3v) = (v + 0.5 * h * k2v, acc(d + 0.5 * h * k2d));
        let (k4d, k4v) = (v + h * k3v, acc(d + h * k3d));
        d += h / 6.0 * (k1d + 2.0 * k2d + 2.0 * k3d + k4d);
        v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        t += h;
        peak_f = peak_f.max(law.response(d).force);
        peak_d = peak_d.max(d);
        if d <= 0.0 {
            return (peak_f, peak_d, t);
        }
    }
}

#[test]
fn elastic_bounce_keeps_energy() {
    let mut s = scene(1.0);
    let e0 = energy(&s);
    let (mut bounces, mut in_contact, mut e_max) = (0, false, e0);
    let mut apex_energies = Vec::new();
    for _ in 0..400 {
        s.world.step();
        let touching = !s.world.soft.contacts().is_empty();
        let e = energy(&s);
        if !touching {
            e_max = e_max.max(e);
        }
        if in_contact && !touching {
            bounces += 1;
            apex_energies.push(e);
            if bounces == 10 {
                break;
            }
        }
        in_contact = touching;
    }
    let e10 = *apex_energies.last().expect("bounced");
    println!(
        "elastic bounce: {bounces} bounces, E10/E0 - 1 = {:.3e}, max E/E0 - 1 = {:.3e}, substeps total {}",
        e10 / e0 - 1.0,
        e_max / e0 - 1.0,
        s.world.soft.counters().substeps_total
    );
    assert_eq!(bounces, 10);
    assert!((e10 / e0 - 1.0).abs() < 0.02);
    assert!(e_max / e0 - 1.0 < 0.005);
}

#[test]
fn first_impact_matches_one_dof_reference() {
    let mut s = scene(1.0);
    let (mut peak_f, mut peak_d, mut duration, mut touched) = (0.0f64, 0.0f64, 0.0, false);
    let mut v_impact = 0.0;
    for _ in 0..200 {
        // The true velocity before the impact step (see `energy`).
        let n = s.world.params.num_solver_iterations as f64;
        let v_before =
            -(s.world.bodies[s.body].linvel().y as f64 - 0.5 * G * s.world.params.dt as f64 / n);
        let y_before = s.world.bodies[s.body].translation().y as f64 - R;
        s.world.step();
        let c = s.world.soft.contacts().first().cloned();
        match c {
            Some(c) => {
                if !touched {
                    // Speed at first touch: from the energy of the free fall over y_before.
                    v_impact = (v_before * v_before + 2.0 * G * y_before).sqrt();
                }
                touched = true;
                peak_f = peak_f.max(c.peak_normal_force);
                peak_d = peak_d.max(c.max_delta);
                duration += c.contact_duration;
            }
            None if touched => break,
            None => {}
        }
    }
    let (ref_f, ref_d, ref_t) = reference(&s.law, s.mass, v_impact);
    println!(
        "first impact at {v_impact:.4} m/s: peak force {peak_f:.3} N (ref {ref_f:.3}, {:+.2e}), peak delta {peak_d:.4e} m (ref {ref_d:.4e}, {:+.2e}), duration {duration:.4e} s (ref {ref_t:.4e}, {:+.2e})",
        peak_f / ref_f - 1.0,
        peak_d / ref_d - 1.0,
        duration / ref_t - 1.0
    );
    assert!((peak_f / ref_f - 1.0).abs() < 0.02);
    assert!((peak_d / ref_d - 1.0).abs() < 0.02);
    assert!((duration / ref_t - 1.0).abs() < 0.02);
}

/// Rebound velocity ratio of a drop that hits the ground at `v` [m/s].
fn rebound_ratio(restitution: f64, v: f64) -> f64 {
    let mut s = scene_from(restitution, v * v / (2.0 * G));
    let e0 = energy(&s);
    let (mut touched, mut e1) = (false, None);
    for _ in 0..2000 {
        s.world.step();
        let c = !s.world.soft.contacts().is_empty();
        if touched && !c {
            e1 = Some(energy(&s));
            break;
        }
        touched |= c;
    }
    let e1 = e1.expect("rebounded");
    // Energy above the contact point is m v^2 / 2 at touch-down and lift-off.
    (e1 / e0).sqrt()
}

/// e = 0.5 is the restitution of an impact at v_ref (default 1 m/s).
#[test]
fn restitution_half_gives_half_rebound_speed() {
    let ratio = rebound_ratio(0.5, softgrip_rapier::DEFAULT_RESTITUTION_SPEED);
    println!("restitution 0.5 at v_ref = 1 m/s: measured rebound velocity ratio {ratio:.4}");
    assert!((ratio - 0.5).abs() < 0.02);
}

/// With a constant Hunt-Crossley alpha the restitution falls with the impact speed (as for
/// rubbers): higher at slow impacts, lower at fast ones; e = 1 stays elastic at any speed.
#[test]
fn restitution_varies_with_impact_speed() {
    let e: Vec<f64> = [0.25, 1.0, 4.0]
        .iter()
        .map(|v| rebound_ratio(0.5, *v))
        .collect();
    let elastic = rebound_ratio(1.0, 4.0);
    println!(
        "restitution (e = 0.5 at 1 m/s) at 0.25 / 1 / 4 m/s: {:.4} / {:.4} / {:.4}; e = 1 at 4 m/s: {elastic:.4}",
        e[0], e[1], e[2]
    );
    assert!(e[0] > e[1] && e[1] > e[2]);
    assert!((e[1] - 0.5).abs() < 0.02);
    assert!((elastic - 1.0).abs() < 0.02);
}
