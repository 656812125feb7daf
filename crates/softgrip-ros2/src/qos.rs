//! The QoS of each topic, set explicitly (ros2-client's own defaults differ from ROS 2's).
//!
//! | topic | reliability | history | durability | as in ROS 2 |
//! |---|---|---|---|---|
//! | `/softgrip/contacts`, `/softgrip/<tip>/wrench`, `/softgrip/markers` | reliable | keep last 10 | volatile | `rclcpp::QoS(10)`, the default profile |
//! | `/tf` | reliable | keep last 100 | volatile | `tf2_ros::DynamicBroadcasterQoS` |
//! | `/tf_static` | reliable | keep last 1 | transient local | `tf2_ros::StaticBroadcasterQoS` |
//! | `/clock` | best effort | keep last 1 | volatile | `rclcpp::ClockQoS` (what `use_sim_time` subscribes with) |
//! | `/softgrip/command` (subscribed) | reliable | keep last 10 | volatile | the default profile |
//!
//! Why: the data topics are what a plot or a logger wants complete, so they are reliable, with
//! the default depth of 10; volatile, because a late joiner wants the current squeeze, not old
//! steps. `/tf` follows tf2's broadcaster so `tf2_ros::TransformListener` matches it; `/tf_static`
//! (the fingertips' frames on their bodies, sent once) follows tf2's static broadcaster: a
//! listener that joins later still receives it. `/clock`
//! follows rclcpp's clock QoS: a late tick is worth nothing once the next one is out, so it is
//! never retransmitted. A reliable publisher matches reliable and best-effort subscribers; a
//! best-effort one matches only best-effort subscribers, so subscribe to `/clock` best effort.
//!
//! A reliable write waits at most [`RELIABLE_MAX_BLOCKING`] for room in the send window (a
//! slow subscriber), then fails and the message is counted in
//! [`PublisherStats::publish_failures`](crate::PublisherStats::publish_failures). That wait is
//! on the publisher thread, never on the simulation's.

use std::time::Duration;

use ros2_client::QosProfile;
use ros2_client::qos::{Durability, History, Liveliness, Reliability, WhenFull};

/// The longest a reliable write waits for send-window room, on the publisher thread.
pub const RELIABLE_MAX_BLOCKING: Duration = Duration::from_millis(20);

/// History depth of the data topics (contacts, wrenches, markers).
pub const DATA_DEPTH: usize = 10;
/// History depth of `/tf` (tf2's `DynamicBroadcasterQoS`).
pub const TF_DEPTH: usize = 100;

const fn profile(reliability: Reliability, depth: usize) -> QosProfile {
    QosProfile {
        reliability,
        durability: Durability::Volatile,
        ..latched(reliability, depth)
    }
}

const fn latched(reliability: Reliability, depth: usize) -> QosProfile {
    QosProfile {
        reliability,
        durability: Durability::TransientLocal,
        history: History::KeepLast { depth },
        deadline: None,
        lifespan: None,
        liveliness: Liveliness::Automatic,
        liveliness_lease: None,
    }
}

const RELIABLE: Reliability = Reliability::Reliable {
    when_full: WhenFull::Wait(RELIABLE_MAX_BLOCKING),
};

/// Contacts, wrenches, markers and the command topic: reliable, keep last 10, volatile.
pub const fn data() -> QosProfile {
    profile(RELIABLE, DATA_DEPTH)
}

/// `/tf`: reliable, keep last 100, volatile.
pub const fn tf() -> QosProfile {
    profile(RELIABLE, TF_DEPTH)
}

/// `/clock`: best effort, keep last 1, volatile.
pub const fn clock() -> QosProfile {
    profile(Reliability::BestEffort, 1)
}

/// `/tf_static`: reliable, keep last 1, transient local.
pub const fn tf_static() -> QosProfile {
    latched(RELIABLE, 1)
}
