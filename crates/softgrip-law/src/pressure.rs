//! Contact patch: radius and a force-conserving pressure profile over it.

use std::f64::consts::PI;

/// Contact radius and pressure of one contact.
///
/// `p(r) = p0 (1 - r^2/a^2)^m (1 + b r^2/a^2)` for `r <= a`, with
/// `p0 = (m + 1)(m + 2)/(m + 2 + b) p_mean` and `p_mean = F / (pi a^2)`: the integral of `p`
/// over the patch is `F` exactly for every shape exponent `m` [-] (`0 <= m <= 2`) and taper `b`
/// [-] (`-1 <= b <= 0`; the peak is then at the centre and `p >= 0`). Hertz's ellipse is
/// `m = 1/2, b = 0` (peak/mean 1.5); the finite-element patches of a squeezed free sphere or
/// flat pad are flatter (peak/mean 1.3-1.5, `b = 0`), those of a thin skin over a rigid core
/// fuller, their centre carrying more than any single power gives (`b < 0`), tending to a thin
/// bonded layer's `(1 - r^2/a^2)^2`. The calibrated levels give `m` and `b` as functions of
/// `x`, nu and the backing.
///
/// ```
/// use softgrip_law::ContactPatch;
/// let p = ContactPatch::new(2.0, 0.001);
/// assert!((p.pressure_at(0.0) - p.peak_pressure).abs() < 1e-9);
/// assert!((p.peak_pressure / p.mean_pressure - 1.5).abs() < 1e-12);
/// assert_eq!(p.pressure_at(0.002), 0.0);
/// let flat = ContactPatch::with_shape(2.0, 0.001, 0.3);
/// assert!((flat.peak_pressure / flat.mean_pressure - 1.3).abs() < 1e-12);
/// // m = 1, b = -1 is (1 - r^2/a^2)^2: peak/mean 3.
/// let layer = ContactPatch::with_profile(2.0, 0.001, 1.0, -1.0);
/// assert!((layer.peak_pressure / layer.mean_pressure - 3.0).abs() < 1e-12);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPatch {
    /// Contact radius a \[m\], >= 0.
    pub radius: f64,
    /// Mean pressure F / (pi a^2) \[Pa\].
    pub mean_pressure: f64,
    /// Peak pressure at the centre, `(m + 1)(m + 2)/(m + 2 + b)` times the mean \[Pa\]
    /// (`m + 1` for `b = 0`).
    pub peak_pressure: f64,
    /// Shape exponent m [-] of `(1 - r^2/a^2)^m`, in [0, 2] (1/2: Hertz).
    pub shape: f64,
    /// Taper b [-] of the factor `(1 + b r^2/a^2)`, in [-1, 0]: 0 for the free sphere's and
    /// the flat pad's patches (and Hertz's), < 0 for a skin over a rigid core.
    pub taper: f64,
}

/// Hertz's shape exponent.
pub(crate) const HERTZ_SHAPE: f64 = 0.5;

impl ContactPatch {
    /// No contact.
    pub const EMPTY: Self = Self {
        radius: 0.0,
        mean_pressure: 0.0,
        peak_pressure: 0.0,
        shape: HERTZ_SHAPE,
        taper: 0.0,
    };

    /// The Hertz-shaped patch (`m = 1/2`) of force `force` \[N\] spread over radius `radius`
    /// \[m\]; empty if either is not positive.
    pub fn new(force: f64, radius: f64) -> Self {
        Self::with_shape(force, radius, HERTZ_SHAPE)
    }

    /// The patch of force `force` \[N\] over radius `radius` \[m\] with shape exponent `shape`
    /// (clamped into [0, 2]; NaN becomes Hertz's 1/2) and no taper; empty if force or radius
    /// is not positive.
    pub fn with_shape(force: f64, radius: f64, shape: f64) -> Self {
        Self::with_profile(force, radius, shape, 0.0)
    }

    /// The patch of force `force` \[N\] over radius `radius` \[m\] with shape exponent `shape`
    /// (clamped into [0, 2]; NaN becomes Hertz's 1/2) and taper `taper` (clamped into [-1, 0];
    /// NaN becomes 0); empty if force or radius is not positive. The levels' shapes are inside
    /// both ranges; the clamps keep a custom law's profile non-negative and peaked at the centre.
    pub fn with_profile(force: f64, radius: f64, shape: f64, taper: f64) -> Self {
        if !(force > 0.0 && radius > 0.0) {
            return Self::EMPTY;
        }
        let m = if shape.is_nan() {
            HERTZ_SHAPE
        } else {
            shape.clamp(0.0, 2.0)
        };
        let b = if taper.is_nan() {
            0.0
        } else {
            taper.clamp(-1.0, 0.0)
        };
        // a^2 underflows below a = 1.5e-154 m (a subnormal compression, 5e-324 m at level
        // `linear`): divide by a twice then, or F / (pi a^2) is F / 0 = inf.
        let a2 = radius * radius;
        let mean = if a2 >= f64::MIN_POSITIVE {
            force / (PI * a2)
        } else {
            force / radius / radius / PI
        };
        // b = 0 exactly: (m + 1) mean, bit for bit as before the taper.
        let peak = if b == 0.0 {
            (m + 1.0) * mean
        } else {
            (m + 1.0) * (m + 2.0) / (m + 2.0 + b) * mean
        };
        Self {
            radius,
            mean_pressure: mean,
            peak_pressure: peak,
            shape: m,
            taper: b,
        }
    }

    /// Pressure p(r) \[Pa\] at distance `r` \[m\] from the centre; 0 outside the patch.
    pub fn pressure_at(&self, r: f64) -> f64 {
        if self.radius <= 0.0 || r.is_nan() || r.abs() >= self.radius {
            return 0.0;
        }
        let s = r / self.radius;
        let s2 = s * s;
        let u = 1.0 - s2;
        let p = if self.shape == HERTZ_SHAPE {
            self.peak_pressure * u.sqrt()
        } else {
            self.peak_pressure * u.powf(self.shape)
        };
        if self.taper == 0.0 {
            p
        } else {
            p * (1.0 + self.taper * s2)
        }
    }

    /// Torsional friction limit [N m]: the integral of `mu_f p r dA` over the patch for
    /// Coulomb friction `friction` and normal force `force` \[N\]:
    /// `mu_f F a (m + 1) B(3/2, m + 1) (m + 2)(2m + 5 + 3b) / ((2m + 5)(m + 2 + b))`
    /// (`3 pi / 16 mu_f F a` for Hertz's shape; `2/3 mu_f F a` for a uniform pressure;
    /// `16/35 mu_f F a` for `(1 - r^2/a^2)^2`).
    pub fn torsion_limit(&self, friction: f64, force: f64) -> f64 {
        let (m, b) = (self.shape, self.taper);
        let taper = if b == 0.0 {
            1.0
        } else {
            (m + 2.0) * (2.0 * m + 5.0 + 3.0 * b) / ((2.0 * m + 5.0) * (m + 2.0 + b))
        };
        torsion_factor(m) * taper * friction * force * self.radius
    }
}

/// `(m + 1) B(3/2, m + 1) = (m + 1) Gamma(3/2) Gamma(m + 1) / Gamma(m + 5/2)`, for `m` in [0, 2].
///
/// The Gamma ratio is computed by Stirling's series for `ln Gamma` after shifting the argument
/// past 8 (error below 1e-13 on [0, 2], checked against the closed forms at m = 0, 1/2, 1, 2).
pub(crate) fn torsion_factor(m: f64) -> f64 {
    if m == HERTZ_SHAPE {
        return 3.0 * PI / 16.0;
    }
    // Gamma(m + 1) / Gamma(m + 5/2) = exp(lnG(m + 1) - lnG(m + 5/2)).
    let ratio = (ln_gamma(m + 1.0) - ln_gamma(m + 2.5)).exp();
    (m + 1.0) * 0.5 * PI.sqrt() * ratio
}

/// `ln Gamma(z)` for `z >= 1`: recurrence up to `z >= 8`, then Stirling's series to `z^-7`.
fn ln_gamma(mut z: f64) -> f64 {
    let mut shift = 0.0;
    while z < 8.0 {
        shift -= z.ln();
        z += 1.0;
    }
    let zi = 1.0 / z;
    let zi2 = zi * zi;
    let series =
        zi * (1.0 / 12.0 - zi2 * (1.0 / 360.0 - zi2 * (1.0 / 1260.0 - zi2 * (1.0 / 1680.0))));
    shift + (z - 0.5) * z.ln() - z + 0.5 * (2.0 * PI).ln() + series
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn torsion_factor_matches_closed_forms() {
        // m = 0: uniform pressure, 2/3. m = 1: 2 B(3/2, 2) = 2 * 4/15 = 8/15. m = 2: 3 B(3/2, 3)
        // = 3 * 16/105 = 16/35. m = 1/2 (generic path, not the shortcut): 3 pi / 16.
        for (m, want) in [
            (0.0, 2.0 / 3.0),
            (1.0, 8.0 / 15.0),
            (2.0, 16.0 / 35.0),
            (0.5000000001, 3.0 * PI / 16.0),
        ] {
            let got = torsion_factor(m);
            assert!((got - want).abs() < 1e-9, "m = {m}: {got} vs {want}");
        }
    }

    /// Force and torsion of tapered profiles by quadrature against the closed forms, and the
    /// taper's limit: m = 1, b = -1 is m = 2 without taper.
    #[test]
    fn tapered_profiles_carry_the_force_and_their_torsion() {
        for (m, b) in [
            (0.3, -0.2),
            (0.5, -0.5),
            (1.0, -1.0),
            (1.7, -0.05),
            (0.0, -1.0),
        ] {
            let p = ContactPatch::with_profile(3.0, 0.002, m, b);
            let n = 40000;
            let (mut force, mut torsion) = (0.0, 0.0);
            for i in 0..n {
                let r = (i as f64 + 0.5) / n as f64 * p.radius;
                let da = 2.0 * PI * r * (p.radius / n as f64);
                force += p.pressure_at(r) * da;
                torsion += 0.4 * p.pressure_at(r) * r * da;
            }
            assert!(
                (force / 3.0 - 1.0).abs() < 2e-5,
                "m {m} b {b}: force {force}"
            );
            let want = p.torsion_limit(0.4, 3.0);
            assert!(
                (torsion / want - 1.0).abs() < 2e-5,
                "m {m} b {b}: {torsion} vs {want}"
            );
        }
        let (layer, square) = (
            ContactPatch::with_profile(3.0, 0.002, 1.0, -1.0),
            ContactPatch::with_shape(3.0, 0.002, 2.0),
        );
        assert!((layer.peak_pressure / square.peak_pressure - 1.0).abs() < 1e-14);
        assert!(
            (layer.torsion_limit(1.0, 1.0) / square.torsion_limit(1.0, 1.0) - 1.0).abs() < 1e-12
        );
        for r in [0.0, 0.0005, 0.0013, 0.00199] {
            let (a, b) = (layer.pressure_at(r), square.pressure_at(r));
            assert!(
                (a - b).abs() <= 1e-12 * square.peak_pressure,
                "r {r}: {a} vs {b}"
            );
        }
    }

    #[test]
    fn every_shape_carries_the_force() {
        for m in [0.0, 0.25, 0.5, 0.8, 1.7] {
            let p = ContactPatch::with_shape(3.0, 0.002, m);
            // 2 pi int_0^a p(r) r dr in u = 1 - r^2/a^2: pi a^2 p0 int_0^1 u^m du.
            let n = 20000;
            let mut sum = 0.0;
            for i in 0..n {
                let r = (i as f64 + 0.5) / n as f64 * p.radius;
                sum += p.pressure_at(r) * 2.0 * PI * r * (p.radius / n as f64);
            }
            assert!((sum / 3.0 - 1.0).abs() < 2e-4, "m = {m}: {sum}");
        }
    }
}
