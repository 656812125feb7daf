#![doc = include_str!("../README.md")]

pub mod cdr;
mod convert;
mod decoded;
mod error;
pub mod frames;
mod mcap_sink;
mod message;
pub mod metadata;
pub mod msgs;
mod recorder;
mod recording;
mod recover;
pub mod schema;
pub mod sink;
mod step;
mod step_messages;
pub mod topics;
pub mod units;
pub mod visuals;

pub use convert::{StepConverter, WORLD_FRAME, arrow_scale, soft_contact_msg, tactile_image};
pub use decoded::Message;
pub use error::{Error, Result};
pub use frames::{UpAxis, fingertip_frame};
pub use mcap_sink::{McapReport, McapSink, McapSinkError};
pub use message::RosMessage;
pub use metadata::{
    ControllerRecord, FingertipLaw, MetadataError, MetadataRecord, RecordingInfo, RunSummary,
    SOFTGRIP_VERSION, TipRunSummary,
};
pub use recorder::{
    METADATA_NAME, OFFERED_QOS_PROFILES, RUN_SUMMARY_NAME, Recorder, RecorderOptions,
    RecordingStats,
};
pub use recording::{ChannelInfo, RecordedMessage, Recording, Recovery};
pub use recover::{RecoverReport, recover, recover_into};
pub use sink::{
    BodyFrame, BodySample, ContactReading, ContactSample, FingertipInfo, JointSample, RobotInfo,
    SceneInfo, ShapeGeometry, ShapeInfo, SinkError, StepFrame, StepSink, TactileSample,
    WrenchSample,
};
pub use step::{BodyPose, FingertipState, StepRecord, contact_wrench};
pub use step_messages::{Delivery, StepTopic, StepVisitor, visit_step};
