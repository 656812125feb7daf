//! [`LEVELS`]: the one table of the law's levels. Every name, file code, description, setting
//! and default of a level is here and nowhere else: [`Level`] and [`LevelKind`] read it, and
//! so do the scene files, the command line, the recordings (the `.msg` constants and the
//! metadata) and Python.
//!
//! A new level is one new row (and its [`Level`] and [`LevelKind`] variants; the tests fail
//! until the row exists). Its `code` is new too: a code once written to a file keeps its
//! meaning for ever, so codes are never reused or derived from the enums' order.

use crate::level::{
    DEFAULT_AUTO_TOLERANCE, DEFAULT_FIT_K, DEFAULT_LINEAR_MATCH_X, Level, LevelKind,
};
use crate::setting::{Interval, LevelSetting};

/// What a level needs besides the contact's parameters (E, nu, R, construction).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum LevelData {
    /// Nothing: [`ContactLaw::try_new`](crate::ContactLaw::try_new) builds it.
    None,
    /// A measured squeeze curve ([`ContactLaw::tabulated`](crate::ContactLaw::tabulated)).
    MeasuredCurve,
    /// A user's [`NormalisedLaw`](crate::NormalisedLaw)
    /// ([`ContactLaw::custom`](crate::ContactLaw::custom); from Rust only).
    UserLaw,
}

/// One row of [`LEVELS`]: everything softgrip says about a level.
#[derive(Debug, Clone, Copy)]
pub struct LevelInfo {
    /// The level with its default settings.
    pub level: Level,
    /// The concrete level it is (what a response says computed it); `None` for `auto`, which
    /// picks a concrete level per call.
    pub kind: Option<LevelKind>,
    /// Its name: scene files, the command line, recordings, Python.
    pub name: &'static str,
    /// The fixed code of [`kind`](Self::kind) in files (`SoftContact.level`, the `.msg`
    /// constants `LEVEL_*`): never reused, never derived from an enum's order. `None` for
    /// `auto` (never what computed a force).
    pub code: Option<u8>,
    /// What it is, on one line.
    pub description: &'static str,
    /// The numbers it takes, with their defaults.
    pub settings: &'static [LevelSetting],
    /// What it needs besides the contact's parameters.
    pub data: LevelData,
}

impl LevelInfo {
    /// The setting with key `key`, if the level takes it.
    pub fn setting(&self, key: &str) -> Option<&'static LevelSetting> {
        self.settings.iter().find(|s| s.key == key)
    }
}

/// `match_x` of `linear`.
const MATCH_X: LevelSetting = LevelSetting {
    key: "match_x",
    default: DEFAULT_LINEAR_MATCH_X,
    range: Interval::new(0.0, false, 1.0, true, "in (0, 1]"),
    description: "compression ratio x [-] where the spring's force equals Hertz's",
    get: |level| match level {
        Level::Linear { match_x } => Some(*match_x),
        _ => None,
    },
    set: |level, match_x| match level {
        Level::Linear { .. } => Some(Level::Linear { match_x }),
        _ => None,
    },
};

/// `k` of `fit`.
const K: LevelSetting = LevelSetting {
    key: "k",
    default: DEFAULT_FIT_K,
    range: Interval::new(0.0, true, 10.0, true, "finite and in [0, 10]"),
    description: "slope k [-] of 1/chi = 1 - k x (Eq. 38; 10/9 in the paper)",
    get: |level| match level {
        Level::Fit { k } => Some(*k),
        _ => None,
    },
    set: |level, k| match level {
        Level::Fit { .. } => Some(Level::Fit { k }),
        _ => None,
    },
};

/// `tolerance` of `auto`.
const TOLERANCE: LevelSetting = LevelSetting {
    key: "tolerance",
    default: DEFAULT_AUTO_TOLERANCE,
    range: Interval::new(0.0, false, 0.5, true, "in (0, 0.5]"),
    description: "relative force tolerance [-] against `calibrated`",
    get: |level| match level {
        Level::Auto { tolerance } => Some(*tolerance),
        _ => None,
    },
    set: |level, tolerance| match level {
        Level::Auto { .. } => Some(Level::Auto { tolerance }),
        _ => None,
    },
};

/// A row of a level without settings that needs no data.
const fn plain(
    level: Level,
    kind: LevelKind,
    name: &'static str,
    code: u8,
    description: &'static str,
) -> LevelInfo {
    LevelInfo {
        level,
        kind: Some(kind),
        name,
        code: Some(code),
        description,
        settings: &[],
        data: LevelData::None,
    }
}

/// Every level, cheapest first, then those that need data, then `auto`. The codes are those
/// every recording since the first has used (0 = linear ... 7 = calibrated, 8 = tabulated,
/// 9 = custom).
pub const LEVELS: [LevelInfo; 11] = [
    LevelInfo {
        settings: &[MATCH_X],
        ..plain(
            Level::linear(),
            LevelKind::Linear,
            "linear",
            0,
            "linear spring matched to Hertz's force at match_x (a baseline only)",
        )
    },
    plain(
        Level::Hertz,
        LevelKind::Hertz,
        "hertz",
        1,
        "Hertz (Eq. 5): exact for small x only",
    ),
    LevelInfo {
        settings: &[K],
        ..plain(
            Level::fit(),
            LevelKind::Fit,
            "fit",
            2,
            "the paper's explicit law chi_L = 1/(1 - k x) (Eq. 38), radius of Eq. 42",
        )
    },
    plain(
        Level::Incompressible,
        LevelKind::Incompressible,
        "incompressible",
        3,
        "exact incompressible neo-Hookean chi_IC (Eq. 36), radius R artanh(sqrt x)",
    ),
    plain(
        Level::NeoHookean,
        LevelKind::NeoHookean,
        "neo-hookean",
        4,
        "full compressible neo-Hookean theory, tabulated once per material (nu < 0.5)",
    ),
    plain(
        Level::NeoHookeanExact,
        LevelKind::NeoHookeanExact,
        "neo-hookean-exact",
        5,
        "full compressible neo-Hookean theory, solved at every call (nu < 0.5)",
    ),
    plain(
        Level::Tatara,
        LevelKind::Tatara,
        "tatara",
        6,
        "Tatara's extended Hertz law of a finite sphere (a peer baseline)",
    ),
    plain(
        Level::Calibrated,
        LevelKind::Calibrated,
        "calibrated",
        7,
        "softgrip's correction fitted to finite elements, for each construction",
    ),
    LevelInfo {
        data: LevelData::MeasuredCurve,
        ..plain(
            Level::Tabulated,
            LevelKind::Tabulated,
            "tabulated",
            8,
            "a measured squeeze curve (delta_m, force_n), monotone cubic interpolation",
        )
    },
    LevelInfo {
        data: LevelData::UserLaw,
        ..plain(
            Level::Custom,
            LevelKind::Custom,
            "custom",
            9,
            "a user's own NormalisedLaw (from Rust)",
        )
    },
    LevelInfo {
        level: Level::auto(),
        kind: None,
        name: "auto",
        code: None,
        description: "per call, the cheapest of hertz, fit, incompressible and calibrated within tolerance of calibrated",
        settings: &[TOLERANCE],
        data: LevelData::None,
    },
];

/// The levels that [`ContactLaw::try_new`](crate::ContactLaw::try_new) builds from parameters
/// alone, with their default settings, in table order ([`Level::ALL`]). Fails to compile if
/// `N` is not their count.
pub(crate) const fn buildable<const N: usize>() -> [Level; N] {
    let mut out = [Level::Hertz; N];
    let (mut i, mut n) = (0, 0);
    while i < LEVELS.len() {
        if matches!(LEVELS[i].data, LevelData::None) {
            assert!(
                n < N,
                "Level::ALL is shorter than the table's buildable levels"
            );
            out[n] = LEVELS[i].level;
            n += 1;
        }
        i += 1;
    }
    assert!(
        n == N,
        "Level::ALL is longer than the table's buildable levels"
    );
    out
}
