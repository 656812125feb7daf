//! [`Backing`]: how a fingertip is built, which decides its law.

use std::fmt;
use std::str::FromStr;

use crate::Shortest;

/// The thinnest skin the calibrated level (and `auto`'s reference) of a [`Backing::Core`]
/// takes, as t/R [-]: down to it the level's tabulated form follows the form within its
/// documented accuracy (1.2e-8 in force); below it the table drifts from the form (2e-7 at
/// 0.01, 6e-6 at 0.001, 2e-3 at 1e-4) and below about 1e-8 the force turns negative (t/R =
/// 1e-22 was accepted and let a fingertip fall through the floor). The FE data behind the form
/// start at t/R = 0.2. A thinner skin needs a measured (`tabulated`) curve.
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
    /// The names [`FromStr`] accepts (`core` parses with no thickness: see there).
    pub const NAMES: [&'static str; 3] = ["free", "flat", "core"];

    /// `free`, `flat` or `core`, as in scene files and on the command line.
    pub fn name(&self) -> &'static str {
        match self {
            Backing::Free => "free",
            Backing::Flat => "flat",
            Backing::Core { .. } => "core",
        }
    }

    /// A small stable code for recordings: 0 = free, 1 = flat, 2 = core.
    pub fn code(&self) -> u8 {
        match self {
            Backing::Free => 0,
            Backing::Flat => 1,
            Backing::Core { .. } => 2,
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
    type Err = String;

    /// `free` or `flat`; `core` needs its thickness and is refused here with a message that
    /// says so (build [`Backing::Core`] directly).
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "free" => Ok(Backing::Free),
            "flat" => Ok(Backing::Flat),
            "core" => Err(
                "backing `core` needs its skin thickness: use Backing::Core { thickness }".into(),
            ),
            _ => Err(format!(
                "unknown backing `{s}`; expected one of: {}",
                Backing::NAMES.join(", ")
            )),
        }
    }
}
