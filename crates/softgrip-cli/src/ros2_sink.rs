//! `softgrip run --ros2`: softgrip-ros2's [`Ros2Sink`](softgrip_ros2::Ros2Sink) for a scene.

use softgrip_ecs::{Scene, scene_info};

/// Creates the publisher sink of a scene (`Ros2Sink::new(&scene)`, as `run` calls it).
pub struct Ros2Sink;

impl Ros2Sink {
    /// softgrip-ros2's sink with the default options (domain from `ROS_DOMAIN_ID`, node
    /// `softgrip`) for `scene`. A bad `ROS_DOMAIN_ID` or a participant that cannot be created is
    /// a typed error.
    pub fn new(scene: &Scene) -> Result<softgrip_ros2::Ros2Sink, softgrip_ros2::Error> {
        softgrip_ros2::Ros2Sink::new(&scene_info(scene), &Default::default())
    }
}
