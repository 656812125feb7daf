//! The paper's explicit law (Eqs. 37-38 and 39-42): `chi_L = 1 / (1 - k x)`, `k = 10/9`, and the
//! compressible radius fit `a = [1 - (10/9)(1/2 - nu) x] a_IC`.

use super::{NormalisedLaw, scale_by_chi};

/// The paper's linear fit of `1/chi` (Eq. 38). `k = 10/9` comes from the least-squares fit of
/// `1/chi_IC = 1 - k x` on `0 <= x <= 0.5` (1.1141).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Fit {
    k: f64,
    /// `(10/9)(1/2 - nu)`, the slope of the radius correction of Eq. 42.
    radius_slope: f64,
    x_max: f64,
}

impl Fit {
    /// `k` finite in [0, 10] (checked by the caller), `nu` in (-1, 0.5].
    pub(crate) fn new(k: f64, nu: f64) -> Self {
        let radius_slope = 10.0 / 9.0 * (0.5 - nu);
        // Validity: stay clear of the pole at x = 1/k (chi <= 10), of the artanh pole of the
        // radius at x = 1 (x <= 0.95), and keep the radius factor of Eq. 42 >= 0.1.
        let mut x_max: f64 = 0.95;
        if k > 0.0 {
            x_max = x_max.min(0.9 / k);
        }
        if radius_slope > 0.0 {
            x_max = x_max.min(0.9 / radius_slope);
        }
        Self {
            k,
            radius_slope,
            x_max,
        }
    }
}

impl NormalisedLaw for Fit {
    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        let d = 1.0 / (1.0 - self.k * x);
        // chi = 1/(1 - kx), chi' = k/(1 - kx)^2
        scale_by_chi(x, d, self.k * d * d)
    }

    fn energy(&self, x: f64) -> f64 {
        let k = self.k;
        let kx = k * x;
        if kx < 0.25 {
            // (4/3) int s^(3/2) sum (k s)^n ds = (4/3) sum k^n x^(n+5/2) / (n + 5/2);
            // the terms fall by kx <= 1/4 each, so 30 terms reach f64 precision.
            let mut term = x * x * x.sqrt();
            let mut sum = 0.0;
            for n in 0..30 {
                sum += term / (n as f64 + 2.5);
                term *= kx;
            }
            4.0 / 3.0 * sum
        } else {
            // With s = t^2, int_0^x s^(3/2)/(1 - k s) ds = int_0^u 2 t^4/(1 - b^2 t^2) dt,
            // b = sqrt(k), u = sqrt(x); t^4/(1 - b^2 t^2) = -t^2/b^2 - 1/b^4 + 1/(b^4 (1 - b^2 t^2)).
            let (b, u) = (k.sqrt(), x.sqrt());
            let b2 = k;
            let b4 = b2 * b2;
            let i = -u * u * u / (3.0 * b2) - u / b4 + (b * u).atanh() / (b4 * b);
            4.0 / 3.0 * 2.0 * i
        }
    }

    fn radius(&self, x: f64) -> f64 {
        (1.0 - self.radius_slope * x) * x.sqrt().atanh()
    }

    fn x_max(&self) -> f64 {
        self.x_max
    }
}
