//! [`Tail`]: the terms a counterpart adds to the mapped plane law (`crate::mapping`), closed-form
//! powers of `x = delta/R` so that stiffness, energy and the inverse stay exact.

/// The force subtracted from the mapped plane law on a counterpart,
/// `t5 x^(5/2) + t7 x^(7/2) + t11 x^(11/2)` \[N\] at `x = delta/R` (all 0 on a plane and an
/// edge):
///
/// - `t5 x^(5/2)`: the counterpart's own finite size (a sphere, not Hertz's paraboloid);
/// - `t7 x^(7/2)`: the compressible collapse under a narrower patch (negative: it adds force)
///   and, bonded, the counterpart's next order beyond its paraboloid (positive on a ball);
/// - `t11 x^(11/2)`: the bonded pad's collapsed column re-stiffening under a narrower patch
///   (negative: it adds force; 0 for the free sphere).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Tail {
    /// `t5` \[N\].
    pub t5: f64,
    /// `t7` \[N\].
    pub t7: f64,
    /// `t11` \[N\].
    pub t11: f64,
}

impl Tail {
    /// No term: a plane, an edge.
    pub(crate) const ZERO: Self = Self {
        t5: 0.0,
        t7: 0.0,
        t11: 0.0,
    };

    /// `true` when every term is 0.
    #[inline(always)]
    pub(crate) fn is_zero(&self) -> bool {
        self.t5 == 0.0 && self.t7 == 0.0 && self.t11 == 0.0
    }

    /// `true` when a term subtracts force and could, at large x, overtake the plane law's
    /// stiffening (the law then ends its range before its stiffness vanishes).
    pub(crate) fn may_soften(&self) -> bool {
        self.t5 > 0.0 || self.t7 > 0.0 || self.t11 > 0.0
    }

    /// Force \[N\] and stiffness \[N/m\] at `x = delta/R` of a fingertip with `1/R` =
    /// `inv_radius` \[1/m\].
    #[inline(always)]
    pub(crate) fn at(&self, x: f64, inv_radius: f64) -> (f64, f64) {
        let s = x.sqrt();
        let x15 = x * s;
        let x25 = x * x15;
        let x3 = x * x * x;
        (
            (self.t5 + self.t7 * x + self.t11 * x3) * x25,
            (2.5 * self.t5 + 3.5 * self.t7 * x + 5.5 * self.t11 * x3) * x15 * inv_radius,
        )
    }

    /// The integral \[J\] of the force from 0 to `x = delta/R`, for a fingertip of radius
    /// `radius` \[m\]: `R (t5 x^(7/2)/(7/2) + t7 x^(9/2)/(9/2) + t11 x^(13/2)/(13/2))`.
    pub(crate) fn integral(&self, x: f64, radius: f64) -> f64 {
        let x3 = x.powi(3);
        let x35 = x3 * x.sqrt();
        radius * x35 * (self.t5 / 3.5 + self.t7 * x / 4.5 + self.t11 * x3 / 6.5)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The stiffness is the force's derivative and the integral the force's integral
    /// (central differences and Simpson's rule, to 1e-9 relative).
    #[test]
    fn stiffness_and_integral_are_the_force_s() {
        let tail = Tail {
            t5: 0.37,
            t7: -1.3,
            t11: -4.1,
        };
        let (r, x) = (0.01, 0.42);
        let (h, n) = (1e-6, 2000);
        let df = (tail.at(x + h, 1.0 / r).0 - tail.at(x - h, 1.0 / r).0) / (2.0 * h * r);
        let k = tail.at(x, 1.0 / r).1;
        assert!((df / k - 1.0).abs() < 1e-8, "{df} vs {k}");
        let step = x / f64::from(n);
        let simpson: f64 = (0..=n)
            .map(|i| {
                let w = if i == 0 || i == n {
                    1.0
                } else if i % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                w * tail.at(f64::from(i) * step, 1.0 / r).0
            })
            .sum::<f64>()
            * step
            / 3.0
            * r;
        let w = tail.integral(x, r);
        assert!((simpson / w - 1.0).abs() < 1e-9, "{simpson} vs {w}");
        assert!(Tail::ZERO.is_zero() && !Tail::ZERO.may_soften());
    }
}
