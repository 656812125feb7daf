//! Message buffers rotate once per step: a message lives through the step after the one it is
//! written in, for the softgrip messages (rotated by the `Sync` system) and for messages of
//! your own registered with bevy (rotated by bevy's `message_update_system`).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use bevy_ecs::message::MessageRegistry;
use bevy_ecs::prelude::{Message, Messages};
use softgrip_ecs::{GripReached, Scene, Simulation, bevy_ecs};

#[derive(Message, Debug, Clone, Copy, PartialEq)]
struct Ping;

#[test]
fn messages_live_two_rotations() {
    let scene = Scene::default_scene();
    let mut sim = Simulation::new(&scene);
    MessageRegistry::register_message::<Ping>(&mut sim.world);
    sim.initialize();
    let gripper = sim.entities.gripper.unwrap();
    let reached = GripReached {
        gripper,
        depth: vec![0.0; 2],
        time: 0.0,
    };
    let counts = |sim: &Simulation| {
        (
            sim.world.resource::<Messages<GripReached>>().len(),
            sim.world.resource::<Messages<Ping>>().len(),
        )
    };
    sim.world.write_message(reached.clone()).unwrap();
    sim.world.write_message(Ping).unwrap();
    assert_eq!(counts(&sim), (1, 1));
    sim.step(); // first rotation: still readable
    assert_eq!(counts(&sim), (1, 1));
    sim.step(); // second rotation: dropped
    assert_eq!(counts(&sim), (0, 0));
    sim.world.write_message(reached.clone()).unwrap();
    sim.step();
    sim.step();
    assert_eq!(counts(&sim), (0, 0));
}
