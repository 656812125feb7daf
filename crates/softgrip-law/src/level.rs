//! Which level of the law to use: [`Level`] is the user's choice (with its settings),
//! [`LevelKind`] names a concrete level (what [`Level::Auto`] picked, what a response used).

use std::fmt;
use std::str::FromStr;

use crate::error::{Error, Result};
use crate::level_table::{LEVELS, LevelInfo};
use crate::setting::LevelSetting;

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
    /// default settings (not [`Level::Tabulated`] and [`Level::Custom`], which need data), in
    /// the order of [`LEVELS`](crate::LEVELS), from which it is made.
    pub const ALL: [Level; 9] = crate::level_table::buildable();

    /// The level's row of [`LEVELS`](crate::LEVELS).
    pub fn info(&self) -> &'static LevelInfo {
        let same = std::mem::discriminant(self);
        LEVELS
            .iter()
            .find(|row| std::mem::discriminant(&row.level) == same)
            .expect("invariant: every Level has a row in LEVELS (tests/kinds.rs)")
    }

    /// The level's name: scene files, the command line, recordings, Python.
    pub fn name(&self) -> &'static str {
        self.info().name
    }

    /// The concrete level it is; `None` for [`Level::Auto`], which picks one per call.
    pub fn kind(&self) -> Option<LevelKind> {
        self.info().kind
    }

    /// The level named `name`, with its default settings (every row of
    /// [`LEVELS`](crate::LEVELS), `tabulated` and `custom` included: [`Level::info`]'s `data`
    /// says what else it needs).
    ///
    /// ```
    /// use softgrip_law::{Error, Level, LevelData};
    /// assert_eq!(Level::from_name("auto")?, Level::auto());
    /// assert_eq!(Level::from_name("tabulated")?.info().data, LevelData::MeasuredCurve);
    /// let e = Level::from_name("spring").unwrap_err();
    /// assert!(matches!(e, Error::UnknownName { field: "level", .. }));
    /// assert!(e.to_string().starts_with("`level` must be one of linear, hertz, fit,"), "{e}");
    /// # Ok::<(), Error>(())
    /// ```
    pub fn from_name(name: &str) -> Result<Level> {
        LEVELS
            .iter()
            .find(|row| row.name == name)
            .map(|row| row.level)
            .ok_or_else(|| Error::UnknownName {
                field: "level",
                value: name.to_owned(),
                expected: LEVELS
                    .iter()
                    .map(|row| row.name)
                    .collect::<Vec<_>>()
                    .join(", "),
            })
    }

    /// The value of its setting `key` (`k`, `tolerance`, `match_x`), `None` if it has none of
    /// that key.
    pub fn setting(&self, key: &str) -> Option<f64> {
        self.info().setting(key).and_then(|s| (s.get)(self))
    }

    /// The level with its setting `key` set to `value`. Fails with
    /// [`Error::UnexpectedSetting`] if the level does not take `key` (naming the levels that
    /// do), [`Error::UnknownName`] if no level does, and [`Error::InvalidParameter`] if the
    /// value is outside the setting's range.
    ///
    /// ```
    /// use softgrip_law::{Error, Level};
    /// assert_eq!(Level::fit().with_setting("k", 1.2)?, Level::Fit { k: 1.2 });
    /// let e = Level::Hertz.with_setting("k", 1.2).unwrap_err();
    /// assert_eq!(e.to_string(), "`k` applies only to level `fit`, not to level `hertz` (got 1.2)");
    /// assert!(Level::auto().with_setting("tolerance", 0.9).is_err()); // outside (0, 0.5]
    /// # Ok::<(), Error>(())
    /// ```
    pub fn with_setting(self, key: &str, value: f64) -> Result<Level> {
        let Some(setting) = self.info().setting(key) else {
            let takes: Vec<&str> = LEVELS
                .iter()
                .filter(|row| row.setting(key).is_some())
                .map(|row| row.name)
                .collect();
            if takes.is_empty() {
                return Err(Error::UnknownName {
                    field: "setting",
                    value: key.to_owned(),
                    expected: setting_keys().join(", "),
                });
            }
            return Err(Error::UnexpectedSetting {
                field: setting_key(key),
                value,
                kind: "level",
                name: self.name(),
            });
        };
        let level = (setting.set)(self, value)
            .expect("invariant: a row's setting applies to the row's level");
        check(setting, value)?;
        Ok(level)
    }

    /// Checks the level's own settings against their ranges.
    pub(crate) fn validate(&self) -> Result<()> {
        for setting in self.info().settings {
            if let Some(value) = (setting.get)(self) {
                check(setting, value)?;
            }
        }
        Ok(())
    }
}

/// Every setting key of the table, in table order (`match_x`, `k`, `tolerance`).
pub fn setting_keys() -> Vec<&'static str> {
    LEVELS
        .iter()
        .flat_map(|row| row.settings.iter().map(|s| s.key))
        .collect()
}

/// The table's `'static` spelling of `key` (one of [`setting_keys`]).
fn setting_key(key: &str) -> &'static str {
    setting_keys()
        .into_iter()
        .find(|k| *k == key)
        .expect("invariant: called with a key of the table")
}

/// `value` against `setting`'s range.
fn check(setting: &LevelSetting, value: f64) -> Result<()> {
    if setting.range.contains(value) {
        Ok(())
    } else {
        Err(Error::InvalidParameter {
            field: setting.key,
            value,
            range: setting.range.text(),
        })
    }
}

impl fmt::Display for Level {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Level {
    type Err = Error;

    /// [`Level::from_name`].
    fn from_str(s: &str) -> Result<Self> {
        Level::from_name(s)
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
    /// The level's row of [`LEVELS`](crate::LEVELS).
    pub fn info(&self) -> &'static LevelInfo {
        LEVELS
            .iter()
            .find(|row| row.kind == Some(*self))
            .expect("invariant: every LevelKind has a row in LEVELS (tests/kinds.rs)")
    }

    /// The level's name, as on the command line.
    pub fn name(&self) -> &'static str {
        self.info().name
    }

    /// The level's fixed code in files (its row's `code`: 0 = linear ... 7 = calibrated,
    /// 8 = tabulated, 9 = custom; never the enum's order).
    pub fn code(&self) -> u8 {
        self.info()
            .code
            .expect("invariant: every concrete level has a code (tests/kinds.rs)")
    }

    /// The concrete level of file code `code`, if any.
    ///
    /// ```
    /// use softgrip_law::LevelKind;
    /// assert_eq!(LevelKind::from_code(8), Some(LevelKind::Tabulated));
    /// assert_eq!(LevelKind::from_code(200), None);
    /// ```
    pub fn from_code(code: u8) -> Option<LevelKind> {
        LEVELS
            .iter()
            .find(|row| row.code == Some(code))
            .and_then(|row| row.kind)
    }

    /// The level that computes this one's forces, with its default settings.
    pub fn level(&self) -> Level {
        self.info().level
    }
}

impl fmt::Display for LevelKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
