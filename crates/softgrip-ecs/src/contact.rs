//! [`FingertipContact`]: one entity per live soft contact, updated every step.

use bevy_ecs::prelude::{Component, Entity};
use softgrip_law::ContactPatch;

/// A soft contact's readout: the plugin's [`softgrip_rapier::TipContact`] with the ECS
/// entities of both sides. Spawned when the contact starts, despawned when it ends.
#[derive(Component, Debug, Clone)]
pub struct FingertipContact {
    /// The fingertip entity.
    pub fingertip: Entity,
    /// The other side's entity (a `Collider` or a `Fingertip`).
    pub other: Entity,
    /// The body the other side belongs to (`None` for a parentless collider).
    pub other_body: Option<Entity>,
    /// What the plugin reported for the last step (forces, compression, regime, ...).
    pub contact: softgrip_rapier::TipContact,
    /// Contact radius and pressure; computed only when a [`PatchRequest`](crate::PatchRequest)
    /// resource exists (someone subscribes to pressure), `None` otherwise.
    pub patch: Option<ContactPatch>,
}
