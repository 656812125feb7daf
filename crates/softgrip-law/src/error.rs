//! The one error type of `softgrip-law`.

use crate::{LevelKind, Shortest};

/// Everything that can go wrong when building or querying a contact law.
///
/// Errors are raised at the edge (construction, checked queries); the hot-path API
/// ([`crate::ContactLaw::response`]) never fails and reports odd input through
/// [`crate::Regime`] instead.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// A parameter is outside its valid range.
    #[error("`{field}` must be {range}, got {}", Shortest(*.value))]
    InvalidParameter {
        /// Name of the offending field or argument.
        field: &'static str,
        /// The value that was passed.
        value: f64,
        /// The valid range, with its unit.
        range: &'static str,
    },
    /// The level cannot be used with this material (e.g. the compressible theory at `nu = 0.5`).
    #[error("level `{level}` cannot be used with Poisson ratio nu = {}: {reason}", Shortest(*.nu))]
    IncompatibleLevel {
        /// The level that was asked for.
        level: LevelKind,
        /// The material's Poisson ratio.
        nu: f64,
        /// Why not.
        reason: &'static str,
    },
    /// Two soft bodies that cannot be combined into one contact law: only two free spheres
    /// combine ([`crate::ContactParams::try_combine_params`]).
    #[error(
        "a soft body with backing `{first}` and one with backing `{second}` cannot be combined into one law: only two `free` soft bodies combine"
    )]
    IncompatibleBacking {
        /// The first body's backing.
        first: &'static str,
        /// The second body's backing.
        second: &'static str,
    },
    /// A counterpart that cannot be bound to this fingertip's law
    /// ([`crate::ContactLaw::with_counterpart`]): too concave (it would wrap the fingertip) or
    /// too sharp for a curvature.
    #[error(
        "counterpart `{field}` relative to the fingertip, kappa R = {relative_curvature}, is out of range: {reason}"
    )]
    IncompatibleCounterpart {
        /// The curvature at fault: `curvature k1` or `curvature k2`.
        field: &'static str,
        /// That curvature times the fingertip's radius, `kappa R` [-].
        relative_curvature: f64,
        /// Why, with the valid range.
        reason: &'static str,
    },
    /// A compression past the validity range of the level (checked API only).
    #[error(
        "compression ratio x = delta/R = {} is outside the validity range of level `{level}` (0 <= x <= {})",
        Shortest(*.x),
        Shortest(*.x_max)
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
        "force {} N is outside the range of level `{level}`: 0 <= F <= {} N (reached at x = {})",
        Shortest(*.force),
        Shortest(*.force_max),
        Shortest(*.x_max)
    )]
    ForceOutOfRange {
        /// The level that was queried.
        level: LevelKind,
        /// The force that was asked for \[N\].
        force: f64,
        /// The largest force inside the validity range \[N\].
        force_max: f64,
        /// The compression ratio at which `force_max` is reached.
        x_max: f64,
    },
    /// A sample of a measured curve ([`crate::TabulatedCurve`]) is invalid, or the table as a
    /// whole is (too short, columns of different lengths: then `index` is `None` and `value` is
    /// the count).
    #[error("`{field}{}` must be {range}, got {}", index_suffix(.index), Shortest(*.value))]
    InvalidTable {
        /// The column: `delta_m` \[m\] or `force_n` \[N\].
        field: &'static str,
        /// The sample's index, if one sample is at fault: in the column as given to
        /// [`crate::TabulatedCurve::try_new`], or, from [`crate::ContactLaw::tabulated`], in
        /// [`crate::TabulatedCurve::delta_m`] (which starts at the origin).
        index: Option<usize>,
        /// The offending value (or count).
        value: f64,
        /// The valid range, with its unit.
        range: String,
    },
    /// A level that needs data, not just parameters ([`crate::Level::Tabulated`],
    /// [`crate::Level::Custom`]), was passed to [`crate::ContactLaw::try_new`].
    #[error("level `{level}` needs more than parameters: {hint}")]
    LevelNeedsData {
        /// The level that was asked for.
        level: LevelKind,
        /// How to build it.
        hint: &'static str,
    },
    /// A name that is not in its table: a level ([`crate::LEVELS`]), a construction
    /// ([`crate::BACKINGS`]) or a level's setting.
    #[error("`{field}` must be one of {expected}, got `{value}`")]
    UnknownName {
        /// What was named: `level`, `backing` or `setting`.
        field: &'static str,
        /// The name that was given.
        value: String,
        /// The names of the table, comma-separated.
        expected: String,
    },
    /// A setting given to a kind that does not take it (`k` to level `hertz`, `core_thickness`
    /// to backing `flat`).
    /// The names of those that take it are [`Error::takes`] (read from the table).
    #[error(
        "`{field}` applies only to {kind} `{}`, not to {kind} `{name}` (got {value})",
        takers(kind, field).join("`, `")
    )]
    UnexpectedSetting {
        /// The setting's key.
        field: &'static str,
        /// Its value.
        value: f64,
        /// What takes settings: `level` or `backing`.
        kind: &'static str,
        /// The name of the level or backing it was given to.
        name: &'static str,
    },
    /// A setting that a kind requires and was not given (`core_thickness` of backing `core`).
    #[error("`{field}` is required with {kind} `{name}`: {range}")]
    MissingSetting {
        /// The setting's key.
        field: &'static str,
        /// `level` or `backing`.
        kind: &'static str,
        /// The level or backing that requires it.
        name: &'static str,
        /// What it must be, with its unit.
        range: &'static str,
    },
    /// A user's [`crate::NormalisedLaw`] failed the checks of [`crate::ContactLaw::custom`].
    #[error("custom law: {quantity} at x = {} must be {range}, got {}", Shortest(*.x), Shortest(*.value))]
    InvalidCustomLaw {
        /// What was checked: `x_max`, `force`, `stiffness`, `energy` or `radius`.
        quantity: &'static str,
        /// The compression ratio where it failed [-].
        x: f64,
        /// The value the law returned.
        value: f64,
        /// What it must be.
        range: &'static str,
    },
    /// Material fitting was given too little or inconsistent data.
    #[error("material fit: {0}")]
    Fit(String),
}

/// `Result` with this crate's [`Error`].
pub type Result<T> = std::result::Result<T, Error>;

/// `[i]` for a sample's index, nothing for the whole table.
fn index_suffix(index: &Option<usize>) -> String {
    index.map(|i| format!("[{i}]")).unwrap_or_default()
}

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

impl Error {
    /// For [`Error::UnexpectedSetting`]: the names of the levels (or constructions) that take
    /// the setting, from their table ([`crate::LEVELS`], [`crate::BACKINGS`]); else empty.
    pub fn takes(&self) -> Vec<&'static str> {
        match self {
            Error::UnexpectedSetting { field, kind, .. } => takers(kind, field),
            _ => Vec::new(),
        }
    }
}

/// The rows of `kind`'s table (`level` or `backing`) that take the setting `key`.
fn takers(kind: &str, key: &str) -> Vec<&'static str> {
    if kind == "backing" {
        crate::BACKINGS
            .iter()
            .filter(|row| row.parameter.is_some_and(|p| p.key == key))
            .map(|row| row.name)
            .collect()
    } else {
        crate::LEVELS
            .iter()
            .filter(|row| row.setting(key).is_some())
            .map(|row| row.name)
            .collect()
    }
}
