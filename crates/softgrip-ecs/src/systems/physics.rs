//! Physics: applies the kinematic targets and calls the plugin's `SoftWorld::step`.

use bevy_ecs::prelude::{Query, Res, ResMut};
use softgrip_scene::vector;

use crate::components::{KinematicTarget, RapierBody};
use crate::resources::{Names, Physics, SimClock, StepFault};

/// One step of the rapier world with its soft contacts (`SoftWorld::try_step`). A step that
/// fails sets [`StepFault`] (named with [`Names`] if present) and leaves the clock where it
/// was; a faulted world is not stepped again.
pub fn physics_step(
    mut physics: ResMut<Physics>,
    mut clock: ResMut<SimClock>,
    fault: Option<ResMut<StepFault>>,
    names: Option<Res<Names>>,
    targets: Query<(&RapierBody, &KinematicTarget)>,
) {
    if fault.as_ref().is_some_and(|f| f.0.is_some()) || physics.world.fault().is_some() {
        return;
    }
    let world = &mut physics.world;
    for (body, target) in &targets {
        if let (Some(p), Some(rb)) = (target.0, world.physics.bodies.get_mut(body.0)) {
            rb.set_next_kinematic_translation(vector(p));
        }
    }
    if let Err(e) = world.try_step() {
        // Without a `StepFault` resource, a faulting error stays in `SoftWorld::fault`.
        if let Some(mut f) = fault {
            f.0 = Some(match names {
                Some(n) => n.0.named(e),
                None => e,
            });
        }
        return;
    }
    clock.step += 1;
    clock.time = clock.step as f64 * world.physics.integration_parameters.dt as f64;
}
