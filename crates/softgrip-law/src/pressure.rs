//! Contact patch: radius and a force-conserving pressure profile over it.

use std::f64::consts::PI;

use crate::elliptic::second_kind;

/// Contact patch and pressure of one contact: a disc on a plane or a ball, an ellipse on a
/// cylinder or any surface of two different curvatures.
///
/// The patch is the ellipse of semi-axes `radius` (a, along the counterpart's first principal
/// direction, [`crate::Counterpart`]) and `radius2` (b, along its second); a disc has `a = b`.
/// With `ρ² = u²/a² + v²/b²` (u, v along the two directions),
/// `p = p0 (1 - ρ²)^m (1 + b_t ρ²)` for `ρ <= 1`, with
/// `p0 = (m + 1)(m + 2)/(m + 2 + b_t) p_mean` and `p_mean = F / (pi a b)`: the integral of `p`
/// over the patch is `F` exactly for every shape exponent `m` [-] (`0 <= m <= 2`) and taper
/// `b_t` [-] (`-1 <= b_t <= 0`; the peak is then at the centre and `p >= 0`). Hertz's ellipsoid is
/// `m = 1/2, b_t = 0` (peak/mean 1.5); the finite-element patches of a squeezed free sphere or
/// flat pad are flatter (peak/mean 1.3-1.5, `b_t = 0`), those of a thin skin over a rigid core
/// fuller, their centre carrying more than any single power gives (`b_t < 0`), tending to a thin
/// bonded layer's `(1 - ρ²)^2`. The calibrated levels give `m` and `b_t` as functions of
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
/// // m = 1, b_t = -1 is (1 - r^2/a^2)^2: peak/mean 3.
/// let layer = ContactPatch::with_profile(2.0, 0.001, 1.0, -1.0);
/// assert!((layer.peak_pressure / layer.mean_pressure - 3.0).abs() < 1e-12);
/// // An ellipse of semi-axes 2 mm and 1 mm: the mean over its area pi a b.
/// let e = ContactPatch::with_ellipse(2.0, [0.002, 0.001], 0.5, 0.0);
/// assert!((e.mean_pressure - 2.0 / (std::f64::consts::PI * 2e-6)).abs() < 1e-6);
/// assert_eq!(e.pressure_at_point(0.0, 0.0011), 0.0); // past b
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPatch {
    /// Contact radius a \[m\], >= 0: of a disc its radius, of an ellipse the semi-axis along
    /// the counterpart's first principal direction.
    pub radius: f64,
    /// The semi-axis b along the counterpart's second principal direction \[m\], >= 0; equal
    /// to `radius` for a disc (a plane, a ball).
    pub radius2: f64,
    /// Mean pressure F / (pi a b) \[Pa\].
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
        radius2: 0.0,
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
        Self::with_ellipse(force, [radius, radius], shape, taper)
    }

    /// The elliptical patch of force `force` \[N\] over the semi-axes `semi_axes` = `[a, b]`
    /// \[m\] (along the counterpart's first and second principal directions) with shape
    /// exponent `shape` (clamped into [0, 2]; NaN becomes Hertz's 1/2) and taper `taper`
    /// (clamped into [-1, 0]; NaN becomes 0); empty if the force or either semi-axis is not
    /// positive. The levels' shapes are inside both ranges; the clamps keep a custom law's
    /// profile non-negative and peaked at the centre.
    pub fn with_ellipse(force: f64, semi_axes: [f64; 2], shape: f64, taper: f64) -> Self {
        let [radius, radius2] = semi_axes;
        if !(force > 0.0 && radius > 0.0 && radius2 > 0.0) {
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
        // a b underflows below a = 1.5e-154 m (a subnormal compression, 5e-324 m at level
        // `linear`): divide by a and b in turn then, or F / (pi a b) is F / 0 = inf.
        let ab = radius * radius2;
        let mean = if ab >= f64::MIN_POSITIVE {
            force / (PI * ab)
        } else {
            force / radius / radius2 / PI
        };
        // b = 0 exactly: (m + 1) mean, bit for bit as before the taper.
        let peak = if b == 0.0 {
            (m + 1.0) * mean
        } else {
            (m + 1.0) * (m + 2.0) / (m + 2.0 + b) * mean
        };
        Self {
            radius,
            radius2,
            mean_pressure: mean,
            peak_pressure: peak,
            shape: m,
            taper: b,
        }
    }

    /// `true` for a disc (`radius == radius2`), the patch on a plane or a ball.
    pub fn is_disc(&self) -> bool {
        self.radius == self.radius2
    }

    /// The radius of the disc of the same area, `sqrt(a b)` \[m\] (`radius` for a disc).
    pub fn equivalent_radius(&self) -> f64 {
        if self.is_disc() {
            self.radius
        } else {
            (self.radius * self.radius2).sqrt()
        }
    }

    /// The pressure \[Pa\] at the point `(u, v)` \[m\] of the patch, u along its first
    /// semi-axis, v along its second; 0 outside the patch.
    pub fn pressure_at_point(&self, u: f64, v: f64) -> f64 {
        if !(self.radius > 0.0 && self.radius2 > 0.0) {
            return 0.0;
        }
        let (su, sv) = (u / self.radius, v / self.radius2);
        self.pressure_at_normalised(su * su + sv * sv)
    }

    /// The profile at `s2 = rho²` (0 at the centre, 1 at the edge); 0 outside or for NaN.
    fn pressure_at_normalised(&self, s2: f64) -> f64 {
        if s2.is_nan() || s2 >= 1.0 {
            return 0.0;
        }
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

    /// Pressure p(r) \[Pa\] at distance `r` \[m\] from the centre along the first semi-axis
    /// (any direction of a disc); 0 outside the patch.
    pub fn pressure_at(&self, r: f64) -> f64 {
        if self.radius <= 0.0 || r.is_nan() || r.abs() >= self.radius {
            return 0.0;
        }
        let s = r / self.radius;
        self.pressure_at_normalised(s * s)
    }

    /// Torsional friction limit [N m]: the integral of `mu_f p r dA` over the patch for
    /// Coulomb friction `friction` and normal force `force` \[N\]:
    /// `mu_f F a (m + 1) B(3/2, m + 1) (m + 2)(2m + 5 + 3b) / ((2m + 5)(m + 2 + b))`
    /// (`3 pi / 16 mu_f F a` for Hertz's shape; `2/3 mu_f F a` for a uniform pressure;
    /// `16/35 mu_f F a` for `(1 - r^2/a^2)^2`). On an ellipse `a` is its mean radius, the
    /// perimeter over 2 pi, `(2/pi) a_max E(e)` (E the complete elliptic integral of the second
    /// kind, e the eccentricity): `∫ r dA` over the ellipse's rings, each of which is the
    /// patch's outline scaled.
    pub fn torsion_limit(&self, friction: f64, force: f64) -> f64 {
        let (m, b) = (self.shape, self.taper);
        let taper = if b == 0.0 {
            1.0
        } else {
            (m + 2.0) * (2.0 * m + 5.0 + 3.0 * b) / ((2.0 * m + 5.0) * (m + 2.0 + b))
        };
        torsion_factor(m) * taper * friction * force * self.mean_radius()
    }

    /// The perimeter over 2 pi \[m\]: `radius` for a disc, `(2/pi) a E(e)` for an ellipse of
    /// larger semi-axis a and eccentricity e.
    pub fn mean_radius(&self) -> f64 {
        if self.is_disc() {
            return self.radius;
        }
        let (long, short) = if self.radius >= self.radius2 {
            (self.radius, self.radius2)
        } else {
            (self.radius2, self.radius)
        };
        if long.is_nan() || long <= 0.0 {
            return 0.0;
        }
        let q = short / long;
        2.0 / PI * long * second_kind(q * q)
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

    /// Ellipses: the force and the torsion limit by quadrature over the patch in Cartesian
    /// cells (`pressure_at_point`, the moment arm the distance from the centre), against the
    /// closed forms; a disc's torsion is unchanged.
    #[test]
    fn ellipses_carry_the_force_and_their_torsion() {
        for (axes, m, b) in [
            ([0.002, 0.001], 0.5, 0.0),
            ([0.001, 0.0035], 0.8, -0.3),
            ([0.003, 0.0003], 0.5, 0.0),
            ([0.0015, 0.0015 * (1.0 - 1e-9)], 1.2, -0.6),
        ] {
            let p = ContactPatch::with_ellipse(3.0, axes, m, b);
            let n = 1500;
            let (du, dv) = (2.0 * axes[0] / n as f64, 2.0 * axes[1] / n as f64);
            let (mut force, mut torsion) = (0.0, 0.0);
            for i in 0..n {
                let u = -axes[0] + (i as f64 + 0.5) * du;
                for j in 0..n {
                    let v = -axes[1] + (j as f64 + 0.5) * dv;
                    let q = p.pressure_at_point(u, v) * du * dv;
                    force += q;
                    torsion += 0.4 * q * (u * u + v * v).sqrt();
                }
            }
            assert!((force / 3.0 - 1.0).abs() < 1e-4, "{axes:?}: force {force}");
            let want = p.torsion_limit(0.4, 3.0);
            assert!(
                (torsion / want - 1.0).abs() < 1e-4,
                "{axes:?}: {torsion} vs {want}"
            );
        }
        let disc = ContactPatch::with_profile(3.0, 0.002, 0.7, -0.2);
        assert!(disc.is_disc() && disc.mean_radius() == 0.002);
        // The mean radius of a circle of radius 1 reached as an ellipse's limit.
        let near = ContactPatch::with_ellipse(3.0, [1.0, 1.0 - 1e-12], 0.5, 0.0);
        assert!((near.mean_radius() - 1.0).abs() < 1e-11);
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
