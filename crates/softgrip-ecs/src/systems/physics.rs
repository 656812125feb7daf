//! Physics: applies the kinematic targets and calls the plugin's `SoftWorld::step`.

use bevy_ecs::prelude::{Query, ResMut};
use softgrip_scene::vector;

use crate::components::{KinematicTarget, RapierBody};
use crate::resources::{Physics, SimClock};

/// One step of the rapier world with its soft contacts.
pub fn physics_step(
    mut physics: ResMut<Physics>,
    mut clock: ResMut<SimClock>,
    targets: Query<(&RapierBody, &KinematicTarget)>,
) {
    let world = &mut physics.world;
    for (body, target) in &targets {
        if let (Some(p), Some(rb)) = (target.0, world.physics.bodies.get_mut(body.0)) {
            rb.set_next_kinematic_translation(vector(p));
        }
    }
    world.step();
    clock.step += 1;
    clock.time = clock.step as f64 * world.physics.integration_parameters.dt as f64;
}
