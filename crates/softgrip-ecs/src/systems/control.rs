//! Controllers: scripted trajectories and grippers write the kinematic targets of the coming
//! step.

use bevy_ecs::prelude::{MessageWriter, Query, Res};

use crate::components::{KinematicPath, KinematicTarget};
use crate::contact::SoftContact;
use crate::gripper::{Gripper, GripperEvent};
use crate::messages::GripReached;
use crate::resources::{Physics, SimClock};

/// Moves every kinematic body with a [`KinematicPath`] to its position at the end of the
/// coming step.
pub fn follow_trajectories(
    physics: Res<Physics>,
    clock: Res<SimClock>,
    mut paths: Query<(&KinematicPath, &mut KinematicTarget)>,
) {
    let t = (clock.step + 1) as f64 * physics.world.params.dt as f64;
    for (path, mut target) in &mut paths {
        target.0 = path.0.position_at(t);
    }
}

/// Largest compression of each jaw's fingertips in the last step's readout.
fn jaw_compressions<'a>(
    tips: &[Vec<bevy_ecs::prelude::Entity>; 2],
    contacts: impl Iterator<Item = &'a SoftContact>,
) -> [Option<f64>; 2] {
    let mut delta = [None, None];
    for c in contacts {
        for k in 0..2 {
            if tips[k].contains(&c.fingertip) {
                let d: f64 = c.contact.delta;
                delta[k] = Some(delta[k].map_or(d, |m: f64| m.max(d)));
            }
        }
    }
    delta
}

/// Advances every gripper's program and writes its jaws' targets; writes [`GripReached`].
pub fn run_grippers(
    physics: Res<Physics>,
    clock: Res<SimClock>,
    mut grippers: Query<(bevy_ecs::prelude::Entity, &mut Gripper)>,
    contacts: Query<&SoftContact>,
    mut targets: Query<&mut KinematicTarget>,
    mut reached: MessageWriter<GripReached>,
) {
    let dt = physics.world.params.dt as f64;
    for (entity, mut g) in &mut grippers {
        let g = &mut *g;
        let delta = jaw_compressions(&g.tips, contacts.iter());
        if let Some(GripperEvent::GripReached) = g.state.advance(&g.program, dt, delta) {
            reached.write(GripReached {
                gripper: entity,
                depth: g.program.depth,
                time: (clock.step + 1) as f64 * dt,
            });
        }
        for k in 0..2 {
            if let Ok(mut t) = targets.get_mut(g.jaws[k]) {
                t.0 = Some(g.state.jaws[k].position);
            }
        }
    }
}
