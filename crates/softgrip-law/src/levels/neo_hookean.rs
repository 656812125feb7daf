//! Full compressible neo-Hookean theory (Eqs. 23, 25, 32, 33 as corrected in MODEL.md), solved
//! exactly per call.
//!
//! `chi_NH(x, nu) = T(1 - x) / (-E x)`, where `T` is the nominal axial stress of a bar in
//! uniaxial compression with free sides, stretch `lam = 1 - x`, volume ratio `J`:
//! - `mu (J - lam^3) + 3 kappa J^(5/3) lam (J - 1) = 0` (Eq. 33),
//! - `T = (2/3) mu J^(-2/3) (lam - J/lam^2) + kappa J (J - 1) / lam` (Eq. 32 with the factor
//!   `J^(-2/3)` that the print lacks).

use super::{NormalisedLaw, scale_by_chi};
use crate::quadrature::integrate;
use crate::root::{Probe, Stop, newton_bracketed};

/// The uniaxial compression of a compressible neo-Hookean bar, in the unknown `j = J - 1`.
///
/// Substituting Eq. 33 into the corrected Eq. 32 gives `lam - J/lam^2 = 3 kappa J^(5/3) (J-1)/(mu lam)`,
/// so at equilibrium `T = 3 kappa J (J - 1) / lam`. With `E = 3 kappa (1 - 2 nu)`:
/// `chi = -(1 + j) j / ((1 - 2 nu)(1 - x) x)`. Working in `j` (small, of order `x`) instead of
/// `J` keeps full relative precision at small `x`, where `T` itself is a difference of
/// nearly equal numbers.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Uniaxial {
    /// `m = mu / kappa = 3 (1 - 2 nu) / (2 (1 + nu))`.
    m: f64,
    /// `q = 1 - 2 nu`.
    q: f64,
    /// `chi'(0)`, from the series `j = a1 x + a2 x^2 + ...`, used below `X_SERIES`.
    dchi0: f64,
}

/// Below this compression ratio `chi` is its first-order series (error ~ x^2 ~ 1e-14).
const X_SERIES: f64 = 1e-7;

impl Uniaxial {
    /// `nu` in (-1, 0.5): checked by the caller.
    pub(crate) fn new(nu: f64) -> Self {
        let q = 1.0 - 2.0 * nu;
        let m = 3.0 * q / (2.0 * (1.0 + nu));
        // Eq. 33 divided by kappa, G(j, x) = m (j + 3x - 3x^2 + x^3) + 3 (1+j)^(5/3) (1-x) j,
        // to second order in x: a1 = -3m/(m+3), a2 = (3m - 5 a1^2 + 3 a1)/(m+3), and
        // chi = -(a1 + (a2 + a1^2 + a1) x)/q + O(x^2), so chi(0) = 1 and chi'(0) as below.
        let a1 = -3.0 * m / (m + 3.0);
        let a2 = (3.0 * m - 5.0 * a1 * a1 + 3.0 * a1) / (m + 3.0);
        Self {
            m,
            q,
            dchi0: -(a2 + a1 * a1 + a1) / q,
        }
    }

    /// `j = J - 1` at compression ratio `x` in (0, 1), on the branch that starts at `j = 0`.
    ///
    /// That branch is the largest root of `G(j) = 0` in `(-1, 0)`: `G(0) = m x (3 - 3x + x^2) > 0`
    /// and `G(-1) = -m (1-x)^3 < 0`, but for `nu` near 0.45 and large `x` two more roots (the
    /// collapsed states) sit below it, and a plain Newton iteration can land there (the property
    /// tests caught it at nu = 0.452, x = 0.9). So first bracket the largest root by stepping
    /// down from half the linear solution by factors of 1.25 until `G < 0`, then run Newton
    /// safeguarded by bisection inside that bracket.
    pub(crate) fn volume_change(&self, x: f64) -> f64 {
        let m = self.m;
        let c = x * (3.0 - 3.0 * x + x * x);
        let w = 1.0 - x;
        let g_of = |j: f64| {
            let cb = (1.0 + j).cbrt();
            m * (j + c) + 3.0 * (1.0 + j) * cb * cb * w * j
        };
        let j_lin = -3.0 * m * x / (m + 3.0);
        if x < X_SERIES {
            // The series (relative error O(x)). Below it the bracket search could start at a
            // probe that underflows to 0 and never moves (the law fuzz target hung there).
            return j_lin;
        }
        let (mut lo, mut hi) = (-1.0_f64, 0.0_f64);
        let mut probe = 0.5 * j_lin;
        while probe > -1.0 {
            if g_of(probe) > 0.0 {
                hi = probe;
                probe *= 1.25;
            } else {
                lo = probe;
                break;
            }
        }
        // Newton on G, safeguarded in the bracket: G > 0 above the root.
        let stop = Stop {
            step: 1e-15,
            width: Some(1e-16),
            max_iterations: 100,
        };
        newton_bracketed(lo, hi, 0.5 * (lo + hi), stop, |j| {
            let cb = (1.0 + j).cbrt();
            let p23 = cb * cb;
            let g = m * (j + c) + 3.0 * (1.0 + j) * p23 * w * j;
            let dg = m + 3.0 * w * p23 * (1.0 + 8.0 / 3.0 * j);
            Probe {
                below_root: g <= 0.0 || g.is_nan(),
                step: g / dg,
            }
        })
    }

    /// `chi(x)` and `chi'(x)`.
    pub(crate) fn chi(&self, x: f64) -> (f64, f64) {
        if x < X_SERIES {
            return (1.0 + self.dchi0 * x, self.dchi0);
        }
        let j = self.volume_change(x);
        self.chi_from_j(x, j)
    }

    /// `chi` and `chi'` given the solved `j` at `x`, by implicit differentiation of `G`.
    pub(crate) fn chi_from_j(&self, x: f64, j: f64) -> (f64, f64) {
        let (m, q) = (self.m, self.q);
        let w = 1.0 - x;
        let cb = (1.0 + j).cbrt();
        let p23 = cb * cb;
        let p53 = (1.0 + j) * p23;
        // dj/dx = -G_x / G_j
        let g_j = m + 3.0 * w * p23 * (1.0 + 8.0 / 3.0 * j);
        let g_x = m * (3.0 - 6.0 * x + 3.0 * x * x) - 3.0 * p53 * j;
        let dj = -g_x / g_j;
        // chi = -N / (q D), N = (1+j) j, D = (1-x) x
        let n = (1.0 + j) * j;
        let dn = (1.0 + 2.0 * j) * dj;
        let d = w * x;
        let dd = 1.0 - 2.0 * x;
        let chi = -n / (q * d);
        let dchi = -(dn * d - n * dd) / (q * d * d);
        (chi, dchi)
    }

    /// `chi'(0)`.
    pub(crate) fn dchi0(&self) -> f64 {
        self.dchi0
    }

    /// Normalised radius of Eq. 25: `a/R = int_0^sqrt(x) sqrt(J(lam)/lam) dt`,
    /// `lam = 1 - x + t^2`, where `J(lam)` is the uniaxial volume ratio at compression `1 - lam`.
    pub(crate) fn radius(&self, x: f64) -> f64 {
        if x <= 0.0 {
            return 0.0;
        }
        integrate(0.0, x.sqrt(), 2, |t| {
            let lam = 1.0 - x + t * t;
            let xc = x - t * t;
            let j = if xc > 0.0 {
                self.volume_change(xc)
            } else {
                0.0
            };
            ((1.0 + j) / lam).sqrt()
        })
    }

    /// `|T| / (3 kappa) = (1 + j)(-j) / (1 - x)` at `x`.
    fn stress(&self, x: f64) -> f64 {
        let j = self.volume_change(x);
        -(1.0 + j) * j / (1.0 - x)
    }

    /// The limit point: the compression ratio where `|T|` stops growing, capped at `cap`.
    ///
    /// Scanned at steps of 1/200 and refined by bisection. A point counts as past the limit
    /// point if `|T|` decreases there, or if `|T|` is below its value at the last good point:
    /// for nu near 0.45 the branch folds (volume collapse) a few 1e-4 after the peak, and past
    /// the fold the solver can only return the collapsed state, whose `|T|` is much lower.
    pub(crate) fn limit_point(&self, cap: f64) -> f64 {
        // d/dx [-(1+j) j / (1-x)] has the sign of -[(1 + 2j) j' (1-x) + (1+j) j].
        let rising = |x: f64| {
            let j = self.volume_change(x);
            let (m, w) = (self.m, 1.0 - x);
            let cb = (1.0 + j).cbrt();
            let g_j = m + 3.0 * w * cb * cb * (1.0 + 8.0 / 3.0 * j);
            let g_x = m * (3.0 - 6.0 * x + 3.0 * x * x) - 3.0 * (1.0 + j) * cb * cb * j;
            let dj = -g_x / g_j;
            -((1.0 + 2.0 * j) * dj * w + (1.0 + j) * j) > 0.0
        };
        let step = 1.0 / 200.0;
        let mut x = step;
        while x + step <= cap {
            let next = x + step;
            if !rising(next) || self.stress(next) < self.stress(x) {
                let (mut lo, mut hi) = (x, next);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if rising(mid) && self.stress(mid) >= self.stress(lo) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                return lo;
            }
            x = next;
        }
        cap
    }

    /// End of the validity range: the largest stiffness `K = f'(x)` on `[0, limit point]`.
    ///
    /// Between it and the limit point the law already softens (at nu = 0.35 `K` falls by a
    /// factor of 6 in the last 0.02 of x) as the bar approaches its limit point and, for nu
    /// near 0.45, its volume collapse; no contact law may soften, so the range ends where `K`
    /// peaks and the extension continues with that (largest) stiffness. Where `K` still grows
    /// at the cap (nu close to 0.5), that is the cap.
    pub(crate) fn stiffness_peak(&self, limit_point: f64) -> f64 {
        let k = |x: f64| {
            let (chi, dchi) = self.chi(x);
            scale_by_chi(x, chi, dchi).1
        };
        let step = 1.0 / 1000.0;
        let mut best = (k(limit_point), limit_point);
        let mut x = 0.1;
        while x < limit_point {
            let kx = k(x);
            if kx > best.0 {
                best = (kx, x);
            }
            x += step;
        }
        if best.1 == limit_point {
            return limit_point;
        }
        // Golden-section refinement around the best grid point.
        let (mut a, mut b) = ((best.1 - step).max(0.1), (best.1 + step).min(limit_point));
        let g = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..40 {
            let (c, d) = (b - g * (b - a), a + g * (b - a));
            if k(c) > k(d) {
                b = d;
            } else {
                a = c;
            }
        }
        0.5 * (a + b)
    }
}

/// Largest compression ratio any full-theory level accepts, even without a limit point.
pub(crate) const NH_CAP: f64 = 0.9;

/// The full theory, solved exactly (Newton) at every call.
#[derive(Debug, Clone, Copy)]
pub(crate) struct NeoHookeanExact {
    pub(crate) uniaxial: Uniaxial,
    x_max: f64,
}

impl NeoHookeanExact {
    /// `nu` in (-1, 0.5): checked by the caller.
    pub(crate) fn new(nu: f64) -> Self {
        let uniaxial = Uniaxial::new(nu);
        let limit_point = uniaxial.limit_point(NH_CAP);
        Self {
            uniaxial,
            x_max: uniaxial.stiffness_peak(limit_point),
        }
    }
}

impl NormalisedLaw for NeoHookeanExact {
    // An iterative solve: a call costs nothing next to it, and keeping it out of line keeps
    // the callers' hot loops (`ContactLaw::response` is inlined) small.
    #[inline(never)]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        let (chi, dchi) = self.uniaxial.chi(x);
        scale_by_chi(x, chi, dchi)
    }

    fn energy(&self, x: f64) -> f64 {
        // w = int_0^x chi(s) (4/3) s^(3/2) ds; with s = u^2 the integrand (8/3) chi(u^2) u^4
        // is smooth, so Gauss-Legendre converges fast; 16 panels of 8 points resolve the steep
        // softening just before the limit point to 1e-9.
        integrate(0.0, x.sqrt(), 16, |u| {
            let s = u * u;
            8.0 / 3.0 * self.uniaxial.chi(s).0 * s * s
        })
    }

    fn radius(&self, x: f64) -> f64 {
        self.uniaxial.radius(x)
    }

    fn x_max(&self) -> f64 {
        self.x_max
    }
}

/// The limit point of the compressible neo-Hookean theory at Poisson ratio `nu`: the
/// compression ratio where the uniaxial stress `T` stops growing (MODEL.md), capped at 0.9.
///
/// The full-theory levels end their validity range a little before it, where their stiffness
/// peaks ([`crate::ContactLaw::x_max`]).
///
/// ```
/// let x = softgrip_law::neo_hookean_limit_point(0.3).unwrap();
/// assert!((x - 0.5955).abs() < 1e-3);
/// assert!(softgrip_law::neo_hookean_limit_point(0.5).is_err());
/// ```
pub fn neo_hookean_limit_point(nu: f64) -> crate::Result<f64> {
    if !(nu.is_finite() && nu > -1.0 && nu < 0.5) {
        return Err(crate::Error::InvalidParameter {
            field: "poisson_ratio",
            value: nu,
            range: "finite and in (-1, 0.5) for the compressible theory",
        });
    }
    Ok(Uniaxial::new(nu).limit_point(NH_CAP))
}
