//! A skin on a rigid core pressed on a rigid ball, against softgrip's FE of it
//! (`tests/data/fe/ball/core/`, `tools/fe`, session 11: t/R 0.3 and 0.5 at nu 0.48 on balls of
//! R and 3R): force per curve against the number this test prints, with the 3 % as the
//! ceiling, and the law's range against the FE's reach.
//!
//! `cargo test -p softgrip-law --test core_counterpart_fe -- --nocapture` prints every number.

mod common;

use common::{Smooth, force_error};
use softgrip_fe::{CORE_COUNTERPART_FILES, Counterpart as FeCounterpart, FeFile, Schema};
use softgrip_law::{Backing, ContactLaw, ContactParams, Counterpart, Level};

/// The calibrated core law (E* = 1 Pa, R = 1 m) of the file's t/R and Poisson ratio on its ball.
fn law_of(file: &FeFile) -> ContactLaw {
    let nu = file.nu.expect("a Poisson ratio");
    let thickness = file.thickness_ratio.expect("a core file has t/R");
    let FeCounterpart::Ball { k } = file.counterpart else {
        panic!("{}: a core file is on a ball", file.path);
    };
    let p = ContactParams::try_from_parts(1.0, 1.0, nu)
        .and_then(|p| p.with_backing(Backing::Core { thickness }))
        .expect("valid params");
    ContactLaw::try_new(p, Level::Calibrated)
        .and_then(|l| l.with_counterpart(Counterpart::try_ball(k).expect("a ball")))
        .expect("the law binds")
}

/// The force files.
fn curves() -> impl Iterator<Item = &'static FeFile> {
    CORE_COUNTERPART_FILES
        .iter()
        .filter(|f| f.schema == Schema::Force)
}

/// The largest force error each curve is allowed to the FE's end: what this test printed
/// when the law was fixed (session 12), rounded up by 0.2 % (so a real change of the law
/// breaks it). No constant of the law was fitted on these curves (`core_map`: the plane law at
/// Hertz's patch, the bonded pad's squeeze excess at the skin's `delta/t`).
/// `force_nu0.48_t0.4_k2.csv` was run after session 11's map and before this one was
/// written (3.20 % with session 11's, 1.44 % with this one).
fn stated_force_error(path: &str) -> f64 {
    let pct = match path {
        // Session 14 (law-curved): the bonded pad's refit (`mapping`'s FLAT, COLLAPSE_FLAT and
        // the re-stiffening RESTIFFEN_FLAT, which the core's map takes) moved every curve;
        // session 12's numbers in the comments.
        "ball/core/force_nu0.48_t0.3_k1.csv" => 2.35, // 2.42
        "ball/core/force_nu0.48_t0.3_k3.csv" => 2.53, // 3.74
        "ball/core/force_nu0.48_t0.4_k2.csv" => 1.49, // 1.44
        "ball/core/force_nu0.48_t0.5_k1.csv" => 4.70, // 3.26
        "ball/core/force_nu0.48_t0.5_k3.csv" => 1.18, // 2.73
        // Session 13, held out: the first core on a ball away from nu = 0.48 (nu 0.4, t/R
        // 0.35, R2/R 1.5, none of which any other run has).
        "ball/core/force_nu0.4_t0.35_k1.5.csv" => 2.77, // 3.35
        // Session 13, held out: a compressible skin (nu 0.33, t/R 0.45 on 3R), 10.4 % too soft
        // at the FE's end (x = 0.36, delta/t 0.8, smallest element volume ratio 0.25).
        "ball/core/force_nu0.33_t0.45_k3.csv" => 9.73, // 10.38
        // and a third (nu 0.36, t/R 0.3 on R): 6.57 % too soft at its end (x = 0.23, delta/t 0.77)
        "ball/core/force_nu0.36_t0.3_k1.csv" => 4.54, // 6.57
        // A curve that landed after: the target.
        _ => 2.8,
    };
    (pct + 0.2) / 100.0
}

/// The curves the law misses the 3 % on, each within it below an x (its error there,
/// the test allows 0.2 % more), each at the FE's last points: t/R 0.3 on 3R, +3.7 % at its end
/// (x = 0.2, delta/t 0.67; the plane law at the patch's x = 0.15 is itself 1-2 % stiff
/// there, t/R 0.3 at nu 0.4 and 0.49); t/R 0.5 on R, -3.3 % at its end (x = 0.38, delta/t 0.76;
/// the plane law at the patch's x = 0.19 is itself 2 % soft, t/R 0.5 at nu 0.45). Session 13's
/// held-out nu 0.4, t/R 0.35 on 1.5R: within 1.62 % to x = 0.25, -3.35 % at its last two
/// points (x = 0.26-0.27, delta/t 0.74-0.77), where the FE's force over the plane law at the
/// patch rises to 1.25 at delta/t 0.71 (nu 0.48: 1.10-1.15 at 0.70-0.74): the squeeze excess grows faster
/// for a more compressible skin than the bonded pad's map gives. The second, nu 0.33 t/R 0.45
/// on 3R: within 1.99 % to x = 0.31 (delta/t 0.69), then -3.0, -4.3, -6.0, -8.0, -10.4 % at
/// x = 0.32-0.36 (delta/t 0.71-0.8, the FE's smallest element keeping 25-34 % of its volume).
/// The third, nu 0.36 t/R 0.3 on R: within 2.51 % to x = 0.2 (delta/t 0.67), then -3.5, -4.7,
/// -6.6 % at x = 0.21-0.23 (delta/t 0.7-0.77).
///
/// Session 14 (law-curved, the bonded pad's refit, which the core's map takes): t/R 0.3 on 3R
/// and nu 0.4 t/R 0.35 on 1.5R are now within 3 % (2.53, 2.77 %); t/R 0.5 on R is further off
/// at its end (4.70 %, was 3.26 %; within 2.98 % to x = 0.33, was 2.50 % to 0.36): the refit's
/// r0 at nu -> 1/2 rose (0.832 -> 0.861) with the nu = 0.499 pads on 2R and 4R in the fit; the
/// nu 0.33 and 0.36 skins are within 1.11 % to x = 0.31 and 1.85 % to 0.2 (were 1.99, 2.51 %).
const WITHIN_TARGET_TO: &[(&str, f64, f64)] = &[
    ("ball/core/force_nu0.48_t0.5_k1.csv", 0.33, 2.98),
    ("ball/core/force_nu0.33_t0.45_k3.csv", 0.31, 1.11),
    ("ball/core/force_nu0.36_t0.3_k1.csv", 0.2, 1.85),
];

#[test]
fn a_skin_on_a_core_on_a_ball_is_within_its_stated_error_of_the_fe() {
    let mut seen = 0;
    for file in curves() {
        let law = law_of(file);
        let (err, top) = force_error(file, &law, f64::INFINITY);
        let fe_end = file.points().expect("parses").last().expect("points").x;
        println!(
            "{:38} force within {:5.2} % for 0.01 <= x <= {top:.2} (law's x_max {:.3}, FE's end {fe_end})",
            file.path,
            100.0 * err,
            law.x_max()
        );
        let miss = WITHIN_TARGET_TO.iter().find(|(p, _, _)| *p == file.path);
        assert!(
            err <= stated_force_error(file.path) && (err < 0.03 || miss.is_some()),
            "{}: {:.2} %",
            file.path,
            100.0 * err
        );
        if let Some(&(_, to, pct)) = miss {
            let (below, _) = force_error(file, &law, to);
            println!(
                "{:38} force within {:5.2} % for x <= {to}",
                "",
                100.0 * below
            );
            assert!(
                below <= (pct + 0.2) / 100.0 && below < 0.03,
                "{}: {:.2} % to x = {to}",
                file.path,
                100.0 * below
            );
        }
        // The law's range reaches the FE's (within one FE step).
        assert!(
            law.x_max() >= fe_end - 0.011,
            "{}: the law ends at x = {} of the FE's {fe_end}",
            file.path,
            law.x_max()
        );
        seen += 1;
    }
    assert!(seen >= 5, "{seen} curves");
}

/// The contact radius on the ball against the FE's (its column smoothed plus the lag of half an
/// element, R/40: as `counterpart_fe.rs` and the plane's `radius_pressure.rs`), for
/// `0.1 <= x <= min(0.4, x_max, FE's end)`.
#[test]
fn a_skin_on_a_core_on_a_ball_has_the_fe_contact_radius() {
    let mut seen = 0;
    for file in curves() {
        let law = law_of(file);
        let points = file.points().expect("parses");
        let end = points.last().expect("points").x;
        let fe = Smooth::fit(
            &points
                .iter()
                .map(|p| (p.x, 0.0, p.radius_norm))
                .collect::<Vec<_>>(),
        );
        let lag = 0.485 / 40.0;
        let mut worst: f64 = 0.0;
        for i in 0..=30 {
            let x = 0.1 + 0.01 * f64::from(i);
            if x > law.x_max().min(end) + 1e-9 {
                break;
            }
            let p = law.patch(x);
            assert_eq!(p.radius, p.radius2, "a ball's patch is a disc");
            worst = worst.max((p.radius / (fe.at(x) + lag) - 1.0).abs());
        }
        println!("{:38} radius within {:5.2} %", file.path, 100.0 * worst);
        let tolerance = match file.path {
            // session 13's held-out compressible skin (nu 0.33, t/R 0.45 on 3R): 3.00 %
            "ball/core/force_nu0.33_t0.45_k3.csv" => 0.0305,
            // and nu 0.36 t/R 0.3 on R: 3.51 % (the law's radius wider at x = 0.1-0.16)
            "ball/core/force_nu0.36_t0.3_k1.csv" => 0.0356,
            _ => RADIUS_TOLERANCE,
        };
        assert!(worst < tolerance, "{}: {:.2} %", file.path, 100.0 * worst);
        seen += 1;
    }
    assert!(seen >= 5, "{seen} curves");
}

/// The radius's largest error seen on these curves (1.32-2.14 %, session 11), rounded up by
/// 0.3 % (the plane's core radius is within 2.23 % of its FE; the target: 5 %).
const RADIUS_TOLERANCE: f64 = 0.0245;
