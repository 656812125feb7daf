//! [`Ros2Sink`]: the [`StepSink`] that hands every step to a [`Ros2Publisher`] (the same
//! messages the MCAP recording holds), as `softgrip run --ros2` does.

use std::sync::{Arc, Mutex};
use std::time::Duration;

use softgrip_record::{SceneInfo, SinkError, StepConverter, StepFrame, StepRecord, StepSink};

use crate::error::Result;
use crate::publisher::{PublisherStats, Ros2Publisher, Ros2PublisherOptions};

/// How long finishing waits for the publisher thread to drain its queue.
pub const SINK_CLOSE_TIMEOUT: Duration = Duration::from_secs(2);

/// Publishes each step over ROS 2; never blocks the simulation (the publisher drops the oldest
/// queued step when DDS falls behind, and counts it).
#[derive(Debug)]
pub struct Ros2Sink {
    publisher: Option<Ros2Publisher>,
    converter: StepConverter,
    step: StepRecord,
    stats: Arc<Mutex<Option<PublisherStats>>>,
}

impl Ros2Sink {
    /// Creates the DDS participant (domain from `ROS_DOMAIN_ID` unless `options` give one), the
    /// node and its publishers, for the scene `info` (where its fingertips are mounted; `start`
    /// replaces it with the simulation's). A bad `ROS_DOMAIN_ID` or a participant that cannot
    /// be created is a typed error.
    pub fn new(info: &SceneInfo, options: &Ros2PublisherOptions) -> Result<Self> {
        Ok(Self {
            publisher: Some(Ros2Publisher::new(options)?),
            converter: StepConverter::new(info),
            step: StepRecord::default(),
            stats: Arc::default(),
        })
    }

    /// The domain id the publisher joined (`None` once finished).
    pub fn domain_id(&self) -> Option<u16> {
        self.publisher.as_ref().map(Ros2Publisher::domain_id)
    }

    /// The publisher's final counts, once the sink has finished.
    pub fn stats_handle(&self) -> Arc<Mutex<Option<PublisherStats>>> {
        Arc::clone(&self.stats)
    }
}

impl StepSink for Ros2Sink {
    fn start(&mut self, info: &SceneInfo) -> Result<(), SinkError> {
        self.converter = StepConverter::new(info);
        Ok(())
    }

    fn write(&mut self, frame: &StepFrame) -> Result<(), SinkError> {
        let Some(publisher) = &self.publisher else {
            return Ok(());
        };
        self.converter.convert(frame, &mut self.step);
        publisher.publish_step(&self.step)?;
        Ok(())
    }

    fn finish(&mut self) -> Result<(), SinkError> {
        if let Some(publisher) = self.publisher.take() {
            let stats = publisher.close(SINK_CLOSE_TIMEOUT)?;
            *self.stats.lock().unwrap_or_else(|e| e.into_inner()) = Some(stats);
        }
        Ok(())
    }
}
