//! Sync: rotates the softgrip message buffers, creates the rapier body, collider or fingertip
//! of every new component.
//!
//! A scene's entities are in rapier from the start (`spawn_scene` builds the scene with
//! `softgrip-scene`'s builder and tags them). The components you spawn yourself are inserted
//! here, in spawn order (entity index) within each kind (bodies, then colliders, then
//! fingertips), through the same rapier builders. Removal is not mirrored: despawning a
//! synchronised entity leaves it in rapier.

use bevy_ecs::prelude::{
    DetectChangesMut, Entity, FromWorld, Local, Message, Messages, Or, QueryState, With, Without,
    World,
};

use crate::components::{AttachedTo, Collider, Fingertip, RapierBody, RapierCollider, RigidBody};
use crate::messages::{
    ContactEnded, ContactStarted, GoalEnded, GripReached, SlipStarted, ValidityExcursion,
};
use crate::resources::Physics;

/// One rotation of a message buffer: what `Messages::update` does, skipped when both buffers
/// are empty (then it changes nothing a reader can see), without marking the resource changed.
fn rotate<M: Message>(world: &mut World) {
    if let Some(mut messages) = world.get_resource_mut::<Messages<M>>()
        && !messages.is_empty()
    {
        messages.bypass_change_detection().update();
    }
}

type NewBody = (With<RigidBody>, Without<RapierBody>);
type NewCollider = (With<Collider>, Without<RapierCollider>);
type NewFingertip = (With<Fingertip>, Without<RapierCollider>);

/// The entities that are not in rapier yet.
pub struct Unsynchronised {
    /// Any of the three kinds (one check per step instead of three).
    any: QueryState<(), Or<(NewBody, NewCollider, NewFingertip)>>,
    bodies: QueryState<(Entity, &'static RigidBody), Without<RapierBody>>,
    colliders: QueryState<
        (Entity, &'static Collider, Option<&'static AttachedTo>),
        Without<RapierCollider>,
    >,
    tips: QueryState<(Entity, &'static Fingertip, &'static AttachedTo), Without<RapierCollider>>,
}

impl FromWorld for Unsynchronised {
    fn from_world(world: &mut World) -> Self {
        Self {
            any: QueryState::new(world),
            bodies: QueryState::new(world),
            colliders: QueryState::new(world),
            tips: QueryState::new(world),
        }
    }
}

/// Rotates the softgrip message buffers, then inserts new bodies, colliders and fingertips into
/// rapier and tags them with their handles (the whole `Sync` set).
///
/// The buffers of the six softgrip messages are rotated once per step, so a message is
/// readable during the step it is written in and the next one, then dropped (bevy's double
/// buffering). This replaces bevy's `message_update_system` for them, so they are not in
/// bevy's `MessageRegistry` ([`init_world`](crate::init_world) only inserts their `Messages`
/// resources): that system takes the registry out of the world and back every step (two
/// archetype moves in bevy_ecs 0.20, where resources are entities). Messages you register in
/// the `MessageRegistry` yourself are still rotated: [`build_schedule`](crate::build_schedule)
/// then adds bevy's system after this one.
///
/// An exclusive system: the handles are inserted at once, so the `Sync` set needs no command
/// sync point before `Control`.
pub fn sync_to_rapier(world: &mut World, mut new: Local<Unsynchronised>) {
    rotate::<ContactStarted>(world);
    rotate::<ContactEnded>(world);
    rotate::<SlipStarted>(world);
    rotate::<ValidityExcursion>(world);
    rotate::<GripReached>(world);
    rotate::<GoalEnded>(world);
    create_in_rapier(world, &mut new);
}

/// Creates the rapier body, collider or fingertip of every entity that has none yet, in spawn
/// order within each kind (bodies, colliders, fingertips).
pub(crate) fn create_in_rapier(world: &mut World, new: &mut Unsynchronised) {
    if new.any.iter(world).next().is_none() {
        return;
    }
    let mut bodies: Vec<_> = new
        .bodies
        .iter(world)
        .map(|(e, b)| (e, b.builder()))
        .collect();
    let mut colliders: Vec<_> = new
        .colliders
        .iter(world)
        .map(|(e, c, parent)| (e, c.builder(), parent.map(|p| p.0)))
        .collect();
    let mut tips: Vec<_> = new
        .tips
        .iter(world)
        .map(|(e, t, parent)| (e, t.builder(), t.tip.clone(), parent.0))
        .collect();
    if bodies.is_empty() && colliders.is_empty() && tips.is_empty() {
        return;
    }
    bodies.sort_by_key(|(e, _)| e.index_u32());
    colliders.sort_by_key(|(e, ..)| e.index_u32());
    tips.sort_by_key(|(e, ..)| e.index_u32());
    let mut tagged_bodies = Vec::with_capacity(bodies.len());
    let mut tagged_colliders = Vec::with_capacity(colliders.len() + tips.len());
    {
        let mut physics = world.resource_mut::<Physics>();
        let physics = &mut *physics;
        for (e, b) in bodies {
            let h = physics.world.physics.bodies.insert(b);
            physics.link_body(h, e);
            tagged_bodies.push((e, RapierBody(h)));
        }
        for (e, c, parent) in colliders {
            let w = &mut physics.world;
            let h = match parent.map(|p| physics.entity_body.get(&p)) {
                Some(Some(b)) => {
                    w.physics
                        .colliders
                        .insert_with_parent(c, *b, &mut w.physics.bodies)
                }
                Some(None) => continue, // its body is not synchronised yet
                None => w.physics.colliders.insert(c),
            };
            physics.link_collider(h, e);
            tagged_colliders.push((e, RapierCollider(h)));
        }
        for (e, c, tip, parent) in tips {
            let Some(&b) = physics.entity_body.get(&parent) else {
                continue;
            };
            let w = &mut physics.world;
            let h = w
                .physics
                .colliders
                .insert_with_parent(c, b, &mut w.physics.bodies);
            w.register(h, tip)
                .expect("invariant: the fingertip's own ball collider was just inserted");
            physics.link_collider(h, e);
            tagged_colliders.push((e, RapierCollider(h)));
        }
    }
    for (e, tag) in tagged_bodies {
        world.entity_mut(e).insert(tag);
    }
    for (e, tag) in tagged_colliders {
        world.entity_mut(e).insert(tag);
    }
}
