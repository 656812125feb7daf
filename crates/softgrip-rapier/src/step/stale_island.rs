//! Clearing the awake island that rapier 0.36.1 leaves behind when several of its
//! islands fall asleep in the same step.
//!
//! rapier keeps every awake body in one island (`IslandManager::awake_island`) and enters
//! its solver whenever that is `Some`. When a step puts to sleep the whole awake set as
//! *one* chunk it sets it to `None`; when it does so as *several* chunks (persistent islands
//! with nothing linking them: ten soft fingertips resting apart, whose collision groups
//! are `none()`) it moves each chunk out (`extract_sleeping_sub_island`) and leaves the
//! awake island empty but still `Some`, so every later step runs the solver on no body
//! (about 1 µs a step: crate README, "Where a resting step's time goes"). The field is
//! `pub(crate)`; the one public path that clears it is removing the last body of the awake
//! island (`RigidBodySet::remove` -> `rigid_body_removed_or_disabled`).
//!
//! So after a step that left no body awake where the step before had some, the next
//! pipeline step carries a body of its own through the awake island: a collider-less,
//! velocity-based kinematic body at the origin with no velocity, inserted before the step
//! (rapier puts it in the awake island, the only body there) and removed after it, which
//! clears the island. It touches nothing: no collider, so no broad phase, narrow phase,
//! contact or hook sees it; no joint; it is not in the plugin's tables, and the state
//! checks run outside the window where it exists. Whatever woke meanwhile is handled by
//! rapier as usual (the awake island is then not empty and no body is inserted). Visible
//! to a user only as a freed slot of the body arena whose generation moved by one.

use rapier3d::prelude::{PhysicsWorld, RigidBodyBuilder, RigidBodyHandle};

/// The state of the clearing: armed by a step that ended with no awake body after one
/// that had some.
#[derive(Debug, Default, Clone)]
pub(crate) struct StaleIsland {
    /// The last pipeline step put the awake set to sleep (awake bodies before it, none
    /// after): rapier may have left its awake island empty but set.
    armed: bool,
    /// The body carried through the present pipeline step, removed after it.
    carrier: Option<RigidBodyHandle>,
    /// Awake bodies before the present pipeline step.
    awake_before: usize,
}

impl StaleIsland {
    /// Before a pipeline step of `w`: the number of awake bodies is noted; if armed and still
    /// nothing is awake, the carrier body is inserted.
    pub(crate) fn before_step(&mut self, w: &mut PhysicsWorld) {
        self.awake_before = w.islands.num_active_bodies();
        if self.armed && self.awake_before == 0 {
            let carrier = RigidBodyBuilder::kinematic_velocity_based()
                .can_sleep(false)
                .build();
            self.carrier = Some(w.bodies.insert(carrier));
        }
        self.armed = false;
    }

    /// After the pipeline step: the carrier is removed (emptying and clearing the awake
    /// island); the clearing is armed if the step put every awake body to sleep.
    /// Returns whether a carrier was removed.
    pub(crate) fn after_step(&mut self, w: &mut PhysicsWorld) -> bool {
        let carried = self.carrier.is_some();
        self.remove_carrier(w);
        self.armed = self.awake_before > 0 && w.islands.num_active_bodies() == 0;
        carried
    }

    /// Removes the carrier if one is in `w` (after its pipeline step, or after a step that
    /// unwound from a panic inside it, so that no body of the plugin's stays in the user's
    /// set).
    pub(crate) fn remove_carrier(&mut self, w: &mut PhysicsWorld) {
        if let Some(carrier) = self.carrier.take() {
            w.bodies.remove(
                carrier,
                &mut w.islands,
                &mut w.colliders,
                &mut w.impulse_joints,
                &mut w.multibody_joints,
                &mut w.soft_bodies,
                true,
            );
        }
    }
}
