//! Pairs of bodies that never touch: a robot's links that start overlapping (a closed chain
//! modelled as a tree, links welded through a chain of fixed joints), as MoveIt's allowed
//! collision matrix disables the pairs in collision at a robot's default pose.
//!
//! rapier filters contacts per joint (a joint's `contacts_enabled`) or per multibody (its
//! self-contacts), not per pair of bodies. An excluded pair is answered by the plugin's hooks
//! (`filter_contact_pair`: no contact, rapier clears the pair) and by its detection (no soft
//! contact between a fingertip on one body and the other). Its colliders get rapier's
//! `FILTER_CONTACT_PAIRS` hook; for the pairs of a collider the user did not turn that hook
//! on for, the plugin answers what rapier would without it (`SolverFlags::default()`), so the
//! user's own filter sees only the pairs it asked for.

use std::collections::HashSet;

use rapier3d::prelude::{ActiveHooks, ColliderHandle, ColliderSet, PhysicsWorld, RigidBodyHandle};

use crate::error::{Error, Result};

/// The excluded pairs of bodies and the colliders whose pair filter the plugin turned on.
#[derive(Debug, Default, Clone)]
pub(crate) struct ExcludedPairs {
    /// Each pair once, the smaller handle first.
    pairs: HashSet<(RigidBodyHandle, RigidBodyHandle)>,
    /// Colliders given `FILTER_CONTACT_PAIRS` by the plugin, not by the user.
    added_filter: HashSet<ColliderHandle>,
}

fn key(a: RigidBodyHandle, b: RigidBodyHandle) -> (RigidBodyHandle, RigidBodyHandle) {
    if a.into_raw_parts() <= b.into_raw_parts() {
        (a, b)
    } else {
        (b, a)
    }
}

impl ExcludedPairs {
    /// Excludes `a` and `b` (two bodies of `world`) from touching each other; turns rapier's
    /// pair filter on for their colliders (those attached now).
    pub(crate) fn insert(
        &mut self,
        world: &mut PhysicsWorld,
        a: RigidBodyHandle,
        b: RigidBodyHandle,
    ) -> Result<()> {
        for h in [a, b] {
            if world.bodies.get(h).is_none() {
                return Err(Error::UnknownBody(h));
            }
        }
        if a == b {
            return Err(Error::SamePair(a));
        }
        self.pairs.insert(key(a, b));
        for h in [a, b] {
            let colliders: Vec<ColliderHandle> = world.bodies[h].colliders().to_vec();
            for ch in colliders {
                let Some(co) = world.colliders.get_mut(ch) else {
                    continue;
                };
                if !co
                    .active_hooks()
                    .contains(ActiveHooks::FILTER_CONTACT_PAIRS)
                {
                    co.set_active_hooks(co.active_hooks() | ActiveHooks::FILTER_CONTACT_PAIRS);
                    self.added_filter.insert(ch);
                }
            }
        }
        Ok(())
    }

    /// Whether bodies `a` and `b` are excluded from touching.
    pub(crate) fn contains(&self, a: RigidBodyHandle, b: RigidBodyHandle) -> bool {
        !self.pairs.is_empty() && self.pairs.contains(&key(a, b))
    }

    /// Whether the user (or a backed fingertip's registration) turned rapier's pair filter on
    /// for collider `a` or `b` of `colliders`: only then does the user's `filter_contact_pair`
    /// answer their pair (a collider the plugin gave the filter counts as the user's no more).
    pub(crate) fn user_asked(
        &self,
        colliders: &ColliderSet,
        a: ColliderHandle,
        b: ColliderHandle,
    ) -> bool {
        let asked = |h: ColliderHandle| {
            !self.added_filter.contains(&h)
                && colliders
                    .get(h)
                    .is_some_and(|c| c.active_hooks().contains(ActiveHooks::FILTER_CONTACT_PAIRS))
        };
        self.added_filter.is_empty() || asked(a) || asked(b)
    }

    /// The excluded pairs, each once.
    pub(crate) fn pairs(&self) -> impl Iterator<Item = (RigidBodyHandle, RigidBodyHandle)> + '_ {
        self.pairs.iter().copied()
    }
}
