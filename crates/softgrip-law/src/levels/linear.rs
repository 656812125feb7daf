//! Linear spring `F = k delta`, what rapier's softness, MuJoCo's solref and Drake's point
//! contact reduce to. A baseline only.

use super::NormalisedLaw;

/// Linear spring matched to Hertz's force at `x = match_x`: `f = (4/3) sqrt(match_x) x`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Linear {
    /// Normalised spring rate `k / (E* R)`.
    rate: f64,
}

impl Linear {
    pub(crate) fn new(match_x: f64) -> Self {
        Self {
            rate: 4.0 / 3.0 * match_x.sqrt(),
        }
    }
}

impl NormalisedLaw for Linear {
    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        (self.rate * x, self.rate)
    }

    fn energy(&self, x: f64) -> f64 {
        0.5 * self.rate * x * x
    }

    fn radius(&self, x: f64) -> f64 {
        // A spring has no contact patch; report Hertz's radius for the same compression.
        x.sqrt()
    }

    fn x_max(&self) -> f64 {
        1.0
    }
}
