//! Contact radius and pressure of the calibrated level for every construction (free, flat,
//! core) against softgrip's own finite elements (`tests/data/fe/`, embedded by `softgrip-fe` and
//! `include_str!`), and the force conservation of every patch.
//!
//! The FE radius column (`a_lin`, the last surface node on the plane, interpolated to the next)
//! moves in node steps and is not even monotone in x: 1.0-1.9 % rms about a smooth curve (up
//! to 5 %) on the R/40 meshes; and it lags the contact edge by about half an element face. The
//! radius the law is measured against is that column smoothed per curve (`a/sqrt(x)` least
//! squares in powers of `sqrt(x)`) plus half the element edge, as
//! `tools/calibration/fit_radius_pressure.py` does (it prints every number quoted here;
//! `tools/calibration/REPORT_radius_pressure.md` says why): on flat nu = 0.48 re-run on R/80
//! and R/120 (`tests/data/fe/flat/radius_mesh_*.csv`) it is within 0.71 % of the fine-mesh limit.
//!
//! Pressure: the FE's nodal profiles (`pressure_*.csv`), the two nodes nearest the axis dropped
//! (the tied on-axis face makes them jitter), against the law's `p0 (1 - r^2/a^2)^m` with the
//! law's radius and shape. Measured twice: with the FE's own force (the shape and radius alone,
//! what the pressure form is fitted on) and with the law's force (what a user gets; the force
//! law's error adds to the peak one for one). The numbers in the comments are what the current
//! code gives; the tolerances sit just above them, so a change of form or constant fails.

mod common;

use common::{Smooth, profile};
use softgrip_law::{Backing, ContactLaw, ContactParams, ContactPatch, Level};

/// The calibrated law in normalised units (E* = 1 Pa, R = 1 m) for `backing` (t as t/R).
fn law(nu: f64, backing: Backing) -> ContactLaw {
    let p = ContactParams::try_from_parts(1.0, 1.0, nu)
        .and_then(|p| p.with_backing(backing))
        .expect("valid params");
    ContactLaw::try_new(p, Level::Calibrated).expect("level builds")
}

/// `(x, f, a/R)` of an embedded FE force file.
fn fe(path: &str) -> Vec<(f64, f64, f64)> {
    embedded(path)
        .points()
        .expect("parses")
        .into_iter()
        .map(|p| (p.x, p.force_norm, p.radius_norm))
        .collect()
}

fn embedded(path: &str) -> &'static softgrip_fe::FeFile {
    softgrip_fe::file(path).unwrap_or_else(|| panic!("{path} is embedded"))
}

/// `a_lin` lags the contact edge by half an element face on average: the contact is resolved per
/// quadratic face (on R/80 the last node on the plane is a midside node 25 times in 29, its outer
/// corner touching within the penalty's penetration). The element edge along the curved surface
/// is 0.97 R/N on a mesh named R/N, so the lag is 0.485 R/N (R/40: 0.012 R, 1.7-3.5 % of the
/// radius at x = 0.4-0.1); the fine-mesh checks alone select 0.47 (flat) and 0.65 (core).
const LAG_TIMES_N: f64 = 0.485;

/// `N` of the mesh `R/N` a file's provenance names (the reference copy: R/60).
fn mesh(path: &str) -> f64 {
    embedded(path)
        .provenance()
        .iter()
        .find_map(|l| {
            let i = l.find("element edge R/")? + "element edge R/".len();
            let n: String = l[i..].chars().take_while(char::is_ascii_digit).collect();
            n.parse().ok()
        })
        .unwrap_or(60.0)
}

/// The trustworthy FE radius of one curve: its smooth radius ([`Smooth`]) plus the lag.
fn fe_radius(path: &str) -> impl Fn(f64) -> f64 {
    let sm = Smooth::fit(&fe(path));
    let lag = LAG_TIMES_N / mesh(path);
    move |x| sm.at(x) + lag
}

fn backing(t: Option<f64>) -> Backing {
    t.map_or(Backing::Flat, |thickness| Backing::Core { thickness })
}

#[test]
fn fe_radius_column_is_step_noise_about_a_smooth_curve() {
    // The scatter of a_lin about its smooth fit, x >= 0.05: 0.97-1.83 % rms on every curve
    // of the campaign (one surface node of R/40 is 1.25 % of R).
    let paths = [
        "free/force_nu0.3.csv",
        "free/force_nu0.49.csv",
        "flat/force_nu0.3.csv",
        "flat/force_nu0.48.csv",
        "core/force_nu0.3_t0.4.csv",
        "core/force_nu0.48_t0.8.csv",
    ];
    for path in paths {
        let pts = fe(path);
        let sm = Smooth::fit(&pts);
        let rel: Vec<f64> = pts
            .iter()
            .filter(|p| p.0 >= 0.05 - 1e-9)
            .map(|p| p.2 / sm.at(p.0) - 1.0)
            .collect();
        let mean = rel.iter().sum::<f64>() / rel.len() as f64;
        let rms = (rel.iter().map(|r| (r - mean).powi(2)).sum::<f64>() / rel.len() as f64).sqrt();
        assert!(mean.abs() < 1e-3, "{path}: mean {mean}");
        assert!((0.008..0.019).contains(&rms), "{path}: rms {rms}");
    }
}

/// `(path, nu, t/R (core), held out, tolerance vs the smooth FE radius, tolerance vs a_lin)`.
type RadiusCase = (&'static str, f64, Option<f64>, bool, f64, f64);

#[test]
fn radius_within_3_percent_of_the_smoothed_fe_radius() {
    // Largest |a_law / a_FE - 1| over the FE points with 0.1 <= x <= min(0.4, reach, x_max)
    // against the FE radius estimate (smoothed a_lin plus the lag) and against the raw a_lin.
    // Seen: flat 0.68-1.37 % (held out 1.15, 1.16 %), core 0.75-2.23 % (to x = 0.8 t/R since
    // session 10; t/R 0.2: 2.02 / 1.00 / 2.23 % at nu 0.3 / 0.4 / 0.48, the squeeze past 0.6 t
    // included; held out 0.82-1.40 %, the second held-out set (made after the form was chosen)
    // 0.96-1.40 %; session 15's t/R 0.3 at nu 0.48 / 0.35 0.90 / 0.70 %, t/R 0.35 at nu 0.45
    // 0.76 %, t/R 0.25 at nu 0.49 1.25 %, the blind t/R 0.25 at nu 0.47 2.04 %; nu 0.499 t/R
    // 0.2 reaches x = 0.09 only,
    // below the band); raw: 3.4-7.5 %
    // (step noise and lag). Tolerances: seen + 0.2-0.5 points (core: + 0.3, rounded up).
    let cases: [RadiusCase; 34] = [
        ("flat/force_nu0.3.csv", 0.3, None, false, 0.010, 0.080),
        ("flat/force_nu0.4.csv", 0.4, None, false, 0.017, 0.075),
        ("flat/force_nu0.48.csv", 0.48, None, false, 0.017, 0.065),
        ("flat/force_nu0.499.csv", 0.499, None, false, 0.015, 0.065),
        ("flat/force_nu0.35.csv", 0.35, None, true, 0.015, 0.078),
        ("flat/force_nu0.45.csv", 0.45, None, true, 0.015, 0.067),
        (
            "core/force_nu0.3_t0.2.csv",
            0.3,
            Some(0.2),
            false,
            0.024,
            0.049,
        ),
        (
            "core/force_nu0.48_t0.2.csv",
            0.48,
            Some(0.2),
            false,
            0.026,
            0.037,
        ),
        (
            "core/force_nu0.4_t0.2.csv",
            0.4,
            Some(0.2),
            false,
            0.013,
            0.054,
        ),
        (
            "core/force_nu0.4_t0.4.csv",
            0.4,
            Some(0.4),
            false,
            0.014,
            0.059,
        ),
        (
            "core/force_nu0.3_t0.4.csv",
            0.3,
            Some(0.4),
            false,
            0.012,
            0.056,
        ),
        (
            "core/force_nu0.48_t0.4.csv",
            0.48,
            Some(0.4),
            false,
            0.013,
            0.046,
        ),
        (
            "core/force_nu0.499_t0.4.csv",
            0.499,
            Some(0.4),
            false,
            0.019,
            0.048,
        ),
        (
            "core/force_nu0.3_t0.6.csv",
            0.3,
            Some(0.6),
            false,
            0.019,
            0.068,
        ),
        (
            "core/force_nu0.48_t0.6.csv",
            0.48,
            Some(0.6),
            false,
            0.016,
            0.063,
        ),
        (
            "core/force_nu0.499_t0.6.csv",
            0.499,
            Some(0.6),
            false,
            0.020,
            0.065,
        ),
        (
            "core/force_nu0.3_t0.8.csv",
            0.3,
            Some(0.8),
            false,
            0.011,
            0.078,
        ),
        (
            "core/force_nu0.48_t0.8.csv",
            0.48,
            Some(0.8),
            false,
            0.012,
            0.066,
        ),
        (
            "core/force_nu0.499_t0.8.csv",
            0.499,
            Some(0.8),
            false,
            0.011,
            0.067,
        ),
        (
            "core/force_nu0.4_t0.3.csv",
            0.4,
            Some(0.3),
            true,
            0.012,
            0.067,
        ),
        (
            "core/force_nu0.49_t0.3.csv",
            0.49,
            Some(0.3),
            true,
            0.017,
            0.043,
        ),
        (
            "core/force_nu0.45_t0.5.csv",
            0.45,
            Some(0.5),
            true,
            0.016,
            0.065,
        ),
        (
            "core/force_nu0.35_t0.7.csv",
            0.35,
            Some(0.7),
            true,
            0.012,
            0.074,
        ),
        (
            "core/force_nu0.46_t0.25.csv",
            0.46,
            Some(0.25),
            true,
            0.016,
            0.051,
        ),
        (
            "core/force_nu0.33_t0.25.csv",
            0.33,
            Some(0.25),
            true,
            0.013,
            0.055,
        ),
        (
            "core/force_nu0.42_t0.55.csv",
            0.42,
            Some(0.55),
            true,
            0.017,
            0.068,
        ),
        (
            "core/force_nu0.36_t0.2.csv",
            0.36,
            Some(0.2),
            true,
            0.017,
            0.054,
        ),
        (
            "core/force_nu0.44_t0.8.csv",
            0.44,
            Some(0.8),
            true,
            0.016,
            0.077,
        ),
        (
            "core/force_nu0.495_t0.35.csv",
            0.495,
            Some(0.35),
            true,
            0.015,
            0.045,
        ),
        // Session 15: t/R 0.3 (made after the radius was fitted) and a blind t/R 0.25.
        (
            "core/force_nu0.48_t0.3.csv",
            0.48,
            Some(0.3),
            true,
            0.012,
            0.047,
        ),
        (
            "core/force_nu0.35_t0.3.csv",
            0.35,
            Some(0.3),
            true,
            0.010,
            0.065,
        ),
        (
            "core/force_nu0.47_t0.25.csv",
            0.47,
            Some(0.25),
            true,
            0.024,
            0.044,
        ),
        (
            "core/force_nu0.45_t0.35.csv",
            0.45,
            Some(0.35),
            true,
            0.011,
            0.049,
        ),
        (
            "core/force_nu0.49_t0.25.csv",
            0.49,
            Some(0.25),
            true,
            0.016,
            0.041,
        ),
    ];
    for (path, nu, t, held, tol_smooth, tol_lin) in cases {
        let pts = fe(path);
        let a_fe = fe_radius(path);
        let l = law(nu, backing(t));
        let (mut ws, mut wl) = (0.0_f64, 0.0_f64);
        // Inside the law's validity (the core's is x <= 0.8 t/R).
        let hi = l.x_max().min(0.4) + 1e-9;
        for &(x, _, a) in pts.iter().filter(|p| p.0 >= 0.1 - 1e-9 && p.0 <= hi) {
            let r = l.patch(x).radius;
            ws = ws.max((r / a_fe(x) - 1.0).abs());
            wl = wl.max((r / a - 1.0).abs());
        }
        println!(
            "{path} held {held}: {:.2} % (smooth), {:.2} % (a_lin)",
            ws * 100.0,
            wl * 100.0
        );
        assert!(tol_smooth <= 0.03, "{path}: the target is 3 %");
        assert!(ws < tol_smooth, "{path}: {:.2} % vs smooth", ws * 100.0);
        assert!(wl < tol_lin, "{path}: {:.2} % vs a_lin", wl * 100.0);
    }
}

#[test]
fn free_radius_within_3_percent_of_the_smoothed_fe_radius() {
    // The free sphere's calibrated radius (refitted on the reference's estimate): seen 1.07 %
    // (reference nu 0.3), 2.64 % (0.49); held out, softgrip's own FE: 0.78 % (0.3), 1.53 % (0.4),
    // 2.00 % (0.45), 1.31 % (0.49).
    for (path, nu, tol) in [
        ("free/force_nu0.3.csv", 0.3, 0.011),
        ("free/force_nu0.4.csv", 0.4, 0.018),
        ("free/force_nu0.45.csv", 0.45, 0.023),
        ("free/force_nu0.49.csv", 0.49, 0.016),
        ("force_nu0.3.csv", 0.3, 0.014),
        ("force_nu0.49.csv", 0.49, 0.029),
    ] {
        let pts = fe(path);
        let a_fe = fe_radius(path);
        let l = law(nu, Backing::Free);
        let w = pts
            .iter()
            .filter(|p| p.0 >= 0.1 - 1e-9 && p.0 <= 0.4 + 1e-9)
            .map(|p| (l.patch(p.0).radius / a_fe(p.0) - 1.0).abs())
            .fold(0.0_f64, f64::max);
        println!("{path}: {:.2} %", w * 100.0);
        assert!(w < tol, "{path}: {:.2} %", w * 100.0);
    }
}

/// Peak error and largest profile error over r <= 0.8 a_FE, both relative to FE's peak.
fn shape_errors(patch: &ContactPatch, fe: &[(f64, f64)]) -> (f64, f64) {
    let peak = fe.iter().fold(0.0_f64, |m, p| m.max(p.1));
    let a_fe = fe.last().expect("rows").0;
    let prof = fe
        .iter()
        .filter(|p| p.0 <= 0.8 * a_fe + 1e-12)
        .map(|&(r, p)| (patch.pressure_at(r) - p).abs() / peak)
        .fold(0.0_f64, f64::max);
    (patch.peak_pressure / peak - 1.0, prof)
}

/// One FE profile: geometry, nu, t/R, x, the file, held out, and the tolerances
/// `[peak, profile]` with the FE's force and `[peak, profile]` with the law's force.
struct Profile {
    geometry: &'static str,
    nu: f64,
    t: Option<f64>,
    x: f64,
    held: bool,
    text: &'static str,
    fe_force: [f64; 2],
    law_force: [f64; 2],
}

macro_rules! profiles {
    ($($g:literal, $nu:literal, $t:tt, $x:literal, $held:literal, [$p1:literal, $q1:literal], [$p2:literal, $q2:literal]);* $(;)?) => {
        [$(Profile {
            geometry: $g,
            nu: $nu,
            t: if $t > 0.0 { Some($t) } else { None },
            x: $x,
            held: $held,
            text: include_str!(concat!(
                "../../../tests/data/fe/", $g, "/pressure_nu", stringify!($nu),
                profiles!(@t $t), "_d", stringify!($x), ".csv"
            )),
            fe_force: [$p1, $q1],
            law_force: [$p2, $q2],
        }),*]
    };
    (@t 0.0) => { "" };
    (@t 0.14) => { "_t0.14" };
    (@t 0.2) => { "_t0.2" };
    (@t 0.25) => { "_t0.25" };
    (@t 0.3) => { "_t0.3" };
    (@t 0.35) => { "_t0.35" };
    (@t 0.4) => { "_t0.4" };
    (@t 0.5) => { "_t0.5" };
    (@t 0.55) => { "_t0.55" };
    (@t 0.6) => { "_t0.6" };
    (@t 0.7) => { "_t0.7" };
    (@t 0.8) => { "_t0.8" };
}

/// Every FE profile inside the law's validity (x <= x_max; the core's x <= 0.8 t/R since session
/// 10): tolerances in fractions of FE's peak, seen values just below (the law-force columns of
/// 14 core profiles raised in session 21, when the core's force changed: the thin-layer floor;
/// of six in session 24, the squeezed skin's deviatoric stiffening: core nu 0.4 t/R 0.2 x 0.1,
/// 0.45/0.5 x 0.3, 0.48/0.6 x 0.3, 0.499/0.6 x 0.3, 0.46/0.25 x 0.1 and 0.42/0.55 x 0.3, each
/// set to its new seen value rounded up; of three in session 28, the thin-skin form below t/R
/// 0.3: core nu 0.4 t/R 0.2 x 0.1 peak 1.5 -> 2.0 % (seen -2.00), 0.46/0.25 x 0.1 profile 6.1 ->
/// 6.2 % (seen 6.15), 0.32/0.14 x 0.1 profile 8.4 -> 9.5 % (seen 9.50; with the FE's force 9.07,
/// the shape's own miss); the other thin profiles moved within their columns; in session 29, the
/// squeezed film in the thin-skin form, every core profile of t/R < 0.3 re-set to its seen
/// value rounded up: raised, by the new law's force there (the shape is unchanged), 0.4/0.2 x
/// 0.1 peak 2.0 -> 2.3 % (seen -2.22), 0.46/0.25 x 0.1 peak 5.5 -> 5.7 % and profile 6.2 ->
/// 6.4 % (seen -5.68, 6.34), 0.32/0.14 x 0.1 profile 9.5 -> 9.6 % (seen 9.58); tightened, 0.4/0.2
/// profile 3.8 -> 3.0 %, 0.3/0.2 3.4 / 6.0 -> 2.5 / 5.3 %, 0.48/0.2 3.4 / 5.1 -> 1.9 / 3.6 %,
/// 0.33/0.25 profile 2.9 -> 2.6 %, 0.36/0.2 1.9 / 5.0 -> 0.2 / 3.5 %). Not here: core nu 0.44 t/R 0.8 x 0.3, whose FE profile
/// integrates to 1.076 F (every other one to 0.93-1.03 F): a contact-edge node entering contact
/// carries a penalty spike (3.53 MPa at r = 0.661 mm, twice the centre's), which would be taken
/// as FE's peak (`fit_radius_pressure.py` `usable` leaves it out of the fits for the same reason).
fn all_profiles() -> Vec<Profile> {
    profiles!(
        "free", 0.3, 0.0, 0.1, false, [0.006, 0.024], [0.013, 0.017];
        "free", 0.3, 0.0, 0.3, false, [0.008, 0.030], [0.010, 0.031];
        "free", 0.3, 0.0, 0.5, false, [0.032, 0.032], [0.030, 0.030];
        "free", 0.4, 0.0, 0.1, false, [0.014, 0.018], [0.028, 0.032];
        "free", 0.4, 0.0, 0.3, false, [0.015, 0.016], [0.029, 0.030];
        "free", 0.4, 0.0, 0.5, false, [0.017, 0.022], [0.029, 0.029];
        "free", 0.45, 0.0, 0.1, false, [0.015, 0.018], [0.024, 0.028];
        "free", 0.45, 0.0, 0.3, false, [0.016, 0.017], [0.025, 0.026];
        "free", 0.45, 0.0, 0.5, false, [0.015, 0.020], [0.024, 0.025];
        "free", 0.49, 0.0, 0.1, false, [0.014, 0.018], [0.014, 0.018];
        "free", 0.49, 0.0, 0.3, false, [0.013, 0.018], [0.012, 0.020];
        "free", 0.49, 0.0, 0.5, false, [0.013, 0.019], [0.015, 0.017];
        "flat", 0.3, 0.0, 0.1, false, [0.011, 0.018], [0.012, 0.017];
        "flat", 0.3, 0.0, 0.3, false, [0.008, 0.030], [0.009, 0.031];
        "flat", 0.3, 0.0, 0.5, false, [0.030, 0.052], [0.031, 0.051];
        "flat", 0.4, 0.0, 0.1, false, [0.022, 0.025], [0.024, 0.028];
        "flat", 0.4, 0.0, 0.3, false, [0.036, 0.037], [0.035, 0.036];
        "flat", 0.48, 0.0, 0.1, false, [0.006, 0.023], [0.005, 0.026];
        "flat", 0.48, 0.0, 0.3, false, [0.018, 0.019], [0.022, 0.023];
        "flat", 0.499, 0.0, 0.1, false, [0.010, 0.030], [0.015, 0.035];
        "flat", 0.499, 0.0, 0.3, false, [0.011, 0.035], [0.005, 0.028];
        "flat", 0.35, 0.0, 0.1, true, [0.018, 0.021], [0.020, 0.023];
        "flat", 0.35, 0.0, 0.3, true, [0.026, 0.027], [0.023, 0.024];
        "flat", 0.45, 0.0, 0.1, true, [0.013, 0.017], [0.014, 0.017];
        "flat", 0.45, 0.0, 0.3, true, [0.029, 0.031], [0.032, 0.033];
        "core", 0.35, 0.7, 0.1, true, [0.019, 0.023], [0.019, 0.023];
        "core", 0.35, 0.7, 0.3, true, [0.020, 0.021], [0.017, 0.021];
        "core", 0.4, 0.2, 0.1, false, [0.024, 0.031], [0.023, 0.030];
        "core", 0.4, 0.4, 0.1, false, [0.030, 0.034], [0.053, 0.056];
        "core", 0.3, 0.2, 0.1, false, [0.018, 0.048], [0.025, 0.053];
        "core", 0.3, 0.4, 0.1, false, [0.012, 0.015], [0.030, 0.034];
        "core", 0.3, 0.6, 0.1, false, [0.013, 0.017], [0.025, 0.028];
        "core", 0.3, 0.6, 0.3, false, [0.008, 0.048], [0.011, 0.047];
        "core", 0.3, 0.8, 0.1, false, [0.010, 0.017], [0.007, 0.020];
        "core", 0.3, 0.8, 0.3, false, [0.019, 0.041], [0.026, 0.048];
        "core", 0.45, 0.5, 0.1, true, [0.017, 0.021], [0.035, 0.039];
        "core", 0.45, 0.5, 0.3, true, [0.042, 0.046], [0.059, 0.063];
        "core", 0.48, 0.2, 0.1, false, [0.029, 0.046], [0.019, 0.036];
        "core", 0.48, 0.4, 0.1, false, [0.022, 0.026], [0.043, 0.047];
        "core", 0.48, 0.6, 0.1, false, [0.014, 0.018], [0.009, 0.020];
        "core", 0.48, 0.6, 0.3, false, [0.046, 0.048], [0.049, 0.052];
        "core", 0.48, 0.8, 0.1, false, [0.009, 0.018], [0.011, 0.031];
        "core", 0.48, 0.8, 0.3, false, [0.007, 0.023], [0.009, 0.032];
        "core", 0.499, 0.4, 0.1, false, [0.005, 0.022], [0.023, 0.028];
        "core", 0.499, 0.6, 0.1, false, [0.009, 0.018], [0.010, 0.030];
        "core", 0.499, 0.6, 0.3, false, [0.027, 0.029], [0.026, 0.031];
        "core", 0.499, 0.8, 0.1, false, [0.004, 0.024], [0.021, 0.041];
        "core", 0.499, 0.8, 0.3, false, [0.016, 0.039], [0.025, 0.048];
        "core", 0.49, 0.3, 0.1, true, [0.047, 0.053], [0.053, 0.059];
        "core", 0.4, 0.3, 0.1, true, [0.054, 0.058], [0.057, 0.062];
        "core", 0.46, 0.25, 0.1, true, [0.056, 0.063], [0.057, 0.064];
        "core", 0.33, 0.25, 0.1, true, [0.028, 0.034], [0.021, 0.026];
        "core", 0.42, 0.55, 0.1, true, [0.020, 0.023], [0.034, 0.037];
        "core", 0.42, 0.55, 0.3, true, [0.042, 0.045], [0.056, 0.059];
        "core", 0.36, 0.2, 0.1, true, [0.010, 0.034], [0.002, 0.035];
        "core", 0.44, 0.8, 0.1, true, [0.017, 0.021], [0.010, 0.018];
        "core", 0.495, 0.35, 0.1, true, [0.031, 0.036], [0.046, 0.051];
        // Past 0.6 t/R, inside the validity since session 10 (x <= 0.8 t/R), the shape not fitted
        // there (tools/calibration/CORE_PRESSURE.md): the FE's patch at delta/t 0.625-0.75 (nu 0.35
        // t/R 0.7 x 0.5 lies past the flat construction's x_max 0.495).
        "core", 0.3, 0.4, 0.3, false, [0.112, 0.115], [0.097, 0.105];
        "core", 0.3, 0.8, 0.5, false, [0.049, 0.102], [0.050, 0.103];
        "core", 0.4, 0.4, 0.3, false, [0.089, 0.094], [0.096, 0.101];
        // Session 13, held out: the first thin skin past 0.6 t/R (nu 0.32 t/R 0.14 x 0.1, delta/t
        // 0.71, R/60; its profile integrates to 0.993 F). Seen: FE force -2.71 / 9.07 %, law
        // force -6.33 / 6.76 % (the law's force is 3.7 % low there): over the 5 % target, as the
        // three above (CORE_PRESSURE.md, session 13). Session 30's thin-skin radius widens this
        // patch by 1.0 % (against the FE's radius there, smoothed plus the lag, -2.90 -> -1.89 %:
        // `try_thin_skin_radius_s30.py`, "thick"): FE force -4.69 / 8.26 %, law force -3.97 / 8.74 %; the FE-force
        // peak's bound moves from 0.030 to 0.050 (the shape, at its most peaked here, v = 0.975,
        // had carried the narrow radius; CORE_FORM.md, session 30).
        "core", 0.32, 0.14, 0.1, true, [0.050, 0.094], [0.066, 0.096];
    )
    .into_iter()
    .collect()
}

#[test]
fn pressure_follows_the_fe_profile_for_every_construction() {
    // Every profile is printed before any is asserted (one run shows them all).
    let mut missed = Vec::new();
    for p in all_profiles() {
        let backing = match (p.geometry, p.t) {
            ("free", _) => Backing::Free,
            (_, t) => backing(t),
        };
        let l = law(p.nu, backing);
        assert!(
            p.x <= l.x_max() + 1e-12,
            "{} {}: past x_max",
            p.geometry,
            p.x
        );
        let fe_prof = profile(p.text, p.nu);
        let patch = l.patch(p.x);
        let f_fe = fe_force_at(p.geometry, p.nu, p.t, p.x);
        let own = ContactPatch::with_profile(f_fe, patch.radius, patch.shape, patch.taper);
        let (pk_fe, pr_fe) = shape_errors(&own, &fe_prof);
        let (pk, pr) = shape_errors(&patch, &fe_prof);
        println!(
            "{} nu {} t {:?} x {} held {}: m {:.3} b {:.3}; FE force: peak {:+.2} %, profile {:.2} %; law force: peak {:+.2} %, profile {:.2} %",
            p.geometry,
            p.nu,
            p.t,
            p.x,
            p.held,
            patch.shape,
            patch.taper,
            pk_fe * 100.0,
            pr_fe * 100.0,
            pk * 100.0,
            pr * 100.0
        );
        let name = format!("{} nu {} t {:?} x {}", p.geometry, p.nu, p.t, p.x);
        for (ok, what) in [
            (
                pk_fe.abs() < p.fe_force[0],
                format!("peak {pk_fe} (FE force)"),
            ),
            (pr_fe < p.fe_force[1], format!("profile {pr_fe} (FE force)")),
            (pk.abs() < p.law_force[0], format!("peak {pk} (law force)")),
            (pr < p.law_force[1], format!("profile {pr} (law force)")),
        ] {
            if !ok {
                missed.push(format!("{name}: {what}"));
            }
        }
    }
    assert!(missed.is_empty(), "{missed:#?}");
}

/// The FE force (normalised) of the construction at x.
fn fe_force_at(geometry: &str, nu: f64, t: Option<f64>, x: f64) -> f64 {
    let path = match t {
        Some(t) => format!("{geometry}/force_nu{nu}_t{t}.csv"),
        None => format!("{geometry}/force_nu{nu}.csv"),
    };
    fe(&path)
        .into_iter()
        .find(|p| (p.0 - x).abs() < 1e-9)
        .unwrap_or_else(|| panic!("{path} has x = {x}"))
        .1
}

/// `2 pi int_0^a p(r) r dr` of a patch, in `u = 1 - r^2/a^2 = w^4` (smooth for every m).
fn carried(patch: &ContactPatch) -> f64 {
    let a = patch.radius;
    let n = 4000;
    let h = 1.0 / f64::from(n);
    let g = |w: f64| {
        let r = a * (1.0 - w.powi(4)).max(0.0).sqrt();
        patch.pressure_at(r) * 4.0 * w.powi(3)
    };
    // Composite Simpson on [0, 1] in w.
    let mut s = g(0.0) + g(1.0);
    for i in 1..n {
        let w = f64::from(i) * h;
        s += if i % 2 == 1 { 4.0 } else { 2.0 } * g(w);
    }
    std::f64::consts::PI * a * a * s * h / 3.0
}

#[test]
fn every_patch_carries_its_force() {
    let backings = [
        Backing::Free,
        Backing::Flat,
        Backing::Core { thickness: 0.2 },
        Backing::Core { thickness: 0.45 },
        Backing::Core { thickness: 0.8 },
    ];
    for backing in backings {
        for nu in [0.3, 0.42, 0.499] {
            let l = law(nu, backing);
            for i in 1..=8 {
                let x = l.x_max() * f64::from(i) / 8.0;
                let patch = l.patch(x);
                let f = l.response(x).force;
                let got = carried(&patch);
                assert!(
                    (got / f - 1.0).abs() < 1e-9,
                    "{backing:?} nu {nu} x {x}: m {} carries {got} of {f}",
                    patch.shape
                );
            }
        }
    }
}

/// `(x, a_R/80, a_R/40)` of a fine-mesh radius check (`radius_mesh_*.csv`).
fn mesh_check(text: &str) -> Vec<(f64, f64, f64)> {
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("delta_over_R"))
        .map(|l| {
            let v: Vec<f64> = l
                .split(',')
                .map(|v| v.trim().parse().expect("number"))
                .collect();
            (v[0], v[2], v[4])
        })
        .collect()
}

#[test]
fn fe_radius_estimate_agrees_between_r40_and_r80() {
    // flat nu = 0.48 on R/80 (to x = 0.38) against the campaign's R/40. The smoothed a_lin of
    // R/80 is 0.70-1.54 % above R/40's (the lag halves with the element); with the lag added both
    // agree within 0.97 %; R/80's own step noise is 0.74 % rms (R/40: 1.68 %).
    let rows = mesh_check(include_str!(
        "../../../tests/data/fe/flat/radius_mesh_nu0.48.csv"
    ));
    let fine: Vec<(f64, f64, f64)> = rows.iter().map(|r| (r.0, 0.0, r.1)).collect();
    let coarse: Vec<(f64, f64, f64)> = rows.iter().map(|r| (r.0, 0.0, r.2)).collect();
    let (s80, s40) = (Smooth::fit(&fine), Smooth::fit(&coarse));
    let (mut raw_lo, mut raw_hi, mut cor) = (f64::MAX, f64::MIN, 0.0_f64);
    for &(x, _, _) in rows.iter().filter(|r| r.0 >= 0.1 - 1e-9) {
        let raw = s80.at(x) / s40.at(x) - 1.0;
        raw_lo = raw_lo.min(raw);
        raw_hi = raw_hi.max(raw);
        let c = (s80.at(x) + LAG_TIMES_N / 80.0) / (s40.at(x) + LAG_TIMES_N / 40.0) - 1.0;
        cor = cor.max(c.abs());
    }

    assert!(raw_lo > 0.005 && raw_hi < 0.018, "{raw_lo} {raw_hi}");
    assert!(cor < 0.011, "with the lag: {cor}");
    // The same estimate (lag included) is what the radius tests compare against.
    let a40 = fe_radius("flat/force_nu0.48.csv");
    for &(x, _, _) in rows.iter().filter(|r| r.0 >= 0.1 - 1e-9) {
        let d = (s80.at(x) + LAG_TIMES_N / 80.0) / a40(x) - 1.0;
        assert!(d.abs() < 0.011, "x = {x}: {d}");
    }
}

#[test]
fn fe_radius_estimate_is_the_fine_mesh_limit() {
    // flat nu = 0.48 on R/40, R/80 and R/120: the smoothed a_lin converges at first order in
    // the element size (a_N = a_inf - c/N, c = 0.40-0.61), and the estimate of R/40 (smoothed +
    // 0.485 R/40) is within 0.71 % of that limit a_inf for 0.1 <= x <= 0.32 (seen).
    let m80 = mesh_check(include_str!(
        "../../../tests/data/fe/flat/radius_mesh_nu0.48.csv"
    ));
    let m120 = mesh_check(include_str!(
        "../../../tests/data/fe/flat/radius_mesh_nu0.48_h120.csv"
    ));
    let fit = |rows: &[(f64, f64, f64)], coarse: bool| {
        let pts: Vec<(f64, f64, f64)> = rows
            .iter()
            .map(|r| (r.0, 0.0, if coarse { r.2 } else { r.1 }))
            .collect();
        Smooth::fit(&pts)
    };
    let (s40, s80, s120) = (fit(&m80, true), fit(&m80, false), fit(&m120, false));
    let mut worst = 0.0_f64;
    for i in 0..=11 {
        let x = 0.1 + 0.02 * f64::from(i);
        // Least squares of a_N = a_inf - c/N through the three meshes.
        let pts = [(40.0, s40.at(x)), (80.0, s80.at(x)), (120.0, s120.at(x))];
        let (sx, sy) = pts
            .iter()
            .fold((0.0, 0.0), |(a, b), p| (a - 1.0 / p.0, b + p.1));
        let (sxx, sxy) = pts.iter().fold((0.0, 0.0), |(a, b), p| {
            (a + 1.0 / (p.0 * p.0), b - p.1 / p.0)
        });
        let c = (3.0 * sxy - sx * sy) / (3.0 * sxx - sx * sx);
        let a_inf = (sy - c * sx) / 3.0;
        assert!((0.35..0.65).contains(&c), "x = {x}: c = {c}");
        let star = s40.at(x) + LAG_TIMES_N / 40.0;
        worst = worst.max((star / a_inf - 1.0).abs());
    }
    assert!(worst < 0.008, "a* vs the fine-mesh limit: {worst}");
}

#[test]
fn radius_and_shape_have_their_limits_for_every_skin() {
    // Hertz at x -> 0 (a = sqrt(R delta) to O(sqrt x), m = 1/2, no taper); the radius grows
    // with x (to x = 1, past x_max too); a skin over a core widens the patch and fills it
    // (m >= flat's, tapered: peak/mean >= flat's), more the thinner the skin.
    let peak_over_mean = |p: &ContactPatch| p.peak_pressure / p.mean_pressure;
    for nu in [0.3, 0.4, 0.49, 0.5] {
        let flat = law(nu, Backing::Flat);
        let ts = [0.99, 0.9, 0.7, 0.5, 0.35, 0.2, 0.1, 0.05];
        let mut prev_m = flat.patch(0.02).shape;
        let mut prev_ratio = peak_over_mean(&flat.patch(0.02));
        for t in ts {
            let core = law(nu, Backing::Core { thickness: t });
            for l in [&flat, &core] {
                let tiny = l.patch(1e-10);
                assert!(
                    (tiny.shape - 0.5).abs() < 1e-3,
                    "nu {nu} t {t}: m {}",
                    tiny.shape
                );
                assert!((tiny.radius / 1e-5 - 1.0).abs() < 0.02, "{}", tiny.radius);
                // The taper fades at first order in the patch over the skin, b ~ -a_H/t: -2.6e-5
                // at x = 1e-10 for the thinnest skin here (t/R = 0.05, nu 0.3), and a patch ten
                // times narrower (x / 100) has a tenth of it.
                assert!(
                    tiny.taper <= 0.0 && tiny.taper > -4e-5,
                    "nu {nu} t {t}: b {}",
                    tiny.taper
                );
                if tiny.taper < 0.0 {
                    let ratio = tiny.taper / l.patch(1e-12).taper;
                    assert!(
                        (9.9..10.1).contains(&ratio),
                        "nu {nu} t {t}: b ratio {ratio}"
                    );
                }
                let mut last = 0.0;
                for i in 1..=400 {
                    let x = f64::from(i) / 400.0;
                    let p = l.patch(x);
                    assert!(
                        p.radius > last,
                        "nu {nu} t {t} x {x}: radius not increasing"
                    );
                    assert!(
                        (0.3..=2.0).contains(&p.shape),
                        "nu {nu} t {t} x {x}: m {}",
                        p.shape
                    );
                    assert!(
                        (-1.0..=0.0).contains(&p.taper),
                        "nu {nu} t {t} x {x}: b {}",
                        p.taper
                    );
                    last = p.radius;
                }
            }
            for i in 1..=40 {
                let x = core.x_max() * f64::from(i) / 40.0;
                let (c, f) = (core.patch(x), flat.patch(x));
                assert!(c.radius >= f.radius, "nu {nu} t {t} x {x}: core narrower");
                assert!(
                    c.shape >= f.shape - 1e-12,
                    "nu {nu} t {t} x {x}: core flatter"
                );
                assert!(
                    peak_over_mean(&c) >= peak_over_mean(&f) - 1e-12,
                    "nu {nu} t {t} x {x}: core's peak/mean below flat's"
                );
            }
            let m = core.patch(0.02).shape;
            assert!(m >= prev_m - 1e-12, "nu {nu} t {t}: m {m} < {prev_m}");
            prev_m = m;
            let ratio = peak_over_mean(&core.patch(0.02));
            assert!(
                ratio >= prev_ratio - 1e-12,
                "nu {nu} t {t}: peak/mean {ratio} < {prev_ratio}"
            );
            prev_ratio = ratio;
        }
    }
}

/// `(x, a/R, N)` of a thin skin's force file of `tests/data/fe/core/k1e6/` (R = 1 mm, so the
/// `contact_radius_mm` column is a/R; `N` of the mesh `R/N` its provenance line names).
fn k1e6(csv: &str) -> (Vec<(f64, f64)>, f64) {
    let mut lines = csv.lines();
    let head = lines.next().expect("provenance");
    let i = head.find("element edge R/").expect("the mesh") + "element edge R/".len();
    let n: String = head[i..].chars().take_while(char::is_ascii_digit).collect();
    let n: f64 = n.parse().expect("N");
    let names: Vec<&str> = lines.next().expect("header").split(',').collect();
    let col = |name: &str| names.iter().position(|c| *c == name).expect(name);
    let (ix, ia) = (col("delta_over_R"), col("contact_radius_mm"));
    let rows = lines
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|c| c.parse().expect("a number")).collect();
            (v[ix], v[ia])
        })
        .collect();
    (rows, n)
}

/// Issue 24 item 5 (session 27): the thin skins' contact radius, x >= 0.02 (no radius test
/// reached below x = 0.1 before). The seventeen re-runs of `tests/data/fe/core/k1e6/` (t/R
/// 0.05-0.14, nu 0.3-0.49; ~9 CAX8R elements through the skin, R/65-R/180 at the surface) go
/// to x = 0.02-0.105: a patch of 8-27 elements, whose radius column moves in node steps of
/// 2-8 % of the radius (0.97 R/N a face), too coarse for `Smooth` (x >= 0.05). What is
/// readable is the mean over the points: the law's `a / (a_lin + 0.485 R/N) - 1` (the lag of
/// `LAG_TIMES_N`) averaged over 0.02 <= x <= min(reach, x_max), and each point about that mean
/// within the column's steps. Since session 30 a thin skin's radius is the exact small-strain
/// bonded layer's, faded into the radius form by t/R 0.2 (`backed.rs`, Radius; no fitted
/// constant): every skin within -0.69 .. +2.33 % (the six of the force's fitted set within
/// 1.87 %, the other eleven within 2.33 %), every point within 1.02 element faces of its mean
/// (`tools/calibration/try_thin_skin_radius_s30.py`, form F0.2, the same numbers). Before it
/// (the radius form alone, `try_thin_skin_s27.py --radius`): -5.02 % at nu 0.3 t/R 0.05 (its
/// a/a_H 1.30 where the FE's is 1.37), +1.8 .. +3.1 % at nu >= 0.45, 15 of 17 within the issue's
/// 3 %, every point within 1.22 faces. Tolerances: each mean within 0.3 points of what was
/// seen, every point within 1.3 faces of its mean.
#[test]
fn thin_skin_radius_is_what_the_readme_states() {
    // (file, nu, t/R, seen mean [%])
    let skins: [(&str, f64, f64, f64); 17] = [
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.3_t0.05.csv"),
            0.3,
            0.05,
            -0.69,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.3_t0.08.csv"),
            0.3,
            0.08,
            0.34,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.3_t0.1.csv"),
            0.3,
            0.1,
            0.44,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.32_t0.14.csv"),
            0.32,
            0.14,
            1.75,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.35_t0.06.csv"),
            0.35,
            0.06,
            0.21,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.38_t0.12.csv"),
            0.38,
            0.12,
            1.82,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.4_t0.05.csv"),
            0.4,
            0.05,
            1.07,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.4_t0.06.csv"),
            0.4,
            0.06,
            0.69,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.4_t0.08.csv"),
            0.4,
            0.08,
            1.17,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.4_t0.1.csv"),
            0.4,
            0.1,
            1.87,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.45_t0.07.csv"),
            0.45,
            0.07,
            0.38,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.46_t0.1.csv"),
            0.46,
            0.1,
            1.55,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.48_t0.05.csv"),
            0.48,
            0.05,
            -0.06,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.48_t0.06.csv"),
            0.48,
            0.06,
            -0.17,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.48_t0.08.csv"),
            0.48,
            0.08,
            0.33,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.48_t0.1.csv"),
            0.48,
            0.1,
            0.44,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.49_t0.12.csv"),
            0.49,
            0.12,
            2.33,
        ),
    ];
    let mut within_3 = 0;
    for (csv, nu, t, seen) in skins {
        let (rows, n) = k1e6(csv);
        let l = law(nu, Backing::Core { thickness: t });
        let face = 0.97 / n;
        let errs: Vec<(f64, f64)> = rows
            .iter()
            .filter(|p| p.0 >= 0.02 - 1e-9 && p.0 <= l.x_max() + 1e-9)
            .map(|&(x, a)| {
                let a_fe = a + LAG_TIMES_N / n;
                (
                    100.0 * (l.patch(x).radius / a_fe - 1.0),
                    100.0 * face / a_fe,
                )
            })
            .collect();
        assert!(!errs.is_empty(), "nu {nu} t/R {t}: points at x >= 0.02");
        let mean = errs.iter().map(|e| e.0).sum::<f64>() / errs.len() as f64;
        let spread = errs
            .iter()
            .map(|e| (e.0 - mean).abs() / e.1)
            .fold(0.0_f64, f64::max);
        println!(
            "nu {nu} t/R {t} (R/{n}, {} points): mean {mean:+.2} %, each within {spread:.2} faces",
            errs.len()
        );
        assert!(
            (mean - seen).abs() < 0.3,
            "nu {nu} t/R {t}: mean {mean:+.2} % (seen {seen:+.2} %)"
        );
        assert!(
            spread < 1.3,
            "nu {nu} t/R {t}: a point {spread:.2} faces off"
        );
        if mean.abs() < 3.0 {
            within_3 += 1;
        }
    }
    assert_eq!(within_3, 17, "the issue's 3 %: every skin");
}
