//! Forward-mode dual numbers `v + d eps` (eps^2 = 0): a law written once as a function of `x`
//! gives its exact derivative alongside its value, so the stiffness is the derivative of the
//! force by construction. Hand-written (a few lines) so that everything inlines into the hot
//! path: `cargo bench -p softgrip-law --bench levels` times the levels that use it.

use std::ops::{Add, Div, Mul, Sub};

/// A value and its derivative with respect to `x`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Dual {
    pub(crate) v: f64,
    pub(crate) d: f64,
}

impl Dual {
    /// The variable itself: `x + 1 eps`.
    #[inline(always)]
    pub(crate) fn var(x: f64) -> Self {
        Self { v: x, d: 1.0 }
    }

    /// A constant.
    #[inline(always)]
    pub(crate) fn c(v: f64) -> Self {
        Self { v, d: 0.0 }
    }

    /// `sqrt`, for `v > 0`.
    #[inline(always)]
    pub(crate) fn sqrt(self) -> Self {
        let s = self.v.sqrt();
        Self {
            v: s,
            d: 0.5 * self.d / s,
        }
    }

    /// `self^k` for a constant `k`, `v > 0`.
    #[inline(always)]
    pub(crate) fn powf(self, k: f64) -> Self {
        let p = self.v.powf(k);
        Self {
            v: p,
            d: k * p / self.v * self.d,
        }
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
    fn derivative_of_a_rational_function_with_a_root() {
        // f = (1 + 2 sqrt(x)) / (1 - x)^2 at x = 0.3: f' by hand.
        let x = Dual::var(0.3);
        let w = 1.0 - x;
        let f = (Dual::c(1.0) + x.sqrt().scale(2.0)) / (w * w);
        let s = 0.3f64.sqrt();
        let fv = (1.0 + 2.0 * s) / (0.7f64 * 0.7);
        let fd = (1.0 / s) / (0.7f64 * 0.7) + (1.0 + 2.0 * s) * 2.0 / 0.7f64.powi(3);
        assert!((f.v - fv).abs() < 1e-14);
        assert!((f.d - fd).abs() < 1e-13);
    }
}
