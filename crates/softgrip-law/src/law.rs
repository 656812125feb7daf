//! [`ContactLaw`]: a level of the law bound to one contact's E*, R and nu, in SI units.

use std::sync::Arc;

use crate::backing::Backing;
use crate::cap_map::capped_on_counterpart;
use crate::core_map::core_on_counterpart;
use crate::counterpart::{Counterpart, CounterpartKind};
use crate::curve::{Curve, finite_non_negative};
use crate::error::{Error, Result};
use crate::extension::Extension;
use crate::level::{Level, LevelKind};
use crate::levels::NormalisedLaw;
use crate::levels::tabulated::Tabulated;
use crate::mapping::{CounterpartMap, reach};
use crate::material::ContactParams;
use crate::pressure::ContactPatch;
use crate::root::{Probe, Stop, newton_bracketed};
use crate::tabulated::TabulatedCurve;
use crate::tail::Tail;

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
    /// Normal force F \[N\], >= 0.
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
    /// Compression delta \[m\].
    pub delta: f64,
    /// Compression ratio x = delta / R [-].
    pub x: f64,
    /// Normal force F \[N\].
    pub force: f64,
    /// Stiffness dF/d delta [N/m].
    pub stiffness: f64,
    /// Stored elastic energy W = integral of F d delta \[J\].
    pub energy: f64,
    /// Contact radius, mean and peak pressure.
    pub patch: ContactPatch,
    /// The level that computed it.
    pub level: LevelKind,
}

pub(crate) use crate::normalised::X_FROZEN;

/// The normalised law at the end of its validity range, where the extension starts.
#[derive(Debug, Clone, Copy)]
struct Edge {
    x: f64,
    f: f64,
    k: f64,
    w: f64,
    radius: f64,
    shape: f64,
    taper: f64,
    /// The barrier past `x` ([`ContactLaw::response`]).
    ext: Extension,
}

impl Edge {
    /// The curve's values at its own compression ratio `x`, with the extension's wall at
    /// `wall` (the curve's own compression ratio).
    fn at(curve: &Curve, x: f64, wall: f64) -> Self {
        let c = curve.as_dyn();
        let (f, k, _) = curve.force_stiffness(x);
        let (shape, taper) = c.pressure_profile(x);
        let w = finite_non_negative(c.energy(x));
        Self {
            x,
            f,
            k,
            w,
            radius: finite_non_negative(c.radius(x)),
            shape,
            taper,
            ext: Extension::new(x, f, k, w, wall),
        }
    }

    /// The same edge with the extension's wall at `wall`.
    fn with_wall(self, wall: f64) -> Self {
        Self {
            ext: Extension::new(self.x, self.f, self.k, self.w, wall),
            ..self
        }
    }
}

/// Where the fingertip's geometry is lost, in `x = delta/R` [-]: its rigid part reaches the
/// surface it presses. A free sphere's centre (and a flat-backed hemisphere's rigid face, at
/// its centre) at `delta = R`, `x = 1`; a skin's rigid core at `delta = t`, `x = t/R`.
fn physical_wall(params: &ContactParams) -> f64 {
    params.thickness_ratio().unwrap_or(1.0)
}

/// One level of the contact law bound to a contact's parameters.
///
/// Two APIs:
/// - **Checked** ([`evaluate`](Self::evaluate), [`compression_for_force`](Self::compression_for_force)):
///   a typed [`Error`] for negative or non-finite input and for compressions past the level's
///   validity range `0 <= x <= x_max`.
/// - **Hot path** ([`response`](Self::response), [`energy`](Self::energy),
///   [`patch`](Self::patch)): never fails, never returns NaN. Past `x_max` it continues the law
///   by a barrier against a wall (the *extension*, [`Regime::Extended`]) that keeps a fixed
///   plane impenetrable. The wall [`x_wall`](Self::x_wall) is where the fingertip's rigid part
///   reaches the surface it presses: `x = 1` for a free sphere (its centre) and a flat-backed
///   hemisphere (its rigid face), `x = t/R` for a skin on a core; on a counterpart it is placed
///   in the mapped variable (`rho x`); a law whose range reaches within 10 % of it (a table or a
///   custom law to `x = 4`) gets its wall at `1.1 x_max`. In the curve's normalised units, with
///   `L = x_wall - x_max`, `u = (x - x_max)/L` and `c = f(x_max) + k(x_max) L`:
///   `f = f(x_max) + k(x_max)(x - x_max) + c u²/(1 - u)`, the stiffness its exact derivative
///   (`>= k(x_max) > 0`: monotone), the energy its exact integral (`c L (-ln(1-u) - u - u²/2)`
///   for the barrier term); continuous with its first derivative at `x_max`, and unbounded as
///   `u -> 1`. From `1e-6 L` short of the wall on, the barrier's tangent there takes over
///   (stiffness about `1e12 c/L`), so the wall itself and anything past it stay finite; past
///   `max(x_wall + L, 4)` (no real contact gets there, only a tunnelled or corrupt state) force
///   and energy are frozen (`K = 0`), so every output stays finite for any finite input. The
///   radius past `x_max` is `a(x_max) sqrt(x / x_max)` (frozen with the force); a counterpart's
///   terms continue by their tangent at the edge.
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
    /// `1/R` [1/m]: the compression ratio `x = delta/R` the API reports.
    inv_radius: f64,
    /// `rho/R` [1/m]: the curve's own compression ratio, `rho x` (`rho = 1` on a plane).
    x_scale: f64,
    /// `s E* R^2` \[N\] (`s = 1` on a plane)
    force_scale: f64,
    /// `s rho E* R` [N/m]
    stiffness_scale: f64,
    /// `R/rho` \[m\]: the energy is `w force_scale R/rho`.
    energy_length: f64,
    /// The counterpart's terms (`mapping`, `tail`): the force `t5 x^(5/2) + t7 x^(7/2) + t11 x^(11/2)` \[N\]
    /// subtracted from the mapped plane law (0 on a plane and an edge).
    tail: Tail,
    /// The counterpart and its map ([`with_counterpart`](Self::with_counterpart)).
    counterpart: Counterpart,
    map: CounterpartMap,
    /// Where the curve's validity ends, in the curve's own `x` (`edge.x` is the curve's
    /// `x_max` unless the counterpart's range ends first).
    edge: Edge,
}

impl ContactLaw {
    /// Binds the built-in `level` to `params`. Fails if the level's settings are invalid, if
    /// the level cannot be used with this Poisson ratio (the compressible theory needs
    /// `nu < 0.5`), or for [`Level::Tabulated`] and [`Level::Custom`], which need data
    /// ([`Error::LevelNeedsData`]: use [`tabulated`](Self::tabulated), [`custom`](Self::custom)).
    pub fn try_new(params: ContactParams, level: Level) -> Result<Self> {
        let curve = Curve::try_new(level, &params)?;
        Ok(Self::bind(params, level, curve))
    }

    /// The `tabulated` level: a user's measured squeeze curve (`delta` \[m\], `F` \[N\]) for this
    /// contact, interpolated by a monotone cubic Hermite (PCHIP) so that the force is
    /// non-decreasing and C1 through every sample; stiffness and energy are the exact derivative
    /// and integral of that interpolant, the radius is Hertz's radius of the measured force,
    /// `a = (3 F R / (4 E*))^(1/3)` (the force does not depend on `params`, the radius does,
    /// through E* and R). Valid to the table's last compression; past it the hot path extends
    /// by the barrier ([`Regime::Extended`], see [`response`](Self::response)) and the checked API returns
    /// [`Error::OutOfRange`].
    ///
    /// Fails if the table reaches past `x = delta/R = 4` or its values overflow once normalised
    /// by `params` ([`Error::InvalidTable`]).
    ///
    /// ```
    /// use softgrip_law::{ContactLaw, ContactParams, Material, Regime, TabulatedCurve};
    /// let tip = ContactParams::try_new(Material::try_new(3.0e6, 0.49)?, 0.010)?;
    /// // A measured squeeze: 1, 2, 3, 4 mm and the forces at them.
    /// let curve = TabulatedCurve::try_new(vec![0.001, 0.002, 0.003, 0.004], vec![1.3, 3.9, 7.6, 12.6])?;
    /// let law = ContactLaw::tabulated(tip, curve)?;
    /// assert!((law.response(0.002).force - 3.9).abs() < 1e-12); // through every sample
    /// let f = law.response(0.0025).force; // between them, monotone
    /// assert!(f > 3.9 && f < 7.6);
    /// assert_eq!(law.response(0.005).regime, Regime::Extended);
    /// assert!(law.evaluate(0.005).is_err()); // past the table's end
    /// # Ok::<(), softgrip_law::Error>(())
    /// ```
    pub fn tabulated(params: ContactParams, curve: TabulatedCurve) -> Result<Self> {
        let r = params.radius();
        let table = Tabulated::try_new(curve, params.effective_modulus() * r * r, r)?;
        Ok(Self::bind(
            params,
            Level::Tabulated,
            Curve::Tabulated(Arc::new(table)),
        ))
    }

    /// A user's own normalised law `law` bound to `params` ([`Level::Custom`]).
    ///
    /// Checked once: `x_max` finite in `(0, 4]`, and at 64 points of `(0, x_max]` the force,
    /// stiffness, energy and radius finite and `>= 0` and the force and energy non-decreasing
    /// ([`Error::InvalidCustomLaw`]); a sampled check, not a proof. On the hot path a value the
    /// law returns NaN, infinite or negative becomes 0. See [`NormalisedLaw`] for an example.
    pub fn custom(params: ContactParams, law: Arc<dyn NormalisedLaw>) -> Result<Self> {
        check_custom(law.as_ref())?;
        Ok(Self::bind(params, Level::Custom, Curve::Custom(law)))
    }

    fn bind(params: ContactParams, level: Level, curve: Curve) -> Self {
        let edge = Edge::at(&curve, curve.as_dyn().x_max(), physical_wall(&params));
        let (e, r) = (params.effective_modulus(), params.radius());
        Self {
            params,
            level,
            curve,
            inv_radius: 1.0 / r,
            x_scale: 1.0 / r,
            force_scale: e * r * r,
            stiffness_scale: e * r,
            energy_length: r,
            tail: Tail::ZERO,
            counterpart: Counterpart::PLANE,
            map: CounterpartMap::IDENTITY,
            edge,
        }
    }

    /// The same fingertip's law on `counterpart`: a plane (today's law, bit for bit), a
    /// curved surface (Hertz's ellipse at small x, the crate README's calibrated form at
    /// large x) or a sharp edge. Cheap (the plane law's scales change; a flat pad or a core on
    /// a curved counterpart builds its table once: `cargo bench -p softgrip-law --bench law --
    /// with_counterpart`), so a plugin can bind one per contact; the hot path then costs what
    /// the plane's does.
    ///
    /// Fails if a curved counterpart is more concave than the fingertip allows or too sharp
    /// ([`Error::IncompatibleCounterpart`], [`crate::MIN_RELATIVE_CURVATURE`],
    /// [`crate::MAX_RELATIVE_CURVATURE`]).
    ///
    /// Validity: in `x = delta/R`, where the FE of curved counterparts stops for the
    /// construction (0.70 free, 0.66 flat, and for a core also `0.6 t/R`), or where the plane
    /// law reaches its own `x_max` (at `rho x`), whichever comes first.
    ///
    /// ```
    /// use softgrip_law::{ContactLaw, ContactParams, Counterpart, Level, Material};
    /// let tip = ContactParams::try_new(Material::try_new(3.0e6, 0.49)?, 0.010)?;
    /// let hertz = ContactLaw::try_new(tip, Level::Hertz)?;
    /// // A ball of the fingertip's size: R_eff = R/2, Hertz's force 1/sqrt(2) of the plane's.
    /// let ball = hertz.with_counterpart(Counterpart::try_ball(0.010)?)?;
    /// let ratio = ball.response(1e-4).force / hertz.response(1e-4).force;
    /// assert!((ratio - 0.5f64.sqrt()).abs() < 1e-12);
    /// assert!((ball.patch(1e-4).radius - (0.005f64 * 1e-4).sqrt()).abs() < 1e-15);
    /// # Ok::<(), softgrip_law::Error>(())
    /// ```
    pub fn with_counterpart(&self, counterpart: Counterpart) -> Result<Self> {
        let p = &self.params;
        // The fingertip's own law takes the calibrated map; the published levels (baselines)
        // the patch argument alone.
        let calibrated = matches!(
            self.level,
            Level::Calibrated | Level::Auto { .. } | Level::Tabulated | Level::Custom
        );
        let map = CounterpartMap::try_new(
            &counterpart,
            p.radius(),
            p.poisson_ratio(),
            p.backing(),
            calibrated,
            // Only `calibrated`'s own plane forms carry the compressible cap (`cap_map`).
            matches!(self.level, Level::Calibrated),
        )?;
        // A skin on a core: its own curve on a curved counterpart (`core_map`); the free
        // sphere and the flat pad: the plane's with its compressible cap scaled (`cap_map`).
        // On an edge a core's curve is rebuilt too (session 18: its narrow patch feels the core
        // less, `core_map`), and the bonded pad's, at the edge's Poisson ratio (session 19).
        let was_rebuilt = matches!(self.level, Level::Calibrated)
            && match self.counterpart.kind() {
                CounterpartKind::Curved => true,
                CounterpartKind::Edge => {
                    matches!(p.backing(), Backing::Core { .. } | Backing::Flat)
                }
                CounterpartKind::Plane => false,
            };
        let (curve, map, replaced) =
            match core_on_counterpart(self.level, p, &map, counterpart.kind())? {
                Some((curve, map)) => (curve, map, true),
                None => match capped_on_counterpart(self.level, p, &map)? {
                    Some(curve) => (curve, map, true),
                    // Away from a curved counterpart: the plane's own curve again.
                    None if was_rebuilt => (Curve::try_new(self.level, p)?, map, true),
                    None => (self.curve.clone(), map, false),
                },
            };
        let (e, r) = (p.effective_modulus(), p.radius());
        let x_max = curve.as_dyn().x_max();
        // The curve's own range, in rho x, or the counterpart's reach in x, whichever ends
        // first; a plane keeps its own.
        let edge_x = if counterpart.is_plane() {
            x_max
        } else {
            let reach = reach(p.backing(), p.thickness_ratio()).min(map.reach);
            x_max.min(map.rho * reach)
        };
        // The wall where the fingertip's rigid part meets the counterpart, in the curve's x.
        let wall = map.rho * physical_wall(p);
        let edge = if edge_x == self.edge.x && !replaced {
            self.edge.with_wall(wall)
        } else {
            Edge::at(&curve, edge_x, wall)
        };
        let s = map.force;
        let law = Self {
            params: self.params,
            level: self.level,
            curve,
            inv_radius: 1.0 / r,
            x_scale: map.rho / r,
            force_scale: s * e * r * r,
            stiffness_scale: s * map.rho * e * r,
            energy_length: r / map.rho,
            tail: Tail {
                t5: map.tail[0] * e * r * r,
                t7: map.tail[1] * e * r * r,
                t11: map.tail[2] * e * r * r,
            },
            counterpart,
            map,
            edge,
        };
        Ok(law.without_softening())
    }

    /// The law with its range ended before its stiffness could vanish: the counterpart's
    /// finite-size term grows as `x^(5/2)` and, on a counterpart far smaller than the
    /// fingertip, overtakes the plane law's stiffening (no contact law may soften). 16 samples
    /// of the range, then bisection on the first sign change (to 1e-6 of the range); a dip
    /// between two stiff samples would be missed (the property tests check the monotonicity
    /// over random counterparts down to R2 = R/20).
    fn without_softening(mut self) -> Self {
        if !self.tail.may_soften() {
            return self;
        }
        const SAMPLES: u32 = 16;
        let top = self.delta_max();
        let soft = |d: f64| {
            let k = self.response(d).stiffness;
            k.is_nan() || k <= 0.0
        };
        let Some(i) = (1..=SAMPLES).find(|&i| soft(top * f64::from(i) / f64::from(SAMPLES))) else {
            return self;
        };
        let (mut lo, mut hi) = (
            top * f64::from(i - 1) / f64::from(SAMPLES),
            top * f64::from(i) / f64::from(SAMPLES),
        );
        while hi - lo > 1e-6 * top {
            let mid = 0.5 * (lo + hi);
            if soft(mid) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        // 5 % short of where it vanishes: the extension needs a positive stiffness.
        let edge_x = lo * self.x_scale;
        self.edge = Edge::at(&self.curve, 0.95 * edge_x, self.edge.ext.wall());
        self
    }

    /// The counterpart this law is bound to ([`Counterpart::PLANE`] unless set by
    /// [`with_counterpart`](Self::with_counterpart)).
    pub fn counterpart(&self) -> Counterpart {
        self.counterpart
    }

    /// For [`Level::Tabulated`]: the measured curve it was built from.
    pub fn tabulated_curve(&self) -> Option<&TabulatedCurve> {
        match &self.curve {
            Curve::Tabulated(t) => Some(t.curve()),
            _ => None,
        }
    }

    /// For [`Level::Custom`]: the user's law's [`NormalisedLaw::name`].
    pub fn custom_name(&self) -> Option<&str> {
        match &self.curve {
            Curve::Custom(law) => Some(law.name()),
            _ => None,
        }
    }

    /// The contact's parameters.
    pub fn params(&self) -> &ContactParams {
        &self.params
    }

    /// The level, with its settings.
    pub fn level(&self) -> Level {
        self.level
    }

    /// Largest compression ratio of the validity range, `x_max` [-] (`x = delta/R`).
    pub fn x_max(&self) -> f64 {
        self.edge.x / self.map.rho
    }

    /// Largest compression of the validity range, `x_max R` \[m\].
    pub fn delta_max(&self) -> f64 {
        let d = self.edge.x * self.params.radius() / self.map.rho;
        // On a counterpart, rounding can put `x_max R/rho` one ulp past the range once mapped
        // back by `rho/R` (seen on a bowl of 2R at nu = 0.49): step down so that
        // `evaluate(delta_max())` holds. A plane keeps its value bit for bit (recordings store it).
        if !self.counterpart.is_plane() && d * self.x_scale > self.edge.x {
            d.next_down()
        } else {
            d
        }
    }

    /// Compression ratio of the extension's wall, `x_wall` [-] (`x = delta/R`, `> x_max`):
    /// where the extension's barrier diverges, the fingertip's rigid part reaching the
    /// surface it presses (see [`response`](Self::response)).
    pub fn x_wall(&self) -> f64 {
        self.edge.ext.wall() / self.map.rho
    }

    /// Force at the end of the validity range \[N\].
    pub fn force_max(&self) -> f64 {
        let f = self.edge.f * self.force_scale;
        if self.tail.is_zero() {
            return f;
        }
        f - self.tail_at(self.edge.x / self.map.rho).0
    }

    /// The level that serves compression ratio `x` (differs from the chosen level for `Auto`).
    pub fn kind_at(&self, x: f64) -> LevelKind {
        self.kind_at_curve(x * self.map.rho)
    }

    /// [`kind_at`](Self::kind_at) in the curve's own compression ratio.
    fn kind_at_curve(&self, x: f64) -> LevelKind {
        match &self.curve {
            Curve::Auto(a) => a.kind_at(x.clamp(0.0, self.edge.x)),
            curve => curve.kind(),
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

    /// Hot path: normal force and stiffness at compression `delta` \[m\] (> 0 in contact).
    ///
    /// Never fails and never returns NaN: `delta <= 0` is [`Regime::Separated`] (zero force),
    /// NaN or infinite `delta` is [`Regime::NonFinite`] (zero force), past `x_max` the
    /// extension is used ([`Regime::Extended`]). It does not compute the radius or pressure.
    #[inline(always)]
    pub fn response(&self, delta: f64) -> NormalResponse {
        let x = delta * self.x_scale;
        // NaN fails both comparisons and goes to the cold path.
        if x > 0.0 && x <= self.edge.x {
            let (f, k, level) = self.curve.force_stiffness(x);
            let (mut force, mut stiffness) = (f * self.force_scale, k * self.stiffness_scale);
            if !self.tail.is_zero() {
                let (tf, tk) = self.tail_at(delta * self.inv_radius);
                force -= tf;
                stiffness -= tk;
            }
            return NormalResponse {
                force,
                stiffness,
                regime: Regime::Valid,
                level,
            };
        }
        self.response_outside(x)
    }

    /// The counterpart's terms at `x = delta/R`: their force \[N\] and stiffness \[N/m\].
    #[inline(always)]
    fn tail_at(&self, x: f64) -> (f64, f64) {
        self.tail.at(x, self.inv_radius)
    }

    /// Separated, extended or non-finite: off the hot path.
    #[cold]
    fn response_outside(&self, x: f64) -> NormalResponse {
        let e = &self.edge;
        let (f, k, regime) = if !x.is_finite() {
            (0.0, 0.0, Regime::NonFinite)
        } else if x <= 0.0 {
            (0.0, 0.0, Regime::Separated)
        } else {
            let (f, k) = e.ext.force_stiffness(x);
            (f, k, Regime::Extended)
        };
        let (mut force, mut stiffness) = (f * self.force_scale, k * self.stiffness_scale);
        if !self.tail.is_zero() && regime == Regime::Extended {
            // The tail extended by its tangent at the edge, frozen with the rest.
            let x_far = e.ext.x_far();
            let (xe, xc) = (e.x / self.map.rho, x.min(x_far) / self.map.rho);
            let (tf, tk) = self.tail_at(xe);
            let r = self.params.radius();
            force -= tf + tk * r * (xc - xe);
            if x <= x_far {
                stiffness -= tk;
            }
        }
        NormalResponse {
            force,
            stiffness,
            regime,
            level: self.kind_at_curve(if x.is_finite() { x } else { 0.0 }),
        }
    }

    /// Stored elastic energy W(delta) \[J\], the exact integral of [`response`](Self::response)'s
    /// force (extension included); 0 when separated or for non-finite input.
    pub fn energy(&self, delta: f64) -> f64 {
        let x = delta * self.x_scale;
        if !x.is_finite() || x <= 0.0 {
            return 0.0;
        }
        let e = &self.edge;
        let w = if x <= e.x {
            finite_non_negative(self.curve.as_dyn().energy(x))
        } else {
            e.ext.energy(x)
        };
        let energy = w * self.force_scale * self.energy_length;
        if self.tail.is_zero() {
            return energy;
        }
        // The tail's integral, and past the edge its tangent's.
        let r = self.params.radius();
        let x_far = e.ext.x_far();
        let (xp, xe) = (x.min(x_far) / self.map.rho, e.x / self.map.rho);
        let inside = xp.min(xe);
        let mut w_tail = self.tail.integral(inside, r);
        if xp > xe {
            let (tf, tk) = self.tail_at(xe);
            let d = xp - xe;
            w_tail += r * (tf * d + 0.5 * tk * r * d * d);
        }
        energy - w_tail
    }

    /// Contact radius and pressure at compression `delta` \[m\] (extension included; an empty
    /// patch when separated or for non-finite input). Costs more than the force: call it only
    /// when someone reads it.
    pub fn patch(&self, delta: f64) -> ContactPatch {
        let x = delta * self.x_scale;
        if !x.is_finite() || x <= 0.0 {
            return ContactPatch::EMPTY;
        }
        let e = &self.edge;
        let rho = if x <= e.x {
            finite_non_negative(self.curve.as_dyn().radius(x))
        } else {
            e.radius * (x.min(e.ext.x_far()) / e.x).sqrt()
        };
        let (m, b) = if x <= e.x {
            self.curve.as_dyn().pressure_profile(x)
        } else {
            (e.shape, e.taper)
        };
        let a = rho * self.params.radius();
        let force = self.response(delta).force;
        if self.counterpart.is_plane() {
            ContactPatch::with_profile(force, a, m, b)
        } else {
            // The counterpart's shrink of each semi-axis, frozen at the range's edge.
            let xs = (delta * self.inv_radius).min(e.x / self.map.rho);
            let [c1, c2] = self.map.axes;
            let [s1, s2] = self.map.shrink;
            ContactPatch::with_ellipse(
                force,
                [c1 * a * (1.0 - s1 * xs), c2 * a * (1.0 - s2 * xs)],
                m,
                b,
            )
        }
    }

    /// Checked: the whole state at compression `delta` \[m\], finite and in
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

    /// Checked: force and stiffness only, at compression `delta` \[m\] in `[0, delta_max]`.
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
        if delta * self.x_scale > self.edge.x {
            return Err(Error::OutOfRange {
                level: self.kind_at(x),
                x,
                x_max: self.x_max(),
            });
        }
        Ok(x)
    }

    /// Inverse: the compression delta \[m\] at which the law gives `force` \[N\] (finite, >= 0 and
    /// at most [`force_max`](Self::force_max)). The Newton iteration stops at a step of 1e-14
    /// in x: the force of the result is usually within 1e-12 (relative) of `force`, but the law
    /// fuzz target (tests/fuzz_law.rs) has seen misses up to 1.3e-8 (e.g. F = 1.2e-2 N on one
    /// of its random laws) and asserts 1e-6 over hostile inputs; below 1e-12 of
    /// [`force_max`](Self::force_max) the error is absolute (about 1e-19 N was seen).
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
        let beyond = if self.tail.is_zero() {
            f_target > self.edge.f
        } else {
            force > self.force_max()
        };
        if beyond {
            return Err(Error::ForceOutOfRange {
                level: self.kind_at_curve(self.edge.x),
                force,
                force_max: self.force_max(),
                x_max: self.x_max(),
            });
        }
        if f_target == 0.0 {
            return Ok(0.0);
        }
        if !self.tail.is_zero() {
            return Ok(self.compression_with_tail(force));
        }
        let x = match &self.curve {
            Curve::Tatara(t) => t.x_of_force(f_target),
            curve => {
                // Safeguarded Newton on f(x) = f_target in [0, x_max]; f is non-decreasing.
                let hi = self.edge.x;
                let start = (0.75 * f_target).powf(2.0 / 3.0).min(hi);
                let stop = Stop {
                    step: 1e-14,
                    width: Some(1e-15),
                    max_iterations: 200,
                };
                newton_bracketed(0.0, hi, start, stop, |x| {
                    let (f, k, _) = curve.force_stiffness(x);
                    Probe {
                        below_root: f < f_target,
                        step: (f - f_target) / k,
                    }
                })
            }
        };
        Ok(x * self.params.radius() / self.map.rho)
    }

    /// The inverse with the counterpart's tail: safeguarded Newton in delta on the total
    /// force (non-decreasing on the range: `with_counterpart` ends the range before the
    /// stiffness could vanish), `0 < force <= force_max`.
    fn compression_with_tail(&self, force: f64) -> f64 {
        let hi = self.delta_max();
        let r = self.params.radius();
        // Hertz's compression of the force, for a start.
        let hertz = (0.75 * force / (self.force_scale * self.map.force)).powf(2.0 / 3.0) * r;
        let stop = Stop {
            step: 1e-14,
            width: Some(1e-15),
            max_iterations: 200,
        };
        newton_bracketed(0.0, hi, hertz.min(hi), stop, |d| {
            let resp = self.response(d);
            Probe {
                below_root: resp.force < force,
                step: (resp.force - force) / resp.stiffness,
            }
        })
    }
}

/// The checks of [`ContactLaw::custom`].
fn check_custom(law: &dyn NormalisedLaw) -> Result<()> {
    let bad = |quantity, x, value, range| {
        Err(Error::InvalidCustomLaw {
            quantity,
            x,
            value,
            range,
        })
    };
    let x_max = law.x_max();
    if !(x_max > 0.0 && x_max <= X_FROZEN) {
        return bad("x_max", x_max, x_max, "finite and in (0, 4]");
    }
    const POINTS: u32 = 64;
    let (mut f_prev, mut w_prev) = (0.0, 0.0);
    for i in 1..=POINTS {
        let x = x_max * f64::from(i) / f64::from(POINTS);
        let (f, k) = law.force_stiffness(x);
        let (w, a) = (law.energy(x), law.radius(x));
        for (quantity, v) in [("force", f), ("stiffness", k), ("energy", w), ("radius", a)] {
            if !(v.is_finite() && v >= 0.0) {
                return bad(quantity, x, v, "finite and >= 0");
            }
        }
        if f < f_prev {
            return bad("force", x, f, "non-decreasing in x");
        }
        if w < w_prev {
            return bad("energy", x, w, "non-decreasing in x");
        }
        (f_prev, w_prev) = (f, w);
    }
    Ok(())
}
