//! [`Curve`]: the level a [`crate::ContactLaw`] holds, dispatched statically on the hot path.
//!
//! The built-in levels are enum arms (their `force_stiffness` inlines into
//! [`crate::ContactLaw::response`]); a user's [`NormalisedLaw`] is one more arm behind an `Arc`,
//! called through its vtable.

use std::sync::Arc;

use crate::error::{Error, Result};
use crate::level::{Level, LevelKind};
use crate::levels::NormalisedLaw;
use crate::levels::auto::{Auto, Reference};
use crate::levels::backed::Backed;
use crate::levels::calibrated::Calibrated;
use crate::levels::fit::Fit;
use crate::levels::hertz::Hertz;
use crate::levels::incompressible::Incompressible;
use crate::levels::linear::Linear;
use crate::levels::neo_hookean::NeoHookeanExact;
use crate::levels::nh_table::NeoHookeanTable;
use crate::levels::tabulated::Tabulated;
use crate::levels::tatara::Tatara;
use crate::material::ContactParams;

/// The chosen level.
#[derive(Debug, Clone)]
pub(crate) enum Curve {
    Linear(Linear),
    Hertz(Hertz),
    Fit(Fit),
    Incompressible(Incompressible),
    NeoHookean(Arc<NeoHookeanTable>),
    NeoHookeanExact(NeoHookeanExact),
    Tatara(Tatara),
    Calibrated(Calibrated),
    Backed(Backed),
    Auto(Arc<Auto>),
    Tabulated(Arc<Tabulated>),
    Custom(Arc<dyn NormalisedLaw>),
}

impl Curve {
    /// The built-in level `level` for `params` (its Poisson ratio and backing), validated.
    ///
    /// With a backing other than free, `calibrated` (and `auto`'s reference) is the backed
    /// construction's own law; every other level is the free sphere's.
    pub(crate) fn try_new(level: Level, params: &ContactParams) -> Result<Self> {
        level.validate()?;
        let nu = params.poisson_ratio();
        let backing = params.backing();
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
        Ok(match level {
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
            Level::Calibrated if backing.is_free() => Curve::Calibrated(Calibrated::try_new(nu)?),
            Level::Calibrated => {
                Curve::Backed(Backed::try_new(backing, params.thickness_ratio(), nu)?)
            }
            Level::Auto { tolerance } => {
                let reference = if backing.is_free() {
                    Reference::Free(Calibrated::try_new(nu)?)
                } else {
                    Reference::Backed(Backed::try_new(backing, params.thickness_ratio(), nu)?)
                };
                Curve::Auto(Arc::new(Auto::new(nu, tolerance, reference)))
            }
            Level::Tabulated => {
                return Err(Error::LevelNeedsData {
                    level: LevelKind::Tabulated,
                    hint: "build it from a measured curve with `ContactLaw::tabulated(params, curve)`",
                });
            }
            Level::Custom => {
                return Err(Error::LevelNeedsData {
                    level: LevelKind::Custom,
                    hint: "build it from your `NormalisedLaw` with `ContactLaw::custom(params, law)`",
                });
            }
        })
    }

    pub(crate) fn as_dyn(&self) -> &dyn NormalisedLaw {
        match self {
            Curve::Linear(c) => c,
            Curve::Hertz(c) => c,
            Curve::Fit(c) => c,
            Curve::Incompressible(c) => c,
            Curve::NeoHookean(c) => c.as_ref(),
            Curve::NeoHookeanExact(c) => c,
            Curve::Tatara(c) => c,
            Curve::Calibrated(c) => c,
            Curve::Backed(c) => c,
            Curve::Auto(c) => c.as_ref(),
            Curve::Tabulated(c) => c.as_ref(),
            Curve::Custom(c) => c.as_ref(),
        }
    }

    /// The level of every `x` (for `Auto`, the reference's; use [`Auto::kind_at`]).
    pub(crate) fn kind(&self) -> LevelKind {
        match self {
            Curve::Linear(_) => LevelKind::Linear,
            Curve::Hertz(_) => LevelKind::Hertz,
            Curve::Fit(_) => LevelKind::Fit,
            Curve::Incompressible(_) => LevelKind::Incompressible,
            Curve::NeoHookean(_) => LevelKind::NeoHookean,
            Curve::NeoHookeanExact(_) => LevelKind::NeoHookeanExact,
            Curve::Tatara(_) => LevelKind::Tatara,
            Curve::Calibrated(_) | Curve::Backed(_) | Curve::Auto(_) => LevelKind::Calibrated,
            Curve::Tabulated(_) => LevelKind::Tabulated,
            Curve::Custom(_) => LevelKind::Custom,
        }
    }

    /// Normalised force and stiffness inside the range, with the level that computed them.
    #[inline(always)]
    pub(crate) fn force_stiffness(&self, x: f64) -> (f64, f64, LevelKind) {
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
            Curve::Backed(c) => with(c.force_stiffness(x), LevelKind::Calibrated),
            Curve::Auto(c) => c.force_stiffness_kind(x),
            Curve::Tabulated(c) => with(c.force_stiffness(x), LevelKind::Tabulated),
            Curve::Custom(c) => with(custom_force_stiffness(c.as_ref(), x), LevelKind::Custom),
        }
    }
}

/// A user's law on the hot path: a NaN, infinite or negative force or stiffness becomes 0, so
/// nothing non-finite reaches the engine (the law's checks at construction make that rare).
#[inline(never)]
fn custom_force_stiffness(law: &dyn NormalisedLaw, x: f64) -> (f64, f64) {
    let (f, k) = law.force_stiffness(x);
    (finite_non_negative(f), finite_non_negative(k))
}

/// `v` if finite and `>= 0`, else 0.
pub(crate) fn finite_non_negative(v: f64) -> f64 {
    if v.is_finite() && v >= 0.0 { v } else { 0.0 }
}
