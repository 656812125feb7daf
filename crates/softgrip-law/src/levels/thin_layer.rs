//! Matthewson's thin bonded layer (J. Mech. Phys. Solids 29 (1981) 89): a rigid sphere of
//! radius R pressed by `delta` into an elastic layer of thickness t bonded to a rigid base,
//! in the thin-layer approximation (the layer's pressure `p - l^2 lap(p) = (M/t) w`, `M = kappa
//! + 4 mu/3` its oedometer modulus, `l = t sqrt(M/(3 mu))` its confinement length). With
//! `z = a/l`:
//!
//! ```text
//! delta R / l^2 = G(z) = 2 + z^2/2 - z I0(z)/I1(z),     F = pi (M/t) a^2 (delta - a^2/(4R))
//! ```
//!
//! Both limits of a thin bonded layer are in it, and with them its dependence on the Poisson
//! ratio: a patch much wider than `l` sees Winkler's oedometer (`a^2 = 2 R delta`, `F/F_H =
//! (3 pi/4)(M/E*) a_H/t`: a compressible layer's stiffness grows linearly in a/t, with the
//! modulus `M = E (1 - nu)/((1 + nu)(1 - 2 nu))`), a patch narrower than `l` (always, for an
//! incompressible layer: `l -> infinity`) the bulging incompressible layer (`a^2 = 4 R delta`,
//! `F/F_H = (3 pi/8) (a_H/t)^3`). No fitted constant.
//!
//! Written in the form that stays finite as `nu -> 1/2`: `G = z^2/4 + z^4 K(z)` and `F = pi (3
//! mu/t^3) a^6 K(z)` with `K = (G - z^2/4)/z^4` (`1/96` at z = 0), so that over `F_H = (4/3) E*
//! R^2 x^(3/2)` (`E* = 2 mu/(1 - nu)`), with R = 1:
//!
//! ```text
//! x = a^2/4 + a^4 K(z)/l^2,   chi_thin = (9 pi (1 - nu)/8) a^6 K(z) / (tau^3 x^(3/2))
//! ```

use crate::root::{Probe, Stop, newton_bracketed};

/// `K(z) = sum c_k q^k`, `q = z^2/4`, for `z < SERIES_END` (the series of `(G - z^2/4)/z^4`
/// from `I0 = sum q^k/(k!)^2`, `I1 = (z/2) sum q^k/(k! (k+1)!)`, exact rationals; at `z = 1`
/// the next term is below 2e-12 of the sum and the two evaluations agree to that).
const K_SERIES: [f64; 10] = [
    1.0 / 96.0,
    -1.0 / 384.0,
    1.0 / 1440.0,
    -13.0 / 69120.0,
    11.0 / 215040.0,
    -647.0 / 46448640.0,
    1133.0 / 298598400.0,
    -43213.0 / 41803776000.0,
    777013.0 / 2759049216000.0,
    -2540291.0 / 33108590592000.0,
];
/// Below it `K` is its series, above it `(G - z^2/4)/z^4` from the Bessel ratio (which cancels
/// `2 - z I0/I1` against `z^2/4` at small z).
const SERIES_END: f64 = 1.0;
/// The continued fraction of `I1/I0` takes `FRACTION_BASE + ceil(z)` terms: converged to
/// rounding (2e-16) from 9 terms at z = 1, 17 at z = 6 (the level's largest z is about 6, a
/// compressible skin of t/R 0.05 at its x_max), 34 at z = 30.
const FRACTION_BASE: f64 = 16.0;

/// `I1(z)/I0(z)` by Gauss' continued fraction `1/(2/z + 1/(4/z + 1/(6/z + ...)))`, `z > 0`.
fn bessel_ratio(z: f64) -> f64 {
    let terms = (FRACTION_BASE + z.ceil()).min(1000.0) as u32;
    let mut t = 0.0;
    for k in (1..=terms).rev() {
        t = 1.0 / (2.0 * f64::from(k) / z + t);
    }
    t
}

/// Matthewson's flat punch's stiffness over its incompressible limit, `psi(z) = 8 (1 - 2
/// I1(z)/(z I0(z)))/z^2` (1 at z = 0, `8/z^2` for z >> 1), `z = a/l`: the share of a bonded
/// thin layer's stiffness that is its flow, the rest its oedometer. Even in z; for `|z| <
/// 1e-2` its leading terms `1 - z^2/6` (the next, `11 z^4/384`, below 3e-10 there), as
/// `tools/calibration/try_thin_skin_s25.py`'s `psi` (the squeezed film's weight, session 29).
pub(crate) fn flow_share(z: f64) -> f64 {
    let z = z.abs().max(1e-6);
    if z < 1e-2 {
        return 1.0 - z * z / 6.0;
    }
    8.0 * (1.0 - 2.0 * bessel_ratio(z) / z) / (z * z)
}

/// `(K(z), G(z), G'(z))`.
fn kernel(z: f64) -> (f64, f64, f64) {
    if z < SERIES_END {
        let q = 0.25 * z * z;
        let (mut k, mut dk_dq, mut qn) = (0.0, 0.0, 1.0);
        for (n, c) in K_SERIES.iter().enumerate() {
            if n > 0 {
                dk_dq += c * f64::from(n as u32) * qn;
                qn *= q;
            }
            k += c * qn;
        }
        // dk_dq = sum n c_n q^(n-1).
        let z4 = z * z * z * z;
        let g = 0.25 * z * z + z4 * k;
        // d/dz (z^4 K) = 4 z^3 K + z^4 K'(q) z/2.
        let dg = 0.5 * z + 4.0 * z * z * z * k + z4 * dk_dq * 0.5 * z;
        (k, g, dg)
    } else {
        let r = bessel_ratio(z);
        let g = 2.0 + 0.5 * z * z - z / r;
        // (I1/I0)' = 1 - r/z - r^2, so G' = z/r^2 - 2/r.
        let dg = z / (r * r) - 2.0 / r;
        ((g - 0.25 * z * z) / (z * z * z * z), g, dg)
    }
}

/// Matthewson's thin bonded layer at one skin and Poisson ratio (the module docs).
#[derive(Debug, Clone, Copy)]
pub(crate) struct ThinLayer {
    /// `R/l = sqrt(3 mu/M)/tau` (0 for an incompressible layer).
    inv_l: f64,
    /// `9 pi (1 - nu) / (8 tau^3)`.
    scale: f64,
}

impl ThinLayer {
    /// A skin of `tau = t/R` in (0, 1) at `0 <= nu <= 1/2`.
    pub(crate) fn new(tau: f64, nu: f64) -> Self {
        // 3 mu/M = 3 (1 - 2 nu)/(2 (1 - nu)).
        let three_mu_m = 3.0 * (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu));
        Self {
            inv_l: three_mu_m.max(0.0).sqrt() / tau,
            scale: 9.0 * std::f64::consts::PI * (1.0 - nu) / (8.0 * tau * tau * tau),
        }
    }

    /// `max(chi_thin - 1, 0)`, the thin layer's excess over Hertz, without the root solve where
    /// it is 0 for sure: `chi_thin` is at most `(3 pi/8) u^3 2 (1 - nu)`, the incompressible
    /// layer's force over this nu's `F_H` (a compressible layer is softer; equal at nu = 1/2;
    /// `bound_holds` checks it over a grid of nu, t/R and x), so where twice that is below 1
    /// the excess is 0 (a factor 2 of margin).
    pub(crate) fn excess(&self, x: f64) -> f64 {
        if 2.0 * self.bound(x) <= 1.0 {
            return 0.0;
        }
        (self.chi(x) - 1.0).max(0.0)
    }

    /// `(3 pi/8) u^3 2 (1 - nu)`, `u = sqrt(x)/tau`: with `scale = 9 pi (1 - nu)/(8 tau^3)`,
    /// `(2/3) scale x^(3/2)`.
    fn bound(&self, x: f64) -> f64 {
        2.0 / 3.0 * self.scale * x * x.sqrt()
    }

    /// `F/F_H` of the thin layer at `x = delta/R >= 0` (0 at x = 0, where it vanishes as
    /// `x^(3/2)`).
    pub(crate) fn chi(&self, x: f64) -> f64 {
        if x <= 0.0 {
            return 0.0;
        }
        let (a, k) = if self.inv_l == 0.0 {
            (2.0 * x.sqrt(), K_SERIES[0])
        } else {
            // G(z) = x / l^2; z^2 lies in [2, 4] x / l^2 (Winkler's patch to the
            // incompressible one).
            let target = x * self.inv_l * self.inv_l;
            let (lo, hi) = ((2.0 * target).sqrt() * 0.999, 2.0 * target.sqrt() * 1.001);
            let z = newton_bracketed(
                lo,
                hi,
                0.5 * (lo + hi),
                Stop {
                    step: 1e-15,
                    width: Some(4e-16),
                    max_iterations: 200,
                },
                |z| {
                    let (_, g, dg) = kernel(z);
                    Probe {
                        below_root: g < target,
                        step: (g - target) / dg,
                    }
                },
            );
            (z / self.inv_l, kernel(z).0)
        };
        let a2 = a * a;
        self.scale * a2 * a2 * a2 * k / (x * x.sqrt())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The two thin-layer limits, and the two evaluations of K meeting at `SERIES_END`.
    #[test]
    fn limits_and_continuity() {
        // Incompressible: (3 pi/8) u^3, u = sqrt(x)/tau.
        let t = ThinLayer::new(0.1, 0.5);
        let x: f64 = 0.02;
        let u = x.sqrt() / 0.1;
        let want = 3.0 * std::f64::consts::PI / 8.0 * u * u * u;
        assert!((t.chi(x) / want - 1.0).abs() < 1e-14, "{} {want}", t.chi(x));
        // Near nu = 1/2 the compressible branch tends to it.
        let near = ThinLayer::new(0.1, 0.499_999_9).chi(x);
        assert!((near / want - 1.0).abs() < 1e-5, "{near} {want}");
        // Compressible, patch much wider than l (z = a/l about 26): Winkler's (3 pi/4)(M/E*) u,
        // M/E* = (1 - nu)^2/(1 - 2 nu), to first order in l/a (0.56 % here).
        let (nu, tau, x) = (0.3, 0.005, 0.01);
        let u = f64::sqrt(x) / tau;
        let winkler =
            3.0 * std::f64::consts::PI / 4.0 * (1.0 - nu) * (1.0 - nu) / (1.0 - 2.0 * nu) * u;
        let got = ThinLayer::new(tau, nu).chi(x);
        assert!((got / winkler - 1.0).abs() < 0.01, "{got} {winkler}");
        // K from the series and from the Bessel ratio agree at the switch (1.9e-12 apart in K;
        // G moves by 2e-12 over the 1e-12 step itself).
        let (k0, g0, d0) = kernel(SERIES_END * (1.0 - 1e-12));
        let (k1, g1, d1) = kernel(SERIES_END);
        assert!((k0 / k1 - 1.0).abs() < 1e-10, "{k0} {k1}");
        assert!(
            (g0 / g1 - 1.0).abs() < 1e-11 && (d0 / d1 - 1.0).abs() < 1e-9,
            "{g0} {g1} {d0} {d1}"
        );
    }

    /// The shortcut of `excess`: `chi_thin <= (3 pi/8) u^3 2 (1 - nu)` over nu in [0.3, 0.5],
    /// t/R in [0.05, 0.98] and x in [1e-4, 0.6], with equality at nu = 1/2.
    #[test]
    fn bound_holds() {
        let mut worst = 0.0f64;
        for i in 0..=20 {
            let nu = 0.3 + 0.01 * f64::from(i);
            for tau in [0.05, 0.07, 0.1, 0.15, 0.2, 0.3, 0.5, 0.7, 0.98] {
                let t = ThinLayer::new(tau, nu);
                for k in 0..=60 {
                    let x = 1e-4 * 6000f64.powf(f64::from(k) / 60.0);
                    worst = worst.max(t.chi(x) / t.bound(x));
                }
            }
        }
        eprintln!("largest chi_thin over its bound: {worst}");
        assert!(worst <= 1.0 + 1e-12, "{worst}");
        assert!(worst >= 1.0 - 1e-12, "{worst}");
    }

    /// Against scipy's Matthewson (`tools/calibration/try_thin_skin_s20.py`, `matthewson`,
    /// brentq on `2 + z^2/2 - z i0e(z)/i1e(z)`): printed values. Within 1e-7: the script's
    /// `F = pi (M/t) a^2 (delta - a^2/4)` cancels at small z (z = 0.1 in the fourth case: 6e-9
    /// apart there, 1e-11 in the others).
    #[test]
    fn matches_the_calibration_script() {
        for (x, nu, tau, want) in [
            (0.01, 0.3, 0.05, 3.884_849_079_420_779),
            (0.02, 0.48, 0.08, 5.347_979_232_793_617),
            (0.03, 0.4, 0.1, 3.545_605_361_162_981),
            (0.0004, 0.45, 0.2, 0.001_293_262_108_914_271),
            (0.01, 0.3, 0.005, 57.403_350_255_996_1),
            (0.3, 0.35, 0.6, 0.819_561_159_244_380_7),
        ] {
            let got = ThinLayer::new(tau, nu).chi(x);
            assert!(
                (got / want - 1.0).abs() < 1e-7,
                "{x} {nu} {tau}: {got} {want}"
            );
        }
    }
}
