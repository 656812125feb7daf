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

use nalgebra::Vector3;
use rapier3d::prelude::{
    ColliderHandle, ColliderSet, CollisionEvent, ContactModificationContext, ContactPair,
    EventHandler, PairFilterContext, PhysicsHooks, RigidBodySet, SoftBodySet, SoftBodyTearEvent,
    SolverFlags,
};

use crate::boundary::to_f64;
use crate::contacts::HookView;
use crate::detect::behind_face;
use crate::excluded::ExcludedPairs;
use crate::link_contacts::LinkContacts;

/// The user's [`PhysicsHooks`], with the pairs of a fingertip answered by the plugin.
pub(crate) struct SoftHooks<'a> {
    /// The fingertips, each with its facing in its collider's frame if it is backed.
    soft: &'a HookView,
    /// rapier's contacts of multibody links along directions they cannot move (dropped).
    links: &'a LinkContacts,
    /// Pairs of bodies that never touch (`SoftContacts::exclude_pair`).
    excluded: &'a ExcludedPairs,
    user: &'a dyn PhysicsHooks,
}

impl<'a> SoftHooks<'a> {
    /// `user`'s hooks, for every pair without a collider of `soft`; the backed fingertips
    /// are those of `soft` with a facing.
    pub(crate) fn new(
        soft: &'a HookView,
        links: &'a LinkContacts,
        excluded: &'a ExcludedPairs,
        user: &'a dyn PhysicsHooks,
    ) -> Self {
        Self {
            soft,
            links,
            excluded,
            user,
        }
    }

    /// What each collider of a pair is to the plugin: `None` not a fingertip, `Some(None)` a
    /// free fingertip, `Some(Some(facing))` a backed one (one map look-up per collider; the
    /// hooks run for every pair of every rapier step).
    fn kinds(&self, a: ColliderHandle, b: ColliderHandle) -> [Tip<'_>; 2] {
        [self.soft.get(&a), self.soft.get(&b)]
    }
}

/// A collider as [`SoftHooks::kinds`] sees it.
type Tip<'a> = Option<&'a Option<Vector3<f64>>>;

/// Whether a pair has a fingertip.
fn is_soft_pair([a, b]: [Tip<'_>; 2]) -> bool {
    a.is_some() || b.is_some()
}

/// A pair that rapier's solver handles where it is behind a backed fingertip's face: at least
/// one backed fingertip, and no free one (a free fingertip is soft all round).
fn is_rigid_capable([a, b]: [Tip<'_>; 2]) -> bool {
    let backed = |k: Tip<'_>| matches!(k, Some(Some(_)));
    let free = |k: Tip<'_>| matches!(k, Some(None));
    (backed(a) || backed(b)) && !free(a) && !free(b)
}

/// The world facing of backed fingertip `h` (`kind` its [`SoftHooks::kinds`]; its collider's
/// rotation applied to it).
fn facing(colliders: &ColliderSet, h: ColliderHandle, kind: Tip<'_>) -> Option<Vector3<f64>> {
    let f = kind?.as_ref()?;
    let co = colliders.get(h)?;
    let local = rapier3d::prelude::Vector::new(f.x as f32, f.y as f32, f.z as f32);
    Some(to_f64(co.position().rotation * local))
}

impl PhysicsHooks for SoftHooks<'_> {
    /// A pair of bodies kept apart (`SoftContacts::exclude_pair`): no contact. A pair with a
    /// fingertip: rapier's solver ignores it (the plugin applies the law's impulses itself).
    /// Any other pair: the user's answer, if the user turned the hook on for one of its
    /// colliders, else rapier's default.
    fn filter_contact_pair(&self, ctx: &PairFilterContext) -> Option<SolverFlags> {
        if let (Some(a), Some(b)) = (ctx.rigid_body1, ctx.rigid_body2)
            && self.excluded.contains(a, b)
        {
            return None;
        }
        let kinds = self.kinds(ctx.collider1, ctx.collider2);
        if is_rigid_capable(kinds) {
            // Behind a backed fingertip's face: rapier's rigid contact (the solver contacts on
            // the pole side are dropped by `modify_solver_contacts`).
            Some(SolverFlags::COMPUTE_RIGID_IMPULSES)
        } else if is_soft_pair(kinds) {
            Some(SolverFlags::empty())
        } else if self
            .excluded
            .user_asked(ctx.colliders, ctx.collider1, ctx.collider2)
        {
            self.user.filter_contact_pair(ctx)
        } else {
            Some(SolverFlags::default())
        }
    }

    /// A pair with a fingertip: no intersection (fingertips are never sensors of rapier's).
    /// Any other pair: the user's answer.
    fn filter_intersection_pair(&self, ctx: &PairFilterContext) -> bool {
        if is_soft_pair(self.kinds(ctx.collider1, ctx.collider2)) {
            false
        } else {
            self.user.filter_intersection_pair(ctx)
        }
    }

    /// A pair with a backed fingertip: only the solver contacts behind the flat face of every
    /// backed fingertip of the pair are kept (the direction from its centre to its own contact
    /// point has a negative component along its facing: the rigid finger's side); the others
    /// belong to the plugin's law. Any other pair with a fingertip has no solver contacts.
    /// Any other pair: the user's (if the user turned the hook on for one of its colliders).
    /// In both, a multibody link's contacts along a direction its joints cannot move it
    /// against a body that cannot yield are dropped first (`link_contacts`).
    fn modify_solver_contacts(&self, ctx: &mut ContactModificationContext) {
        let (c1, c2) = (ctx.collider1, ctx.collider2);
        let kinds = self.kinds(c1, c2);
        if !is_soft_pair(kinds) {
            self.links.filter(ctx);
            if self.links.user_asked(ctx) {
                self.user.modify_solver_contacts(ctx);
            }
            return;
        }
        let side = |h: ColliderHandle, kind: Tip<'_>| {
            let centre = ctx
                .colliders
                .get(h)
                .map(|c| to_f64(c.position().translation));
            facing(ctx.colliders, h, kind).zip(centre)
        };
        let (s1, s2) = (side(c1, kinds[0]), side(c2, kinds[1]));
        let rigid_capable = is_rigid_capable(kinds);
        let Some(rigid) = ctx.rigid_mut() else {
            return;
        };
        if !rigid_capable {
            rigid.solver_contacts.clear();
            return;
        }
        rigid.solver_contacts.retain(|c| {
            let behind = |s: Option<(Vector3<f64>, Vector3<f64>)>, anchor| match s {
                Some((facing, centre)) => behind_face(Some(facing), &(to_f64(anchor) - centre)),
                None => true,
            };
            behind(s1, c.anchor1) && behind(s2, c.anchor2)
        });
        // A finger's rigid side behind its pad is a link like any other.
        self.links.filter(ctx);
    }
}

/// The user's [`EventHandler`], without the events of a fingertip's pairs.
pub(crate) struct SoftEvents<'a> {
    soft: &'a HookView,
    user: &'a dyn EventHandler,
}

impl<'a> SoftEvents<'a> {
    /// `user`'s handler, for every event without a collider of `soft`.
    pub(crate) fn new(soft: &'a HookView, user: &'a dyn EventHandler) -> Self {
        Self { soft, user }
    }

    fn is_soft_pair(&self, a: ColliderHandle, b: ColliderHandle) -> bool {
        self.soft.contains_key(&a) || self.soft.contains_key(&b)
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
