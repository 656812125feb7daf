//! softgrip's calibrated level of the free sphere: an explicit correction (one square root and
//! one division per evaluation, like `chi_L`; see `cargo bench -p softgrip-law`), fitted to the
//! finite-element reference (`tests/data/fe/`) and built from physical terms.
//!
//! ```text
//! chi_cal = N S / D
//!   N = 1 - x + x^2/3                          numerator of chi_IC (Eq. 36)
//!   S = 1 - x + c(nu) sqrt(x) + e x^2 + f x^3  finite-size factor (the other plate is 2R away)
//!   D = (1 - x)^2 + B(nu) x^2                  chi_IC's lateral-area pole, softened by compressibility
//!   c(nu) = c0 + c1 beta,  beta = (1 - 2nu) / (2 (1 - nu))      (Dundurs' beta)
//!   B(nu) = (b eps)^2,     eps = mu/kappa = 3 (1 - 2nu) / (2 (1 + nu))
//! a/R = artanh(sqrt x) (1 + g1 x + g3 x^3) (1 - x) / (1 - x + eps x / 4)
//! ```
//!
//! - **Finite size.** FE over Hertz grows like `1 + c sqrt(x)` at small x (the sphere is
//!   squeezed between two plates: the far contact's field stiffens this one, a Boussinesq
//!   correction of relative order a/R). FE gives c = 0.45 at nu = 0.3 and 0.37 at nu = 0.49:
//!   the compressible body is stiffer. The coupling of normal pressure to radial surface motion in
//!   a frictionless contact is Dundurs' beta, zero at nu = 0.5: `c = c0 + c1 beta`. (Tatara's
//!   `(3 - 2nu)/(2 pi (1 - nu))` = 0.55-0.63 is too large and trends the other way in nu.)
//!   `e x^2 + f x^3` is the finite-size factor's large-x part: the two patches' fields overlap
//!   once a ~ R; the cubic term (negative) is what the FE's reach past x = 0.65 selects.
//! - **Compressibility.** `1/(1-x)^2` is the lateral area growth of an incompressible bar; a
//!   compressible bar loses volume instead, with volumetric strain ~ `eps x / (1 - x)`, which
//!   regularises the pole as `(1-x)^2 + (b eps x)^2`. The square is what the nu = 0.3 FE curve
//!   selects (other powers fit at 0.7-1.3 % instead of 0.5 %), and it matches the full theory,
//!   whose limit point sits about `0.9 eps` below x = 1 (a cut-off linear in eps).
//! - **Radius.** `(1 - x)/(1 - x + eps x/4)` is the full theory's `sqrt(J/lam)` factor (the 1/4 is
//!   fitted to the theory's Eq. 25, not to FE); `1 + g1 x + g3 x^3` is the FE's excess.
//!
//! Constants: least squares on the reference FE force (`tests/data/fe/force_nu{0.3,0.49}.csv`)
//! for 0.01 <= x <= 0.61 at nu = 0.3 and 0.01 <= x <= 0.78 at nu = 0.49 (each to where the FE
//! reaches): c0 = 0.36889, c1 = 0.28197, e = 0.837, f = -0.25364, b = 0.56801; the radius
//! below.
//!
//! Residuals against FE (`cargo test -p softgrip-law --test fe_reference` asserts them):
//! force within 0.72 % (nu = 0.3, to x = 0.61) and 1.34 % (nu = 0.49, to 0.78); held out (not in
//! the fit, softgrip's own FE, `tests/data/fe/free/`): within 1.74 % at nu = 0.4 and 1.27 % at
//! nu = 0.45 for 0.01 <= x <= 0.78. The radius, for 0.1 <= x <= 0.4, against the FE radius
//! without the radius column's step noise and lag (smoothed plus half an element, see
//! `backed.rs`, `tools/calibration/REPORT_radius_pressure.md`): within 1.07 % (nu = 0.3) and
//! 2.64 % (0.49); on softgrip's own FE (not in the fit) 0.78 % (0.3), 1.53 % (0.4), 2.00 %
//! (0.45), 1.31 % (0.49) (`--test radius_pressure`). Against the raw column: 3.57 % and 1.87 %
//! for 0.1 <= x <= 0.5 (`--test fe_reference`).
//!
//! - **Pressure.** `p = p0 (1 - r^2/a^2)^m` over the calibrated radius, force-conserving
//!   ([`crate::ContactPatch`]), with `m = 1/2 + (a0 + a1 eps) sqrt(x) + a2 x`: Hertz's ellipse at
//!   x -> 0, flatter at moderate x (the finite body spreads the load towards the edge, more so
//!   when incompressible), more peaked at large x. a0 = -0.429863, a1 = 0.461134, a2 = 0.704516:
//!   per FE profile at x = 0.1, 0.3, 0.5 for nu = 0.3, 0.4, 0.45, 0.49
//!   (`tests/data/fe/free/pressure_*.csv`, the two nodes nearest the axis dropped: the tie
//!   artefact) the exponent that best matches it with the FE's force and this radius, then least
//!   squares of `(m + 1)/(m_best + 1)` (`tools/calibration/fit_radius_pressure.py`). Peak within
//!   2.8 % of FE and the profile within 2.8 % of FE's peak over r <= 0.8 a (FE's force); with
//!   the law's force 2.6 % and 2.7 % (`--test radius_pressure`).
//! - **Radius** (refitted with the pressure): `g1 x + g3 x^3`, g1 = 0.042222, g3 = 0.109823,
//!   least squares on the reference's FE radius without its step noise and lag for
//!   0.05 <= x <= 0.6 (the estimate: `backed.rs`, Radius).
//!
//! Validity: `0 <= nu <= 0.5`, validated for `0.3 <= nu <= 0.5`; `0 <= x <= x_max(nu)` with
//! `x_max = 0.65` for `nu <= 0.3`, rising linearly to `0.78` at `nu >= 0.4`: where the FE stops
//! (at nu = 0.3 the FE material collapses past 0.61-0.65, at nu = 0.4-0.49 the mesh past
//! 0.78-0.81, an element volume ratio below 0.2).

use super::NormalisedLaw;
use crate::error::{Error, Result};
use crate::level::LevelKind;
use crate::quadrature::integrate;

const C0: f64 = 0.36889;
const C1: f64 = 0.28197;
const E: f64 = 0.837;
const F3: f64 = -0.25364;
const B: f64 = 0.56801;
/// Radius excess `1 + g1 x + g3 x^3`: g1, g3.
const G: [f64; 2] = [0.042222, 0.109823];
/// Pressure shape: a0, a1, a2 of `m = 1/2 + (a0 + a1 eps) sqrt(x) + a2 x`.
const SHAPE: [f64; 3] = [-0.429863, 0.461134, 0.704516];

/// The calibrated level for one Poisson ratio.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Calibrated {
    /// `c(nu)`, the coefficient of `sqrt(x)`.
    c: f64,
    /// `B(nu) = (b eps)^2`.
    b2: f64,
    /// `eps / 4` of the radius.
    eps4: f64,
    x_max: f64,
}

impl Calibrated {
    /// Needs `0 <= nu <= 0.5` (the form is fitted at 0.3 and 0.49).
    pub(crate) fn try_new(nu: f64) -> Result<Self> {
        if !(0.0..=0.5).contains(&nu) {
            return Err(Error::IncompatibleLevel {
                level: LevelKind::Calibrated,
                nu,
                reason: "the calibrated level is defined for 0 <= nu <= 0.5 (fitted at 0.3 and 0.49)",
            });
        }
        let beta = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
        let eps = 3.0 * (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu));
        let x_max = 0.65 + 0.13 * ((nu - 0.3) / 0.1).clamp(0.0, 1.0);
        Ok(Self {
            c: C0 + C1 * beta,
            b2: (B * eps) * (B * eps),
            eps4: 0.25 * eps,
            x_max,
        })
    }

    /// The law with its compressible cap `B(nu)` scaled by `cap` in (0, 1]: on a curved
    /// counterpart the area it presses over the plane's, `rho_H` (`crate::cap_map`).
    pub(crate) fn try_new_capped(nu: f64, cap: f64) -> Result<Self> {
        let mut law = Self::try_new(nu)?;
        law.b2 *= cap;
        Ok(law)
    }

    /// `chi_cal(x)` (for the energy; the force and stiffness group its terms differently).
    fn chi(&self, x: f64) -> f64 {
        let w = 1.0 - x;
        let n = w + x * x * (1.0 / 3.0);
        let sf = w + self.c * x.sqrt() + E * x * x + F3 * x * x * x;
        n * sf / (w * w + self.b2 * x * x)
    }
}

impl NormalisedLaw for Calibrated {
    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        // f = (4/3) chi x^(3/2) and df/dx = (4/3) sqrt(x) (3/2 chi + x chi'), with the terms of
        // `chi` grouped so that everything that does not need sqrt(x) (the division included)
        // runs while the square root is computed:
        // 3/2 chi + x chi' = (N S (3/2 - x D'/D) + x N' S + N x S') / D.
        let s = x.sqrt();
        let w = 1.0 - x;
        let x2 = x * x;
        let n = w + x2 * (1.0 / 3.0);
        let xn = -x + 2.0 / 3.0 * x2;
        let inv = 1.0 / (w * w + self.b2 * x2);
        let q = 1.5 - (-2.0 * x * w + 2.0 * self.b2 * x2) * inv;
        let x3 = x2 * x;
        let sf = w + self.c * s + E * x2 + F3 * x3;
        let xs = -x + 0.5 * self.c * s + 2.0 * E * x2 + 3.0 * F3 * x3;
        let ns = n * sf;
        let si = 4.0 / 3.0 * s * inv;
        (si * x * ns, si * (ns * q + xn * sf + n * xs))
    }

    fn energy(&self, x: f64) -> f64 {
        // No closed form; in u = sqrt(x) the integrand (8/3) chi(u^2) u^4 is smooth (chi is a
        // rational function of u with no pole on [0, 1)), so 4 panels of 8-point
        // Gauss-Legendre reach 1e-14.
        integrate(0.0, x.sqrt(), 4, |u| {
            let s = u * u;
            8.0 / 3.0 * self.chi(s) * s * s
        })
    }

    fn radius(&self, x: f64) -> f64 {
        let w = 1.0 - x;
        let [g1, g3] = G;
        x.sqrt().atanh() * (1.0 + (g1 + g3 * x * x) * x) * w / (w + self.eps4 * x)
    }

    fn x_max(&self) -> f64 {
        self.x_max
    }

    fn pressure_shape(&self, x: f64) -> f64 {
        let [a0, a1, a2] = SHAPE;
        0.5 + (a0 + a1 * self.eps4 * 4.0) * x.sqrt() + a2 * x
    }
}
