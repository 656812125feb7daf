//! [`SoftHooks`]: rapier keeps computing manifolds for soft pairs, but builds no constraint.

use std::collections::HashSet;

use rapier3d::prelude::{ColliderHandle, PairFilterContext, PhysicsHooks, SolverFlags};

/// The physics hooks of the plugin: a read-only set of the soft colliders.
///
/// `filter_contact_pair` returns `Some(SolverFlags::empty())` for a pair with a fingertip
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
