//! [`Model`]: the law and coefficients of one contact, a fingertip's own or a pair's.

use std::sync::Arc;

use nalgebra::Vector3;
use softgrip_law::{Backing, ContactLaw, ContactParams};

use crate::fingertip::SoftFingertip;
use crate::series::SeriesLaw;

/// The law and coefficients of one contact (a fingertip on a rigid body, or two fingertips).
#[derive(Debug, Clone)]
pub(crate) struct Model {
    pub law: ContactLaw,
    /// Hunt-Crossley dissipation coefficient `alpha` [s/m]: `F (1 + alpha d delta/dt)`.
    pub alpha: f64,
    pub friction: f64,
    /// Effective shear modulus G* of the pair \[Pa\], > 0: `1/G* = (2 - nu1)/G1 + (2 -
    /// nu2)/G2` (Mindlin; a rigid body's term is 0). The static friction spring's stiffness is
    /// `8 G* a` at contact radius `a` (`step`, `solve`).
    pub shear_modulus: f64,
    /// Torsional friction from the contact patch is on.
    pub torsion: bool,
    /// Effective radius R of the contact \[m\].
    pub radius: f64,
    /// Two fingertips: the readout reports the contact on both (`readout::assemble`).
    pub soft_pair: bool,
    /// Two fingertips of which one is backed, in series (`series`): the split of the
    /// approach and each fingertip's own model, for the readout.
    pub series: Option<Series>,
    /// The fingertip's construction (a combined pair of free fingertips: free).
    pub backing: Backing,
    /// The world direction of the patch's first semi-axis (`curvature::Touch::direction`);
    /// zero for a plane or a pair of fingertips (a disc: any tangent).
    pub patch_direction: Vector3<f64>,
}

/// The parts of a pair in series: its law (for the split) and the two fingertips' own models.
#[derive(Debug, Clone)]
pub(crate) struct Series {
    pub law: Arc<SeriesLaw>,
    /// The model of the pair's first fingertip (`Geom::tip`) against a rigid body.
    pub first: Arc<Model>,
    /// The model of its second fingertip (`Geom::other`).
    pub second: Arc<Model>,
}

impl Model {
    /// The Hunt-Crossley restitution at approach speed `v` \[m/s\], `v >= 0`:
    /// `e(v) = 1 - (2/3) alpha v`, clamped to \[0, 1\] (at most the body's speed back, never
    /// a negative one).
    pub(crate) fn restitution(&self, v: f64) -> f64 {
        (1.0 - 2.0 / 3.0 * self.alpha * v).clamp(0.0, 1.0)
    }

    pub(crate) fn of_tip(tip: &SoftFingertip) -> Self {
        Self {
            law: tip.law().clone(),
            alpha: tip.damping_alpha(),
            friction: tip.friction(),
            shear_modulus: shear_compliance(tip).recip(),
            torsion: tip.torsional_friction(),
            radius: tip.radius(),
            soft_pair: false,
            series: None,
            backing: tip.backing(),
            patch_direction: Vector3::zeros(),
        }
    }

    /// Two fingertips `a` and `b` (their own models `model_a`, `model_b`): the larger
    /// dissipation coefficient alpha and the geometric mean of the frictions; torsional
    /// friction only if both have it. Both free: one combined law (combined E*, R and nu,
    /// `ContactParams::try_combine`, `a`'s level). Either backed: the two own laws in series
    /// ([`SeriesLaw`]), normalised by `a`'s E* and the larger radius.
    pub(crate) fn of_pair(
        a: &SoftFingertip,
        b: &SoftFingertip,
        model_a: Arc<Model>,
        model_b: Arc<Model>,
    ) -> Option<Self> {
        let (law, radius, series) = if a.backing().is_free() && b.backing().is_free() {
            let p = ContactParams::try_combine(a.material(), a.radius(), b.material(), b.radius())
                .ok()?;
            (ContactLaw::try_new(p, a.level()).ok()?, p.radius(), None)
        } else {
            let radius = a.radius().max(b.radius());
            let reference = ContactParams::try_from_parts(
                a.material().effective_modulus(),
                radius,
                a.material().poisson_ratio(),
            )
            .ok()?;
            let series = Arc::new(SeriesLaw::new(
                model_a.law.clone(),
                model_b.law.clone(),
                reference.effective_modulus(),
                radius,
            ));
            let law = ContactLaw::custom(reference, series.clone()).ok()?;
            let parts = Series {
                law: series,
                first: model_a,
                second: model_b,
            };
            (law, radius, Some(parts))
        };
        Some(Self {
            alpha: a.damping_alpha().max(b.damping_alpha()),
            friction: (a.friction() * b.friction()).sqrt(),
            shear_modulus: (shear_compliance(a) + shear_compliance(b)).recip(),
            torsion: a.torsional_friction() && b.torsional_friction(),
            radius,
            soft_pair: true,
            series,
            law,
            backing: Backing::Free,
            patch_direction: Vector3::zeros(),
        })
    }
}

/// A fingertip's term `(2 - nu) / G` of Mindlin's effective shear compliance `1 / G*`
/// \[1/Pa\] (`G = E / (2 (1 + nu))` its shear modulus, `nu` its Poisson ratio).
fn shear_compliance(tip: &SoftFingertip) -> f64 {
    let m = tip.material();
    (2.0 - m.poisson_ratio()) / m.shear_modulus()
}
