//! The metadata of every softgrip version reads as today's types
//! ([`softgrip_record::metadata::legacy`]): `tests/data/default_text_metadata.mcap` is the
//! default grasp as recorded before the records were typed JSON (`git show
//! 12ba9ad:recordings/default.mcap`, 2026-11-22: laws as text lines, the run summary as flat
//! `NAME.field` keys), `tests/data/default_y_up_tactile.mcap` after it (`git show
//! 3d922f2:recordings/default.mcap`, 2026-12-02: typed JSON, y-up, tactile pads). Both hold
//! the same run (peak force 11.82 N on both tips), so both read the same laws and summary.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_law::{Backing, Level};
use softgrip_record::metadata::legacy::{recording_info, run_summary};
use softgrip_record::{METADATA_NAME, RUN_SUMMARY_NAME, Recording};

fn open(name: &str) -> Recording {
    Recording::open(format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

#[test]
fn text_laws_and_flat_summaries_read_as_todays_records() {
    let old = open("default_text_metadata.mcap");
    // Today's typed reader refuses the text laws; the legacy reader takes them.
    assert!(old.info().is_err());
    let newer = open("default_y_up_tactile.mcap");
    for rec in [&old, &newer] {
        let info = recording_info(&rec.metadata[METADATA_NAME]).unwrap();
        assert_eq!((info.every_n_steps, info.steps), (4, 300));
        assert_eq!(info.dt, 1.0 / 60.0);
        assert_eq!(info.origin, "scenes/default.toml");
        assert_eq!(info.law.len(), 2);
        let tip = &info.law[1];
        assert_eq!(tip.name, "right_tip");
        assert_eq!(tip.level, Level::Auto { tolerance: 0.01 });
        assert_eq!(
            (tip.youngs_modulus, tip.poisson_ratio, tip.radius),
            (590000.0, 0.49, 0.01)
        );
        assert_eq!((tip.friction, tip.restitution), (0.8, 0.5));
        assert_eq!(tip.backing, Backing::Free);
        assert!(tip.law().unwrap().response(1e-3).force > 0.0);
        let summary = run_summary(&rec.metadata[RUN_SUMMARY_NAME]).unwrap();
        assert_eq!(summary.steps, 300);
        let left = summary.tip("left_tip").unwrap();
        assert_eq!(left.peak_force, 11.82173681913686);
        assert_eq!(left.peak_x, 0.2002445684016837);
        assert_eq!((left.slips, left.validity_excursions), (2, 0));
    }
    // Today's record is read as it is.
    let today = open("default_before_backing.mcap");
    let info = recording_info(&today.metadata[METADATA_NAME]).unwrap();
    assert_eq!(Some(info), today.info().unwrap());
    let summary = run_summary(&today.metadata[RUN_SUMMARY_NAME]).unwrap();
    assert_eq!(Some(summary), today.run_summary().unwrap());
}

#[test]
fn a_bad_legacy_value_is_an_error_naming_it() {
    let mut map = open("default_text_metadata.mcap").metadata[METADATA_NAME].clone();
    map.insert("law".into(), "left_tip: level=spring radius=0.01".into());
    let e = recording_info(&map).unwrap_err().to_string();
    assert!(e.contains("spring"), "{e}");
    map.insert("law".into(), "no level here".into());
    let e = recording_info(&map).unwrap_err().to_string();
    assert!(e.contains("no `: level=`"), "{e}");
    map.insert("steps".into(), "three hundred".into());
    let e = recording_info(&map).unwrap_err().to_string();
    assert!(e.contains("`steps` is not a count"), "{e}");
    let mut summary = open("default_text_metadata.mcap").metadata[RUN_SUMMARY_NAME].clone();
    summary.insert("left_tip.peak_force".into(), "lots".into());
    let e = run_summary(&summary).unwrap_err().to_string();
    assert!(e.contains("left_tip.peak_force"), "{e}");
}
