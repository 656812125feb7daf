//! The law on curved counterparts against the FE of curved counterparts
//! (`tests/data/fe/{ball,cylinder}/`, softgrip's `tools/fe`, copied from the fe-curved branch):
//! force and contact semi-axes per FE curve, each against the number
//! `tools/calibration/fit_counterpart.py` prints (COUNTERPART.md), with the targets (3 %
//! force on balls and cylinders, 5 % semi-axes) as the ceiling.
//!
//! `cargo test -p softgrip-law --test counterpart_fe -- --nocapture` prints every number.

mod common;

use common::Smooth;
use softgrip_fe::{COUNTERPART_FILES, Counterpart as FeCounterpart, FeFile};
use softgrip_law::{Backing, ContactLaw, ContactParams, Counterpart, Level};

/// The calibrated law (E* = 1 Pa, R = 1 m) of the file's construction and Poisson ratio, on its
/// counterpart (curvature 1/K for K = R2/R).
fn law_of(file: &FeFile) -> ContactLaw {
    let nu = file.nu.expect("a Poisson ratio");
    let backing = match file.geometry {
        "flat" => Backing::Flat,
        _ => Backing::Free,
    };
    let p = ContactParams::try_from_parts(1.0, 1.0, nu)
        .and_then(|p| p.with_backing(backing))
        .expect("valid params");
    let cp = match file.counterpart {
        FeCounterpart::Ball { k } => Counterpart::try_ball(k),
        FeCounterpart::Cylinder { k } => Counterpart::try_cylinder(k),
        FeCounterpart::Edge => Ok(Counterpart::EDGE),
        FeCounterpart::Plane => Ok(Counterpart::PLANE),
    }
    .expect("valid counterpart");
    ContactLaw::try_new(p, Level::Calibrated)
        .and_then(|l| l.with_counterpart(cp))
        .expect("the law binds")
}

/// The force files of the balls and cylinders.
fn curves() -> impl Iterator<Item = &'static FeFile> {
    COUNTERPART_FILES.iter().filter(|f| {
        matches!(
            f.counterpart,
            FeCounterpart::Ball { .. } | FeCounterpart::Cylinder { .. }
        ) && f.path.contains("/force_")
    })
}

/// Largest |F_law / F_FE - 1| over `0.01 <= x <= x_max` and the x range compared.
fn force_error(file: &FeFile, law: &ContactLaw) -> (f64, f64) {
    common::force_error(file, law, f64::INFINITY)
}

/// The largest force error each curve is allowed: what `fit_counterpart.py` prints for the law
/// (`r+g+q+q2+g3, eps, cap`, session 16; the free sphere's constants are session 12's), rounded up by 0.2 % (the law's own rounding of the constants and the Rust tables
/// of the backed constructions: 2.7e-8), so a real change of the law breaks it. Held out of
/// every fit: the campaign's held-out runs (`ball/*/force_nu0.4_k0.7.csv`,
/// `ball/*/force_nu0.4_k6.csv`, `ball/flat/force_nu0.45_k1.5.csv`,
/// `ball/free/force_nu0.35_k3.csv`), the cylinders, and every curve that landed after the
/// constants were fixed (blind: `ball/free/force_nu0.499_k2.csv`, and the campaign's end of
/// session 10, R2/R = 4 and 10 at nu 0.3, 0.48 (10), 0.499 and R/2 at nu 0.499), and session
/// 11's runs at nu and R2/R no other run has (`ball/free/force_nu0.42_k1.5.csv`,
/// `ball/flat/force_nu0.35_k0.7.csv`: each stopped at the FE's wall-clock limit, x = 0.56 and
/// 0.63). Session 14 fitted the bonded pad at nu = 0.499 on 2R and 4R (without the range
/// penalty) and session 13's `fit13mid`; session 13's, 14's, 15's and 16's blind runs stay out.
/// Session 16 refitted the bonded pad's `g`, `q`, `q2` with the sextic `g3` (`r` held): every
/// flat curve moved; worse than session 14's law on five, all within 1.80 % (flat nu 0.3 on R
/// 1.53 -> 1.66, 0.7 R 0.66 -> 1.60, nu 0.499 on R 1.27 -> 1.50, nu 0.48 on 10 R 0.88 -> 0.89,
/// the flat cylinder at nu 0.3 on 3R 1.78 -> 1.80 %). `ball/free/force_nu0.48_k4.csv` was
/// stated 1.69 (the Python's number); this test printed 1.37 with session 14's law too (the free
/// sphere's map is unchanged).
fn stated_force_error(path: &str) -> f64 {
    let pct = match path {
        "ball/free/force_nu0.3_k0.5.csv" => 1.29,
        "ball/free/force_nu0.3_k1.csv" => 0.77,
        "ball/free/force_nu0.3_k2.csv" => 1.11,
        "ball/free/force_nu0.3_k4.csv" => 2.97,
        "ball/free/force_nu0.3_k10.csv" => 1.47,
        "ball/free/force_nu0.35_k3.csv" => 1.06,
        "ball/free/force_nu0.48_k0.5.csv" => 1.20,
        "ball/free/force_nu0.48_k1.csv" => 1.53,
        "ball/free/force_nu0.48_k2.csv" => 0.86,
        "ball/free/force_nu0.48_k4.csv" => 1.37,
        "ball/free/force_nu0.48_k10.csv" => 2.42,
        "ball/free/force_nu0.499_k0.5.csv" => 1.61,
        "ball/free/force_nu0.499_k1.csv" => 1.67,
        "ball/free/force_nu0.499_k2.csv" => 1.42,
        "ball/free/force_nu0.499_k4.csv" => 1.94,
        "ball/free/force_nu0.499_k10.csv" => 0.90,
        "ball/free/force_nu0.4_k0.7.csv" => 2.40,
        "ball/free/force_nu0.4_k6.csv" => 1.41,
        // Session 11's held-out runs (blind: run after the constants were fixed).
        "ball/free/force_nu0.42_k1.5.csv" => 1.69,
        "ball/flat/force_nu0.35_k0.7.csv" => 1.60,
        "ball/flat/force_nu0.3_k0.5.csv" => 1.81,
        "ball/flat/force_nu0.3_k1.csv" => 1.66,
        "ball/flat/force_nu0.3_k2.csv" => 2.09,
        "ball/flat/force_nu0.3_k4.csv" => 2.11,
        "ball/flat/force_nu0.3_k10.csv" => 1.14,
        "ball/flat/force_nu0.45_k1.5.csv" => 2.12,
        "ball/flat/force_nu0.48_k0.5.csv" => 1.88,
        "ball/flat/force_nu0.48_k1.csv" => 1.26,
        "ball/flat/force_nu0.48_k2.csv" => 1.77,
        "ball/flat/force_nu0.48_k4.csv" => 1.35,
        "ball/flat/force_nu0.48_k10.csv" => 0.89,
        "ball/flat/force_nu0.499_k1.csv" => 1.50,
        "ball/flat/force_nu0.499_k2.csv" => 1.67,
        "ball/flat/force_nu0.499_k4.csv" => 1.36,
        "ball/flat/force_nu0.499_k10.csv" => 1.02,
        "ball/flat/force_nu0.4_k0.7.csv" => 2.17,
        "ball/flat/force_nu0.4_k6.csv" => 0.91,
        "cylinder/flat/force_nu0.48_k1.csv" => 1.11,
        "cylinder/flat/force_nu0.48_k3.csv" => 0.97,
        // Session 12, blind (run after the constants were fixed): the free cylinders of R and
        // 3R and the flat pad on 3R at nu = 0.3, the first away from nu = 0.48 (session 11's
        // law: 1.91, 1.09 and 1.58 %).
        "cylinder/free/force_nu0.3_k1.csv" => 1.91,
        "cylinder/free/force_nu0.3_k3.csv" => 1.13,
        "cylinder/flat/force_nu0.3_k3.csv" => 1.80,
        "cylinder/free/force_nu0.48_k1.csv" => 1.48,
        "cylinder/free/force_nu0.48_k3.csv" => 0.72,
        // Session 13, blind (run after the constants were fixed, session 12, and never
        // fitted, session 14's refit included): the bonded pad at nu 0.3-0.37 on balls no
        // other run has (session 12's law: 1.72, 4.14, 2.28, 1.36, 3.32, 2.67 %).
        "ball/flat/force_nu0.3_k0.7.csv" => 1.60,
        "ball/flat/force_nu0.33_k1.4.csv" => 0.98,
        "ball/flat/force_nu0.3_k3.csv" => 2.21,
        "ball/free/force_nu0.3_k0.7.csv" => 1.36,
        "ball/flat/force_nu0.37_k1.csv" => 1.82,
        "ball/flat/force_nu0.3_k1.4.csv" => 1.83,
        // Session 13's fit data (`fe_campaign.py`'s `fit13mid`: the bonded pad on R, 1.5 R and
        // 2 R at nu 0.35-0.45), fitted in session 14 (session 12's law: 4.00, 2.70, 3.11,
        // 2.26, 1.87, 2.09, 1.58, 1.58 %).
        "ball/flat/force_nu0.35_k1.csv" => 1.64,
        "ball/flat/force_nu0.4_k1.csv" => 2.14,
        "ball/flat/force_nu0.35_k1.5.csv" => 1.08,
        "ball/flat/force_nu0.4_k1.5.csv" => 1.91,
        "ball/flat/force_nu0.45_k1.csv" => 1.83,
        "ball/flat/force_nu0.35_k2.csv" => 0.74,
        "ball/flat/force_nu0.4_k2.csv" => 1.44,
        "ball/flat/force_nu0.45_k2.csv" => 1.94,
        // Session 14, blind (`fe_campaign.py`'s `held14`, run before the refit and never
        // fitted; session 12's law: 1.98 and 2.03 %).
        "ball/flat/force_nu0.42_k0.8.csv" => 2.02,
        "ball/flat/force_nu0.32_k2.5.csv" => 1.89,
        // Session 15, blind (`fe_campaign.py`'s `held15`, the small-ball end between the fitted
        // R/2 and the held-out 0.7 R; no constant saw them): the flat pad at nu 0.4 on 0.6 R
        // (session 14's law: -3.10 % at x = 0.41, the 3 % missed; session 16's sextic
        // term, fitted without it: 2.33 %), the free sphere 2.26 %.
        "ball/flat/force_nu0.4_k0.6.csv" => 2.33,
        "ball/free/force_nu0.4_k0.6.csv" => 2.26,
        // Session 16, blind (`fe_campaign.py`'s `held16`, run before the refit and never
        // fitted): the flat pad on balls below 0.7 R at nu 0.36 and 0.45 (session 14's law:
        // 3.25 % at x = 0.41 and 2.07 %).
        "ball/flat/force_nu0.36_k0.55.csv" => 2.52,
        "ball/flat/force_nu0.45_k0.65.csv" => 1.14,
        // ... and, run after session 16's constants were fixed, R/2 at nu 0.4, between the two
        // fitted R/2 curves (session 14's law: 3.69 % at x = 0.38): -2.85 % at x = 0.47.
        "ball/flat/force_nu0.4_k0.5.csv" => 2.85,
        // A curve not in COUNTERPART.md yet: the target.
        _ => 2.8,
    };
    (pct + 0.2) / 100.0
}

/// The curves whose FE runs past the law's range: the flat pad at nu = 0.3 on the balls of 0.7 R
/// (session 13: the FE to x = 0.70, the law to the bonded reach constant 0.66), at nu = 0.33 on
/// 1.4 R (session 13: 0.66 of 0.69), at nu = 0.35 on R (session 13's fit data: 0.66 of 0.68), R/2
/// (0.66, the bonded reach constant, of 0.68) and R (0.654, where the plane law ends at rho x,
/// of 0.68), on the ball of 0.7 R at nu = 0.4 (0.66 of 0.69), at nu = 0.42 on 0.8 R (session 14's
/// blind run: 0.66 of 0.68), and at nu = 0.499 on 2R, 4R and
/// 10R (the plane law of the bonded pad ends at x = 0.44 at nu >= 0.48, at rho x: 0.62 of
/// the FE's 0.65, 0.53 of 0.57, 0.48 of 0.53; the nearly incompressible pad on a large ball
/// folds over its bonded edge later than on the plane, where the plane law was fitted).
const RANGE_SHORT: &[&str] = &[
    "ball/flat/force_nu0.3_k0.7.csv",
    "ball/flat/force_nu0.33_k1.4.csv",
    "ball/flat/force_nu0.35_k1.csv",
    "ball/flat/force_nu0.3_k0.5.csv",
    "ball/flat/force_nu0.3_k1.csv",
    "ball/flat/force_nu0.4_k0.7.csv",
    "ball/flat/force_nu0.42_k0.8.csv",
    "ball/flat/force_nu0.499_k2.csv",
    "ball/flat/force_nu0.499_k4.csv",
    "ball/flat/force_nu0.499_k10.csv",
];

/// The curves the law misses the 3 % on (COUNTERPART.md): none since session 16.
///
/// Session 15 left one: its blind flat pad at nu 0.4 on 0.6 R, 3.10 % too soft at x = 0.41
/// (the small-ball end of the map's `g`, fitted on the R/2 curves at nu 0.3 and 0.48 only;
/// session 16's blind 0.55 R at nu 0.36 was 3.25 % with that law). Session 16's sextic term
/// (`mapping`, the sphere's next order beyond its paraboloid, `g3 mu2 x^(7/2)`) brought them
/// to 2.33 and 2.52 %. Session 13 left five, all the bonded pad at nu 0.3-0.37 going soft past
/// x ≈ 0.55: on R at nu 0.3 (3.46 %), 0.35 (4.00 %) and 0.37 (3.32 %, blind), on 1.4 R at nu
/// 0.33 (4.14 %, blind), on 1.5 R at nu 0.35 (3.11 %). Session 14's re-stiffening term
/// (`mapping`, the collapsed column under a narrower patch, `q2 eps (1 - rho_H) rho_H
/// x^(11/2)`) brought them to 1.53, 2.32, 2.40, 1.63 and 1.51 % (session 16: 1.66, 1.64,
/// 1.82, 0.98, 1.08 %).
const KNOWN_MISSES: &[&str] = &[];

/// Where the curves past 3 % (or near it) are within the 3 % below the FE's collapse:
/// `(file, to x, its error there %)`; the test allows 0.2 % more.
const WITHIN_TARGET_TO: &[(&str, f64, f64)] = &[
    ("ball/free/force_nu0.3_k4.csv", 0.65, 1.43),
    ("ball/flat/force_nu0.3_k1.csv", 0.64, 1.66),
    ("ball/flat/force_nu0.33_k1.4.csv", 0.63, 0.98),
    ("ball/flat/force_nu0.37_k1.csv", 0.62, 1.80),
    ("ball/flat/force_nu0.35_k1.csv", 0.62, 1.33),
    ("ball/flat/force_nu0.35_k1.5.csv", 0.62, 0.95),
];

#[test]
fn force_on_balls_and_cylinders_is_within_its_stated_error_of_the_fe() {
    let mut seen = 0;
    for file in curves() {
        let law = law_of(file);
        let (err, top) = force_error(file, &law);
        println!(
            "{:38} force within {:5.2} % for 0.01 <= x <= {top:.2} (law's x_max {:.3})",
            file.path,
            100.0 * err,
            law.x_max()
        );
        assert!(
            err <= stated_force_error(file.path)
                && (err < 0.03 || KNOWN_MISSES.contains(&file.path)),
            "{}: {:.2} %",
            file.path,
            100.0 * err
        );
        // The law's range reaches the FE's (within one FE step, 0.02 at the end of a 3D run),
        // except where it is stated short.
        let fe_end = file.points().expect("parses").last().expect("points").x;
        assert!(
            law.x_max() >= fe_end - 0.021 || RANGE_SHORT.contains(&file.path),
            "{}: the law ends at x = {} of the FE's {fe_end}",
            file.path,
            law.x_max()
        );
        assert!(top > 0.0, "{}: nothing compared", file.path);
        if let Some(&(_, to, pct)) = WITHIN_TARGET_TO.iter().find(|(p, _, _)| *p == file.path) {
            let (below, _) = common::force_error(file, &law, to);
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
        seen += 1;
    }
    assert!(seen >= 50, "{seen} curves");
}

/// The FE's trustworthy radius, as the plane's (`radius_pressure.rs`): the column smoothed plus
/// the lag of half an element (axisymmetric CAX8R on R/40); the 3D files' `_32` columns (from
/// the gap's Hertzian edge shape) have no lag.
fn fe_semi_axes(file: &FeFile) -> (Smooth, Option<Smooth>, f64) {
    let points = file.points().expect("parses");
    let across: Vec<(f64, f64, f64)> = points.iter().map(|p| (p.x, 0.0, p.radius_norm)).collect();
    let along: Option<Vec<(f64, f64, f64)>> = points
        .iter()
        .map(|p| p.radius_along_norm.map(|a| (p.x, 0.0, a)))
        .collect();
    let lag = if matches!(file.counterpart, FeCounterpart::Ball { .. }) {
        0.485 / 40.0
    } else {
        0.0
    };
    (Smooth::fit(&across), along.map(|a| Smooth::fit(&a)), lag)
}

/// A ball's contact radius within 5 % of the FE's for 0.1 <= x <= 0.4 (`fit_counterpart.py`:
/// 0.9-4.6 %, the flat pad on R/2 at nu = 0.48 the worst; the ball of R/2 at nu = 0.3 was
/// 8.85 % free and 9.00 % flat before Sneddon's shrink of the patch, `mapping`'s `gamma`).
#[test]
fn contact_radius_on_a_ball_is_within_five_percent_of_the_fe() {
    for file in curves().filter(|f| matches!(f.counterpart, FeCounterpart::Ball { .. })) {
        let end = file.points().expect("parses").last().expect("points").x;
        if end < 0.4 {
            // The bonded pad at nu = 0.499 on a ball of R diverged at x = 0.05: no radius to
            // compare at x >= 0.1 (the FE's radius is resolved to a node below it).
            println!("{:38} radius: the FE ends at x = {end}", file.path);
            continue;
        }
        let law = law_of(file);
        let (fe, _, lag) = fe_semi_axes(file);
        let mut worst: f64 = 0.0;
        for i in 0..=30 {
            let x = 0.1 + 0.01 * f64::from(i);
            if x > law.x_max() {
                break;
            }
            let p = law.patch(x);
            assert_eq!(p.radius, p.radius2, "a ball's patch is a disc");
            worst = worst.max((p.radius / (fe.at(x) + lag) - 1.0).abs());
        }
        println!("{:38} radius within {:5.2} %", file.path, 100.0 * worst);
        assert!(worst < 0.05, "{}: {:.2} %", file.path, 100.0 * worst);
    }
}

/// A right-angle edge within its stated error of the FE (`fit_counterpart.py`, one `(s, rho)`
/// per construction, each fitted on its one curve: flat 4.25 %, free 3.31 %; the target
/// 10 %; the free sphere with the bonded pad's constants was 11.87 %). The plane law there,
/// what an edge was before, is 2.2-3.2x the FE.
#[test]
fn force_on_an_edge_is_within_its_stated_error_of_the_fe() {
    let mut seen = 0;
    for file in COUNTERPART_FILES
        .iter()
        .filter(|f| matches!(f.counterpart, FeCounterpart::Edge) && f.path.contains("/force_"))
    {
        let law = law_of(file);
        let (err, top) = force_error(file, &law);
        let plane = ContactLaw::try_new(*law.params(), Level::Calibrated).expect("binds");
        let (plane_err, _) = force_error(file, &plane);
        println!(
            "{:38} force within {:5.2} % for 0.01 <= x <= {top:.2} (as a plane: {:.0} %)",
            file.path,
            100.0 * err,
            100.0 * plane_err
        );
        let stated = match file.path {
            "edge/flat/force_nu0.48.csv" => 4.25,
            "edge/free/force_nu0.48.csv" => 3.31,
            // Session 20, blind (run after session 19 took the edge form at nu 0.48, never in a
            // fit): F/E* there is 0.99-1.026x the nu 0.48 run's at every x to 0.15, as the
            // strip argument says.
            "edge/flat/force_nu0.3.csv" => 4.03,
            _ => 9.8, // an edge not in COUNTERPART.md yet: the target
        };
        assert!(
            err <= (stated + 0.2) / 100.0,
            "{}: {:.2} %",
            file.path,
            100.0 * err
        );
        assert!(plane_err > 1.0, "{}: as a plane {plane_err}", file.path);
        let fe_end = file.points().expect("parses").last().expect("points").x;
        assert!(law.x_max() >= fe_end, "{}", file.path);
        seen += 1;
    }
    assert!(seen >= 2, "{seen} edge curves");
}

/// The FE the bonded pad at nu = 0.3 on R misses is converged where it misses (session 13,
/// `fe_campaign.py` role `conv-reach`: R/60 against the campaign's R/40 to x = 0.68, where the
/// smallest element keeps 21 % of its volume): the two meshes' forces agree within 0.233 % at
/// every x (0.015 % at x = 0.66), so the 3.46 % there is the law's, not the mesh's.
#[test]
fn the_missed_bonded_curve_is_mesh_converged_to_its_end() {
    let rows = common::ball_mesh_convergence("flat", 0.3, 1.0);
    let (worst, end) = common::mesh_convergence_summary(&rows);
    println!("flat nu 0.3 on R: R/40 vs R/60 within {worst:.3} % to x = {end}");
    assert!(rows.len() >= 60, "{} rows", rows.len());
    assert!(end >= 0.68 - 1e-9, "to x = {end}");
    assert!(worst <= 0.25, "{worst} %");
}
