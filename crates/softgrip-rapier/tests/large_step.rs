//! Hard case 4, large step: at dt = 1/30 s a 1 kg box (10 cm cube) is squeezed by two stiff
//! fingertips (R = 10 mm, E = 3 MPa, 20 N grip: contact frequency ~ 190 Hz, omega dt ~ 40),
//! lifted 0.1 m and held 5 s: nothing explodes, nothing is NaN, and the box's kinetic energy
//! relative to the jaws stays bounded.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use common::{Grasp, GraspSpec};

#[test]
fn one_kg_box_squeezed_and_lifted_at_30_hz_stays_bounded() {
    let spec = GraspSpec {
        dt: 1.0 / 30.0,
        mass: 1.0,
        half: 0.05,
        grip_force: 20.0,
        friction: 0.8,
        youngs_modulus: 3.0e6,
        ..GraspSpec::default()
    };
    let mut g = common::grasp(&spec);
    let mut hold = Vec::new();
    let (mut ke_max, mut w_max, mut f_max) = (0.0f64, 0.0f64, 0.0f64);
    let dt = g.world.physics.integration_parameters.dt as f64;
    // Velocities from the poses of consecutive steps: rapier's stored velocity of a supported
    // body is offset by g dt (N-1)/(2N) (N-pass kick-drift), which is not motion.
    let mut prev = (g.jaw_y(), *g.world.physics.bodies[g.object].position());
    let mut rel0 = None;
    g.run(0.1, 5.0, |g: &Grasp, phase| {
        assert!(common::all_finite(&g.world), "non-finite in {phase}");
        let pose = *g.world.physics.bodies[g.object].position();
        let v_jaw = (g.jaw_y() - prev.0) / dt;
        let v = (pose.translation - prev.1.translation) / dt as f32;
        let (_, angle) = (pose.rotation * prev.1.rotation.inverse()).to_axis_angle();
        let w = (angle as f64).min(2.0 * std::f64::consts::PI - angle as f64) / dt;
        prev = (g.jaw_y(), pose);
        let rel_v = [v.x as f64, v.y as f64 - v_jaw, v.z as f64];
        // m = 1 kg; rotation: I = m (2 h^2)/3 about any axis of the cube.
        let inertia = 2.0 * g.half * g.half / 3.0;
        let ke = 0.5 * rel_v.iter().map(|x| x * x).sum::<f64>() + 0.5 * inertia * w * w;
        ke_max = ke_max.max(ke);
        w_max = w_max.max(w);
        for c in g.world.soft.contacts() {
            f_max = f_max.max(c.normal_force);
        }
        if phase == "settle" {
            rel0 = Some(g.object_y() - g.jaw_y());
        }
        if phase == "hold" {
            hold.push(g.object_y() - g.jaw_y());
        }
    });
    let (mindlin, k_t) = common::mindlin_sag(&spec, g.squeeze);
    let late = common::late_spread(&hold);
    let slip = rel0.unwrap() - (g.object_y() - g.jaw_y());
    println!(
        "dt = 1/30, 1 kg: max relative KE {ke_max:.3e} J, max |w| {w_max:.3e} rad/s, max normal force {f_max:.3} N, slip {slip:.3e} m (Mindlin m g / (2 k_t) {mindlin:.3e} m, k_t {k_t:.1} N/m; late hold {late:.2e} m), lifted {:.4} m, substeps total {}",
        g.object_y() - g.half,
        g.world.soft.counters().substeps_total
    );
    // The README states 1.5e-5 J, 0.044 rad/s, 20.1 N and a slip of 0.3 um: a factor 2 to 5
    // on the energy, 10 % on the force. The slip was 0.39 mm (and 3.4e-5 J, 0.18 rad/s) while
    // the plugin's solve did not see the ground under the box at the start of the lift
    // (`src/rigid.rs`); the friction limit, 32 N, is far above the lift's 10.4 N.
    assert!(
        ke_max < 7e-5,
        "relative kinetic energy {ke_max} J, README: 1.5e-5"
    );
    // 0.044 rad/s (0.18 rad/s before the ground was in the solve, during the lift's
    // acceleration: the box rocked in the grip). Before the
    // velocity-independent Hunt-Crossley alpha (e at 1 m/s), the slow grip contacts got
    // chi = zeta / (R * 1/s), 100x today's damping, and the peak was 0.05 rad/s.
    assert!(w_max < 0.1, "max spin {w_max} rad/s, README: 0.044");
    assert!(f_max < 22.0, "max force {f_max} N, README: 20.1"); // 20 N grip plus the lift's share, no spikes
    // Session 19, the friction spring the default: the box slides by Mindlin's elastic shear
    // of the pads, m g / (2 k_t) (275.2 um; measured 276.4 um), within 2 %, then holds (< 1 um
    // over the hold's second half). The rigid stick's slip was 0.3 um.
    assert!(
        (slip / mindlin - 1.0).abs() < 0.02,
        "slip {slip} m, Mindlin {mindlin} m"
    );
    assert!(late < 1e-6, "late hold spread {late} m");
    assert!((g.object_y() - g.half - 0.1).abs() < 2e-3);
}
