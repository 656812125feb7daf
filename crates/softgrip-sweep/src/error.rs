//! [`SweepError`]: a sweep that cannot be loaded, run or written, with where.

use std::path::PathBuf;

/// Everything that can be wrong with a sweep file or its results file. A bad *trial* is not
/// an error of the sweep: it is a row with its error ([`TrialRow::outcome`](crate::TrialRow)).
#[derive(Debug, thiserror::Error)]
pub enum SweepError {
    /// A file could not be read or written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The sweep's TOML is malformed, has an unknown field or a value of the wrong type.
    #[error("{origin}:{line}:{column}: {message}")]
    Parse {
        /// The sweep file.
        origin: String,
        /// Line of the error, from 1.
        line: usize,
        /// Column of the error, from 1.
        column: usize,
        /// What the TOML parser says.
        message: String,
    },
    /// A sweep field is outside its valid range or inconsistent.
    #[error("{origin}: `{field}` must be {expected}, got {value}")]
    Invalid {
        /// The sweep file.
        origin: String,
        /// Path of the sweep field, e.g. `vary[1].random.n`.
        field: String,
        /// The value found.
        value: String,
        /// The valid range or form.
        expected: String,
    },
    /// The base scene cannot be used (it does not load, or has no gripper or object).
    #[error("{origin}: `scene`: {message}")]
    Scene {
        /// The sweep file.
        origin: String,
        /// What is wrong.
        message: String,
    },
    /// `--shard i/n` (or [`Shard::new`](crate::Shard::new)) is not a valid slice.
    #[error("shard `{value}`: {message}")]
    Shard {
        /// The shard as given.
        value: String,
        /// What is wrong.
        message: String,
    },
    /// A run option is outside its range (`threads`).
    #[error("`{option}` must be {expected}, got {value}")]
    Options {
        /// The option, e.g. `threads`.
        option: &'static str,
        /// The value given.
        value: String,
        /// The valid range.
        expected: String,
    },
    /// A results file (CSV or Parquet) could not be written or read back.
    #[error("{}: {message}", path.display())]
    Results {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
}
