//! The sweep file's data model, as written in TOML (documented in SWEEPS.md). Every table
//! rejects unknown fields; ranges are checked by [`Sweep::parse`](crate::Sweep::parse).

use serde::Deserialize;

/// A sweep: a base scene, the fields to vary, what to keep.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepFile {
    /// The base scene file, relative to the sweep file (it must be a valid scene with a
    /// `[gripper]`).
    pub scene: String,
    /// The body whose hold decides `held` (a dynamic body's name; default: the scene's only
    /// dynamic body).
    #[serde(default)]
    pub object: Option<String>,
    /// A folder (relative to the sweep file) for one MCAP recording per trial,
    /// `trial-NNNNNN.mcap` (the trial's index), every `record.every_n_steps` of the trial's
    /// scene; default none: no recordings.
    #[serde(default)]
    pub mcap_dir: Option<String>,
    /// The fields to vary, in order: the trials are the product of their values, the last
    /// field varying fastest.
    #[serde(default, rename = "vary")]
    pub vary: Vec<VarySpec>,
}

/// One `[[vary]]`: a field and its values.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VarySpec {
    /// The scene field by its path, e.g. `fingertip[0].material.youngs_modulus`.
    pub field: String,
    /// The values, all of one type (numbers, integers, booleans or strings; integers among
    /// numbers count as numbers); exclusive with `random`.
    #[serde(default)]
    pub values: Option<Vec<toml::Value>>,
    /// `n` numbers drawn uniformly in `[low, high)`; exclusive with `values`.
    #[serde(default)]
    pub random: Option<RandomSpec>,
}

/// `random = { low, high, n, seed }`.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RandomSpec {
    /// Lower bound (inclusive), finite.
    pub low: f64,
    /// Upper bound (exclusive), finite and > `low`.
    pub high: f64,
    /// Number of values, in 1..=[`MAX_TRIALS`](crate::MAX_TRIALS).
    pub n: i64,
    /// Seed of the generator, >= 0 (default 0).
    #[serde(default)]
    pub seed: i64,
}
