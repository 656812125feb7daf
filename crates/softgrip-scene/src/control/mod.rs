//! Control as one interface: every controller implements [`Controller`] (ros2_control's idea:
//! robots are data, controllers are plug-ins loaded by name). The kinds: `parallel_jaws`
//! ([`ParallelJaws`], the `[gripper]`), `trajectory` ([`JointTrajectory`]), `grasp`
//! ([`Grasp`]), and each robot's commands from outside ([`JointCommands`]).

mod controller;
mod external;
mod grasp;
mod group;
mod io;
mod jaws;
mod joint_trajectory;
mod set;
mod spec;

pub use controller::{ControlEvent, Controller, GoalResult, GraspView, Phase};
pub use external::{
    CommandInbox, GOAL_TOLERANCE, GoalFeedback, GoalJoint, GripperGoal, JointCommand,
    JointCommands, STALL_SPEED, STALL_TIME, SharedInbox,
};
pub use grasp::{Grasp, GraspState};
pub use io::{Carrier, ControlIo};
pub use jaws::{
    GripperEvent, GripperProgram, GripperState, JawState, ParallelJaws, Squeeze, jaw_compressions,
};
pub use joint_trajectory::JointTrajectory;
pub use set::ControlSet;
pub use spec::{ControllerSpec, GraspSpec, JointPointSpec, TrajectorySpec};

/// The kinds of controller a scene file names (`[[controller]] type = ...`), and the kind a
/// runner adds for every robot (`joint_commands`).
pub const KINDS: [&str; 4] = ["parallel_jaws", "trajectory", "grasp", "joint_commands"];
