//! The recording's metadata records, as typed serde structs: [`RecordingInfo`] (the
//! `softgrip` record: scene, laws, time step), [`RunSummary`] (the
//! `softgrip_run_summary` record), the [`FingertipLaw`] each fingertip's law is written as and
//! the [`ControllerRecord`] each controller of the run is written as.
//!
//! An MCAP metadata record is a map of strings. Each struct is written and read by the same
//! code ([`MetadataRecord`]): a text field is stored as it is (the scene file stays readable
//! by any MCAP tool), every other field as its JSON text (`"dt": "0.001"`,
//! `"law": "[{\"name\":\"left_tip\",...}]"`).

mod controller;
mod json_text;
mod law;
pub mod legacy;
mod records;

pub use controller::ControllerRecord;
pub use law::FingertipLaw;
pub use records::{
    MetadataError, MetadataRecord, RecordingInfo, RunSummary, SOFTGRIP_VERSION, TipRunSummary,
};
