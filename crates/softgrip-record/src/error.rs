//! [`Error`]: everything that can go wrong writing or reading a recording.

use std::path::PathBuf;

use crate::cdr::CdrError;
use crate::metadata::MetadataError;

/// An error of `softgrip-record`.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A file could not be created, read or written.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The OS error.
        source: std::io::Error,
    },
    /// The MCAP library failed while writing `path` (its I/O failures are [`Error::Io`],
    /// naming the file and the OS error).
    #[error("{}: writing MCAP: {source}", path.display())]
    Write {
        /// The file being written.
        path: PathBuf,
        /// What the MCAP library said.
        source: mcap::McapError,
    },
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
    /// [`recover`](crate::recover) kept no message: there is nothing to recover (the output
    /// is not written).
    #[error(
        "nothing to recover: no complete message in {bytes_read} of {file_len} bytes read{}",
        skipped_list(skipped)
    )]
    NothingRecovered {
        /// Input length \[bytes\].
        file_len: u64,
        /// Bytes read as complete records.
        bytes_read: u64,
        /// What was skipped, and why.
        skipped: Vec<String>,
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

impl Error {
    /// An error of the MCAP writer on `path`: [`Error::Io`] (the path and the OS error) when
    /// the library failed on I/O, else [`Error::Write`].
    pub(crate) fn write(path: &std::path::Path, e: mcap::McapError) -> Self {
        match e {
            mcap::McapError::Io(source) => Error::Io {
                path: path.to_path_buf(),
                source,
            },
            source => Error::Write {
                path: path.to_path_buf(),
                source,
            },
        }
    }
}

/// `` (skipped: a; b)`` or nothing.
fn skipped_list(skipped: &[String]) -> String {
    if skipped.is_empty() {
        String::new()
    } else {
        format!(" (skipped: {})", skipped.join("; "))
    }
}

/// `Result` with [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;
