//! [`SoftFingertip`]: the validated parameters of one soft fingertip, and its builder.

use std::sync::Mutex;

use softgrip_law::{Backing, ContactLaw, ContactParams, Level, Material};

use crate::error::{Error, Result};
use crate::presets::Preset;
use crate::tactile::{TactileGrid, TactilePad};

/// Default coefficient of restitution e [-] (see [`SoftFingertipBuilder::restitution`]).
pub const DEFAULT_RESTITUTION: f64 = 0.5;
/// Default Coulomb friction coefficient mu_f [-]: silicone on dry rigid surfaces is 0.5 to
/// above 1; 0.8 is a middle value.
pub const DEFAULT_FRICTION: f64 = 0.8;
/// Default reference impact speed v_ref [m/s] at which the restitution e holds (see
/// [`SoftFingertipBuilder::restitution_speed`]).
pub const DEFAULT_RESTITUTION_SPEED: f64 = 1.0;

/// Smallest fingertip radius R \[m\] (1 nm): rapier holds the ball's radius, mass and inertia
/// in `f32` (an inertia ~ rho R^5 underflows below this).
pub const MIN_RADIUS: f64 = 1.0e-9;
/// Largest fingertip radius R \[m\] (1 km): rapier's `f32` ball radius, mass and inertia stay
/// finite (a radius of 1e39 m was an infinite `f32` radius and a panic at registration).
pub const MAX_RADIUS: f64 = 1.0e3;
/// Largest Young's modulus E \[Pa\] of a fingertip (10 TPa, ten times diamond): the law's force
/// `~ E R^2` must stay within rapier's `f32` impulses.
pub const MAX_YOUNGS_MODULUS: f64 = 1.0e13;
/// Range of the reference impact speed v_ref [m/s]: the damping `alpha = zeta / v_ref` must
/// stay finite.
pub const RESTITUTION_SPEED_RANGE: (f64, f64) = (1.0e-6, 1.0e6);
/// Largest Coulomb friction coefficient mu_f [-].
pub const MAX_FRICTION: f64 = 1.0e3;

/// A soft spherical fingertip: radius, material, law level, restitution and friction.
///
/// Validated once by [`SoftFingertipBuilder::build`]; the fields are private, so an invalid
/// fingertip cannot exist. It carries its [`ContactLaw`] (for contacts with rigid bodies).
///
/// ```
/// use softgrip_rapier::{Preset, SoftFingertip};
/// let tip = SoftFingertip::builder(0.01).preset(Preset::DragonSkin30).build().unwrap();
/// assert_eq!(tip.radius(), 0.01);
/// assert_eq!(tip.restitution(), 0.5);
/// assert!(SoftFingertip::builder(-0.01).preset(Preset::DragonSkin30).build().is_err());
/// ```
#[derive(Debug, Clone)]
pub struct SoftFingertip {
    name: String,
    radius: f64,
    material: Material,
    level: Level,
    restitution: f64,
    restitution_speed: f64,
    friction: f64,
    torsional_friction: bool,
    law: ContactLaw,
    damping_zeta: f64,
    tactile: Option<TactileGrid>,
    backing: Backing,
    facing: Option<[f64; 3]>,
}

impl SoftFingertip {
    /// Starts a builder for a fingertip of radius `radius` R \[m\], in
    /// [[`MIN_RADIUS`], [`MAX_RADIUS`]] (checked by [`SoftFingertipBuilder::build`]).
    pub fn builder(radius: f64) -> SoftFingertipBuilder {
        SoftFingertipBuilder {
            name: String::from("fingertip"),
            radius,
            material: None,
            level: Level::auto(),
            law: None,
            restitution: DEFAULT_RESTITUTION,
            restitution_speed: DEFAULT_RESTITUTION_SPEED,
            friction: DEFAULT_FRICTION,
            torsional_friction: true,
            tactile: None,
            backing: Backing::Free,
            facing: None,
        }
    }

    /// The fingertip's name (for readouts and logs).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Radius R \[m\].
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The elastic material.
    pub fn material(&self) -> Material {
        self.material
    }

    /// The level of the law.
    pub fn level(&self) -> Level {
        self.level
    }

    /// Coefficient of restitution e [-], in (0, 1], of an impact at
    /// [`restitution_speed`](Self::restitution_speed).
    pub fn restitution(&self) -> f64 {
        self.restitution
    }

    /// Reference impact speed v_ref [m/s] at which the restitution is `e`.
    pub fn restitution_speed(&self) -> f64 {
        self.restitution_speed
    }

    /// Coulomb friction coefficient mu_f [-], >= 0.
    pub fn friction(&self) -> f64 {
        self.friction
    }

    /// Whether the contact patch resists twist about the normal, up to the integral of
    /// `mu_f p r dA` over the law's patch (`ContactPatch::torsion_limit`; `(3 pi / 16) mu_f F a`
    /// for Hertz's pressure shape).
    pub fn torsional_friction(&self) -> bool {
        self.torsional_friction
    }

    /// The contact law against a rigid body (for a backed fingertip, the law of its
    /// construction: see [`SoftFingertipBuilder::backing`]).
    pub fn law(&self) -> &ContactLaw {
        &self.law
    }

    /// How the fingertip is built ([`Backing::Free`] unless set by
    /// [`SoftFingertipBuilder::backing`]).
    pub fn backing(&self) -> Backing {
        self.backing
    }

    /// For a backed fingertip ([`Backing::Flat`], [`Backing::Core`]): the unit direction its
    /// pad faces, from the flat face towards the pole, in its collider's frame (its body's
    /// axes for a collider without a rotation of its own). `None` for a free fingertip.
    pub fn facing(&self) -> Option<[f64; 3]> {
        self.facing
    }

    /// The tactile pad, if the fingertip has one
    /// ([`SoftFingertipBuilder::tactile`]): its image is
    /// [`SoftContacts::tactile_image`](crate::SoftContacts::tactile_image).
    pub fn tactile(&self) -> Option<&TactileGrid> {
        self.tactile.as_ref()
    }

    /// Dimensionless Hunt-Crossley damping `zeta = alpha v_ref` [-] that gives the restitution
    /// e at v_ref (see [`hunt_crossley_zeta`]).
    pub fn damping_zeta(&self) -> f64 {
        self.damping_zeta
    }

    /// Hunt-Crossley dissipation coefficient `alpha = zeta(e) / v_ref` [s/m]: the contact force
    /// is `F (1 + alpha d delta/dt)`. A material constant, independent of the contact's history
    /// (0 for e = 1).
    pub fn damping_alpha(&self) -> f64 {
        self.damping_zeta / self.restitution_speed
    }
}

/// The dimensionless Hunt-Crossley damping `zeta = alpha v_in` for which a Hertz impact
/// `m x'' = -k x^(3/2) (1 + alpha x')` at the speed `v_in` rebounds with restitution `e` (0 for
/// e >= 1).
///
/// For a power-law force the rebound ratio depends on `alpha v_in` alone, so it is found once,
/// by bisection on the normalised impact `x'' = -x^(3/2) (1 + zeta x')`, `x(0) = 0`,
/// `x'(0) = 1` (RK4). Flores et al. (2011)'s closed form `zeta = 8 (1 - e) / (5 e)` is an
/// approximation of this root: at e = 0.5 it gives a rebound of 0.466 instead of 0.5.
///
/// ```
/// use softgrip_rapier::hunt_crossley_zeta;
/// assert_eq!(hunt_crossley_zeta(1.0), 0.0);
/// let z = hunt_crossley_zeta(0.5);
/// assert!(z > 0.0 && z < 8.0 * 0.5 / (5.0 * 0.5)); // less damping than Flores' closed form
/// ```
pub fn hunt_crossley_zeta(e: f64) -> f64 {
    if !(e < 1.0) {
        return 0.0;
    }
    let e = e.max(1e-3);
    // A pure function of `e` that costs a few ms (48 RK4 impacts): every scene parse, check
    // and build of a fingertip asks for it (a sweep's trials did so 3 times each: 20-26 % of
    // a trial's CPU time), so the last few answers are kept (bit for bit the same answer).
    static CACHE: Mutex<Vec<(u64, f64)>> = Mutex::new(Vec::new());
    let key = e.to_bits();
    if let Ok(cache) = CACHE.lock()
        && let Some(&(_, z)) = cache.iter().find(|(k, _)| *k == key)
    {
        return z;
    }
    let z = hunt_crossley_root(e);
    if let Ok(mut cache) = CACHE.lock() {
        if cache.len() >= 16 {
            cache.remove(0);
        }
        cache.push((key, z));
    }
    z
}

/// The rebound ratio of the normalised impact `x'' = -x^(3/2) (1 + zeta x')`, `x(0) = 0`,
/// `x'(0) = 1` (RK4, h = 2e-3, the exit velocity interpolated linearly at `x = 0`).
fn hunt_crossley_rebound(zeta: f64) -> f64 {
    let acc = |x: f64, v: f64| -x.max(0.0).powf(1.5) * (1.0 + zeta * v);
    let (mut x, mut v, h) = (0.0f64, 1.0f64, 2e-3);
    for _ in 0..200_000 {
        let (k1x, k1v) = (v, acc(x, v));
        let (k2x, k2v) = (v + 0.5 * h * k1v, acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v));
        let (k3x, k3v) = (v + 0.5 * h * k2v, acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v));
        let (k4x, k4v) = (v + h * k3v, acc(x + h * k3x, v + h * k3v));
        let (xn, vn) = (
            x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x),
            v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v),
        );
        if xn <= 0.0 {
            // Linear interpolation of the exit velocity at x = 0.
            let s = x / (x - xn);
            return -(v + s * (vn - v));
        }
        if vn <= 0.0 && xn < 1e-12 {
            return 0.0;
        }
        x = xn;
        v = vn;
    }
    0.0
}

/// The root `zeta` of `rebound(zeta) = e` (decreasing in `zeta`) by bisection, bracketed by 0
/// and twice Flores' closed form plus one, 48 halvings.
fn hunt_crossley_root(e: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, 2.0 * 8.0 * (1.0 - e) / (5.0 * e) + 1.0);
    for _ in 0..48 {
        let mid = 0.5 * (lo + hi);
        if hunt_crossley_rebound(mid) > e {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Builder of a [`SoftFingertip`] (rapier's builder style).
#[derive(Debug, Clone)]
pub struct SoftFingertipBuilder {
    name: String,
    radius: f64,
    material: Option<Material>,
    level: Level,
    law: Option<ContactLaw>,
    restitution: f64,
    restitution_speed: f64,
    friction: f64,
    torsional_friction: bool,
    tactile: Option<TactilePad>,
    backing: Backing,
    facing: Option<[f64; 3]>,
}

impl SoftFingertipBuilder {
    /// The elastic material (validated by `softgrip_law::Material::try_new`).
    pub fn material(mut self, material: Material) -> Self {
        self.material = Some(material);
        self
    }

    /// A literature material (see [`Preset`]).
    pub fn preset(mut self, preset: Preset) -> Self {
        self.material = Some(preset.material());
        self
    }

    /// The level of the law; default `Level::auto()`.
    pub fn level(mut self, level: Level) -> Self {
        self.level = level;
        self
    }

    /// A contact law built by the caller, e.g. `ContactLaw::tabulated` from a measured squeeze
    /// curve or `ContactLaw::custom` with a user's own `NormalisedLaw`. It replaces
    /// [`level`](Self::level); the law's radius must equal the fingertip's (to 1e-9 relative)
    /// and a [`material`](Self::material) is still required (it gives the damping and the
    /// patch). The fingertip reports `law.level()` (`Level::Tabulated` or `Level::Custom`).
    pub fn law(mut self, law: ContactLaw) -> Self {
        self.law = Some(law);
        self
    }

    /// Coefficient of restitution e [-], in (0, 1], of an impact on a rigid body at the
    /// reference speed [`restitution_speed`](Self::restitution_speed) (default 1 m/s);
    /// default 0.5 (a soft silicone fingertip hitting a rigid object at ~1 m/s loses roughly
    /// half of its rebound speed). e = 1 is purely elastic.
    ///
    /// The dissipation is Hunt-Crossley's `F (1 + alpha d delta/dt)` with the material
    /// constant `alpha = zeta(e) / v_ref` [s/m] ([`hunt_crossley_zeta`]), as Drake's
    /// Hunt-Crossley dissipation: the damping does not depend on how the contact started, so a
    /// slow squeeze reads the elastic law (at 5 mm/s and e = 0.5 the damping adds
    /// `alpha v = 0.3 %`). The restitution then varies with the impact speed v, as measured for
    /// rubbers: `e(v) ~ 1 - (2/3) alpha v` for small `alpha v` (larger at slower impacts).
    pub fn restitution(mut self, restitution: f64) -> Self {
        self.restitution = restitution;
        self
    }

    /// Reference impact speed v_ref [m/s] (in [1e-6, 1e6] m/s; default 1 m/s) at which an impact on
    /// a rigid body rebounds with the [`restitution`](Self::restitution) e.
    pub fn restitution_speed(mut self, speed: f64) -> Self {
        self.restitution_speed = speed;
        self
    }

    /// Coulomb friction coefficient mu_f [-], in [0, 1e3]; default 0.8.
    pub fn friction(mut self, friction: f64) -> Self {
        self.friction = friction;
        self
    }

    /// Torsional friction of the contact patch (default on): twist about the contact normal is
    /// resisted up to the moment of Coulomb friction under the law's pressure profile,
    /// `ContactPatch::torsion_limit` = the integral of `mu_f p r dA` over the contact radius `a`
    /// (`(3 pi / 16) mu_f F a` for Hertz's shape, `2/3 mu_f F a` for a uniform pressure). Off,
    /// a point contact that cannot resist twist (for comparison).
    pub fn torsional_friction(mut self, enabled: bool) -> Self {
        self.torsional_friction = enabled;
        self
    }

    /// A tactile sensor pad: after every step the plugin integrates the pressure of the
    /// fingertip's contacts over each taxel ([`crate::TactileImage`]); without one nothing is
    /// computed. Checked by [`build`](Self::build) (`tactile.*` fields).
    pub fn tactile(mut self, pad: TactilePad) -> Self {
        self.tactile = Some(pad);
        self
    }

    /// How the fingertip is built (default [`Backing::Free`], a whole soft sphere): a
    /// [`Backing::Flat`] hemisphere bonded at its flat face to a rigid finger, or a
    /// [`Backing::Core`] skin of thickness `t` \[m\] (in (0, R)) over a rigid core. Its law
    /// against a rigid body is then that construction's (`ContactParams::with_backing`: the
    /// `calibrated` level, and `auto`'s reference, are the backed law; the other levels compute
    /// the free sphere's). A backed fingertip needs [`facing`](Self::facing).
    ///
    /// Only the pole side is soft. A contact whose direction from the fingertip's centre
    /// towards the other body has a negative component along `facing` (behind the flat face:
    /// the finger's side) is a rigid contact: rapier's own solver handles it (the fingertip's
    /// ball behaves there as a rigid ball), it has no soft readout row and no tactile pressure.
    /// Two fingertips of which one is backed are pressed in series onto their rigid
    /// mid-surface: see the crate README ("Backed fingertips").
    pub fn backing(mut self, backing: Backing) -> Self {
        self.backing = backing;
        self
    }

    /// The direction the pad of a backed fingertip faces, from its flat face towards its pole,
    /// in its collider's frame (its body's axes for a collider without a rotation of its own):
    /// finite and non-zero (normalised by [`build`](Self::build)). Required for
    /// [`Backing::Flat`] and [`Backing::Core`]; checked but not used for a free fingertip.
    pub fn facing(mut self, direction: [f64; 3]) -> Self {
        self.facing = Some(direction);
        self
    }

    /// A name for readouts.
    pub fn name(mut self, name: impl Into<String>) -> Self {
        self.name = name.into();
        self
    }

    /// Checks the radius, restitution, restitution speed, friction and Young's modulus
    /// against their ranges (the first out of range: `Error::InvalidParameter`).
    fn check_numbers(&self) -> Result<()> {
        let invalid = |field, value, range| {
            Err(Error::InvalidParameter {
                field,
                value,
                range,
            })
        };
        if !(self.radius.is_finite() && (MIN_RADIUS..=MAX_RADIUS).contains(&self.radius)) {
            return invalid("radius", self.radius, "in [1e-9, 1e3] m");
        }
        if !(self.restitution > 0.0 && self.restitution <= 1.0) {
            return invalid("restitution", self.restitution, "in (0, 1]");
        }
        let (lo, hi) = RESTITUTION_SPEED_RANGE;
        if !(self.restitution_speed.is_finite() && (lo..=hi).contains(&self.restitution_speed)) {
            return invalid(
                "restitution_speed",
                self.restitution_speed,
                "in [1e-6, 1e6] m/s",
            );
        }
        if !(self.friction.is_finite() && (0.0..=MAX_FRICTION).contains(&self.friction)) {
            return invalid("friction", self.friction, "in [0, 1e3]");
        }
        if let Some(m) = self.material
            && m.youngs_modulus() > MAX_YOUNGS_MODULUS
        {
            return invalid(
                "material.youngs_modulus",
                m.youngs_modulus(),
                "finite, > 0 and <= 1e13 Pa",
            );
        }
        Ok(())
    }

    /// Validates everything and binds the law.
    pub fn build(self) -> Result<SoftFingertip> {
        self.check_numbers()?;
        let tactile = self
            .tactile
            .map(|pad| pad.validate(self.radius))
            .transpose()?;
        let facing = match self.facing {
            Some(d) => Some(unit_facing(d)?),
            None if self.backing.is_free() => None,
            None => return Err(Error::MissingFacing(self.backing.name())),
        };
        let material = self.material.ok_or(Error::MissingMaterial)?;
        let law = match self.law {
            Some(law) => {
                let backing = law.params().backing();
                if !backing.is_free() && backing != self.backing {
                    return Err(Error::BackingMismatch {
                        fingertip: self.backing.to_string(),
                        law: backing.to_string(),
                    });
                }
                let r = law.params().radius();
                if (r - self.radius).abs() > 1e-9 * self.radius {
                    return Err(Error::InvalidParameter {
                        field: "law.radius",
                        value: r,
                        range: "equal to the fingertip's radius (1e-9 relative) m",
                    });
                }
                law
            }
            None => ContactLaw::try_new(
                ContactParams::try_new(material, self.radius)?.with_backing(self.backing)?,
                self.level,
            )?,
        };
        Ok(SoftFingertip {
            name: self.name,
            radius: self.radius,
            material,
            level: law.level(),
            restitution: self.restitution,
            restitution_speed: self.restitution_speed,
            friction: self.friction,
            torsional_friction: self.torsional_friction,
            law,
            damping_zeta: hunt_crossley_zeta(self.restitution),
            tactile,
            backing: self.backing,
            facing: if self.backing.is_free() { None } else { facing },
        })
    }
}

/// `d` normalised: finite components and a norm > 0 (and finite), else the error naming
/// `facing` with the offending number (a non-finite component, or the norm).
fn unit_facing(d: [f64; 3]) -> Result<[f64; 3]> {
    const RANGE: &str = "a finite, non-zero direction [x, y, z] in the collider's frame";
    if let Some(bad) = d.iter().find(|v| !v.is_finite()) {
        return Err(Error::InvalidParameter {
            field: "facing",
            value: *bad,
            range: RANGE,
        });
    }
    let norm = d.iter().map(|v| v * v).sum::<f64>().sqrt();
    if !(norm > 0.0 && norm.is_finite()) {
        return Err(Error::InvalidParameter {
            field: "facing",
            value: norm,
            range: RANGE,
        });
    }
    Ok(d.map(|v| v / norm))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cached root is the computed one, bit for bit (1.432750527280168 at e = 0.5, the
    /// value a Python port of the same RK4 and bisection gives), on the first call and the
    /// next, and its rebound is e.
    #[test]
    fn hunt_crossley_zeta_is_cached_bit_for_bit() {
        let z = hunt_crossley_zeta(0.5);
        assert!((z - 1.432750527280168).abs() < 1e-12, "{z}");
        assert_eq!(hunt_crossley_zeta(0.5).to_bits(), z.to_bits());
        assert_eq!(hunt_crossley_root(0.5).to_bits(), z.to_bits());
        assert!((hunt_crossley_rebound(z) - 0.5).abs() < 1e-10);
        for e in [0.05, 0.3, 0.9, 0.999] {
            let z = hunt_crossley_zeta(e);
            assert!(
                (hunt_crossley_rebound(z) - e).abs() < 1e-9,
                "e {e}: zeta {z}"
            );
        }
    }
}
