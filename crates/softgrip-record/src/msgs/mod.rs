//! The message types softgrip records and publishes, one module per ROS 2 package, each a
//! Rust struct whose fields mirror its `.msg` file in order (see [`RosMessage`](crate::RosMessage)).

pub mod builtin_interfaces;
pub mod geometry_msgs;
pub(crate) mod legacy;
pub mod rosgraph_msgs;
pub mod sensor_msgs;
pub mod softgrip_msgs;
pub mod std_msgs;
pub mod tf2_msgs;
pub mod visualization_msgs;
