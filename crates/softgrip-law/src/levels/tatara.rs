//! Tatara's extended Hertz law for a finite sphere between two plates, a peer baseline.
//!
//! Source: Y. Tatara, "On compression of rubber elastic sphere over a large range of
//! displacements - Part 1: Theoretical study", ASME J. Eng. Mater. Technol. 113 (1991) 285-291,
//! in the one-contact form given in MODEL.md (half the plate approach):
//! `delta = (3F/(4 E* sqrt(R)))^(2/3) - (F/(pi E*)) [1/sqrt(a^2+4R^2) + 2R^2/((1-nu)(a^2+4R^2)^(3/2))]`,
//! `a = (3 F R/(4 E*))^(1/3)`. The bracket is the Boussinesq displacement of the load's axis at
//! the depth 2R of the other plate, `F (1+nu)(3-2nu)/(4 pi E R)` as `a -> 0`, which the
//! tests check. Normalised (`f = F/(E* R^2)`, `alpha = a/R = (3f/4)^(1/3)`):
//! `x(f) = alpha^2 - (f/pi) [ (alpha^2+4)^(-1/2) + 2/(1-nu) (alpha^2+4)^(-3/2) ]`.

use super::NormalisedLaw;
use crate::quadrature::integrate;
use crate::root::{Probe, Stop, newton_bracketed};

/// Tatara's law: explicit in the force, solved for the force at each call.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Tatara {
    /// `2 / (1 - nu)`.
    c: f64,
}

/// `(3/4)^(1/3)`: `alpha = C34 s` with `s = f^(1/3)`.
const C34: f64 = 0.908_560_296_416_069_8;

impl Tatara {
    pub(crate) fn new(nu: f64) -> Self {
        Self {
            c: 2.0 / (1.0 - nu),
        }
    }

    /// `x` and `dx/ds` at `s = f^(1/3)`.
    fn x_of_s(&self, s: f64) -> (f64, f64) {
        let alpha = C34 * s;
        let q = alpha * alpha + 4.0;
        let r = 1.0 / q.sqrt();
        let r3 = r * r * r;
        let bracket = r + self.c * r3;
        // d bracket / d alpha = -alpha q^(-3/2) - 3 c alpha q^(-5/2)
        let dbracket = -alpha * r3 - 3.0 * self.c * alpha * r3 * r * r;
        let f = s * s * s;
        let x = alpha * alpha - f / std::f64::consts::PI * bracket;
        let dx =
            2.0 * alpha * C34 - (3.0 * s * s * bracket + f * dbracket * C34) / std::f64::consts::PI;
        (x, dx)
    }

    /// `s = f^(1/3)` at compression `x`: Newton from Hertz's value, safeguarded by bisection.
    fn s_of_x(&self, x: f64) -> f64 {
        if x <= 0.0 {
            return 0.0;
        }
        // Hertz: x = alpha^2, and Tatara's force is above Hertz's: s >= sqrt(x)/C34.
        let mut lo = x.sqrt() / C34;
        let mut hi = 2.0 * lo;
        while self.x_of_s(hi).0 < x {
            lo = hi;
            hi *= 2.0;
        }
        let stop = Stop {
            step: 1e-15,
            width: None,
            max_iterations: 100,
        };
        newton_bracketed(lo, hi, lo, stop, |s| {
            let (xs, dx) = self.x_of_s(s);
            Probe {
                below_root: xs < x,
                step: (xs - x) / dx,
            }
        })
    }

    /// Normalised compression at normalised force `f` (the law's explicit direction).
    pub(crate) fn x_of_force(&self, f: f64) -> f64 {
        self.x_of_s(f.cbrt()).0
    }
}

impl NormalisedLaw for Tatara {
    // An iterative solve: a call costs nothing next to it, and keeping it out of line keeps
    // the callers' hot loops (`ContactLaw::response` is inlined) small.
    #[inline(never)]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        let s = self.s_of_x(x);
        if s == 0.0 {
            return (0.0, 0.0);
        }
        let (_, dx_ds) = self.x_of_s(s);
        // df/dx = (df/ds) / (dx/ds) = 3 s^2 / (dx/ds)
        (s * s * s, 3.0 * s * s / dx_ds)
    }

    fn energy(&self, x: f64) -> f64 {
        // w = int_0^x f dx = f x - int_0^f x(f') df', and with f' = s^3 the last integral is
        // int_0^S x(s) 3 s^2 ds, a smooth integrand.
        let s_end = self.s_of_x(x);
        let f = s_end * s_end * s_end;
        f * x - integrate(0.0, s_end, 2, |s| 3.0 * s * s * self.x_of_s(s).0)
    }

    fn radius(&self, x: f64) -> f64 {
        C34 * self.s_of_x(x)
    }

    fn x_max(&self) -> f64 {
        // Tatara's x(f) stays monotone far past x = 1 for 0 <= nu <= 0.5; the sphere's
        // geometry ends at x = 1 (the plates meet).
        1.0
    }
}
