//! `[[controller]]` as written in a scene file (SCENES.md, "Controllers"): one table per
//! controller, its kind in `type`, read through the kinds' table ([`CONTROLLERS`](super::CONTROLLERS)).

use serde::Deserialize;
use serde::de::{Deserializer, Error as _};

use crate::control::kinds::ControllerKind;
use crate::exact::exact_opt;
use crate::format::GripperSpec;

/// A controller of a scene file, by kind: `type` is looked up in
/// [`CONTROLLERS`](super::CONTROLLERS) ([`ControllerKind::from_scene_name`]; an unknown name
/// is an error listing the table), the other keys are the kind's fields.
#[derive(Debug, Clone, PartialEq)]
pub enum ControllerSpec {
    /// Kinematic jaws (the `[gripper]` table's controller).
    ParallelJaws(GripperSpec),
    /// Joint position targets over time.
    Trajectory(TrajectorySpec),
    /// Close a group of joints until a force or a position, hold, lift, open.
    Grasp(GraspSpec),
}

impl ControllerSpec {
    /// Its kind.
    pub fn kind(&self) -> ControllerKind {
        match self {
            Self::ParallelJaws(_) => ControllerKind::ParallelJaws,
            Self::Trajectory(_) => ControllerKind::Trajectory,
            Self::Grasp(_) => ControllerKind::Grasp,
        }
    }
}

impl<'de> Deserialize<'de> for ControllerSpec {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let mut table = toml::Table::deserialize(deserializer)?;
        let kind = match table.remove("type") {
            Some(toml::Value::String(name)) => {
                ControllerKind::from_scene_name(&name).map_err(D::Error::custom)?
            }
            Some(other) => {
                return Err(D::Error::custom(format!(
                    "`type` must be a string naming a controller kind, not {}",
                    other.type_str()
                )));
            }
            None => return Err(D::Error::missing_field("type")),
        };
        let fields = toml::Value::Table(table);
        match kind {
            ControllerKind::ParallelJaws => fields.try_into().map(Self::ParallelJaws),
            ControllerKind::Trajectory => fields.try_into().map(Self::Trajectory),
            ControllerKind::Grasp => fields.try_into().map(Self::Grasp),
            // `from_scene_name` gives only kinds a scene file names.
            ControllerKind::JointCommands => {
                return Err(D::Error::custom(
                    "`joint_commands` is added for every robot, not written",
                ));
            }
        }
        .map_err(|e| {
            D::Error::custom(format!(
                "`[[controller]]` of type `{kind}`: {}",
                e.message()
            ))
        })
    }
}

/// `type = "trajectory"`: joint position targets at times, linear in between (the velocity
/// target is the segment's slope), held before the first and after the last.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TrajectorySpec {
    /// Name (default `trajectory`).
    #[serde(default = "trajectory_name")]
    pub name: String,
    /// The robot.
    pub robot: String,
    /// The joints it commands, by URDF name (moving, not mimic joints).
    pub joints: Vec<String>,
    /// The points: `t` \[s\] increasing, `positions` \[m or rad\] one per joint.
    pub points: Vec<JointPointSpec>,
}

fn trajectory_name() -> String {
    ControllerKind::Trajectory.name().into()
}

/// A point of a joint trajectory.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct JointPointSpec {
    /// Time \[s\], >= 0, strictly increasing.
    pub t: f64,
    /// Position of each joint \[m or rad\], within its limits.
    pub positions: Vec<f64>,
}

/// `type = "grasp"`: closes a group of joints at `speed` until each joint's finger presses
/// `force` (or until `closed`), settles, lifts the robot's base along `up`, holds, opens.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GraspSpec {
    /// Name (default `grasp`).
    #[serde(default = "grasp_name")]
    pub name: String,
    /// The robot (its base must be `kinematic` to lift).
    pub robot: String,
    /// The joints of the group, by URDF name (moving, not mimic joints).
    pub joints: Vec<String>,
    /// Each joint's closed position \[m or rad\] (where closing stops at the latest).
    pub closed: Vec<f64>,
    /// Each joint's position after the release \[m or rad\] (default: its start position).
    #[serde(default)]
    pub open: Option<Vec<f64>>,
    /// Speed of each joint's target while closing and opening \[m/s or rad/s\], > 0 and
    /// within the joint's URDF velocity limit.
    pub speed: f64,
    /// Stop closing a joint once every fingertip of its finger presses at least this normal
    /// force \[N\], > 0; through the settle, lift and hold a stopped joint whose finger presses
    /// less (its least pad force `f`) closes again by `speed dt (force - f) / force` a step.
    /// Without it, each joint closes to `closed`.
    #[serde(default)]
    pub force: Option<f64>,
    /// Time before closing starts \[s\], >= 0 (default 0).
    #[serde(default)]
    pub start: f64,
    /// Wait after the grip is reached \[s\], >= 0 (default 0.2).
    #[serde(default = "settle")]
    pub settle: f64,
    /// Lift of the base along `up` after the settle.
    pub lift: LiftSpec,
    /// Lift direction (normalised; default opposite to gravity).
    #[serde(default, deserialize_with = "exact_opt")]
    pub up: Option<[f64; 3]>,
    /// Hold at the top \[s\], >= 0.
    pub hold: f64,
}

/// A grasp's lift: `distance` \[m\] at `speed` \[m/s\], starting and stopping at
/// `acceleration` \[m/s^2\] (a trapezoidal speed profile) or, without it, at full speed from
/// the first step to the last.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LiftSpec {
    /// Length of the lift \[m\], finite and >= 0.
    pub distance: f64,
    /// Top speed \[m/s\], finite and > 0.
    pub speed: f64,
    /// Acceleration and deceleration \[m/s^2\], finite and > 0 (default: none, the speed
    /// steps from 0 to `speed` and back in one step each).
    #[serde(default)]
    pub acceleration: Option<f64>,
}

fn grasp_name() -> String {
    ControllerKind::Grasp.name().into()
}
fn settle() -> f64 {
    0.2
}
