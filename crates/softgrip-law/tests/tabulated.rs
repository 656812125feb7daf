//! The `tabulated` level: a measured curve sampled from a known law reproduces it; stiffness,
//! energy and inverse are consistent with the interpolant; past the table's end the checked API
//! errs and the hot path extends.

mod common;

use common::{grid, normalised};
use softgrip_law::{
    ContactLaw, ContactParams, Error, Level, LevelKind, Material, Regime, TabulatedCurve,
};

/// A silicone fingertip: R = 10 mm, E = 3 MPa, nu = 0.49.
fn tip() -> ContactParams {
    ContactParams::try_new(Material::try_new(3.0e6, 0.49).expect("valid"), 0.010).expect("valid")
}

/// `law` sampled at `n` equal steps of delta to `x_end` (the origin included), as a table.
fn sampled(law: &ContactLaw, x_end: f64, n: usize) -> TabulatedCurve {
    let r = law.params().radius();
    let delta: Vec<f64> = (0..=n).map(|i| x_end * r * i as f64 / n as f64).collect();
    let force = delta.iter().map(|&d| law.response(d).force).collect();
    TabulatedCurve::try_new(delta, force).expect("a law's samples are a valid table")
}

#[test]
fn a_table_sampled_from_the_calibrated_law_reproduces_it() {
    //! 65 samples (x = 0 .. 0.65 in steps of 0.01): between the nodes the interpolant is within
    //! 3e-4 of the law for x >= 0.05 (seen 1.4e-4), 5 % from half the first sample on (seen
    //! 3.3 %, in the first cell, where F ~ x^1.5 bends most) and 1e-4 of the largest force
    //! everywhere (seen 3.2e-5); at the nodes it is the sample.
    let cal = ContactLaw::try_new(tip(), Level::Calibrated).expect("builds");
    let law = ContactLaw::tabulated(tip(), sampled(&cal, 0.65, 65)).expect("builds");
    assert_eq!(law.level(), Level::Tabulated);
    assert!((law.x_max() - 0.65).abs() < 1e-12);
    let (mut rel, mut first, mut abs) = (0.0_f64, 0.0_f64, 0.0_f64);
    for x in grid(0.65, 2000) {
        let delta = x * 0.010;
        let (t, c) = (law.response(delta), cal.response(delta));
        assert_eq!(t.level, LevelKind::Tabulated);
        let err = (t.force / c.force - 1.0).abs();
        abs = abs.max((t.force - c.force).abs() / law.force_max());
        if x >= 0.05 {
            rel = rel.max(err);
        }
        if x >= 0.005 {
            first = first.max(err);
        }
    }
    assert!(rel < 3e-4, "relative force error {rel:e}");
    assert!(
        first < 0.05,
        "relative force error {first:e} from x = 0.005"
    );
    assert!(abs < 1e-4, "force error {abs:e} of F_max");
    let curve = law.tabulated_curve().expect("tabulated");
    for (&d, &f) in curve.delta_m().iter().zip(curve.force_n()) {
        assert!(
            (law.response(d).force - f).abs() <= 1e-12 * f.max(1e-12),
            "delta {d}"
        );
    }
}

#[test]
fn stiffness_is_the_derivative_of_the_interpolant() {
    let cal = ContactLaw::try_new(tip(), Level::Calibrated).expect("builds");
    let law = ContactLaw::tabulated(tip(), sampled(&cal, 0.65, 40)).expect("builds");
    for x in grid(0.65, 300) {
        let (d, h) = (x * 0.010, 1e-6 * x * 0.010);
        let fd = (law.response(d + h).force - law.response(d - h).force) / (2.0 * h);
        let k = law.response(d).stiffness;
        assert!((k - fd).abs() <= 1e-6 * k, "x={x}: K={k} fd={fd}");
    }
    // C1 at the nodes: the stiffness is continuous across them.
    for &d in &law.tabulated_curve().expect("tabulated").delta_m()[1..40] {
        let (below, above) = (law.response(d.next_down()), law.response(d.next_up()));
        assert!(
            (below.stiffness / above.stiffness - 1.0).abs() < 1e-9,
            "delta {d}"
        );
    }
}

#[test]
fn energy_is_the_integral_of_the_interpolant() {
    let cal = ContactLaw::try_new(tip(), Level::Calibrated).expect("builds");
    let law = ContactLaw::tabulated(tip(), sampled(&cal, 0.65, 13)).expect("builds");
    for x in grid(0.65, 9).into_iter().chain([0.65]) {
        let delta = x * 0.010;
        // Composite Simpson on a step that divides every cell (1/13 of 0.65 = 0.05): exact
        // for cubics, so exact up to rounding.
        let n = (x / 0.05 * 200.0).ceil() as usize * 2;
        let h = delta / n as f64;
        let mut s = law.response(0.0).force + law.response(delta).force;
        for i in 1..n {
            s += if i % 2 == 1 { 4.0 } else { 2.0 } * law.response(i as f64 * h).force;
        }
        let q = s * h / 3.0;
        let w = law.energy(delta);
        assert!((w / q - 1.0).abs() < 1e-9, "x={x}: W={w} quad={q}");
        assert_eq!(law.evaluate(delta).expect("in range").energy, w);
    }
}

#[test]
fn inverse_round_trip() {
    let cal = ContactLaw::try_new(tip(), Level::Calibrated).expect("builds");
    let law = ContactLaw::tabulated(tip(), sampled(&cal, 0.65, 20)).expect("builds");
    for x in grid(0.65, 200) {
        let f = law.response(x * 0.010).force;
        let back = law.compression_for_force(f).expect("in range");
        assert!(
            (back / (x * 0.010) - 1.0).abs() < 1e-9,
            "x={x}: back {back}"
        );
    }
    assert!(matches!(
        law.compression_for_force(law.force_max() * 1.01),
        Err(Error::ForceOutOfRange {
            level: LevelKind::Tabulated,
            ..
        })
    ));
}

#[test]
fn past_the_table_the_checked_api_errs_and_the_hot_path_extends() {
    let cal = normalised(Level::Calibrated, 0.49);
    let p = ContactParams::try_from_parts(1.0, 1.0, 0.49).expect("valid");
    let law = ContactLaw::tabulated(p, sampled(&cal, 0.5, 10)).expect("builds");
    match law.evaluate(0.6) {
        Err(Error::OutOfRange { level, x, x_max }) => {
            assert_eq!((level, x, x_max), (LevelKind::Tabulated, 0.6, 0.5));
        }
        other => panic!("expected OutOfRange, got {other:?}"),
    }
    assert!(law.try_response(0.6).is_err());
    assert!(law.evaluate(0.5).is_ok());
    // The extension: the tangent at the last sample plus the barrier c u^2/(1-u) against the
    // wall at x = 1 (a free sphere's centre), C1 there: L = 0.5, c = F + K L, u = 0.1/L = 0.2.
    let (end, past) = (law.response(0.5), law.response(0.6));
    assert_eq!(past.regime, Regime::Extended);
    assert_eq!(law.x_wall(), 1.0);
    let (len, u) = (0.5, 0.2);
    let c = end.force + end.stiffness * len;
    let k_want = end.stiffness + c / len * u * (2.0 - u) / ((1.0 - u) * (1.0 - u));
    assert!((past.stiffness / k_want - 1.0).abs() < 1e-12);
    let f_want = end.force + 0.1 * end.stiffness + c * u * u / (1.0 - u);
    assert!((past.force / f_want - 1.0).abs() < 1e-12);
    let just = law.response(0.5 * (1.0 + 1e-12));
    assert!((just.force / end.force - 1.0).abs() < 1e-9);
}

#[test]
fn the_radius_is_hertz_radius_of_the_measured_force() {
    let cal = ContactLaw::try_new(tip(), Level::Calibrated).expect("builds");
    let law = ContactLaw::tabulated(tip(), sampled(&cal, 0.65, 65)).expect("builds");
    let e_star = tip().effective_modulus();
    for x in [0.05, 0.2, 0.5] {
        let delta = x * 0.010;
        let f = law.response(delta).force;
        let a = law.patch(delta).radius;
        let hertz = (3.0 * f * 0.010 / (4.0 * e_star)).cbrt();
        assert!((a / hertz - 1.0).abs() < 1e-12, "x={x}");
        // Wider than the geometric sqrt(R delta) for a law stiffer than Hertz.
        assert!(a > (0.010 * delta).sqrt());
    }
}

#[test]
fn a_table_of_hertz_stays_close_to_hertz() {
    //! The first cell (from the origin) is the hardest: Hertz's F ~ x^1.5 has an infinite
    //! curvature there. With 50 samples to x = 0.5 the table is within 2e-4 of F_max (seen
    //! 8.4e-5) and within 6 % of the force from half the first sample on (seen 4.1 %); with the
    //! zero slope at the origin it starts as Hertz does, with zero stiffness.
    let hertz = normalised(Level::Hertz, 0.5);
    let p = ContactParams::try_from_parts(1.0, 1.0, 0.5).expect("valid");
    let law = ContactLaw::tabulated(p, sampled(&hertz, 0.5, 50)).expect("builds");
    for x in grid(0.5, 1000) {
        let (t, h) = (law.response(x).force, hertz.response(x).force);
        let err = (t - h).abs() / law.force_max();
        assert!(err < 2e-4, "x={x}: {err:e}");
        if x >= 0.005 {
            assert!((t / h - 1.0).abs() < 0.06, "x={x}: {t} vs {h}");
        }
    }
    assert!(law.response(1e-9).stiffness < 1e-6);
}
