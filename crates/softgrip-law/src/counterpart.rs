//! [`Counterpart`]: the rigid body a fingertip touches, as the law sees it at the contact: a
//! plane, a smooth surface of two principal curvatures, or a sharp edge.

use std::fmt;

use crate::error::{Error, Result};

/// The kinds of counterpart, each with its fixed code for files (never the enum's order) and
/// its name: the one table ([`CounterpartKind::ALL`]) every reader and writer uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CounterpartKind {
    /// A flat body: the law of the fingertip's construction, unchanged.
    Plane,
    /// A smooth surface with two principal curvatures at the contact (a ball, a cylinder, a
    /// capsule, a cone's side, a curved mesh; convex or concave).
    Curved,
    /// A sharp edge (two flat faces meeting at a ridge, as a box's), pressed along the
    /// bisector of its faces.
    Edge,
}

impl CounterpartKind {
    /// Every kind: `(kind, code, name)`. The code is what recordings store.
    pub const ALL: [(CounterpartKind, u8, &'static str); 3] = [
        (CounterpartKind::Plane, 0, "plane"),
        (CounterpartKind::Curved, 1, "curved"),
        (CounterpartKind::Edge, 2, "edge"),
    ];

    /// The kind's row of [`ALL`](Self::ALL).
    fn row(self) -> (CounterpartKind, u8, &'static str) {
        Self::ALL
            .into_iter()
            .find(|(k, _, _)| *k == self)
            .expect("invariant: every kind has a row in CounterpartKind::ALL")
    }

    /// The fixed code for recordings: 0 plane, 1 curved, 2 edge.
    pub fn code(self) -> u8 {
        self.row().1
    }

    /// `plane`, `curved` or `edge`.
    pub fn name(self) -> &'static str {
        self.row().2
    }

    /// The kind of code `code`, if any.
    ///
    /// ```
    /// use softgrip_law::CounterpartKind;
    /// assert_eq!(CounterpartKind::from_code(2), Some(CounterpartKind::Edge));
    /// assert_eq!(CounterpartKind::from_code(7), None);
    /// ```
    pub fn from_code(code: u8) -> Option<Self> {
        Self::ALL
            .into_iter()
            .find(|(_, c, _)| *c == code)
            .map(|(k, _, _)| k)
    }
}

impl fmt::Display for CounterpartKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The largest curvature a [`Counterpart`] may have, in units of the fingertip's curvature:
/// `kappa R <= 1e4` (a ball 1e4 times smaller than the fingertip; anything sharper is an
/// [`Counterpart::EDGE`]). Checked when the counterpart is bound to a law
/// ([`crate::ContactLaw::with_counterpart`]).
pub const MAX_RELATIVE_CURVATURE: f64 = 1e4;

/// The most concave a [`Counterpart`] may be, in units of the fingertip's curvature:
/// `kappa R >= -0.999` (a bowl at least 1.001 times the fingertip's radius; a bowl the
/// fingertip's own size or tighter would wrap it: no Hertz contact).
pub const MIN_RELATIVE_CURVATURE: f64 = -0.999;

/// The rigid body a fingertip touches, at the contact: what shape the law's force, patch and
/// pressure are computed for.
///
/// - [`PLANE`](Self::PLANE): today's law of the fingertip's construction, bit for bit.
/// - [`try_curved`](Self::try_curved): a smooth surface with principal curvatures `k1`, `k2`
///   \[1/m\] along two orthogonal tangent directions (convex > 0, concave < 0, 0 along a
///   straight line): a ball of radius r is `(1/r, 1/r)`, a cylinder's side `(0, 1/r)`. The
///   contact patch is an ellipse whose first semi-axis lies along `k1`'s direction
///   ([`crate::ContactPatch`]).
/// - [`EDGE`](Self::EDGE): a sharp edge, pressed along the bisector of its faces (the patch's
///   first semi-axis lies along the edge).
///
/// A curved counterpart is checked here for finite curvatures; against the fingertip it
/// touches (neither more concave than [`MIN_RELATIVE_CURVATURE`] nor sharper than
/// [`MAX_RELATIVE_CURVATURE`], relative to its radius) when it is bound to the law.
///
/// ```
/// use softgrip_law::{Counterpart, CounterpartKind};
/// let ball = Counterpart::try_ball(0.03)?; // a ball of radius 30 mm
/// assert_eq!(ball.kind(), CounterpartKind::Curved);
/// assert!((ball.curvatures()[0] - 1.0 / 0.03).abs() < 1e-12);
/// let can = Counterpart::try_cylinder(0.033)?; // curvature 0 along the axis, first
/// assert_eq!(can.curvatures()[0], 0.0);
/// assert_eq!(Counterpart::try_curved(0.0, 0.0)?, Counterpart::PLANE); // flat is a plane
/// assert!(Counterpart::try_curved(f64::NAN, 1.0).is_err());
/// # Ok::<(), softgrip_law::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Counterpart {
    kind: CounterpartKind,
    /// Principal curvatures \[1/m\]; 0 for a plane and an edge.
    curvatures: [f64; 2],
}

impl Default for Counterpart {
    fn default() -> Self {
        Self::PLANE
    }
}

impl Counterpart {
    /// A flat rigid body.
    pub const PLANE: Self = Self {
        kind: CounterpartKind::Plane,
        curvatures: [0.0; 2],
    };

    /// A sharp edge of a rigid body (two flat faces at a ridge), pressed along the bisector
    /// of its faces. Calibrated on a right-angle edge (a box's); see the crate's README for
    /// other angles.
    pub const EDGE: Self = Self {
        kind: CounterpartKind::Edge,
        curvatures: [0.0; 2],
    };

    /// A smooth surface with principal curvatures `k1` and `k2` \[1/m\] (finite; convex > 0,
    /// concave < 0) along two orthogonal tangent directions; both 0 is [`PLANE`](Self::PLANE).
    pub fn try_curved(k1: f64, k2: f64) -> Result<Self> {
        for (field, k) in [("curvature k1", k1), ("curvature k2", k2)] {
            if !k.is_finite() {
                return Err(Error::InvalidParameter {
                    field,
                    value: k,
                    range: "finite [1/m] (convex > 0, concave < 0)",
                });
            }
        }
        if k1 == 0.0 && k2 == 0.0 {
            return Ok(Self::PLANE);
        }
        Ok(Self {
            kind: CounterpartKind::Curved,
            curvatures: [k1, k2],
        })
    }

    /// A rigid ball of radius `radius` \[m\] (finite, > 0): curvatures `(1/r, 1/r)`.
    pub fn try_ball(radius: f64) -> Result<Self> {
        let k = inverse_radius("ball radius", radius)?;
        Self::try_curved(k, k)
    }

    /// A rigid cylinder's side of radius `radius` \[m\] (finite, > 0): curvature 0 along its
    /// axis (the first direction) and `1/r` around it.
    pub fn try_cylinder(radius: f64) -> Result<Self> {
        let k = inverse_radius("cylinder radius", radius)?;
        Self::try_curved(0.0, k)
    }

    /// The counterpart of `kind` with `curvatures` \[1/m\] (ignored unless `Curved`), as a
    /// recording stores it.
    pub fn try_from_parts(kind: CounterpartKind, curvatures: [f64; 2]) -> Result<Self> {
        match kind {
            CounterpartKind::Plane => Ok(Self::PLANE),
            CounterpartKind::Edge => Ok(Self::EDGE),
            CounterpartKind::Curved => Self::try_curved(curvatures[0], curvatures[1]),
        }
    }

    /// Plane, curved or edge.
    pub fn kind(&self) -> CounterpartKind {
        self.kind
    }

    /// Principal curvatures `[k1, k2]` \[1/m\]; zeros for a plane and an edge.
    pub fn curvatures(&self) -> [f64; 2] {
        self.curvatures
    }

    /// `true` for [`PLANE`](Self::PLANE).
    pub fn is_plane(&self) -> bool {
        self.kind == CounterpartKind::Plane
    }

    /// The curvatures in units of the fingertip's, `kappa R`, checked against
    /// [`MIN_RELATIVE_CURVATURE`] and [`MAX_RELATIVE_CURVATURE`] for a fingertip of radius
    /// `radius` \[m\].
    pub(crate) fn relative_curvatures(&self, radius: f64) -> Result<[f64; 2]> {
        let rel = self.curvatures.map(|k| k * radius);
        for (field, v) in [("curvature k1", rel[0]), ("curvature k2", rel[1])] {
            if !(v.is_finite() && v >= MIN_RELATIVE_CURVATURE) {
                return Err(Error::IncompatibleCounterpart {
                    field,
                    relative_curvature: v,
                    reason: "a concave counterpart must be wider than the fingertip: kappa R >= -0.999 (a bowl at least 1.001 R), else it wraps the fingertip and the contact is not Hertz's",
                });
            }
            if v > MAX_RELATIVE_CURVATURE {
                return Err(Error::IncompatibleCounterpart {
                    field,
                    relative_curvature: v,
                    reason: "a counterpart curved more than 1e4 times the fingertip (kappa R > 1e4) is a sharp feature: use Counterpart::EDGE",
                });
            }
        }
        Ok(rel)
    }
}

impl fmt::Display for Counterpart {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.kind {
            CounterpartKind::Curved => {
                let [k1, k2] = self.curvatures;
                write!(f, "curved (k1 = {k1} 1/m, k2 = {k2} 1/m)")
            }
            kind => f.write_str(kind.name()),
        }
    }
}

/// `1/r` for a radius `r` that must be finite and > 0 (and `1/r` finite).
fn inverse_radius(field: &'static str, r: f64) -> Result<f64> {
    if r.is_finite() && r > 0.0 && (1.0 / r).is_finite() {
        Ok(1.0 / r)
    } else {
        Err(Error::InvalidParameter {
            field,
            value: r,
            range: "finite and > 0 m (with 1/r finite)",
        })
    }
}
