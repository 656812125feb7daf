//! [`Backing`]: how a fingertip is built, which decides its law.

use std::fmt;
use std::str::FromStr;

use crate::Shortest;
use crate::backing_table::{BACKINGS, BackingInfo, BackingKind};
use crate::error::{Error, Result};

/// The thinnest skin the calibrated level (and `auto`'s reference) of a [`Backing::Core`]
/// takes, as t/R [-]: down to it the level's tabulated form follows the form within its
/// documented accuracy (5.3e-8 in force); below it the table drifted from the form (the
/// session-7 form: 2e-7 at 0.01, 6e-6 at 0.001, 2e-3 at 1e-4) and below about 1e-8 the force
/// turned negative (t/R = 1e-22 was accepted and let a fingertip fall through the floor). FE
/// skins go down to t/R 0.05: since session 24 (the thin-layer floor of session 21 and the
/// squeezed skin's deviatoric stiffening) the force is within 3.32 % of the fitted t/R 0.05-0.1
/// skins and 3.80 % of the seven blind ones (t/R 0.06-0.08; the session-20 law was up to 16.2 %
/// too soft there; softgrip-law README, *Thin skins*). A thinner skin needs
/// a measured (`tabulated`) curve.
pub const MIN_CORE_THICKNESS_RATIO: f64 = 0.05;

/// How a soft fingertip of outer radius R is held by the rigid finger.
///
/// - [`Free`](Backing::Free): a free elastic sphere, the paper's case (and the finite-element
///   reference: a sphere flattened between two rigid plates, its equator free to slide).
/// - [`Flat`](Backing::Flat): a soft hemisphere of radius R whose flat face is bonded to a
///   rigid finger (no slip, no radial expansion there): a moulded silicone pad. Stiffer than
///   the free sphere: 1.16x at x = 0.1, 1.3x at 0.2 (FE, nu = 0.49).
/// - [`Core`](Backing::Core): a soft hemispherical skin between radii R - t and R, bonded on its
///   inner surface to a rigid core and on its flat annulus to the finger. Stiffer still, and
///   the thinner the skin, the stiffer (a thin incompressible layer carries far more than
///   Hertz).
///
/// Only the pole side (the curved half the pad faces with) is soft; what touches a backed
/// fingertip from behind its flat face touches the finger (see the plugin's documentation).
///
/// ```
/// use softgrip_law::Backing;
/// assert_eq!("flat".parse::<Backing>().unwrap(), Backing::Flat);
/// assert_eq!(Backing::Core { thickness: 0.004 }.name(), "core");
/// assert_eq!(Backing::default(), Backing::Free);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Backing {
    /// A free sphere (today's law, unchanged).
    #[default]
    Free,
    /// A hemisphere bonded at its flat face to a rigid finger.
    Flat,
    /// A skin over a rigid core.
    Core {
        /// Skin thickness t \[m\], `0 < t < R` (checked by
        /// [`ContactParams::with_backing`](crate::ContactParams::with_backing)).
        thickness: f64,
    },
}

impl Backing {
    /// The names [`FromStr`] accepts, in the order of [`BACKINGS`] (`core` parses with no
    /// thickness: see there).
    pub const NAMES: [&'static str; BACKINGS.len()] = {
        let mut names = [""; BACKINGS.len()];
        let mut i = 0;
        while i < BACKINGS.len() {
            names[i] = BACKINGS[i].name;
            i += 1;
        }
        names
    };

    /// The construction without its numbers.
    pub fn kind(&self) -> BackingKind {
        match self {
            Backing::Free => BackingKind::Free,
            Backing::Flat => BackingKind::Flat,
            Backing::Core { .. } => BackingKind::Core,
        }
    }

    /// The construction's row of [`BACKINGS`].
    pub fn info(&self) -> &'static BackingInfo {
        self.kind().info()
    }

    /// `free`, `flat` or `core`, as in scene files and on the command line.
    pub fn name(&self) -> &'static str {
        self.info().name
    }

    /// The construction's fixed code in files (0 = free, 1 = flat, 2 = core).
    pub fn code(&self) -> u8 {
        self.info().code
    }

    /// The construction named `name` with its parameter (`thickness` \[m\], the skin of
    /// `core`): the one parser of `(name, thickness)` that scene files, the command line,
    /// recordings and Python use. Typed errors name the field, the value and the range:
    /// [`Error::UnknownName`] (`backing`), [`Error::MissingSetting`] (`core` without a
    /// thickness), [`Error::UnexpectedSetting`] (a thickness for `free` or `flat`) and
    /// [`Error::InvalidParameter`] (a thickness that is not finite and > 0; against the
    /// radius, [`ContactParams::with_backing`](crate::ContactParams::with_backing) checks).
    ///
    /// ```
    /// use softgrip_law::{Backing, Error};
    /// assert_eq!(Backing::try_from_parts("core", Some(0.004))?, Backing::Core { thickness: 0.004 });
    /// assert_eq!(Backing::try_from_parts("flat", None)?, Backing::Flat);
    /// let e = Backing::try_from_parts("flat", Some(0.004)).unwrap_err();
    /// assert_eq!(e.to_string(), "`core_thickness` applies only to backing `core`, not to backing `flat` (got 0.004)");
    /// assert!(matches!(Backing::try_from_parts("core", None), Err(Error::MissingSetting { .. })));
    /// assert!(matches!(Backing::try_from_parts("steel", None), Err(Error::UnknownName { .. })));
    /// # Ok::<(), Error>(())
    /// ```
    pub fn try_from_parts(name: &str, thickness: Option<f64>) -> Result<Backing> {
        let row = BACKINGS
            .iter()
            .find(|row| row.name == name)
            .ok_or_else(|| Error::UnknownName {
                field: "backing",
                value: name.to_owned(),
                expected: Backing::NAMES.join(", "),
            })?;
        match (row.parameter, thickness) {
            (Some(p), Some(t)) if !(t.is_finite() && t > 0.0) => Err(Error::InvalidParameter {
                field: p.key,
                value: t,
                range: p.range,
            }),
            (Some(_), Some(t)) => Ok(row.kind.with_parameter(t)),
            (Some(p), None) => Err(Error::MissingSetting {
                field: p.key,
                kind: "backing",
                name: row.name,
                range: p.range,
            }),
            (None, Some(t)) => {
                let key = BACKINGS
                    .iter()
                    .find_map(|r| r.parameter)
                    .expect("invariant: a construction in BACKINGS takes a parameter")
                    .key;
                Err(Error::UnexpectedSetting {
                    field: key,
                    value: t,
                    kind: "backing",
                    name: row.name,
                })
            }
            (None, None) => Ok(row.kind.with_parameter(0.0)),
        }
    }

    /// The skin thickness t \[m\] of a [`Backing::Core`], else `None`.
    pub fn thickness(&self) -> Option<f64> {
        match self {
            Backing::Core { thickness } => Some(*thickness),
            _ => None,
        }
    }

    /// `true` for [`Backing::Free`].
    pub fn is_free(&self) -> bool {
        matches!(self, Backing::Free)
    }
}

impl fmt::Display for Backing {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Backing::Core { thickness } => write!(f, "core (t = {} m)", Shortest(*thickness)),
            b => f.write_str(b.name()),
        }
    }
}

impl FromStr for Backing {
    type Err = Error;

    /// A construction without parameter (`free`, `flat`); `core` needs its thickness and is
    /// refused ([`Error::MissingSetting`]: use [`Backing::try_from_parts`]).
    fn from_str(s: &str) -> Result<Self> {
        Backing::try_from_parts(s, None)
    }
}
