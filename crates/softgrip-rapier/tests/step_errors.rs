//! A simulation that goes wrong numerically is a typed error from the step, never a panic,
//! and never a NaN carried on: non-finite or out-of-bounds state before or after the step, an
//! engine panic inside rapier's pipeline (the world is then faulted).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use proptest::prelude::*;
use rapier3d::prelude::*;
use softgrip_law::Material;
use softgrip_rapier::{
    MAX_ANGULAR_SPEED, MAX_LINEAR_SPEED, MAX_POSITION, Phase, Quantity, SoftFingertip, SoftWorld,
    StepError, Subject,
};

/// A fingertip (10 mm, 3 MPa) on a dynamic body resting 1 mm into a fixed floor, and a free
/// box beside it.
fn world() -> (SoftWorld, RigidBodyHandle, RigidBodyHandle) {
    let mut w = SoftWorld::new();
    let p = &mut w.physics;
    let floor = p.bodies.insert(RigidBodyBuilder::fixed());
    p.colliders
        .insert_with_parent(ColliderBuilder::cuboid(1.0, 0.1, 1.0), floor, &mut p.bodies);
    let tip = p
        .bodies
        .insert(RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 0.1 + 0.009, 0.0)));
    let c = p
        .colliders
        .insert_with_parent(ColliderBuilder::ball(0.01), tip, &mut p.bodies);
    let boxed = p
        .bodies
        .insert(RigidBodyBuilder::dynamic().translation(Vector::new(0.5, 0.2, 0.0)));
    p.colliders.insert_with_parent(
        ColliderBuilder::cuboid(0.02, 0.02, 0.02),
        boxed,
        &mut p.bodies,
    );
    let m = Material::try_new(3.0e6, 0.49).unwrap();
    w.register(c, SoftFingertip::builder(0.01).material(m).build().unwrap())
        .unwrap();
    (w, tip, boxed)
}

/// A fixed root and one dynamic link on a multibody revolute joint about z, with `limits`
/// and a position motor to 0.
fn arm(limits: [f32; 2]) -> (SoftWorld, RigidBodyHandle) {
    let (mut w, _, _) = world();
    let p = &mut w.physics;
    let root = p
        .bodies
        .insert(RigidBodyBuilder::fixed().translation(Vector::new(0.0, 1.0, 0.0)));
    let link = p
        .bodies
        .insert(RigidBodyBuilder::dynamic().translation(Vector::new(0.1, 1.0, 0.0)));
    p.colliders.insert_with_parent(
        ColliderBuilder::cuboid(0.05, 0.01, 0.01),
        link,
        &mut p.bodies,
    );
    let joint = RevoluteJointBuilder::new(Vector::Z)
        .local_anchor2(Vector::new(-0.1, 0.0, 0.0))
        .limits(limits)
        .motor_position(0.0, 100.0, 1.0);
    p.multibody_joints.insert(root, link, joint, true).unwrap();
    (w, link)
}

fn diverged(e: &StepError) -> (Subject, Quantity, f64, f64, Phase) {
    let d = (e.divergence()).unwrap_or_else(|| panic!("expected Diverged, got {e}"));
    (d.subject, d.quantity, d.value, d.bound, d.phase)
}

#[test]
fn a_valid_world_steps_without_error() {
    let (mut w, tip, _) = world();
    for _ in 0..60 {
        w.try_step().unwrap();
    }
    assert!(w.fault().is_none());
    assert_eq!(w.soft.counters().steps, 60);
    assert!((w.soft.time() - 1.0).abs() < 1e-6, "{}", w.soft.time());
    // The fingertip rests on the floor (it neither fell through nor flew off).
    let y = w.physics.bodies[tip].translation().y;
    assert!((0.105..0.111).contains(&y), "{y}");
}

#[test]
fn a_nan_or_infinite_velocity_or_position_is_rejected_before_the_step() {
    type Poke = fn(&mut RigidBody);
    let cases: [(Poke, Quantity, f64); 4] = [
        (
            |rb| rb.set_linvel(Vector::new(0.0, f32::NAN, 0.0), true),
            Quantity::LinearVelocity,
            MAX_LINEAR_SPEED,
        ),
        (
            |rb| rb.set_angvel(Vector::new(f32::INFINITY, 0.0, 0.0), true),
            Quantity::AngularVelocity,
            MAX_ANGULAR_SPEED,
        ),
        (
            |rb| rb.set_translation(Vector::new(0.0, 0.0, f32::NEG_INFINITY), true),
            Quantity::Position,
            MAX_POSITION,
        ),
        (
            |rb| rb.set_linvel(Vector::new(2.0e6, 0.0, 0.0), true),
            Quantity::LinearVelocity,
            MAX_LINEAR_SPEED,
        ),
    ];
    for (poke, quantity, bound) in cases {
        let (mut w, _, boxed) = world();
        w.try_step().unwrap();
        let before = *w.physics.bodies[boxed].position();
        poke(&mut w.physics.bodies[boxed]);
        let e = w.try_step().unwrap_err();
        let (s, q, value, b, phase) = diverged(&e);
        assert_eq!(
            (s, q, b, phase),
            (Subject::Body(boxed), quantity, bound, Phase::Before)
        );
        assert!(value.is_nan() || value.abs() > bound, "{value}");
        assert_eq!(e.step(), 2);
        assert!((e.time() - 1.0 / 60.0).abs() < 1e-9);
        // Nothing was advanced and the world is not faulted: fixing the state lets it go on.
        assert!(w.fault().is_none());
        assert_eq!(w.soft.counters().steps, 1);
        let rb = &mut w.physics.bodies[boxed];
        rb.set_position(before, true);
        rb.set_linvel(Vector::ZERO, true);
        rb.set_angvel(Vector::ZERO, true);
        w.try_step().unwrap();
        assert!(e.to_string().contains("diverged at step 2"), "{e}");
    }
}

#[test]
fn a_huge_multibody_joint_velocity_is_a_typed_error() {
    let (mut w, link) = arm([-1.0, 1.0]);
    w.try_step().unwrap();
    let id = *w.physics.multibody_joints.rigid_body_link(link).unwrap();
    let mb = w
        .physics
        .multibody_joints
        .get_multibody_mut(id.multibody)
        .unwrap();
    mb.generalized_velocity_mut()[0] = 1.0e30;
    let e = w.try_step().unwrap_err();
    let (s, q, value, bound, phase) = diverged(&e);
    assert_eq!(s, Subject::Joint { link, dof: 0 });
    assert_eq!(
        (q, value, bound, phase),
        (
            Quantity::JointVelocity,
            1.0e30f32 as f64,
            MAX_ANGULAR_SPEED,
            Phase::Before
        )
    );
}

#[test]
fn a_state_that_leaves_the_bounds_during_the_step_faults_the_world() {
    let (mut w, _, boxed) = world();
    w.physics.gravity = Vector::ZERO;
    let rb = &mut w.physics.bodies[boxed];
    rb.set_translation(Vector::new(999_999.0, 0.0, 0.0), true);
    rb.set_linvel(Vector::new(300.0, 0.0, 0.0), true); // 5 m in a step of 1/60 s
    let e = w.try_step().unwrap_err();
    let (s, q, value, bound, phase) = diverged(&e);
    assert_eq!(
        (s, q, bound, phase),
        (
            Subject::Body(boxed),
            Quantity::Position,
            MAX_POSITION,
            Phase::After
        )
    );
    assert!((value - 1_000_004.0).abs() < 0.1, "{value}");
    // Faulted: the world does not advance, and every step returns the same error.
    assert_eq!(w.fault(), Some(&e));
    let x = w.physics.bodies[boxed].translation().x;
    w.step();
    assert_eq!(w.try_step().unwrap_err(), e);
    assert_eq!(w.physics.bodies[boxed].translation().x, x);
}

/// The check after the step walks rapier's active set only (a sleeping world is not walked):
/// a body that leaves the bounds beside sleeping ones is still caught, and with two such
/// bodies the error names the first in the body set's order, as the full walk does.
#[test]
fn a_body_leaving_the_bounds_beside_sleeping_ones_is_caught_after_the_step() {
    let (mut w, tip, boxed) = world();
    for _ in 0..600 {
        w.try_step().unwrap();
    }
    assert!(w.physics.bodies[tip].is_sleeping() && w.physics.bodies[boxed].is_sleeping());
    assert_eq!(w.physics.islands.num_active_bodies(), 0);
    let runaway = |w: &mut SoftWorld, z: f32| {
        let p = &mut w.physics;
        let b = p.bodies.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(999_999.0, 5.0, z))
                .linvel(Vector::new(300.0, 0.0, 0.0)),
        );
        p.colliders
            .insert_with_parent(ColliderBuilder::ball(0.01), b, &mut p.bodies);
        b
    };
    let first = runaway(&mut w, 0.0);
    let second = runaway(&mut w, 1.0);
    assert!(first.into_raw_parts().0 < second.into_raw_parts().0);
    let e = w.try_step().unwrap_err();
    let (s, q, value, bound, phase) = diverged(&e);
    assert_eq!(
        (s, q, bound, phase),
        (
            Subject::Body(first),
            Quantity::Position,
            MAX_POSITION,
            Phase::After
        )
    );
    assert!((value - 1_000_004.0).abs() < 0.1, "{value}");
    assert!(w.physics.bodies[tip].is_sleeping() && w.physics.bodies[boxed].is_sleeping());
}

#[test]
fn a_panic_inside_rapier_is_caught_and_faults_the_world() {
    // Limits upside down: rapier's joint motor clamps its target velocity between them
    // (`f32::clamp` asserts min <= max) and panics inside the pipeline.
    let (mut w, link) = arm([1.0, -1.0]);
    let e = w.try_step().unwrap_err();
    let StepError::EnginePanicked {
        step,
        message,
        location,
        ..
    } = &e
    else {
        panic!("expected EnginePanicked, got {e}");
    };
    assert_eq!(*step, 1);
    assert!(
        message.contains("min > max") || message.contains("min <= max"),
        "{message}"
    );
    assert!(
        location.as_deref().is_some_and(|l| l.contains(".rs:")),
        "{location:?}"
    );
    assert_eq!(w.fault(), Some(&e));
    let p = *w.physics.bodies[link].position();
    w.step();
    assert_eq!(w.try_step().unwrap_err(), e);
    assert_eq!(*w.physics.bodies[link].position(), p);
}

/// A hostile number: NaN, +-inf, huge, tiny or ordinary.
fn hostile() -> impl Strategy<Value = f32> {
    prop_oneof![
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(f32::MAX),
        Just(-1.0e30f32),
        Just(1.0e7f32),
        -10.0f32..10.0,
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Random hostile values written into a body's pose or velocity, or a multibody joint's
    /// velocity, at a random step: every step returns (never panics), an error once seen stays
    /// or was a rejection before the step, and no accepted step leaves a non-finite state.
    #[test]
    fn hostile_state_never_panics(
        at in 0usize..5,
        which in 0usize..5,
        v in hostile(),
        limits_flipped in any::<bool>(),
    ) {
        let (mut w, link) = arm(if limits_flipped { [0.5, -0.5] } else { [-0.5, 0.5] });
        for k in 0..8 {
            if k == at {
                match which {
                    0 => w.physics.bodies[link].set_linvel(Vector::new(v, 0.0, 0.0), true),
                    1 => w.physics.bodies[link].set_angvel(Vector::new(0.0, 0.0, v), true),
                    2 => w.physics.bodies[link].set_translation(Vector::new(0.0, v, 0.0), true),
                    3 => {
                        let id = *w.physics.multibody_joints.rigid_body_link(link).unwrap();
                        let mb = w.physics.multibody_joints.get_multibody_mut(id.multibody).unwrap();
                        mb.generalized_velocity_mut()[0] = v;
                    }
                    _ => w.physics.gravity = Vector::new(0.0, v, 0.0),
                }
            }
            match w.try_step() {
                Ok(()) => {
                    for (_, rb) in w.physics.bodies.iter() {
                        prop_assert!(rb.translation().is_finite() && rb.linvel().is_finite());
                    }
                }
                Err(e) => prop_assert!(e.faults() == w.fault().is_some(), "{e}"),
            }
        }
    }
}
