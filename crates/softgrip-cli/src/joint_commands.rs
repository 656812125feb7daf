//! `softgrip run --ros2` with robots: joint commands from ROS 2. A thread subscribes to
//! `sensor_msgs/JointState` commands (the convention of ros2_control's topic-based hardware
//! interfaces: a position and/or velocity target per named joint) and hands each named joint to
//! its robot's [`CommandInbox`](softgrip_ecs::scene::control::CommandInbox); the robot's
//! `joint_commands` controller applies them at the next step (positions clamped to the URDF
//! limits). A topic has no answer, so an entry that cannot be applied (no robot of that name, a
//! name that is not one of the robot's commandable joints, its moving joints that are not
//! mimics, or a position or velocity that is not finite) is refused: counted, and each refused
//! name with its reason printed once when the run ends.

use std::collections::BTreeMap;
use std::time::Duration;

use anyhow::Result;
use softgrip_ecs::scene::control::{JointCommand, SharedInbox};
use softgrip_record::msgs::sensor_msgs::JointState;
use softgrip_ros2::{NodeOptions, Ros2Subscriber};

use crate::worker::Worker;

/// The default command topic: `joint_state_topic_hardware_interface`'s (topic_based_ros2_control)
/// default `joint_commands_topic`.
pub const DEFAULT_TOPIC: &str = "/robot_joint_command";

/// How long the thread waits for a message before it looks at the stop flag.
const POLL: Duration = Duration::from_millis(20);

/// At most this many refused names are kept with their reasons (the count goes on).
const MAX_REFUSED_NAMES: usize = 16;

/// A robot commands can reach.
#[derive(Debug, Clone, Default)]
pub struct Route {
    /// The robot's name.
    pub robot: String,
    /// Its commandable joints (moving, not mimic), in URDF order.
    pub joints: Vec<String>,
    /// Where its commands go.
    pub inbox: SharedInbox,
}

/// Each robot's route, in scene order.
pub type Routes = Vec<Route>;

/// What came in.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Counts {
    /// Messages received.
    pub messages: u64,
    /// Joint entries handed to a robot.
    pub routed: u64,
    /// Joint entries refused (see the module).
    pub refused: u64,
    /// The first [`MAX_REFUSED_NAMES`] names refused, each with why.
    pub refused_names: BTreeMap<String, String>,
}

impl Counts {
    fn refuse(&mut self, name: &str, why: impl FnOnce() -> String) {
        self.refused += 1;
        if self.refused_names.len() < MAX_REFUSED_NAMES && !self.refused_names.contains_key(name) {
            self.refused_names.insert(name.to_owned(), why());
        }
    }
}

/// Hands the joints of `msg` to their robots: with one robot every name is its joint's; with
/// several, a name is `<robot>/<joint>`. `position[i]` and `velocity[i]` are the i-th name's
/// targets (an array shorter than the names, as ROS allows for an empty one, gives none).
pub fn route(msg: &JointState, routes: &Routes, counts: &mut Counts) {
    counts.messages += 1;
    for (i, name) in msg.name.iter().enumerate() {
        let target = if routes.len() == 1 {
            Some((&routes[0], name.as_str()))
        } else {
            name.split_once('/').and_then(|(robot, joint)| {
                (routes.iter().find(|r| r.robot == robot)).map(|r| (r, joint))
            })
        };
        let Some((route, joint)) = target else {
            let robots: Vec<&str> = routes.iter().map(|r| r.robot.as_str()).collect();
            counts.refuse(name, || {
                format!(
                    "names no robot: expected `<robot>/<joint>` (robots: {})",
                    robots.join(", ")
                )
            });
            continue;
        };
        if !route.joints.iter().any(|j| j == joint) {
            counts.refuse(name, || {
                format!(
                    "robot `{}` has no commandable joint `{joint}` (its moving joints that are not mimics: {})",
                    route.robot,
                    route.joints.join(", ")
                )
            });
            continue;
        }
        let (position, velocity) = (msg.position.get(i).copied(), msg.velocity.get(i).copied());
        if let Some((field, v)) = [("position", position), ("velocity", velocity)]
            .into_iter()
            .find_map(|(f, v)| v.filter(|v| !v.is_finite()).map(|v| (f, v)))
        {
            counts.refuse(name, || format!("{field}[{i}] = {v} is not finite"));
            continue;
        }
        let command = JointCommand {
            name: joint.to_owned(),
            position,
            velocity,
        };
        (route
            .inbox
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner))
        .commands
        .push(command);
        counts.routed += 1;
    }
}

/// The subscription's thread.
pub struct CommandBridge {
    worker: Worker<Counts>,
    topic: String,
}

impl CommandBridge {
    /// Subscribes to `topic` (absolute) on the domain of `ROS_DOMAIN_ID` and routes what comes
    /// to `routes`; returns once the subscription exists (its error, if it cannot).
    pub fn start(topic: &str, routes: Routes) -> Result<Self> {
        let name = topic.to_owned();
        let what = format!("subscribing to joint commands on {topic}");
        let worker = Worker::start("ros2-joint-commands", &what, move |stop, ready| {
            let sub = match Ros2Subscriber::<JointState>::new(
                &NodeOptions::default(),
                &name,
                softgrip_ros2::qos::data(),
            ) {
                Ok(s) => {
                    let _ = ready.send(Ok(()));
                    s
                }
                Err(e) => {
                    let _ = ready.send(Err(anyhow::anyhow!("{e}")));
                    return Ok(Counts::default());
                }
            };
            let mut counts = Counts::default();
            while !stop.stopped() {
                if let Some(msg) = sub.recv_timeout(POLL)? {
                    route(&msg, &routes, &mut counts);
                }
            }
            Ok(counts)
        })?;
        Ok(Self {
            worker,
            topic: topic.to_owned(),
        })
    }

    /// The topic subscribed to.
    pub fn topic(&self) -> &str {
        &self.topic
    }

    /// Stops the thread and returns what came in.
    pub fn finish(self) -> Result<Counts> {
        self.worker.finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn command(names: &[&str], position: &[f64], velocity: &[f64]) -> JointState {
        JointState {
            name: names.iter().map(|n| (*n).to_owned()).collect(),
            position: position.to_vec(),
            velocity: velocity.to_vec(),
            ..JointState::default()
        }
    }

    fn taken(inbox: &SharedInbox) -> Vec<JointCommand> {
        std::mem::take(&mut inbox.lock().unwrap().commands)
    }

    fn robot(name: &str, joints: &[&str]) -> Route {
        Route {
            robot: name.into(),
            joints: joints.iter().map(|j| (*j).to_owned()).collect(),
            inbox: SharedInbox::default(),
        }
    }

    #[test]
    fn one_robot_takes_its_joints_with_their_targets() {
        let routes: Routes = vec![robot("gripper", &["finger_joint", "x"])];
        let mut counts = Counts::default();
        route(
            &command(&["finger_joint", "x"], &[0.01, 0.02], &[]),
            &routes,
            &mut counts,
        );
        assert_eq!(
            taken(&routes[0].inbox),
            [
                JointCommand {
                    name: "finger_joint".into(),
                    position: Some(0.01),
                    velocity: None,
                },
                JointCommand {
                    name: "x".into(),
                    position: Some(0.02),
                    velocity: None,
                },
            ]
        );
        assert_eq!((counts.messages, counts.routed, counts.refused), (1, 2, 0));
    }

    #[test]
    fn several_robots_are_addressed_by_prefix() {
        let routes: Routes = vec![robot("left", &["j2"]), robot("right", &["j1"])];
        let mut counts = Counts::default();
        let msg = command(
            &["right/j1", "left/j2", "j3", "other/j4"],
            &[],
            &[0.1, -0.2],
        );
        route(&msg, &routes, &mut counts);
        let right = taken(&routes[1].inbox);
        assert_eq!(right.len(), 1);
        assert_eq!(
            (right[0].name.as_str(), right[0].velocity),
            ("j1", Some(0.1))
        );
        let left = taken(&routes[0].inbox);
        assert_eq!(left.len(), 1);
        assert_eq!(
            (left[0].name.as_str(), left[0].velocity),
            ("j2", Some(-0.2))
        );
        assert_eq!(left[0].position, None);
        assert_eq!((counts.routed, counts.refused), (2, 2));
        assert_eq!(
            counts.refused_names["other/j4"],
            "names no robot: expected `<robot>/<joint>` (robots: left, right)"
        );
        assert!(counts.refused_names.contains_key("j3"));
    }

    /// An unknown or mimic joint and a NaN or infinite target are refused, each name with its
    /// reason, and nothing of them reaches the robot; the valid entry beside them does.
    #[test]
    fn unknown_joints_and_non_finite_targets_are_refused_naming_them() {
        let routes: Routes = vec![robot("gripper", &["finger_joint"])];
        let mut counts = Counts::default();
        let msg = command(
            &["wrist", "right_finger_joint", "finger_joint"],
            &[0.1, 0.1, 0.02],
            &[],
        );
        route(&msg, &routes, &mut counts);
        route(
            &command(&["finger_joint"], &[f64::NAN], &[]),
            &routes,
            &mut counts,
        );
        route(
            &command(&["finger_joint"], &[], &[f64::INFINITY]),
            &routes,
            &mut counts,
        );
        route(&command(&["wrist"], &[0.0], &[]), &routes, &mut counts);
        let taken = taken(&routes[0].inbox);
        assert_eq!(taken.len(), 1, "{taken:?}");
        assert_eq!(taken[0].position, Some(0.02));
        assert_eq!((counts.messages, counts.routed, counts.refused), (4, 1, 5));
        let why = |n: &str| counts.refused_names[n].as_str();
        assert_eq!(
            why("wrist"),
            "robot `gripper` has no commandable joint `wrist` (its moving joints that are not mimics: finger_joint)"
        );
        assert!(why("right_finger_joint").contains("no commandable joint `right_finger_joint`"));
        // The first reason a name was refused is the one kept.
        assert_eq!(why("finger_joint"), "position[0] = NaN is not finite");
    }
}
