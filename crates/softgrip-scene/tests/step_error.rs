//! A scene run whose state goes wrong is a typed `StepError` naming the step, its time and
//! what diverged by the scene's name, never a panic.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::path::Path;

use softgrip_rapier::rapier3d::prelude::Vector;
use softgrip_rapier::{MAX_ANGULAR_SPEED, Phase, Quantity, StepError, Subject};
use softgrip_scene::{PlainRun, Scene};

fn parts(e: &StepError) -> (Subject, Option<&str>, Quantity, f64, Phase) {
    let d = (e.divergence()).unwrap_or_else(|| panic!("expected Diverged, got {e}"));
    (d.subject, d.name, d.quantity, d.value, d.phase)
}

#[test]
fn a_nan_velocity_on_the_default_scenes_box_is_named() {
    let scene = Scene::default_scene();
    let mut run = PlainRun::new(&scene);
    run.try_run(10, |_| {}).unwrap();
    let b = run.handles.body("box").unwrap();
    run.world.physics.bodies[b].set_linvel(Vector::new(0.0, f32::NAN, 0.0), true);
    let e = run.try_step().unwrap_err();
    let (s, name, q, v, phase) = parts(&e);
    assert_eq!(
        (s, name, q, phase),
        (
            Subject::Body(b),
            Some("box"),
            Quantity::LinearVelocity,
            Phase::Before
        )
    );
    assert!(v.is_nan());
    assert_eq!(e.step(), 11);
    let dt = scene.file().dt;
    // The sum of rapier's f32 dt.
    assert!((e.time() - 10.0 * dt).abs() < 1e-7, "{}", e.time());
    assert!(e.to_string().contains("(`box`)"), "{e}");
    // Rejected before the step: nothing advanced, nothing faulted.
    assert_eq!(run.steps(), 10);
    assert!(run.fault().is_none());
}

#[test]
fn a_huge_joint_velocity_on_a_shipped_gripper_is_named_by_its_joint() {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenes/robots/parallel_gripper_box.toml");
    let scene = Scene::from_file(&path).unwrap();
    let mut run = PlainRun::new(&scene);
    run.try_run(5, |_| {}).unwrap();
    let robot = run.handles.robot("gripper").unwrap();
    // The first moving link (not the root) and its multibody.
    let link = robot.links[1];
    let mbj = &mut run.world.physics.multibody_joints;
    let id = *mbj.rigid_body_link(link).unwrap();
    let mb = mbj.get_multibody_mut(id.multibody).unwrap();
    let at = mb.link(id.id).unwrap().assembly_id();
    mb.generalized_velocity_mut()[at] = 1.0e30;
    let e = run.try_step().unwrap_err();
    let (s, name, q, v, _) = parts(&e);
    assert_eq!(s, Subject::Joint { link, dof: 0 });
    assert_eq!(q, Quantity::JointVelocity);
    assert_eq!(v, 1.0e30f32 as f64);
    let name = name.unwrap();
    assert!(name.starts_with("gripper/"), "{name}");
    assert!(
        e.to_string()
            .contains(&format!("beyond its bound {MAX_ANGULAR_SPEED:e}"))
            || e.to_string().contains("1000000000000"),
        "{e}"
    );
}
