//! [`ContactLaw`]: a level of the law bound to one contact's E*, R and nu, in SI units.

use std::sync::Arc;

use crate::error::{Error, Result};
use crate::level::{Level, LevelKind};
use crate::levels::Normalised;
use crate::levels::auto::{Auto, Reference};
use crate::levels::calibrated::Calibrated;
use crate::levels::fit::Fit;
use crate::levels::hertz::Hertz;
use crate::levels::incompressible::Incompressible;
use crate::levels::linear::Linear;
use crate::levels::neo_hookean::NeoHookeanExact;
use crate::levels::nh_table::NeoHookeanTable;
use crate::levels::tatara::Tatara;
use crate::material::ContactParams;
use crate::pressure::ContactPatch;

/// Where a hot-path evaluation fell.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Regime {
    /// `delta <= 0`: no contact, zero force.
    Separated,
    /// Inside the level's validity range.
    Valid,
    /// Past the validity range: the documented extension was used (see [`ContactLaw::response`]).
    Extended,
    /// `delta` was NaN or infinite: zero force, counted by the caller.
    NonFinite,
}

/// Normal force and stiffness at one compression: all that a time step needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NormalResponse {
    /// Normal force F [N], >= 0.
    pub force: f64,
    /// Stiffness K = dF/d delta [N/m], >= 0: the exact derivative of `force`.
    pub stiffness: f64,
    /// Valid, extended, separated or non-finite input.
    pub regime: Regime,
    /// The level that computed it (for [`Level::Auto`], the one it picked).
    pub level: LevelKind,
}

/// Everything the law says about one compression (checked API).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactState {
    /// Compression delta [m].
    pub delta: f64,
    /// Compression ratio x = delta / R [-].
    pub x: f64,
    /// Normal force F [N].
    pub force: f64,
    /// Stiffness dF/d delta [N/m].
    pub stiffness: f64,
    /// Stored elastic energy W = integral of F d delta [J].
    pub energy: f64,
    /// Contact radius, mean and peak pressure.
    pub patch: ContactPatch,
    /// The level that computed it.
    pub level: LevelKind,
}

/// The chosen level, dispatched statically on the hot path.
#[derive(Debug, Clone)]
enum Curve {
    Linear(Linear),
    Hertz(Hertz),
    Fit(Fit),
    Incompressible(Incompressible),
    NeoHookean(Arc<NeoHookeanTable>),
    NeoHookeanExact(NeoHookeanExact),
    Tatara(Tatara),
    Calibrated(Calibrated),
    Auto(Arc<Auto>),
}

impl Curve {
    fn as_dyn(&self) -> &dyn Normalised {
        match self {
            Curve::Linear(c) => c,
            Curve::Hertz(c) => c,
            Curve::Fit(c) => c,
            Curve::Incompressible(c) => c,
            Curve::NeoHookean(c) => c.as_ref(),
            Curve::NeoHookeanExact(c) => c,
            Curve::Tatara(c) => c,
            Curve::Calibrated(c) => c,
            Curve::Auto(c) => c.as_ref(),
        }
    }

    /// Normalised force and stiffness inside the range, with the level that computed them.
    #[inline(always)]
    fn force_stiffness(&self, x: f64) -> (f64, f64, LevelKind) {
        let with = |(f, k): (f64, f64), kind| (f, k, kind);
        match self {
            Curve::Linear(c) => with(c.force_stiffness(x), LevelKind::Linear),
            Curve::Hertz(c) => with(c.force_stiffness(x), LevelKind::Hertz),
            Curve::Fit(c) => with(c.force_stiffness(x), LevelKind::Fit),
            Curve::Incompressible(c) => with(c.force_stiffness(x), LevelKind::Incompressible),
            Curve::NeoHookean(c) => with(c.force_stiffness(x), LevelKind::NeoHookean),
            Curve::NeoHookeanExact(c) => with(c.force_stiffness(x), LevelKind::NeoHookeanExact),
            Curve::Tatara(c) => with(c.force_stiffness(x), LevelKind::Tatara),
            Curve::Calibrated(c) => with(c.force_stiffness(x), LevelKind::Calibrated),
            Curve::Auto(c) => c.force_stiffness_kind(x),
        }
    }
}

/// Compression ratio past which the extension is frozen (see [`ContactLaw`]).
const X_FROZEN: f64 = 4.0;

/// The normalised law at the end of its validity range, where the extension starts.
#[derive(Debug, Clone, Copy)]
struct Edge {
    x: f64,
    f: f64,
    k: f64,
    w: f64,
    radius: f64,
}

/// One level of the contact law bound to a contact's parameters.
///
/// Two APIs:
/// - **Checked** ([`evaluate`](Self::evaluate), [`compression_for_force`](Self::compression_for_force)):
///   a typed [`Error`] for negative or non-finite input and for compressions past the level's
///   validity range `0 <= x <= x_max`.
/// - **Hot path** ([`response`](Self::response), [`energy`](Self::energy),
///   [`patch`](Self::patch)): never fails, never returns NaN. Past `x_max` it continues the law
///   by its tangent (the *extension*): `F = F(x_max) + K(x_max) (delta - delta_max)`, stiffness
///   `K(x_max)`, energy the matching quadratic, radius `a(x_max) sqrt(x / x_max)`. That is finite,
///   continuous with its first derivative, and monotonic (every level has `K(x_max) > 0`), and
///   the response says [`Regime::Extended`]. Past `x = 4` (twice the deepest compression a
///   sphere has: no real contact gets there, only a tunnelled or corrupt state) the extension is
///   frozen at its value at `x = 4` (`K = 0`), so every output stays finite for any finite input.
///
/// ```
/// use softgrip_law::{ContactLaw, ContactParams, Level, Material, Regime};
/// // A silicone fingertip, R = 10 mm, E = 3 MPa, nu = 0.49, squeezed to x = 0.5.
/// let m = Material::try_new(3.0e6, 0.49).unwrap();
/// let law = ContactLaw::try_new(ContactParams::try_new(m, 0.01).unwrap(), Level::fit()).unwrap();
/// let r = law.response(0.005);
/// let e_star = m.effective_modulus();
/// // chi_L(0.5) = 1/(1 - 5/9) = 2.25 times Hertz's (4/3) E* R^2 x^1.5
/// let hertz = 4.0 / 3.0 * e_star * 0.01f64.powi(2) * 0.5f64.powf(1.5);
/// assert!((r.force / (2.25 * hertz) - 1.0).abs() < 1e-12);
/// assert_eq!(r.regime, Regime::Valid);
/// assert_eq!(law.response(0.0095).regime, Regime::Extended); // x = 0.95 > x_max = 0.81
/// assert!(law.evaluate(0.0095).is_err());
/// ```
#[derive(Debug, Clone)]
pub struct ContactLaw {
    params: ContactParams,
    level: Level,
    curve: Curve,
    inv_radius: f64,
    /// E* R^2 [N]
    force_scale: f64,
    /// E* R [N/m]
    stiffness_scale: f64,
    edge: Edge,
}

impl ContactLaw {
    /// Binds `level` to `params`. Fails if the level's settings are invalid or the level cannot
    /// be used with this Poisson ratio (the compressible theory needs `nu < 0.5`).
    pub fn try_new(params: ContactParams, level: Level) -> Result<Self> {
        level.validate()?;
        let nu = params.poisson_ratio();
        let needs_compressible = |kind| {
            if nu < 0.5 {
                Ok(())
            } else {
                Err(Error::IncompatibleLevel {
                    level: kind,
                    nu,
                    reason: "the compressible neo-Hookean theory needs nu < 0.5 (use `incompressible` at nu = 0.5)",
                })
            }
        };
        let curve = match level {
            Level::Linear { match_x } => Curve::Linear(Linear::new(match_x)),
            Level::Hertz => Curve::Hertz(Hertz),
            Level::Fit { k } => Curve::Fit(Fit::new(k, nu)),
            Level::Incompressible => Curve::Incompressible(Incompressible),
            Level::NeoHookean => {
                needs_compressible(LevelKind::NeoHookean)?;
                Curve::NeoHookean(Arc::new(NeoHookeanTable::new(nu)))
            }
            Level::NeoHookeanExact => {
                needs_compressible(LevelKind::NeoHookeanExact)?;
                Curve::NeoHookeanExact(NeoHookeanExact::new(nu))
            }
            Level::Tatara => Curve::Tatara(Tatara::new(nu)),
            Level::Calibrated => Curve::Calibrated(Calibrated::try_new(nu)?),
            Level::Auto { tolerance } => {
                let reference = if nu < 0.5 {
                    Reference::Table(Arc::new(NeoHookeanTable::new(nu)))
                } else {
                    Reference::Incompressible
                };
                Curve::Auto(Arc::new(Auto::new(nu, tolerance, reference)))
            }
        };
        let c = curve.as_dyn();
        let x = c.x_max();
        let (f, k) = c.force_stiffness(x);
        let edge = Edge {
            x,
            f,
            k,
            w: c.energy(x),
            radius: c.radius(x),
        };
        let (e, r) = (params.effective_modulus(), params.radius());
        Ok(Self {
            params,
            level,
            curve,
            inv_radius: 1.0 / r,
            force_scale: e * r * r,
            stiffness_scale: e * r,
            edge,
        })
    }

    /// The contact's parameters.
    pub fn params(&self) -> &ContactParams {
        &self.params
    }

    /// The level, with its settings.
    pub fn level(&self) -> Level {
        self.level
    }

    /// Largest compression ratio of the validity range, `x_max` [-].
    pub fn x_max(&self) -> f64 {
        self.edge.x
    }

    /// Largest compression of the validity range, `x_max R` [m].
    pub fn delta_max(&self) -> f64 {
        self.edge.x * self.params.radius()
    }

    /// Force at the end of the validity range [N].
    pub fn force_max(&self) -> f64 {
        self.edge.f * self.force_scale
    }

    /// The level that serves compression ratio `x` (differs from the chosen level for `Auto`).
    pub fn kind_at(&self, x: f64) -> LevelKind {
        match (&self.curve, self.level) {
            (Curve::Auto(a), _) => a.kind_at(x.clamp(0.0, self.edge.x)),
            (_, Level::Linear { .. }) => LevelKind::Linear,
            (_, Level::Hertz) => LevelKind::Hertz,
            (_, Level::Fit { .. }) => LevelKind::Fit,
            (_, Level::Incompressible) => LevelKind::Incompressible,
            (_, Level::NeoHookean) => LevelKind::NeoHookean,
            (_, Level::NeoHookeanExact) => LevelKind::NeoHookeanExact,
            (_, Level::Tatara) => LevelKind::Tatara,
            (_, Level::Calibrated | Level::Auto { .. }) => LevelKind::Calibrated,
        }
    }

    /// For [`Level::Auto`]: the ranges of `x` and the level serving each, as `(x_end, level)`.
    /// Empty for the other levels.
    pub fn auto_segments(&self) -> Vec<(f64, LevelKind)> {
        match &self.curve {
            Curve::Auto(a) => a.segments(),
            _ => Vec::new(),
        }
    }

    /// Hot path: normal force and stiffness at compression `delta` [m] (> 0 in contact).
    ///
    /// Never fails and never returns NaN: `delta <= 0` is [`Regime::Separated`] (zero force),
    /// NaN or infinite `delta` is [`Regime::NonFinite`] (zero force), past `x_max` the
    /// extension is used ([`Regime::Extended`]). It does not compute the radius or pressure.
    #[inline(always)]
    pub fn response(&self, delta: f64) -> NormalResponse {
        let x = delta * self.inv_radius;
        // NaN fails both comparisons and goes to the cold path.
        if x > 0.0 && x <= self.edge.x {
            let (f, k, level) = self.curve.force_stiffness(x);
            return NormalResponse {
                force: f * self.force_scale,
                stiffness: k * self.stiffness_scale,
                regime: Regime::Valid,
                level,
            };
        }
        self.response_outside(x)
    }

    /// Separated, extended or non-finite: off the hot path.
    #[cold]
    fn response_outside(&self, x: f64) -> NormalResponse {
        let e = &self.edge;
        let (f, k, regime) = if !x.is_finite() {
            (0.0, 0.0, Regime::NonFinite)
        } else if x <= 0.0 {
            (0.0, 0.0, Regime::Separated)
        } else if x <= X_FROZEN {
            (e.f + e.k * (x - e.x), e.k, Regime::Extended)
        } else {
            (e.f + e.k * (X_FROZEN - e.x), 0.0, Regime::Extended)
        };
        NormalResponse {
            force: f * self.force_scale,
            stiffness: k * self.stiffness_scale,
            regime,
            level: self.kind_at(if x.is_finite() { x } else { 0.0 }),
        }
    }

    /// Stored elastic energy W(delta) [J], the exact integral of [`response`](Self::response)'s
    /// force (extension included); 0 when separated or for non-finite input.
    pub fn energy(&self, delta: f64) -> f64 {
        let x = delta * self.inv_radius;
        if !x.is_finite() || x <= 0.0 {
            return 0.0;
        }
        let e = &self.edge;
        let w = if x <= e.x {
            self.curve.as_dyn().energy(x)
        } else {
            let dx = x.min(X_FROZEN) - e.x;
            e.w + e.f * dx + 0.5 * e.k * dx * dx
        };
        w * self.force_scale * self.params.radius()
    }

    /// Contact radius and pressure at compression `delta` [m] (extension included; an empty
    /// patch when separated or for non-finite input). Costs more than the force: call it only
    /// when someone reads it.
    pub fn patch(&self, delta: f64) -> ContactPatch {
        let x = delta * self.inv_radius;
        if !x.is_finite() || x <= 0.0 {
            return ContactPatch::EMPTY;
        }
        let e = &self.edge;
        let rho = if x <= e.x {
            self.curve.as_dyn().radius(x)
        } else {
            e.radius * (x.min(X_FROZEN) / e.x).sqrt()
        };
        ContactPatch::new(self.response(delta).force, rho * self.params.radius())
    }

    /// Checked: the whole state at compression `delta` [m], finite and in
    /// `[0, delta_max]`; a typed error otherwise.
    pub fn evaluate(&self, delta: f64) -> Result<ContactState> {
        let x = self.checked_x(delta)?;
        let r = self.response(delta);
        debug_assert!(r.regime == Regime::Valid || r.regime == Regime::Separated);
        Ok(ContactState {
            delta,
            x,
            force: r.force,
            stiffness: r.stiffness,
            energy: self.energy(delta),
            patch: self.patch(delta),
            level: r.level,
        })
    }

    /// Checked: force and stiffness only, at compression `delta` [m] in `[0, delta_max]`.
    pub fn try_response(&self, delta: f64) -> Result<NormalResponse> {
        self.checked_x(delta)?;
        Ok(self.response(delta))
    }

    fn checked_x(&self, delta: f64) -> Result<f64> {
        if !(delta.is_finite() && delta >= 0.0) {
            return Err(Error::InvalidParameter {
                field: "delta",
                value: delta,
                range: "finite and >= 0 m",
            });
        }
        let x = delta * self.inv_radius;
        if x > self.edge.x {
            return Err(Error::OutOfRange {
                level: self.kind_at(x),
                x,
                x_max: self.edge.x,
            });
        }
        Ok(x)
    }

    /// Inverse: the compression delta [m] at which the law gives `force` [N] (finite, >= 0 and
    /// at most [`force_max`](Self::force_max)), to a relative accuracy of 1e-12.
    ///
    /// ```
    /// # use softgrip_law::{ContactLaw, ContactParams, Level, Material};
    /// let p = ContactParams::try_new(Material::try_new(3.0e6, 0.49).unwrap(), 0.01).unwrap();
    /// let law = ContactLaw::try_new(p, Level::NeoHookean).unwrap();
    /// let delta = law.compression_for_force(5.0).unwrap();
    /// assert!((law.response(delta).force / 5.0 - 1.0).abs() < 1e-12);
    /// ```
    pub fn compression_for_force(&self, force: f64) -> Result<f64> {
        if !(force.is_finite() && force >= 0.0) {
            return Err(Error::InvalidParameter {
                field: "force",
                value: force,
                range: "finite and >= 0 N",
            });
        }
        let f_target = force / self.force_scale;
        if f_target > self.edge.f {
            return Err(Error::ForceOutOfRange {
                level: self.kind_at(self.edge.x),
                force,
                force_max: self.force_max(),
                x_max: self.edge.x,
            });
        }
        if f_target == 0.0 {
            return Ok(0.0);
        }
        let x = match &self.curve {
            Curve::Tatara(t) => t.x_of_force(f_target),
            curve => {
                // Safeguarded Newton on f(x) = f_target in [0, x_max]; f is increasing.
                let (mut lo, mut hi) = (0.0, self.edge.x);
                let mut x = (0.75 * f_target).powf(2.0 / 3.0).min(hi);
                for _ in 0..200 {
                    let (f, k, _) = curve.force_stiffness(x);
                    if f < f_target {
                        lo = x;
                    } else {
                        hi = x;
                    }
                    let mut next = x - (f - f_target) / k;
                    if !(next > lo && next < hi) {
                        next = 0.5 * (lo + hi);
                    }
                    let done = (next - x).abs() <= 1e-14 * x || hi - lo <= 1e-15 * hi;
                    x = next;
                    if done {
                        break;
                    }
                }
                x
            }
        };
        Ok(x * self.params.radius())
    }
}
