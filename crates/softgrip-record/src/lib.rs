#![doc = include_str!("../README.md")]

pub mod cdr;
mod decoded;
mod error;
mod message;
pub mod msgs;
mod recorder;
mod recording;
pub mod schema;
mod step;
pub mod topics;
pub mod visuals;

pub use decoded::Message;
pub use error::{Error, Result};
pub use message::RosMessage;
pub use recorder::{
    METADATA_NAME, RUN_SUMMARY_NAME, Recorder, RecorderOptions, RecordingInfo, RecordingStats,
    SOFTGRIP_VERSION,
};
pub use recording::{ChannelInfo, RecordedMessage, Recording, Recovery};
pub use step::{BodyPose, FingertipState, StepRecord, contact_wrench};
