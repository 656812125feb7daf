//! `std_msgs`: [`Header`], [`ColorRGBA`] and [`StringMsg`] (`/robot_description`).

use super::builtin_interfaces::Time;
use crate::message::ros_message;

ros_message! {
    /// Time stamp and coordinate frame of a message.
    #[derive(Debug, Clone, PartialEq, Default)]
    pub struct Header {
        name = "std_msgs/msg/Header", file = "msg/std_msgs/Header.msg", deps = [Time];
        /// Simulation time of the data.
        pub stamp: Time,
        /// The frame the data are expressed in.
        pub frame_id: String,
    }
}

ros_message! {
    /// A colour, each component in [0, 1].
    #[derive(Debug, Clone, Copy, PartialEq, Default)]
    pub struct ColorRGBA {
        name = "std_msgs/msg/ColorRGBA", file = "msg/std_msgs/ColorRGBA.msg", deps = [];
        /// Red [-].
        pub r: f32,
        /// Green [-].
        pub g: f32,
        /// Blue [-].
        pub b: f32,
        /// Opacity [-].
        pub a: f32,
    }
}

ros_message! {
    /// A string: a robot's URDF on `/robot_description` (`std_msgs/msg/String`; the Rust name
    /// says `Msg` to keep it apart from `std`'s `String`).
    #[derive(Debug, Clone, PartialEq, Default)]
    pub struct StringMsg {
        name = "std_msgs/msg/String", file = "msg/std_msgs/String.msg", deps = [];
        /// The text.
        pub data: String,
    }
}

impl Header {
    /// A header at `time_ns` \[ns\] in frame `frame_id`.
    pub fn new(time_ns: u64, frame_id: &str) -> Self {
        Self {
            stamp: Time::from_nanos(time_ns),
            frame_id: frame_id.to_owned(),
        }
    }
}

impl ColorRGBA {
    /// A colour from its components, each in [0, 1].
    pub const fn new(r: f32, g: f32, b: f32, a: f32) -> Self {
        Self { r, g, b, a }
    }
}
