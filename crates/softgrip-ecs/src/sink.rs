//! [`StepSink`]: how a recorder (MCAP) or publisher (ROS 2) receives each step's data.

use std::collections::BTreeMap;

use softgrip_law::ContactPatch;

/// An error of a sink (I/O, encoding, transport).
pub type SinkError = Box<dyn std::error::Error + Send + Sync>;

/// What a sink learns once, before the first step.
#[derive(Debug, Clone)]
pub struct SceneInfo {
    /// Where the scene came from.
    pub origin: String,
    /// Time step [s].
    pub dt: f64,
    /// Body names, in scene order.
    pub bodies: Vec<String>,
    /// Fingertips, in scene order.
    pub fingertips: Vec<softgrip_rapier::SoftFingertip>,
}

/// A body's pose.
#[derive(Debug, Clone, PartialEq)]
pub struct BodySample {
    /// Body name.
    pub name: String,
    /// Position [m].
    pub translation: [f64; 3],
    /// Orientation quaternion `[x, y, z, w]`.
    pub rotation: [f64; 4],
}

/// The total contact wrench on a fingertip (step averages, world frame).
#[derive(Debug, Clone, PartialEq)]
pub struct WrenchSample {
    /// Fingertip name.
    pub fingertip: String,
    /// Force [N].
    pub force: [f64; 3],
    /// Torque about the fingertip's centre [N m].
    pub torque: [f64; 3],
}

/// One soft contact with both sides named.
#[derive(Debug, Clone)]
pub struct ContactSample {
    /// Fingertip name.
    pub fingertip: String,
    /// Name of the other side: a fingertip's name, or the other collider's body name.
    pub other: String,
    /// The plugin's readout.
    pub contact: softgrip_rapier::SoftContact,
    /// Radius and pressure, when the scene records pressure.
    pub patch: Option<ContactPatch>,
}

/// One step's data, in the order of the scene (bodies, fingertips) and of the plugin's
/// readout (contacts). Sections the scene does not record are empty.
#[derive(Debug, Clone, Default)]
pub struct StepFrame {
    /// Step index, from 1 (the state after the first step).
    pub step: u64,
    /// Simulated time at the end of the step [s].
    pub time: f64,
    /// Body poses (`record.poses`).
    pub bodies: Vec<BodySample>,
    /// Fingertip wrenches (`record.wrenches`).
    pub wrenches: Vec<WrenchSample>,
    /// Soft contacts (`record.contacts`; with `patch` when `record.pressure`).
    pub contacts: Vec<ContactSample>,
}

/// A consumer of steps: the MCAP recorder, a ROS 2 publisher, a test probe.
///
/// Plug one in as a [`Recorder`](crate::Recorder) or [`Publisher`](crate::Publisher)
/// resource before the schedule is built; the recording (publishing) system then calls
/// `start` once and `write` after every step it [`wants`](StepSink::wants) (by default
/// every step). Errors stop that sink (kept in the resource,
/// see `Recorder::error`), not the simulation.
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
    /// summary counted over every step (`key = value` lines; see
    /// [`Simulation::finish`](crate::Simulation::finish)). Default: ignored.
    fn run_summary(&mut self, summary: &BTreeMap<String, String>) {
        let _ = summary;
    }
    /// Called once at the end of the run (flush, close).
    fn finish(&mut self) -> Result<(), SinkError> {
        Ok(())
    }
}
