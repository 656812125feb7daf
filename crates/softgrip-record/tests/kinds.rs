//! Every level and construction of the law's tables round-trips through a recording's
//! metadata ([`FingertipLaw`]), `tabulated` and `custom` included (their curve is recorded),
//! and a recording made before curves were recorded still reads:
//! `tests/data/tabulated_before_curve.mcap` is `scenes/default.toml` with the left fingertip's
//! level `{ tabulated = "tip.csv" }` and both tips `backing = "flat"`, run with `softgrip run
//! --out` at main 30ba0a8 (2026-12-04, before issue 26 item 2): its metadata names the level
//! `tabulated` and holds no curve (`softgrip inspect` of it said "unknown level").

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::sync::Arc;

use softgrip_law::{
    BACKINGS, Backing, ContactLaw, ContactParams, Error, LEVELS, Level, LevelData, Material,
    NormalisedLaw, TabulatedCurve,
};
use softgrip_record::{FingertipLaw, Recording};

fn record(level: Level, backing: Backing) -> FingertipLaw {
    FingertipLaw {
        name: "tip".into(),
        level,
        youngs_modulus: 5.9e5,
        poisson_ratio: 0.49,
        radius: 0.01,
        friction: 0.8,
        restitution: 0.5,
        backing,
        curve: None,
        custom_name: None,
    }
}

fn params(backing: Backing) -> ContactParams {
    ContactParams::try_new(Material::try_new(5.9e5, 0.49).unwrap(), 0.01)
        .unwrap()
        .with_backing(backing)
        .unwrap()
}

fn json_round_trip(law: &FingertipLaw) -> FingertipLaw {
    let json = serde_json::to_string(law).unwrap();
    serde_json::from_str(&json).unwrap_or_else(|e| panic!("{json}: {e}"))
}

/// A measured-looking curve: 1.2 x Hertz's force of the fingertip, 12 samples to 3 mm.
fn curve() -> TabulatedCurve {
    let hertz = ContactLaw::try_new(params(Backing::Free), Level::Hertz).unwrap();
    let delta: Vec<f64> = (1..=12).map(|i| 0.00025 * f64::from(i)).collect();
    let force = delta
        .iter()
        .map(|&d| 1.2 * hertz.response(d).force)
        .collect();
    TabulatedCurve::try_new(delta, force).unwrap()
}

#[test]
fn every_buildable_level_with_every_backing_round_trips_through_the_metadata() {
    for row in LEVELS.iter().filter(|r| r.data == LevelData::None) {
        for b in BACKINGS {
            let backing = b.kind.with_parameter(0.004);
            // A non-default value of each setting, so that a dropped one shows.
            let mut level = row.level;
            for s in row.settings {
                level = level.with_setting(s.key, s.default * 0.5).unwrap();
            }
            let law = record(level, backing);
            let back = json_round_trip(&law);
            assert_eq!(back, law, "{}", row.name);
            let (a, b) = (law.law().unwrap(), back.law().unwrap());
            assert_eq!(
                a.response(0.002).force.to_bits(),
                b.response(0.002).force.to_bits()
            );
        }
    }
}

#[test]
fn tabulated_level_round_trips_with_its_curve_bit_for_bit() {
    let backing = Backing::Flat;
    let original = ContactLaw::tabulated(params(backing), curve()).unwrap();
    let mut law = record(Level::Tabulated, backing);
    law.curve = original.recorded_curve().unwrap();
    assert_eq!(law.curve.as_ref(), original.tabulated_curve());
    let back = json_round_trip(&law);
    assert_eq!(back, law);
    let rebuilt = back.law().unwrap();
    assert_eq!(rebuilt.level(), Level::Tabulated);
    for i in 0..=40 {
        let delta = 0.0001 * f64::from(i);
        let (a, b) = (original.response(delta), rebuilt.response(delta));
        assert_eq!(a.force.to_bits(), b.force.to_bits(), "delta {delta}");
        assert_eq!(
            a.stiffness.to_bits(),
            b.stiffness.to_bits(),
            "delta {delta}"
        );
    }
}

/// Twice Hertz's normalised force, as a user might write a law.
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
    fn name(&self) -> &str {
        "double-hertz"
    }
}

#[test]
fn custom_level_round_trips_as_its_sampled_curve_and_name() {
    let original = ContactLaw::custom(params(Backing::Free), Arc::new(DoubleHertz)).unwrap();
    let mut law = record(Level::Custom, Backing::Free);
    law.curve = original.recorded_curve().unwrap();
    law.custom_name = original.custom_name().map(str::to_owned);
    let back = json_round_trip(&law);
    assert_eq!(back, law);
    assert_eq!(back.custom_name.as_deref(), Some("double-hertz"));
    assert!(
        back.to_string()
            .contains("level=custom custom_name=double-hertz")
    );
    let rebuilt = back.law().unwrap();
    // From x_max/100 to x_max the sampled curve is within 2e-5 of the law (CUSTOM_CURVE_SAMPLES).
    let delta_max = original.delta_max();
    for i in 1..=100 {
        let delta = delta_max * f64::from(i) / 100.0;
        let (a, b) = (
            original.response(delta).force,
            rebuilt.response(delta).force,
        );
        assert!((b / a - 1.0).abs() < 2e-5, "delta {delta}: {a} vs {b}");
    }
}

#[test]
fn a_recording_made_before_curves_were_recorded_still_reads() {
    let rec = Recording::open(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/tabulated_before_curve.mcap"
    ))
    .unwrap();
    let info = rec.info().unwrap().expect("the recording has its metadata");
    assert_eq!(info.law.len(), 2);
    let left = &info.law[0];
    assert_eq!(left.name, "left_tip");
    assert_eq!(
        (left.level, left.backing),
        (Level::Tabulated, Backing::Flat)
    );
    assert_eq!(
        (left.curve.as_ref(), left.custom_name.as_deref()),
        (None, None)
    );
    assert_eq!((left.youngs_modulus, left.radius), (590000.0, 0.01));
    // Its law cannot be rebuilt (the curve was never written), and says so; the overlays of
    // levels its parameters build still can be.
    assert!(matches!(left.law(), Err(Error::LevelNeedsData { .. })));
    assert!(left.law_at(Level::Hertz).unwrap().response(1e-3).force > 0.0);
    let right = &info.law[1];
    assert_eq!(right.level, Level::Auto { tolerance: 0.01 });
    assert!(right.law().unwrap().response(1e-3).force > 0.0);
}

#[test]
fn a_bad_kind_in_the_metadata_is_an_error_naming_it() {
    let json = serde_json::to_string(&record(Level::fit(), Backing::Flat)).unwrap();
    for (from, to, says) in [
        (
            r#""name":"fit""#,
            r#""name":"spring""#,
            "`level` must be one of",
        ),
        (
            r#""backing":"flat""#,
            r#""backing":"steel""#,
            "`backing` must be one of",
        ),
        (
            r#""backing":"flat""#,
            r#""backing":"flat","core_thickness":0.004"#,
            "`core_thickness` applies only to backing `core`",
        ),
        (
            r#""backing":"flat""#,
            r#""backing":"core""#,
            "`core_thickness` is required",
        ),
        (
            r#""k":"#,
            r#""tolerance":"#,
            "`tolerance` applies only to level `auto`",
        ),
    ] {
        let bad = json.replace(from, to);
        assert_ne!(bad, json, "{from}");
        let e = serde_json::from_str::<FingertipLaw>(&bad)
            .unwrap_err()
            .to_string();
        assert!(e.contains(says), "{bad}: {e}");
    }
}
