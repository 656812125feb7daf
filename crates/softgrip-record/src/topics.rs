//! The topic names softgrip records and publishes.

/// Every soft contact of a step: `softgrip_msgs/msg/SoftContactArray`.
pub const CONTACTS: &str = "/softgrip/contacts";
/// Body and fingertip poses: `tf2_msgs/msg/TFMessage`.
pub const TF: &str = "/tf";
/// Each fingertip's constant frame on its body: `tf2_msgs/msg/TFMessage`, once per run
/// (transient-local on ROS 2).
pub const TF_STATIC: &str = "/tf_static";
/// Contact patches and fingertips for 3D views: `visualization_msgs/msg/MarkerArray`.
pub const MARKERS: &str = "/softgrip/markers";
/// Simulation time: `rosgraph_msgs/msg/Clock`.
pub const CLOCK: &str = "/clock";
/// Every robot joint's position, velocity and effort: `sensor_msgs/msg/JointState`.
pub const JOINT_STATES: &str = "/joint_states";
/// The joint targets the controllers commanded for the step (position and velocity targets,
/// effort = the motor's force limit, 0 without one): `sensor_msgs/msg/JointState`.
pub const JOINT_COMMANDS: &str = "/joint_commands";
/// A robot's URDF: `std_msgs/msg/String`, once per run (transient-local on ROS 2).
pub const ROBOT_DESCRIPTION: &str = "/robot_description";

/// The description topic of robot `robot`: [`ROBOT_DESCRIPTION`] for `""` (a scene with one
/// robot), `/<robot>/robot_description` otherwise (the name sanitised as in [`wrench`]).
///
/// ```
/// use softgrip_record::topics::robot_description;
/// assert_eq!(robot_description(""), "/robot_description");
/// assert_eq!(robot_description("left hand"), "/left_hand/robot_description");
/// ```
pub fn robot_description(robot: &str) -> String {
    if robot.is_empty() {
        ROBOT_DESCRIPTION.to_owned()
    } else {
        format!("/{}/robot_description", ros_name_token(robot))
    }
}

/// The wrench topic of a fingertip, `/softgrip/<fingertip>/wrench`
/// (`geometry_msgs/msg/WrenchStamped`). Characters a ROS name cannot hold become `_`, and a
/// name that is empty or starts with a digit gets a leading `_`.
///
/// ```
/// assert_eq!(softgrip_record::topics::wrench("thumb"), "/softgrip/thumb/wrench");
/// assert_eq!(softgrip_record::topics::wrench("tip 2-left"), "/softgrip/tip_2_left/wrench");
/// assert_eq!(softgrip_record::topics::wrench("1"), "/softgrip/_1/wrench");
/// ```
pub fn wrench(fingertip: &str) -> String {
    format!("/softgrip/{}/wrench", ros_name_token(fingertip))
}

/// `name` made a valid ROS name token (`[A-Za-z_][A-Za-z0-9_]*`).
pub fn ros_name_token(name: &str) -> String {
    let mut s: String = name
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    if s.is_empty() || s.starts_with(|c: char| c.is_ascii_digit()) {
        s.insert(0, '_');
    }
    s
}

/// The tactile image topic of a fingertip, `/softgrip/<fingertip>/tactile`
/// (`sensor_msgs/msg/Image`, `32FC1`, pressure \[Pa\]); the name is sanitised as in
/// [`wrench`].
///
/// ```
/// assert_eq!(softgrip_record::topics::tactile("left_tip"), "/softgrip/left_tip/tactile");
/// ```
pub fn tactile(fingertip: &str) -> String {
    format!("/softgrip/{}/tactile", ros_name_token(fingertip))
}
