//! The `Auto` level: per call, the cheapest level whose known error against `calibrated` (the
//! most accurate level of the fingertip's construction: within its stated error of the finite
//! elements) is inside a force tolerance at that `x` ("model only what a scene needs"). So
//! `auto` at tolerance `tol` is within `tol` plus calibrated's own error of the FE truth.
//!
//! At construction (once per material and backing) the range `0 <= x <= x_max` of calibrated
//! is cut into cells of width 1/64; each cell gets the first of Hertz, fit (`k = 10/9`),
//! incompressible whose error against calibrated stays within half the tolerance at nine points
//! of the cell, else calibrated itself. Neighbouring cells with the same level merge into a
//! segment. Inside a segment the level's force is multiplied by the straight line `phi(x)` that
//! makes it equal calibrated at both ends of the segment: the law is then continuous (no force
//! jump where the level changes, so it stays monotone and an integrator sees no step), the
//! stiffness is the exact derivative `f_L' phi + f_L phi'`, and the energy the exact integral.
//! Correcting by a line at most doubles the raw error, hence the half tolerance; the tests check
//! the result against calibrated on a fine grid. The cheap levels are the free sphere's, so
//! with a backing (flat, core) they are never close enough and `auto` is calibrated.

use super::NormalisedLaw;
use super::backed::Backed;
use super::calibrated::Calibrated;
use super::fit::Fit;
use super::hertz::Hertz;
use super::incompressible::Incompressible;
use crate::level::{DEFAULT_FIT_K, LevelKind};
use crate::quadrature::integrate;

/// The reference of `Auto`: the most accurate level of the construction, `calibrated` (within
/// its stated error of the finite elements), so that `Auto` at tolerance `tol` is within `tol`
/// plus calibrated's own error of the FE truth.
#[derive(Debug, Clone)]
pub(crate) enum Reference {
    /// The free sphere's calibrated level.
    Free(Calibrated),
    /// A backed fingertip's calibrated level.
    Backed(Backed),
}

impl Reference {
    fn curve(&self) -> &dyn NormalisedLaw {
        match self {
            Reference::Free(c) => c,
            Reference::Backed(b) => b,
        }
    }

    fn kind(&self) -> LevelKind {
        LevelKind::Calibrated
    }
}

/// One candidate level.
#[derive(Debug, Clone)]
enum Candidate {
    Hertz,
    Fit(Fit),
    Incompressible,
    Reference(Reference),
}

impl Candidate {
    fn curve(&self) -> &dyn NormalisedLaw {
        match self {
            Candidate::Hertz => &Hertz,
            Candidate::Fit(f) => f,
            Candidate::Incompressible => &Incompressible,
            Candidate::Reference(r) => r.curve(),
        }
    }

    fn kind(&self) -> LevelKind {
        match self {
            Candidate::Hertz => LevelKind::Hertz,
            Candidate::Fit(_) => LevelKind::Fit,
            Candidate::Incompressible => LevelKind::Incompressible,
            Candidate::Reference(r) => r.kind(),
        }
    }

    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        // Static dispatch on the hot path.
        match self {
            Candidate::Hertz => super::hertz(x),
            Candidate::Fit(f) => f.force_stiffness(x),
            Candidate::Incompressible => Incompressible.force_stiffness(x),
            Candidate::Reference(Reference::Free(c)) => c.force_stiffness(x),
            Candidate::Reference(Reference::Backed(b)) => b.force_stiffness(x),
        }
    }
}

/// A range `[x_start, x_end]` served by one level, scaled by `phi(x) = a + b x`.
#[derive(Debug, Clone)]
struct Segment {
    x_end: f64,
    x_start: f64,
    candidate: Candidate,
    a: f64,
    b: f64,
    /// Energy at `x_start`.
    energy_start: f64,
}

/// The `Auto` level.
#[derive(Debug, Clone)]
pub(crate) struct Auto {
    segments: Vec<Segment>,
    reference: Reference,
}

/// Cell width of the selection.
const CELL: f64 = 1.0 / 64.0;

impl Auto {
    pub(crate) fn new(nu: f64, tolerance: f64, reference: Reference) -> Self {
        let x_max = reference.curve().x_max();
        let candidates = [
            Candidate::Hertz,
            Candidate::Fit(Fit::new(DEFAULT_FIT_K, nu)),
            Candidate::Incompressible,
        ];
        let ref_curve = reference.curve();
        let n_cells = (x_max / CELL).ceil() as usize;
        // (x_end, candidate index or None for the reference)
        let mut picks: Vec<(f64, Option<usize>)> = Vec::new();
        for c in 0..n_cells {
            let (x0, x1) = (c as f64 * CELL, ((c + 1) as f64 * CELL).min(x_max));
            let pick = candidates.iter().position(|cand| {
                cand.curve().x_max() >= x1
                    && (0..=8).all(|k| {
                        let x = (x0 + (x1 - x0) * k as f64 / 8.0).max(1e-6);
                        let r = cand.force_stiffness(x).0 / ref_curve.force_stiffness(x).0;
                        (r - 1.0).abs() <= 0.5 * tolerance
                    })
            });
            match picks.last_mut() {
                Some(last) if last.1 == pick => last.0 = x1,
                _ => picks.push((x1, pick)),
            }
        }
        let mut segments = Vec::with_capacity(picks.len());
        let mut x_start = 0.0;
        let mut energy_start = 0.0;
        for (x_end, pick) in picks {
            let candidate = match pick {
                Some(i) => candidates[i].clone(),
                None => Candidate::Reference(reference.clone()),
            };
            // phi equals f_ref / f_L at both ends; at x = 0 the ratio is chi_ref(0)/chi_L(0) = 1.
            let ratio = |x: f64| {
                if x <= 0.0 {
                    1.0
                } else {
                    ref_curve.force_stiffness(x).0 / candidate.force_stiffness(x).0
                }
            };
            let (r0, r1) = (ratio(x_start), ratio(x_end));
            let b = (r1 - r0) / (x_end - x_start);
            let a = r0 - b * x_start;
            let seg = Segment {
                x_end,
                x_start,
                candidate,
                a,
                b,
                energy_start,
            };
            energy_start += seg.energy_from_start(x_end);
            segments.push(seg);
            x_start = x_end;
        }
        Self {
            segments,
            reference,
        }
    }

    #[inline]
    fn segment(&self, x: f64) -> &Segment {
        self.segments
            .iter()
            .find(|s| x <= s.x_end)
            .unwrap_or_else(|| {
                self.segments
                    .last()
                    .expect("invariant: at least one segment")
            })
    }

    /// The level that serves compression ratio `x`.
    pub(crate) fn kind_at(&self, x: f64) -> LevelKind {
        self.segment(x).candidate.kind()
    }

    /// The segments as `(x_end, level)`, for documentation and tests.
    pub(crate) fn segments(&self) -> Vec<(f64, LevelKind)> {
        self.segments
            .iter()
            .map(|s| (s.x_end, s.candidate.kind()))
            .collect()
    }
}

impl Segment {
    /// `int_{x_start}^{x} f_L(s) (a + b s) ds`.
    fn energy_from_start(&self, x: f64) -> f64 {
        let curve = self.candidate.curve();
        let plain = curve.energy(x) - curve.energy(self.x_start);
        if self.b == 0.0 {
            return self.a * plain;
        }
        // First moment int s f_L(s) ds, in u = sqrt(s) where the integrand is smooth.
        let moment = integrate(self.x_start.sqrt(), x.sqrt(), 2, |u| {
            let s = u * u;
            2.0 * u * s * self.candidate.force_stiffness(s).0
        });
        self.a * plain + self.b * moment
    }
}

impl Auto {
    /// Force, stiffness and the level that served them, in one segment lookup.
    #[inline(always)]
    pub(crate) fn force_stiffness_kind(&self, x: f64) -> (f64, f64, LevelKind) {
        let s = self.segment(x);
        let (f, k) = s.candidate.force_stiffness(x);
        let phi = s.a + s.b * x;
        (f * phi, k * phi + f * s.b, s.candidate.kind())
    }
}

impl NormalisedLaw for Auto {
    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        let (f, k, _) = self.force_stiffness_kind(x);
        (f, k)
    }

    fn energy(&self, x: f64) -> f64 {
        let s = self.segment(x);
        s.energy_start + s.energy_from_start(x)
    }

    fn radius(&self, x: f64) -> f64 {
        // The reference's radius: continuous whatever level serves the force.
        self.reference.curve().radius(x)
    }

    fn pressure_shape(&self, x: f64) -> f64 {
        self.reference.curve().pressure_shape(x)
    }

    fn pressure_taper(&self, x: f64) -> f64 {
        self.reference.curve().pressure_taper(x)
    }

    fn pressure_profile(&self, x: f64) -> (f64, f64) {
        self.reference.curve().pressure_profile(x)
    }

    fn x_max(&self) -> f64 {
        self.reference.curve().x_max()
    }
}
