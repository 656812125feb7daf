//! Controllers: scripted kinematic paths, then the scene's [`Controllers`] (grippers, joint
//! trajectories, grasps, commands from outside) write the targets of the coming step.

use bevy_ecs::prelude::{MessageWriter, Query, Res, ResMut};
use softgrip_scene::ControlEvent;

use crate::components::{KinematicPath, KinematicTarget};
use crate::controller::{ControllerEntities, Controllers};
use crate::messages::{GoalEnded, GripReached};
use crate::resources::{Physics, SimClock};

/// The built-in controllers, one system: moves every kinematic body with a [`KinematicPath`]
/// to its position at the end of the coming step, then steps every controller of
/// [`Controllers`] in order (kinematic targets and joint motor targets are written into the
/// rapier world); a [`GripReached`] or [`GoalEnded`] message for what they report.
pub fn run_controllers(
    mut physics: ResMut<Physics>,
    clock: Res<SimClock>,
    controllers: Option<ResMut<Controllers>>,
    entities: Option<Res<ControllerEntities>>,
    mut targets: Query<(Option<&KinematicPath>, &mut KinematicTarget)>,
    mut reached: MessageWriter<GripReached>,
    mut goals: MessageWriter<GoalEnded>,
) {
    let dt = physics.world.physics.integration_parameters.dt as f64;
    let t = (clock.step + 1) as f64 * dt;
    for (path, mut target) in &mut targets {
        if let Some(path) = path {
            target.0 = path.0.position_at(t);
        }
    }
    let Some(mut controllers) = controllers else {
        return;
    };
    let events = controllers.0.step(&mut physics.world, t, dt);
    let entity = |i: usize| entities.as_ref().and_then(|e| e.0.get(i).copied());
    for (i, event) in events {
        let Some(controller) = entity(i) else {
            continue;
        };
        match event {
            ControlEvent::GripReached { depth } => {
                reached.write(GripReached {
                    gripper: controller,
                    depth,
                    time: t,
                });
            }
            ControlEvent::GoalEnded(result) => {
                goals.write(GoalEnded {
                    controller,
                    result,
                    time: t,
                });
            }
        }
    }
}
