//! PROVISIONAL (not committed): replaced by the fitted form.

use super::{Normalised, scale_by_chi};
use crate::error::Result;

#[derive(Debug, Clone, Copy)]
pub(crate) struct Calibrated {
    nu: f64,
}

impl Calibrated {
    pub(crate) fn try_new(nu: f64) -> Result<Self> {
        Ok(Self { nu })
    }
}

impl Normalised for Calibrated {
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        let k = 10.0 / 9.0;
        let d = 1.0 / (1.0 - k * x);
        scale_by_chi(x, d, k * d * d)
    }
    fn energy(&self, x: f64) -> f64 {
        crate::quadrature::integrate(0.0, x.sqrt(), 4, |u| {
            let s = u * u;
            2.0 * u * self.force_stiffness(s).0
        })
    }
    fn radius(&self, x: f64) -> f64 {
        (1.0 - 10.0 / 9.0 * (0.5 - self.nu) * x) * x.sqrt().atanh()
    }
    fn x_max(&self) -> f64 {
        0.8
    }
}
