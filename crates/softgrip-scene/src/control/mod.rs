//! Control as one interface: every controller implements [`Controller`] (ros2_control's idea:
//! robots are data, controllers are plug-ins loaded by name). The kinds are listed once, in
//! [`CONTROLLERS`]: `parallel_jaws` ([`ParallelJaws`], the `[gripper]`), `trajectory`
//! ([`JointTrajectory`]), `grasp` ([`Grasp`]), and each robot's commands from outside
//! (`joint_commands`, [`JointCommands`]).

mod controller;
mod external;
mod grasp;
mod group;
mod io;
mod jaws;
mod joint_trajectory;
mod kinds;
mod set;
mod spec;

pub use controller::{ControlEvent, Controller, GoalResult, GraspView, Phase};
pub use external::{
    CommandInbox, GOAL_TOLERANCE, GoalFeedback, GoalJoint, GripperGoal, JointCommand,
    JointCommands, STALL_SPEED, STALL_TIME, SharedInbox,
};
pub use grasp::{Grasp, GraspState};
pub(crate) use group::robot_names;
pub use io::{Carrier, ControlIo};
pub use jaws::{
    GripperEvent, GripperProgram, GripperState, JawState, ParallelJaws, Squeeze, jaw_compressions,
};
pub use joint_trajectory::JointTrajectory;
pub use kinds::{
    CONTROLLERS, ControllerInfo, ControllerKind, ControllerSource, UnknownControllerKind,
};
pub use set::ControlSet;
pub use spec::{ControllerSpec, GraspSpec, JointPointSpec, LiftSpec, TrajectorySpec};
