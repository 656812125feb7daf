//! [`FePoint`]: an FE point normalised like the law, `f = F / (E* R²)` against `x = δ/R`.

/// Shear modulus of every FE run, mu \[MPa\].
pub const SHEAR_MODULUS_MPA: f64 = 1.0;
/// Sphere radius of every FE run, R \[mm\].
pub const RADIUS_MM: f64 = 1.0;

/// Effective modulus of the runs at Poisson ratio `nu`, `E* = 2 mu (1 + nu) / (1 - nu²)` \[MPa\].
///
/// With R = 1 mm and E* in MPa, `f = F / (E* R²)` is the force in N divided by this number.
pub fn effective_modulus_mpa(nu: f64) -> f64 {
    2.0 * SHEAR_MODULUS_MPA * (1.0 + nu) / (1.0 - nu * nu)
}

/// One FE point in the law's normalised units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FePoint {
    /// Poisson ratio of the run [-].
    pub nu: f64,
    /// Compression ratio x = delta/R [-].
    pub x: f64,
    /// Normalised force f = F / (E* R²) [-].
    pub force_norm: f64,
    /// Normalised contact radius a / R [-] (resolved to about one element, R/60: compare radii
    /// for x >= 0.1).
    pub radius_norm: f64,
    /// Smallest element Jacobian J [-] (volume ratio), where the file has it.
    pub min_element_j: Option<f64>,
    /// 3D runs ([`crate::Schema::Force3d`]): the patch's semi-axis along the cylinder's axis or
    /// the edge over R [-] ([`FePoint::radius_norm`] is the one across it); `None` for
    /// axisymmetric runs (a circular patch).
    pub radius_along_norm: Option<f64>,
}

impl FePoint {
    /// A point from the file's units: force \[N\], radius \[mm\].
    pub(crate) fn from_si(nu: f64, x: f64, force_n: f64, radius_mm: f64) -> Self {
        Self {
            nu,
            x,
            force_norm: force_n / effective_modulus_mpa(nu),
            radius_norm: radius_mm / RADIUS_MM,
            min_element_j: None,
            radius_along_norm: None,
        }
    }
}
