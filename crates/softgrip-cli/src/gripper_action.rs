//! `softgrip run --ros2` with robots: a `control_msgs/action/ParallelGripperCommand` server for
//! each gripper group, at `/<group>/gripper_cmd`. A group is a `grasp` controller's joints
//! (named by the controller), or, for a robot no grasp controller names, the robot's moving
//! joints but its mimic ones (named by the robot). A goal becomes a
//! [`GripperGoal`] in its robot's inbox: the robot's
//! `joint_commands` controller runs it (close at the goal's speed until each joint's effort
//! reaches the goal's effort or the position is reached, then hold) and hands back its feedback
//! and result, which a thread here sends.

use std::collections::HashMap;
use std::sync::PoisonError;
use std::time::Duration;

use anyhow::Result;
use softgrip_ecs::scene::control::{
    ControlSet, GoalJoint, GoalResult, Grasp, GripperGoal, SharedInbox,
};
use softgrip_record::msgs::sensor_msgs::JointState;
use softgrip_ros2::{GoalKey, GripperActionServer, NodeOptions, ParallelGripperResult};

use crate::worker::Worker;

/// How often the thread looks for goals, result requests and the simulation's answers.
const POLL: Duration = Duration::from_millis(5);

/// A gripper group: its name, its robot's inbox and its joints' URDF names.
#[derive(Debug, Clone)]
pub struct Group {
    /// The action is `/<name>/gripper_cmd`.
    pub name: String,
    /// Its robot's inbox.
    pub inbox: SharedInbox,
    /// The joints a goal may name.
    pub joints: Vec<String>,
    /// Each joint's URDF limits `[lower, upper]` \[m or rad\]: a goal's position must lie
    /// within them.
    pub limits: Vec<[f64; 2]>,
}

/// A joint a gripper goal may name: its URDF name and limits `[lower, upper]` \[m or rad\].
type NamedJoint = (String, [f64; 2]);

/// The gripper groups of a scene's controllers (see the module's documentation).
pub fn groups(set: &mut ControlSet) -> Vec<Group> {
    let robots = set.robots().to_vec();
    let mut found: Vec<(usize, String, Vec<NamedJoint>)> = Vec::new();
    for c in set.controllers_mut() {
        if let Some(g) = c.as_any_mut().downcast_mut::<Grasp>() {
            let model = &robots[g.robot];
            let names = (g.joints.iter())
                .map(|&j| (model.joints()[j].name.clone(), model.joints()[j].limits))
                .collect();
            found.push((g.robot, g.name.clone(), names));
        }
    }
    for (r, model) in robots.iter().enumerate() {
        if found.iter().any(|(fr, _, _)| *fr == r) {
            continue;
        }
        let names: Vec<NamedJoint> = (model.joints().iter())
            .filter(|j| j.kind.moves() && j.mimic.is_none())
            .map(|j| (j.name.clone(), j.limits))
            .collect();
        if !names.is_empty() {
            found.push((r, model.name().to_owned(), names));
        }
    }
    (found.into_iter())
        .filter_map(|(r, name, joints)| {
            set.inbox(r).map(|inbox| Group {
                name,
                inbox,
                limits: joints.iter().map(|j| j.1).collect(),
                joints: joints.into_iter().map(|j| j.0).collect(),
            })
        })
        .collect()
}

/// Why a goal's command is refused, if it is: every name a joint of the group (no name: the
/// group's joints in order), one finite position per joint within the joint's URDF limits, and
/// `velocity` and `effort` empty or one finite value > 0 per joint.
pub fn check_goal(group: &Group, command: &JointState) -> Result<Vec<GoalJoint>, String> {
    let names: Vec<String> = if command.name.is_empty() {
        group.joints.clone()
    } else {
        command.name.clone()
    };
    if let Some(n) = names.iter().find(|n| !group.joints.contains(n)) {
        return Err(format!(
            "`{n}` is not a joint of gripper group `{}` ({})",
            group.name,
            group.joints.join(", ")
        ));
    }
    if command.position.len() != names.len() {
        return Err(format!(
            "{} positions for {} joints",
            command.position.len(),
            names.len()
        ));
    }
    let limit = |field: &str, v: &[f64], k: usize| -> Result<Option<f64>, String> {
        match v.len() {
            0 => Ok(None),
            n if n != names.len() => Err(format!("{n} {field} values for {} joints", names.len())),
            _ if v[k].is_finite() && v[k] > 0.0 => Ok(Some(v[k])),
            _ => Err(format!("{field}[{k}] = {} is not finite and > 0", v[k])),
        }
    };
    (names.iter().enumerate())
        .map(|(k, name)| {
            let position = command.position[k];
            if !position.is_finite() {
                return Err(format!("position[{k}] = {position} is not finite"));
            }
            let i = (group.joints.iter().position(|j| j == name)).unwrap_or_default();
            if let Some(&[lo, hi]) = group.limits.get(i)
                && !(lo..=hi).contains(&position)
            {
                return Err(format!(
                    "position[{k}] = {position} is outside joint `{name}`'s limits [{lo}, {hi}]"
                ));
            }
            Ok(GoalJoint {
                name: name.clone(),
                position,
                max_velocity: limit("velocity", &command.velocity, k)?,
                max_effort: limit("effort", &command.effort, k)?,
            })
        })
        .collect()
}

/// The result message of a goal that ended.
fn result_message(r: &GoalResult) -> ParallelGripperResult {
    ParallelGripperResult {
        state: JointState {
            name: r.joints.iter().map(|j| j.0.clone()).collect(),
            position: r.joints.iter().map(|j| j.1).collect(),
            effort: r.joints.iter().map(|j| j.2).collect(),
            ..JointState::default()
        },
        stalled: r.stalled,
        reached_goal: r.reached_goal,
    }
}

/// What the action servers did.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Counts {
    /// Goals accepted.
    pub accepted: u64,
    /// Goals refused (see [`check_goal`]).
    pub rejected: u64,
    /// Goals that ended reached.
    pub reached: u64,
    /// Goals that ended stalled.
    pub stalled: u64,
}

/// One server per group, and the goals sent to the simulation.
struct Bridge {
    servers: Vec<(GripperActionServer, Group)>,
    /// Goal id (the simulation's) -> (server index, the action's goal key).
    running: HashMap<u64, (usize, GoalKey)>,
    next_id: u64,
    counts: Counts,
}

impl Bridge {
    fn step(&mut self) -> Result<()> {
        for (i, (server, group)) in self.servers.iter_mut().enumerate() {
            server.poll()?;
            let mut refused = None;
            let mut joints = Vec::new();
            let goal = server.take_goal(|command| match check_goal(group, command) {
                Ok(j) => {
                    joints = j;
                    true
                }
                Err(e) => {
                    refused = Some(e);
                    false
                }
            })?;
            if let Some(why) = refused {
                self.counts.rejected += 1;
                eprintln!("ros2: gripper goal on {} refused: {why}", server.name());
            }
            if let Some((key, _)) = goal {
                let id = self.next_id;
                self.next_id += 1;
                self.running.insert(id, (i, key));
                self.counts.accepted += 1;
                lock(&group.inbox).goals.push(GripperGoal { id, joints });
            }
        }
        for k in 0..self.servers.len() {
            let (results, feedback) = {
                let mut inbox = lock(&self.servers[k].1.inbox);
                (std::mem::take(&mut inbox.results), inbox.feedback.take())
            };
            if let Some(f) = feedback
                && let Some(&(i, key)) = self.running.get(&f.id)
            {
                let state = JointState {
                    name: f.joints.iter().map(|j| j.0.clone()).collect(),
                    position: f.joints.iter().map(|j| j.1).collect(),
                    velocity: f.joints.iter().map(|j| j.2).collect(),
                    effort: f.joints.iter().map(|j| j.3).collect(),
                    ..JointState::default()
                };
                self.servers[i].0.feedback(key, state);
            }
            for r in results {
                if let Some((i, key)) = self.running.remove(&r.id) {
                    self.counts.reached += u64::from(r.reached_goal);
                    self.counts.stalled += u64::from(r.stalled);
                    self.servers[i].0.finish(key, result_message(&r));
                }
            }
        }
        Ok(())
    }
}

fn lock(
    inbox: &SharedInbox,
) -> std::sync::MutexGuard<'_, softgrip_ecs::scene::control::CommandInbox> {
    inbox.lock().unwrap_or_else(PoisonError::into_inner)
}

/// The action servers' thread.
pub struct GripperActions {
    worker: Worker<Counts>,
    names: Vec<String>,
}

impl GripperActions {
    /// Serves each group's action on the domain of `ROS_DOMAIN_ID`; returns once every server
    /// exists (the first error, if one cannot).
    pub fn start(groups: Vec<Group>) -> Result<Self> {
        let names = (groups.iter())
            .map(|g| format!("/{}/{}", g.name, softgrip_ros2::GRIPPER_ACTION_SUFFIX))
            .collect();
        let what = "serving control_msgs/action/ParallelGripperCommand";
        let worker = Worker::start("ros2-gripper-action", what, move |stop, ready| {
            let mut servers = Vec::new();
            for g in groups {
                let options = NodeOptions {
                    name: format!("softgrip_{}", g.name),
                    ..NodeOptions::default()
                };
                match GripperActionServer::new(&options, &g.name) {
                    Ok(s) => servers.push((s, g)),
                    Err(e) => {
                        let _ = ready.send(Err(anyhow::anyhow!("{e}")));
                        return Ok(Counts::default());
                    }
                }
            }
            let _ = ready.send(Ok(()));
            let mut bridge = Bridge {
                servers,
                running: HashMap::new(),
                next_id: 0,
                counts: Counts::default(),
            };
            while !stop.stopped() {
                bridge.step()?;
                std::thread::sleep(POLL);
            }
            // The simulation's last answers (a goal that ended in the last step).
            bridge.step()?;
            Ok(bridge.counts)
        })?;
        Ok(Self { worker, names })
    }

    /// The actions served.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// Stops the thread and returns what it did.
    pub fn finish(self) -> Result<Counts> {
        self.worker.finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn group() -> Group {
        Group {
            name: "gripper".into(),
            inbox: SharedInbox::default(),
            joints: vec!["a".into(), "b".into()],
            limits: vec![[0.0, 0.5], [-1.0, 1.0]],
        }
    }

    fn command(name: &[&str], position: &[f64], velocity: &[f64], effort: &[f64]) -> JointState {
        JointState {
            name: name.iter().map(|n| (*n).to_owned()).collect(),
            position: position.to_vec(),
            velocity: velocity.to_vec(),
            effort: effort.to_vec(),
            ..JointState::default()
        }
    }

    #[test]
    fn a_goal_names_joints_of_its_group_with_limits() {
        let g = check_goal(&group(), &command(&["b"], &[0.01], &[0.02], &[5.0])).unwrap();
        assert_eq!(
            g,
            [GoalJoint {
                name: "b".into(),
                position: 0.01,
                max_velocity: Some(0.02),
                max_effort: Some(5.0),
            }]
        );
        // No names: the group's joints in order; no velocity or effort: no limits.
        let g = check_goal(&group(), &command(&[], &[0.1, 0.2], &[], &[])).unwrap();
        assert_eq!(
            (g[1].name.as_str(), g[1].position, g[1].max_effort),
            ("b", 0.2, None)
        );
    }

    #[test]
    fn bad_goals_are_refused_naming_the_field() {
        let cases = [
            (command(&["c"], &[0.0], &[], &[]), "`c` is not a joint"),
            (command(&["a"], &[], &[], &[]), "0 positions for 1 joints"),
            (command(&["a"], &[f64::NAN], &[], &[]), "position[0] = NaN"),
            (
                command(&["a"], &[0.0], &[-1.0], &[]),
                "velocity[0] = -1 is not",
            ),
            (
                command(&["a"], &[0.0], &[], &[f64::INFINITY]),
                "effort[0] = inf",
            ),
            (
                command(&["a", "b"], &[0.0, 0.0], &[1.0], &[]),
                "1 velocity values for 2 joints",
            ),
            (
                command(&["a"], &[0.0], &[], &[f64::NAN]),
                "effort[0] = NaN is not finite and > 0",
            ),
            (
                command(&["a"], &[0.0], &[], &[-5.0]),
                "effort[0] = -5 is not finite and > 0",
            ),
            (
                command(&["a"], &[0.0], &[], &[0.0]),
                "effort[0] = 0 is not finite and > 0",
            ),
            (
                command(&["b", "a"], &[0.5, 0.6], &[], &[]),
                "position[1] = 0.6 is outside joint `a`'s limits [0, 0.5]",
            ),
            (
                command(&[], &[-0.001, 0.0], &[], &[]),
                "position[0] = -0.001 is outside joint `a`'s limits [0, 0.5]",
            ),
        ];
        for (c, want) in cases {
            let e = check_goal(&group(), &c).unwrap_err();
            assert!(e.contains(want), "{e:?} lacks {want:?}");
        }
    }
}
