//! [`Ros2Subscriber`]: receives one topic's messages (e.g. commands sent to the simulation).

use std::time::{Duration, Instant};

use ros2_client::{Context, Node, QosProfile, Subscription};
use serde::de::DeserializeOwned;
use softgrip_record::RosMessage;

use crate::error::{Error, Result};
use crate::node::{NodeOptions, create_node, create_topic};

/// The topic softgrip listens on for commands: `geometry_msgs/msg/WrenchStamped`, a target
/// wrench (what a runner does with it is its own choice).
pub const COMMAND_TOPIC: &str = "/softgrip/command";

/// Receives messages of type `M` on one topic, with its own DDS participant.
///
/// Reading never blocks longer than asked: [`try_recv`](Self::try_recv) returns at once,
/// [`recv_timeout`](Self::recv_timeout) polls until its timeout.
///
/// ```no_run
/// use std::time::Duration;
/// use softgrip_record::msgs::geometry_msgs::WrenchStamped;
/// use softgrip_ros2::{COMMAND_TOPIC, NodeOptions, Ros2Subscriber, qos};
/// # fn main() -> Result<(), softgrip_ros2::Error> {
/// let commands = Ros2Subscriber::<WrenchStamped>::new(
///     &NodeOptions { name: "softgrip_commands".into(), ..Default::default() },
///     COMMAND_TOPIC,
///     qos::data(),
/// )?;
/// if let Some(cmd) = commands.recv_timeout(Duration::from_millis(10))? {
///     println!("target force {:?} N", cmd.wrench.force);
/// }
/// # Ok(()) }
/// ```
pub struct Ros2Subscriber<M: 'static> {
    subscription: Subscription<M>,
    topic: String,
    domain_id: u16,
    // Field order is drop order: the subscription goes before the node and the context.
    _node: Node,
    _context: Context,
}

impl<M: 'static> std::fmt::Debug for Ros2Subscriber<M> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Ros2Subscriber")
            .field("topic", &self.topic)
            .field("domain_id", &self.domain_id)
            .finish_non_exhaustive()
    }
}

impl<M: RosMessage + DeserializeOwned + 'static> Ros2Subscriber<M> {
    /// Joins the domain and subscribes to `topic` (absolute) with `qos`, which must be
    /// compatible with the publishers' (a reliable subscription matches reliable publishers
    /// only).
    pub fn new(options: &NodeOptions, topic: &str, qos: QosProfile) -> Result<Self> {
        let (context, mut node, domain_id) = create_node(options)?;
        let t = create_topic::<M>(&context, topic, &qos)?;
        let subscription =
            node.create_subscription(&t, Some(qos))
                .map_err(|e| Error::Endpoint {
                    what: "subscription",
                    topic: topic.to_owned(),
                    reason: e.to_string(),
                })?;
        Ok(Self {
            subscription,
            topic: topic.to_owned(),
            domain_id,
            _node: node,
            _context: context,
        })
    }

    /// The ROS domain id in use.
    pub fn domain_id(&self) -> u16 {
        self.domain_id
    }

    /// The topic.
    pub fn topic(&self) -> &str {
        &self.topic
    }

    /// The next message, if one has arrived; never waits.
    pub fn try_recv(&self) -> Result<Option<M>> {
        match self.subscription.take() {
            Ok(m) => Ok(m.map(|(msg, _info)| msg)),
            Err(e) => Err(Error::Read {
                topic: self.topic.clone(),
                reason: e.to_string(),
            }),
        }
    }

    /// The next message, waiting at most `timeout` (polled every millisecond).
    pub fn recv_timeout(&self, timeout: Duration) -> Result<Option<M>> {
        let deadline = Instant::now() + timeout;
        loop {
            if let Some(m) = self.try_recv()? {
                return Ok(Some(m));
            }
            if Instant::now() >= deadline {
                return Ok(None);
            }
            std::thread::sleep(Duration::from_millis(1));
        }
    }
}
