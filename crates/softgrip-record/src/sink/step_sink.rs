//! [`StepSink`]: how a recorder (MCAP) or publisher (ROS 2) receives each step's data.

use super::{SceneInfo, StepFrame};
use crate::metadata::RunSummary;

/// An error of a sink (I/O, encoding, transport).
pub type SinkError = Box<dyn std::error::Error + Send + Sync>;

/// A consumer of steps: the MCAP recorder ([`McapSink`](crate::McapSink)), a ROS 2 publisher,
/// a test probe.
///
/// The simulation calls `start` once and `write` after every step the sink
/// [`wants`](StepSink::wants) (by default every step), then `run_summary` and `finish` once.
/// In softgrip-ecs a sink is plugged in as a `Recorder` or `Publisher` resource; an error
/// stops that sink (kept in the resource), not the simulation.
pub trait StepSink: Send + Sync + 'static {
    /// Called once, before the first frame.
    fn start(&mut self, info: &SceneInfo) -> Result<(), SinkError> {
        let _ = info;
        Ok(())
    }
    /// Whether the sink takes step `step` (from 1). The frame is assembled, and `write`
    /// called, only on steps that some sink takes. Default: every step.
    fn wants(&self, step: u64) -> bool {
        let _ = step;
        true
    }
    /// Called after every step the sink [`wants`](Self::wants).
    fn write(&mut self, frame: &StepFrame) -> Result<(), SinkError>;
    /// Called once at the end of the run, before [`finish`](Self::finish), with the run's
    /// summary counted over every step. Default: ignored.
    fn run_summary(&mut self, summary: &RunSummary) {
        let _ = summary;
    }
    /// Called once at the end of the run (flush, close).
    fn finish(&mut self) -> Result<(), SinkError> {
        Ok(())
    }
}
