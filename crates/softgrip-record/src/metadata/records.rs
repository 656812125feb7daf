//! [`RecordingInfo`] and [`RunSummary`]: the metadata records softgrip writes, and
//! [`MetadataRecord`], the one way they become MCAP metadata maps and back.

use std::collections::BTreeMap;

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use super::controller::ControllerRecord;
use super::json_text;
use super::law::FingertipLaw;

/// A metadata record that does not convert (a value that is not the JSON its field needs).
#[derive(Debug, thiserror::Error)]
#[error("metadata record `{name}`: {source}")]
pub struct MetadataError {
    /// The record's name.
    pub name: &'static str,
    /// What did not convert.
    #[source]
    pub source: serde_json::Error,
}

/// A typed metadata record: text fields stored as they are, other fields as JSON text (see
/// the [module](crate::metadata)). Absent keys take their defaults.
pub trait MetadataRecord: Serialize + DeserializeOwned {
    /// The MCAP metadata record's name.
    const NAME: &'static str;

    /// The record as an MCAP metadata map.
    fn to_metadata(&self) -> Result<BTreeMap<String, String>, MetadataError> {
        let err = |source| MetadataError {
            name: Self::NAME,
            source,
        };
        serde_json::to_value(self)
            .and_then(serde_json::from_value)
            .map_err(err)
    }

    /// Reads the record back from its MCAP metadata map.
    fn from_metadata(map: &BTreeMap<String, String>) -> Result<Self, MetadataError> {
        let err = |source| MetadataError {
            name: Self::NAME,
            source,
        };
        serde_json::to_value(map)
            .and_then(serde_json::from_value)
            .map_err(err)
    }
}

/// The version of this crate, written in the metadata as `softgrip_version`.
pub const SOFTGRIP_VERSION: &str = env!("CARGO_PKG_VERSION");

/// What the recording is of: the `softgrip` metadata record, written when the file is created.
///
/// ```
/// use softgrip_record::{MetadataRecord, RecordingInfo};
/// let info = RecordingInfo { scene: "dt = 0.001".into(), dt: 1e-3, steps: 300, ..Default::default() };
/// let map = info.to_metadata().unwrap();
/// assert_eq!(map["scene"], "dt = 0.001"); // text as it is
/// assert_eq!(map["dt"], "0.001"); // JSON
/// assert_eq!(map["law"], "[]");
/// assert_eq!(map["controllers"], "[]");
/// // Written before the controllers were: read as none.
/// let mut old = map.clone();
/// old.remove("controllers");
/// assert!(RecordingInfo::from_metadata(&old).unwrap().controllers.is_empty());
/// assert_eq!(RecordingInfo::from_metadata(&map).unwrap(), info);
/// ```
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct RecordingInfo {
    /// The scene (its file's text, or a description).
    pub scene: String,
    /// The softgrip version that wrote the file (default: this crate's).
    pub softgrip_version: String,
    /// Where the scene came from (a path, or `default scene`).
    pub origin: String,
    /// Time step \[s\] (0: not given).
    #[serde(with = "json_text")]
    pub dt: f64,
    /// Every how many steps a step is recorded (>= 1; 0: not given).
    #[serde(with = "json_text")]
    pub every_n_steps: u64,
    /// Steps the run takes.
    #[serde(with = "json_text")]
    pub steps: u64,
    /// The law of each fingertip, in scene order.
    #[serde(with = "json_text")]
    pub law: Vec<FingertipLaw>,
    /// Gravity in the recording's world frame (z-up, REP 103) \[m/s²\]: `[0, 0, -9.81]` for a
    /// scene with gravity down its up axis; `[0, 0, 0]` when not given.
    #[serde(with = "json_text")]
    pub gravity: [f64; 3],
    /// The run's controllers, in the order they run (name, kind, the kind's fixed code);
    /// empty in recordings made before they were written (session 10) and in runs without
    /// any.
    #[serde(with = "json_text")]
    pub controllers: Vec<ControllerRecord>,
}

impl Default for RecordingInfo {
    fn default() -> Self {
        Self {
            scene: String::new(),
            softgrip_version: SOFTGRIP_VERSION.to_owned(),
            origin: String::new(),
            dt: 0.0,
            every_n_steps: 0,
            steps: 0,
            law: Vec::new(),
            gravity: [0.0; 3],
            controllers: Vec::new(),
        }
    }
}

impl MetadataRecord for RecordingInfo {
    const NAME: &'static str = "softgrip";
}

/// One fingertip's counts over the whole run.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(default)]
pub struct TipRunSummary {
    /// Fingertip name.
    pub name: String,
    /// Slip events (a contact started sliding).
    pub slips: u32,
    /// Validity excursions (a contact went past the law's validity range).
    pub validity_excursions: u32,
    /// Largest normal force of any contact of the fingertip \[N\].
    pub peak_force: f64,
    /// Largest compression ratio x = delta / R [-].
    pub peak_x: f64,
}

/// The run's own summary, counted over every simulated step (a recording may hold only every
/// n-th step): the `softgrip_run_summary` metadata record, written when the run finishes.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(default)]
pub struct RunSummary {
    /// Steps run.
    #[serde(with = "json_text")]
    pub steps: u64,
    /// Per fingertip, in scene order.
    #[serde(with = "json_text")]
    pub fingertips: Vec<TipRunSummary>,
}

impl RunSummary {
    /// The summary of the fingertip named `name`.
    pub fn tip(&self, name: &str) -> Option<&TipRunSummary> {
        self.fingertips.iter().find(|t| t.name == name)
    }
}

impl MetadataRecord for RunSummary {
    const NAME: &'static str = "softgrip_run_summary";
}
