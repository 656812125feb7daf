//! [`Controller`]: the one interface every controller implements (ros2_control's idea: the
//! robot is data, a controller is a plug-in that reads the state and writes commands).

use std::any::Any;
use std::fmt::Debug;

use crate::control::io::{Carrier, ControlIo};
use crate::control::kinds::ControllerKind;

/// The phase of a grasp (the parallel jaws' program and the grasp primitive).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Phase {
    /// Closing until each finger touches; then squeezing to the commanded depth or force.
    Squeeze,
    /// At the commanded grip, waiting `settle`.
    Settle,
    /// Moving along `up`.
    Lift,
    /// Holding still.
    Hold,
    /// Opening.
    Release,
    /// Finished.
    Done,
}

/// What a controller did in one step.
#[derive(Debug, Clone, PartialEq)]
pub enum ControlEvent {
    /// Every jaw or finger reached the commanded grip; `depth` is each one's commanded
    /// compression \[m\] (jaws) or its fingertips' force at the stop \[N\] (grasp primitive,
    /// one per joint of the group).
    GripReached {
        /// Per jaw or joint, see above.
        depth: Vec<f64>,
    },
    /// A goal given from outside (ROS 2's gripper action, Python) ended.
    GoalEnded(GoalResult),
}

/// How a goal from outside ended (`control_msgs/action/ParallelGripperCommand`'s result).
#[derive(Debug, Clone, PartialEq)]
pub struct GoalResult {
    /// The goal's id (given when it was sent).
    pub id: u64,
    /// Every joint is within its tolerance of its target.
    pub reached_goal: bool,
    /// The joints stopped short of their targets (held by contact or their effort limit).
    pub stalled: bool,
    /// Each joint's name, position \[m or rad\] and effort \[N or N m\] at the end.
    pub joints: Vec<(String, f64, f64)>,
}

/// What a grasp looks like from outside (for sweeps and summaries): where its fingers are,
/// which bodies carry them, which way it lifts.
#[derive(Debug, Clone, PartialEq)]
pub struct GraspView {
    /// Lift direction (unit).
    pub up: [f64; 3],
    /// Lift distance \[m\].
    pub lift_distance: f64,
    /// The fingertips (scene indices) of each jaw or finger.
    pub fingers: Vec<Vec<usize>>,
    /// The bodies or links whose mean position is the hand's.
    pub hand: Vec<Carrier>,
    /// The commanded compression of each finger's fingertips at the grip \[m\], where the
    /// controller commands one.
    pub depth: Vec<Option<f64>>,
    /// The latest time its hold can end \[s\], when the controller knows its whole timeline
    /// (a `grasp`: every joint closing its whole stroke at its speed, as when no force is
    /// reached, then the settle, the lift with its ramps and the hold); a few steps more for
    /// the phases' step boundaries are the runner's to add. `None`: not known.
    pub hold_ends_by: Option<f64>,
}

/// A controller: each step, before the physics step, it reads the state after the last step
/// and writes the targets for the end of the coming one (kinematic bodies' positions, joint
/// motors' targets). Loaded by name from a scene file (`[[controller]] type = ...`), or added
/// by a runner (commands from ROS 2 or Python).
pub trait Controller: Debug + Send + Sync {
    /// Its name (unique in the scene).
    fn name(&self) -> &str;
    /// Its kind: a row of [`CONTROLLERS`](super::CONTROLLERS) (its name is what a scene
    /// file's `type` says: `parallel_jaws`, `trajectory`, `grasp`, ...).
    fn kind(&self) -> ControllerKind;
    /// One step: reads `io`'s state, writes its commands; returns what happened.
    fn update(&mut self, io: &mut ControlIo<'_>) -> Option<ControlEvent>;
    /// The grasp's phase, for a controller that runs a grasp.
    fn phase(&self) -> Option<Phase> {
        None
    }
    /// The grasp seen from outside, for a controller that runs one.
    fn grasp(&self) -> Option<GraspView> {
        None
    }
    /// As `Any`, for a runner that feeds a controller of its own kind (commands from outside).
    fn as_any_mut(&mut self) -> &mut dyn Any;
    /// A copy of the controller in its current state.
    fn boxed_clone(&self) -> Box<dyn Controller>;
}

impl Clone for Box<dyn Controller> {
    fn clone(&self) -> Self {
        self.boxed_clone()
    }
}
