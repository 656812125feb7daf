//! [`NormalisedLaw`]: the extension point of the law, a contact law in normalised form.

use std::fmt::Debug;

/// The largest end of a law's validity range [-]; the hot path's extension is frozen past
/// `max(x_wall + L, X_FROZEN)` (see [`ContactLaw`](crate::ContactLaw)).
pub(crate) const X_FROZEN: f64 = 4.0;

/// A contact law in normalised form: the force `f(x) = F / (E* R²)` [-] as a function of the
/// compression ratio `x = δ/R` [-], with its stiffness, energy and contact radius.
///
/// Every built-in level implements it, and so can a user's own law, used through
/// [`crate::ContactLaw::custom`]. [`crate::ContactLaw`] binds a normalised law to a contact's
/// E* \[Pa\] and R \[m\], handles separation (`x <= 0`), non-finite input and the extension past
/// [`x_max`](Self::x_max) (a barrier against the fingertip's wall, C1 with the law at `x_max`,
/// [`crate::Regime::Extended`]): the methods are only called with `0 < x <= x_max`.
///
/// What a law must satisfy on `0 < x <= x_max` (so that an integrator sees one consistent,
/// passive law; the tests check the built-in levels for all of it):
/// - `f(0+) = 0`, `f >= 0`, `f` non-decreasing, everything finite;
/// - the stiffness is the exact derivative `df/dx = K / (E* R)`;
/// - the energy is the exact integral `w(x) = ∫₀ˣ f ds = W / (E* R³)`;
/// - the radius `a/R >= 0`.
///
/// ```
/// use std::sync::Arc;
/// use softgrip_law::{ContactLaw, ContactParams, Material, NormalisedLaw};
///
/// /// Hertz with twice the force: f = (8/3) x^(3/2).
/// #[derive(Debug)]
/// struct DoubleHertz;
///
/// impl NormalisedLaw for DoubleHertz {
///     fn force_stiffness(&self, x: f64) -> (f64, f64) {
///         (8.0 / 3.0 * x * x.sqrt(), 4.0 * x.sqrt())
///     }
///     fn energy(&self, x: f64) -> f64 {
///         16.0 / 15.0 * x * x * x.sqrt()
///     }
///     fn radius(&self, x: f64) -> f64 {
///         x.sqrt()
///     }
///     fn x_max(&self) -> f64 {
///         0.5
///     }
/// }
///
/// // E* = 1 MPa, R = 10 mm: at delta = 1 mm (x = 0.1), F = (8/3) E* R^2 x^1.5 = 8.433 N.
/// let params = ContactParams::try_from_parts(1.0e6, 0.010, 0.5)?;
/// let law = ContactLaw::custom(params, Arc::new(DoubleHertz))?;
/// assert!((law.response(0.001).force - 8.4327).abs() < 1e-4);
/// assert!(law.evaluate(0.006).is_err()); // x = 0.6 is past x_max = 0.5
/// # Ok::<(), softgrip_law::Error>(())
/// ```
pub trait NormalisedLaw: Send + Sync + Debug {
    /// Normalised force `f = F / (E* R²)` [-] and stiffness `df/dx = K / (E* R)` [-] at
    /// compression ratio `x` in `(0, x_max]`.
    fn force_stiffness(&self, x: f64) -> (f64, f64);

    /// Normalised stored energy `w = W / (E* R³)` [-], the integral of `f` from 0 to `x`
    /// (`x` in `(0, x_max]`).
    fn energy(&self, x: f64) -> f64;

    /// Normalised contact radius `a / R` [-] at `x` in `(0, x_max]`.
    fn radius(&self, x: f64) -> f64;

    /// Largest compression ratio of the validity range [-]: finite, in `(0, 4]`.
    fn x_max(&self) -> f64;

    /// Exponent `m` [-] of the pressure profile `p(r) = p0 (1 - r^2/a^2)^m` at `x` in
    /// `(0, x_max]`, in `[0, 2]` (`p0 = (m + 1) F / (pi a^2)`, so the profile carries the force
    /// exactly). The default is Hertz's `1/2`.
    fn pressure_shape(&self, x: f64) -> f64 {
        let _ = x;
        0.5
    }

    /// Taper `b` [-] of the pressure profile's factor `(1 + b r^2/a^2)` at `x` in
    /// `(0, x_max]`, in `[-1, 0]` ([`ContactPatch`](crate::ContactPatch)). The default is 0 (no
    /// taper: `p0 (1 - r^2/a^2)^m`).
    fn pressure_taper(&self, x: f64) -> f64 {
        let _ = x;
        0.0
    }

    /// The law's name, kept by recordings: a recording stores a custom law as a sample of its
    /// curve ([`ContactLaw::recorded_curve`](crate::ContactLaw::recorded_curve)) under this
    /// name. The default is `custom`.
    fn name(&self) -> &str {
        "custom"
    }

    /// Shape and taper together, `(m, b)` at `x` in `(0, x_max]`: what
    /// [`ContactLaw::patch`](crate::ContactLaw::patch) asks for. The default is
    /// `(pressure_shape(x), pressure_taper(x))`; a level whose two share their work overrides
    /// it (it must return the same pair).
    fn pressure_profile(&self, x: f64) -> (f64, f64) {
        (self.pressure_shape(x), self.pressure_taper(x))
    }
}
