//! softgrip's calibrated level for a backed fingertip ([`Backing::Flat`], [`Backing::Core`]):
//! `F = chi(x, nu, t/R) F_H`, fitted to softgrip's own finite-element pipeline (`tools/fe/`,
//! data in `tests/data/fe/{flat,core}/`).
//!
//! PROVISIONAL FORM (being calibrated; see the crate README once final).

use super::NormalisedLaw;
use super::dual::Dual;
use crate::backing::Backing;
use crate::error::{Error, Result};
use crate::level::LevelKind;
use crate::quadrature::integrate;

/// The calibrated level of one backed construction at one Poisson ratio.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Backed {
    c: f64,
    d: f64,
    e: f64,
    b2: f64,
    /// Core only: coefficient of the bonded layer's first-order stiffening, 0 for flat.
    k_layer: f64,
    /// 1 / (t/R) for core, 0 for flat.
    inv_tau: f64,
    eps4: f64,
    shape: f64,
    x_max: f64,
}

impl Backed {
    /// `backing` is `Flat` or `Core` (with `tau = t/R` in (0, 1)), `0 <= nu <= 0.5`.
    pub(crate) fn try_new(backing: Backing, tau: Option<f64>, nu: f64) -> Result<Self> {
        if !(0.0..=0.5).contains(&nu) {
            return Err(Error::IncompatibleLevel {
                level: LevelKind::Calibrated,
                nu,
                reason: "the calibrated level of a backed fingertip is defined for 0 <= nu <= 0.5",
            });
        }
        let beta = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
        let eps = 3.0 * (1.0 - 2.0 * nu) / (2.0 * (1.0 + nu));
        let b = 1.0133 * eps;
        let (k_layer, inv_tau, x_max) = match (backing, tau) {
            (Backing::Core { .. }, Some(tau)) => {
                let k = 2.0 / std::f64::consts::PI * (1.2876 - 1.4678 * nu + 1.3442 * nu * nu)
                    / (1.0 - nu);
                (k * (1.0 - tau), 1.0 / tau, (0.65 * tau).min(0.43))
            }
            _ => (0.0, 0.0, 0.43),
        };
        Ok(Self {
            c: 0.6499 - 0.4904 * beta,
            d: 0.1982,
            e: 1.5869 - 5.9793 * beta,
            b2: b * b,
            k_layer,
            inv_tau,
            eps4: 0.25 * eps,
            shape: 0.4,
            x_max,
        })
    }

    #[inline(always)]
    fn chi(&self, x: Dual) -> Dual {
        let w = 1.0 - x;
        let x2 = x * x;
        let n = w + x2.scale(1.0 / 3.0);
        let s = x.sqrt();
        let sf = Dual::c(1.0) - x.scale(self.d) + s.scale(self.c) + x2.scale(self.e);
        let den = w * w + x2.scale(self.b2);
        let layer = Dual::c(1.0) + s.scale(self.k_layer * self.inv_tau);
        n * sf * layer / den
    }

    /// Exponent `m` of the pressure profile `p ~ (1 - r^2/a^2)^m`.
    pub(crate) fn shape(&self, _x: f64) -> f64 {
        self.shape
    }
}

impl NormalisedLaw for Backed {
    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        let chi = self.chi(Dual::var(x));
        super::scale_by_chi(x, chi.v, chi.d)
    }

    fn energy(&self, x: f64) -> f64 {
        integrate(0.0, x.sqrt(), 4, |u| {
            let s = u * u;
            8.0 / 3.0 * self.chi(Dual::c(s)).v * s * s
        })
    }

    fn radius(&self, x: f64) -> f64 {
        let w = 1.0 - x;
        x.sqrt().atanh() * w / (w + self.eps4 * x)
    }

    fn x_max(&self) -> f64 {
        self.x_max
    }

    fn pressure_shape(&self, x: f64) -> f64 {
        self.shape(x)
    }
}
