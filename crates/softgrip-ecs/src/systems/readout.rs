//! Readout: poses back from rapier, one [`SoftContact`] entity per live contact, fingertip
//! wrenches, and the transition messages (one system, [`readout`]).

use bevy_ecs::prelude::{Commands, Query, Res, ResMut};
use softgrip_law::Regime;

use crate::components::{BodyPose, FingertipWrench, RapierBody};
use crate::contact::SoftContact;
use crate::messages::{ContactEnded, ContactStarted, SlipStarted, ValidityExcursion};
use crate::resources::{PatchRequest, Physics, SimClock, Tracked};

/// Copies every synchronised body's pose into its [`BodyPose`].
fn read_poses(physics: &Physics, poses: &mut Query<(&RapierBody, &mut BodyPose)>) {
    for (body, mut pose) in poses {
        if let Some(rb) = physics.world.bodies.get(body.0) {
            let (t, q) = (rb.translation(), rb.rotation());
            pose.translation = [t.x as f64, t.y as f64, t.z as f64];
            pose.rotation = [q.x as f64, q.y as f64, q.z as f64, q.w as f64];
        }
    }
}

/// The whole `Readout` set, one system: copies every synchronised body's pose into its
/// [`BodyPose`], then spawns, updates and despawns the [`SoftContact`] entities, sums the
/// [`FingertipWrench`]es and writes one message per transition (started, ended, slip started,
/// validity excursion).
///
/// A live contact's entity is updated in place; entities are only spawned and despawned when
/// contacts start and end. Spawns, despawns and messages go through [`Commands`], in that
/// order per contact, so they take effect together at the sync point after this system (bevy
/// inserts one before any system ordered after it, e.g. in the `Record` set) or at the end of
/// the step: a transition costs a command, a step without one touches no message buffer.
pub fn readout(
    mut physics: ResMut<Physics>,
    clock: Res<SimClock>,
    patches: Option<Res<PatchRequest>>,
    mut commands: Commands,
    mut poses: Query<(&RapierBody, &mut BodyPose)>,
    mut contacts: Query<&mut SoftContact>,
    mut wrenches: Query<&mut FingertipWrench>,
) {
    read_poses(&physics, &mut poses);
    let physics = &mut *physics;
    let (time, step) = (clock.time, clock.step);
    for mut w in &mut wrenches {
        if *w != FingertipWrench::default() {
            *w = FingertipWrench::default();
        }
    }
    // Tracked contacts seen in this readout (including the new ones).
    let mut live = 0;
    for c in physics.world.soft.contacts() {
        let (Some(tip), Some(other)) = (
            physics.collider_entity(c.fingertip),
            physics.collider_entity(c.other),
        ) else {
            continue;
        };
        let colliders = &physics.world.colliders;
        let other_body = colliders
            .get(c.other)
            .and_then(|co| co.parent())
            .and_then(|b| physics.body_entity.get(b.into_raw_parts()));
        let patch = patches.as_ref().map(|_| c.patch());
        let (sliding, extended) = (c.sliding, c.regime == Regime::Extended);
        let (entity, was_sliding, was_extended) = match physics.contacts.get_mut(&(tip, other)) {
            Some(t) => {
                if let Ok(mut sc) = contacts.get_mut(t.entity) {
                    let sc = &mut *sc;
                    (sc.fingertip, sc.other, sc.other_body) = (tip, other, other_body);
                    sc.contact.clone_from(c);
                    sc.patch = patch;
                }
                let old = (t.entity, t.sliding, t.extended);
                live += usize::from(t.seen != step);
                (t.sliding, t.extended, t.seen) = (sliding, extended, step);
                old
            }
            None => {
                let entity = commands
                    .spawn(SoftContact {
                        fingertip: tip,
                        other,
                        other_body,
                        contact: c.clone(),
                        patch,
                    })
                    .id();
                let t = Tracked {
                    entity,
                    sliding,
                    extended,
                    seen: step,
                };
                physics.contacts.insert((tip, other), t);
                live += 1;
                commands.write_message(ContactStarted {
                    contact: entity,
                    fingertip: tip,
                    other,
                    time,
                });
                (entity, false, false)
            }
        };
        if sliding && !was_sliding {
            commands.write_message(SlipStarted {
                contact: entity,
                fingertip: tip,
                other,
                time,
            });
        }
        if extended && !was_extended {
            commands.write_message(ValidityExcursion {
                contact: entity,
                fingertip: tip,
                x: c.x,
                x_max: c.law().x_max(),
                time,
            });
        }
        if let Ok(mut w) = wrenches.get_mut(tip) {
            let center = colliders
                .get(c.fingertip)
                .map(|co| co.translation())
                .map(|t| [t.x as f64, t.y as f64, t.z as f64])
                .unwrap_or(c.point);
            let (f, tau) = c.wrench_about(center);
            for i in 0..3 {
                w.force[i] += f[i];
                w.torque[i] += tau[i];
            }
        }
    }
    // Every tracked contact is live again: none ended (the common case, no pass over them).
    if live == physics.contacts.len() {
        return;
    }
    physics.contacts.retain(|&(tip, other), t| {
        let seen = t.seen == step;
        if !seen {
            commands.entity(t.entity).despawn();
            commands.write_message(ContactEnded {
                fingertip: tip,
                other,
                time,
            });
        }
        seen
    });
}
