//! The one error type of `softgrip-law`.

use crate::LevelKind;

/// Everything that can go wrong when building or querying a contact law.
///
/// Errors are raised at the edge (construction, checked queries); the hot-path API
/// ([`crate::ContactLaw::response`]) never fails and reports odd input through
/// [`crate::Regime`] instead.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A parameter is outside its valid range.
    #[error("`{field}` must be {range}, got {value}")]
    InvalidParameter {
        /// Name of the offending field or argument.
        field: &'static str,
        /// The value that was passed.
        value: f64,
        /// The valid range, with its unit.
        range: &'static str,
    },
    /// The level cannot be used with this material (e.g. the compressible theory at `nu = 0.5`).
    #[error("level `{level}` cannot be used with Poisson ratio nu = {nu}: {reason}")]
    IncompatibleLevel {
        /// The level that was asked for.
        level: LevelKind,
        /// The material's Poisson ratio.
        nu: f64,
        /// Why not.
        reason: &'static str,
    },
    /// A compression past the validity range of the level (checked API only).
    #[error(
        "compression ratio x = delta/R = {x} is outside the validity range of level `{level}` (0 <= x <= {x_max})"
    )]
    OutOfRange {
        /// The level that was queried.
        level: LevelKind,
        /// The compression ratio that was asked for.
        x: f64,
        /// The largest valid compression ratio of this level for this material.
        x_max: f64,
    },
    /// A force that the level cannot produce inside its validity range (inverse queries).
    #[error(
        "force {force} N is outside the range of level `{level}`: 0 <= F <= {force_max} N (reached at x = {x_max})"
    )]
    ForceOutOfRange {
        /// The level that was queried.
        level: LevelKind,
        /// The force that was asked for [N].
        force: f64,
        /// The largest force inside the validity range [N].
        force_max: f64,
        /// The compression ratio at which `force_max` is reached.
        x_max: f64,
    },
    /// Material fitting was given too little or inconsistent data.
    #[error("material fit: {0}")]
    Fit(String),
}

/// `Result` with this crate's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

/// Checks that `value` is finite and strictly positive.
pub(crate) fn positive(field: &'static str, value: f64, range: &'static str) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::InvalidParameter {
            field,
            value,
            range,
        })
    }
}
