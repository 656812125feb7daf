//! Hertz (small deformation, Eqs. 2 and 5): `F_H = (4/3) E* R^2 x^(3/2)`, `a_H = sqrt(R delta)`.

use super::NormalisedLaw;

/// Hertz's law. Valid (as mathematics) for `0 <= x <= 1`; as physics only for small `x`:
/// it is 30 % low at `x = 0.3` and half the force at `x = 0.5`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Hertz;

/// Hertz's normalised force `(4/3) x^(3/2)` and its derivative `2 x^(1/2)` (Eq. 5).
#[inline]
pub(crate) fn hertz(x: f64) -> (f64, f64) {
    let s = x.sqrt();
    (4.0 / 3.0 * x * s, 2.0 * s)
}

/// `F = chi F_H` in normalised form, with `df/dx = chi' f_H + chi f_H'`.
#[inline]
pub(crate) fn scale_by_chi(x: f64, chi: f64, dchi: f64) -> (f64, f64) {
    let (f_h, df_h) = hertz(x);
    (chi * f_h, dchi * f_h + chi * df_h)
}

impl NormalisedLaw for Hertz {
    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        hertz(x)
    }

    fn energy(&self, x: f64) -> f64 {
        // integral of (4/3) s^(3/2) ds = (8/15) x^(5/2)
        8.0 / 15.0 * x * x * x.sqrt()
    }

    fn radius(&self, x: f64) -> f64 {
        x.sqrt()
    }

    fn x_max(&self) -> f64 {
        1.0
    }
}
