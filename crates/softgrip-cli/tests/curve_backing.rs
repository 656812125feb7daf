//! `softgrip curve --backing free|flat|core [--thickness T]` and `--profile X` (issue 10 item
//! 6), run as a user runs them. Every number is compared with `ContactLaw` itself (the backed
//! constants are being fitted: no law number is written here).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use common::{curve_csv as csv, softgrip_curve as softgrip};
use softgrip_law::{Backing, ContactLaw, ContactParams, Level};

/// The law the command should print: E* = 1 Pa, R = 1 m (so t = T m), `nu`, `backing`.
fn law(level: Level, nu: f64, backing: Backing) -> ContactLaw {
    let p = ContactParams::try_from_parts(1.0, 1.0, nu)
        .unwrap()
        .with_backing(backing)
        .unwrap();
    ContactLaw::try_new(p, level).unwrap()
}

fn fails_with(args: &[&str], message: &str) {
    let out = softgrip(args);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{args:?} succeeded");
    assert!(err.contains(message), "{args:?}: {err}");
}

#[test]
fn backed_curves_are_the_constructions_law_with_valid_past_its_range() {
    let cases = [
        (vec!["--backing", "flat"], Backing::Flat),
        (
            vec!["--backing", "core", "--thickness", "0.4"],
            Backing::Core { thickness: 0.4 },
        ),
        (vec![], Backing::Free),
    ];
    let free = law(Level::Calibrated, 0.49, Backing::Free);
    for (extra, backing) in cases {
        let mut args = vec![
            "--level",
            "calibrated",
            "--nu",
            "0.49",
            "--x",
            "0.01:1.0:0.01",
        ];
        args.extend_from_slice(&extra);
        let (header, rows) = csv(&args);
        assert_eq!(
            header,
            "x,force_norm,stiffness_norm,energy_norm,radius_norm,p_mean_norm,valid"
        );
        assert_eq!(rows.len(), 100);
        let want = law(Level::Calibrated, 0.49, backing);
        let mut past = 0;
        for row in &rows {
            let x = row[0];
            let r = want.response(x);
            // Printed with the shortest representation that parses back: exact.
            assert_eq!(row[1], r.force, "{backing} force at x = {x}");
            assert_eq!(row[2], r.stiffness, "{backing} stiffness at x = {x}");
            assert_eq!(row[3], want.energy(x), "{backing} energy at x = {x}");
            assert_eq!(row[4], want.patch(x).radius, "{backing} radius at x = {x}");
            assert_eq!(row[6], f64::from(u8::from(x <= want.x_max())), "x = {x}");
            past += usize::from(row[6] == 0.0);
        }
        assert!(past > 0, "{backing}: a row past x_max = {}", want.x_max());
        if !backing.is_free() {
            // The backed construction is not the free sphere's law.
            let x = 0.2;
            assert_ne!(want.response(x).force, free.response(x).force, "{backing}");
        }
    }
}

#[test]
fn published_levels_with_a_backing_are_the_free_spheres() {
    let (_, flat) = csv(&[
        "--level",
        "hertz",
        "--nu",
        "0.3",
        "--backing",
        "flat",
        "--x",
        "0.1:0.3:0.1",
    ]);
    let (_, free) = csv(&["--level", "hertz", "--nu", "0.3", "--x", "0.1:0.3:0.1"]);
    assert_eq!(flat.len(), 3);
    assert_eq!(flat, free);
}

#[test]
fn profile_prints_50_rows_of_the_levels_pressure_from_the_centre_to_the_edge() {
    for (extra, backing) in [
        (vec!["--backing", "flat"], Backing::Flat),
        (
            vec!["--backing", "core", "--thickness", "0.6"],
            Backing::Core { thickness: 0.6 },
        ),
        (vec![], Backing::Free),
    ] {
        let x = 0.2;
        let mut args = vec!["--level", "calibrated", "--nu", "0.45", "--profile", "0.2"];
        args.extend_from_slice(&extra);
        let (header, rows) = csv(&args);
        assert_eq!(header, "r_norm,p_norm");
        assert_eq!(rows.len(), 50);
        let patch = law(Level::Calibrated, 0.45, backing).patch(x);
        assert_eq!(rows[0], vec![0.0, patch.peak_pressure]);
        assert_eq!(rows[49][0], patch.radius);
        assert_eq!(rows[49][1], 0.0);
        for row in &rows {
            assert!(row.len() == 2 && row[0] >= 0.0 && row[0] <= patch.radius);
            assert_eq!(
                row[1],
                patch.pressure_at(row[0]),
                "{backing} at r = {}",
                row[0]
            );
        }
        // The profile carries the force: 2 pi int p r dr (trapezoids over the 50 rows; the
        // edge's steep fall costs ~1 %) against F / (E* R^2).
        let f: f64 = rows
            .windows(2)
            .map(|w| {
                std::f64::consts::PI * (w[1][0] - w[0][0]) * (w[1][1] * w[1][0] + w[0][1] * w[0][0])
            })
            .sum();
        let force = law(Level::Calibrated, 0.45, backing).response(x).force;
        assert!((f / force - 1.0).abs() < 0.03, "{backing}: {f} vs {force}");
    }
}

#[test]
fn bad_combinations_are_refused_with_a_clear_message() {
    let base = ["--level", "calibrated", "--nu", "0.49"];
    let with = |extra: &[&'static str]| -> Vec<&'static str> {
        let mut a = base.to_vec();
        a.extend_from_slice(extra);
        a
    };
    fails_with(
        &with(&[
            "--backing",
            "flat",
            "--thickness",
            "0.4",
            "--x",
            "0.1:0.2:0.1",
        ]),
        "`--thickness` applies only to `--backing core`",
    );
    fails_with(
        &with(&["--thickness", "0.4", "--x", "0.1:0.2:0.1"]),
        "`--thickness` applies only to `--backing core`",
    );
    fails_with(
        &with(&["--backing", "core", "--x", "0.1:0.2:0.1"]),
        "`--backing core` needs `--thickness",
    );
    for t in ["0", "1", "1.5", "-0.2", "nan"] {
        fails_with(
            &with(&["--backing", "core", "--thickness", t, "--x", "0.1:0.2:0.1"]),
            "must be in (0, 1)",
        );
    }
    fails_with(
        &with(&["--backing", "glued", "--x", "0.1:0.2:0.1"]),
        "invalid value 'glued' for '--backing <NAME>'",
    );
    for x in ["0", "-0.1", "nan"] {
        fails_with(
            &with(&["--backing", "flat", "--profile", x]),
            "`--profile` must be in (0, ",
        );
    }
    let past = law(Level::Calibrated, 0.49, Backing::Flat).x_max() * 1.01;
    let past = format!("{past}");
    let mut args = with(&["--backing", "flat", "--profile"]);
    args.push(&past);
    fails_with(&args, "`--profile` must be in (0, ");
    // A core's range names the construction as given: t/R, not the law's t in metres (R = 1 m).
    fails_with(
        &with(&[
            "--backing",
            "core",
            "--thickness",
            "0.3",
            "--profile",
            "0.5",
        ]),
        "validity range for backing core (t/R = 0.3)), got 0.5",
    );
    // --profile is one x: a grid does not make sense with it.
    fails_with(
        &with(&["--profile", "0.1", "--x", "0.1:0.2:0.1"]),
        "cannot be used with",
    );
    fails_with(&base, "--x");
}
