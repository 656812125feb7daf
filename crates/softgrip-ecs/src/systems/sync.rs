//! Sync: creates the rapier body, collider or fingertip of every new component.
//!
//! New entities are inserted in spawn order (entity index) (bodies, then colliders, then fingertips), so a
//! world built from components gets the same rapier handles as one built directly in scene
//! order. Removal is not mirrored: despawning a synchronised entity leaves it in rapier.

use bevy_ecs::prelude::{Commands, Entity, Query, ResMut, Without};

use crate::components::{AttachedTo, Collider, Fingertip, RapierBody, RapierCollider, RigidBody};
use crate::resources::Physics;

/// Inserts new bodies, colliders and fingertips into rapier and tags them with their handles.
pub fn sync_to_rapier(
    mut physics: ResMut<Physics>,
    mut commands: Commands,
    bodies: Query<(Entity, &RigidBody), Without<RapierBody>>,
    colliders: Query<(Entity, &Collider, Option<&AttachedTo>), Without<RapierCollider>>,
    tips: Query<(Entity, &Fingertip, &AttachedTo), Without<RapierCollider>>,
) {
    if bodies.is_empty() && colliders.is_empty() && tips.is_empty() {
        return;
    }
    let physics = &mut *physics;
    let mut new_bodies: Vec<_> = bodies.iter().collect();
    new_bodies.sort_by_key(|(e, _)| e.index_u32());
    for (e, b) in new_bodies {
        let h = physics.world.bodies.insert(b.builder());
        physics.body_entity.insert(h.into_raw_parts(), e);
        physics.entity_body.insert(e, h);
        commands.entity(e).insert(RapierBody(h));
    }
    let mut new_colliders: Vec<_> = colliders.iter().collect();
    new_colliders.sort_by_key(|(e, ..)| e.index_u32());
    for (e, c, parent) in new_colliders {
        let w = &mut physics.world;
        let h = match parent.map(|p| physics.entity_body.get(&p.0)) {
            Some(Some(b)) => w
                .colliders
                .insert_with_parent(c.builder(), *b, &mut w.bodies),
            Some(None) => continue, // its body is not synchronised yet
            None => w.colliders.insert(c.builder()),
        };
        physics.collider_entity.insert(h.into_raw_parts(), e);
        commands.entity(e).insert(RapierCollider(h));
    }
    let mut new_tips: Vec<_> = tips.iter().collect();
    new_tips.sort_by_key(|(e, ..)| e.index_u32());
    for (e, t, parent) in new_tips {
        let Some(&b) = physics.entity_body.get(&parent.0) else {
            continue;
        };
        let w = &mut physics.world;
        let h = w
            .colliders
            .insert_with_parent(t.builder(), b, &mut w.bodies);
        w.register(h, t.tip.clone())
            .expect("invariant: the fingertip's own ball collider was just inserted");
        physics.collider_entity.insert(h.into_raw_parts(), e);
        commands.entity(e).insert(RapierCollider(h));
    }
}
