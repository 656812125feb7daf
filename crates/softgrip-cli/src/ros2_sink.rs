//! `softgrip run --ros2`: the ECS's publisher sink that hands every step to softgrip-ros2's
//! non-blocking publisher (the same messages the MCAP recording holds).

use std::sync::{Arc, Mutex};
use std::time::Duration;

use softgrip_ecs::softgrip_record::StepRecord;
use softgrip_ecs::{Scene, SinkError, StepConverter, StepFrame, StepSink};
use softgrip_ros2::{PublisherStats, Ros2Publisher, Ros2PublisherOptions};

/// How long closing waits for the publisher thread to drain its queue.
const CLOSE_TIMEOUT: Duration = Duration::from_secs(2);

/// Publishes each step over ROS 2; never blocks the simulation (the publisher drops the oldest
/// queued step when DDS falls behind, and counts it).
pub struct Ros2Sink {
    publisher: Option<Ros2Publisher>,
    converter: StepConverter,
    step: StepRecord,
    stats: Arc<Mutex<Option<PublisherStats>>>,
}

impl Ros2Sink {
    /// Creates the DDS participant (domain from `ROS_DOMAIN_ID`), node `softgrip` and its
    /// publishers. A bad `ROS_DOMAIN_ID` or a participant that cannot be created is a typed error.
    pub fn new(scene: &Scene) -> Result<Self, softgrip_ros2::Error> {
        Ok(Self {
            publisher: Some(Ros2Publisher::new(&Ros2PublisherOptions::default())?),
            converter: StepConverter::for_scene(scene),
            step: StepRecord::default(),
            stats: Arc::default(),
        })
    }

    /// The domain id the publisher joined.
    pub fn domain_id(&self) -> Option<u16> {
        self.publisher.as_ref().map(Ros2Publisher::domain_id)
    }

    /// The publisher's final counts, once the sink has finished.
    pub fn stats_handle(&self) -> Arc<Mutex<Option<PublisherStats>>> {
        Arc::clone(&self.stats)
    }
}

impl StepSink for Ros2Sink {
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
            let stats = publisher.close(CLOSE_TIMEOUT)?;
            *self.stats.lock().unwrap_or_else(|e| e.into_inner()) = Some(stats);
        }
        Ok(())
    }
}
