//! [`Error`]: everything that can go wrong publishing or subscribing.

use std::time::Duration;

/// An error of `softgrip-ros2`.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// `ROS_DOMAIN_ID` (or the domain id given) is not an integer in `0..=232`.
    #[error(
        "ROS_DOMAIN_ID must be an integer in 0..=232 (ROS 2's valid range: higher ids overflow \
         the UDP port numbers DDS derives from them), got {value:?}"
    )]
    DomainId {
        /// The value given.
        value: String,
    },
    /// The queue capacity is 0 (at least one step must fit).
    #[error("queue_capacity must be >= 1 step, got 0")]
    QueueCapacity,
    /// The DDS participant (ros2-client `Context`) could not be created, e.g. no usable network
    /// interface or no free UDP port.
    #[error("creating the DDS participant on ROS domain {domain_id} failed: {reason}")]
    Context {
        /// The ROS domain id.
        domain_id: u16,
        /// ros2-client's message.
        reason: String,
    },
    /// The ROS node could not be created.
    #[error("creating the ROS 2 node {node:?} failed: {reason}")]
    Node {
        /// The node name.
        node: String,
        /// ros2-client's message.
        reason: String,
    },
    /// A topic, publisher or subscription could not be created.
    #[error("creating the {what} of {topic} failed: {reason}")]
    Endpoint {
        /// `topic`, `publisher` or `subscription`.
        what: &'static str,
        /// The ROS topic name.
        topic: String,
        /// ros2-client's message.
        reason: String,
    },
    /// The publisher thread could not be started.
    #[error("starting the publisher thread failed: {0}")]
    Spawn(#[source] std::io::Error),
    /// The publisher thread has stopped (it panicked or was closed): nothing more is sent.
    #[error("the ROS 2 publisher thread is no longer running{}", panic_suffix(.panic))]
    PublisherDead {
        /// The panic message, if the thread panicked.
        panic: Option<String>,
    },
    /// `close()` gave up waiting: `unsent` steps were still queued after `timeout`.
    #[error("closing the ROS 2 publisher timed out after {timeout:?} with {unsent} steps unsent")]
    CloseTimeout {
        /// The timeout given.
        timeout: Duration,
        /// Steps still queued (discarded).
        unsent: u64,
    },
    /// Taking a message from a subscription failed (e.g. bytes that do not decode).
    #[error("reading {topic} failed: {reason}")]
    Read {
        /// The ROS topic name.
        topic: String,
        /// ros2-client's message.
        reason: String,
    },
}

fn panic_suffix(panic: &Option<String>) -> String {
    match panic {
        Some(p) => format!(" (it panicked: {p})"),
        None => String::new(),
    }
}

/// `Result` with [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;
