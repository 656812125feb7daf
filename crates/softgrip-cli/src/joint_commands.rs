//! `softgrip run --ros2` with robots: joint commands from ROS 2. A thread subscribes to
//! `sensor_msgs/JointState` commands (the convention of ros2_control's topic-based hardware
//! interfaces: a position and/or velocity target per named joint) and hands each named joint to
//! its robot's [`CommandInbox`](softgrip_ecs::scene::control::CommandInbox); the robot's
//! `joint_commands` controller applies them at the next step (clamped to the URDF limits;
//! unknown, fixed and mimic joints ignored).

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

/// Each robot's name and inbox, in scene order.
pub type Routes = Vec<(String, SharedInbox)>;

/// What came in.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Counts {
    /// Messages received.
    pub messages: u64,
    /// Joint entries handed to a robot.
    pub routed: u64,
    /// Joint entries naming no robot of the scene (with several robots, names are
    /// `<robot>/<joint>`).
    pub unrouted: u64,
}

/// Hands the joints of `msg` to their robots: with one robot every name is its joint's; with
/// several, a name is `<robot>/<joint>`. `position[i]` and `velocity[i]` are the i-th name's
/// targets (an array shorter than the names, as ROS allows for an empty one, gives none).
pub fn route(msg: &JointState, routes: &Routes, counts: &mut Counts) {
    counts.messages += 1;
    for (i, name) in msg.name.iter().enumerate() {
        let target = if routes.len() == 1 {
            Some((&routes[0].1, name.as_str()))
        } else {
            name.split_once('/').and_then(|(robot, joint)| {
                (routes.iter().find(|(r, _)| r == robot)).map(|(_, inbox)| (inbox, joint))
            })
        };
        let Some((inbox, joint)) = target else {
            counts.unrouted += 1;
            continue;
        };
        let command = JointCommand {
            name: joint.to_owned(),
            position: msg.position.get(i).copied(),
            velocity: msg.velocity.get(i).copied(),
        };
        (inbox
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

    #[test]
    fn one_robot_takes_every_name_with_its_targets() {
        let routes: Routes = vec![("gripper".into(), SharedInbox::default())];
        let mut counts = Counts::default();
        route(
            &command(&["finger_joint", "x"], &[0.01, 0.02], &[]),
            &routes,
            &mut counts,
        );
        assert_eq!(
            taken(&routes[0].1),
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
        assert_eq!((counts.messages, counts.routed, counts.unrouted), (1, 2, 0));
    }

    #[test]
    fn several_robots_are_addressed_by_prefix() {
        let routes: Routes = vec![
            ("left".into(), SharedInbox::default()),
            ("right".into(), SharedInbox::default()),
        ];
        let mut counts = Counts::default();
        let msg = command(
            &["right/j1", "left/j2", "j3", "other/j4"],
            &[],
            &[0.1, -0.2],
        );
        route(&msg, &routes, &mut counts);
        let right = taken(&routes[1].1);
        assert_eq!(right.len(), 1);
        assert_eq!(
            (right[0].name.as_str(), right[0].velocity),
            ("j1", Some(0.1))
        );
        let left = taken(&routes[0].1);
        assert_eq!(left.len(), 1);
        assert_eq!(
            (left[0].name.as_str(), left[0].velocity),
            ("j2", Some(-0.2))
        );
        assert_eq!(left[0].position, None);
        assert_eq!((counts.routed, counts.unrouted), (2, 2));
    }
}
