#![doc = include_str!("../README.md")]

mod domain;
mod error;
mod gripper_action;
mod node;
mod publisher;
pub mod qos;
pub mod queue;
mod sink;
mod subscriber;

pub use domain::{MAX_DOMAIN_ID, ROS_DOMAIN_ID, domain_id_from_env, parse_domain_id};
pub use error::{Error, Result};
pub use gripper_action::{
    GRIPPER_ACTION_SUFFIX, GRIPPER_ACTION_TYPE, GoalKey, GripperActionServer,
    ParallelGripperFeedback, ParallelGripperGoal, ParallelGripperResult,
};
pub use node::{NodeOptions, dds_topic_name, dds_type_name};
pub use publisher::{CLOSE_LINGER, PublisherStats, Ros2Publisher, Ros2PublisherOptions};
pub use sink::{Ros2Sink, SINK_CLOSE_TIMEOUT};
pub use subscriber::{COMMAND_TOPIC, Ros2Subscriber};
