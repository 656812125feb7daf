//! The same scene through the ECS and through the plain plugin: bit-identical contact forces
//! over 1000 steps.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use std::path::Path;

use common::{Probe, contact_bits, readout_bits};
use softgrip_ecs::scene::Trajectory;
use softgrip_ecs::softgrip_rapier::rapier3d::prelude::*;
use softgrip_ecs::softgrip_rapier::{SoftAccuracy, SoftWorld};
use softgrip_ecs::{PlainRun, Scene, Simulation};

fn scene() -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/scenes/scripted_squeeze.toml");
    Scene::from_file(&path).unwrap()
}

/// The contact values of one step of the plain plugin, as the ECS frame lists them.
fn bits(world: &SoftWorld) -> Vec<u64> {
    world
        .soft
        .contacts()
        .iter()
        .flat_map(readout_bits)
        .collect()
}

/// The scripted scene written directly with rapier's and the plugin's API.
fn by_hand(scene: &Scene) -> Vec<Vec<u64>> {
    let f = scene.file();
    let mut w = SoftWorld::new();
    w.physics.gravity = Vector::new(0.0, -9.81, 0.0);
    w.physics.integration_parameters.dt = f.dt as f32;
    w.soft.set_accuracy(SoftAccuracy::try_new(0.05).unwrap());
    let body = |b: RigidBodyBuilder, x: f32| {
        b.translation(Vector::new(x, 0.02, 0.0))
            .rotation(Vector::ZERO)
            .can_sleep(false)
    };
    let table = w.physics.bodies.insert(
        RigidBodyBuilder::fixed()
            .translation(Vector::ZERO)
            .rotation(Vector::ZERO)
            .can_sleep(false),
    );
    let boxed = w
        .physics
        .bodies
        .insert(body(RigidBodyBuilder::dynamic(), 0.0));
    let left = w
        .physics
        .bodies
        .insert(body(RigidBodyBuilder::kinematic_position_based(), -0.034));
    let right = w
        .physics
        .bodies
        .insert(body(RigidBodyBuilder::kinematic_position_based(), 0.034));
    let plane = ColliderBuilder::new(SharedShape::halfspace(Vector::Y))
        .density(1000.0)
        .friction(0.5)
        .restitution(0.0);
    w.physics.colliders.insert_with_parent(
        plane.translation(Vector::ZERO),
        table,
        &mut w.physics.bodies,
    );
    let cube = ColliderBuilder::cuboid(0.02, 0.02, 0.02)
        .translation(Vector::ZERO)
        .density(31250.0)
        .friction(0.5)
        .restitution(0.0);
    w.physics
        .colliders
        .insert_with_parent(cube, boxed, &mut w.physics.bodies);
    for (jaw, tip) in [left, right].into_iter().zip(scene.fingertips()) {
        let ball = ColliderBuilder::ball(0.01)
            .translation(Vector::ZERO)
            .density(1070.0);
        let h = w
            .physics
            .colliders
            .insert_with_parent(ball, jaw, &mut w.physics.bodies);
        w.register(h, tip.clone()).unwrap();
    }
    let paths = [
        (left, Trajectory::of(&f.bodies[2])),
        (right, Trajectory::of(&f.bodies[3])),
    ];
    let dt = w.physics.integration_parameters.dt as f64;
    (0..1000u64)
        .map(|k| {
            for (h, path) in &paths {
                let p = path.position_at((k + 1) as f64 * dt).unwrap();
                w.physics.bodies[*h].set_next_kinematic_translation(Vector::new(
                    p[0] as f32,
                    p[1] as f32,
                    p[2] as f32,
                ));
            }
            w.step();
            bits(&w)
        })
        .collect()
}

#[test]
fn ecs_and_plain_plugin_give_bit_identical_forces_over_1000_steps() {
    let scene = scene();
    assert_eq!(scene.steps(), 1000);
    let probe = Probe::default();
    let mut sim = Simulation::new(&scene).with_recorder(probe.clone());
    sim.run(|_, _| {});
    let ecs = contact_bits(&probe.frames());
    let hand = by_hand(&scene);
    let mut plain = PlainRun::new(&scene);
    let baseline: Vec<Vec<u64>> = (0..1000)
        .map(|_| {
            plain.step();
            bits(&plain.world)
        })
        .collect();
    let in_contact = ecs.iter().filter(|f| !f.is_empty()).count();
    println!("{in_contact} of 1000 steps with soft contacts");
    assert!(in_contact > 200);
    assert_eq!(ecs.len(), 1000);
    for k in 0..1000 {
        assert_eq!(ecs[k], hand[k], "step {}: ECS vs rapier by hand", k + 1);
        assert_eq!(ecs[k], baseline[k], "step {}: ECS vs PlainRun", k + 1);
    }
}

#[test]
fn default_scene_ecs_equals_plain_run() {
    let scene = Scene::default_scene();
    let probe = Probe::default();
    let mut sim = Simulation::new(&scene).with_recorder(probe.clone());
    sim.run(|_, _| {});
    let ecs = contact_bits(&probe.frames());
    let mut plain = PlainRun::new(&scene);
    for (k, frame) in ecs.iter().enumerate() {
        plain.step();
        assert_eq!(*frame, bits(&plain.world), "step {}", k + 1);
    }
}
