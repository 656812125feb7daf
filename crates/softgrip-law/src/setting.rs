//! [`LevelSetting`]: a number a level takes (`k` of `fit`, `tolerance` of `auto`, `match_x` of
//! `linear`), with its default, its valid [`Interval`] and how to read and set it on a
//! [`Level`]: one row of the level table ([`crate::LEVELS`]) says all of it.

use std::fmt;

use crate::level::Level;

/// A closed, open or half-open interval of real numbers: where a setting is valid. NaN is in
/// no interval.
///
/// ```
/// use softgrip_law::Interval;
/// let i = Interval::new(0.0, false, 0.5, true, "in (0, 0.5]");
/// assert!(i.contains(0.5) && !i.contains(0.0) && !i.contains(f64::NAN));
/// assert_eq!(i.to_string(), "in (0, 0.5]");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    min: f64,
    min_closed: bool,
    max: f64,
    max_closed: bool,
    text: &'static str,
}

impl Interval {
    /// `[min, max]`, `(min, max]`, ... as the flags say, with `text` its description in
    /// messages (`"in (0, 0.5]"`; a test checks that it names the bounds).
    pub const fn new(
        min: f64,
        min_closed: bool,
        max: f64,
        max_closed: bool,
        text: &'static str,
    ) -> Self {
        Self {
            min,
            min_closed,
            max,
            max_closed,
            text,
        }
    }

    /// Whether `value` lies in the interval (never for NaN).
    pub fn contains(&self, value: f64) -> bool {
        let above = if self.min_closed {
            value >= self.min
        } else {
            value > self.min
        };
        let below = if self.max_closed {
            value <= self.max
        } else {
            value < self.max
        };
        above && below
    }

    /// The lower bound.
    pub const fn min(&self) -> f64 {
        self.min
    }

    /// The upper bound.
    pub const fn max(&self) -> f64 {
        self.max
    }

    /// The bounds in interval notation: `(0, 0.5]`.
    pub fn bounds(&self) -> String {
        format!(
            "{}{}, {}{}",
            if self.min_closed { '[' } else { '(' },
            self.min,
            self.max,
            if self.max_closed { ']' } else { ')' },
        )
    }

    /// The description used in messages, `in (0, 0.5]`.
    pub const fn text(&self) -> &'static str {
        self.text
    }
}

impl fmt::Display for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.text)
    }
}

/// A number a level takes, one entry of a [`LevelInfo`](crate::LevelInfo)'s `settings`: its
/// key (the same in scene files, recordings' metadata, on the command line as `--key` with `-`
/// for `_`, and in Python as a keyword), default, range and one-line description.
#[derive(Debug, Clone, Copy)]
pub struct LevelSetting {
    /// The key: `k`, `tolerance`, `match_x`.
    pub key: &'static str,
    /// The value a level has when none is given.
    pub default: f64,
    /// Where the value is valid ([`Level`] construction checks it).
    pub range: Interval,
    /// What it is, with its unit.
    pub description: &'static str,
    /// The setting's value on `level`, `None` for a level of another kind.
    pub get: fn(&Level) -> Option<f64>,
    /// `level` with the setting set to `value` (unchecked), `None` for a level of another kind.
    pub set: fn(Level, f64) -> Option<Level>,
}

impl LevelSetting {
    /// The command-line flag: `--match-x` for `match_x`.
    pub fn flag(&self) -> String {
        format!("--{}", self.key.replace('_', "-"))
    }
}
