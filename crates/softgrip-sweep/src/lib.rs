#![doc = include_str!("../README.md")]

mod axis;
mod csv_io;
mod error;
mod file;
mod parquet_io;
mod path;
mod random;
mod shard;
mod sweep;
mod table;
mod trial;
mod value;

pub use axis::{Axis, MAX_TRIALS};
pub use error::SweepError;
pub use file::{RandomSpec, SweepFile, VarySpec};
pub use path::FieldPath;
pub use random::uniform;
pub use shard::Shard;
pub use sweep::{MAX_SWEEP_BYTES, RunOptions, Sweep, THREADS_PER_CORE, check_threads, max_threads};
pub use table::{OUTCOME_COLUMNS, ResultsTable, TrialRow};
pub use trial::{Outcome, run_scene};
pub use value::{Value, ValueKind};
