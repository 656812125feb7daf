//! [`Error`]: everything that can go wrong writing or reading a recording.

use std::path::PathBuf;

use crate::cdr::CdrError;
use crate::metadata::MetadataError;

/// An error of `softgrip-record`.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A file could not be created, read or written.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The OS error.
        source: std::io::Error,
    },
    /// The MCAP library failed while writing.
    #[error("writing MCAP: {0}")]
    Write(#[source] mcap::McapError),
    /// The file is shorter than the MCAP magic: nothing to read.
    #[error("not an MCAP file: only {len} bytes (truncated before the magic)")]
    Truncated {
        /// File length \[bytes\].
        len: usize,
    },
    /// The file does not start with the MCAP magic.
    #[error("not an MCAP file: the magic bytes are missing")]
    NotMcap,
    /// A finished file (with footer) whose records, chunks or summary are damaged.
    #[error("corrupt MCAP file: {reason}")]
    Corrupt {
        /// What was found wrong.
        reason: String,
    },
    /// A metadata record that does not convert to or from its typed struct.
    #[error(transparent)]
    Metadata(#[from] MetadataError),
    /// A message whose CDR bytes do not decode as its schema's type.
    #[error("message on {topic} at log time {log_time_ns} ns does not decode: {source}")]
    Decode {
        /// The message's topic.
        topic: String,
        /// Its log time \[ns\].
        log_time_ns: u64,
        /// Why.
        source: CdrError,
    },
}

/// `Result` with [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;
