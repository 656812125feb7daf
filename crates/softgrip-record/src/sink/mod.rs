//! What a sink (the MCAP recorder, the ROS 2 publisher, a test probe) receives from a
//! simulation: plain data only, no engine types, so a recorder needs neither rapier nor an ECS.
//!
//! - [`SceneInfo`] once, before the first step: bodies, fingertips and their laws;
//! - a [`StepFrame`] after every step the sink [`wants`](StepSink::wants);
//! - the run's [`RunSummary`](crate::RunSummary) once at the end, then `finish`.

mod frame;
mod scene;
mod step_sink;

pub use frame::{
    BodySample, ContactReading, ContactSample, JointSample, StepFrame, TactileSample, WrenchSample,
};
pub use scene::{BodyFrame, FingertipInfo, RobotInfo, SceneInfo, ShapeGeometry, ShapeInfo};
pub use step_sink::{SinkError, StepSink};
