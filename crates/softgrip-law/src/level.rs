//! Which level of the law to use: [`Level`] is the user's choice (with its settings),
//! [`LevelKind`] names a concrete level (what [`Level::Auto`] picked, what a response used).

use std::fmt;
use std::str::FromStr;

use crate::error::{Error, Result};

/// The paper's `k` of Eq. 38 (the least-squares value is 1.1141).
pub const DEFAULT_FIT_K: f64 = 10.0 / 9.0;
/// Default force tolerance of [`Level::Auto`]: 1 % against `calibrated` (the truth's best
/// estimate for the construction).
pub const DEFAULT_AUTO_TOLERANCE: f64 = 0.01;
/// Default compression ratio at which [`Level::Linear`] matches Hertz's force.
pub const DEFAULT_LINEAR_MATCH_X: f64 = 0.05;

/// A level of the contact law, with its settings. Cheapest first.
///
/// ```
/// use softgrip_law::Level;
/// assert_eq!("fit".parse::<Level>().unwrap(), Level::Fit { k: 10.0 / 9.0 });
/// assert_eq!(Level::Calibrated.to_string(), "calibrated");
/// assert!("spring".parse::<Level>().is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Level {
    /// Linear spring matched to Hertz's force at `match_x` (baseline only; `0 < match_x <= 1`).
    Linear {
        /// Compression ratio where the spring's force equals Hertz's.
        match_x: f64,
    },
    /// Hertz (Eq. 5): exact for small `x` only.
    Hertz,
    /// The paper's explicit law `chi_L = 1/(1 - k x)` (Eq. 38) with the radius fit of Eq. 42.
    Fit {
        /// The slope `k` of `1/chi` (10/9 in the paper), finite in [0, 10].
        k: f64,
    },
    /// Exact incompressible neo-Hookean `chi_IC` (Eq. 36) and radius `R artanh(sqrt x)` (Eq. 26).
    Incompressible,
    /// Full compressible neo-Hookean theory (Eqs. 23, 25, 32-33), tabulated once per material.
    NeoHookean,
    /// Full compressible neo-Hookean theory solved by Newton at every call.
    NeoHookeanExact,
    /// Tatara's extended Hertz law for a finite sphere (peer baseline).
    Tatara,
    /// softgrip's explicit correction fitted to the finite-element reference.
    Calibrated,
    /// A user's measured squeeze curve, monotone cubic interpolation (the curve lives in the
    /// law: build it with [`crate::ContactLaw::tabulated`]).
    Tabulated,
    /// A user's own [`crate::NormalisedLaw`] (build it with [`crate::ContactLaw::custom`]).
    Custom,
    /// Per call, the cheapest of Hertz, fit, incompressible and `calibrated` whose error against
    /// `calibrated` (the most accurate level of the fingertip's construction, itself within its
    /// stated error of the finite elements) is within `tolerance` at that `x`: `auto` at 1 % is
    /// within 1 % plus calibrated's own error of the FE. With a backing (flat, core) the cheap
    /// levels are the free sphere's and are 7-60 % off, so `auto` is `calibrated` there.
    Auto {
        /// Relative force tolerance against `calibrated`, in (0, 0.5].
        tolerance: f64,
    },
}

impl Level {
    /// [`Level::Fit`] with the paper's `k = 10/9`.
    pub const fn fit() -> Self {
        Self::Fit { k: DEFAULT_FIT_K }
    }

    /// [`Level::Auto`] with the default 1 % tolerance.
    pub const fn auto() -> Self {
        Self::Auto {
            tolerance: DEFAULT_AUTO_TOLERANCE,
        }
    }

    /// [`Level::Linear`] matched to Hertz at `x = 0.05`.
    pub const fn linear() -> Self {
        Self::Linear {
            match_x: DEFAULT_LINEAR_MATCH_X,
        }
    }

    /// Every level that [`crate::ContactLaw::try_new`] builds from parameters alone, with its
    /// default settings (not [`Level::Tabulated`] and [`Level::Custom`], which need data).
    pub const ALL: [Level; 9] = [
        Level::linear(),
        Level::Hertz,
        Level::fit(),
        Level::Incompressible,
        Level::NeoHookean,
        Level::NeoHookeanExact,
        Level::Tatara,
        Level::Calibrated,
        Level::auto(),
    ];

    /// The command-line name of the level.
    pub fn name(&self) -> &'static str {
        match self {
            Level::Linear { .. } => "linear",
            Level::Hertz => "hertz",
            Level::Fit { .. } => "fit",
            Level::Incompressible => "incompressible",
            Level::NeoHookean => "neo-hookean",
            Level::NeoHookeanExact => "neo-hookean-exact",
            Level::Tatara => "tatara",
            Level::Calibrated => "calibrated",
            Level::Tabulated => "tabulated",
            Level::Custom => "custom",
            Level::Auto { .. } => "auto",
        }
    }

    /// Checks the level's own settings.
    pub(crate) fn validate(&self) -> Result<()> {
        let bad = |field, value, range| {
            Err(Error::InvalidParameter {
                field,
                value,
                range,
            })
        };
        match *self {
            Level::Linear { match_x } if !(match_x > 0.0 && match_x <= 1.0) => {
                bad("match_x", match_x, "in (0, 1]")
            }
            Level::Fit { k } if !(k.is_finite() && (0.0..=10.0).contains(&k)) => {
                bad("k", k, "finite and in [0, 10]")
            }
            Level::Auto { tolerance } if !(tolerance > 0.0 && tolerance <= 0.5) => {
                bad("tolerance", tolerance, "in (0, 0.5]")
            }
            _ => Ok(()),
        }
    }
}

impl fmt::Display for Level {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Level {
    type Err = String;

    /// Parses a level name with default settings (`linear`, `hertz`, `fit`, `incompressible`,
    /// `neo-hookean`, `neo-hookean-exact`, `tatara`, `calibrated`, `auto`; not `tabulated` and
    /// `custom`, which need data).
    fn from_str(s: &str) -> std::result::Result<Self, Self::Err> {
        Level::ALL
            .iter()
            .find(|l| l.name() == s)
            .copied()
            .ok_or_else(|| {
                let names: Vec<_> = Level::ALL.iter().map(|l| l.name()).collect();
                format!("unknown level `{s}`; expected one of: {}", names.join(", "))
            })
    }
}

/// A concrete level: the one a response was computed with.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LevelKind {
    /// Linear spring.
    Linear,
    /// Hertz.
    Hertz,
    /// The paper's explicit law (Eq. 38).
    Fit,
    /// Exact incompressible (Eq. 36).
    Incompressible,
    /// Tabulated full theory.
    NeoHookean,
    /// Exactly solved full theory.
    NeoHookeanExact,
    /// Tatara's extended Hertz.
    Tatara,
    /// softgrip's calibrated correction.
    Calibrated,
    /// A user's measured curve.
    Tabulated,
    /// A user's own normalised law.
    Custom,
}

impl LevelKind {
    /// The level's name, as on the command line.
    pub fn name(&self) -> &'static str {
        match self {
            LevelKind::Linear => "linear",
            LevelKind::Hertz => "hertz",
            LevelKind::Fit => "fit",
            LevelKind::Incompressible => "incompressible",
            LevelKind::NeoHookean => "neo-hookean",
            LevelKind::NeoHookeanExact => "neo-hookean-exact",
            LevelKind::Tatara => "tatara",
            LevelKind::Calibrated => "calibrated",
            LevelKind::Tabulated => "tabulated",
            LevelKind::Custom => "custom",
        }
    }

    /// A small stable code, for recordings (0 = linear ... 7 = calibrated, 8 = tabulated,
    /// 9 = custom).
    pub fn code(&self) -> u8 {
        *self as u8
    }
}

impl fmt::Display for LevelKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
