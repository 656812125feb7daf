//! Determinism: the same scene built and stepped twice from scratch in one process (so with
//! different hash-map seeds) gives bit-identical contact forces and poses.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use common::{Grasp, GraspSpec};

/// The bits of every contact force, friction, torsion and the box pose, every step.
fn trace() -> Vec<u64> {
    let mut g = common::grasp(&GraspSpec {
        com_offset_z: 0.002,
        ..GraspSpec::default()
    });
    let mut out = Vec::new();
    g.run(0.1, 1.0, |g: &Grasp, _| {
        for c in g.world.soft.contacts() {
            out.push(c.normal_force.to_bits());
            out.extend(c.friction_force.iter().map(|f| f.to_bits()));
            out.push(c.torsional_moment.to_bits());
            out.push(c.delta.to_bits());
        }
        let p = g.world.physics.bodies[g.object].position();
        out.extend(p.translation.to_array().iter().map(|v| v.to_bits() as u64));
        out.extend(p.rotation.to_array().iter().map(|v| v.to_bits() as u64));
    });
    out
}

#[test]
fn same_grasp_twice_gives_bit_identical_forces() {
    let (a, b) = (trace(), trace());
    println!("determinism: {} values compared", a.len());
    // The README states 3216 values.
    assert_eq!(a.len(), 3216);
    assert_eq!(a, b);
}
