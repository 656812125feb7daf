//! softgrip's calibrated level of a backed fingertip ([`Backing::Flat`], [`Backing::Core`]):
//! `F = chi(x, nu, t/R) F_H`, fitted to softgrip's own finite-element pipeline (`tools/fe/`,
//! data in `tests/data/fe/{flat,core}/`, CalculiX, axisymmetric neo-Hookean, R = 1 mm).
//!
//! ## Flat: a hemisphere bonded at its flat face
//!
//! ```text
//! chi_flat = N S / D
//!   N = 1 - x + x^2/3                          numerator of chi_IC (Eq. 36)
//!   S = 1 - d x + c(nu) sqrt(x) + e(nu) x^2    finite-thickness factor of the bonded base
//!   D = (1 - x)^2 + b^2 eps x^2                lateral-area pole, softened by compressibility
//!   c = c0 + c1 eps,  e = e0 + e1 eps,  eps = mu/kappa = 3 (1 - 2nu) / (2 (1 + nu))
//! ```
//!
//! - `c sqrt(x)` is the first-order correction of a contact on a body of finite depth bonded to a
//!   rigid base (Dimitriadis' `a/h` term, here h = R): FE gives 1.066 x Hertz at x = 0.01 for
//!   nu = 0.3 and 1.078 for nu >= 0.4, the incompressible body being the more constrained.
//! - `e x^2` is the bonded base restraining the lateral bulge at large x: at nu = 0.49 the
//!   hemisphere carries 1.3x the free sphere at x = 0.2 and 1.6x at 0.4; much less for a
//!   compressible body, which loses volume instead (`e` linear in eps).
//! - `D` is the free sphere's pole `(1 - x)^2` with a compressible softening linear in eps (the
//!   free sphere's is quadratic: its equator is free to expand).
//!
//! Constants: least squares on all four FE curves (nu = 0.3, 0.4, 0.48, 0.499, each for
//! 0.01 <= x <= its reach): c0 = 0.681614, c1 = -0.341872, e0 = 1.754842, e1 = -2.984330,
//! b = 0.791282, d = 0.329388. Residuals: within 0.95 % at every fitted nu; each nu held out
//! of the fit in turn: 1.31 % (0.4), 0.76 % (0.48), 0.75 % (0.499), i.e. within 2 % between the
//! fitted points (`cargo test -p softgrip-law --test backed`). Held out at nu = 0.3 (an
//! extrapolation below every fitted nu) it is 4.4 %: below nu = 0.3 the form is not validated.
//!
//! Poisson ratio: `0.3 <= nu <= 0.5` (an [`Error::IncompatibleLevel`] below: the FE data start
//! at 0.3 and the form extrapolated to nu = 0 is not monotone).
//!
//! Validity: `0 <= x <= x_max(nu)`, where the FE stops: 0.53 at nu <= 0.3 (the element volume
//! ratio falls below 0.2), 0.46 at 0.4 and 0.44 at nu >= 0.48 (the free surface folds over the
//! bonded edge), linear in between. At nu = 0.499 the FE solver stops at x = 0.31 (increment
//! below its minimum, no fold-over): the form there is validated to 0.31 only and follows the
//! nu = 0.48 curve it is within 1.5 % of.
//!
//! ## Core: a skin of thickness t over a rigid core
//!
//! PROVISIONAL (issue 10 is open): within 1.9 % of the FE for t/R >= 0.4 at nu = 0.3, 0.48,
//! 0.499, but 3.1-6.0 % at t/R = 0.2 (the thin, nearly incompressible skin).
//!
//! ```text
//! chi_core = chi_flat + phi (Dim(chi_t) - Dim(sqrt x)) (1 + lambda x/tau) chi_flat^(1 - k)
//!   tau = t/R, chi_t = sqrt(x)/tau         contact radius over skin thickness
//!   Dim(u) = Dimitriadis' bonded-layer series to third order in u (a/h of a layer of depth h)
//!   phi = rho^n / (rho^n + c), rho = (R - t)/t   how much of a layer the core is
//!   lambda = l0 + l1 eps,  k = k0 + k1 eps
//! ```
//!
//! - `Dim(chi_t) - Dim(sqrt x)`: the excess of a bonded layer of thickness t over one of depth
//!   R (which the flat law already carries). Dimitriadis' series alone is within 2 % of the
//!   FE for t/R = 0.2 up to x = 0.1 (chi_t = 1.6); its fourth-order term makes it worse.
//! - `phi`: the core is a sphere of radius R - t, not a plane: a thin skin (rho large) is a
//!   layer, a small deep core (rho small) barely matters; phi -> 0 as t -> R, so core -> flat.
//! - `1 + lambda x/tau`: the layer thins under the squeeze (x/tau = delta/t): a compressible
//!   skin stiffens, an incompressible one less so.
//! - `chi_flat^(1 - k)`: the large-deformation stiffening of the hemisphere and of the layer do
//!   not simply multiply (k ~ 1.8 incompressible, ~0 at nu = 0.3).
//!
//! n = 1.913237, c = 0.578666, l0 = 0.635466, l1 = -2.284206, k0 = 1.816930, k1 = -4.559464:
//! least squares on the 12 FE curves (t/R = 0.2, 0.4, 0.6, 0.8 at nu = 0.3, 0.48, 0.499) for
//! `0.01 <= x` and `delta/t <= 0.6`. Each t/R held out in turn: 1.8 % (0.6), 2.1 % (0.8), 3.7 %
//! (0.4), 6.2 % (0.2).
//!
//! Validity: `0 <= x <= min(x_max_flat, 0.6 t/R)`: the FE stops at delta/t = 0.65-0.7 (the layer
//! over the core's pole; at nu = 0.3 its elements approach volume collapse near 0.8).
//!
//! ## Radius
//!
//! ```text
//! a_flat = a_free (1 + (q0 + q1 eps) x + q2 x^2)
//! a_core = a_flat (1 + (s0 + s1 eps) rc^2 (u / (u + c)) / (1 + k x / rc)),  u = sqrt(x) / tau
//!   a_free = artanh(sqrt x) (1 + g1 x + g3 x^3) (1 - x) / (1 - x + eps x / 4)   (calibrated.rs)
//!   rc = 1 - tau = (R - t)/R, the core's radius
//! ```
//!
//! - `(q0 + q1 eps) x`: the bonded base pushes the material under the contact outwards (less
//!   so when compressible, which loses volume instead); `q2 x^2 < 0`: it holds back the bulge
//!   the free sphere's equator would make at large x.
//! - `u / (u + c)`: Hertz's radius over the skin's thickness, saturating: a patch on a bonded
//!   layer thinner than itself is wider than Hertz's (`a^2 -> 2 R delta` for a compressible thin
//!   layer, `4 R delta` incompressible), a thick skin is the flat hemisphere (u -> 0, and
//!   `rc^2 -> 0` as t -> R: how much of a layer the core is). `1 / (1 + k x / rc)`: the rigid core
//!   holds back the large-deformation expansion the hemisphere has (`x / rc = delta / (R - t)`).
//!
//! The FE radius the forms are fitted to is not the FE's radius column itself: that column
//! (`a_lin`, the last surface node on the plane, interpolated) moves in node steps, 1.0-1.9 %
//! rms about a smooth curve (up to 5 %), and lags the edge by about half an element face (the
//! contact is resolved per quadratic face). The estimate used is per curve `a_lin` smoothed
//! (`a/sqrt(x)` least squares in powers of `sqrt(x)`) plus half the element edge, 0.485 R/N on a
//! mesh R/N. Re-runs on R/80 and R/120 (`tests/data/fe/{flat,core}/radius_mesh_*.csv`) show
//! `a_lin` converging at first order in the element, and the R/40 estimate within 0.71 % of the
//! fine-mesh limit (the smoothed columns alone move by 0.7-2.4 % from R/40 to R/120).
//!
//! Constants (`tools/calibration/fit_radius_pressure.py`, least squares on the fitted cases,
//! 0.05 <= x <= min(reach, 0.45)): q0 = 0.648666, q1 = -0.706160, q2 = -0.954134 (flat nu =
//! 0.3, 0.4, 0.48, 0.499); s0 = 0.791275, s1 = -0.508830, c = 0.351075, k = 2.361401 (the 12
//! core curves). Residuals for 0.1 <= x <= min(0.4, x_max) against that FE radius
//! (`cargo test -p softgrip-law --test radius_pressure`): flat within 1.37 % (held out: 1.15 %
//! at nu = 0.35, 1.16 % at 0.45); core within 2.04 % (held out: 0.91 % at (nu, t/R) = (0.4,
//! 0.3), 1.53 % (0.49, 0.3), 1.33 % (0.45, 0.5), 0.73 % (0.35, 0.7)). Against the raw column its
//! step noise and lag add up to 7.5 %. Before: 4.4 % (flat) and 6.4 % (core) off the raw
//! column, 4.3 % and 8.0 % off the estimate.
//!
//! ## Pressure
//!
//! `p = p0 (1 - r^2/a^2)^m` ([`crate::ContactPatch`], force-conserving) with
//!
//! ```text
//! m_flat = 1/2 + (a0 + a1 eps) sqrt(x) + a2 x + a3 x^2
//! m_core = m_flat + (2 - b eps - m_flat) v,  v = z^n / (z^n + cm^n),  z = x^alpha / (tau - x)
//! ```
//!
//! - `m_flat`: Hertz's ellipse at x -> 0; the patch of a bonded hemisphere is flatter than
//!   Hertz's at moderate x, fuller at large x.
//! - `m_core`: a thin bonded incompressible layer squeezed by a sphere carries
//!   `p ~ (1 - r^2/a^2)^2` (the squeeze film of a layer whose material can only flow outwards); a
//!   compressible one less so (`- b eps`; a thin Winkler-like layer would be m = 1, but over the
//!   data's nu >= 0.3 the fit keeps b small, 0.12); `v` is how much of such a layer the skin is: the patch against the layer that is left over the
//!   core's pole, `tau - x = (t - delta)/R`, with `x^alpha` between the radius over the layer
//!   (alpha = 1/2) and the layer's squeeze (alpha = 1). v -> 0 for a thick skin (core -> flat).
//!
//! Constants: a0 = -0.399773, a1 = 0.189139, a2 = 1.031300, a3 = -0.688498; b = 0.095467,
//! n = 2.285182, cm = 3.668819, alpha = 0.530249 (`tools/calibration/fit_radius_pressure.py`):
//! per FE profile (`pressure_*.csv` at x = 0.1, 0.3, 0.5 where reached) the exponent that best
//! matches it over r <= 0.8 a with the FE's own force and the law's radius, then least squares
//! of `(m + 1)/(m_best + 1)` (the peak is m + 1 times the mean) on the fitted cases (flat nu =
//! 0.3, 0.4, 0.48, 0.499; the 12 core curves inside the validity x <= 0.6 t/R).
//!
//! Residuals as fractions of FE's peak, peak / profile over r <= 0.8 a, inside the validity
//! (`cargo test -p softgrip-law --test radius_pressure` asserts each profile), with the FE's
//! force (the shape and radius alone) and [with the law's force]:
//! - flat: 3.1 % / 4.8 % [3.0 % / 4.7 %]; held out (nu 0.35, 0.45): 2.5 % / 2.6 % [2.8 % / 2.9 %];
//! - core: 7.1 % / 7.3 % (nu 0.48, t/R 0.6, x 0.3) [7.7 % / 7.9 %], within 5 % / 5.6 % on 15 of
//!   the 17 fitted profiles; held out: 1.4 % / 2.5 % at (nu, t/R) = (0.35, 0.7), 2.9 % / 3.3 %
//!   at (0.45, 0.5) x 0.1 but 10.1 % / 10.4 % at its x = 0.3 (the validity's edge), 7.7-8.3 % /
//!   8.2-8.7 % at t/R = 0.3 (x 0.1: the FE's patch is fuller, m = 0.75-0.77, than the form's
//!   0.64-0.65) [10.9 % / 11.1 % at most].
//!
//! The core misses the 5 % target there: the form's m is 0.07-0.12 short of the best exponent
//! (and even the best leaves 5.0 % and 5.5 % profile error at nu 0.3 t/R 0.6 x 0.3 and the
//! held-out (0.45, 0.5) x 0.3: the family `(1 - r^2/a^2)^m` over the law's radius cannot follow
//! those patches closer). Past the core's validity the FE's profiles are 11-17 % off.
//! Before this fit the core took flat's shape: 1-43 % off FE's peak.

use super::NormalisedLaw;
use super::dual::Dual;
use crate::backing::Backing;
use crate::error::{Error, Result};
use crate::level::LevelKind;
use crate::quadrature::integrate;

/// Flat: c0, c1, e0, e1, b, d.
const FLAT: [f64; 6] = [0.681614, -0.341872, 1.754842, -2.984330, 0.791282, 0.329388];
/// Core: n, c (how much of a layer the core is), l0, l1 (the layer's thinning), k0, k1.
const CORE: [f64; 6] = [1.913237, 0.578666, 0.635466, -2.284206, 1.816930, -4.559464];
/// The core's validity: the skin over the core's pole squeezed by at most this fraction of t.
const CORE_SQUEEZE: f64 = 0.6;
/// Flat radius: q0, q1, q2 of `a_flat = a_free (1 + (q0 + q1 eps) x + q2 x^2)`.
const RADIUS: [f64; 3] = [0.648666, -0.706160, -0.954134];
/// Core radius: s0, s1, c, k of `a_core = a_flat (1 + (s0 + s1 eps) rc^2 (u / (u + c)) / (1 + k x / rc))`,
/// `u = sqrt(x) / tau`.
const RADIUS_CORE: [f64; 4] = [0.791275, -0.508830, 0.351075, 2.361401];
/// Flat pressure shape: a0, a1, a2, a3 of `m = 1/2 + (a0 + a1 eps) sqrt(x) + a2 x + a3 x^2`.
const SHAPE: [f64; 4] = [-0.399773, 0.189139, 1.031300, -0.688498];
/// Core pressure shape: b, n, cm, alpha of `m = m_flat + (2 - b eps - m_flat) v`,
/// `v = z^n / (z^n + cm^n)`, `z = x^alpha / (tau - x)`.
const SHAPE_CORE: [f64; 4] = [0.095467, 2.285182, 3.668819, 0.530249];
/// Free sphere's radius excess `1 + g1 x + g3 x^3` (as `calibrated.rs`).
const G: [f64; 2] = [0.042222, 0.109823];

/// The calibrated level of one backed construction at one Poisson ratio.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Backed {
    c: f64,
    d: f64,
    e: f64,
    b2: f64,
    /// Core only (else `phi = 0`): `phi(Rc/t)`.
    phi: f64,
    /// `1 - k(nu)`, the power of `chi_flat` the layer excess scales with.
    one_minus_k: f64,
    /// `lambda(nu) / (t/R)`: the layer's thinning factor is `1 + lambda x/(t/R)`.
    thinning: f64,
    /// Dimitriadis' series coefficients of chi_t, chi_t^2, chi_t^3.
    dim: [f64; 3],
    /// `1 / (t/R)` (core), 0 for flat.
    inv_tau: f64,
    eps4: f64,
    /// Radius: `q0 + q1 eps`, the flat base's linear restraint.
    rad_x: f64,
    /// Radius: `(s0 + s1 eps) rc^2`, the core's layer excess at saturation (0 for flat).
    rad_core: f64,
    /// Radius: `k / rc`, the rigid core holding back the large-x expansion (core).
    rad_thick: f64,
    /// Shape: `2 - b eps`, the thin bonded layer's exponent.
    shape_layer: f64,
    /// Shape: `tau = t/R` (core), 0 for flat.
    tau: f64,
    x_max: f64,
}

/// `x_max` of a flat-backed hemisphere at `nu`: where the FE stops.
fn flat_x_max(nu: f64) -> f64 {
    const KNOTS: [(f64, f64); 3] = [(0.3, 0.53), (0.4, 0.46), (0.48, 0.44)];
    if nu <= KNOTS[0].0 {
        return KNOTS[0].1;
    }
    for w in KNOTS.windows(2) {
        let ((n0, x0), (n1, x1)) = (w[0], w[1]);
        if nu <= n1 {
            return x0 + (x1 - x0) * (nu - n0) / (n1 - n0);
        }
    }
    KNOTS[2].1
}

impl Backed {
    /// `backing` is `Flat` or `Core` (with `tau = t/R` in (0, 1)), `0.3 <= nu <= 0.5`.
    pub(crate) fn try_new(backing: Backing, tau: Option<f64>, nu: f64) -> Result<Self> {
        if !(0.3..=0.5).contains(&nu) {
            return Err(Error::IncompatibleLevel {
                level: LevelKind::Calibrated,
                nu,
                reason: "the calibrated level of a backed fingertip is fitted and validated for 0.3 <= nu <= 0.5 (below, its form is not monotone at nu = 0); use a `tabulated` curve of your fingertip",
            });
        }
        let eps = 3.0 * (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu));
        let [c0, c1, e0, e1, b, d] = FLAT;
        let pi = std::f64::consts::PI;
        let a0 = -(1.2876 - 1.4678 * nu + 1.3442 * nu * nu) / (1.0 - nu);
        let b0 = (0.6387 - 1.0277 * nu + 1.5164 * nu * nu) / (1.0 - nu);
        let dim = [
            -2.0 * a0 / pi,
            4.0 * a0 * a0 / (pi * pi),
            -8.0 / (pi * pi * pi) * (a0 * a0 * a0 + 4.0 * pi * pi * b0 / 15.0),
        ];
        let [n, c, l0, l1, k0, k1] = CORE;
        let [q0, q1, _] = RADIUS;
        let [s0, s1, _, k_thick] = RADIUS_CORE;
        let (phi, inv_tau, rc, x_max) = match (backing, tau) {
            (Backing::Core { .. }, Some(tau)) => {
                let rc = 1.0 - tau;
                let rho = (rc / tau).powf(n);
                (
                    rho / (rho + c),
                    1.0 / tau,
                    rc,
                    flat_x_max(nu).min(CORE_SQUEEZE * tau),
                )
            }
            _ => (0.0, 0.0, 0.0, flat_x_max(nu)),
        };
        Ok(Self {
            c: c0 + c1 * eps,
            d,
            e: e0 + e1 * eps,
            b2: b * b * eps,
            phi,
            one_minus_k: 1.0 - (k0 + k1 * eps),
            thinning: (l0 + l1 * eps) * inv_tau,
            dim,
            inv_tau,
            eps4: 0.25 * eps,
            rad_x: q0 + q1 * eps,
            rad_core: (s0 + s1 * eps) * rc * rc,
            rad_thick: if rc > 0.0 { k_thick / rc } else { 0.0 },
            shape_layer: 2.0 - SHAPE_CORE[0] * eps,
            tau: if inv_tau > 0.0 { 1.0 / inv_tau } else { 0.0 },
            x_max,
        })
    }

    /// `chi` and `x chi'` at `x > 0`.
    #[inline(always)]
    fn chi(&self, x0: f64) -> Dual {
        let x = Dual::var(x0);
        let w = 1.0 - x;
        let x2 = x * x;
        let n = w + x2.scale(1.0 / 3.0);
        let s = Dual::sqrt_of_var(x0);
        let sf = Dual::c(1.0) - x.scale(self.d) + s.scale(self.c) + x2.scale(self.e);
        let den = w * w + x2.scale(self.b2);
        let flat = n * sf / den;
        if self.phi == 0.0 {
            return flat;
        }
        // The layer excess Dim(chi_t) - Dim(sqrt x): a layer of thickness t over a layer of the
        // hemisphere's depth R (which chi_flat already carries); Dim(u) - 1 = u (d1 + u (d2 + d3 u)).
        let [d1, d2, d3] = self.dim;
        let dim_excess = |u: Dual| u * ((u.scale(d3) + d2) * u + d1);
        let excess = dim_excess(s.scale(self.inv_tau)) - dim_excess(s);
        let thinning = Dual::c(1.0) + x.scale(self.thinning);
        flat + (excess * thinning).scale(self.phi) * flat.powf(self.one_minus_k)
    }
}

impl NormalisedLaw for Backed {
    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        // f = (4/3) chi x sqrt(x), df/dx = (4/3) sqrt(x) (3/2 chi + x chi').
        let chi = self.chi(x);
        let s = x.sqrt();
        let h = 4.0 / 3.0 * s;
        (h * chi.v * x, h * (1.5 * chi.v + chi.d))
    }

    fn energy(&self, x: f64) -> f64 {
        // In u = sqrt(x) the integrand (8/3) chi(u^2) u^4 is smooth (chi is a function of u with
        // no pole on [0, x_max]).
        integrate(0.0, x.sqrt(), 4, |u| {
            let s = u * u;
            8.0 / 3.0 * self.chi(s).v * s * s
        })
    }

    fn radius(&self, x: f64) -> f64 {
        let w = 1.0 - x;
        let s = x.sqrt();
        let [g1, g3] = G;
        let free = s.atanh() * (1.0 + (g1 + g3 * x * x) * x) * w / (w + self.eps4 * x);
        let flat = free * (1.0 + (self.rad_x + RADIUS[2] * x) * x);
        if self.rad_core == 0.0 {
            return flat;
        }
        // u = a_H / t: Hertz's radius over the skin's thickness; the layer's widening saturates
        // in u and is held back by the rigid core as the squeeze grows.
        let u = s * self.inv_tau;
        flat * (1.0 + self.rad_core * u / ((u + RADIUS_CORE[2]) * (1.0 + self.rad_thick * x)))
    }

    fn x_max(&self) -> f64 {
        self.x_max
    }

    fn pressure_shape(&self, x: f64) -> f64 {
        let [a0, a1, a2, a3] = SHAPE;
        let flat = 0.5 + (a0 + a1 * self.eps4 * 4.0) * x.sqrt() + (a2 + a3 * x) * x;
        if self.tau == 0.0 || x <= 0.0 {
            return flat;
        }
        // z = x^alpha / (tau - x): the patch against the layer left over the core's pole; the
        // layer's share v -> 1 (a thin bonded layer, m -> 2 - b eps) as the layer thins.
        let [_, n, cm, alpha] = SHAPE_CORE;
        let v = if x >= self.tau {
            1.0
        } else {
            let zn = (x.powf(alpha) / (self.tau - x) / cm).powf(n);
            zn / (zn + 1.0)
        };
        flat + (self.shape_layer - flat) * v
    }
}
