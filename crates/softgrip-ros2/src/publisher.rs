//! [`Ros2Publisher`]: publishes each [`StepRecord`] on the recording's topics from its own
//! thread, fed by a bounded drop-oldest queue so the simulation never waits for the network.

use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use ros2_client::{Context, Node, Publisher, QosProfile};
use serde::Serialize;
use softgrip_record::msgs::geometry_msgs::WrenchStamped;
use softgrip_record::msgs::rosgraph_msgs::Clock;
use softgrip_record::msgs::softgrip_msgs::SoftContactArray;
use softgrip_record::msgs::tf2_msgs::TFMessage;
use softgrip_record::msgs::visualization_msgs::MarkerArray;
use softgrip_record::{RosMessage, StepRecord, topics, visuals};

use crate::error::{Error, Result};
use crate::node::{NodeOptions, create_node, create_topic};
use crate::qos;
use crate::queue::{DropOldestQueue, Popped, Pushed};

/// How long [`Ros2Publisher::close`] keeps the participant alive after the last write (at
/// most; never past the close timeout), so that DDS can deliver the last steps.
pub const CLOSE_LINGER: Duration = Duration::from_millis(200);

/// How a [`Ros2Publisher`] is set up.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Ros2PublisherOptions {
    /// Domain, node name and namespace.
    pub node: NodeOptions,
    /// Steps the queue holds before it drops the oldest, >= 1. Default 64 (64 ms of a
    /// 1 kHz simulation; each queued step is a copy of the [`StepRecord`]).
    pub queue_capacity: usize,
}

impl Default for Ros2PublisherOptions {
    fn default() -> Self {
        Self {
            node: NodeOptions::default(),
            queue_capacity: 64,
        }
    }
}

/// Counts of a publisher so far.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct PublisherStats {
    /// Steps handed to [`Ros2Publisher::publish_step`].
    pub submitted: u64,
    /// Steps published (every message of the step handed to DDS; some may have failed, see
    /// `publish_failures`).
    pub published: u64,
    /// Steps dropped unpublished: the oldest of a full queue, those submitted after close, and
    /// those still queued when `close` timed out.
    pub dropped: u64,
    /// Messages DDS refused (e.g. a reliable send window still full after
    /// [`qos::RELIABLE_MAX_BLOCKING`]), or wrench topics that could not be created.
    pub publish_failures: u64,
    /// Steps waiting in the queue now.
    pub queued: u64,
}

#[derive(Debug)]
struct Shared {
    queue: DropOldestQueue<StepRecord>,
    submitted: AtomicU64,
    published: AtomicU64,
    publish_failures: AtomicU64,
    discarded_at_close: AtomicU64,
    /// Set by `close`: the worker drains the queue until then, and discards the rest.
    flush_deadline: Mutex<Option<Instant>>,
    last_failure: Mutex<Option<String>>,
}

impl Shared {
    fn fail(&self, what: String) {
        self.publish_failures.fetch_add(1, Ordering::Relaxed);
        *self
            .last_failure
            .lock()
            .unwrap_or_else(PoisonError::into_inner) = Some(what);
    }

    fn flush_deadline(&self) -> Option<Instant> {
        *self
            .flush_deadline
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
    }
}

/// Publishes softgrip's messages on ROS 2 (DDS), live, on the topics the recording uses.
///
/// [`new`](Self::new) creates the DDS participant (domain from `ROS_DOMAIN_ID` unless given),
/// the node and the publishers, with the QoS of [`qos`](crate::qos).
/// [`publish_step`](Self::publish_step) copies the step into a bounded queue and returns at once; a thread
/// publishes `/clock`, `/tf`, `/softgrip/contacts`, one `/softgrip/<tip>/wrench` per fingertip
/// and `/softgrip/markers`, exactly the messages [`softgrip_record::Recorder::write_step`]
/// writes. A full queue drops its oldest step ([`dropped`](Self::dropped) counts them).
/// [`close`](Self::close) sends what is queued, within a timeout, and stops the thread.
///
/// ```no_run
/// use std::time::Duration;
/// use softgrip_ros2::{Ros2Publisher, Ros2PublisherOptions};
/// # fn steps() -> Vec<softgrip_record::StepRecord> { Vec::new() }
/// # fn main() -> Result<(), softgrip_ros2::Error> {
/// let publisher = Ros2Publisher::new(&Ros2PublisherOptions::default())?;
/// for step in steps() {
///     publisher.publish_step(&step)?; // never waits for the network
/// }
/// let stats = publisher.close(Duration::from_secs(1))?;
/// println!("{} steps published, {} dropped", stats.published, stats.dropped);
/// # Ok(()) }
/// ```
#[derive(Debug)]
pub struct Ros2Publisher {
    shared: Arc<Shared>,
    thread: Option<JoinHandle<()>>,
    domain_id: u16,
}

impl Ros2Publisher {
    /// Creates the participant, node and publishers and starts the publisher thread.
    ///
    /// Errors: [`Error::DomainId`] (a bad `ROS_DOMAIN_ID`), [`Error::QueueCapacity`],
    /// [`Error::Context`], [`Error::Node`], [`Error::Endpoint`], [`Error::Spawn`]. No peer is
    /// needed: DDS publishes to whoever is there, possibly no one.
    pub fn new(options: &Ros2PublisherOptions) -> Result<Self> {
        if options.queue_capacity == 0 {
            return Err(Error::QueueCapacity);
        }
        let (context, mut node, domain_id) = create_node(&options.node)?;
        let mut worker = Worker {
            clock: publisher(&context, &mut node, topics::CLOCK, qos::clock())?,
            tf: publisher(&context, &mut node, topics::TF, qos::tf())?,
            contacts: publisher(&context, &mut node, topics::CONTACTS, qos::data())?,
            markers: publisher(&context, &mut node, topics::MARKERS, qos::data())?,
            wrenches: HashMap::new(),
            context,
            node,
            shared: Arc::new(Shared {
                queue: DropOldestQueue::new(options.queue_capacity),
                submitted: AtomicU64::new(0),
                published: AtomicU64::new(0),
                publish_failures: AtomicU64::new(0),
                discarded_at_close: AtomicU64::new(0),
                flush_deadline: Mutex::new(None),
                last_failure: Mutex::new(None),
            }),
        };
        let shared = Arc::clone(&worker.shared);
        let thread = std::thread::Builder::new()
            .name("softgrip-ros2-publisher".into())
            .spawn(move || worker.run())
            .map_err(Error::Spawn)?;
        Ok(Self {
            shared,
            thread: Some(thread),
            domain_id,
        })
    }

    /// The ROS domain id in use.
    pub fn domain_id(&self) -> u16 {
        self.domain_id
    }

    /// Queues a copy of `step` for publishing and returns at once. If the queue is full its
    /// oldest step is dropped (and counted). Fails with [`Error::PublisherDead`] if the
    /// publisher thread has stopped.
    pub fn publish_step(&self, step: &StepRecord) -> Result<()> {
        self.publish_step_owned(step.clone())
    }

    /// As [`publish_step`](Self::publish_step), without the copy.
    pub fn publish_step_owned(&self, step: StepRecord) -> Result<()> {
        if self.thread.as_ref().is_none_or(JoinHandle::is_finished) {
            return Err(Error::PublisherDead { panic: None });
        }
        self.shared.submitted.fetch_add(1, Ordering::Relaxed);
        match self.shared.queue.push(step) {
            Pushed::Queued | Pushed::DroppedOldest => Ok(()),
            Pushed::Closed => Err(Error::PublisherDead { panic: None }),
        }
    }

    /// Steps dropped unpublished so far (see [`PublisherStats::dropped`]).
    pub fn dropped(&self) -> u64 {
        self.shared.queue.dropped() + self.shared.discarded_at_close.load(Ordering::Relaxed)
    }

    /// The counts so far.
    pub fn stats(&self) -> PublisherStats {
        let s = &self.shared;
        PublisherStats {
            submitted: s.submitted.load(Ordering::Relaxed),
            published: s.published.load(Ordering::Relaxed),
            dropped: self.dropped(),
            publish_failures: s.publish_failures.load(Ordering::Relaxed),
            queued: s.queue.len() as u64,
        }
    }

    /// The last message DDS refused, or wrench topic that could not be created, as text.
    pub fn last_failure(&self) -> Option<String> {
        self.shared
            .last_failure
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .clone()
    }

    /// Publishes what is queued, for at most `timeout`, then stops the thread and drops the
    /// participant. Steps still queued at the timeout are discarded and counted in `dropped`.
    ///
    /// Always returns within about `timeout` plus one step's worth of writes (each at most
    /// [`qos::RELIABLE_MAX_BLOCKING`]) plus the participant's shutdown, whether or not any
    /// subscriber ever appeared. Errors: [`Error::CloseTimeout`] if steps were discarded,
    /// [`Error::PublisherDead`] if the thread had panicked or does not stop.
    pub fn close(mut self, timeout: Duration) -> Result<PublisherStats> {
        self.shutdown(timeout)
    }

    fn shutdown(&mut self, timeout: Duration) -> Result<PublisherStats> {
        let Some(thread) = self.thread.take() else {
            return Ok(self.stats());
        };
        let deadline = Instant::now() + timeout;
        *self
            .shared
            .flush_deadline
            .lock()
            .unwrap_or_else(PoisonError::into_inner) = Some(deadline);
        self.shared.queue.close();

        // The worker checks the deadline between messages, so after it at most one step's
        // writes (each bounded by RELIABLE_MAX_BLOCKING) and the participant's shutdown remain.
        let grace = Duration::from_secs(5);
        while !thread.is_finished() && Instant::now() < deadline + grace {
            std::thread::sleep(Duration::from_millis(2));
        }
        if !thread.is_finished() {
            // Detach it rather than hang the caller.
            return Err(Error::PublisherDead {
                panic: Some(format!(
                    "did not stop within {:?} after close",
                    timeout + grace
                )),
            });
        }
        if let Err(panic) = thread.join() {
            let msg = panic
                .downcast_ref::<&str>()
                .map(|s| (*s).to_owned())
                .or_else(|| panic.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "non-string panic payload".into());
            return Err(Error::PublisherDead { panic: Some(msg) });
        }
        let stats = self.stats();
        let unsent = self.shared.discarded_at_close.load(Ordering::Relaxed);
        if unsent > 0 {
            return Err(Error::CloseTimeout { timeout, unsent });
        }
        Ok(stats)
    }
}

impl Drop for Ros2Publisher {
    /// Closes with a 1 s flush if [`close`](Ros2Publisher::close) was not called (errors are
    /// ignored here: call `close` to see them).
    fn drop(&mut self) {
        let _ = self.shutdown(Duration::from_secs(1));
    }
}

fn publisher<M: RosMessage + Serialize>(
    context: &Context,
    node: &mut Node,
    topic: &str,
    qos: QosProfile,
) -> Result<Publisher<M>> {
    let t = create_topic::<M>(context, topic, &qos)?;
    node.create_publisher(&t, Some(qos))
        .map_err(|e| Error::Endpoint {
            what: "publisher",
            topic: topic.to_owned(),
            reason: e.to_string(),
        })
}

/// The publisher thread's state: it owns the participant, so the participant is dropped
/// (and leaves the DDS network) when the thread ends.
struct Worker {
    clock: Publisher<Clock>,
    tf: Publisher<TFMessage>,
    contacts: Publisher<SoftContactArray>,
    markers: Publisher<MarkerArray>,
    /// By fingertip name: the topic and its publisher (created on first use, as the
    /// recorder's channels are).
    wrenches: HashMap<String, (String, Publisher<WrenchStamped>)>,
    // Field order is drop order: the publishers go before the node and the context.
    node: Node,
    context: Context,
    shared: Arc<Shared>,
}

impl Worker {
    fn run(&mut self) {
        loop {
            if let Some(deadline) = self.shared.flush_deadline()
                && Instant::now() >= deadline
            {
                let n = self.shared.queue.clear();
                self.shared
                    .discarded_at_close
                    .fetch_add(n as u64, Ordering::Relaxed);
                return;
            }
            match self.shared.queue.pop_timeout(Duration::from_millis(100)) {
                Popped::Item(step) => self.publish(step),
                Popped::TimedOut => {}
                Popped::Closed => {
                    self.linger();
                    return;
                }
            }
        }
    }

    /// Keeps the participant alive for [`CLOSE_LINGER`] (less if the close deadline comes
    /// first) after the last write, so DDS can deliver, and retransmit, the tail to reliable
    /// subscribers before the participant leaves. ros2-client's `Publisher` does not expose
    /// DDS's `wait_for_acknowledgments`, so this is a bounded wait, not a proof of delivery.
    fn linger(&self) {
        if self.shared.published.load(Ordering::Relaxed) == 0 {
            return;
        }
        let until = Instant::now() + CLOSE_LINGER;
        let until = self.shared.flush_deadline().map_or(until, |d| d.min(until));
        std::thread::sleep(until.saturating_duration_since(Instant::now()));
    }

    fn send<M: Serialize>(shared: &Shared, publisher: &Publisher<M>, topic: &str, msg: M) {
        if let Err(e) = publisher.publish(msg) {
            shared.fail(format!("{topic}: {e}"));
        }
    }

    /// The messages of `Recorder::write_step`, in its order.
    fn publish(&mut self, mut step: StepRecord) {
        let shared = &*self.shared;
        let header = step.header();
        Self::send(shared, &self.clock, topics::CLOCK, step.clock());
        Self::send(shared, &self.tf, topics::TF, step.tf());
        // The markers are built from the step before its contacts move into the array.
        let markers = visuals::markers(&step);
        let array = step.take_contact_array();
        Self::send(shared, &self.contacts, topics::CONTACTS, array);
        for tip in &step.fingertips {
            let (topic, publisher) = match self.wrenches.get(&tip.name) {
                Some(p) => p,
                None => {
                    let topic = topics::wrench(&tip.name);
                    match publisher(&self.context, &mut self.node, &topic, qos::data()) {
                        Ok(p) => self.wrenches.entry(tip.name.clone()).or_insert((topic, p)),
                        Err(e) => {
                            shared.fail(e.to_string());
                            continue;
                        }
                    }
                }
            };
            let msg = WrenchStamped {
                header: header.clone(),
                wrench: tip.wrench,
            };
            Self::send(shared, publisher, topic, msg);
        }
        Self::send(shared, &self.markers, topics::MARKERS, markers);
        shared.published.fetch_add(1, Ordering::Relaxed);
    }
}
