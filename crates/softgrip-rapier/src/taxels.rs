//! [`TactileImage`]: the taxel pressures of a fingertip's pad after a step, and the integral
//! of a contact's Hertz-shaped pressure over each taxel (see `tactile` for the geometry).

use std::sync::OnceLock;

use rapier3d::prelude::ColliderHandle;

use crate::tactile::TactileGrid;
use crate::tip_contact::TipContact;

/// Mean pressure \[Pa\] of each taxel of a fingertip's pad over the last step, row-major
/// (row 0 at the pad's top, `v = +height/2`; column 0 at its left, `u = -width/2`).
///
/// ```
/// use softgrip_rapier::{Preset, SoftFingertip, TactileImage, TactilePad};
/// let pad = TactilePad::new(4, 4, [0.0, -1.0, 0.0], 0.008, 0.008);
/// let tip = SoftFingertip::builder(0.01).preset(Preset::DragonSkin30).tactile(pad).build().unwrap();
/// let mut image = TactileImage::new(*tip.tactile().unwrap());
/// image.add_disc([0.0, 0.0], 0.002, 1.5); // 1.5 N over a = 2 mm at the centre
/// assert!((image.total_force() / 1.5 - 1.0).abs() < 1e-6);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct TactileImage {
    grid: TactileGrid,
    pressure: Vec<f64>,
}

impl TactileImage {
    /// A zero image of `grid`.
    pub fn new(grid: TactileGrid) -> Self {
        let n = grid.rows() as usize * grid.columns() as usize;
        Self {
            grid,
            pressure: vec![0.0; n],
        }
    }

    /// The pad's grid.
    pub fn grid(&self) -> &TactileGrid {
        &self.grid
    }

    /// Mean pressure of every taxel \[Pa\], `>= 0`, row-major (`rows x columns` values).
    pub fn pressure(&self) -> &[f64] {
        &self.pressure
    }

    /// Mean pressure \[Pa\] of the taxel at `row`, `column` (0 outside the grid).
    pub fn at(&self, row: u32, column: u32) -> f64 {
        if row >= self.grid.rows() || column >= self.grid.columns() {
            return 0.0;
        }
        self.pressure[row as usize * self.grid.columns() as usize + column as usize]
    }

    /// `Σ taxel pressure x taxel area` \[N\]: the normal force on the pad.
    pub fn total_force(&self) -> f64 {
        self.pressure.iter().sum::<f64>() * self.grid.taxel_area()
    }

    /// Pressure-weighted mean of the taxel centres, pad coordinates `(u, v)` \[m\]; `None` for
    /// an empty image.
    pub fn centroid(&self) -> Option<[f64; 2]> {
        let (mut s, mut su, mut sv) = (0.0, 0.0, 0.0);
        for r in 0..self.grid.rows() {
            for c in 0..self.grid.columns() {
                let p = self.at(r, c);
                let [u, v] = self.grid.taxel_center(r, c);
                s += p;
                su += p * u;
                sv += p * v;
            }
        }
        (s > 0.0).then(|| [su / s, sv / s])
    }

    /// Sets every taxel to 0.
    pub fn clear(&mut self) {
        self.pressure.fill(0.0);
    }

    /// Adds the law's Hertz-shaped pressure `p(ρ) = (3/2) F/(π a²) sqrt(1 - ρ²/a²)` of a
    /// contact of normal force `force` \[N\] and radius `radius` a \[m\], centred at pad
    /// coordinates `center` \[m\]; nothing unless `force` and `radius` are finite and > 0.
    /// Only the taxels under the disc are visited.
    pub fn add_disc(&mut self, center: [f64; 2], radius: f64, force: f64) {
        let a = radius;
        if !(a > 0.0 && a.is_finite() && force > 0.0 && force.is_finite()) {
            return;
        }
        let g = self.grid;
        let (du, dv) = (g.taxel_width(), g.taxel_height());
        let (half_w, half_h) = (0.5 * g.pad().width, 0.5 * g.pad().height);
        let (cols, rows) = (g.columns() as usize, g.rows() as usize);
        // Columns with u in [cu - a, cu + a], rows with v in [cv - a, cv + a] (row 0 at the top).
        let span = |lo: f64, hi: f64, step: f64, n: usize| {
            let first = (lo / step).floor().max(0.0) as usize;
            let last = ((hi / step).ceil().max(0.0) as usize).min(n);
            first..last
        };
        let columns = span(center[0] - a + half_w, center[0] + a + half_w, du, cols);
        let row_range = span(half_h - center[1] - a, half_h - center[1] + a, dv, rows);
        // ∫∫ p = (3 F / (2 π a³)) ∫∫ sqrt(a² - x² - y²); a taxel's mean divides by its area.
        let scale = 1.5 * force / (std::f64::consts::PI * a * a * a) / g.taxel_area();
        for r in row_range {
            let v1 = half_h - r as f64 * dv - center[1];
            let v0 = v1 - dv;
            for c in columns.clone() {
                let u0 = -half_w + c as f64 * du - center[0];
                let cap = cap_integral(a, u0, u0 + du, v0, v1);
                self.pressure[r * cols + c] += scale * cap;
            }
        }
    }
}

impl TactileImage {
    /// Adds the law's Hertz-shaped pressure over an ellipse,
    /// `p = (3/2) F/(π a b) sqrt(1 - ξ²/a² - η²/b²)` (ξ, η along its two semi-axes), of a
    /// contact of normal force `force` \[N\] with semi-axes `semi_axes` = `[a, b]` \[m\],
    /// centred at pad coordinates `center` \[m\], its first semi-axis along the unit vector
    /// `first_axis` of the pad's `(u, v)`; nothing unless the force and both semi-axes are
    /// finite and > 0 and `first_axis` is finite and non-zero (it is normalised). Only the
    /// taxels under the ellipse are visited; each taxel's integral is exact along u and
    /// Gauss-Legendre along v (split where the ellipse's outline crosses the taxel's sides),
    /// so `Σ taxel pressure x taxel area = F` for an ellipse inside the grid.
    ///
    /// ```
    /// use softgrip_rapier::{Preset, SoftFingertip, TactileImage, TactilePad};
    /// let pad = TactilePad::new(16, 16, [0.0, -1.0, 0.0], 0.016, 0.016);
    /// let tip = SoftFingertip::builder(0.01).preset(Preset::DragonSkin30).tactile(pad).build().unwrap();
    /// let mut image = TactileImage::new(*tip.tactile().unwrap());
    /// // 2 N over a 4 mm x 1.5 mm ellipse turned 30° from the pad's u axis.
    /// let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
    /// image.add_ellipse([0.001, 0.0], [0.004, 0.0015], [c, s], 2.0);
    /// assert!((image.total_force() / 2.0 - 1.0).abs() < 1e-6);
    /// ```
    pub fn add_ellipse(
        &mut self,
        center: [f64; 2],
        semi_axes: [f64; 2],
        first_axis: [f64; 2],
        force: f64,
    ) {
        let [a, b] = semi_axes;
        let len = first_axis[0].hypot(first_axis[1]);
        let positive = |v: f64| v > 0.0 && v.is_finite();
        if !(positive(a) && positive(b) && positive(force) && positive(len)) {
            return;
        }
        let (c, s) = (first_axis[0] / len, first_axis[1] / len);
        // Q(u, v) = A u² + 2 B u v + C v² <= 1 inside, relative to the centre.
        let (ia2, ib2) = (1.0 / (a * a), 1.0 / (b * b));
        let q = Quadric {
            a: c * c * ia2 + s * s * ib2,
            b: c * s * (ia2 - ib2),
            c: s * s * ia2 + c * c * ib2,
            ab: a * b,
        };
        let g = self.grid;
        let (du, dv) = (g.taxel_width(), g.taxel_height());
        let (half_w, half_h) = (0.5 * g.pad().width, 0.5 * g.pad().height);
        let (cols, rows) = (g.columns() as usize, g.rows() as usize);
        // The ellipse's bounding box: |u| <= a b sqrt(C), |v| <= a b sqrt(A).
        let (eu, ev) = (q.ab * q.c.sqrt(), q.ab * q.a.sqrt());
        let span = |lo: f64, hi: f64, step: f64, n: usize| {
            let first = (lo / step).floor().max(0.0) as usize;
            let last = ((hi / step).ceil().max(0.0) as usize).min(n);
            first..last
        };
        let columns = span(center[0] - eu + half_w, center[0] + eu + half_w, du, cols);
        let row_range = span(half_h - center[1] - ev, half_h - center[1] + ev, dv, rows);
        // p0 = 3 F / (2 π a b); a taxel's mean divides by its area.
        let scale = 1.5 * force / (std::f64::consts::PI * q.ab) / g.taxel_area();
        for r in row_range {
            let v1 = half_h - r as f64 * dv - center[1];
            let v0 = v1 - dv;
            for col in columns.clone() {
                let u0 = -half_w + col as f64 * du - center[0];
                self.pressure[r * cols + col] += scale * q.cap_integral(u0, u0 + du, v0, v1);
            }
        }
    }
}

/// The ellipse `Q(u, v) = A u² + 2 B u v + C v² <= 1` (`A C - B² = 1/(a b)²`).
struct Quadric {
    a: f64,
    b: f64,
    c: f64,
    /// `a b`, the product of the semi-axes \[m²\].
    ab: f64,
}

impl Quadric {
    /// `∫_{u0}^{u1} ∫_{v0}^{v1} sqrt(1 - Q(u, v))₊ dv du` \[m²\]. For fixed v,
    /// `1 - Q = β² - A w²` with `w = u + B v/A`, `β² = 1 - v²/(A a² b²)`, whose integral along
    /// u is exact (as in [`cap_integral`]); along v Gauss-Legendre on the pieces of
    /// `[v0, v1] ∩ [-v_max, v_max]` between the v where the outline crosses `u = u0` or
    /// `u = u1`.
    fn cap_integral(&self, u0: f64, u1: f64, v0: f64, v1: f64) -> f64 {
        let v_max = self.ab * self.a.sqrt();
        let (lo, hi) = (v0.max(-v_max), v1.min(v_max));
        if !(lo < hi) {
            return 0.0;
        }
        let mut cuts = [lo, hi, hi, hi, hi, hi];
        let mut n = 1;
        for u in [u0, u1] {
            // C v² + 2 B u v + (A u² - 1) = 0.
            let disc = self.b * self.b * u * u - self.c * (self.a * u * u - 1.0);
            if disc > 0.0 {
                let r = disc.sqrt();
                for v in [(-self.b * u - r) / self.c, (-self.b * u + r) / self.c] {
                    if v > lo && v < hi {
                        cuts[n] = v;
                        n += 1;
                    }
                }
            }
        }
        cuts[n] = hi;
        cuts[..=n].sort_unstable_by(f64::total_cmp);
        let sa = self.a.sqrt();
        let inner = |v: f64| {
            let beta2 = (1.0 - v * v / (self.a * self.ab * self.ab)).max(0.0);
            let beta = beta2.sqrt();
            let shift = self.b * v / self.a;
            // ∫ sqrt(β² - t²) dt from t0 to t1, t = sqrt(A) (u + B v/A), over sqrt(A).
            let prim = |t: f64| {
                if t >= beta {
                    return 0.25 * std::f64::consts::PI * beta2;
                }
                if t <= -beta {
                    return -0.25 * std::f64::consts::PI * beta2;
                }
                let chord = ((beta - t) * (beta + t)).max(0.0).sqrt();
                0.5 * (t * chord + beta2 * (t / beta).clamp(-1.0, 1.0).asin())
            };
            if beta == 0.0 {
                return 0.0;
            }
            (prim(sa * (u1 + shift)) - prim(sa * (u0 + shift))) / sa
        };
        let mut total = 0.0;
        for w in cuts[..=n].windows(2) {
            let (m, h) = (0.5 * (w[0] + w[1]), 0.5 * (w[1] - w[0]));
            if h > 0.0 {
                total += h * GAUSS_8
                    .iter()
                    .map(|(t, wt)| wt * inner(m + h * t))
                    .sum::<f64>();
            }
        }
        total
    }
}

/// Gauss-Legendre nodes and weights on [-1, 1], 8 points (exact for polynomials of degree 15).
const GAUSS_8: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_5),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_3),
];

/// `∫_{x0}^{x1} ∫_{y0}^{y1} sqrt(a² - x² - y²)₊ dy dx` [m³]: the volume of the hemisphere of
/// radius `a` over a rectangle (coordinates relative to its centre).
///
/// The inner integral is exact: `∫_0^y sqrt(b² - t²) dt = (y sqrt(b² - y²) + b² asin(y/b)) / 2`
/// with `b = sqrt(a² - x²)` and `y` clamped to `[-b, b]`. The outer one is Gauss-Legendre on
/// the pieces of `[x0, x1] ∩ [-a, a]` between the kinks `x = ±sqrt(a² - y_i²)` (where the
/// disc's edge crosses `y = y0` or `y = y1`), on each of which the integrand is smooth
/// except for a `(x - kink)^(3/2)` end: relative error below 1e-5 of a taxel's value.
pub(crate) fn cap_integral(a: f64, x0: f64, x1: f64, y0: f64, y1: f64) -> f64 {
    let (lo, hi) = (x0.max(-a), x1.min(a));
    if !(lo < hi && y0 < a && y1 > -a) {
        return 0.0;
    }
    let mut cuts = [lo, hi, hi, hi, hi, hi];
    let mut n = 1;
    for y in [y0, y1] {
        if y.abs() < a {
            let k = (a * a - y * y).sqrt();
            for x in [-k, k] {
                if x > lo && x < hi {
                    cuts[n] = x;
                    n += 1;
                }
            }
        }
    }
    cuts[n] = hi;
    cuts[..=n].sort_unstable_by(f64::total_cmp);
    let inner = |x: f64| {
        let b2 = (a * a - x * x).max(0.0);
        let b = b2.sqrt();
        let s = |y: f64| {
            if y >= b {
                return 0.25 * std::f64::consts::PI * b2;
            }
            if y <= -b {
                return -0.25 * std::f64::consts::PI * b2;
            }
            // (b - y)(b + y), not b² - y²: no cancellation near the chord's ends.
            let chord = ((b - y) * (b + y)).max(0.0).sqrt();
            0.5 * (y * chord + b2 * (y / b).clamp(-1.0, 1.0).asin())
        };
        s(y1) - s(y0)
    };
    let mut total = 0.0;
    for w in cuts[..=n].windows(2) {
        let (m, h) = (0.5 * (w[0] + w[1]), 0.5 * (w[1] - w[0]));
        if h > 0.0 {
            total += h * GAUSS_8
                .iter()
                .map(|(t, wt)| wt * inner(m + h * t))
                .sum::<f64>();
        }
    }
    total
}

/// A fingertip's pad between steps: its image, computed on first read after a step (the
/// recorder reads every `every_n_steps`-th step, a sweep none: the images were 15 % of a
/// default grasp step when computed on every step). What it is computed from (the step's
/// readout and the fingertip's orientation at the step's end) does not change until the next
/// step, so a deferred image is the one an eager one was, bit for bit.
#[derive(Debug, Clone)]
pub(crate) struct TactileSlot {
    grid: TactileGrid,
    /// The fingertip collider's orientation at the end of the last step, `[x, y, z, w]`
    /// (`None`: before the first step, or its collider is gone: a blank image).
    rotation: Option<[f64; 4]>,
    /// The image of the last step, once read (a fresh buffer per read: a 16 x 16 pad is 2 kB,
    /// against ~50 us to lay a contact on it).
    image: OnceLock<TactileImage>,
}

impl TactileSlot {
    pub(crate) fn new(grid: TactileGrid) -> Self {
        Self {
            grid,
            rotation: None,
            image: OnceLock::new(),
        }
    }
}

impl TactileSlot {
    /// The image of the last step of the fingertip `handle` (its rows of `contacts`),
    /// computing it if not read since the step.
    pub(crate) fn image(&self, handle: ColliderHandle, contacts: &[TipContact]) -> &TactileImage {
        self.image.get_or_init(|| {
            let mut image = TactileImage::new(self.grid);
            if let Some(q) = self.rotation {
                lay_contacts(contacts, handle, q, &mut image);
            }
            image
        })
    }

    /// Marks the image stale after a step and keeps the fingertip's orientation at its end
    /// for the deferred image (`image`): `rotation` `[x, y, z, w]`, `None` if its collider is
    /// gone.
    pub(crate) fn refresh(&mut self, rotation: Option<[f64; 4]>) {
        self.image.take();
        self.rotation = rotation;
    }
}

/// Lays each contact of fingertip `handle` (orientation `q`) on its pad's `image`. A
/// soft-soft pair has a readout row for each of its two fingertips, so every pad takes only
/// the rows of its own fingertip.
fn lay_contacts(
    contacts: &[TipContact],
    handle: ColliderHandle,
    q: [f64; 4],
    image: &mut TactileImage,
) {
    for c in contacts.iter().filter(|c| c.fingertip == handle) {
        // The patch's direction from the fingertip's centre: against the normal
        // (other -> fingertip).
        let local = rotate_inverse(q, c.normal.map(|n| -n));
        let Some(center) = image.grid.coordinates(local) else {
            continue;
        };
        let patch = c.patch();
        if patch.is_disc() {
            image.add_disc(center, patch.radius, c.normal_force);
            continue;
        }
        // The first semi-axis in pad coordinates: the image of a short step along it
        // from the contact's point on the sphere.
        let d = rotate_inverse(q, c.patch_direction);
        let n = crate::tactile::norm(local);
        let step: [f64; 3] = std::array::from_fn(|i| local[i] / n + 1e-6 * d[i]);
        let Some(ahead) = image.grid.coordinates(step) else {
            continue;
        };
        let axis = [ahead[0] - center[0], ahead[1] - center[1]];
        image.add_ellipse(center, [patch.radius, patch.radius2], axis, c.normal_force);
    }
}

/// `q* v q` for a unit quaternion `[x, y, z, w]`: `v` from world axes into the body's.
fn rotate_inverse(q: [f64; 4], v: [f64; 3]) -> [f64; 3] {
    let [x, y, z, w] = q;
    let (x, y, z) = (-x, -y, -z);
    // t = 2 (q_v x v); v' = v + w t + q_v x t
    let t = [
        2.0 * (y * v[2] - z * v[1]),
        2.0 * (z * v[0] - x * v[2]),
        2.0 * (x * v[1] - y * v[0]),
    ];
    [
        v[0] + w * t[0] + (y * t[2] - z * t[1]),
        v[1] + w * t[1] + (z * t[0] - x * t[2]),
        v[2] + w * t[2] + (x * t[1] - y * t[0]),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Brute-force midpoint sum of the same integral.
    fn brute(a: f64, x0: f64, x1: f64, y0: f64, y1: f64) -> f64 {
        let n = 2000;
        let (dx, dy) = ((x1 - x0) / n as f64, (y1 - y0) / n as f64);
        let mut s = 0.0;
        for i in 0..n {
            let x = x0 + (i as f64 + 0.5) * dx;
            for j in 0..n {
                let y = y0 + (j as f64 + 0.5) * dy;
                s += (a * a - x * x - y * y).max(0.0).sqrt();
            }
        }
        s * dx * dy
    }

    #[test]
    fn cap_integral_of_the_whole_disc_is_the_hemisphere() {
        let a = 0.003;
        let v = cap_integral(a, -1.0, 1.0, -1.0, 1.0);
        let exact = 2.0 / 3.0 * std::f64::consts::PI * a * a * a;
        assert!((v / exact - 1.0).abs() < 1e-12, "{v} vs {exact}");
        let q = cap_integral(a, 0.0, 1.0, 0.0, 1.0);
        assert!(
            (q / (exact / 4.0) - 1.0).abs() < 1e-12,
            "{q} vs {}",
            exact / 4.0
        );
    }

    #[test]
    fn cap_integral_of_cut_rectangles_matches_a_fine_sum() {
        let a = 1.0;
        for (x0, x1, y0, y1) in [
            (0.3, 0.9, -0.2, 0.5),
            (-0.95, -0.4, 0.6, 1.2),
            (0.7, 1.3, 0.6, 1.3),
            (-0.1, 0.1, -0.1, 0.1),
        ] {
            let v = cap_integral(a, x0, x1, y0, y1);
            let b = brute(a, x0, x1, y0, y1);
            assert!(
                (v / b - 1.0).abs() < 2e-5,
                "{x0} {x1} {y0} {y1}: {v} vs {b}"
            );
        }
    }

    /// The rotated ellipse's cap integral against a fine midpoint sum, and a circle given as
    /// an ellipse against the disc's.
    #[test]
    fn ellipse_cap_integral_matches_a_fine_sum() {
        let (a, b, angle) = (1.0, 0.35, 0.6f64);
        let (c, s) = (angle.cos(), angle.sin());
        let q = Quadric {
            a: c * c / (a * a) + s * s / (b * b),
            b: c * s * (1.0 / (a * a) - 1.0 / (b * b)),
            c: s * s / (a * a) + c * c / (b * b),
            ab: a * b,
        };
        let brute = |u0: f64, u1: f64, v0: f64, v1: f64| {
            let n = 2000;
            let (du, dv) = ((u1 - u0) / n as f64, (v1 - v0) / n as f64);
            let mut sum = 0.0;
            for i in 0..n {
                let u = u0 + (i as f64 + 0.5) * du;
                for j in 0..n {
                    let v = v0 + (j as f64 + 0.5) * dv;
                    let qq = q.a * u * u + 2.0 * q.b * u * v + q.c * v * v;
                    sum += (1.0 - qq).max(0.0).sqrt();
                }
            }
            sum * du * dv
        };
        for (u0, u1, v0, v1) in [
            (0.3, 0.9, -0.2, 0.5),
            (-0.95, -0.4, 0.1, 0.7),
            (0.5, 1.3, 0.3, 1.3),
            (-0.1, 0.1, -0.1, 0.1),
        ] {
            let (got, want) = (q.cap_integral(u0, u1, v0, v1), brute(u0, u1, v0, v1));
            assert!(
                (got / want - 1.0).abs() < 2e-5,
                "{u0} {u1} {v0} {v1}: {got} vs {want}"
            );
        }
        // The whole ellipse: (2/3) pi a b.
        let whole = q.cap_integral(-2.0, 2.0, -2.0, 2.0);
        assert!((whole / (2.0 / 3.0 * std::f64::consts::PI * a * b) - 1.0).abs() < 1e-12);
        // A circle given as an ellipse: the disc's integral, to the two quadratures' error
        // (the disc's runs its Gauss-Legendre along u, the ellipse's along v).
        let circle = Quadric {
            a: 1.0,
            b: 0.0,
            c: 1.0,
            ab: 1.0,
        };
        for (u0, u1, v0, v1) in [(0.3, 0.9, -0.2, 0.5), (0.7, 1.3, 0.6, 1.3)] {
            let (got, want) = (
                circle.cap_integral(u0, u1, v0, v1),
                cap_integral(1.0, u0, u1, v0, v1),
            );
            assert!((got / want - 1.0).abs() < 1e-5, "{got} vs {want}");
        }
    }

    #[test]
    fn rotate_inverse_undoes_a_quarter_turn_about_z() {
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let v = rotate_inverse([0.0, 0.0, h, h], [0.0, 1.0, 0.0]);
        assert!((v[0] - 1.0).abs() < 1e-12 && v[1].abs() < 1e-12);
    }
}
