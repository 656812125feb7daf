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

/// A gripper's jaws (or a grasp's fingers) reached the commanded grip.
#[derive(Message, Debug, Clone, PartialEq)]
pub struct GripReached {
    /// The controller's entity.
    pub gripper: Entity,
    /// Commanded compression of each jaw's fingertip \[m\] (parallel jaws), or each joint's
    /// finger's smallest fingertip force at the stop \[N\] (grasp).
    pub depth: Vec<f64>,
    /// Simulated time at the end of the step that reaches it \[s\].
    pub time: f64,
}

/// A goal sent from outside (ROS 2's gripper action, Python) ended.
#[derive(Message, Debug, Clone, PartialEq)]
pub struct GoalEnded {
    /// The controller's entity (the robot's `joint_commands`).
    pub controller: Entity,
    /// How it ended.
    pub result: softgrip_scene::control::GoalResult,
    /// Simulated time at the end of the step \[s\].
    pub time: f64,
}
