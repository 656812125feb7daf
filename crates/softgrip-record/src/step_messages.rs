//! The one table of a step's messages: [`StepTopic`] lists the topics, [`visit_step`] builds
//! each message of a step, in order, and hands it to a [`StepVisitor`]. The MCAP recorder
//! ([`Recorder::write_step`](crate::Recorder::write_step)) and the ROS 2 publisher
//! (softgrip-ros2) are two visitors, so a new topic is a variant here and a line in
//! [`visit_step`], and both write it.

use std::borrow::Cow;

use crate::message::RosMessage;
use crate::msgs::geometry_msgs::WrenchStamped;
use crate::msgs::std_msgs::Header;
use crate::step::StepRecord;
use crate::topics;
use crate::visuals;

/// How a topic is delivered live: the ROS 2 QoS class softgrip-ros2 gives it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Delivery {
    /// `/clock`: best effort, latest only.
    Clock,
    /// `/tf`: reliable, a deep history (tf buffers interpolate).
    Tf,
    /// Everything else: reliable, a short history.
    Data,
    /// `/tf_static`: reliable, transient-local (a late subscriber gets it), latest only, as
    /// tf2's static broadcaster.
    Static,
}

impl Delivery {
    /// History depth of the class (keep last n): clock 1, tf 100, data 10, static 1; as
    /// softgrip-ros2 publishes them.
    pub fn depth(self) -> u32 {
        match self {
            Delivery::Clock | Delivery::Static => 1,
            Delivery::Tf => 100,
            Delivery::Data => 10,
        }
    }

    /// The channel metadata value `offered_qos_profiles` rosbag2 writes (a YAML list of one
    /// profile; rmw enums as integers: history 1 keep last, reliability 1 reliable / 2 best
    /// effort, durability 1 transient local / 2 volatile, liveliness 1 automatic; durations
    /// 0 = unspecified), so that `ros2 bag play` offers the live QoS: `/tf_static`
    /// transient-local, `/clock` best effort, the rest reliable and volatile.
    pub fn offered_qos_profiles(self) -> String {
        let reliability = if self == Delivery::Clock { 2 } else { 1 };
        let durability = if self == Delivery::Static { 1 } else { 2 };
        let zero = "\n    sec: 0\n    nsec: 0";
        format!(
            "- history: 1\n  depth: {}\n  reliability: {reliability}\n  durability: \
             {durability}\n  deadline:{zero}\n  lifespan:{zero}\n  liveliness: 1\n  \
             liveliness_lease_duration:{zero}\n  avoid_ros_namespace_conventions: false",
            self.depth()
        )
    }
}

/// A topic of a step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum StepTopic {
    /// [`topics::CLOCK`], `rosgraph_msgs/msg/Clock`.
    Clock,
    /// [`topics::TF`], `tf2_msgs/msg/TFMessage`: every fingertip, then every body.
    Tf,
    /// [`topics::CONTACTS`], `softgrip_msgs/msg/SoftContactArray`.
    Contacts,
    /// [`topics::wrench`] of each fingertip, `geometry_msgs/msg/WrenchStamped`.
    Wrench,
    /// [`topics::MARKERS`], `visualization_msgs/msg/MarkerArray`.
    Markers,
    /// [`topics::TF_STATIC`], `tf2_msgs/msg/TFMessage`: each fingertip's frame on its body,
    /// on the first step only (right after `/clock`).
    TfStatic,
    /// [`topics::tactile`] of each fingertip with a pad, `sensor_msgs/msg/Image` (`32FC1`,
    /// pressure \[Pa\], in the fingertip's frame).
    Tactile,
    /// [`topics::robot_description`] of each robot, `std_msgs/msg/String` (its URDF), on the
    /// first step only (right after `/tf_static`).
    RobotDescription,
    /// [`topics::JOINT_STATES`], `sensor_msgs/msg/JointState`: every robot's moving joints.
    JointStates,
    /// [`topics::JOINT_COMMANDS`], `sensor_msgs/msg/JointState`: their targets for the step.
    JointCommands,
}

impl StepTopic {
    /// Every topic, in the order a step's messages come (`/tf_static` on the first step only).
    pub const ALL: [StepTopic; 10] = [
        StepTopic::Clock,
        StepTopic::TfStatic,
        StepTopic::RobotDescription,
        StepTopic::Tf,
        StepTopic::Contacts,
        StepTopic::Wrench,
        StepTopic::Markers,
        StepTopic::Tactile,
        StepTopic::JointStates,
        StepTopic::JointCommands,
    ];

    /// The topic's name; `fingertip` names the fingertip of a per-fingertip topic, or the robot
    /// of a robot's description (`""`: the scene's only robot), and is ignored by the others.
    pub fn name(self, fingertip: &str) -> Cow<'static, str> {
        match self {
            StepTopic::Clock => Cow::Borrowed(topics::CLOCK),
            StepTopic::Tf => Cow::Borrowed(topics::TF),
            StepTopic::Contacts => Cow::Borrowed(topics::CONTACTS),
            StepTopic::Wrench => Cow::Owned(topics::wrench(fingertip)),
            StepTopic::Markers => Cow::Borrowed(topics::MARKERS),
            StepTopic::TfStatic => Cow::Borrowed(topics::TF_STATIC),
            StepTopic::Tactile => Cow::Owned(topics::tactile(fingertip)),
            StepTopic::RobotDescription => Cow::Owned(topics::robot_description(fingertip)),
            StepTopic::JointStates => Cow::Borrowed(topics::JOINT_STATES),
            StepTopic::JointCommands => Cow::Borrowed(topics::JOINT_COMMANDS),
        }
    }

    /// Whether there is one such topic per fingertip (or per robot: its description).
    pub fn per_fingertip(self) -> bool {
        matches!(
            self,
            StepTopic::Wrench | StepTopic::Tactile | StepTopic::RobotDescription
        )
    }

    /// How the topic is delivered live.
    pub fn delivery(self) -> Delivery {
        match self {
            StepTopic::Clock => Delivery::Clock,
            StepTopic::Tf => Delivery::Tf,
            StepTopic::Contacts
            | StepTopic::Wrench
            | StepTopic::Markers
            | StepTopic::Tactile
            | StepTopic::JointStates
            | StepTopic::JointCommands => Delivery::Data,
            StepTopic::TfStatic | StepTopic::RobotDescription => Delivery::Static,
        }
    }
}

/// A consumer of a step's messages (one call per message, in order).
pub trait StepVisitor {
    /// Why a message could not be taken; stops the step.
    type Error;

    /// Takes `msg` on `topic` (of `fingertip` for a per-fingertip topic, else `""`), at the
    /// step's time `time_ns` \[ns\].
    fn message<M: RosMessage>(
        &mut self,
        topic: StepTopic,
        fingertip: &str,
        time_ns: u64,
        msg: &M,
    ) -> Result<(), Self::Error>;
}

/// Hands every message of `step` to `visitor`, in the order of [`StepTopic::ALL`]: `/clock`,
/// `/tf_static` (when the step carries it: the first of a run), `/tf`, `/softgrip/contacts`
/// (each contact's header set to the step's), one `/softgrip/<fingertip>/wrench` per
/// fingertip (in the fingertip's frame), `/softgrip/markers`, one
/// `/softgrip/<fingertip>/tactile` per fingertip with a pad; with robots, their descriptions on the
/// first step (after `/tf_static`), `/joint_states` and `/joint_commands`.
///
/// `step` is only borrowed mutably to stamp its contacts and move them into the array
/// without a copy; they are back in `step.contacts` when this returns.
pub fn visit_step<V: StepVisitor>(step: &mut StepRecord, visitor: &mut V) -> Result<(), V::Error> {
    let t = step.time_ns;
    visitor.message(StepTopic::Clock, "", t, &step.clock())?;
    if let Some(tf_static) = &step.tf_static {
        visitor.message(StepTopic::TfStatic, "", t, tf_static)?;
    }
    for (robot, urdf) in &step.robot_descriptions {
        visitor.message(StepTopic::RobotDescription, robot, t, urdf)?;
    }
    visitor.message(StepTopic::Tf, "", t, &step.tf())?;
    let array = step.take_contact_array();
    let taken = visitor.message(StepTopic::Contacts, "", t, &array);
    step.contacts = array.contacts;
    taken?;
    for tip in &step.fingertips {
        let msg = WrenchStamped {
            header: Header::new(t, step.frame_of(tip)),
            wrench: tip.wrench,
        };
        visitor.message(StepTopic::Wrench, &tip.name, t, &msg)?;
    }
    visitor.message(StepTopic::Markers, "", t, &visuals::markers(step))?;
    for (tip, image) in &step.tactile {
        visitor.message(StepTopic::Tactile, tip, t, image)?;
    }
    if let Some(states) = &step.joint_states {
        visitor.message(StepTopic::JointStates, "", t, states)?;
    }
    if let Some(commands) = &step.joint_commands {
        visitor.message(StepTopic::JointCommands, "", t, commands)?;
    }
    Ok(())
}
