//! Two fingertips in series: each pressed onto their rigid mid-surface by the same force.
//!
//! The law combines two soft bodies into one only when both are free spheres
//! (`ContactParams::try_combine_params`; a backed fingertip is refused with
//! `Error::IncompatibleBacking`, the combined Hertz radius having no meaning for a bonded pad).
//! When either fingertip of a touching pair is backed, the plugin presses each onto the rigid
//! surface midway between them, in series: the approach of their surfaces `delta` splits into
//! `delta_1 + delta_2 = delta` with `F_1(delta_1) = F_2(delta_2)`, each `F_i` the fingertip's
//! own law against a rigid body. The force of the pair is that common force, its stiffness
//! `K_1 K_2 / (K_1 + K_2)` (the exact derivative: `d delta = dF / K_1 + dF / K_2`), its
//! energy `W_1(delta_1) + W_2(delta_2)` (the exact integral: `dW = F d delta_1 + F d delta_2`).

use softgrip_law::{ContactLaw, ContactPatch, NormalisedLaw};

/// The series law of two fingertips' own laws, normalised by `E*_ref` \[Pa\] and `R_ref`
/// \[m\] (the pair's `ContactLaw::custom` parameters).
#[derive(Debug, Clone)]
pub(crate) struct SeriesLaw {
    pub first: ContactLaw,
    pub second: ContactLaw,
    /// `R_ref` \[m\].
    radius: f64,
    /// `E*_ref R_ref^2` \[N\].
    force_scale: f64,
    /// `x_max` of the pair [-]: the law's largest (4), so that past either fingertip's own
    /// range the pair stays the series of the two extended laws (`extended` flags it).
    x_max: f64,
}

impl SeriesLaw {
    /// The series law of `first` and `second`, normalised by `e_star` \[Pa\] and `radius`
    /// \[m\].
    pub(crate) fn new(first: ContactLaw, second: ContactLaw, e_star: f64, radius: f64) -> Self {
        Self {
            x_max: 4.0,
            first,
            second,
            radius,
            force_scale: e_star * radius * radius,
        }
    }

    /// Whether either fingertip's share of the approach `delta` \[m\] is past its own law's
    /// validity range (a validity excursion of the pair).
    pub(crate) fn extended(&self, delta: f64) -> bool {
        let (d1, d2) = self.split(delta);
        d1 > self.first.delta_max() || d2 > self.second.delta_max()
    }

    /// The split `(delta_1, delta_2)` \[m\] of an approach `delta` \[m\] (> 0) with equal forces,
    /// `delta_1 + delta_2 = delta`: a safeguarded Newton iteration on
    /// `g(d) = F_1(d) - F_2(delta - d)` (non-decreasing in `d`, `g(0) <= 0 <= g(delta)`),
    /// started at `delta / 2`, so identical fingertips split exactly in half (then `g = 0` at
    /// the start: `delta - delta/2 == delta/2` in floating point). Stops at a step of 1e-14
    /// `delta` or after 100 iterations; falls back to bisection where Newton leaves the bracket.
    pub(crate) fn split(&self, delta: f64) -> (f64, f64) {
        if !(delta > 0.0 && delta.is_finite()) {
            return (0.5 * delta, 0.5 * delta);
        }
        let (mut lo, mut hi) = (0.0, delta);
        let mut d = 0.5 * delta;
        for _ in 0..100 {
            let r1 = self.first.response(d);
            let r2 = self.second.response(delta - d);
            let g = r1.force - r2.force;
            if g == 0.0 {
                break;
            }
            if g < 0.0 {
                lo = d;
            } else {
                hi = d;
            }
            let k = r1.stiffness + r2.stiffness;
            let newton = d - g / k;
            let next = if k > 0.0 && newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            if (next - d).abs() <= 1e-14 * delta || hi - lo <= 1e-15 * delta {
                d = next;
                break;
            }
            d = next;
        }
        (d, delta - d)
    }

    /// Of the two patches at the pair's normalised approach `x`, the one of smaller radius
    /// (the one that slips first in torsion).
    fn narrower_patch(&self, x: f64) -> ContactPatch {
        let (d1, d2) = self.split(x * self.radius);
        let (p1, p2) = (self.first.patch(d1), self.second.patch(d2));
        if p1.radius <= p2.radius { p1 } else { p2 }
    }
}

impl NormalisedLaw for SeriesLaw {
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        let (d1, d2) = self.split(x * self.radius);
        let (r1, r2) = (self.first.response(d1), self.second.response(d2));
        let k_sum = r1.stiffness + r2.stiffness;
        let k = if k_sum > 0.0 {
            r1.stiffness * r2.stiffness / k_sum
        } else {
            0.0
        };
        // Both forces are equal at the split; their mean removes the iteration's residual.
        let f = 0.5 * (r1.force + r2.force);
        (f / self.force_scale, k * self.radius / self.force_scale)
    }

    fn energy(&self, x: f64) -> f64 {
        let (d1, d2) = self.split(x * self.radius);
        (self.first.energy(d1) + self.second.energy(d2)) / (self.force_scale * self.radius)
    }

    /// The smaller of the two patches' radii (the pair's torsion is limited by the patch
    /// that slips first).
    fn radius(&self, x: f64) -> f64 {
        self.narrower_patch(x).radius / self.radius
    }

    fn x_max(&self) -> f64 {
        self.x_max
    }

    /// The shape of the patch whose radius [`radius`](Self::radius) gives.
    fn pressure_shape(&self, x: f64) -> f64 {
        self.narrower_patch(x).shape
    }

    /// The taper of the same patch as [`pressure_shape`](Self::pressure_shape).
    fn pressure_taper(&self, x: f64) -> f64 {
        self.narrower_patch(x).taper
    }

    /// Shape and taper of that patch, from one split.
    fn pressure_profile(&self, x: f64) -> (f64, f64) {
        let p = self.narrower_patch(x);
        (p.shape, p.taper)
    }
}
