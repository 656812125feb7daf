//! Forward-mode dual numbers carrying a value and its *scaled* derivative `x dv/dx`: a law
//! written once as a function of `x` gives its exact derivative alongside its value, so the
//! stiffness is the derivative of the force by construction. Scaled by `x` so that `sqrt(x)`
//! costs no division (`x d sqrt(x)/dx = sqrt(x)/2`): a level built on
//! it needs one square root and one division per division in its form, like the hand-grouped
//! `calibrated`. Hand-written (a few lines) so that everything inlines into the hot path
//! (`cargo bench -p softgrip-law` times the levels that use it).

use std::ops::{Add, Div, Mul, Sub};

/// A value `v` and its scaled derivative `d = x dv/dx`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Dual {
    pub(crate) v: f64,
    pub(crate) d: f64,
}

impl Dual {
    /// The variable itself: `x dx/dx = x`.
    #[inline(always)]
    pub(crate) fn var(x: f64) -> Self {
        Self { v: x, d: x }
    }

    /// `sqrt(x)` of the variable `x > 0`: `x d sqrt(x)/dx = sqrt(x)/2`, no division.
    #[inline(always)]
    pub(crate) fn sqrt_of_var(x: f64) -> Self {
        let s = x.sqrt();
        Self { v: s, d: 0.5 * s }
    }

    /// A constant.
    #[inline(always)]
    pub(crate) fn c(v: f64) -> Self {
        Self { v, d: 0.0 }
    }

    /// `self * k` for a constant `k`.
    #[inline(always)]
    pub(crate) fn scale(self, k: f64) -> Self {
        Self {
            v: self.v * k,
            d: self.d * k,
        }
    }
}

impl Add for Dual {
    type Output = Dual;
    #[inline(always)]
    fn add(self, o: Dual) -> Dual {
        Dual {
            v: self.v + o.v,
            d: self.d + o.d,
        }
    }
}

impl Sub for Dual {
    type Output = Dual;
    #[inline(always)]
    fn sub(self, o: Dual) -> Dual {
        Dual {
            v: self.v - o.v,
            d: self.d - o.d,
        }
    }
}

impl Mul for Dual {
    type Output = Dual;
    #[inline(always)]
    fn mul(self, o: Dual) -> Dual {
        Dual {
            v: self.v * o.v,
            d: self.d * o.v + self.v * o.d,
        }
    }
}

impl Div for Dual {
    type Output = Dual;
    #[inline(always)]
    fn div(self, o: Dual) -> Dual {
        let r = 1.0 / o.v;
        let v = self.v * r;
        Dual {
            v,
            d: (self.d - v * o.d) * r,
        }
    }
}

impl Add<f64> for Dual {
    type Output = Dual;
    #[inline(always)]
    fn add(self, o: f64) -> Dual {
        Dual {
            v: self.v + o,
            d: self.d,
        }
    }
}

impl Sub<Dual> for f64 {
    type Output = Dual;
    #[inline(always)]
    fn sub(self, o: Dual) -> Dual {
        Dual {
            v: self - o.v,
            d: -o.d,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Dual;

    #[test]
    fn scaled_derivative_of_a_rational_function_with_a_root() {
        // f = (1 + 2 sqrt(x)) / (1 - x)^2 * x^2 at x = 0.3: x f'(x) by hand.
        let x0 = 0.3f64;
        let x = Dual::var(x0);
        let w = 1.0 - x;
        let f = (Dual::c(1.0) + Dual::sqrt_of_var(x0).scale(2.0)) / (w * w) * (x * x);
        let s = x0.sqrt();
        let g = (1.0 + 2.0 * s) / (0.7f64 * 0.7);
        let dg = (1.0 / s) / (0.7f64 * 0.7) + (1.0 + 2.0 * s) * 2.0 / 0.7f64.powi(3);
        let h = x0 * x0;
        let dh = 2.0 * x0;
        assert!((f.v - g * h).abs() < 1e-14);
        assert!((f.d - x0 * (dg * h + g * dh)).abs() < 1e-13);
    }
}
