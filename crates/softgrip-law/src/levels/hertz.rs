//! Hertz (small deformation, Eqs. 2 and 5): `F_H = (4/3) E* R^2 x^(3/2)`, `a_H = sqrt(R delta)`.

use super::Normalised;

/// Hertz's law. Valid (as mathematics) for `0 <= x <= 1`; as physics only for small `x`:
/// it is 30 % low at `x = 0.3` and half the force at `x = 0.5`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Hertz;

impl Normalised for Hertz {
    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        super::hertz(x)
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
