//! `rosgraph_msgs`: [`Clock`], the `/clock` topic's type (simulation time).

use super::builtin_interfaces::Time;
use crate::message::ros_message;

ros_message! {
    /// The current simulation time (ROS nodes with `use_sim_time` follow it).
    #[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
    pub struct Clock {
        name = "rosgraph_msgs/msg/Clock", file = "msg/rosgraph_msgs/Clock.msg", deps = [Time];
        /// Simulation time.
        pub clock: Time,
    }
}
