//! The one error type of `softgrip-fe`.

use std::fmt;

/// An embedded FE file that does not parse into the rows asked for.
#[derive(Debug)]
pub struct Error {
    /// The file, relative to `tests/data/fe/`.
    pub path: &'static str,
    /// What the CSV reader or serde said (with the line).
    pub source: csv::Error,
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "FE reference `{}`: {}", self.path, self.source)
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        Some(&self.source)
    }
}

/// `Result` with this crate's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;
