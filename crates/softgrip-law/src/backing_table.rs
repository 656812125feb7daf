//! [`BACKINGS`]: the one table of fingertip constructions. Every name, file code, description
//! and parameter of a construction is here and nowhere else: [`Backing`] and [`BackingKind`]
//! read it, and so do the scene files, the command line, the recordings (the `.msg` constants
//! and the metadata) and Python.
//!
//! A new construction is one new row (and its [`Backing`] and [`BackingKind`] variants; the
//! tests fail until the row exists), with a new code: a code once written to a file keeps its
//! meaning for ever.

use crate::backing::Backing;

/// A construction without its numbers: what [`Backing`] is, as a plain name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BackingKind {
    /// [`Backing::Free`].
    Free,
    /// [`Backing::Flat`].
    Flat,
    /// [`Backing::Core`].
    Core,
}

/// The number a construction takes: `core`'s skin thickness.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BackingParameter {
    /// The key in scene files and recordings' metadata: `core_thickness`.
    pub key: &'static str,
    /// What it must be, with its unit (checked against the radius by
    /// [`ContactParams::with_backing`](crate::ContactParams::with_backing)).
    pub range: &'static str,
}

/// One row of [`BACKINGS`]: everything softgrip says about a construction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BackingInfo {
    /// The construction.
    pub kind: BackingKind,
    /// Its name: scene files, the command line, recordings, Python.
    pub name: &'static str,
    /// Its fixed code in files (`SoftContact.backing`, the `.msg` constants `BACKING_*`):
    /// never reused, never derived from an enum's order.
    pub code: u8,
    /// What it is, on one line.
    pub description: &'static str,
    /// The number it takes, if any.
    pub parameter: Option<BackingParameter>,
}

/// `core`'s skin thickness.
const CORE_THICKNESS: BackingParameter = BackingParameter {
    key: "core_thickness",
    range: "the skin thickness t, finite and in (0, R) m, R the fingertip's outer radius",
};

/// Every construction. The codes are those every recording since constructions were
/// recorded has used (0 = free, 1 = flat, 2 = core).
pub const BACKINGS: [BackingInfo; 3] = [
    BackingInfo {
        kind: BackingKind::Free,
        name: "free",
        code: 0,
        description: "a whole soft sphere (the paper's case)",
        parameter: None,
    },
    BackingInfo {
        kind: BackingKind::Flat,
        name: "flat",
        code: 1,
        description: "a soft hemisphere bonded at its flat face to the rigid finger",
        parameter: None,
    },
    BackingInfo {
        kind: BackingKind::Core,
        name: "core",
        code: 2,
        description: "a soft skin of thickness core_thickness over a rigid core",
        parameter: Some(CORE_THICKNESS),
    },
];

impl BackingKind {
    /// The construction's row of [`BACKINGS`].
    pub fn info(self) -> &'static BackingInfo {
        BACKINGS
            .iter()
            .find(|row| row.kind == self)
            .expect("invariant: every BackingKind has a row in BACKINGS (tests/kinds.rs)")
    }

    /// The construction of code `code`, if any.
    ///
    /// ```
    /// use softgrip_law::BackingKind;
    /// assert_eq!(BackingKind::from_code(2), Some(BackingKind::Core));
    /// assert_eq!(BackingKind::from_code(9), None);
    /// ```
    pub fn from_code(code: u8) -> Option<Self> {
        BACKINGS
            .iter()
            .find(|row| row.code == code)
            .map(|row| row.kind)
    }

    /// The [`Backing`] of this kind with the row's parameter (`thickness` \[m\] of `core`; the
    /// others ignore it). Unchecked: [`Backing::try_from_parts`] checks.
    pub fn with_parameter(self, thickness: f64) -> Backing {
        match self {
            BackingKind::Free => Backing::Free,
            BackingKind::Flat => Backing::Flat,
            BackingKind::Core => Backing::Core { thickness },
        }
    }
}
