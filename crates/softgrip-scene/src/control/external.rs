//! [`JointCommands`]: commands from outside (ROS 2's `JointState` commands and gripper action,
//! Python), through a shared [`CommandInbox`]. Every robot has one, run after the scene's own
//! controllers: a joint commanded from outside follows its last command.

use std::any::Any;
use std::sync::{Arc, Mutex, PoisonError};

use crate::control::controller::{ControlEvent, Controller, GoalResult};
use crate::control::io::ControlIo;
use crate::control::kinds::ControllerKind;
use crate::robot::Robot;

/// A joint command by name: a position target \[m or rad\] and/or a velocity target \[m/s or
/// rad/s\] (topic_based_ros2_control's `sensor_msgs/JointState` command).
#[derive(Debug, Clone, PartialEq)]
pub struct JointCommand {
    /// The joint's URDF name.
    pub name: String,
    /// Position target; `None`: keep the last.
    pub position: Option<f64>,
    /// Velocity target; `None`: 0 with a position, else keep the last.
    pub velocity: Option<f64>,
}

/// A gripper goal (`control_msgs/action/ParallelGripperCommand`): move the named joints to
/// their positions with at most `max_effort` each, until reached or stalled.
#[derive(Debug, Clone, PartialEq)]
pub struct GripperGoal {
    /// An id the sender chose (given back in the [`GoalResult`]).
    pub id: u64,
    /// (joint name, target position \[m or rad\], largest effort \[N or N m\], if given).
    pub joints: Vec<(String, f64, Option<f64>)>,
}

/// Position tolerance of a goal: reached within 1e-4 m or 1e-3 rad... as one number: a joint
/// is at its target within this \[m or rad\].
pub const GOAL_TOLERANCE: f64 = 1e-3;
/// A goal stalls when every joint short of its target moved slower than this \[m/s or rad/s\]
/// for [`STALL_TIME`].
pub const STALL_SPEED: f64 = 1e-3;
/// How long the joints must be still, short of the target, for a goal to stall \[s\].
pub const STALL_TIME: f64 = 0.1;

/// What is exchanged with the outside: commands and goals in, results out.
#[derive(Debug, Default)]
pub struct CommandInbox {
    /// Joint commands not yet applied, oldest first.
    pub commands: Vec<JointCommand>,
    /// Gripper goals not yet started, oldest first (a new goal replaces a running one, which
    /// ends as neither reached nor stalled).
    pub goals: Vec<GripperGoal>,
    /// Goals that ended, oldest first (taken by the sender).
    pub results: Vec<GoalResult>,
}

/// A shared [`CommandInbox`].
pub type SharedInbox = Arc<Mutex<CommandInbox>>;

/// A running goal.
#[derive(Debug, Clone, PartialEq)]
struct Running {
    goal: GripperGoal,
    joints: Vec<usize>,
    still: f64,
}

/// The commands from outside for one robot.
#[derive(Debug, Clone)]
pub struct JointCommands {
    name: String,
    robot: usize,
    inbox: SharedInbox,
    /// Each joint's commanded (position, velocity), once commanded.
    targets: Vec<Option<(f64, f64)>>,
    /// The position target each joint's motor was given at the last step: it moves toward the
    /// commanded position at most the URDF `velocity` per second.
    applied: Vec<Option<f64>>,
    running: Option<Running>,
}

impl JointCommands {
    /// The commands of robot `robot` (index) named `<robot>/commands`.
    pub fn new(robot: usize, model: &Robot) -> Self {
        Self {
            name: format!("{}/commands", model.name()),
            robot,
            inbox: SharedInbox::default(),
            targets: vec![None; model.joints().len()],
            applied: vec![None; model.joints().len()],
            running: None,
        }
    }

    /// The inbox the outside writes to.
    pub fn inbox(&self) -> SharedInbox {
        Arc::clone(&self.inbox)
    }

    /// The robot's index.
    pub fn robot(&self) -> usize {
        self.robot
    }

    fn apply(&mut self, model: &Robot, c: &JointCommand) {
        let Some(j) = model.joint_index(&c.name) else {
            return;
        };
        let joint = &model.joints()[j];
        if !joint.kind.moves() || joint.mimic.is_some() {
            return;
        }
        let last = self.targets[j];
        let position = c
            .position
            .filter(|p| p.is_finite())
            .map(|p| p.clamp(joint.limits[0], joint.limits[1]))
            .or(last.map(|t| t.0));
        let velocity = c
            .velocity
            .filter(|v| v.is_finite())
            .or(if c.position.is_some() {
                Some(0.0)
            } else {
                last.map(|t| t.1)
            });
        if let (Some(p), Some(v)) = (position, velocity) {
            self.targets[j] = Some((p, v));
        }
    }

    /// Ends the running goal (if any) with the joints' states; `reached` and `stalled` as found.
    fn end(&mut self, io: &ControlIo<'_>, reached: bool, stalled: bool) -> Option<ControlEvent> {
        let r = self.running.take()?;
        let model = &io.robots()[self.robot];
        let joints = (r.joints.iter())
            .map(|&j| {
                let s = io.joint(self.robot, j);
                (model.joints()[j].name.clone(), s.position, s.effort)
            })
            .collect();
        let result = GoalResult {
            id: r.goal.id,
            reached_goal: reached,
            stalled,
            joints,
        };
        self.inbox
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .results
            .push(result.clone());
        Some(ControlEvent::GoalEnded(result))
    }

    /// Checks the running goal: reached, stalled, or still going.
    fn watch(&mut self, io: &ControlIo<'_>) -> Option<ControlEvent> {
        let r = self.running.as_mut()?;
        let mut reached = true;
        let mut moving = false;
        for (&j, (_, target, _)) in r.joints.iter().zip(&r.goal.joints) {
            let s = io.joint(self.robot, j);
            if (s.position - target).abs() > GOAL_TOLERANCE {
                reached = false;
                moving |= s.velocity.abs() > STALL_SPEED;
            }
        }
        if reached {
            return self.end(io, true, false);
        }
        r.still = if moving { 0.0 } else { r.still + io.dt };
        if r.still >= STALL_TIME {
            return self.end(io, false, true);
        }
        None
    }
}

/// The motor target for a step of `dt` \[s\] from position target `from` toward the
/// commanded `(target, velocity)`: the command itself when it is within `limit · dt` (or
/// without a limit), else `limit · dt` toward it with the velocity target `±limit` (a position
/// command moves the joint no faster than its URDF `velocity`).
fn ramp(from: f64, target: f64, velocity: f64, limit: Option<f64>, dt: f64) -> (f64, f64) {
    match limit {
        Some(vmax) if vmax > 0.0 && (target - from).abs() > vmax * dt => {
            let s = (target - from).signum();
            (from + s * vmax * dt, s * vmax)
        }
        _ => (target, velocity),
    }
}

impl Controller for JointCommands {
    fn name(&self) -> &str {
        &self.name
    }

    fn kind(&self) -> ControllerKind {
        ControllerKind::JointCommands
    }

    fn update(&mut self, io: &mut ControlIo<'_>) -> Option<ControlEvent> {
        let model = &io.robots()[self.robot];
        let (commands, goals) = {
            let mut inbox = self.inbox.lock().unwrap_or_else(PoisonError::into_inner);
            (
                std::mem::take(&mut inbox.commands),
                std::mem::take(&mut inbox.goals),
            )
        };
        for c in &commands {
            self.apply(model, c);
        }
        let mut event = None;
        for goal in goals {
            if self.running.is_some() {
                event = self.end(io, false, false);
            }
            let model = &io.robots()[self.robot];
            let joints: Vec<usize> = (goal.joints.iter())
                .filter_map(|(name, _, _)| model.joint_index(name))
                .collect();
            for (name, p, _) in &goal.joints {
                self.apply(
                    model,
                    &JointCommand {
                        name: name.clone(),
                        position: Some(*p),
                        velocity: None,
                    },
                );
            }
            self.running = Some(Running {
                goal,
                joints,
                still: 0.0,
            });
        }
        let limits: Vec<Option<f64>> = (io.robots()[self.robot].joints().iter())
            .map(|j| j.velocity)
            .collect();
        for (j, limit) in limits.into_iter().enumerate() {
            let Some((p, v)) = self.targets[j] else {
                continue;
            };
            let from = self.applied[j].unwrap_or_else(|| io.joint(self.robot, j).position);
            let (p, v) = ramp(from, p, v, limit, io.dt);
            self.applied[j] = Some(p);
            io.set_joint(self.robot, j, p, v);
        }
        event.or_else(|| self.watch(io))
    }

    fn as_any_mut(&mut self) -> &mut dyn Any {
        self
    }

    fn boxed_clone(&self) -> Box<dyn Controller> {
        Box::new(self.clone())
    }
}
