//! The one table of a step's messages: [`StepTopic`] lists the topics, [`visit_step`] builds
//! each message of a step, in order, and hands it to a [`StepVisitor`]. The MCAP recorder
//! ([`Recorder::write_step`](crate::Recorder::write_step)) and the ROS 2 publisher
//! (softgrip-ros2) are two visitors, so a new topic is a variant here and a line in
//! [`visit_step`], and both write it.

use std::borrow::Cow;

use crate::message::RosMessage;
use crate::msgs::geometry_msgs::WrenchStamped;
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
    /// [`topics::tactile`] of each fingertip with a pad, `sensor_msgs/msg/Image` (`32FC1`,
    /// pressure \[Pa\], in the fingertip's frame).
    Tactile,
}

impl StepTopic {
    /// Every topic, in the order a step's messages come.
    pub const ALL: [StepTopic; 6] = [
        StepTopic::Clock,
        StepTopic::Tf,
        StepTopic::Contacts,
        StepTopic::Wrench,
        StepTopic::Markers,
        StepTopic::Tactile,
    ];

    /// The topic's name; `fingertip` names the fingertip of a per-fingertip topic (ignored by
    /// the others).
    pub fn name(self, fingertip: &str) -> Cow<'static, str> {
        match self {
            StepTopic::Clock => Cow::Borrowed(topics::CLOCK),
            StepTopic::Tf => Cow::Borrowed(topics::TF),
            StepTopic::Contacts => Cow::Borrowed(topics::CONTACTS),
            StepTopic::Wrench => Cow::Owned(topics::wrench(fingertip)),
            StepTopic::Markers => Cow::Borrowed(topics::MARKERS),
            StepTopic::Tactile => Cow::Owned(topics::tactile(fingertip)),
        }
    }

    /// Whether there is one such topic per fingertip.
    pub fn per_fingertip(self) -> bool {
        matches!(self, StepTopic::Wrench | StepTopic::Tactile)
    }

    /// How the topic is delivered live.
    pub fn delivery(self) -> Delivery {
        match self {
            StepTopic::Clock => Delivery::Clock,
            StepTopic::Tf => Delivery::Tf,
            StepTopic::Contacts | StepTopic::Wrench | StepTopic::Markers | StepTopic::Tactile => {
                Delivery::Data
            }
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
/// `/tf`, `/softgrip/contacts` (each contact's header set to the step's), one
/// `/softgrip/<fingertip>/wrench` per fingertip, `/softgrip/markers`, one
/// `/softgrip/<fingertip>/tactile` per fingertip with a pad.
///
/// `step` is only borrowed mutably to stamp its contacts and move them into the array
/// without a copy; they are back in `step.contacts` when this returns.
pub fn visit_step<V: StepVisitor>(step: &mut StepRecord, visitor: &mut V) -> Result<(), V::Error> {
    let t = step.time_ns;
    visitor.message(StepTopic::Clock, "", t, &step.clock())?;
    visitor.message(StepTopic::Tf, "", t, &step.tf())?;
    let array = step.take_contact_array();
    let taken = visitor.message(StepTopic::Contacts, "", t, &array);
    step.contacts = array.contacts;
    taken?;
    let header = step.header();
    for tip in &step.fingertips {
        let msg = WrenchStamped {
            header: header.clone(),
            wrench: tip.wrench,
        };
        visitor.message(StepTopic::Wrench, &tip.name, t, &msg)?;
    }
    visitor.message(StepTopic::Markers, "", t, &visuals::markers(step))?;
    for (tip, image) in &step.tactile {
        visitor.message(StepTopic::Tactile, tip, t, image)?;
    }
    Ok(())
}
