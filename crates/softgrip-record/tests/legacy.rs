//! Recordings of earlier versions still read: `tests/data/default_before_backing.mcap` is the
//! default grasp as recorded before fingertips had a construction (`git show
//! 1fc2a14:recordings/default.mcap`, 2026-12-02): its `SoftContact` schema has no `backing` and
//! `core_thickness`. Its contacts decode, as free fingertips, with the values it was recorded
//! with (its own run summary: peak force 11.82 N on both tips).
//! `tests/data/default_before_counterpart.mcap` is the default grasp as recorded before the
//! counterpart and the elliptical patch (`git show 5c033ce:recordings/default.mcap`,
//! 2026-12-04): its schema has `backing` but no `contact_radius2`, `patch_direction`,
//! `counterpart` and curvatures; its contacts decode as discs on a plane, with the values it
//! was recorded with.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
use softgrip_record::{Message, Recording};

/// Decodes the legacy recording `file`, checks every contact row with `check` and with what
/// every recording's rows hold, and returns the run summary's peak force [N].
fn decode(file: &str, check: impl Fn(&SoftContactMsg)) -> f64 {
    let path = format!("{}/tests/data/{file}", env!("CARGO_MANIFEST_DIR"));
    let rec = Recording::open(&path).unwrap();
    let (mut arrays, mut rows) = (0, 0);
    let mut peak: f64 = 0.0;
    for m in &rec.messages {
        if let Message::Contacts(c) = &m.message {
            arrays += 1;
            for row in &c.contacts {
                rows += 1;
                assert!(row.normal_force.is_finite() && row.normal_force >= 0.0);
                assert!(row.max_compression >= row.compression, "{row:?}");
                check(row);
                peak = peak.max(row.peak_normal_force);
            }
        }
    }
    let summary = rec.run_summary().unwrap().unwrap();
    let recorded_peak = summary
        .fingertips
        .iter()
        .map(|f| f.peak_force)
        .fold(0.0_f64, f64::max);
    // 300 steps recorded every 4th: 75 contact arrays; the box is held in most of them.
    assert_eq!(arrays, 75);
    assert!(rows > 100, "{rows}");
    // The recorded steps hold the summary's peak (written every substep) to 4 digits.
    assert!(
        (peak / recorded_peak - 1.0).abs() < 1e-3,
        "{peak} vs {recorded_peak}"
    );
    recorded_peak
}

#[test]
fn contacts_recorded_before_backing_decode_as_free_fingertips() {
    let recorded_peak = decode("default_before_backing.mcap", |row| {
        assert_eq!((row.backing, row.core_thickness), (0, 0.0));
        assert!(row.fingertip == "left_tip" || row.fingertip == "right_tip");
    });
    // The run summary written with the file says 11.82 N.
    assert!((recorded_peak - 11.82).abs() < 0.005, "{recorded_peak}");
}

#[test]
fn contacts_recorded_before_the_counterpart_decode_as_discs_on_a_plane() {
    let recorded_peak = decode("default_before_counterpart.mcap", |row| {
        // The default scene's pads are flat-backed (its construction was recorded).
        assert_eq!((row.backing, row.core_thickness), (1, 0.0));
        assert_eq!(row.counterpart, 0);
        assert_eq!(row.counterpart(), Some(softgrip_law::Counterpart::PLANE));
        assert_eq!(row.contact_radius2, row.contact_radius);
        assert!(row.contact_radius > 0.0, "{row:?}");
    });
    // Its run summary says 15.37 N (the default grasp of 2026-12-04).
    assert!((recorded_peak - 15.37).abs() < 0.005, "{recorded_peak}");
}
