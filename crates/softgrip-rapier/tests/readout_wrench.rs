//! `TipContact::wrench_about`: the contact's force and torque on a fingertip resting on the
//! ground, about its centre and about a point beside it.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_law::Level;
use softgrip_testkit::scenes::{BallDrop, G, fingertip};

#[test]
fn wrench_of_a_resting_fingertip() {
    // Dropped from 1 mm with e = 0.5: it settles on the ground within 2 s.
    let mut s = BallDrop::new(fingertip(Level::fit(), 0.5).build().unwrap(), 0.001);
    for _ in 0..120 {
        s.world.step();
    }
    let contacts = s.world.soft.contacts();
    assert_eq!(contacts.len(), 1);
    let c = &contacts[0];
    let t = s.world.physics.bodies[s.body].translation();
    let center = [t.x as f64, t.y as f64, t.z as f64];
    let weight = s.mass * G;

    // About the centre: the weight's reaction straight up through it, no torque.
    let (f, tau) = c.wrench_about(center);
    assert!(
        (f[1] / weight - 1.0).abs() < 1e-6,
        "F_y = {} vs m g = {weight}",
        f[1]
    );
    assert!(
        f[0].abs() < 1e-9 * weight && f[2].abs() < 1e-9 * weight,
        "{f:?}"
    );
    assert!(
        tau.iter().all(|v| v.abs() < 1e-9 * weight * s.radius),
        "{tau:?}"
    );

    // About a point d beside the centre along +x: r = (-d, -(R - delta), 0), so
    // r x f = (0, 0, -d F_y).
    let d = 0.05;
    let (_, tau) = c.wrench_about([center[0] + d, center[1], center[2]]);
    assert!((tau[2] / (-d * f[1]) - 1.0).abs() < 1e-6, "{tau:?}");
    assert!(
        tau[0].abs() < 1e-9 * weight * d && tau[1].abs() < 1e-9 * weight * d,
        "{tau:?}"
    );
}
