//! [`Ros2Publisher`]: publishes each [`StepRecord`] on the recording's topics (softgrip-record's
//! step table, [`visit_step`]) from its own thread, fed by a bounded drop-oldest queue so the
//! simulation never waits for the network.

use std::any::Any;
use std::collections::HashMap;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex, PoisonError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use ros2_client::{Context, Node, Publisher, QosProfile};
use softgrip_record::msgs::tf2_msgs::TFMessage;
use softgrip_record::{Delivery, RosMessage, StepRecord, StepTopic, StepVisitor, visit_step};

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
    /// `/tf_static` of the run, kept until published: the step that carried it may be dropped
    /// by a full queue, then the next published step carries it.
    tf_static: Mutex<Option<TFMessage>>,
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
/// [`publish_step`](Self::publish_step) copies the step into a bounded queue and returns at
/// once; a thread publishes the messages of softgrip-record's step table ([`visit_step`]:
/// `/clock`, `/tf`, `/softgrip/contacts`, one `/softgrip/<tip>/wrench` per fingertip and
/// `/softgrip/markers`), exactly those [`softgrip_record::Recorder::write_step`] writes. A full queue drops its oldest step ([`dropped`](Self::dropped) counts them).
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
        let (context, node, domain_id) = create_node(&options.node)?;
        let mut publishers = Publishers {
            by_topic: HashMap::new(),
            node,
            context,
        };
        // The topics of a step without fingertips (all but the wrenches) exist from the start.
        visit_step(&mut StepRecord::default(), &mut Declare(&mut publishers))?;
        let mut worker = Worker {
            publishers,
            shared: Arc::new(Shared {
                queue: DropOldestQueue::new(options.queue_capacity),
                submitted: AtomicU64::new(0),
                published: AtomicU64::new(0),
                publish_failures: AtomicU64::new(0),
                discarded_at_close: AtomicU64::new(0),
                flush_deadline: Mutex::new(None),
                last_failure: Mutex::new(None),
                tf_static: Mutex::new(None),
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
        if let Some(tf) = &step.tf_static {
            *self
                .shared
                .tf_static
                .lock()
                .unwrap_or_else(PoisonError::into_inner) = Some(tf.clone());
        }
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

fn publisher<M: RosMessage>(
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

/// The QoS of a delivery class of the step table.
fn qos_of(delivery: Delivery) -> QosProfile {
    match delivery {
        Delivery::Clock => qos::clock(),
        Delivery::Tf => qos::tf(),
        Delivery::Data => qos::data(),
        Delivery::Static => qos::tf_static(),
    }
}

/// A publisher of each topic of the step table (by topic, then fingertip; `""` for the topics
/// that are not per fingertip), created on first use as the recorder's channels are.
struct Publishers {
    /// Each a `Publisher<M>` of its topic's type.
    by_topic: HashMap<StepTopic, HashMap<String, Box<dyn Any + Send>>>,
    // Field order is drop order: the publishers go before the node and the context.
    node: Node,
    context: Context,
}

impl Publishers {
    fn get<M: RosMessage>(&mut self, topic: StepTopic, fingertip: &str) -> Result<&Publisher<M>> {
        let by_tip = self.by_topic.entry(topic).or_default();
        if !by_tip.contains_key(fingertip) {
            let name = topic.name(fingertip);
            let p = publisher::<M>(
                &self.context,
                &mut self.node,
                &name,
                qos_of(topic.delivery()),
            )?;
            by_tip.insert(fingertip.to_owned(), Box::new(p));
        }
        by_tip
            .get(fingertip)
            .and_then(|p| p.downcast_ref::<Publisher<M>>())
            .ok_or_else(|| Error::Endpoint {
                what: "publisher",
                topic: topic.name(fingertip).into_owned(),
                reason: format!("the topic has another type than {}", M::TYPE_NAME),
            })
    }
}

/// Creates the publishers of the topics it visits, publishing nothing.
struct Declare<'a>(&'a mut Publishers);

impl StepVisitor for Declare<'_> {
    type Error = Error;

    fn message<M: RosMessage>(
        &mut self,
        topic: StepTopic,
        fingertip: &str,
        _time_ns: u64,
        _msg: &M,
    ) -> Result<()> {
        self.0.get::<M>(topic, fingertip).map(|_| ())
    }
}

/// The publisher thread's state: it owns the participant, so the participant is dropped
/// (and leaves the DDS network) when the thread ends.
struct Worker {
    publishers: Publishers,
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
                Popped::Item(mut step) => {
                    // `/tf_static` once: with the first step published, whichever it is.
                    let pending = self
                        .shared
                        .tf_static
                        .lock()
                        .unwrap_or_else(PoisonError::into_inner)
                        .take();
                    if step.tf_static.is_none() {
                        step.tf_static = pending;
                    }
                    // Publishing never fails as a whole: each refused message is counted.
                    let Ok(()) = visit_step(&mut step, self);
                    self.shared.published.fetch_add(1, Ordering::Relaxed);
                }
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
}

impl StepVisitor for Worker {
    type Error = std::convert::Infallible;

    /// Publishes one message of the step; a topic that cannot be created or a message DDS
    /// refuses is counted in `publish_failures`, and the step goes on.
    fn message<M: RosMessage>(
        &mut self,
        topic: StepTopic,
        fingertip: &str,
        _time_ns: u64,
        msg: &M,
    ) -> Result<(), Self::Error> {
        match self.publishers.get::<M>(topic, fingertip) {
            Ok(publisher) => {
                if let Err(e) = publisher.publish(msg.clone()) {
                    self.shared.fail(format!("{}: {e}", topic.name(fingertip)));
                }
            }
            Err(e) => self.shared.fail(e.to_string()),
        }
        Ok(())
    }
}
