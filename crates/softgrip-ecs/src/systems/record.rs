//! Recording and publishing: the step's data is assembled once ([`CurrentFrame`]) and handed
//! to the [`Recorder`] and the [`Publisher`] sinks.

use bevy_ecs::prelude::{Entity, Local, Name, Query, Res, ResMut, With};

use crate::components::{BodyPose, Fingertip, FingertipWrench, RigidBody};
use crate::controller::Controllers;
use crate::resources::{
    CurrentFrame, Physics, Publisher, RecordSelection, Recorder, SceneInfoResource, SimClock,
};
use crate::to_record::{JointMemory, joint_rates, joint_samples};
use softgrip_law::ContactPatch;
use softgrip_record::{BodySample, ContactSample, WrenchSample};

use crate::to_record::{contact_reading, tactile_samples};

/// Fills [`CurrentFrame`] with what [`RecordSelection`] asks for, names resolved. Scheduled
/// only on steps that a sink takes ([`StepSink::wants`](crate::StepSink::wants)): with only
/// the MCAP recorder, every `record.every_n_steps`-th step.
pub fn assemble_frame(
    physics: Res<Physics>,
    (clock, selection): (Res<SimClock>, Res<RecordSelection>),
    // The robots' controllers and the joints' positions at the last frame (one parameter).
    (controllers, mut last_joints): (Option<Res<Controllers>>, Local<Option<JointMemory>>),
    mut frame: ResMut<CurrentFrame>,
    bodies: Query<(Entity, &Name, &BodyPose), With<RigidBody>>,
    tips: Query<(Entity, &Name, &FingertipWrench), With<Fingertip>>,
    names: Query<&Name>,
) {
    let sel = &selection.0;
    let f = &mut frame.0;
    f.step = clock.step;
    f.time = clock.time;
    f.bodies.clear();
    f.wrenches.clear();
    f.contacts.clear();
    match (&controllers, sel.joints) {
        (Some(c), true) => {
            joint_samples(&c.0, &physics, &mut f.joints, &mut f.commands);
            joint_rates(clock.time, &mut last_joints, &mut f.joints);
        }
        _ => {
            f.joints.clear();
            f.commands.clear();
        }
    }
    // Tactile images whenever a fingertip has a pad (the plugin computes them only then).
    tactile_samples(&physics, &names, &mut f.tactile);
    if sel.poses {
        let mut list: Vec<_> = bodies.iter().collect();
        list.sort_by_key(|(e, ..)| e.index_u32());
        f.bodies
            .extend(list.into_iter().map(|(_, n, p)| BodySample {
                name: n.as_str().to_string(),
                translation: p.translation,
                rotation: p.rotation,
            }));
    }
    if sel.wrenches {
        let mut list: Vec<_> = tips.iter().collect();
        list.sort_by_key(|(e, ..)| e.index_u32());
        f.wrenches
            .extend(list.into_iter().map(|(_, n, w)| WrenchSample {
                fingertip: n.as_str().to_string(),
                force: w.force,
                torque: w.torque,
            }));
    }
    if sel.contacts {
        let name_of = |e: Option<Entity>| {
            e.and_then(|e| names.get(e).ok())
                .map_or_else(|| String::from("world"), |n| n.as_str().to_string())
        };
        for c in physics.world.soft.contacts() {
            let tip = physics.collider_entity(c.fingertip);
            let other = if physics.world.soft.is_soft(c.other) {
                physics.collider_entity(c.other)
            } else {
                physics
                    .world
                    .physics
                    .colliders
                    .get(c.other)
                    .and_then(|co| co.parent())
                    .and_then(|b| physics.body_entity(b))
            };
            f.contacts.push(ContactSample {
                fingertip: name_of(tip),
                other: name_of(other),
                contact: contact_reading(c, Some(recorded_patch(c, sel.pressure))),
            });
        }
    }
}

/// A contact's patch as recorded: its semi-axes always (cheap, and what a 3D view draws), its
/// pressures only when the scene records pressure.
fn recorded_patch(c: &softgrip_rapier::TipContact, pressure: bool) -> ContactPatch {
    let patch = c.patch();
    if pressure {
        patch
    } else {
        ContactPatch {
            radius: patch.radius,
            radius2: patch.radius2,
            ..ContactPatch::EMPTY
        }
    }
}

/// Hands the frame to the recorder (scheduled only on the steps it takes).
pub fn record(
    frame: Res<CurrentFrame>,
    info: Option<Res<SceneInfoResource>>,
    mut recorder: ResMut<Recorder>,
) {
    recorder.0.write(info.as_ref().map(|i| &i.0), &frame.0);
}

/// Hands the frame to the publisher.
pub fn publish(
    frame: Res<CurrentFrame>,
    info: Option<Res<SceneInfoResource>>,
    mut publisher: ResMut<Publisher>,
) {
    publisher.0.write(info.as_ref().map(|i| &i.0), &frame.0);
}
