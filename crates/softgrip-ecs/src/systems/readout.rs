//! Readout: poses back from rapier, one [`FingertipContact`] entity per live contact,
//! fingertip wrenches, and the transition messages (one system, [`readout`]).

use std::collections::BTreeMap;

use bevy_ecs::prelude::{Commands, Entity, Query, Res, ResMut};
use softgrip_law::ContactPatch;
use softgrip_rapier::TipContact;
use softgrip_rapier::rapier3d::prelude::ColliderSet;

use crate::components::{BodyPose, FingertipWrench, RapierBody};
use crate::contact::FingertipContact;
use crate::messages::{ContactEnded, ContactStarted, SlipStarted, ValidityExcursion};
use crate::resources::{PatchRequest, Physics, SimClock, Tracked};

/// The live contacts the readout remembers, by (fingertip, other) entity.
type TrackedContacts = BTreeMap<(Entity, Entity), Tracked>;

/// The step being read out: its index and its end time [s].
#[derive(Clone, Copy)]
struct Now {
    step: u64,
    time: f64,
}

/// Both sides of a contact as entities.
#[derive(Clone, Copy)]
struct Sides {
    tip: Entity,
    other: Entity,
    other_body: Option<Entity>,
}

/// Copies every synchronised body's pose into its [`BodyPose`].
fn read_poses(physics: &Physics, poses: &mut Query<(&RapierBody, &mut BodyPose)>) {
    for (body, mut pose) in poses {
        if let Some(rb) = physics.world.physics.bodies.get(body.0) {
            let (t, q) = (rb.translation(), rb.rotation());
            pose.translation = [t.x as f64, t.y as f64, t.z as f64];
            pose.rotation = [q.x as f64, q.y as f64, q.z as f64, q.w as f64];
        }
    }
}

/// The whole `Readout` set, one system: copies every synchronised body's pose into its
/// [`BodyPose`], then spawns, updates and despawns the [`FingertipContact`] entities, sums
/// the [`FingertipWrench`]es and writes one message per transition (started, ended, slip
/// started, validity excursion).
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
    mut contacts: Query<&mut FingertipContact>,
    mut wrenches: Query<&mut FingertipWrench>,
) {
    read_poses(&physics, &mut poses);
    let physics = &mut *physics;
    let now = Now {
        step: clock.step,
        time: clock.time,
    };
    for mut w in &mut wrenches {
        if *w != FingertipWrench::default() {
            *w = FingertipWrench::default();
        }
    }
    // Tracked contacts seen in this readout (including the new ones).
    let mut live = 0;
    for c in physics.world.soft.contacts() {
        let Some(sides) = sides_of(physics, c) else {
            continue;
        };
        let patch = patches.as_ref().map(|_| c.patch());
        let tracked = &mut physics.contacts;
        let (entity, was_sliding, was_extended) = match tracked.get_mut(&(sides.tip, sides.other)) {
            Some(t) => {
                live += usize::from(t.seen != now.step);
                update(t, &mut contacts, c, sides, patch, now)
            }
            None => {
                live += 1;
                start(tracked, &mut commands, c, sides, patch, now)
            }
        };
        write_transitions(
            &mut commands,
            c,
            entity,
            sides,
            (was_sliding, was_extended),
            now,
        );
        add_wrench(
            &physics.world.physics.colliders,
            &mut wrenches,
            c,
            sides.tip,
        );
    }
    // Every tracked contact is live again: none ended (the common case, no pass over them).
    if live != physics.contacts.len() {
        end_unseen(&mut physics.contacts, &mut commands, now);
    }
}

/// The entities of both sides of a contact (`None` if either collider has none) and of the
/// other side's body.
fn sides_of(physics: &Physics, c: &TipContact) -> Option<Sides> {
    let (tip, other) = (
        physics.collider_entity(c.fingertip)?,
        physics.collider_entity(c.other)?,
    );
    let other_body = (physics.world.physics.colliders.get(c.other))
        .and_then(|co| co.parent())
        .and_then(|b| physics.body_entity(b));
    Some(Sides {
        tip,
        other,
        other_body,
    })
}

/// Updates a live contact's entity in place; returns (entity, was sliding, was extended).
fn update(
    t: &mut Tracked,
    contacts: &mut Query<&mut FingertipContact>,
    c: &TipContact,
    sides: Sides,
    patch: Option<ContactPatch>,
    now: Now,
) -> (Entity, bool, bool) {
    if let Ok(mut sc) = contacts.get_mut(t.entity) {
        let sc = &mut *sc;
        (sc.fingertip, sc.other, sc.other_body) = (sides.tip, sides.other, sides.other_body);
        sc.contact.clone_from(c);
        sc.patch = patch;
    }
    let old = (t.entity, t.sliding, t.extended);
    (t.sliding, t.extended, t.seen) = (c.sliding, c.validity_exceeded, now.step);
    old
}

/// Spawns a new contact's entity, tracks it and writes [`ContactStarted`]; returns (entity,
/// false, false): a new contact was neither sliding nor extended.
fn start(
    tracked: &mut TrackedContacts,
    commands: &mut Commands,
    c: &TipContact,
    sides: Sides,
    patch: Option<ContactPatch>,
    now: Now,
) -> (Entity, bool, bool) {
    let entity = commands
        .spawn(FingertipContact {
            fingertip: sides.tip,
            other: sides.other,
            other_body: sides.other_body,
            contact: c.clone(),
            patch,
        })
        .id();
    let t = Tracked {
        entity,
        sliding: c.sliding,
        extended: c.validity_exceeded,
        seen: now.step,
    };
    tracked.insert((sides.tip, sides.other), t);
    commands.write_message(ContactStarted {
        contact: entity,
        fingertip: sides.tip,
        other: sides.other,
        time: now.time,
    });
    (entity, false, false)
}

/// [`SlipStarted`] when the contact slides and did not, [`ValidityExcursion`] when it entered
/// the extended regime.
fn write_transitions(
    commands: &mut Commands,
    c: &TipContact,
    entity: Entity,
    sides: Sides,
    (was_sliding, was_extended): (bool, bool),
    now: Now,
) {
    if c.sliding && !was_sliding {
        commands.write_message(SlipStarted {
            contact: entity,
            fingertip: sides.tip,
            other: sides.other,
            time: now.time,
        });
    }
    if c.validity_exceeded && !was_extended {
        commands.write_message(ValidityExcursion {
            contact: entity,
            fingertip: sides.tip,
            x: c.max_x,
            x_max: c.law().x_max(),
            time: now.time,
        });
    }
}

/// Adds the contact's wrench about the fingertip's centre to the fingertip's
/// [`FingertipWrench`].
fn add_wrench(
    colliders: &ColliderSet,
    wrenches: &mut Query<&mut FingertipWrench>,
    c: &TipContact,
    tip: Entity,
) {
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

/// Despawns every tracked contact not seen in this step and writes its [`ContactEnded`].
fn end_unseen(tracked: &mut TrackedContacts, commands: &mut Commands, now: Now) {
    tracked.retain(|&(tip, other), t| {
        let seen = t.seen == now.step;
        if !seen {
            commands.entity(t.entity).despawn();
            commands.write_message(ContactEnded {
                fingertip: tip,
                other,
                time: now.time,
            });
        }
        seen
    });
}
