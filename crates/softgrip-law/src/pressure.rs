//! Contact patch: radius and the Hertz-shaped pressure over it (Eqs. 1, 3, 30-31).

/// Contact radius and pressure of one contact.
///
/// `p(r) = (3/2) p_mean sqrt(1 - r^2/a^2)` for `r <= a`, `p_mean = F / (pi a^2)`: Hertz's shape
/// over the (expanded) radius of the level. The paper finds it within a few percent of FE for
/// nu = 0.5, up to 9 % (nu = 0.4) and 12 % (nu = 0.3) off at x = 0.5.
///
/// ```
/// use softgrip_law::ContactPatch;
/// let p = ContactPatch::new(2.0, 0.001);
/// assert!((p.pressure_at(0.0) - p.peak_pressure).abs() < 1e-9);
/// assert!((p.peak_pressure / p.mean_pressure - 1.5).abs() < 1e-12);
/// assert_eq!(p.pressure_at(0.002), 0.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactPatch {
    /// Contact radius a \[m\], >= 0.
    pub radius: f64,
    /// Mean pressure F / (pi a^2) \[Pa\].
    pub mean_pressure: f64,
    /// Peak pressure at the centre, 3/2 of the mean \[Pa\].
    pub peak_pressure: f64,
}

impl ContactPatch {
    /// No contact.
    pub const EMPTY: Self = Self {
        radius: 0.0,
        mean_pressure: 0.0,
        peak_pressure: 0.0,
    };

    /// The patch of force `force` \[N\] spread over radius `radius` \[m\]; empty if either is not
    /// positive.
    pub fn new(force: f64, radius: f64) -> Self {
        if !(force > 0.0 && radius > 0.0) {
            return Self::EMPTY;
        }
        let mean = force / (std::f64::consts::PI * radius * radius);
        Self {
            radius,
            mean_pressure: mean,
            peak_pressure: 1.5 * mean,
        }
    }

    /// Pressure p(r) \[Pa\] at distance `r` \[m\] from the centre; 0 outside the patch.
    pub fn pressure_at(&self, r: f64) -> f64 {
        if self.radius <= 0.0 || r.abs() >= self.radius {
            return 0.0;
        }
        let s = r / self.radius;
        self.peak_pressure * (1.0 - s * s).sqrt()
    }

    /// Torsional friction limit `(3 pi / 16) mu_f F a` [N m] of this Hertz-shaped patch for a
    /// Coulomb friction coefficient `friction` and normal force `force` \[N\].
    pub fn torsion_limit(&self, friction: f64, force: f64) -> f64 {
        3.0 * std::f64::consts::PI / 16.0 * friction * force * self.radius
    }
}
