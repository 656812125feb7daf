//! [`ContactLaw::recorded_curve`]: what a recording stores for the levels its parameters do not
//! rebuild. A tabulated law reads back bit for bit; a custom law reads back as a tabulated
//! sample of itself, its force within the tolerance stated in `CUSTOM_CURVE_SAMPLES`'s docs.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::sync::Arc;

use softgrip_law::{
    CUSTOM_CURVE_SAMPLES, ContactLaw, ContactParams, Level, LevelKind, NormalisedLaw,
    TabulatedCurve,
};

/// A built-in level behind the custom interface: `f = chi_IC(x) (4/3) x^1.5`-like shapes.
#[derive(Debug)]
struct Wrapped(ContactLaw);

impl NormalisedLaw for Wrapped {
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        let r = self.0.response(x);
        (r.force, r.stiffness)
    }
    fn energy(&self, x: f64) -> f64 {
        self.0.energy(x)
    }
    fn radius(&self, x: f64) -> f64 {
        self.0.patch(x).radius
    }
    fn x_max(&self) -> f64 {
        self.0.x_max()
    }
    fn name(&self) -> &str {
        self.0.level().name()
    }
}

/// Largest relative force error of `back` against `law` over x in [x_max/100, x_max].
fn worst(law: &ContactLaw, back: &ContactLaw) -> f64 {
    (0..=2000)
        .map(|i| {
            let x = law.x_max() * (0.01 + 0.99 * f64::from(i) / 2000.0);
            let delta = x * law.params().radius();
            let (a, b) = (law.response(delta).force, back.response(delta).force);
            (b / a - 1.0).abs()
        })
        .fold(0.0, f64::max)
}

#[test]
fn a_custom_law_reads_back_as_its_sample_within_5e_5() {
    let mut largest = 0.0_f64;
    for level in [
        Level::Hertz,
        Level::fit(),
        Level::Incompressible,
        Level::Calibrated,
    ] {
        for nu in [0.3, 0.45, 0.49] {
            let unit = ContactParams::try_from_parts(1.0, 1.0, nu).unwrap();
            let normalised = ContactLaw::try_new(unit, level).unwrap();
            let params = ContactParams::try_from_parts(2.3e5, 0.012, nu).unwrap();
            let custom = ContactLaw::custom(params, Arc::new(Wrapped(normalised))).unwrap();
            let curve = custom.recorded_curve().unwrap().unwrap();
            assert_eq!(
                curve.delta_m().len(),
                CUSTOM_CURVE_SAMPLES + 1,
                "origin + samples"
            );
            assert_eq!(curve.delta_max(), custom.delta_max());
            let back = ContactLaw::tabulated(params, curve).unwrap();
            assert_eq!(back.response(1e-3).level, LevelKind::Tabulated);
            let w = worst(&custom, &back);
            largest = largest.max(w);
            assert!(w < 5e-5, "{level} nu = {nu}: {w:e}");
        }
    }
    println!("largest relative force error of a recorded custom law: {largest:e}");
}

#[test]
fn a_tabulated_law_reads_back_bit_for_bit() {
    let params = ContactParams::try_from_parts(8.0e5, 0.01, 0.49).unwrap();
    let curve =
        TabulatedCurve::try_new(vec![0.0005, 0.001, 0.002, 0.003], vec![0.2, 0.6, 1.9, 3.7])
            .unwrap();
    let law = ContactLaw::tabulated(params, curve.clone()).unwrap();
    let recorded = law.recorded_curve().unwrap().unwrap();
    assert_eq!(recorded, curve);
    let back = ContactLaw::tabulated(params, recorded).unwrap();
    for i in 0..=400 {
        let delta = 3.5e-3 * f64::from(i) / 400.0;
        assert_eq!(law.response(delta), back.response(delta));
        assert_eq!(law.patch(delta), back.patch(delta));
    }
}

/// A law whose force dips between the 64 points `ContactLaw::custom` checks: the sample keeps
/// the points a measured curve can hold (non-decreasing), so it still records.
#[derive(Debug)]
struct Dipping;

impl NormalisedLaw for Dipping {
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        // A small dip just after each of the checked points x = i/64.
        let dip = if (x * 64.0).fract() > 0.0 && (x * 64.0).fract() < 0.1 {
            0.1
        } else {
            0.0
        };
        (x * x - dip * x * x, 2.0 * x)
    }
    fn energy(&self, x: f64) -> f64 {
        x * x * x / 3.0
    }
    fn radius(&self, x: f64) -> f64 {
        x.sqrt()
    }
    fn x_max(&self) -> f64 {
        1.0
    }
}

#[test]
fn a_custom_law_that_dips_between_its_checks_still_records() {
    let params = ContactParams::try_from_parts(1.0e6, 0.01, 0.4).unwrap();
    let custom = ContactLaw::custom(params, Arc::new(Dipping)).unwrap();
    let curve = custom.recorded_curve().unwrap().unwrap();
    assert!(
        curve.delta_m().len() < CUSTOM_CURVE_SAMPLES + 1,
        "dips left out"
    );
    assert!(curve.force_n().windows(2).all(|w| w[1] >= w[0]));
    assert_eq!(curve.delta_max(), custom.delta_max());
}
