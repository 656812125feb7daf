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

/// A gripper goal (`control_msgs/action/ParallelGripperCommand`): the grasp primitive for the
/// named joints. Each joint's motor target moves toward its position at most at its largest
/// speed (and the URDF `velocity`); a joint whose effort reaches its largest effort stops there
/// and holds (its target frozen). The goal ends reached (every joint within [`GOAL_TOLERANCE`])
/// or stalled (the joints short of their targets still for [`STALL_TIME`]); the joints then
/// hold where the goal left them.
#[derive(Debug, Clone, PartialEq)]
pub struct GripperGoal {
    /// An id the sender chose (given back in the [`GoalResult`] and the feedback).
    pub id: u64,
    /// The joints.
    pub joints: Vec<GoalJoint>,
}

/// One joint of a [`GripperGoal`].
#[derive(Debug, Clone, PartialEq)]
pub struct GoalJoint {
    /// The joint's URDF name (a moving, not mimic joint; others are ignored, as is an entry
    /// whose position is not finite: a sender checks its goals, as `softgrip run --ros2` does).
    pub name: String,
    /// Target position \[m or rad\] (clamped to the URDF limits).
    pub position: f64,
    /// Largest speed of its target \[m/s or rad/s\], > 0 (`None`, or not finite and > 0: the
    /// URDF `velocity`).
    pub max_velocity: Option<f64>,
    /// Largest effort \[N or N m\], > 0: the joint stops and holds once its effort reaches it
    /// (`None`, or not finite and > 0: no limit but the URDF `effort`).
    pub max_effort: Option<f64>,
}

/// The state of a running goal's joints, sent as its feedback.
#[derive(Debug, Clone, PartialEq)]
pub struct GoalFeedback {
    /// The goal's id.
    pub id: u64,
    /// Each joint's name, position \[m or rad\], velocity \[m/s or rad/s\] and effort \[N
    /// or N m\] after the last step.
    pub joints: Vec<(String, f64, f64, f64)>,
}

/// A goal's joint is at its position within this \[m or rad\] (1 mm, 1 mrad).
pub const GOAL_TOLERANCE: f64 = 1e-3;
/// A goal stalls when every joint short of its target is held (its motor target at the command,
/// or frozen at its largest effort) and moved less than this speed times
/// [`STALL_TIME`] over the last [`STALL_TIME`] \[m/s or rad/s\] (its mean speed: a joint held
/// against a soft pad trembles at a few mm/s within a step's substeps).
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
    /// The running goal's state after the last step (replaced every step; taken by the sender).
    pub feedback: Option<GoalFeedback>,
}

/// A shared [`CommandInbox`].
pub type SharedInbox = Arc<Mutex<CommandInbox>>;

/// A running goal.
#[derive(Debug, Clone, PartialEq)]
struct Running {
    goal: GripperGoal,
    /// The goal's joints (robot indices), one per `goal.joints` entry that names a joint.
    joints: Vec<usize>,
    /// The entry of `goal.joints` of each of `joints`.
    entries: Vec<usize>,
    /// Each joint's position when it was last seen moving \[m or rad\].
    anchor: Vec<Option<f64>>,
    /// Time since a joint short of its target last moved \[s\].
    still: f64,
}

impl Running {
    /// The goal entry of robot joint `j`, if the goal drives it.
    fn entry(&self, j: usize) -> Option<&GoalJoint> {
        (self.joints.iter().zip(&self.entries))
            .find(|(jj, _)| **jj == j)
            .map(|(_, &e)| &self.goal.joints[e])
    }
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

    /// Checks the running goal: reached, stalled, or still going; sends its feedback.
    fn watch(&mut self, io: &ControlIo<'_>) -> Option<ControlEvent> {
        let r = self.running.as_mut()?;
        let mut reached = true;
        let mut moving = false;
        let mut feedback = Vec::with_capacity(r.joints.len());
        let model = &io.robots()[self.robot];
        for (k, (&j, &e)) in r.joints.iter().zip(&r.entries).enumerate() {
            let s = io.joint(self.robot, j);
            feedback.push((
                model.joints()[j].name.clone(),
                s.position,
                s.velocity,
                s.effort,
            ));
            let [lo, hi] = model.joints()[j].limits;
            let target = r.goal.joints[e].position.clamp(lo, hi);
            if (s.position - target).abs() > GOAL_TOLERANCE {
                reached = false;
                // Still closing: its target has not reached the command (nor been frozen at
                // the effort limit), or the joint itself moved.
                let advancing = self.targets[j].map(|t| t.0) != self.applied[j];
                let anchor = r.anchor[k].get_or_insert(s.position);
                if advancing || (s.position - *anchor).abs() > STALL_SPEED * STALL_TIME {
                    *anchor = s.position;
                    moving = true;
                }
            }
        }
        let id = r.goal.id;
        self.inbox
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .feedback = Some(GoalFeedback {
            id,
            joints: feedback,
        });
        if reached {
            return self.end(io, true, false);
        }
        r.still = if moving { 0.0 } else { r.still + io.dt };
        if r.still >= STALL_TIME {
            return self.end(io, false, true);
        }
        None
    }

    /// Starts `goal`: each named joint's target is its position (ending a running goal as
    /// neither reached nor stalled).
    fn start(&mut self, io: &ControlIo<'_>, goal: GripperGoal) -> Option<ControlEvent> {
        let event = if self.running.is_some() {
            self.end(io, false, false)
        } else {
            None
        };
        let model = &io.robots()[self.robot];
        let (mut joints, mut entries) = (Vec::new(), Vec::new());
        for (e, g) in goal.joints.iter().enumerate() {
            let Some(j) = model
                .joint_index(&g.name)
                .filter(|_| g.position.is_finite())
            else {
                continue;
            };
            let joint = &model.joints()[j];
            if !joint.kind.moves() || joint.mimic.is_some() || joints.contains(&j) {
                continue;
            }
            self.apply(
                model,
                &JointCommand {
                    name: g.name.clone(),
                    position: Some(g.position),
                    velocity: None,
                },
            );
            joints.push(j);
            entries.push(e);
        }
        let empty = joints.is_empty();
        self.running = Some(Running {
            goal,
            joints,
            anchor: vec![None; entries.len()],
            entries,
            still: 0.0,
        });
        // A goal naming no joint it can move ends at once, neither reached nor stalled.
        if empty {
            return self.end(io, false, false).or(event);
        }
        event
    }

    /// A running goal's joint whose effort reached its largest effort stops: its target is
    /// frozen where its motor's target is now.
    fn hold_at_effort(&mut self, io: &ControlIo<'_>) {
        let Some(r) = &self.running else {
            return;
        };
        for &j in &r.joints {
            let limit =
                (r.entry(j).and_then(|g| g.max_effort)).filter(|e| e.is_finite() && *e > 0.0);
            if let (Some(limit), Some(applied)) = (limit, self.applied[j])
                && io.joint(self.robot, j).effort.abs() >= limit
            {
                self.targets[j] = Some((applied, 0.0));
            }
        }
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
        // The running goal's check and feedback read the state after the last step, before
        // this step's targets change the motors (a multibody joint's effort is its motor's).
        let mut event = self.watch(io);
        for goal in goals {
            event = self.start(io, goal).or(event);
        }
        self.hold_at_effort(io);
        let limits: Vec<Option<f64>> = (io.robots()[self.robot].joints().iter().enumerate())
            .map(|(j, joint)| {
                let goal = (self.running.as_ref())
                    .and_then(|r| r.entry(j))
                    .and_then(|g| g.max_velocity)
                    .filter(|v| v.is_finite() && *v > 0.0);
                // A URDF `velocity` of 0 gives none.
                match (joint.velocity.filter(|&v| v > 0.0), goal) {
                    (Some(a), Some(b)) => Some(a.min(b)),
                    (a, b) => a.or(b),
                }
            })
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
        event
    }

    fn as_any_mut(&mut self) -> &mut dyn Any {
        self
    }

    fn boxed_clone(&self) -> Box<dyn Controller> {
        Box::new(self.clone())
    }
}
