//! Exact incompressible neo-Hookean law (Eq. 36) and radius (Eq. 26):
//! `chi_IC = (1 - x + x^2/3) / (1 - x)^2`, `a_IC = R artanh(sqrt(x))`.

use super::{NormalisedLaw, scale_by_chi};

/// The incompressible (`nu = 0.5`) limit of the full theory. Singular at `x = 1`; valid for
/// `0 <= x <= 0.9` (where `chi = 37`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Incompressible;

/// `chi_IC` and its derivative. With `w = 1 - x` the numerator is `(1 + w + w^2)/3`, so
/// `chi_IC = (1 + 1/w + 1/w^2) / 3` and `chi_IC' = (1/w^2 + 2/w^3) / 3`.
#[inline]
pub(crate) fn chi_ic(x: f64) -> (f64, f64) {
    let r = 1.0 / (1.0 - x);
    let r2 = r * r;
    // Multiply by 1/3 (folded at compile time): a division by 3 would be a second division.
    const THIRD: f64 = 1.0 / 3.0;
    ((1.0 + r + r2) * THIRD, (r2 + 2.0 * r2 * r) * THIRD)
}

/// Incompressible contact radius `a/R = artanh(sqrt(x))` (Eq. 26).
#[inline]
pub(crate) fn radius_ic(x: f64) -> f64 {
    x.sqrt().atanh()
}

impl NormalisedLaw for Incompressible {
    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        let (chi, dchi) = chi_ic(x);
        scale_by_chi(x, chi, dchi)
    }

    fn energy(&self, x: f64) -> f64 {
        if x < 0.25 {
            // chi_IC = 1 + sum_{n>=1} (n + 2)/3 x^n, so w = (4/3) sum c_n x^(n+5/2)/(n+5/2).
            let mut pow = x * x * x.sqrt();
            let mut sum = pow / 2.5;
            for n in 1..40 {
                pow *= x;
                sum += (n as f64 + 2.0) / 3.0 * pow / (n as f64 + 2.5);
            }
            4.0 / 3.0 * sum
        } else {
            // With s = t^2 and u = sqrt(x): (4/3)(1/3) int 2 t^4 [1 + 1/(1-t^2) + 1/(1-t^2)^2] dt
            // = (4/9) [2u^5/5 - 2u^3/3 + u/(1 - u^2) - artanh(u)].
            let u = x.sqrt();
            let u2 = u * u;
            4.0 / 9.0 * (0.4 * u2 * u2 * u - 2.0 / 3.0 * u2 * u + u / (1.0 - u2) - u.atanh())
        }
    }

    fn radius(&self, x: f64) -> f64 {
        radius_ic(x)
    }

    fn x_max(&self) -> f64 {
        0.9
    }
}
