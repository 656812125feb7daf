//! The kinds tables ([`LEVELS`], [`BACKINGS`]): every variant of [`Level`], [`LevelKind`],
//! [`Backing`] and [`BackingKind`] has its row (the matches below are exhaustive: a new
//! variant does not compile here until it is listed, and fails until its row exists), the
//! codes written to files are the ones every recording so far has used, and each row's
//! settings, defaults and data agree with what the law builds.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use std::collections::HashSet;
use std::sync::Arc;

use softgrip_law::{
    BACKINGS, Backing, BackingKind, ContactLaw, ContactParams, Error, LEVELS, Level, LevelData,
    LevelKind, NormalisedLaw, TabulatedCurve, setting_keys,
};

/// One value of each variant (with default settings). Exhaustive: a new variant is a compile
/// error here until it is added.
fn every_level() -> Vec<Level> {
    let all = [
        Level::linear(),
        Level::Hertz,
        Level::fit(),
        Level::Incompressible,
        Level::NeoHookean,
        Level::NeoHookeanExact,
        Level::Tatara,
        Level::Calibrated,
        Level::Tabulated,
        Level::Custom,
        Level::auto(),
    ];
    for l in &all {
        match l {
            Level::Linear { .. }
            | Level::Hertz
            | Level::Fit { .. }
            | Level::Incompressible
            | Level::NeoHookean
            | Level::NeoHookeanExact
            | Level::Tatara
            | Level::Calibrated
            | Level::Tabulated
            | Level::Custom
            | Level::Auto { .. } => {}
        }
    }
    all.to_vec()
}

/// Every concrete level and its code in files since the first recording. Exhaustive.
fn every_kind() -> Vec<(LevelKind, u8)> {
    let code = |k: LevelKind| match k {
        LevelKind::Linear => 0,
        LevelKind::Hertz => 1,
        LevelKind::Fit => 2,
        LevelKind::Incompressible => 3,
        LevelKind::NeoHookean => 4,
        LevelKind::NeoHookeanExact => 5,
        LevelKind::Tatara => 6,
        LevelKind::Calibrated => 7,
        LevelKind::Tabulated => 8,
        LevelKind::Custom => 9,
    };
    [
        LevelKind::Linear,
        LevelKind::Hertz,
        LevelKind::Fit,
        LevelKind::Incompressible,
        LevelKind::NeoHookean,
        LevelKind::NeoHookeanExact,
        LevelKind::Tatara,
        LevelKind::Calibrated,
        LevelKind::Tabulated,
        LevelKind::Custom,
    ]
    .into_iter()
    .map(|k| (k, code(k)))
    .collect()
}

/// Every construction and its code in files since constructions were recorded. Exhaustive.
fn every_backing() -> Vec<(Backing, BackingKind, u8)> {
    let row = |b: Backing| match b {
        Backing::Free => (b, BackingKind::Free, 0),
        Backing::Flat => (b, BackingKind::Flat, 1),
        Backing::Core { .. } => (b, BackingKind::Core, 2),
    };
    [
        Backing::Free,
        Backing::Flat,
        Backing::Core { thickness: 0.004 },
    ]
    .into_iter()
    .map(row)
    .collect()
}

#[test]
fn every_level_variant_has_exactly_one_row() {
    let levels = every_level();
    assert_eq!(levels.len(), LEVELS.len(), "a row per variant, no more");
    for level in levels {
        let rows: Vec<_> = LEVELS
            .iter()
            .filter(|r| std::mem::discriminant(&r.level) == std::mem::discriminant(&level))
            .collect();
        assert_eq!(rows.len(), 1, "{level:?}");
        assert_eq!(level.info().name, rows[0].name);
        assert_eq!(
            level.info().level,
            level,
            "the row holds the default settings"
        );
        assert_eq!(Level::from_name(level.name()).unwrap(), level);
        assert_eq!(level.to_string().parse::<Level>().unwrap(), level);
    }
    let names: HashSet<_> = LEVELS.iter().map(|r| r.name).collect();
    assert_eq!(names.len(), LEVELS.len(), "names are unique");
}

#[test]
fn level_codes_are_the_ones_every_recording_used() {
    let kinds = every_kind();
    let with_kind = LEVELS.iter().filter(|r| r.kind.is_some()).count();
    assert_eq!(kinds.len(), with_kind, "a row per concrete level");
    for (kind, code) in kinds {
        assert_eq!(kind.code(), code, "{kind}: codes never change");
        assert_eq!(LevelKind::from_code(code), Some(kind));
        assert_eq!(kind.level().kind(), Some(kind));
        assert_eq!(kind.info().code, Some(code));
    }
    for row in &LEVELS {
        assert_eq!(row.kind.is_some(), row.code.is_some(), "{}", row.name);
    }
    let codes: HashSet<_> = LEVELS.iter().filter_map(|r| r.code).collect();
    assert_eq!(codes.len(), every_kind().len(), "codes are unique");
    assert_eq!(LevelKind::from_code(10), None);
    assert_eq!(
        Level::auto().kind(),
        None,
        "auto picks a concrete level per call"
    );
}

#[test]
fn backing_codes_are_the_ones_every_recording_used() {
    let backings = every_backing();
    assert_eq!(backings.len(), BACKINGS.len());
    for (backing, kind, code) in backings {
        assert_eq!((backing.kind(), backing.code()), (kind, code));
        assert_eq!(BackingKind::from_code(code), Some(kind));
        assert_eq!(kind.info().name, backing.name());
        let thickness = backing.thickness();
        assert_eq!(kind.info().parameter.is_some(), thickness.is_some());
        assert_eq!(
            Backing::try_from_parts(backing.name(), thickness),
            Ok(backing)
        );
    }
    assert_eq!(Backing::NAMES.to_vec(), BACKINGS.map(|r| r.name).to_vec());
    let names: HashSet<_> = BACKINGS.iter().map(|r| r.name).collect();
    assert_eq!(names.len(), BACKINGS.len());
}

#[test]
fn every_setting_reads_sets_and_checks_from_its_row() {
    for row in &LEVELS {
        for s in row.settings {
            assert_eq!(
                (s.get)(&row.level),
                Some(s.default),
                "{}.{}",
                row.name,
                s.key
            );
            assert_eq!(row.level.setting(s.key), Some(s.default));
            assert!(s.range.contains(s.default), "{}: default in range", s.key);
            assert!(
                s.range.text().contains(&s.range.bounds()),
                "{}: `{}` names {}",
                s.key,
                s.range.text(),
                s.range.bounds()
            );
            // Inside the range: set and read back; outside: the typed error of the key.
            let inside = 0.5 * (s.range.min() + s.range.max());
            let set = row.level.with_setting(s.key, inside).unwrap();
            assert_eq!(set.setting(s.key), Some(inside));
            for outside in [s.range.min() - 1.0, s.range.max() + 1.0, f64::NAN] {
                match row.level.with_setting(s.key, outside) {
                    Err(Error::InvalidParameter { field, range, .. }) => {
                        assert_eq!((field, range), (s.key, s.range.text()));
                    }
                    other => panic!("{}={outside}: {other:?}", s.key),
                }
            }
            // Every other level refuses the key, naming the level that takes it.
            for other in LEVELS.iter().filter(|o| o.setting(s.key).is_none()) {
                assert_eq!((s.get)(&other.level), None);
                let e = other.level.with_setting(s.key, s.default).unwrap_err();
                assert!(
                    matches!(&e, Error::UnexpectedSetting { field, .. } if *field == s.key)
                        && e.takes().contains(&row.name),
                    "{e}"
                );
            }
        }
    }
    let keys = setting_keys();
    assert_eq!(keys, ["match_x", "k", "tolerance"]);
    assert!(matches!(
        Level::Hertz.with_setting("stiffness", 1.0),
        Err(Error::UnknownName {
            field: "setting",
            ..
        })
    ));
}

#[derive(Debug)]
struct Half;

impl NormalisedLaw for Half {
    fn force_stiffness(&self, x: f64) -> (f64, f64) {
        (0.5 * x * x, x)
    }
    fn energy(&self, x: f64) -> f64 {
        x * x * x / 6.0
    }
    fn radius(&self, x: f64) -> f64 {
        x.sqrt()
    }
    fn x_max(&self) -> f64 {
        0.5
    }
}

#[test]
fn each_row_builds_the_level_it_names_with_the_data_it_says() {
    let params = ContactParams::try_from_parts(1.0e6, 0.01, 0.45).unwrap();
    for row in &LEVELS {
        let law = match row.data {
            LevelData::None => ContactLaw::try_new(params, row.level).unwrap(),
            LevelData::MeasuredCurve => {
                assert!(matches!(
                    ContactLaw::try_new(params, row.level),
                    Err(Error::LevelNeedsData { .. })
                ));
                let curve = TabulatedCurve::try_new(vec![0.001, 0.002, 0.003], vec![1.0, 3.0, 6.0])
                    .unwrap();
                ContactLaw::tabulated(params, curve).unwrap()
            }
            LevelData::UserLaw => {
                assert!(matches!(
                    ContactLaw::try_new(params, row.level),
                    Err(Error::LevelNeedsData { .. })
                ));
                ContactLaw::custom(params, Arc::new(Half)).unwrap()
            }
        };
        assert_eq!(law.level(), row.level, "{}", row.name);
        match row.kind {
            Some(kind) => assert_eq!(law.response(0.001).level, kind, "{}", row.name),
            // auto serves each x with one of the cheaper levels or calibrated.
            None => assert!(!law.auto_segments().is_empty()),
        }
    }
    let buildable: Vec<Level> = LEVELS
        .iter()
        .filter(|r| r.data == LevelData::None)
        .map(|r| r.level)
        .collect();
    assert_eq!(Level::ALL.to_vec(), buildable, "Level::ALL is the table's");
}

#[test]
fn backing_parse_errors_name_field_value_and_range() {
    let cases: [(&str, Option<f64>, &str); 6] = [
        (
            "steel",
            None,
            "`backing` must be one of free, flat, core, got `steel`",
        ),
        (
            "core",
            None,
            "`core_thickness` is required with backing `core`: the skin thickness t, finite and in (0, R) m",
        ),
        (
            "free",
            Some(0.002),
            "`core_thickness` applies only to backing `core`, not to backing `free` (got 0.002)",
        ),
        (
            "core",
            Some(-0.002),
            "`core_thickness` must be the skin thickness t, finite and in (0, R) m, R the fingertip's outer radius, got -0.002",
        ),
        ("core", Some(f64::NAN), "`core_thickness` must be"),
        ("core", Some(f64::INFINITY), "got inf"),
    ];
    for (name, thickness, message) in cases {
        let e = Backing::try_from_parts(name, thickness).unwrap_err();
        assert!(
            e.to_string().starts_with(message) || e.to_string().contains(message),
            "{name} {thickness:?}: {e}"
        );
    }
    assert_eq!("flat".parse::<Backing>(), Ok(Backing::Flat));
    assert!(matches!(
        "core".parse::<Backing>(),
        Err(Error::MissingSetting {
            field: "core_thickness",
            ..
        })
    ));
}
