//! The one builder: a scene's bodies, shapes and fingertips in a rapier world, by name and in
//! file order; into a world of its own or into yours.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_scene::softgrip_rapier::SoftWorld;
use softgrip_scene::softgrip_rapier::rapier3d::prelude::Vector;
use softgrip_scene::{PlainRun, Scene};

#[test]
fn default_scene_handles_are_named_in_file_order() {
    let scene = Scene::default_scene();
    let built = scene.build();
    let h = &built.handles;
    let names: Vec<_> = h.bodies.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["table", "box", "left_jaw", "right_jaw"]);
    assert_eq!(h.shapes_of("box").count(), 1);
    assert_eq!(h.shapes_of("left_jaw").count(), 0);
    let w = &built.world;
    for (tip, jaw) in [("left_tip", "left_jaw"), ("right_tip", "right_jaw")] {
        let c = h.fingertip(tip).unwrap();
        assert!(w.soft.is_soft(c), "{tip} is registered with the plugin");
        assert_eq!(
            w.physics.colliders[c].parent(),
            h.body(jaw),
            "{tip} sits on {jaw}"
        );
    }
    assert_eq!(h.body("nope"), None);
    assert_eq!(w.physics.gravity, Vector::new(0.0, -9.81, 0.0));
    assert_eq!(w.physics.integration_parameters.dt, scene.file().dt as f32);
}

#[test]
fn build_into_keeps_the_users_world_settings_and_bodies() {
    let scene = Scene::default_scene();
    let mut world = SoftWorld::new();
    world.physics.gravity = Vector::ZERO;
    let before = world.physics.bodies.len();
    let h = scene.build_into(&mut world);
    assert_eq!(world.physics.gravity, Vector::ZERO);
    assert_eq!(world.physics.bodies.len(), before + 4);
    assert_eq!(h, scene.build().handles, "same handles in an empty world");
}

#[test]
fn plain_run_is_deterministic() {
    let scene = Scene::default_scene();
    let run = || {
        let mut run = PlainRun::new(&scene);
        let mut forces = Vec::new();
        run.run(scene.steps(), |r| {
            forces.extend(
                r.world
                    .soft
                    .contacts()
                    .iter()
                    .map(|c| c.normal_force.to_bits()),
            );
        });
        forces
    };
    let a = run();
    assert!(a.len() > 100, "the fingertips touch the box");
    assert_eq!(a, run());
}
