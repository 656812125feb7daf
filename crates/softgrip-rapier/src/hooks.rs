//! [`SoftHooks`]: the soft colliders as rapier physics hooks (kept for callers that drive
//! rapier's pipeline themselves; registration no longer needs them).

use std::collections::HashSet;

use rapier3d::prelude::{ColliderHandle, PairFilterContext, PhysicsHooks, SolverFlags};

/// The physics hooks of the plugin: a read-only set of the soft colliders.
///
/// Registration keeps rapier's narrow phase and solver off soft pairs through the fingertip's
/// collision and solver groups (`InteractionGroups::none()`), not through these hooks: rapier
/// filters such pairs before computing any contact (and never recycles the manifolds of pairs
/// with active hooks). The hooks stay harmless to pass (rapier calls them only for
/// colliders with `ActiveHooks::FILTER_CONTACT_PAIRS`, which the plugin no longer sets); for a
/// collider that has it, `filter_contact_pair` returns `Some(SolverFlags::empty())` for a pair with a fingertip
/// (rapier computes and keeps the manifold, events fire, but its solver ignores the pair: the
/// plugin applies the law's impulses itself) and `Some(COMPUTE_RIGID_IMPULSES)` otherwise, so
/// every other contact keeps rapier's own response.
#[derive(Debug, Clone, Default)]
pub struct SoftHooks {
    soft: HashSet<ColliderHandle>,
}

impl SoftHooks {
    pub(crate) fn insert(&mut self, handle: ColliderHandle) {
        self.soft.insert(handle);
    }

    /// Whether `handle` is a registered fingertip.
    pub fn is_soft(&self, handle: ColliderHandle) -> bool {
        self.soft.contains(&handle)
    }
}

impl PhysicsHooks for SoftHooks {
    fn filter_contact_pair(&self, ctx: &PairFilterContext) -> Option<SolverFlags> {
        if self.is_soft(ctx.collider1) || self.is_soft(ctx.collider2) {
            Some(SolverFlags::empty())
        } else {
            Some(SolverFlags::COMPUTE_RIGID_IMPULSES)
        }
    }
}
