//! Controllers: scripted trajectories and grippers write the kinematic targets of the coming
//! step.

use bevy_ecs::prelude::{Entity, MessageWriter, Query, Res};
use softgrip_scene::{GripperEvent, jaw_compressions};

use crate::components::{KinematicPath, KinematicTarget};
use crate::contact::FingertipContact;
use crate::gripper::Gripper;
use crate::messages::GripReached;
use crate::resources::{Physics, SimClock};

/// The built-in controllers, one system: moves every kinematic body with a [`KinematicPath`]
/// to its position at the end of the coming step, then advances every [`Gripper`]'s program
/// and writes its jaws' targets (a [`GripReached`] message when the grip is reached).
pub fn run_controllers(
    physics: Res<Physics>,
    clock: Res<SimClock>,
    mut targets: Query<(Option<&KinematicPath>, &mut KinematicTarget)>,
    mut grippers: Query<(Entity, &mut Gripper)>,
    contacts: Query<&FingertipContact>,
    mut reached: MessageWriter<GripReached>,
) {
    let dt = physics.world.physics.integration_parameters.dt as f64;
    let t = (clock.step + 1) as f64 * dt;
    for (path, mut target) in &mut targets {
        if let Some(path) = path {
            target.0 = path.0.position_at(t);
        }
    }
    for (entity, mut g) in &mut grippers {
        let g = &mut *g;
        let delta = jaw_compressions(
            &g.tips,
            contacts.iter().map(|c| (c.fingertip, c.contact.delta)),
        );
        if let Some(GripperEvent::GripReached) = g.state.advance(&g.program, dt, delta) {
            reached.write(GripReached {
                gripper: entity,
                depth: g.program.depth,
                time: t,
            });
        }
        for k in 0..2 {
            if let Ok((_, mut target)) = targets.get_mut(g.jaws[k]) {
                target.0 = Some(g.state.jaws[k].position);
            }
        }
    }
}
