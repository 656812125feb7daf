//! The levels of the law, each as a normalised curve `f(x) = F / (E* R^2)` of the compression
//! ratio `x = delta / R`. One level per file; this module declares them and the trait they share.

pub(crate) mod auto;
pub(crate) mod calibrated;
pub(crate) mod fit;
pub(crate) mod hertz;
pub(crate) mod incompressible;
pub(crate) mod linear;
pub(crate) mod neo_hookean;
pub(crate) mod nh_table;
pub(crate) mod tatara;

/// A level in normalised form. Every method takes `0 <= x <= x_max()`; the caller
/// ([`crate::ContactLaw`]) handles separation and the extension past `x_max`.
pub(crate) trait Normalised {
    /// Normalised force `f = F / (E* R^2)` and stiffness `df/dx = K / (E* R)`.
    fn force_stiffness(&self, x: f64) -> (f64, f64);
    /// Normalised stored energy `w = W / (E* R^3)`, the integral of `f` from 0 to `x`.
    fn energy(&self, x: f64) -> f64;
    /// Normalised contact radius `a / R`.
    fn radius(&self, x: f64) -> f64;
    /// Largest compression ratio of the validity range.
    fn x_max(&self) -> f64;
}

/// Hertz's normalised force `(4/3) x^(3/2)` and its derivative `2 x^(1/2)` (Eq. 5).
#[inline]
pub(crate) fn hertz(x: f64) -> (f64, f64) {
    let s = x.sqrt();
    (4.0 / 3.0 * x * s, 2.0 * s)
}

/// `F = chi F_H` in normalised form, with `df/dx = chi' f_H + chi f_H'`.
#[inline]
pub(crate) fn scale_by_chi(x: f64, chi: f64, dchi: f64) -> (f64, f64) {
    let (f_h, df_h) = hertz(x);
    (chi * f_h, dchi * f_h + chi * df_h)
}
