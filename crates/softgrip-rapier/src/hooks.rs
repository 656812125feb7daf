//! The user's rapier hooks and event handler, passed through for every pair that is not a soft
//! contact.
//!
//! rapier's narrow phase never sees a fingertip: registration sets its collision and solver
//! groups to `InteractionGroups::none()` (see [`SoftContacts::register`]), so rapier filters a
//! fingertip's pairs before computing any contact, calling no hook and firing no event for
//! them. These adapters keep that true whatever the user does with the groups afterwards: a
//! pair with a fingertip is answered here (no solver contacts, no intersection, no contact
//! modification, no event) and never reaches the user's hooks or events. Every other pair, and
//! every soft-body tear event, is delegated unchanged, so the user's hooks and events on rigid
//! pairs behave exactly as in plain rapier.
//!
//! [`SoftContacts::register`]: crate::SoftContacts::register

use std::collections::HashSet;

use rapier3d::prelude::{
    ColliderHandle, ColliderSet, CollisionEvent, ContactModificationContext, ContactPair,
    EventHandler, PairFilterContext, PhysicsHooks, RigidBodySet, SoftBodySet, SoftBodyTearEvent,
    SolverFlags,
};

/// The user's [`PhysicsHooks`], with the pairs of a fingertip answered by the plugin.
pub(crate) struct SoftHooks<'a> {
    soft: &'a HashSet<ColliderHandle>,
    user: &'a dyn PhysicsHooks,
}

impl<'a> SoftHooks<'a> {
    /// `user`'s hooks, for every pair without a collider of `soft`.
    pub(crate) fn new(soft: &'a HashSet<ColliderHandle>, user: &'a dyn PhysicsHooks) -> Self {
        Self { soft, user }
    }

    fn is_soft_pair(&self, a: ColliderHandle, b: ColliderHandle) -> bool {
        self.soft.contains(&a) || self.soft.contains(&b)
    }
}

impl PhysicsHooks for SoftHooks<'_> {
    /// A pair with a fingertip: rapier's solver ignores it (the plugin applies the law's
    /// impulses itself). Any other pair: the user's answer.
    fn filter_contact_pair(&self, ctx: &PairFilterContext) -> Option<SolverFlags> {
        if self.is_soft_pair(ctx.collider1, ctx.collider2) {
            Some(SolverFlags::empty())
        } else {
            self.user.filter_contact_pair(ctx)
        }
    }

    /// A pair with a fingertip: no intersection (fingertips are never sensors of rapier's).
    /// Any other pair: the user's answer.
    fn filter_intersection_pair(&self, ctx: &PairFilterContext) -> bool {
        if self.is_soft_pair(ctx.collider1, ctx.collider2) {
            false
        } else {
            self.user.filter_intersection_pair(ctx)
        }
    }

    /// A pair with a fingertip has no solver contacts to modify. Any other pair: the user's.
    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        if !self.is_soft_pair(ctx.collider1, ctx.collider2) {
            self.user.modify_solver_contacts(ctx);
        }
    }
}

/// The user's [`EventHandler`], without the events of a fingertip's pairs.
pub(crate) struct SoftEvents<'a> {
    soft: &'a HashSet<ColliderHandle>,
    user: &'a dyn EventHandler,
}

impl<'a> SoftEvents<'a> {
    /// `user`'s handler, for every event without a collider of `soft`.
    pub(crate) fn new(soft: &'a HashSet<ColliderHandle>, user: &'a dyn EventHandler) -> Self {
        Self { soft, user }
    }

    fn is_soft_pair(&self, a: ColliderHandle, b: ColliderHandle) -> bool {
        self.soft.contains(&a) || self.soft.contains(&b)
    }
}

impl EventHandler for SoftEvents<'_> {
    fn handle_collision_event(
        &self,
        bodies: &RigidBodySet,
        colliders: &ColliderSet,
        event: CollisionEvent,
        contact_pair: Option<&ContactPair>,
    ) {
        if !self.is_soft_pair(event.collider1(), event.collider2()) {
            self.user
                .handle_collision_event(bodies, colliders, event, contact_pair);
        }
    }

    fn handle_contact_force_event(
        &self,
        dt: f32,
        bodies: &RigidBodySet,
        colliders: &ColliderSet,
        contact_pair: &ContactPair,
        total_force_magnitude: f32,
    ) {
        if !self.is_soft_pair(contact_pair.collider1, contact_pair.collider2) {
            self.user.handle_contact_force_event(
                dt,
                bodies,
                colliders,
                contact_pair,
                total_force_magnitude,
            );
        }
    }

    fn handle_soft_body_tear_event(&self, soft_bodies: &SoftBodySet, event: &SoftBodyTearEvent) {
        // rapier's own soft bodies are not fingertips: always the user's.
        self.user.handle_soft_body_tear_event(soft_bodies, event);
    }
}
