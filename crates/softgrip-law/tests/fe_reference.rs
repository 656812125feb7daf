//! Every level against the independent finite-element reference (`tests/data/fe/`, CalculiX,
//! R = 1 mm, mu = 1 MPa; see its README). Each assertion states what the data show, with its
//! tolerance; the numbers in the comments are what the current code gives.

mod common;

use common::normalised;
use softgrip_law::fitting::{Sample, fit_material};
use softgrip_law::{ContactLaw, Level};

/// `(x, f = F/(E* R^2), a/R)` of one embedded FE file (`softgrip-fe`), normalised with
/// E* = 2 mu (1+nu)/(1-nu^2), mu = 1 MPa.
fn fe(path: &str) -> Vec<(f64, f64, f64)> {
    softgrip_fe::file(path)
        .expect("embedded FE file")
        .points()
        .expect("FE file parses")
        .into_iter()
        .map(|p| (p.x, p.force_norm, p.radius_norm))
        .collect()
}

fn data(nu: f64) -> Vec<(f64, f64, f64)> {
    if nu == 0.3 {
        // force_nu0.3 stops at x = 0.61; full_nu0.3 has the converged points to 0.85 (the
        // material collapses past ~0.65): take 0.62..0.65 from it for the 0.65 target.
        let mut d = fe("force_nu0.3.csv");
        let full = fe("full_nu0.3.csv");
        d.extend(full.into_iter().filter(|p| p.0 > 0.615 && p.0 < 0.655));
        d
    } else {
        fe("force_nu0.49.csv")
    }
}

/// Signed force error `F_level / F_FE - 1` at every FE point with `lo <= x <= hi`.
fn force_errors(law: &ContactLaw, nu: f64, lo: f64, hi: f64) -> Vec<(f64, f64)> {
    data(nu)
        .into_iter()
        .filter(|p| p.0 >= lo - 1e-9 && p.0 <= hi + 1e-9)
        .map(|(x, f, _)| (x, law.response(x).force / f - 1.0))
        .collect()
}

fn max_abs(errors: &[(f64, f64)]) -> f64 {
    errors.iter().fold(0.0_f64, |m, e| m.max(e.1.abs()))
}

fn error_at(law: &ContactLaw, nu: f64, x: f64) -> f64 {
    force_errors(law, nu, x, x)[0].1
}

#[test]
fn calibrated_force_is_within_2_percent_to_x_0_65() {
    for nu in [0.3, 0.49] {
        let law = normalised(Level::Calibrated, nu);
        let worst = max_abs(&force_errors(&law, nu, 0.01, 0.65));
        // Target 2 %; seen 0.52 % at both nu. Assert 1 % to catch a regression early.
        assert!(
            worst < 0.01,
            "nu={nu}: calibrated worst {:.2} %",
            worst * 100.0
        );
    }
}

#[test]
fn calibrated_radius_is_within_3_percent() {
    for nu in [0.3, 0.49] {
        let law = normalised(Level::Calibrated, nu);
        for (x, _, a) in data(nu)
            .into_iter()
            .filter(|p| p.0 >= 0.1 && p.0 <= 0.5 + 1e-9)
        {
            let err = law.patch(x).radius / a - 1.0;
            // Against the raw radius column: seen 3.57 % (nu 0.3), 1.87 % (0.49). The column is
            // step noise and lags the edge by half an element (R/60: 0.8 % of R); against the FE
            // radius without them the law is within 1.07 % and 2.64 % for 0.1 <= x <= 0.4
            // (`tests/radius_pressure.rs`, which asserts the 3 % target).
            assert!(
                err.abs() < 0.038,
                "nu={nu} x={x}: radius error {:.2} %",
                err * 100.0
            );
        }
    }
}

#[test]
fn calibrated_captures_the_finite_size_excess_at_small_x() {
    //! FE / Hertz grows like 1 + c sqrt(x) at small x; every published level misses it.
    let small_x = softgrip_fe::file("small_x_check.csv").expect("embedded");
    for p in small_x.points().expect("FE file parses") {
        let (nu, x, f) = (p.nu, p.x, p.force_norm);
        let cal = normalised(Level::Calibrated, nu).response(x).force / f - 1.0;
        let fit = normalised(Level::fit(), nu).response(x).force / f - 1.0;
        // Seen: calibrated within 0.71 %, chi_L 1.2-3.2 % low (the FE jitters by ~0.5 %).
        assert!(
            cal.abs() < 0.01,
            "nu={nu} x={x}: calibrated {:.2} %",
            cal * 100.0
        );
        assert!(fit < -0.005, "nu={nu} x={x}: chi_L {:.2} %", fit * 100.0);
    }
}

#[test]
fn paper_fit_is_within_5_percent_to_x_0_5_and_drifts_beyond() {
    for nu in [0.3, 0.49] {
        let law = normalised(Level::fit(), nu);
        let worst = max_abs(&force_errors(&law, nu, 0.01, 0.5));
        // The paper's claim (Eq. 38 within 5 %): seen 4.82 % (nu = 0.3), 4.34 % (nu = 0.49).
        assert!(worst < 0.05, "nu={nu}: chi_L worst {:.2} %", worst * 100.0);
    }
    // MODEL.md: +7 % at x = 0.6 and +12 % at 0.65 for nu = 0.3; -4.5 % at 0.65, -8 % at 0.75
    // for nu = 0.49.
    let fit = |nu| normalised(Level::fit(), nu);
    for (nu, x, want) in [
        (0.3, 0.6, 0.07),
        (0.3, 0.65, 0.12),
        (0.49, 0.65, -0.045),
        (0.49, 0.75, -0.08),
    ] {
        let got = error_at(&fit(nu), nu, x);
        assert!(
            (got - want).abs() < 0.01,
            "nu={nu} x={x}: chi_L {:.2} %",
            got * 100.0
        );
    }
}

#[test]
fn hertz_underestimates_by_30_percent_at_0_3_and_half_at_0_5() {
    for nu in [0.3, 0.49] {
        let law = normalised(Level::Hertz, nu);
        // FE / Hertz - 1: more than 30 % at x = 0.3 and more than 100 % at x = 0.5.
        let over = |x| 1.0 / (1.0 + error_at(&law, nu, x)) - 1.0;
        assert!(
            over(0.3) > 0.30,
            "nu={nu}: FE/Hertz at 0.3 = {}",
            1.0 + over(0.3)
        );
        assert!(
            over(0.5) > 1.00,
            "nu={nu}: FE/Hertz at 0.5 = {}",
            1.0 + over(0.5)
        );
    }
}

#[test]
fn full_theory_is_within_6_5_percent_to_x_0_5() {
    // Seen: 5.22 % (nu = 0.3: -3.3 % at x = 0.01 from the finite size it ignores, -5.2 % at
    // x = 0.55) and 6.13 % (nu = 0.49: +6.1 % at x = 0.5; the uniaxial bar overestimates the
    // stiffening of the confined contact zone). See the crate README.
    for nu in [0.3, 0.49] {
        for level in [Level::NeoHookean, Level::NeoHookeanExact] {
            let law = normalised(level, nu);
            let worst = max_abs(&force_errors(&law, nu, 0.01, 0.5));
            assert!(
                worst < 0.065,
                "nu={nu} {level}: worst {:.2} %",
                worst * 100.0
            );
        }
    }
    // The radius of Eq. 25 (full theory): within 4.5 % on 0.1..0.5 (seen 2.23 %, 3.95 %).
    for nu in [0.3, 0.49] {
        let law = normalised(Level::NeoHookean, nu);
        for (x, _, a) in data(nu)
            .into_iter()
            .filter(|p| p.0 >= 0.1 && p.0 <= 0.5 + 1e-9)
        {
            assert!(
                (law.patch(x).radius / a - 1.0).abs() < 0.045,
                "nu={nu} x={x}"
            );
        }
    }
}

#[test]
fn incompressible_law_is_within_8_percent_to_x_0_5() {
    // chi_IC ignores compressibility: seen +7.63 % at nu = 0.3 and +6.02 % at nu = 0.49.
    for (nu, tol) in [(0.3, 0.08), (0.49, 0.065)] {
        let law = normalised(Level::Incompressible, nu);
        let worst = max_abs(&force_errors(&law, nu, 0.01, 0.5));
        assert!(worst < tol, "nu={nu}: worst {:.2} %", worst * 100.0);
    }
}

#[test]
fn tatara_is_above_fe_at_small_x_and_far_below_at_large_x() {
    // The paper reports Tatara's model above experiment at large compression; that is his full
    // model with a strain-dependent modulus. The extended-Hertz form of MODEL.md (constant
    // modulus) has the Boussinesq finite-size term but no lateral area growth: seen +2.8 % /
    // +9.5 % at x = 0.1 (nu = 0.3 / 0.49), -27.5 % / -21.9 % at x = 0.5. See the crate README.
    for nu in [0.3, 0.49] {
        let law = normalised(Level::Tatara, nu);
        assert!(
            error_at(&law, nu, 0.1) > 0.02,
            "nu={nu}: {}",
            error_at(&law, nu, 0.1)
        );
        assert!(
            error_at(&law, nu, 0.5) < -0.2,
            "nu={nu}: {}",
            error_at(&law, nu, 0.5)
        );
    }
}

#[test]
fn auto_stays_within_its_tolerance_of_calibrated() {
    for nu in [0.3, 0.4, 0.49] {
        for tolerance in [0.005, 0.01, 0.05] {
            let auto = normalised(Level::Auto { tolerance }, nu);
            let full = normalised(Level::Calibrated, nu);
            for x in common::grid(auto.x_max(), 500) {
                let r = auto.response(x).force / full.response(x).force - 1.0;
                assert!(r.abs() <= tolerance, "nu={nu} tol={tolerance} x={x}: {r:e}");
            }
        }
    }
    // At 5 % it uses the cheaper levels where they are within 2.5 % of calibrated.
    let auto = normalised(Level::Auto { tolerance: 0.05 }, 0.49);
    let kinds: Vec<_> = auto.auto_segments().into_iter().map(|s| s.1).collect();
    assert!(kinds.contains(&softgrip_law::LevelKind::Fit), "{kinds:?}");
}

#[test]
fn material_fit_as_the_paper_does_it() {
    // The paper's procedure: Hertz on x <= 0.1, then predict the rest. On FE data Hertz
    // inflates E* by the finite-size excess it lacks (seen +15.7 % at nu = 0.3, +12.5 % at 0.49);
    // fitting with the calibrated level recovers E* (seen within 0.22 %).
    for (nu, lo, hi) in [(0.3, 1.12, 1.20), (0.49, 1.08, 1.15)] {
        let e_star = 2.0 * (1.0 + nu) / (1.0 - nu * nu) * 1e6; // Pa
        let r = 1e-3;
        let samples: Vec<_> = data(nu)
            .into_iter()
            .map(|(x, f, _)| Sample {
                delta: x * r,
                force: f * e_star * r * r,
            })
            .collect();
        let paper = fit_material(&samples, r, nu, 0.1, Level::Hertz).expect("fits");
        let ratio = paper.material.effective_modulus() / e_star;
        assert!(
            ratio > lo && ratio < hi,
            "nu={nu}: Hertz-fitted E*/E* = {ratio}"
        );
        let ours = fit_material(&samples, r, nu, 0.1, Level::Calibrated).expect("fits");
        let ratio = ours.material.effective_modulus() / e_star;
        assert!(
            (ratio - 1.0).abs() < 0.01,
            "nu={nu}: calibrated-fitted E*/E* = {ratio}"
        );
        let cal = ours
            .residuals
            .iter()
            .find(|l| l.level == Level::Calibrated)
            .expect("calibrated");
        let hertz = ours
            .residuals
            .iter()
            .find(|l| l.level == Level::Hertz)
            .expect("hertz");
        assert!(
            cal.max_abs_error < 0.015,
            "calibrated residual {}",
            cal.max_abs_error
        );
        assert!(
            hertz.max_abs_error > 0.5,
            "hertz residual {}",
            hertz.max_abs_error
        );
    }
}
