//! The full theory tabulated once per Poisson ratio and interpolated: the speed of the explicit
//! levels with the accuracy of the exact solve.

use super::neo_hookean::{NeoHookeanExact, Uniaxial};
use super::{NormalisedLaw, scale_by_chi};
use crate::quadrature::integrate;

/// Table spacing in x. The force interpolant is a cubic Hermite of `chi` with the exact `chi'`
/// at the nodes; its error is `h^4/384 max|chi''''|`, below 1e-9 relative over most of the range,
/// 1.5e-7 in the last cells before the limit point where `j(x)` nears its fold (tested
/// against the exact solve: force to 1e-6, stiffness to 3e-4 of its largest value (1.05e-4 seen at nu = 0.35); near the
/// limit point the stiffness falls steeply to a small value, which a coarser table misses).
const H: f64 = 1.0 / 1024.0;

/// `chi`, `chi'`, radius and energy at nodes `x_i = i H`, for `0 <= x <= x_max`.
///
/// The force law *is* the interpolant: stiffness is its exact derivative and the energy its
/// exact integral (Gauss-Legendre in `u = sqrt(x)` integrates `chi(u^2) u^4`, a polynomial of
/// degree 10, exactly), so an integrator sees a consistent law.
#[derive(Clone)]
pub(crate) struct NeoHookeanTable {
    /// `[chi, chi']` at the nodes.
    nodes: Vec<[f64; 2]>,
    /// Per cell, the Hermite cubic as `chi = c0 + c1 t + c2 t^2 + c3 t^3` in the cell's local
    /// coordinate `t` (the same polynomial, fewer operations per lookup).
    cells: Vec<[f64; 4]>,
    /// `a/R / sqrt(x)` at the nodes (smooth, 1 at x = 0), interpolated by Catmull-Rom.
    radius_ratio: Vec<f64>,
    /// Cumulative normalised energy at the nodes.
    energy: Vec<f64>,
    x_max: f64,
}

impl std::fmt::Debug for NeoHookeanTable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("NeoHookeanTable")
            .field("nodes", &self.nodes.len())
            .field("cells", &self.cells.len())
            .field("spacing", &H)
            .field("x_max", &self.x_max)
            .finish()
    }
}

impl NeoHookeanTable {
    /// Builds the table for `nu` in (-1, 0.5) (checked by the caller): about 920 solves plus
    /// the radius integrals (16 solves a node): about a millisecond.
    pub(crate) fn new(nu: f64) -> Self {
        let exact = NeoHookeanExact::new(nu);
        let uni: Uniaxial = exact.uniaxial;
        let x_max = exact.x_max();
        // One node past x_max so that the last cell is whole and Catmull-Rom has a neighbour.
        let n = (x_max / H).ceil() as usize + 2;
        let mut nodes = Vec::with_capacity(n + 1);
        let mut radius_ratio = Vec::with_capacity(n + 1);
        nodes.push([1.0, uni.dchi0()]);
        radius_ratio.push(1.0);
        for i in 1..=n {
            let x = i as f64 * H;
            let (c, d) = uni.chi(x);
            nodes.push([c, d]);
            radius_ratio.push(uni.radius(x) / x.sqrt());
        }
        let cells = nodes
            .windows(2)
            .map(|w| {
                let ([c0, d0], [c1, d1]) = (w[0], w[1]);
                let (d0, d1) = (d0 * H, d1 * H);
                // Hermite basis expanded in t.
                [
                    c0,
                    d0,
                    3.0 * (c1 - c0) - 2.0 * d0 - d1,
                    2.0 * (c0 - c1) + d0 + d1,
                ]
            })
            .collect();
        let mut table = Self {
            nodes,
            cells,
            radius_ratio,
            energy: vec![0.0; n + 1],
            x_max,
        };
        for i in 1..=n {
            let x0 = (i - 1) as f64 * H;
            table.energy[i] = table.energy[i - 1] + table.energy_in_cell(i - 1, x0, i as f64 * H);
        }
        table
    }

    /// Cell index and local coordinate `t` in [0, 1].
    #[inline]
    fn locate(&self, x: f64) -> (usize, f64) {
        // 1.5 * 2^52: adding it to a value v with |v| < 2^31 lands in [2^52, 2^53), where
        // the spacing of f64 is 1, so it rounds v to an integer held in the low 32 bits of the
        // mantissa; cheaper than the saturating f64 -> usize cast.
        const ROUND: f64 = 6_755_399_441_055_744.0;
        let s = x * (1.0 / H);
        // round(s - 1/2) is floor(s), or floor(s) - 1 at an exact integer (then t = 1, where
        // the cell's cubic equals the next node's value: either cell is right).
        let m = (s - 0.5) + ROUND;
        let i = (m.to_bits() as u32 as usize).min(self.cells.len() - 1);
        (i, s - i as f64)
    }

    /// Cubic Hermite `chi` and `chi'` in cell `i` at local coordinate `t`.
    #[inline]
    fn chi_at(&self, i: usize, t: f64) -> (f64, f64) {
        let [c0, c1, c2, c3] = self.cells[i];
        // Estrin's scheme: two independent halves, one multiply by t^2 (shorter dependency
        // chain than Horner on the hot path).
        let t2 = t * t;
        let chi = (c0 + c1 * t) + (c2 + c3 * t) * t2;
        let dchi = (c1 + 2.0 * c2 * t + 3.0 * c3 * t2) * (1.0 / H);
        (chi, dchi)
    }

    /// Energy of the interpolated law from `x0` to `x1`, both in cell `i`.
    fn energy_in_cell(&self, i: usize, x0: f64, x1: f64) -> f64 {
        let xi = i as f64 * H;
        integrate(x0.sqrt(), x1.sqrt(), 1, |u| {
            let s = u * u;
            let (chi, _) = self.chi_at(i, (s - xi) * (1.0 / H));
            8.0 / 3.0 * chi * s * s
        })
    }
}

impl NormalisedLaw for NeoHookeanTable {
    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        let (i, t) = self.locate(x);
        let (chi, dchi) = self.chi_at(i, t);
        scale_by_chi(x, chi, dchi)
    }

    fn energy(&self, x: f64) -> f64 {
        let (i, _) = self.locate(x);
        self.energy[i] + self.energy_in_cell(i, i as f64 * H, x)
    }

    fn radius(&self, x: f64) -> f64 {
        let (i, t) = self.locate(x);
        let r = &self.radius_ratio;
        // Catmull-Rom through r[i-1..=i+2]; at the first cell mirror the even function
        // a/(R sqrt(x)) = 1 + O(x) with a linear extrapolation.
        let p1 = r[i];
        let p2 = r[i + 1];
        let p0 = if i > 0 { r[i - 1] } else { 2.0 * p1 - p2 };
        let p3 = if i + 2 < r.len() {
            r[i + 2]
        } else {
            2.0 * p2 - p1
        };
        let ratio = p1
            + 0.5
                * t
                * (p2 - p0
                    + t * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + t * (3.0 * (p1 - p2) + p3 - p0)));
        ratio * x.sqrt()
    }

    fn x_max(&self) -> f64 {
        self.x_max
    }
}
