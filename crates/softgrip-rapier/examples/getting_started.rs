//! rapier's getting-started scene (the ground cuboid and the bouncing ball of rapier's user
//! guide, on rapier's own `PhysicsWorld`) with a soft fingertip added in a few lines: a 10 mm
//! Dragon Skin 30 ball resting on the same ground. Prints the ball's altitude, then the
//! fingertip's contact force over its weight (1.0000 at rest).
//!
//! `cargo run -p softgrip-rapier --example getting_started`

use rapier3d::prelude::*;
use softgrip_rapier::{Preset, SoftContacts, SoftFingertip};

fn main() -> Result<(), softgrip_rapier::Error> {
    let mut world = PhysicsWorld::new();
    // Create the ground.
    world.insert_collider(ColliderBuilder::cuboid(100.0, 0.1, 100.0), None);
    // Create the bouncing ball.
    let (ball, _) = world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(0.0, 10.0, 0.0)),
        ColliderBuilder::ball(0.5).restitution(0.7),
    );

    // softgrip: a fingertip ball on the ground, registered with the plugin.
    let (tip_body, tip) = world.insert(
        RigidBodyBuilder::dynamic().translation(Vector::new(2.0, 0.11, 0.0)),
        ColliderBuilder::ball(0.01).density(1070.0),
    );
    let mut soft = SoftContacts::new();
    let fingertip = SoftFingertip::builder(0.01)
        .preset(Preset::DragonSkin30)
        .build()?;
    soft.register(&mut world, tip, fingertip)?;

    for _ in 0..200 {
        soft.step(&mut world, &(), &()); // instead of `world.step()`
        println!("Ball altitude: {}", world.bodies[ball].translation().y);
    }

    let weight = world.bodies[tip_body].mass() as f64 * -world.gravity.y as f64;
    let c = &soft.contacts()[0];
    println!(
        "fingertip: F / m g = {:.4}, x = {:.4}",
        c.normal_force / weight,
        c.x
    );
    Ok(())
}
