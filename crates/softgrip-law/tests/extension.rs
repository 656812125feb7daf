//! The extension past a law's validity range, for every level and construction: continuous
//! with its first derivative at `x_max`, monotone, its stiffness the derivative and its energy
//! the integral of its force, finite for any finite input, and a barrier that grows without
//! bound before the wall (`x_wall`: the fingertip's rigid part at the surface it presses).

mod common;

use std::sync::Arc;

use common::{levels_at, normalised};
use softgrip_law::{
    Backing, ContactLaw, ContactParams, Counterpart, Level, NormalisedLaw, Regime, TabulatedCurve,
};

/// Every law the checks run on, with a name: each level at four nu, the backed
/// constructions, counterparts, a tabulated and a custom law.
fn laws() -> Vec<(String, ContactLaw)> {
    let mut out = Vec::new();
    for nu in [0.3, 0.4, 0.49, 0.5] {
        for law in levels_at(nu) {
            out.push((format!("{} nu {nu}", law.level()), law));
        }
    }
    for (backing, nu) in [
        (Backing::Flat, 0.49),
        (Backing::Flat, 0.3),
        (Backing::Core { thickness: 0.2 }, 0.45),
        (Backing::Core { thickness: 0.05 }, 0.3),
        (Backing::Core { thickness: 0.5 }, 0.49),
    ] {
        let p = ContactParams::try_from_parts(1.0, 1.0, nu)
            .and_then(|p| p.with_backing(backing))
            .expect("params");
        let law = ContactLaw::try_new(p, Level::Calibrated).expect("backed law");
        out.push((format!("calibrated {backing:?} nu {nu}"), law.clone()));
        for cp in [
            Counterpart::try_ball(1.0).expect("ball"),
            Counterpart::try_curved(0.5, 0.0).expect("cylinder"),
        ] {
            if let Ok(on) = law.with_counterpart(cp) {
                out.push((format!("calibrated {backing:?} nu {nu} on {cp:?}"), on));
            }
        }
    }
    for nu in [0.3, 0.49] {
        for level in [Level::Calibrated, Level::Hertz, Level::fit()] {
            let law = normalised(level, nu);
            for cp in [
                Counterpart::try_ball(1.0).expect("ball"),
                Counterpart::try_ball(0.1).expect("small ball"),
                Counterpart::try_curved(-0.5, -0.5).expect("bowl"),
                Counterpart::EDGE,
            ] {
                if let Ok(on) = law.with_counterpart(cp) {
                    out.push((format!("{level} nu {nu} on {cp:?}"), on));
                }
            }
        }
    }
    let p = ContactParams::try_from_parts(1.0, 1.0, 0.49).expect("params");
    let table = TabulatedCurve::try_new(vec![0.1, 0.2, 0.3, 0.5], vec![0.06, 0.2, 0.45, 1.4])
        .expect("table");
    out.push((
        "tabulated".into(),
        ContactLaw::tabulated(p, table).expect("tabulated"),
    ));
    // A table that reaches past the physical wall: its own wall is 10 % past its end.
    let deep = TabulatedCurve::try_new(vec![0.5, 1.0, 2.0], vec![0.5, 2.0, 9.0]).expect("table");
    out.push((
        "tabulated to x = 2".into(),
        ContactLaw::tabulated(p, deep).expect("tabulated"),
    ));
    out.push((
        "custom".into(),
        ContactLaw::custom(p, Arc::new(DoubleHertz)).expect("custom"),
    ));
    out.push((
        "custom, zero".into(),
        ContactLaw::custom(p, Arc::new(Zero)).expect("custom"),
    ));
    out
}

#[derive(Debug)]
struct DoubleHertz;

impl NormalisedLaw for DoubleHertz {
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        (8.0 / 3.0 * x * x.sqrt(), 4.0 * x.sqrt())
    }
    fn energy(&self, x: f64) -> f64 {
        16.0 / 15.0 * x * x * x.sqrt()
    }
    fn radius(&self, x: f64) -> f64 {
        x.sqrt()
    }
    fn x_max(&self) -> f64 {
        0.5
    }
}

/// A law with no force at all: the barrier takes Hertz's force at the edge as its scale.
#[derive(Debug)]
struct Zero;

impl NormalisedLaw for Zero {
    fn force_stiffness(&self, _x: f64) -> (f64, f64) {
        (0.0, 0.0)
    }
    fn energy(&self, _x: f64) -> f64 {
        0.0
    }
    fn radius(&self, x: f64) -> f64 {
        x.sqrt()
    }
    fn x_max(&self) -> f64 {
        0.5
    }
}

/// Compressions from `delta_max` towards the wall, `1 - u` = 0.9, 0.5, 0.1, ... 1e-5 of the way
/// left, then past the wall (every law here has E* = 1 Pa and R = 1 m).
fn probes(law: &ContactLaw) -> Vec<f64> {
    let r = law.params().radius();
    let (d0, dw) = (law.delta_max(), law.x_wall() * r);
    let mut v: Vec<f64> = [0.1, 0.5, 0.9, 0.99, 0.999, 0.9999, 0.99999]
        .iter()
        .map(|u| d0 + u * (dw - d0))
        .collect();
    // Past it, up to half the way again (the force is frozen at `max(x_wall + L, 4)`).
    v.extend([dw, dw + 1e-9 * dw, dw + 0.5 * (dw - d0)]);
    v
}

#[test]
fn the_extension_is_c1_at_the_edge_and_its_wall_lies_past_it() {
    for (name, law) in laws() {
        let d = law.delta_max();
        assert!(law.x_wall() > law.x_max(), "{name}");
        let (inside, outside) = (law.response(d), law.response(d * (1.0 + 1e-12)));
        assert_eq!(outside.regime, Regime::Extended, "{name}");
        let df = (outside.force - inside.force).abs();
        assert!(df <= 1e-9 * inside.force.max(1e-12), "{name}: {df}");
        let dk = (outside.stiffness - inside.stiffness).abs();
        assert!(dk <= 1e-6 * inside.stiffness.max(1e-3), "{name}: {dk}");
    }
}

#[test]
fn the_extension_is_monotone_finite_and_diverges_at_the_wall() {
    for (name, law) in laws() {
        let (mut f_prev, mut w_prev) = (law.response(law.delta_max()).force, 0.0);
        for d in probes(&law) {
            let r = law.response(d);
            let w = law.energy(d);
            assert!(
                r.force.is_finite() && r.stiffness.is_finite() && w.is_finite(),
                "{name}"
            );
            assert!(r.force > f_prev && r.stiffness > 0.0, "{name} at {d}");
            assert!(w > w_prev, "{name} at {d}");
            assert_eq!(r.regime, Regime::Extended);
            (f_prev, w_prev) = (r.force, w);
        }
        // 1e-4 of the way short of the wall the barrier holds over 1000 times the range's end
        // (`c >= F(x_max)`: c u^2/(1-u) ~ 1e4 c). The zero law has no force to compare with.
        let (d0, dw) = (law.delta_max(), law.x_wall() * law.params().radius());
        let near = law.response(d0 + (1.0 - 1e-4) * (dw - d0)).force;
        assert!(near > 1000.0 * law.force_max(), "{name}: {near}");
        // Any finite input: finite outputs, even where x = delta/R overflows.
        for d in [1e10, 1e300, f64::MAX] {
            let r = law.response(d);
            assert!(r.force.is_finite() && r.force >= 0.0, "{name}");
            assert!(
                r.stiffness.is_finite() && law.energy(d).is_finite(),
                "{name}"
            );
            let p = law.patch(d);
            assert!(
                p.radius.is_finite() && p.mean_pressure.is_finite(),
                "{name}"
            );
        }
    }
}

#[test]
fn the_extension_stiffness_is_the_derivative_of_its_force() {
    for (name, law) in laws() {
        let dw = law.x_wall() * law.params().radius();
        for d in probes(&law) {
            // A step well inside the distance to the wall (or past it, in the straight part).
            let h = if d < dw {
                1e-5 * (dw - d)
            } else {
                1e-3 * (d - dw + 1e-6 * (dw - law.delta_max()))
            };
            let fd = (law.response(d + h).force - law.response(d - h).force) / (2.0 * h);
            let k = law.response(d).stiffness;
            assert!((k - fd).abs() <= 1e-5 * k, "{name} at {d}: K {k} fd {fd}");
        }
    }
}

/// Simpson's rule on `[a, b]` with `n` (even) panels.
fn simpson(g: impl Fn(f64) -> f64, a: f64, b: f64, n: u32) -> f64 {
    let h = (b - a) / f64::from(n);
    let mut s = g(a) + g(b);
    for i in 1..n {
        s += if i % 2 == 1 { 4.0 } else { 2.0 } * g(a + f64::from(i) * h);
    }
    s * h / 3.0
}

#[test]
fn the_extension_energy_is_the_integral_of_its_force() {
    for (name, law) in laws() {
        let r = law.params().radius();
        let (d0, dw) = (law.delta_max(), law.x_wall() * r);
        let g = |d: f64| law.response(d).force;
        // Segments [1 - 10^-j, 1 - 10^-(j+1)] of the way to the wall, where the barrier's
        // 1/(1-u) grows ten-fold, then the straight part past the hand-over.
        let mut lo = d0;
        let mut integral = 0.0;
        for j in 1..=6 {
            let hi = d0 + (1.0 - 10f64.powi(-j)) * (dw - d0);
            integral += simpson(g, lo, hi, 2000);
            lo = hi;
            let got = law.energy(hi) - law.energy(d0);
            assert!(
                (got / integral - 1.0).abs() < 1e-9,
                "{name} to 1 - 1e-{j}: W {got} quadrature {integral}"
            );
        }
        // Past the wall: the tangent at the hand-over, exactly quadratic in delta.
        let (a, b) = (1.01 * dw, 1.5 * dw);
        let got = law.energy(b) - law.energy(a);
        let q = simpson(g, a, b, 2);
        assert!(
            (got / q - 1.0).abs() < 1e-9,
            "{name} past the wall: {got} {q}"
        );
    }
}
