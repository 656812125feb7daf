//! Messages (bevy_ecs 0.20's buffered events), each written exactly once per transition.

use bevy_ecs::prelude::{Entity, Message};

/// A soft contact appeared (the pair is in the plugin's readout and was not in the last one).
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct ContactStarted {
    /// The contact's entity (carrying [`FingertipContact`](crate::FingertipContact)).
    pub contact: Entity,
    /// The fingertip entity.
    pub fingertip: Entity,
    /// The other collider's entity (a `Collider` or a `Fingertip`).
    pub other: Entity,
    /// Simulated time at the end of the step \[s\].
    pub time: f64,
}

/// A soft contact disappeared; its entity was despawned.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct ContactEnded {
    /// The fingertip entity.
    pub fingertip: Entity,
    /// The other collider's entity.
    pub other: Entity,
    /// Simulated time at the end of the step \[s\].
    pub time: f64,
}

/// A contact's friction saturated (it slid) after not sliding, or at its first step.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct SlipStarted {
    /// The contact's entity.
    pub contact: Entity,
    /// The fingertip entity.
    pub fingertip: Entity,
    /// The other collider's entity.
    pub other: Entity,
    /// Simulated time at the end of the step \[s\].
    pub time: f64,
}

/// A contact's compression went past its law's validity range in some substep of the step
/// (`TipContact::validity_exceeded`), and had not in the step before: one per excursion.
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct ValidityExcursion {
    /// The contact's entity.
    pub contact: Entity,
    /// The fingertip entity.
    pub fingertip: Entity,
    /// Largest compression ratio of the step (`TipContact::max_x`) [-].
    pub x: f64,
    /// The law's validity limit [-].
    pub x_max: f64,
    /// Simulated time at the end of the step \[s\].
    pub time: f64,
}

/// A gripper's jaws reached the commanded grip (depth, or the depth of the commanded force).
#[derive(Message, Debug, Clone, Copy, PartialEq)]
pub struct GripReached {
    /// The gripper entity.
    pub gripper: Entity,
    /// Commanded compression of each jaw's fingertip \[m\].
    pub depth: [f64; 2],
    /// Simulated time at the end of the step that reaches it \[s\].
    pub time: f64,
}
