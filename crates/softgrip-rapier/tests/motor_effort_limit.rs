//! A joint motor at its effort limit (`JointMotor::max_force`) in the coupled solve (issue 25):
//! the multibody prismatic jaw of `jointed` pressing its fingertip on the box on the table
//! with a position target so deep that its 2e4 N/m motor would push far past its effort.
//! rapier's motor then pushes its `max_force` and no more; the soft solve must see the same
//! (`saturation.rs`), or it predicts a motor that holds and the tip's force is off the law
//! (the three-finger hand driven into the table took 2.4e8 N on a link from such a
//! prediction).
//!
//! `cargo test -p softgrip-rapier --test motor_effort_limit -- --nocapture` prints the numbers.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod jointed_scene;

use jointed_scene::*;

/// Sets every joint's motor's effort limit to `max_force` \[N\].
fn limit_effort(s: &mut Scene, max_force: f32) {
    let p = &mut s.world.physics;
    for j in &s.joints {
        let link = *p.multibody_joints.rigid_body_link(j.child).unwrap();
        let mb = p
            .multibody_joints
            .get_multibody_mut(link.multibody)
            .unwrap();
        let joint = &mut mb.link_mut(link.id).unwrap().joint.data;
        joint.set_motor_max_force(j.kind.axis(), max_force);
    }
}

/// The jaw's target 3 mm into the box (its unbounded motor would push about 2e4 N/m times the
/// target's depth past the tip's compression: tens of N), its effort capped at `cap`: the tip
/// must carry the cap (the motor saturated pushes exactly it; the jaw has no weight here),
/// the law's force at the geometry's compression, and the box must be still.
#[test]
fn prismatic_jaw_at_its_effort_limit_presses_with_its_effort() {
    for (pgs, cap) in [(1, 3.0f32), (PGS, 3.0), (PGS, 8.0)] {
        let mut s = scene(Build::Multibody, true, pgs, 0.0);
        limit_effort(&mut s, cap);
        let h = hold(&mut s, &[-0.003], 240);
        println!("cap {cap} N, {pgs} PGS: {h:?}");
        assert!((h.force / cap as f64 - 1.0).abs() < 1e-2, "{h:?}");
        assert!(h.law_error < 5e-3, "{h:?}");
        assert!(h.box_speed < 1e-6, "{h:?}");
    }
}
