//! `softgrip curve --counterpart plane|ball:K|cylinder:K|edge` (issue 24 item 7), run as a user
//! runs it: every number against `ContactLaw::with_counterpart` itself; a plane (the default)
//! prints exactly what it printed before; the patch's second semi-axis is a column off a plane.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use common::{curve_csv as csv, softgrip_curve as softgrip};
use softgrip_law::{Backing, ContactLaw, ContactParams, Counterpart, Level};

/// The law the command should print: E* = 1 Pa, R = 1 m, so a counterpart of K = R2/R has
/// curvature 1/K.
fn law(nu: f64, backing: Backing, counterpart: Counterpart) -> ContactLaw {
    let p = ContactParams::try_from_parts(1.0, 1.0, nu)
        .unwrap()
        .with_backing(backing)
        .unwrap();
    ContactLaw::try_new(p, Level::Calibrated)
        .unwrap()
        .with_counterpart(counterpart)
        .unwrap()
}

#[test]
fn counterparts_print_the_law_on_them_with_the_second_semi_axis() {
    let cases = [
        ("ball:1", Backing::Free, Counterpart::try_ball(1.0).unwrap()),
        (
            "ball:0.5",
            Backing::Flat,
            Counterpart::try_ball(0.5).unwrap(),
        ),
        (
            "cylinder:3",
            Backing::Free,
            Counterpart::try_cylinder(3.0).unwrap(),
        ),
        ("edge", Backing::Flat, Counterpart::EDGE),
        (
            "ball:2",
            Backing::Core { thickness: 0.4 },
            Counterpart::try_ball(2.0).unwrap(),
        ),
    ];
    for (arg, backing, cp) in cases {
        let mut args = vec![
            "--level",
            "calibrated",
            "--nu",
            "0.45",
            "--x",
            "0.02:0.9:0.02",
        ];
        args.extend(["--counterpart", arg, "--backing", backing.name()]);
        if let Backing::Core { .. } = backing {
            args.extend(["--thickness", "0.4"]);
        }
        let (header, rows) = csv(&args);
        assert_eq!(
            header,
            "x,force_norm,stiffness_norm,energy_norm,radius_norm,p_mean_norm,valid,radius2_norm"
        );
        let want = law(0.45, backing, cp);
        for row in rows {
            let x = row[0];
            let patch = want.patch(x);
            assert_eq!(row[1], want.response(x).force, "{arg} force at {x}");
            assert_eq!(row[2], want.response(x).stiffness, "{arg} stiffness at {x}");
            assert_eq!(row[3], want.energy(x), "{arg} energy at {x}");
            assert_eq!(
                (row[4], row[7]),
                (patch.radius, patch.radius2),
                "{arg} at {x}"
            );
            assert_eq!(
                row[6],
                f64::from(u8::from(x <= want.x_max())),
                "{arg} valid at {x}"
            );
        }
    }
}

#[test]
fn a_plane_prints_what_it_printed_before() {
    let before = csv(&[
        "--level",
        "calibrated",
        "--nu",
        "0.49",
        "--x",
        "0.01:0.8:0.01",
    ]);
    let plane = csv(&[
        "--level",
        "calibrated",
        "--nu",
        "0.49",
        "--x",
        "0.01:0.8:0.01",
        "--counterpart",
        "plane",
    ]);
    assert_eq!(before, plane);
    assert_eq!(
        before.0,
        "x,force_norm,stiffness_norm,energy_norm,radius_norm,p_mean_norm,valid"
    );
}

#[test]
fn the_profile_runs_along_the_first_semi_axis() {
    let out = softgrip(&[
        "--level",
        "calibrated",
        "--nu",
        "0.48",
        "--counterpart",
        "cylinder:1",
        "--profile",
        "0.2",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let last: Vec<f64> = text
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    let patch = law(0.48, Backing::Free, Counterpart::try_cylinder(1.0).unwrap()).patch(0.2);
    assert_eq!(last, vec![patch.radius, 0.0]);
    assert!(patch.radius > patch.radius2);
}

#[test]
fn bad_counterparts_are_errors_naming_the_forms() {
    for (arg, message) in [
        ("ball", "`ball:K`"),
        ("ball:-1", "must be finite and > 0"),
        ("cylinder:nan", "must be finite and > 0"),
        ("cone:1", "plane, ball:K, cylinder:K (K = R2/R > 0) or edge"),
        ("ball:1e-9", "kappa R"),
    ] {
        let out = softgrip(&[
            "--level",
            "calibrated",
            "--nu",
            "0.45",
            "--x",
            "0.1:0.2:0.1",
            "--counterpart",
            arg,
        ]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{arg} succeeded");
        assert!(err.contains(message), "{arg}: {err}");
    }
}
