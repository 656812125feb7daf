//! Complete elliptic integrals and Hertz's elliptical contact.
//!
//! Carlson's symmetric integrals `R_F` and `R_D` by the duplication algorithm (B. C. Carlson,
//! "Numerical computation of real or complex elliptic integrals", Numer. Algorithms 10 (1995)
//! 13-26; the constants of Numerical Recipes 3rd ed. §6.12), and from them, with the
//! complementary parameter `m' = 1 - e²` (`e` the eccentricity):
//!
//! ```text
//! K(e) = R_F(0, m', 1)                 first kind
//! D(e) = (K - E)/e²  = R_D(0, m', 1)/3  (Jahnke-Emde's D: no cancellation as e -> 0)
//! B(e) = (E - m' K)/e² = m' R_D(0, 1, m')/3
//! E(e) = K - e² D                       second kind
//! ```
//!
//! **Hertz's elliptical contact** (K. L. Johnson, *Contact Mechanics*, CUP 1985, §3.5 and
//! §4.2): two bodies whose gap near the first touch is `h = A u² + B v²` (`A, B > 0`, half the
//! sums of the principal curvatures along u and v) pressed together by `delta` touch over an
//! ellipse of semi-axes `a` (along u) and `b` (along v), with `p = p0 sqrt(1 - u²/a² - v²/b²)`,
//! `F = (2/3) pi a b p0` and, for `A <= B` (so `a >= b`, `b = a sqrt(1 - e²)`):
//!
//! ```text
//! B/A   = (E/(1 - e²) - K)/(K - E)       = R_D(0, 1, m')/R_D(0, m', 1)
//! delta = (p0/E*) b K(e)
//! A     = (p0/E*) (b/(e² a²)) (K - E)   =>  a² = delta D(e)/(A K(e))
//! F     = (2 pi/3) E* a delta / K(e)
//! ```
//!
//! At `e = 0` (`A = B = 1/(2 R_eff)`) this is the circular Hertz contact: `a² = R_eff delta`,
//! `F = (4/3) E* sqrt(R_eff) delta^(3/2)`.

use std::f64::consts::PI;

use crate::root::{Probe, Stop, newton_bracketed};

/// Carlson's `R_F(x, y, z)` for `x, y, z >= 0`, at most one of them 0.
pub(crate) fn carlson_rf(x: f64, y: f64, z: f64) -> f64 {
    const ERRTOL: f64 = 0.001;
    let (mut x, mut y, mut z) = (x, y, z);
    let mut ave;
    let (mut dx, mut dy, mut dz);
    loop {
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * (sy + sz) + sy * sz;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        ave = (x + y + z) / 3.0;
        dx = (ave - x) / ave;
        dy = (ave - y) / ave;
        dz = (ave - z) / ave;
        // NaN ends the loop too (a NaN argument is the caller's bug: it propagates).
        let err = dx.abs().max(dy.abs()).max(dz.abs());
        if err.is_nan() || err <= ERRTOL {
            break;
        }
    }
    let e2 = dx * dy - dz * dz;
    let e3 = dx * dy * dz;
    (1.0 + (e2 / 24.0 - 0.1 - 3.0 / 44.0 * e3) * e2 + e3 / 14.0) / ave.sqrt()
}

/// Carlson's `R_D(x, y, z)` for `x, y >= 0` (at most one of them 0) and `z > 0`.
pub(crate) fn carlson_rd(x: f64, y: f64, z: f64) -> f64 {
    const ERRTOL: f64 = 0.0008;
    const C1: f64 = 3.0 / 14.0;
    const C2: f64 = 1.0 / 6.0;
    const C3: f64 = 9.0 / 22.0;
    const C4: f64 = 3.0 / 26.0;
    const C5: f64 = 0.25 * C3;
    const C6: f64 = 1.5 * C4;
    let (mut x, mut y, mut z) = (x, y, z);
    let (mut sum, mut fac) = (0.0, 1.0);
    let mut ave;
    let (mut dx, mut dy, mut dz);
    loop {
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * (sy + sz) + sy * sz;
        sum += fac / (sz * (z + lambda));
        fac *= 0.25;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        ave = 0.2 * (x + y + 3.0 * z);
        dx = (ave - x) / ave;
        dy = (ave - y) / ave;
        dz = (ave - z) / ave;
        let err = dx.abs().max(dy.abs()).max(dz.abs());
        if err.is_nan() || err <= ERRTOL {
            break;
        }
    }
    let ea = dx * dy;
    let eb = dz * dz;
    let ec = ea - eb;
    let ed = ea - 6.0 * eb;
    let ee = ed + ec + ec;
    3.0 * sum
        + fac
            * (1.0
                + ed * (-C1 + C5 * ed - C6 * dz * ee)
                + dz * (C2 * ee + dz * (-C3 * ec + dz * C4 * ea)))
            / (ave * ave.sqrt())
}

/// The complete elliptic integrals of an ellipse of complementary parameter `m1 = 1 - e²` in
/// `(0, 1]`: `(K, E, D)` with `D = (K - E)/e²` (`pi/4` at `e = 0`).
pub(crate) fn complete(m1: f64) -> (f64, f64, f64) {
    let k = carlson_rf(0.0, m1, 1.0);
    let d = carlson_rd(0.0, m1, 1.0) / 3.0;
    (k, k - (1.0 - m1) * d, d)
}

/// `E(e)`, the complete elliptic integral of the second kind, of complementary parameter
/// `m1 = 1 - e²` in `(0, 1]` (`pi/2` for a circle): a quarter of the perimeter of the ellipse
/// of semi-axes 1 and `sqrt(m1)`.
pub(crate) fn second_kind(m1: f64) -> f64 {
    if m1 == 1.0 {
        return 0.5 * PI;
    }
    complete(m1).1
}

/// Hertz's elliptical contact in the fingertip's units: the gap `h = A u² + B v²` with
/// `A R = a_hat`, `B R = b_hat` (both > 0; R the fingertip's radius), at compression delta:
/// `a = alpha sqrt(R delta)` along u, `b = beta sqrt(R delta)` along v, and
/// `F = (4/3) E* R² x^(3/2) h`, `x = delta/R`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct HertzEllipse {
    /// Semi-axis along u over `sqrt(R delta)` [-].
    pub alpha: f64,
    /// Semi-axis along v over `sqrt(R delta)` [-].
    pub beta: f64,
    /// The force over the circular contact's with a plane, `(4/3) E* R² x^(3/2)` [-].
    pub force_factor: f64,
}

impl HertzEllipse {
    /// The contact of gap `h R = a_hat u² + b_hat v²` (both finite and > 0, their ratio at
    /// most [`MAX_CURVATURE_RATIO`] either way: the caller checks).
    pub(crate) fn new(a_hat: f64, b_hat: f64) -> Self {
        // Long axis along the smaller half-curvature sum.
        let (small, large) = if a_hat <= b_hat {
            (a_hat, b_hat)
        } else {
            (b_hat, a_hat)
        };
        let m1 = eccentricity_complement(large / small);
        let (k, _, d) = complete(m1);
        // a² = delta D/(A K), over R delta: D/(A R K).
        let long = (d / (small * k)).sqrt();
        let short = long * m1.sqrt();
        let force_factor = 0.5 * PI * long / k;
        let (alpha, beta) = if a_hat <= b_hat {
            (long, short)
        } else {
            (short, long)
        };
        Self {
            alpha,
            beta,
            force_factor,
        }
    }
}

/// The largest ratio of the two half-curvature sums `B/A` that [`eccentricity_complement`]
/// solves (an ellipse of axis ratio about 3e4); a counterpart within
/// [`crate::MIN_RELATIVE_CURVATURE`] and [`crate::MAX_RELATIVE_CURVATURE`] has at most
/// `(1 + 1e4)/(1 - 0.999)`, about 1e7.
pub(crate) const MAX_CURVATURE_RATIO: f64 = 1e8;

/// `m' = 1 - e²` of Hertz's ellipse for the half-curvature ratio `ratio = B/A` in
/// `[1, MAX_CURVATURE_RATIO]`: the root of `R_D(0, 1, m')/R_D(0, m', 1) = ratio`, by Newton in
/// `t = ln m'` (the ratio is smooth and decreasing in m') by secant steps, started from
/// Hamrock and Brewe's `b/a ~ ratio^(-2/pi)` and kept in its bracket; to 1e-13 relative in
/// the ratio.
pub(crate) fn eccentricity_complement(ratio: f64) -> f64 {
    if ratio.is_nan() || ratio <= 1.0 {
        return 1.0;
    }
    let target = ratio.min(MAX_CURVATURE_RATIO).ln();
    let g = |t: f64| {
        let m1 = t.exp();
        (carlson_rd(0.0, 1.0, m1) / carlson_rd(0.0, m1, 1.0)).ln() - target
    };
    // g decreases in t; at t = 0 (a circle) g = -target < 0, and m' = 1e-20 is past any
    // ratio <= 1e8 (there the ratio is about 1/(m' ln(4/sqrt m'))).
    let (lo, hi) = (-46.0, 0.0);
    let start = -4.0 / PI * target;
    let stop = Stop {
        step: 1e-14,
        width: Some(1e-15),
        max_iterations: 100,
    };
    // Secant steps (one evaluation each), started with Hamrock and Brewe's slope
    // d ln(ratio)/dt = -pi/4, inside the bracket.
    let mut prev: Option<(f64, f64)> = None;
    let t = newton_bracketed(lo, hi, start.clamp(lo, hi), stop, |t| {
        let v = g(t);
        let slope = match prev {
            Some((tp, vp)) if tp != t && vp != v => (v - vp) / (t - tp),
            _ => -0.25 * PI,
        };
        prev = Some((t, v));
        Probe {
            below_root: v > 0.0,
            step: v / slope,
        }
    });
    t.exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Reference values of K, E from SciPy 1.17.1 (`ellipk`, `ellipe`; m = e²).
    #[test]
    fn complete_integrals_match_reference_values() {
        for (m, k_ref, e_ref) in [
            (0.1, 1.6124413487202192, 1.5307576368977633),
            (0.5, 1.8540746773013719, 1.3506438810476755),
            (0.9, 2.5780921133481733, 1.1047747327040733),
            (0.999, 4.841132560550296, 1.0021707908344453),
        ] {
            let (k, e, d) = complete(1.0 - m);
            assert!((k / k_ref - 1.0).abs() < 1e-14, "K({m}) = {k}");
            assert!((e / e_ref - 1.0).abs() < 1e-14, "E({m}) = {e}");
            assert!(((k - e) / m / d - 1.0).abs() < 1e-12, "D({m})");
        }
        let (k, e, d) = complete(1.0);
        assert!((k - 0.5 * PI).abs() < 1e-15 && (e - 0.5 * PI).abs() < 1e-15);
        assert!((d - 0.25 * PI).abs() < 1e-15);
    }

    /// Legendre's relation E K' + E' K - K K' = pi/2 over the whole range.
    #[test]
    fn legendre_relation_holds() {
        for i in 1..100 {
            let m = f64::from(i) / 100.0;
            let (k, e, _) = complete(1.0 - m);
            let (kp, ep, _) = complete(m);
            let l = e * kp + ep * k - k * kp;
            assert!((l / (0.5 * PI) - 1.0).abs() < 2e-15, "m = {m}: {l}");
        }
    }

    #[test]
    fn the_ellipse_solves_its_curvature_ratio() {
        for ratio in [1.0 + 1e-9, 1.001, 1.5, 2.0, 3.0, 10.0, 1e3, 1e6, 1e8] {
            let m1 = eccentricity_complement(ratio);
            let got = carlson_rd(0.0, 1.0, m1) / carlson_rd(0.0, m1, 1.0);
            assert!((got / ratio - 1.0).abs() < 1e-12, "{ratio}: {got}");
        }
        assert_eq!(eccentricity_complement(1.0), 1.0);
    }

    /// Hertz's ellipse against an independent solution: SciPy 1.17.1's `ellipk`/`ellipe` and
    /// `brentq` on Johnson's `B/A = (E/(1 - e²) - K)/(K - E)`
    /// (`tools/calibration/check_hertz_ellipse.py` prints them; `(A R, B R)`: cylinders of
    /// radius R and 3R, a general gap, and a cylinder of R/2 given the other way round).
    #[test]
    fn hertz_ellipse_matches_an_independent_solution() {
        for ((a_hat, b_hat), (alpha, beta, h)) in [
            (
                (0.5, 1.0),
                (1.0554708788231213, 0.6655753991683993, 0.8492997417663052),
            ),
            (
                (0.5, 2.0 / 3.0),
                (1.0236392137109795, 0.8450574359857888, 0.9322089374850906),
            ),
            (
                (0.3, 2.0),
                (1.4658823635339153, 0.42151907957058504, 0.8630822199106549),
            ),
            (
                (1.5, 0.5),
                (0.5236699220275899, 1.0850389109570469, 0.7788679983110256),
            ),
        ] {
            let e = HertzEllipse::new(a_hat, b_hat);
            for (got, want) in [(e.alpha, alpha), (e.beta, beta), (e.force_factor, h)] {
                assert!((got / want - 1.0).abs() < 1e-12, "{a_hat} {b_hat}: {e:?}");
            }
        }
    }

    /// The circle: `a² = R_eff delta`, the force factor `sqrt(R_eff/R)`; and the limits
    /// of the ellipse as it becomes a circle.
    #[test]
    fn a_circle_is_hertz_with_the_effective_radius() {
        for k in [0.5, 1.0, 3.0, 10.0] {
            // Ball of radius k R: A R = B R = (1 + 1/k)/2, R_eff/R = k/(1 + k).
            let h = 0.5 * (1.0 + 1.0 / k);
            let e = HertzEllipse::new(h, h);
            let rho = k / (1.0 + k);
            assert!((e.alpha / rho.sqrt() - 1.0).abs() < 1e-14);
            assert!((e.beta / rho.sqrt() - 1.0).abs() < 1e-14);
            assert!((e.force_factor / rho.sqrt() - 1.0).abs() < 1e-14);
            let near = HertzEllipse::new(h, h * (1.0 + 1e-7));
            assert!((near.force_factor / e.force_factor - 1.0).abs() < 1e-7);
        }
    }
}
