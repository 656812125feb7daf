//! The backed fingertips (`Backing::Flat`, `Backing::Core`) and the free sphere's extension,
//! against softgrip's own finite elements (`tests/data/fe/{free,flat,core}/`, embedded by
//! `softgrip-fe`), and the law's invariants for every backing. The numbers in the comments are
//! what the current code gives.

mod common;

use common::profile;
use softgrip_law::{Backing, ContactLaw, ContactParams, Error, Level, LevelKind, Regime};

/// A law in normalised units (E* = 1 Pa, R = 1 m) with `backing` (thickness as t/R).
fn law(level: Level, nu: f64, backing: Backing) -> ContactLaw {
    let p = ContactParams::try_from_parts(1.0, 1.0, nu)
        .and_then(|p| p.with_backing(backing))
        .expect("valid params");
    ContactLaw::try_new(p, level).expect("level builds")
}

/// `(x, f)` of an embedded FE force file.
fn fe(path: &str) -> Vec<(f64, f64)> {
    softgrip_fe::file(path)
        .unwrap_or_else(|| panic!("{path} is embedded"))
        .points()
        .expect("parses")
        .into_iter()
        .map(|p| (p.x, p.force_norm))
        .collect()
}

/// Largest `|F_law / F_FE - 1|` over the FE points with `0.01 <= x <= hi`, and where.
fn worst(law: &ContactLaw, data: &[(f64, f64)], hi: f64) -> (f64, f64) {
    data.iter()
        .filter(|p| p.0 >= 0.01 - 1e-9 && p.0 <= hi + 1e-9)
        .map(|&(x, f)| ((law.response(x).force / f - 1.0).abs(), x))
        .fold((0.0, 0.0), |m, e| if e.0 > m.0 { e } else { m })
}

#[test]
fn free_calibrated_reaches_the_fe_reach_on_held_out_nu() {
    // Fitted on the reference (nu = 0.3 and 0.49); softgrip's own FE at nu = 0.4 and 0.45 is
    // not in the fit. Seen: 1.74 % (0.4, at x = 0.2) and 1.27 % (0.45) to x = 0.78.
    for nu in [0.4, 0.45] {
        let cal = law(Level::Calibrated, nu, Backing::Free);
        assert!((cal.x_max() - 0.78).abs() < 1e-12, "x_max {}", cal.x_max());
        let (w, x) = worst(&cal, &fe(&format!("free/force_nu{nu}.csv")), 0.78);
        assert!(w < 0.02, "nu = {nu}: {:.2} % at x = {x}", w * 100.0);
    }
    // And the reference itself, to its reach: seen 0.72 % (0.3, to 0.61), 1.34 % (0.49, to 0.78).
    for (nu, hi, tol) in [(0.3, 0.61, 0.01), (0.49, 0.78, 0.015)] {
        let cal = law(Level::Calibrated, nu, Backing::Free);
        let (w, x) = worst(&cal, &fe(&format!("force_nu{nu}.csv")), hi);
        assert!(w < tol, "nu = {nu}: {:.2} % at x = {x}", w * 100.0);
    }
}

#[test]
fn flat_calibrated_is_within_1_percent_of_its_fe_at_every_nu() {
    // Seen: 0.54 % (0.3), 0.75 % (0.4), 0.55 % (0.48), 0.63 % (0.499) over 0.01..reach; each nu
    // held out of the fit in turn stays within 1.31 % (crate README).
    for (nu, reach) in [(0.3, 0.53), (0.4, 0.46), (0.48, 0.44), (0.499, 0.31)] {
        let flat = law(Level::Calibrated, nu, Backing::Flat);
        let (w, x) = worst(&flat, &fe(&format!("flat/force_nu{nu}.csv")), reach);
        assert!(w < 0.01, "nu = {nu}: {:.2} % at x = {x}", w * 100.0);
        assert!(
            flat.x_max() >= reach.min(0.44) - 1e-12,
            "x_max {}",
            flat.x_max()
        );
    }
}

#[test]
fn backed_calibrated_on_fe_runs_held_out_of_every_fit() {
    // nu and t/R between the fitted ones (tools/fe/fe_campaign.py role "heldout"), each to
    // its FE reach. Seen: flat 0.35: 1.66 %, flat 0.45: 0.54 %. Core since session 24 (the
    // squeezed skin's deviatoric stiffening, eight constants refitted; session 21's law's value
    // in brackets): (0.45, 0.5) 2.39 [1.63], (0.35, 0.7) 0.45 [0.48], (0.4, 0.3) 1.37 [2.40],
    // (0.49, 0.3) 2.67 [2.01]; the second set (0.46, 0.25) 1.34 [3.53], (0.33, 0.25) 1.44
    // [1.24], (0.42, 0.55) 2.05 [1.66], (0.36, 0.2) 2.26 [2.88], (0.44, 0.8) 0.95 [1.09],
    // (0.495, 0.35) 1.22 [1.78]; the third (0.47, 0.15) 2.27 [2.05], (0.42, 0.25) 1.98 [2.92];
    // the fourth: (0.38, 0.12) 2.33 [2.51], (0.46, 0.1) 1.62 [1.64], (0.32, 0.14) 1.53 [1.21],
    // (0.49, 0.12) 3.08 [3.40]; session 15's (0.48, 0.3) 1.24 [1.18], (0.35, 0.3) 0.53 [0.82],
    // (0.45, 0.35) 1.31 [1.88], (0.49, 0.25) 1.95 [1.83], (0.47, 0.25) 1.00 [1.86]; session
    // 20's blind t/R 0.08: (0.4, 0.08) 3.10 [3.30], (0.3, 0.08) 2.07 [2.25]; session 20's thin
    // skins (fit data since session 21): (0.3, 0.05) 3.32 [3.46], (0.4, 0.05) 3.18 [3.26],
    // (0.3, 0.1) 1.70 [1.87], (0.48, 0.1) 2.84 [3.18], (0.4, 0.1) 2.83 [3.06]. The 2 % target
    // is missed on sixteen of the 33 core files, as with session 21's law (crate README *Thin
    // skins*). Since session 28 (the thin-skin form SFB0030 below t/R 0.3; the tolerances of
    // the files of t/R < 0.3 are its): (0.46, 0.25) 1.85, (0.33, 0.25) 0.96, (0.36, 0.2) 1.05,
    // (0.47, 0.15) 2.84, (0.42, 0.25) 2.20, (0.38, 0.12) 0.56, (0.46, 0.1) 1.47, (0.32, 0.14)
    // 0.95, (0.49, 0.12) 0.94, (0.49, 0.25) 1.70, (0.47, 0.25) 0.95, (0.4, 0.08) 0.42, (0.3,
    // 0.08) 0.60, (0.3, 0.05) 1.19, (0.4, 0.05) 2.11, (0.3, 0.1) 0.62, (0.48, 0.1) 0.77, (0.48,
    // 0.08) 2.37, (0.4, 0.06) 2.43, (0.48, 0.06) 2.52, (0.45, 0.07) 1.24, (0.35, 0.06) 1.67,
    // (0.4, 0.1) 0.34: the 2 % target missed on nine of the 33. Since session 29 (the
    // thin-skin form SFF: SFB0030 with the squeezed film; the tolerances of the files of t/R <
    // 0.3 are its, `tools/calibration/try_deep_squeeze_s29.py --var SFF`): (0.46, 0.25) 1.67,
    // (0.33, 0.25) 0.87, (0.36, 0.2) 0.65, (0.47, 0.15) 2.27, (0.42, 0.25) 2.13, (0.38, 0.12)
    // 0.37, (0.46, 0.1) 1.61, (0.32, 0.14) 1.04, (0.49, 0.12) 1.46, (0.49, 0.25) 1.80, (0.47,
    // 0.25) 0.92, (0.4, 0.08) 0.54, (0.3, 0.08) 1.03, (0.3, 0.05) 0.79, (0.4, 0.05) 1.75, (0.3,
    // 0.1) 1.20, (0.48, 0.1) 1.35, (0.48, 0.08) 2.69, (0.4, 0.06) 2.25, (0.48, 0.06) 2.32, (0.45,
    // 0.07) 1.12, (0.35, 0.06) 1.67, (0.4, 0.1) 0.48: the 2 % target missed on eight of the 33,
    // worst 2.69 % (was 2.84). Ten tolerances are looser than session 28's, each by the new
    // law's own number (a re-pin, not a slack): (0.46, 0.1), (0.32, 0.14), (0.49, 0.12), (0.49,
    // 0.25), (0.4, 0.08), (0.3, 0.08), (0.3, 0.1), (0.48, 0.1), (0.48, 0.08), (0.4, 0.1), all
    // but (0.48, 0.08) within 1.8 %. They are the campaign's penalty-1e5 runs, soft by the
    // penalty (0.4-1.6 %, more as the squeeze grows: `core/penalty.csv`), and the film stiffens
    // the deep squeeze they under-report; their penalty-1e6 re-runs (the `k1e6` tests below)
    // are the references the form was judged on, and there it is better on every set's worst.
    // Each tolerance: seen + 0.1 %.
    let cases = [
        ("flat/force_nu0.35.csv", 0.35, Backing::Flat, 0.02),
        ("flat/force_nu0.45.csv", 0.45, Backing::Flat, 0.01),
        (
            "core/force_nu0.45_t0.5.csv",
            0.45,
            Backing::Core { thickness: 0.5 },
            0.0249,
        ),
        (
            "core/force_nu0.35_t0.7.csv",
            0.35,
            Backing::Core { thickness: 0.7 },
            0.0055,
        ),
        (
            "core/force_nu0.4_t0.3.csv",
            0.4,
            Backing::Core { thickness: 0.3 },
            0.0147,
        ),
        (
            "core/force_nu0.49_t0.3.csv",
            0.49,
            Backing::Core { thickness: 0.3 },
            0.0277,
        ),
        (
            "core/force_nu0.46_t0.25.csv",
            0.46,
            Backing::Core { thickness: 0.25 },
            0.0177,
        ),
        (
            "core/force_nu0.33_t0.25.csv",
            0.33,
            Backing::Core { thickness: 0.25 },
            0.0097,
        ),
        (
            "core/force_nu0.42_t0.55.csv",
            0.42,
            Backing::Core { thickness: 0.55 },
            0.0215,
        ),
        (
            "core/force_nu0.36_t0.2.csv",
            0.36,
            Backing::Core { thickness: 0.2 },
            0.0075,
        ),
        (
            "core/force_nu0.44_t0.8.csv",
            0.44,
            Backing::Core { thickness: 0.8 },
            0.0105,
        ),
        (
            "core/force_nu0.495_t0.35.csv",
            0.495,
            Backing::Core { thickness: 0.35 },
            0.0132,
        ),
        // The third set (session 11, run after every constant was fixed): a skin thinner than
        // any fitted (t/R 0.15, to its FE's end 0.08) and one between them.
        (
            "core/force_nu0.47_t0.15.csv",
            0.47,
            Backing::Core { thickness: 0.15 },
            0.0237,
        ),
        (
            "core/force_nu0.42_t0.25.csv",
            0.42,
            Backing::Core { thickness: 0.25 },
            0.0223,
        ),
        // The fourth set (session 13, run after every constant was fixed): skins thinner than
        // any fitted, each to its FE's end, on finer meshes (R/75 and R/60).
        (
            "core/force_nu0.38_t0.12.csv",
            0.38,
            Backing::Core { thickness: 0.12 },
            0.0047,
        ),
        (
            "core/force_nu0.46_t0.1.csv",
            0.46,
            Backing::Core { thickness: 0.1 },
            0.0171,
        ),
        (
            "core/force_nu0.32_t0.14.csv",
            0.32,
            Backing::Core { thickness: 0.14 },
            0.0114,
        ),
        (
            "core/force_nu0.49_t0.12.csv",
            0.49,
            Backing::Core { thickness: 0.12 },
            0.0156,
        ),
        // Session 15: fit data for the next refit between the fitted t/R 0.2 and 0.4 (made
        // after the constants; the refit tried was not adopted, crate README *Thin skins*).
        (
            "core/force_nu0.48_t0.3.csv",
            0.48,
            Backing::Core { thickness: 0.3 },
            0.0134,
        ),
        (
            "core/force_nu0.35_t0.3.csv",
            0.35,
            Backing::Core { thickness: 0.3 },
            0.0063,
        ),
        (
            "core/force_nu0.45_t0.35.csv",
            0.45,
            Backing::Core { thickness: 0.35 },
            0.0141,
        ),
        (
            "core/force_nu0.49_t0.25.csv",
            0.49,
            Backing::Core { thickness: 0.25 },
            0.0190,
        ),
        // Session 15, blind (run after every constant tried that session was fixed).
        (
            "core/force_nu0.47_t0.25.csv",
            0.47,
            Backing::Core { thickness: 0.25 },
            0.0102,
        ),
        // Session 20, blind (run after the session's thin-layer variants were fixed), thinner
        // than any run before: (0.4, 0.08) 3.77 % (at its end x = 0.04, delta/t 0.5, -; +3.47 %
        // at x = 0.01; R/100 within 0.16 % of this R/75 run); (0.3, 0.08) 10.16 % (at its end
        // x = 0.05, delta/t 0.63, -; -5.2 % already at x = 0.02): inside the stated validity
        // (t/R >= 0.05, x <= 0.8 t/R) the law is far too soft on a thin compressible skin, where
        // the patch outgrows the skin (a_H/t 1.8-2.8) and the thin layer's oedometer carries it
        // (crate README *Thin skins*, CORE_FORM.md "Thin skins: session 20").
        (
            "core/force_nu0.4_t0.08.csv",
            0.4,
            Backing::Core { thickness: 0.08 },
            0.0064,
        ),
        (
            "core/force_nu0.3_t0.08.csv",
            0.3,
            Backing::Core { thickness: 0.08 },
            0.0113,
        ),
        // Session 20, second part: fit data for the thin-layer floor (not fitted: the law was
        // not refitted; CORE_FORM.md "Thin skins: session 20, fit data at t/R 0.05-0.1"),
        // thinner than any run before, R/120 (6 elements through the skin): today's law is far
        // too soft, already at x = 0.01 (-10.1 % at nu 0.3).
        (
            "core/force_nu0.3_t0.05.csv",
            0.3,
            Backing::Core { thickness: 0.05 },
            0.0089,
        ),
        (
            "core/force_nu0.4_t0.05.csv",
            0.4,
            Backing::Core { thickness: 0.05 },
            0.0185,
        ),
        (
            "core/force_nu0.3_t0.1.csv",
            0.3,
            Backing::Core { thickness: 0.1 },
            0.0130,
        ),
        (
            "core/force_nu0.48_t0.1.csv",
            0.48,
            Backing::Core { thickness: 0.1 },
            0.0145,
        ),
        // Session 21, blind (run after the thin-layer floor's constants were fixed; smaller
        // increments, `fe_campaign.py` S21_DT): (0.48, 0.08) on R/80 2.71 % (x = 0.01, too
        // soft; within 1.3 % from x = 0.015; session 20's law 3.15 %, too soft at its end x =
        // 0.0325), (0.4, 0.06) on R/100 3.75 % (x = 0.01, too stiff, falling to +1.94 % at its
        // end x = 0.03; session 20's law 6.99 %, too soft at the end), (0.48, 0.06) on R/100
        // 1.47 % (x = 0.01, too soft; to x = 0.02; session 20's law 5.38 %, too soft at its end).
        // Session 24's law: 2.35 %, 3.80 % (the one blind skin it makes worse, at x = 0.01) and
        // 1.18 %.
        (
            "core/force_nu0.48_t0.08.csv",
            0.48,
            Backing::Core { thickness: 0.08 },
            0.0279,
        ),
        (
            "core/force_nu0.4_t0.06.csv",
            0.4,
            Backing::Core { thickness: 0.06 },
            0.0235,
        ),
        (
            "core/force_nu0.48_t0.06.csv",
            0.48,
            Backing::Core { thickness: 0.06 },
            0.0242,
        ),
        // ... and (0.45, 0.07) on R/90 3.76 % (x = 0.0175, too stiff, +2.3 to +3.8 % along
        // it; session 20's law 2.94 %: on this blind skin the thin-layer floor is worse;
        // session 24's law 3.58 %).
        (
            "core/force_nu0.45_t0.07.csv",
            0.45,
            Backing::Core { thickness: 0.07 },
            0.0122,
        ),
        // Session 21's fifth blind skin, exported in session 22: (0.35, 0.06) on R/100 1.97 %
        // (x = 0.03, its end: too stiff, +0.5 to +2.0 % along it; session 20's law 9.14 %;
        // session 24's law 1.53 %).
        (
            "core/force_nu0.35_t0.06.csv",
            0.35,
            Backing::Core { thickness: 0.06 },
            0.0177,
        ),
        (
            "core/force_nu0.4_t0.1.csv",
            0.4,
            Backing::Core { thickness: 0.1 },
            0.0058,
        ),
    ];
    // Every file is printed before any is asserted (one run shows them all).
    let mut missed = Vec::new();
    for (path, nu, backing, tol) in cases {
        let cal = law(Level::Calibrated, nu, backing);
        let (w, x) = worst(&cal, &fe(path), cal.x_max());
        eprintln!("{path}: {:.2} % at x = {x}", w * 100.0);
        if w >= tol {
            missed.push(format!("{path}: {:.2} % at x = {x}", w * 100.0));
        }
    }
    assert!(missed.is_empty(), "{missed:#?}");
}

#[test]
fn flat_is_stiffer_than_the_free_sphere_as_the_issue_measured() {
    // Issue 10: at nu = 0.49 the bonded hemisphere carries 1.04x the free sphere at x = 0.01,
    // 1.16x at 0.1, 1.30x at 0.2 and 1.63x at 0.4 (FE over FE).
    let flat = law(Level::Calibrated, 0.49, Backing::Flat);
    let free = law(Level::Calibrated, 0.49, Backing::Free);
    for (x, want) in [(0.01, 1.04), (0.1, 1.16), (0.2, 1.30), (0.4, 1.63)] {
        let r = flat.response(x).force / free.response(x).force;
        assert!((r / want - 1.0).abs() < 0.02, "x = {x}: {r:.3} vs {want}");
    }
}

#[test]
fn core_calibrated_error_against_its_fe_is_what_the_readme_states() {
    // Fitted on these 14 curves (with the CAX8 run of nu 0.48, t/R 0.4 in place of its CAX8R
    // one here) and session 20's six t/R 0.05-0.1 skins (session 24,
    // tools/calibration/try_thin_skin_s23.py --var K: eight constants; session 21's law in
    // brackets: 1.65, 2.98, 2.20, 2.09; 2.66, 1.41, 0.86, 1.04; 2.17, 1.58, 2.38; 0.87, 1.94,
    // 1.75). Since session 28 t/R 0.2 takes the thin-skin form at weight 0.26 (session 24-27's
    // law there: 2.52, 1.83, 1.26, 2.16; session 28's SFB0030 1.56, 1.79, 1.85, 2.29; since
    // session 29 SFF, with the squeezed film); from t/R 0.3 the law is unchanged. Seen, to x_max
    // = min(flat's, 0.8 t/R) (each FE curve's reach: delta/t 0.45-0.8), the largest
    // |F/F_FE - 1| in %; each tolerance is the seen value plus 0.1 % above, 0.25 % below (a
    // changed constant or term breaks it).
    let seen = [
        (0.3, 0.2, 1.45),
        (0.4, 0.2, 1.62),
        (0.48, 0.2, 1.45),
        (0.499, 0.2, 1.99),
        (0.3, 0.4, 2.42),
        (0.4, 0.4, 1.85),
        (0.48, 0.4, 1.55),
        (0.499, 0.4, 1.36),
        (0.3, 0.6, 1.80),
        (0.48, 0.6, 1.20),
        (0.499, 0.6, 2.17),
        (0.3, 0.8, 0.74),
        (0.48, 0.8, 1.78),
        (0.499, 0.8, 1.69),
    ];
    for (nu, t, pct) in seen {
        let core = law(Level::Calibrated, nu, Backing::Core { thickness: t });
        let flat = law(Level::Calibrated, nu, Backing::Flat);
        assert!((core.x_max() - (0.8 * t).min(flat.x_max())).abs() < 1e-12);
        let data = fe(&format!("core/force_nu{nu}_t{t}.csv"));
        let (w, x) = worst(&core, &data, core.x_max());
        eprintln!("nu = {nu} t = {t}: {:.2} % at x = {x}", w * 100.0);
        assert!(
            w * 100.0 < pct + 0.1,
            "nu = {nu} t = {t}: {:.2} % at x = {x} (seen {pct} %)",
            w * 100.0
        );
        // Not loose either: within 0.25 % of what was seen.
        assert!(
            w * 100.0 > pct - 0.25,
            "nu = {nu} t = {t}: {:.2} %",
            w * 100.0
        );
    }
}

/// `(x, f)` of a CAX8 force file of `tests/data/fe/core/cax8/` (the columns of `core/`'s force
/// files after one `# provenance:` line), normalised as `fe`'s.
fn cax8(csv: &str, nu: f64) -> Vec<(f64, f64)> {
    let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
    assert_eq!(
        lines.next().and_then(|h| h.split(',').nth(1)),
        Some("force_N")
    );
    lines
        .map(|l| {
            let mut v = l.split(',').map(|c| c.parse::<f64>().expect("a number"));
            let x = v.next().expect("x");
            let force_n = v.next().expect("force");
            (x, force_n / softgrip_fe::effective_modulus_mpa(nu))
        })
        .collect()
}

/// One FE skin curve a test pins the calibrated core law on: its CSV text (`cax8`), nu, t/R,
/// the x its FE reached, the law's worst |miss| \[%\] seen to `x_max`, the x where it is, and
/// whether the law is softer than the FE there.
type Skin = (&'static str, f64, f64, f64, f64, f64, bool);

/// Pins the law's worst miss on each of `skins` to `x_max`: where it is (exactly), how large
/// (within -0.25 / +0.1 of a percentage point of what was seen) and its sign; with `inside`,
/// every curve also ends inside the law's range.
fn pin_skins(skins: &[Skin], inside: bool) {
    for &(csv, nu, t, reach, pct, at, soft) in skins {
        let data = cax8(csv, nu);
        assert!((data.last().expect("points").0 - reach).abs() < 1e-9);
        let core = law(Level::Calibrated, nu, Backing::Core { thickness: t });
        assert!(
            !inside || core.x_max() >= reach,
            "nu {nu} t/R {t}: inside the law's range"
        );
        let (w, x) = worst(&core, &data, core.x_max());
        eprintln!(
            "nu {nu} t/R {t}: {:.2} % at x = {x} (x_max {})",
            w * 100.0,
            core.x_max()
        );
        assert!((x - at).abs() < 1e-9, "nu {nu} t/R {t}: worst at x = {x}");
        assert!(
            w * 100.0 < pct + 0.1 && w * 100.0 > pct - 0.25,
            "nu {nu} t/R {t}: {:.2} % (seen {pct} %)",
            w * 100.0
        );
        let f = data.iter().find(|p| (p.0 - at).abs() < 1e-9).expect("x").1;
        assert_eq!(
            core.response(at).force < f,
            soft,
            "nu {nu} t/R {t}: the sign"
        );
    }
}

/// Session 23: the skin of t/R 0.4 at nu 0.48 on CAX8 elements (`tests/data/fe/core/cax8/`,
/// tools/fe/README.md "The skin squeezed against the core, on CAX8"), whose FE converges to
/// x = 0.34 (delta/t 0.85) where the CAX8R run of `core/force_nu0.48_t0.4.csv` stops at 0.28.
/// softgrip-fe does not embed it (it ends past the law's x_max, 0.8 t/R = 0.32); read here.
/// Seen (`tools/calibration/try_thin_skin_s23.py`): session 23's law within 0.96 % to x =
/// 0.28, as on the CAX8R curve (0.86 %), then too soft, by 3.07 % at x_max (delta/t 0.8): the
/// deep end of a nearly incompressible skin, which no FE constrained before. Session 24's law
/// (the squeezed skin's deviatoric stiffening, fitted with this curve): within 1.58 % to x =
/// 0.28 (at x = 0.15, as on the CAX8R curve: 1.55 % at 0.13) and 1.98 % at x_max, too stiff
/// there (+0.08 / +0.49 / +1.08 / +1.98 % at x 0.29-0.32; past x_max the form is +3.40 % and
/// +5.70 % at 0.33 and 0.34: the range is not extended). Tolerances: seen + 0.1 % above,
/// 0.25 % below, and the sign.
#[test]
fn core_at_the_deep_end_of_the_cax8_skin_is_what_the_readme_states() {
    let (nu, t) = (0.48, 0.4);
    let data = cax8(
        include_str!("../../../tests/data/fe/core/cax8/force_nu0.48_t0.4.csv"),
        nu,
    );
    assert!((data.last().expect("points").0 - 0.34).abs() < 1e-9);
    let core = law(Level::Calibrated, nu, Backing::Core { thickness: t });
    assert!((core.x_max() - 0.32).abs() < 1e-12);
    let (w, x) = worst(&core, &data, 0.28);
    eprintln!("to x = 0.28: {:.2} % at x = {x}", w * 100.0);
    assert!(
        w * 100.0 < 1.58 + 0.1 && w * 100.0 > 1.58 - 0.25,
        "{:.2} % at x = {x}",
        w * 100.0
    );
    let (w, x) = worst(&core, &data, core.x_max());
    eprintln!("to x_max: {:.2} % at x = {x}", w * 100.0);
    assert!((x - 0.32).abs() < 1e-9 && w * 100.0 < 1.98 + 0.1 && w * 100.0 > 1.98 - 0.25);
    let at = |x: f64| data.iter().find(|p| (p.0 - x).abs() < 1e-9).expect("x").1;
    assert!(
        core.response(0.32).force > at(0.32),
        "too stiff there, not too soft"
    );
}

/// Session 26: the deep CAX8 run at the other nu of the skins whose CAX8R runs stop at 0.67-0.8
/// t/R (`tests/data/fe/core/cax8/`, `fe_campaign.py` role `deep`; tools/fe/README.md "Deep skins
/// at other nu (session 26)"), blind (no constant saw them): nu 0.4 t/R 0.4 to x = 0.33
/// (delta/t 0.825; CAX8R 0.30), nu 0.3 t/R 0.4 to 0.32 (its elements collapse past it, as on
/// CAX8R), nu 0.45 t/R 0.5 to 0.43 (delta/t 0.86; CAX8R 0.39), nu 0.49 t/R 0.3 to 0.2 (Newton
/// fails there, as on CAX8R). Seen: the law's worst `|F/F_FE - 1|` to min(x_max, the FE's
/// reach), where, and its sign there; past x_max (`tools/calibration/CORE_FORM.md` "Session 26:
/// past 0.8 t/R") the form is +1.59 % at nu 0.4's x = 0.33 and +1.74 / +2.94 / +4.68 % at nu
/// 0.45's 0.41 / 0.42 / 0.43: the range is not extended. Tolerances: seen + 0.1 % above, 0.25 %
/// below, the place and the sign.
#[test]
fn core_on_the_deep_cax8_skins_at_other_nu_is_what_the_readme_states() {
    // (file, nu, t/R, FE reach, seen %, at x, law too soft there)
    let skins = [
        // nu 0.4 t/R 0.4: -1.85 % at x = 0.19 (the CAX8R curve's place); +0.47 % at x_max
        (
            include_str!("../../../tests/data/fe/core/cax8/force_nu0.4_t0.4.csv"),
            0.4,
            0.4,
            0.33,
            1.85,
            0.19,
            true,
        ),
        // nu 0.3 t/R 0.4: +2.42 % at x_max = 0.32, its end (the fitted CAX8R curve's)
        (
            include_str!("../../../tests/data/fe/core/cax8/force_nu0.3_t0.4.csv"),
            0.3,
            0.4,
            0.32,
            2.42,
            0.32,
            false,
        ),
        // nu 0.45 t/R 0.5: -2.40 % at x = 0.22 (the held-out CAX8R curve's); +0.88 % at x_max
        (
            include_str!("../../../tests/data/fe/core/cax8/force_nu0.45_t0.5.csv"),
            0.45,
            0.5,
            0.43,
            2.40,
            0.22,
            true,
        ),
        // nu 0.49 t/R 0.3: +2.49 % at its end x = 0.2 (the CAX8R curve +2.67 %)
        (
            include_str!("../../../tests/data/fe/core/cax8/force_nu0.49_t0.3.csv"),
            0.49,
            0.3,
            0.2,
            2.49,
            0.2,
            false,
        ),
    ];
    pin_skins(&skins, false);
}

/// Session 28: the two deep thin skins above re-run with penalty 1e6 and ~9 CAX8 elements
/// through the skin (`tests/data/fe/core/cax8/k1e6/`, `tools/fe/fe_thin_rerun.py --deep`; the
/// runs above, penalty 1e5, are soft by their penalty: 5.2 % at t/R 0.08's x = 0.04, 4.3 % at
/// t/R 0.1's x = 0.06), which reach further: x = 0.05 (delta/t 0.625) and 0.07 (0.7), inside the
/// law's range (0.8 t/R). Blind (no constant saw them). Session 28's law (SFB0030) was too
/// soft at both ends, by 6.29 % (t/R 0.08, x = 0.05) and 8.19 % (t/R 0.1, x = 0.07): the deep
/// squeeze of a thin, nearly incompressible skin is stiffer than its squeeze term. Session 29:
/// a third, held out (its CAX8R twin is): nu 0.49 t/R 0.12 to x = 0.095 (delta/t 0.79),
/// where SFB0030 was 5.16 % too soft (at x 0.095). Since session 29 the law is SFF, with the
/// squeezed film (softgrip-law README, "Session 29"), still blind to all three (fitted on the
/// fitted set only): too soft at both ends of the nu 0.48 skins, by 3.49 % (t/R 0.08, x =
/// 0.05) and 4.91 % (t/R 0.1, x = 0.07), past the 2 % target; too stiff on nu 0.49 t/R 0.12 by
/// 1.86 % at x = 0.0825 (+1.27 % at its end; within 1.86 % along it, where SFB0030 fell from +0.65 % to
/// -5.16 %). A fourth landed after SFF was chosen and ported, blind to all of it: nu 0.45 t/R
/// 0.07 to x = 0.045 (delta/t 0.64; within 0.31 % of its CAX8R twin to 0.0325): SFF is within
/// 1.71 % along it, too soft by that at its end (SFB0030 -2.23 %, session 27's law -4.18 %).
/// Tolerances: seen + 0.1 % above, 0.25 % below, the place and the sign.
#[test]
fn core_on_the_deep_thin_skins_with_penalty_1e6_is_what_the_readme_states() {
    let skins = [
        (
            include_str!("../../../tests/data/fe/core/cax8/k1e6/force_nu0.48_t0.08.csv"),
            0.48,
            0.08,
            0.05,
            3.49,
            0.05,
            true,
        ),
        (
            include_str!("../../../tests/data/fe/core/cax8/k1e6/force_nu0.48_t0.1.csv"),
            0.48,
            0.1,
            0.07,
            4.91,
            0.07,
            true,
        ),
        (
            include_str!("../../../tests/data/fe/core/cax8/k1e6/force_nu0.49_t0.12.csv"),
            0.49,
            0.12,
            0.095,
            1.86,
            0.0825,
            false,
        ),
        (
            include_str!("../../../tests/data/fe/core/cax8/k1e6/force_nu0.45_t0.07.csv"),
            0.45,
            0.07,
            0.045,
            1.71,
            0.045,
            true,
        ),
    ];
    pin_skins(&skins, true);
}

/// Session 23: thin skins at nu 0.48 on CAX8 (`tests/data/fe/core/cax8/`), blind (no constant
/// of the law saw them): t/R 0.1 (R/60, increments <= 0.001) to x = 0.06 (delta/t 0.6; session
/// 20's CAX8R run with increments <= 0.005 stopped at 0.04 and is 1.69 % stiffer there) and
/// t/R 0.08 (R/80, <= 0.0005) to x = 0.04 (delta/t 0.5; the CAX8R run with the same increments,
/// `core/force_nu0.48_t0.08.csv`, stopped at 0.0325 and agrees within 0.047 %). Seen
/// (`tools/calibration/try_thin_skin_s23.py`): session 23's law too soft, by 3.72 % at t/R
/// 0.1's end (x = 0.06) and by 2.67 % at t/R 0.08's first point (x = 0.01): past the 2 %
/// target. And the worst held-out skin of t/R >= 0.1, nu 0.46 t/R 0.25, on CAX8 one step past
/// its CAX8R end (x = 0.19, delta/t 0.76; the CAX8R curve 0.18, within 0.06 % of it for x
/// 0.02-0.18): 4.77 % too soft there (3.54 % at 0.18). Session 24's law (blind to all three):
/// 2.90 % too soft at t/R 0.1's end, 2.31 % too soft at t/R 0.08's first point, and on t/R
/// 0.25 2.18 % too stiff at x = 0.01 (within 1.35 % from x = 0.02; -0.91 % at 0.19).
/// Session 28's law (the thin-skin form SFB0030, faded out by t/R 0.3; blind to all three but
/// its fade's end, chosen after the deep set was seen): 1.23 % too soft at t/R 0.1's end,
/// 2.36 % too stiff at t/R 0.08's x = 0.03, 2.13 % too stiff on t/R 0.25 at x = 0.01.
/// Session 29's law (SFF, the squeezed film; blind to all three): 1.39 % too stiff at t/R
/// 0.1's end, 3.46 % too stiff at t/R 0.08's end (x = 0.04), 2.10 % too stiff on t/R 0.25 at x
/// = 0.01. The two thin ones are loosened by the new law's own numbers (re-pinned, sign
/// flipped at t/R 0.1): these penalty-1e5 runs are soft by their penalty, 5.2 % at t/R 0.08's
/// x = 0.04 and 4.3 % at t/R 0.1's x = 0.06 against their penalty-1e6 re-runs (the test
/// below), where SFF is 3.49 / 4.91 % too soft instead of 6.29 / 8.19 %: a law that meets the
/// deep squeeze is too stiff against these. Tolerances: seen + 0.1 % above, 0.25 % below, the
/// place and the sign.
#[test]
fn core_on_the_thin_cax8_skins_is_what_the_readme_states() {
    let skins = [
        (
            include_str!("../../../tests/data/fe/core/cax8/force_nu0.48_t0.1.csv"),
            0.48,
            0.1,
            0.06,
            1.39,
            0.06,
            false,
        ),
        (
            include_str!("../../../tests/data/fe/core/cax8/force_nu0.48_t0.08.csv"),
            0.48,
            0.08,
            0.04,
            3.46,
            0.04,
            false,
        ),
        (
            include_str!("../../../tests/data/fe/core/cax8/force_nu0.46_t0.25.csv"),
            0.46,
            0.25,
            0.19,
            2.10,
            0.01,
            false,
        ),
    ];
    pin_skins(&skins, true);
}

/// Session 25: thin skins re-run with the contact penalty 10x stiffer (1e6 MPa/mm) and about
/// 9 CAX8R elements through the skin (`tests/data/fe/core/k1e6/`, tools/fe/fe_thin_rerun.py;
/// tools/fe/README.md "Thin skins re-run (session 25)"): session 24 found the campaign's 1e5
/// MPa/mm leaves a thin skin 0.4-1.6 % soft. Each is the same skin as the committed
/// `core/force_nu{NU}_t{T}.csv` (but nu 0.48 t/R 0.05, fit data with no committed twin) and
/// keeps its role (fit data, held out or blind); twelve since session 25, five since 26; the law was
/// not refitted on them (no form tried in session 25 passed: tools/calibration/CORE_FORM.md
/// "Thin skins: session 25"). Seen (`tools/calibration/try_thin_skin_s25.py --new --curves
/// law`): the law's worst `|F/F_FE - 1|` to x_max, where, and its sign there. Since session 28
/// (the thin-skin form SFB0030, `tools/calibration/try_shell_table_s28.py --var SFB0030
/// --curves`, which prints the same numbers) the pinned values were its; since session 29 they
/// are SFF's (SFB0030 with the squeezed film, `tools/calibration/try_deep_squeeze_s29.py --var
/// SFB0030 SFF --curves`): each comment gives SFB0030's and session 27's law's in parentheses,
/// and the committed curves' numbers after it are session 27's law's. SFF is better than SFB0030
/// here by max (2.39 % against 2.88 %) and on 12 of the 17 skins; worse by more than 0.1 % on
/// four, each within 1.83 %: (0.3, 0.08) 0.70 -> 1.19, (0.3, 0.1) 0.86 -> 1.17, (0.4, 0.08)
/// 0.30 -> 0.56, (0.49, 0.12) 1.17 -> 1.83 (all at x <= 0.015, the small-x nu pattern, not
/// the squeeze); (0.35, 0.06) 0.56 -> 0.61. Tolerances: seen + 0.1 % above, 0.25 % below, the
/// place and the sign.
#[test]
fn core_on_the_penalty_1e6_thin_skins_is_what_the_readme_states() {
    // (file, nu, t/R, FE reach, seen %, at x, law too soft there)
    let skins = [
        // nu 0.35 t/R 0.06 (blind): -0.61 % at x = 0.01 (session 28's SFB0030 +0.56 % at 0.03; session 27's law +0.46 % at 0.0275; the committed
        // curve, to x = 0.03: +1.53 % at 0.03)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.35_t0.06.csv"),
            0.35,
            0.06,
            0.035,
            0.61,
            0.01,
            true,
        ),
        // nu 0.3 t/R 0.05 (fit data): -1.30 % at x = 0.03 (session 28's SFB0030 -1.69 % at 0.03; session 27's law -3.42 % at 0.01; the committed
        // curve, to x = 0.03: -3.32 % at 0.01)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.3_t0.05.csv"),
            0.3,
            0.05,
            0.035,
            1.30,
            0.03,
            true,
        ),
        // nu 0.3 t/R 0.08 (blind): -1.19 % at x = 0.0125 (session 28's SFB0030 -0.70 % at 0.05; session 27's law -2.35 % at 0.0125; the committed
        // curve, to x = 0.05: -2.07 % at 0.02)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.3_t0.08.csv"),
            0.3,
            0.08,
            0.055,
            1.19,
            0.0125,
            true,
        ),
        // nu 0.3 t/R 0.1 (fit data): -1.17 % at x = 0.015 (session 28's SFB0030 +0.86 % at 0.075; session 27's law -3.15 % at 0.075; the committed
        // curve, to x = 0.07: -1.70 % at 0.02)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.3_t0.1.csv"),
            0.3,
            0.1,
            0.075,
            1.17,
            0.015,
            true,
        ),
        // nu 0.45 t/R 0.07 (blind): -1.70 % at x = 0.0325 (session 28's SFB0030 -1.94 % at 0.0325; session 27's law +2.36 % at 0.015; the committed
        // curve, to x = 0.0275: +3.58 % at 0.0175)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.45_t0.07.csv"),
            0.45,
            0.07,
            0.0325,
            1.70,
            0.0325,
            true,
        ),
        // nu 0.48 t/R 0.06 (blind): -1.56 % at x = 0.025 (session 28's SFB0030 -2.16 % at 0.025; session 27's law -5.89 % at 0.025; the committed
        // curve, to x = 0.02: -1.18 % at 0.01)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.48_t0.06.csv"),
            0.48,
            0.06,
            0.025,
            1.56,
            0.025,
            true,
        ),
        // nu 0.48 t/R 0.08 (blind): -1.81 % at x = 0.0375 (session 28's SFB0030 -2.88 % at 0.0375; session 27's law -5.75 % at 0.0375; the committed
        // curve, to x = 0.0325: -2.35 % at 0.01)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.48_t0.08.csv"),
            0.48,
            0.08,
            0.0375,
            1.81,
            0.0375,
            true,
        ),
        // nu 0.48 t/R 0.1 (fit data): -1.45 % at x = 0.045 (session 28's SFB0030 -2.06 % at 0.045; session 27's law -4.04 % at 0.045; the committed
        // curve, to x = 0.04: -2.84 % at 0.01)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.48_t0.1.csv"),
            0.48,
            0.1,
            0.045,
            1.45,
            0.045,
            true,
        ),
        // nu 0.49 t/R 0.12 (held out): -1.83 % at x = 0.0125 (session 28's SFB0030 -1.17 % at 0.0125; session 27's law -3.70 % at 0.015; the committed
        // curve, to x = 0.05: -3.08 % at 0.01)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.49_t0.12.csv"),
            0.49,
            0.12,
            0.055,
            1.83,
            0.0125,
            true,
        ),
        // nu 0.4 t/R 0.05 (fit data): +1.48 % at x = 0.03 (session 28's SFB0030 +2.03 % at 0.03; session 27's law +3.02 % at 0.01; the committed
        // curve, to x = 0.025: +3.18 % at 0.01)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.4_t0.05.csv"),
            0.4,
            0.05,
            0.03,
            1.48,
            0.03,
            false,
        ),
        // nu 0.4 t/R 0.06 (blind): +0.98 % at x = 0.0325 (session 28's SFB0030 +1.21 % at 0.035; session 27's law +3.48 % at 0.01; the committed
        // curve, to x = 0.03: +3.80 % at 0.01)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.4_t0.06.csv"),
            0.4,
            0.06,
            0.035,
            0.98,
            0.0325,
            false,
        ),
        // nu 0.4 t/R 0.1 (fit data): -0.64 % at x = 0.0125 (session 28's SFB0030 -0.51 % at 0.065; session 27's law +2.84 % at 0.025; the committed
        // curve, to x = 0.06: +2.83 % at 0.02)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.4_t0.1.csv"),
            0.4,
            0.1,
            0.065,
            0.64,
            0.0125,
            true,
        ),
        // Session 26: the last five re-runs.
        // nu 0.4 t/R 0.08 (blind): -0.56 % at x = 0.0125 (session 28's SFB0030 +0.30 % at 0.0175; session 27's law +3.17 % at 0.0175; the committed
        // curve, to x = 0.04: +3.10 % at 0.02)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.4_t0.08.csv"),
            0.4,
            0.08,
            0.045,
            0.56,
            0.0125,
            true,
        ),
        // nu 0.46 t/R 0.1 (held out): -2.39 % at x = 0.045 (session 28's SFB0030 -2.63 % at 0.045; session 27's law -1.91 % at 0.045; the committed
        // curve, to x = 0.04: +1.62 % at 0.02)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.46_t0.1.csv"),
            0.46,
            0.1,
            0.045,
            2.39,
            0.045,
            true,
        ),
        // nu 0.38 t/R 0.12 (held out): -0.47 % at x = 0.0175 (session 28's SFB0030 +0.57 % at 0.0275; session 27's law +2.33 % at 0.0275; the committed
        // curve, to x = 0.08: +2.33 % at 0.03)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.38_t0.12.csv"),
            0.38,
            0.12,
            0.085,
            0.47,
            0.0175,
            true,
        ),
        // nu 0.32 t/R 0.14 (held out): +0.92 % at x = 0.105 (session 28's SFB0030 +0.83 % at 0.105; session 27's law -2.69 % at 0.105; the committed
        // curve, to x = 0.1: -1.53 % at 0.1)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.32_t0.14.csv"),
            0.32,
            0.14,
            0.105,
            0.92,
            0.105,
            false,
        ),
        // nu 0.48 t/R 0.05 (fit data; its only earlier run, R/120 with penalty
        // 1e5, stopped at x = 0.015 and was never committed): -1.55 % at x = 0.02 (session 28's SFB0030 -1.98 % at 0.02; session 27's law -6.21 % at 0.02)
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.48_t0.05.csv"),
            0.48,
            0.05,
            0.02,
            1.55,
            0.02,
            true,
        ),
        // Session 30: nu 0.47 t/R 0.15 (held out), the law's largest miss among the skins
        // never re-run (2.27 % at x 0.08 against its committed penalty-1e5 curve, which this
        // run exceeds by +0.11 to +0.34 %): -3.07 % at x = 0.085 (delta/t 0.57), this run's
        // end, past the committed curve's. Too soft in the deep squeeze, as the nu 0.48 deep
        // skins are (tools/calibration/CORE_FORM.md, session 29): the thin-skin form is faded
        // to 0.42 of its weight at t/R 0.15 and the law there is the thick skins'.
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.47_t0.15.csv"),
            0.47,
            0.15,
            0.085,
            3.07,
            0.085,
            true,
        ),
        // Session 30: the two held-out skins past 2 % at t/R 0.25-0.3 (the thin-skin form's
        // fade), re-run: each within 0.7 % of its committed twin (+0.69 % at x 0.01, then within
        // 0.5 %), so their misses are the law's. nu 0.42 t/R 0.25: -2.21 % at x = 0.185
        // (delta/t 0.74), too soft (committed: 2.13 %).
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.42_t0.25.csv"),
            0.42,
            0.25,
            0.185,
            2.21,
            0.185,
            true,
        ),
        // nu 0.49 t/R 0.3 (the law's own form, the thin-skin form's weight 0): +2.86 % at
        // x = 0.205 (delta/t 0.68), too stiff (committed: 2.67 %).
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.49_t0.3.csv"),
            0.49,
            0.3,
            0.205,
            2.86,
            0.205,
            false,
        ),
        // Session 30, blind: two skins at a nu and t/R no run had had, run after the law was
        // fixed (no form was chosen with them in view). nu 0.34 t/R 0.18, to x 0.145 (the end
        // of its load): +0.88 % at x = 0.0975, too stiff.
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.34_t0.18.csv"),
            0.34,
            0.18,
            0.145,
            0.88,
            0.0975,
            false,
        ),
        // nu 0.44 t/R 0.09, to x 0.0525 (diverged at 0.0545, delta/t 0.61): -1.99 % at its
        // end, too soft (the deep squeeze of the nearly incompressible thin skins).
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.44_t0.09.csv"),
            0.44,
            0.09,
            0.0525,
            1.99,
            0.0525,
            true,
        ),
        // Session 31, blind: nu 0.455 t/R 0.12 (no earlier run), inside the deep-squeeze miss,
        // run after the session's forms were judged (none adopted: tools/calibration/CORE_FORM.md,
        // session 31), to x 0.0725 (diverged at 0.073, delta/t 0.60): -3.90 % at its end, too
        // soft (within 2 % to x 0.05, delta/t 0.42: -1.83 %).
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.455_t0.12.csv"),
            0.455,
            0.12,
            0.0725,
            3.90,
            0.0725,
            true,
        ),
    ];
    pin_skins(&skins, false);
}

/// Session 32: six deep penalty-1e6 skins with no earlier run of their nu and t/R
/// (`tests/data/fe/core/k1e6/`, tools/fe/fe_thin_rerun.py, ~9 CAX8R elements through the skin,
/// to the law's x_max or where Newton failed), their roles declared before any form was tried:
/// fit data (of the forms tried in `tools/calibration/try_deep_fade_s32.py`, none adopted)
/// nu 0.46 and 0.48 at t/R 0.15, nu 0.47 and 0.45 at t/R 0.2, nu 0.48 at t/R 0.25; held out
/// nu 0.495 t/R 0.12, and its CAX8 twin (`core/cax8/k1e6/`, to delta/t 0.9, past x_max).
/// The law (SFF, which saw none of them; `try_deep_fade_s32.py --var SFF --curves`): too soft
/// in the deep squeeze at nu 0.45-0.47 (-4.64 % at nu 0.46 t/R 0.15's end, delta/t 0.65;
/// -3.99 % at nu 0.45 t/R 0.2's, 0.71), and too stiff at nu 0.495, by 3.08 % at the CAX8R
/// end (delta/t 0.48) and 9.90 % on CAX8 at x = 0.095 (delta/t 0.79, inside its range), where
/// nu 0.49 t/R 0.12 is within 1.86 % (tools/calibration/CORE_FORM.md, "Thin skins: deep fit
/// runs and a faded deep term, session 32"), and nu 0.499 t/R 0.12 on CAX8 +22.32 % at x = 0.095
/// ("nu 0.499 t/R 0.12 deep on CAX8"). Tolerances: seen + 0.1 % above, 0.25 % below, the place
/// and the sign.
#[test]
fn core_on_session_32s_deep_skins_is_what_the_readme_states() {
    // (file, nu, t/R, FE reach, seen %, at x, law too soft there)
    let skins = [
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.46_t0.15.csv"),
            0.46,
            0.15,
            0.0975,
            4.64,
            0.0975,
            true,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.48_t0.15.csv"),
            0.48,
            0.15,
            0.085,
            1.74,
            0.02,
            true,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.47_t0.2.csv"),
            0.47,
            0.2,
            0.135,
            2.75,
            0.135,
            true,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.45_t0.2.csv"),
            0.45,
            0.2,
            0.1425,
            3.99,
            0.1425,
            true,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.48_t0.25.csv"),
            0.48,
            0.25,
            0.185,
            1.30,
            0.185,
            false,
        ),
        (
            include_str!("../../../tests/data/fe/core/k1e6/force_nu0.495_t0.12.csv"),
            0.495,
            0.12,
            0.0575,
            3.08,
            0.0575,
            false,
        ),
    ];
    pin_skins(&skins, true);
    // The CAX8 twin of nu 0.495 t/R 0.12 reaches x = 0.1075, past x_max (0.096): pinned to x_max;
    // nu 0.499 t/R 0.12 on CAX8 (no CAX8R run; held out, run after the session's forms were
    // judged) reaches x = 0.0975: +22.32 % at x = 0.095 (delta/t 0.79). Session 33's nu 0.497
    // t/R 0.15 on CAX8 (no CAX8R run; declared held out before any form was tried on it) reaches
    // x = 0.1375, past x_max (0.12): +12.99 % at x_max (delta/t 0.8; CORE_FORM.md "Thin skins:
    // the film towards nu 0.5, session 33").
    pin_skins(
        &[
            (
                include_str!("../../../tests/data/fe/core/cax8/k1e6/force_nu0.495_t0.12.csv"),
                0.495,
                0.12,
                0.1075,
                9.90,
                0.095,
                false,
            ),
            (
                include_str!("../../../tests/data/fe/core/cax8/k1e6/force_nu0.499_t0.12.csv"),
                0.499,
                0.12,
                0.0975,
                22.32,
                0.095,
                false,
            ),
            (
                include_str!("../../../tests/data/fe/core/cax8/k1e6/force_nu0.497_t0.15.csv"),
                0.497,
                0.15,
                0.1375,
                12.99,
                0.12,
                false,
            ),
        ],
        false,
    );
}

/// Session 34: two held-out deep CAX8 skins (`tests/data/fe/core/cax8/k1e6/`,
/// `tools/fe/fe_thin_rerun.py --deep`, penalty 1e6, ~9 elements through the skin; no CAX8R run),
/// declared with the film attenuation Hm4's predictions before they were run
/// (`tools/calibration/hm4_predictions_s34.md`): nu 0.4925 t/R 0.12 to x = 0.0975 (delta/t 0.81)
/// and nu 0.497 t/R 0.2 to x = 0.19 (delta/t 0.95), both past x_max. The law (SFF, unchanged:
/// Hm4 met the declared rule on the first, 2.28 %, not on the second, +4.80 % at delta/t 0.8,
/// and was not ported; CORE_FORM.md "Thin skins: Hm4 against two new held-out deep skins,
/// session 34") is too stiff at both deep ends: +4.93 % at x = 0.095 (delta/t 0.79) and +10.09 %
/// at x_max = 0.16 (delta/t 0.8). Tolerances: seen + 0.1 % above, 0.25 % below, the place and
/// the sign.
#[test]
fn core_on_session_34s_held_out_deep_skins_is_what_the_readme_states() {
    pin_skins(
        &[
            (
                include_str!("../../../tests/data/fe/core/cax8/k1e6/force_nu0.4925_t0.12.csv"),
                0.4925,
                0.12,
                0.0975,
                4.93,
                0.095,
                false,
            ),
            (
                include_str!("../../../tests/data/fe/core/cax8/k1e6/force_nu0.497_t0.2.csv"),
                0.497,
                0.2,
                0.19,
                10.09,
                0.16,
                false,
            ),
        ],
        false,
    );
}

/// Issue 24 item 5: the core's validity reaches the FE's. Every committed FE core curve (the 14
/// fitted, the 18 held out with session 20's two t/R 0.08 skins, session 15's five, and session
/// 20's five t/R 0.05-0.1 fit-data skins) lies inside the law's range to its
/// last converged point, or to the flat construction's x_max where that comes first (nu 0.499 t/R 0.6: FE 0.47, flat 0.44; nu
/// 0.35 t/R 0.7: FE 0.50, flat 0.495), and the issue's two marks hold at every nu the level
/// takes: x = 0.22 at t/R 0.3 (FE: 0.23 at nu 0.4, 0.20 at 0.49) and 0.38 at t/R 0.5 (FE: 0.39
/// at nu 0.45). Before session 10 the law stopped at 0.6 t/R: 0.18 and 0.30.
#[test]
fn core_validity_reaches_the_fe_reach() {
    let mut files = 0;
    for f in softgrip_fe::all().filter(|f| f.path.starts_with("core/force_nu")) {
        let (nu, t) = (f.nu.expect("nu"), f.thickness_ratio.expect("t/R"));
        let reach = fe(f.path).last().expect("points").0;
        let core = law(Level::Calibrated, nu, Backing::Core { thickness: t });
        let flat = law(Level::Calibrated, nu, Backing::Flat);
        let want = reach.min(flat.x_max());
        assert!(
            core.x_max() >= want - 1e-9,
            "{}: x_max {} < {want}",
            f.path,
            core.x_max()
        );
        files += 1;
    }
    assert_eq!(files, 47);
    for j in 0..=20 {
        let nu = 0.3 + 0.01 * f64::from(j);
        for (t, x) in [(0.3, 0.22), (0.5, 0.38)] {
            let core = law(Level::Calibrated, nu, Backing::Core { thickness: t });
            assert!(core.x_max() >= x, "nu {nu} t/R {t}: x_max {}", core.x_max());
        }
    }
}

#[test]
fn the_published_levels_with_a_backing_are_the_free_sphere_s() {
    for level in [
        Level::Hertz,
        Level::fit(),
        Level::Incompressible,
        Level::Tatara,
    ] {
        let free = law(level, 0.45, Backing::Free);
        for b in [Backing::Flat, Backing::Core { thickness: 0.4 }] {
            let backed = law(level, 0.45, b);
            assert_eq!(
                backed.response(0.2).force,
                free.response(0.2).force,
                "{level} {b}"
            );
        }
    }
}

/// Every backing and a spread of nu and t/R, including values not in the FE data.
fn every_backed_law() -> Vec<(f64, Backing, ContactLaw)> {
    let mut out = Vec::new();
    for nu in [0.3, 0.33, 0.35, 0.42, 0.47, 0.49, 0.499, 0.5] {
        let mut backings = vec![Backing::Free, Backing::Flat];
        backings.extend([0.05, 0.2, 0.3, 0.5, 0.7, 0.95].map(|t| Backing::Core { thickness: t }));
        for b in backings {
            out.push((nu, b, law(Level::Calibrated, nu, b)));
        }
    }
    out
}

#[test]
fn every_backing_is_zero_at_contact_monotone_finite_and_passive() {
    for (nu, b, law) in every_backed_law() {
        assert_eq!(law.response(0.0).force, 0.0);
        let n = 400;
        let mut prev = 0.0;
        for i in 1..=n {
            let x = law.x_max() * f64::from(i) / f64::from(n);
            let r = law.response(x);
            assert_eq!(r.regime, Regime::Valid);
            assert!(
                r.force.is_finite() && r.stiffness.is_finite(),
                "nu {nu} {b} x {x}"
            );
            assert!(
                r.force > prev && r.stiffness > 0.0,
                "nu {nu} {b} x {x}: {r:?}"
            );
            let patch = law.patch(x);
            assert!(
                patch.radius > 0.0 && patch.radius.is_finite(),
                "nu {nu} {b} x {x}"
            );
            prev = r.force;
        }
    }
}

#[test]
fn every_backing_s_stiffness_is_the_derivative_and_energy_the_integral() {
    for (nu, b, law) in every_backed_law() {
        let x_max = law.x_max();
        for i in 1..10 {
            let x = x_max * f64::from(i) / 10.0;
            let h = 1e-6 * x_max;
            let fd = (law.response(x + h).force - law.response(x - h).force) / (2.0 * h);
            let k = law.response(x).stiffness;
            assert!(
                (fd / k - 1.0).abs() < 1e-6,
                "nu {nu} {b} x {x}: {fd} vs {k}"
            );
            // Energy against a fine midpoint rule of the force.
            let m = 20_000;
            let w: f64 = (0..m)
                .map(|j| law.response(x * (f64::from(j) + 0.5) / f64::from(m)).force)
                .sum::<f64>()
                * x
                / f64::from(m);
            assert!((law.energy(x) / w - 1.0).abs() < 1e-6, "nu {nu} {b} x {x}");
        }
    }
}

#[test]
fn every_backing_s_inverse_round_trips() {
    for (nu, b, law) in every_backed_law() {
        for frac in [1e-4, 0.01, 0.3, 0.77, 1.0] {
            let f = law.force_max() * frac;
            let d = law.compression_for_force(f).expect("in range");
            let back = law.response(d).force;
            assert!((back / f - 1.0).abs() < 1e-9, "nu {nu} {b} F {f}: {back}");
        }
    }
}

#[test]
fn core_tends_to_flat_as_the_core_vanishes() {
    for nu in [0.3, 0.45, 0.49] {
        let flat = law(Level::Calibrated, nu, Backing::Flat);
        let core = law(Level::Calibrated, nu, Backing::Core { thickness: 0.999 });
        for x in [0.01, 0.1, 0.3] {
            let r = core.response(x).force / flat.response(x).force - 1.0;
            assert!(r.abs() < 1e-4, "nu {nu} x {x}: {r:e}");
        }
    }
}

#[test]
fn auto_with_a_backing_stays_within_its_tolerance_of_that_backing_s_calibrated() {
    for b in [Backing::Flat, Backing::Core { thickness: 0.5 }] {
        for nu in [0.3, 0.45, 0.49] {
            let auto = law(Level::auto(), nu, b);
            let cal = law(Level::Calibrated, nu, b);
            assert_eq!(auto.x_max(), cal.x_max());
            for i in 1..500 {
                let x = cal.x_max() * (f64::from(i) + 0.2937) / 500.5;
                let r = auto.response(x).force / cal.response(x).force - 1.0;
                assert!(r.abs() <= 0.01, "{b} nu {nu} x {x}: {r:e}");
            }
            assert_eq!(auto.kind_at(0.1), LevelKind::Calibrated);
        }
    }
}

#[test]
fn a_backed_fingertip_below_nu_0_3_is_a_typed_error() {
    let p = ContactParams::try_from_parts(1.0, 1.0, 0.25)
        .and_then(|p| p.with_backing(Backing::Flat))
        .expect("valid params");
    let err = ContactLaw::try_new(p, Level::Calibrated).unwrap_err();
    assert!(
        matches!(err, Error::IncompatibleLevel { nu, .. } if nu == 0.25),
        "{err}"
    );
    assert!(err.to_string().contains("0.3 <= nu <= 0.5"), "{err}");
    // The free sphere's levels still build there.
    assert!(ContactLaw::try_new(p, Level::Hertz).is_ok());
}

#[test]
fn combining_a_backed_body_is_a_typed_error() {
    let free = ContactParams::try_from_parts(1e6, 0.01, 0.49).expect("valid");
    let core = free
        .with_backing(Backing::Core { thickness: 0.003 })
        .expect("valid");
    let err = ContactParams::try_combine_params(&core, &free).unwrap_err();
    assert_eq!(
        err,
        Error::IncompatibleBacking {
            first: "core",
            second: "free"
        }
    );
    assert!(
        err.to_string()
            .contains("only two `free` soft bodies combine")
    );
    for t in [0.0, -1e-3, 0.01, 0.02, f64::NAN, f64::INFINITY] {
        let e = free
            .with_backing(Backing::Core { thickness: t })
            .unwrap_err();
        assert!(e.to_string().contains("`thickness` must be"), "{t}: {e}");
    }
}

macro_rules! pressure_files {
    ($($g:literal, $nu:literal, $x:literal);* $(;)?) => {
        [$(($g, $nu, $x, include_str!(concat!("../../../tests/data/fe/", $g, "/pressure_nu", $nu, "_d", $x, ".csv")))),*]
    };
}

#[test]
fn pressure_follows_the_fe_profile_for_free_and_flat() {
    let files = pressure_files!(
        "free", "0.3", "0.1"; "free", "0.3", "0.3"; "free", "0.3", "0.5";
        "free", "0.4", "0.1"; "free", "0.4", "0.3"; "free", "0.4", "0.5";
        "free", "0.45", "0.1"; "free", "0.45", "0.3"; "free", "0.45", "0.5";
        "free", "0.49", "0.1"; "free", "0.49", "0.3"; "free", "0.49", "0.5";
        "flat", "0.3", "0.1"; "flat", "0.3", "0.3"; "flat", "0.3", "0.5";
        "flat", "0.4", "0.1"; "flat", "0.4", "0.3";
        "flat", "0.48", "0.1"; "flat", "0.48", "0.3";
        "flat", "0.499", "0.1"; "flat", "0.499", "0.3";
        "flat", "0.35", "0.1"; "flat", "0.35", "0.3"; "flat", "0.35", "0.5";
        "flat", "0.45", "0.1"; "flat", "0.45", "0.3";
    );
    for (g, nu, x, text) in files {
        let (nu, x): (f64, f64) = (nu.parse().expect("nu"), x.parse().expect("x"));
        let backing = if g == "flat" {
            Backing::Flat
        } else {
            Backing::Free
        };
        let law = law(Level::Calibrated, nu, backing);
        let patch = law.patch(x);
        let fe = profile(text, nu);
        let fe_peak = fe.iter().fold(0.0_f64, |m, p| m.max(p.1));
        let a_fe = fe.last().expect("rows").0;
        // Target 5 %. Seen (radius and shapes refitted to the FE radius without a_lin's lag;
        // `tests/radius_pressure.rs` asserts each profile): peak within 2.6 % (free) and 3.0 %
        // (flat; 3.4 % at nu 0.35 x 0.5, past its x_max); the profile within 2.7 % and 4.7 %.
        let peak = patch.peak_pressure / fe_peak - 1.0;
        assert!(
            peak.abs() < 0.04,
            "{g} nu {nu} x {x}: peak {:.2} %",
            peak * 100.0
        );
        let worst = fe
            .iter()
            .filter(|p| p.0 <= 0.8 * a_fe)
            .map(|&(r, p)| (patch.pressure_at(r) - p).abs() / fe_peak)
            .fold(0.0_f64, f64::max);
        assert!(
            worst < 0.05,
            "{g} nu {nu} x {x}: profile {:.2} %",
            worst * 100.0
        );
    }
}

#[test]
fn torsion_limit_comes_from_the_profile() {
    // mu F a (m + 1) B(3/2, m + 1): 3 pi/16 for Hertz's shape, larger for a flatter patch.
    let law = law(Level::Calibrated, 0.49, Backing::Flat);
    let patch = law.patch(0.1);
    assert!(patch.shape < 0.5, "{}", patch.shape);
    let f = law.response(0.1).force;
    let t = patch.torsion_limit(0.8, f) / (0.8 * f * patch.radius);
    // Numerical integral of r p(r) 2 pi r dr / (F a).
    let n = 20_000;
    let a = patch.radius;
    let num: f64 = (0..n)
        .map(|i| {
            let r = (f64::from(i) + 0.5) / f64::from(n) * a;
            patch.pressure_at(r) * r * 2.0 * std::f64::consts::PI * r * a / f64::from(n)
        })
        .sum::<f64>()
        / (f * a);
    assert!((t / num - 1.0).abs() < 1e-4, "{t} vs {num}");
    assert!(t > 3.0 * std::f64::consts::PI / 16.0, "{t}");
}

mod properties {
    //! Property tests of the backed constructions over random materials, radii and (for `Core`)
    //! skin thicknesses 0.2 R < t < 0.8 R, nu in [0.3, 0.5): F(0) = 0, finite and monotone over
    //! the validity range, stiffness = the derivative (central differences), energy = the
    //! integral (midpoint quadrature), and the inverse round trip.

    use proptest::prelude::*;
    use softgrip_law::{Backing, ContactLaw, ContactParams, Level, Material, Regime};

    fn backed_law() -> impl Strategy<Value = (ContactLaw, Backing)> {
        (
            1e4f64..1e8,
            0.3f64..0.5,
            1e-3f64..0.05,
            prop_oneof![Just(None), (0.2f64..0.8).prop_map(Some)],
        )
            .prop_map(|(e, nu, r, t)| {
                let backing = match t {
                    None => Backing::Flat,
                    Some(t) => Backing::Core { thickness: t * r },
                };
                let p = ContactParams::try_new(Material::try_new(e, nu).expect("material"), r)
                    .and_then(|p| p.with_backing(backing))
                    .expect("valid params");
                (
                    ContactLaw::try_new(p, Level::Calibrated).expect("builds"),
                    backing,
                )
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]

        #[test]
        fn zero_at_contact_finite_and_monotone((law, b) in backed_law(), a in 0.0f64..1.0, c in 0.0f64..1.0) {
            prop_assert_eq!(law.response(0.0).force, 0.0);
            let (lo, hi) = if a < c { (a, c) } else { (c, a) };
            let d_max = law.delta_max();
            let (r0, r1) = (law.response(lo * d_max), law.response(hi * d_max));
            prop_assert!(r0.force.is_finite() && r1.force.is_finite() && r1.stiffness.is_finite(), "{b}");
            prop_assert!(r1.force >= r0.force, "{b}: F({lo}) = {} > F({hi}) = {}", r0.force, r1.force);
            prop_assert!(r1.stiffness > 0.0 || hi == 0.0, "{b}: {r1:?}");
            if hi > 0.0 {
                prop_assert_eq!(r1.regime, Regime::Valid);
            }
        }

        #[test]
        fn stiffness_is_the_derivative_and_energy_the_integral((law, b) in backed_law(), f in 0.02f64..0.98) {
            let d_max = law.delta_max();
            let d = f * d_max;
            let h = 1e-6 * d_max;
            let fd = (law.response(d + h).force - law.response(d - h).force) / (2.0 * h);
            let k = law.response(d).stiffness;
            prop_assert!((fd / k - 1.0).abs() < 1e-5, "{b} delta {d}: {fd} vs {k}");
            let m = 20_000;
            let w: f64 = (0..m)
                .map(|j| law.response(d * (f64::from(j) + 0.5) / f64::from(m)).force)
                .sum::<f64>()
                * d
                / f64::from(m);
            prop_assert!((law.energy(d) / w - 1.0).abs() < 1e-6, "{b} delta {d}: {} vs {w}", law.energy(d));
        }

        #[test]
        fn inverse_round_trips((law, b) in backed_law(), f in 1e-4f64..1.0) {
            let force = f * law.force_max();
            let d = law.compression_for_force(force).expect("in range");
            let back = law.response(d).force;
            prop_assert!((back / force - 1.0).abs() < 1e-9, "{b} F {force}: {back}");
        }
    }
}
