//! The `tabulated` level: a user's measured squeeze curve ([`crate::TabulatedCurve`]),
//! normalised by the contact's E* and R and interpolated by a monotone cubic Hermite.
//!
//! - **Force**: on each cell `[x_i, x_{i+1}]` the cubic Hermite through `(x_i, f_i)` and
//!   `(x_{i+1}, f_{i+1})` with slopes `d_i` (PCHIP, as MATLAB's `pchip` and SciPy's
//!   `PchipInterpolator`): at an interior node the weighted harmonic mean of the two secants,
//!   `d_i = (w1 + w2) / (w1/s_{i-1} + w2/s_i)`, `w1 = 2h_i + h_{i-1}`, `w2 = h_i + 2h_{i-1}`,
//!   and 0 where either secant is 0 (Fritsch & Butland 1984); at the last node the one-sided
//!   three-point formula, clamped to `[0, 3 s]`. Every slope is then in `[0, 3 s]` of its
//!   cells, Fritsch & Carlson's (1980) sufficient condition for a monotone cubic: the force is
//!   non-decreasing, C1, and passes through every sample.
//! - **`ORIGIN_SLOPE`: `d_0 = 0`** (PCHIP would use the end formula there). A sphere's contact
//!   starts with zero stiffness (Hertz: `K ~ sqrt(delta)`), and its `f ~ x^(3/2)` has an
//!   infinite curvature at the origin that no cubic follows: with the end formula the first
//!   cell starts as a linear spring, 16 % too stiff at half the first sample (and unboundedly
//!   so towards 0); with `d_0 = 0` it is 3-4 % low there, and the force error over the whole
//!   range halves (Hertz or `calibrated` sampled at 50-65 equal steps: 3-4 % in the first cell,
//!   2 % in the second, 1.4e-4 from x = 0.05 on, `tests/tabulated.rs`). A curve that starts
//!   linearly (a preloaded or flat pad) is then 25 % low in the first half cell: sample the
//!   first cells densely.
//! - **Stiffness**: the exact derivative of that cubic (continuous at the nodes).
//! - **Energy**: its exact integral, `h (c0 t + c1 t²/2 + c2 t³/3 + c3 t⁴/4)` in a cell plus the
//!   cumulative energy at the cell's start.
//! - **Radius**: Hertz's radius of the measured force, `a = (3 F R / (4 E*))^(1/3)`, i.e.
//!   `a/R = (3f/4)^(1/3)` (Eq. 2 with Eq. 5 solved for `delta`). A squeeze curve has no radius in
//!   it; this one is exact where Hertz is, grows with the measured force (a stiffer-than-Hertz
//!   tip gets a wider patch than `sqrt(R delta)`, as the large-deformation levels do), and needs
//!   only the E* of the material the user gave. It is the radius Tatara's law uses too.
//! - **Validity**: `0 <= x <= x_max`, the last sample; past it the law's generic tangent
//!   extension ([`crate::Regime::Extended`]).

use super::NormalisedLaw;
use crate::Shortest;
use crate::error::{Error, Result};
use crate::normalised::X_FROZEN;
use crate::tabulated::TabulatedCurve;

/// One cell: the cubic `f = c0 + c1 t + c2 t² + c3 t³` in `t = (x - x0) / h`.
#[derive(Debug, Clone, Copy)]
struct Cell {
    x0: f64,
    h: f64,
    inv_h: f64,
    c: [f64; 4],
    /// Energy at `x0`.
    energy0: f64,
}

impl Cell {
    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        let [c0, c1, c2, c3] = self.c;
        let t = (x - self.x0) * self.inv_h;
        let f = c0 + t * (c1 + t * (c2 + t * c3));
        let k = (c1 + t * (2.0 * c2 + 3.0 * t * c3)) * self.inv_h;
        // Both are >= 0 exactly (monotone cubic); keep rounding from making them -0.0 or -1e-30.
        (f.max(0.0), k.max(0.0))
    }

    fn energy(&self, x: f64) -> f64 {
        self.energy_at((x - self.x0) * self.inv_h)
    }

    /// Energy at local coordinate `t`: `h ∫₀ᵗ p`.
    fn energy_at(&self, t: f64) -> f64 {
        let [c0, c1, c2, c3] = self.c;
        self.energy0 + self.h * t * (c0 + t * (0.5 * c1 + t * (c2 / 3.0 + t * (0.25 * c3))))
    }
}

/// The tabulated level, in normalised units.
#[derive(Debug, Clone)]
pub(crate) struct Tabulated {
    /// Upper ends of the cells `x_1 .. x_n` (for the lookup).
    ends: Vec<f64>,
    cells: Vec<Cell>,
    /// The curve as given, in SI units.
    curve: TabulatedCurve,
}

impl Tabulated {
    /// Normalises `curve` by `force_scale = E* R²` \[N\] and `radius = R` \[m\].
    pub(crate) fn try_new(curve: TabulatedCurve, force_scale: f64, radius: f64) -> Result<Self> {
        // x as the hot path computes it (`delta * (1/R)`), so that a sample's delta is a node.
        let inv_radius = 1.0 / radius;
        let x: Vec<f64> = curve.delta_m().iter().map(|d| d * inv_radius).collect();
        let f: Vec<f64> = curve.force_n().iter().map(|v| v / force_scale).collect();
        let x_max = x[x.len() - 1];
        if x_max > X_FROZEN || x_max.is_nan() {
            return Err(Error::InvalidTable {
                field: "delta_m",
                index: Some(x.len() - 1),
                value: curve.delta_max(),
                range: format!("<= 4 R = {} m (x = delta/R <= 4)", Shortest(4.0 * radius)),
            });
        }
        if let Some(i) = f.iter().position(|v| !v.is_finite()) {
            return Err(Error::InvalidTable {
                field: "force_n",
                index: Some(i),
                value: curve.force_n()[i],
                range: format!(
                    "finite once divided by E* R^2 = {} N",
                    Shortest(force_scale)
                ),
            });
        }
        if let Some(i) = (1..x.len()).find(|&i| x[i] <= x[i - 1]) {
            return Err(Error::InvalidTable {
                field: "delta_m",
                index: Some(i),
                value: curve.delta_m()[i],
                range: format!(
                    "distinct from delta_m[{}] once divided by R = {} m",
                    i - 1,
                    Shortest(radius)
                ),
            });
        }
        let cells = build_cells(&x, &f);
        if let Some(i) = cells.iter().position(|c| !cell_is_finite(c)) {
            return Err(Error::InvalidTable {
                field: "delta_m",
                index: Some(i + 1),
                value: curve.delta_m()[i + 1],
                range: "spaced so that the force's slope between samples is finite".into(),
            });
        }
        Ok(Self {
            ends: x[1..].to_vec(),
            cells,
            curve,
        })
    }

    /// The curve as given.
    pub(crate) fn curve(&self) -> &TabulatedCurve {
        &self.curve
    }

    /// The cell holding `x`: cell `i` for `x_i <= x < x_{i+1}` (a node starts its cell, where
    /// the cubic is exactly the sample), the last one from `x_max` on.
    #[inline]
    fn cell(&self, x: f64) -> &Cell {
        let i = self.ends.partition_point(|&end| end <= x);
        &self.cells[i.min(self.cells.len() - 1)]
    }
}

fn cell_is_finite(c: &Cell) -> bool {
    c.inv_h.is_finite() && c.energy0.is_finite() && c.c.iter().all(|v| v.is_finite())
}

/// The PCHIP slopes at the nodes (see the module docs).
fn slopes(x: &[f64], f: &[f64]) -> Vec<f64> {
    let n = x.len();
    let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
    let s: Vec<f64> = (0..n - 1).map(|i| (f[i + 1] - f[i]) / h[i]).collect();
    let mut d = vec![0.0; n];
    for i in 1..n - 1 {
        if s[i - 1] > 0.0 && s[i] > 0.0 {
            let (w1, w2) = (2.0 * h[i] + h[i - 1], h[i] + 2.0 * h[i - 1]);
            d[i] = (w1 + w2) / (w1 / s[i - 1] + w2 / s[i]);
        }
    }
    // d[0] = 0: see `ORIGIN_SLOPE` in the module docs. The last node: the one-sided
    // three-point formula over the last cell (h0, s0) and the one before (h1, s1).
    let (h0, h1, s0, s1) = (h[n - 2], h[n - 3], s[n - 2], s[n - 3]);
    d[n - 1] = (((2.0 * h0 + h1) * s0 - h0 * s1) / (h0 + h1)).clamp(0.0, 3.0 * s0);
    d
}

/// The Hermite cells, with their cumulative energy. Needs at least 3 nodes.
fn build_cells(x: &[f64], f: &[f64]) -> Vec<Cell> {
    let d = slopes(x, f);
    let mut energy0 = 0.0;
    let mut cells = Vec::with_capacity(x.len() - 1);
    for i in 0..x.len() - 1 {
        let h = x[i + 1] - x[i];
        let (f0, f1) = (f[i], f[i + 1]);
        let (d0, d1) = (d[i] * h, d[i + 1] * h);
        // The Hermite basis expanded in t.
        let c = [
            f0,
            d0,
            3.0 * (f1 - f0) - 2.0 * d0 - d1,
            2.0 * (f0 - f1) + d0 + d1,
        ];
        let cell = Cell {
            x0: x[i],
            h,
            inv_h: 1.0 / h,
            c,
            energy0,
        };
        energy0 = cell.energy_at(1.0);
        cells.push(cell);
    }
    cells
}

impl NormalisedLaw for Tabulated {
    #[inline]
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        self.cell(x).force_stiffness(x)
    }

    fn energy(&self, x: f64) -> f64 {
        self.cell(x).energy(x)
    }

    fn radius(&self, x: f64) -> f64 {
        (0.75 * self.force_stiffness(x).0).cbrt()
    }

    fn x_max(&self) -> f64 {
        self.ends[self.ends.len() - 1]
    }
}
