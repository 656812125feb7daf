//! A skin on a rigid core pressed on a rigid ball, against softgrip's FE of it
//! (`tests/data/fe/ball/core/`, `tools/fe`, session 11: t/R 0.3 and 0.5 at nu 0.48 on balls of
//! R and 3R; sessions 12-14: t/R 0.3-0.45 at nu 0.3-0.48 on balls of R to 3R; sessions 16-17:
//! t/R 0.4-0.6 at nu 0.43-0.49 on balls of 0.6 R to 2R): force per curve against the number this test prints, with the 3 % as the
//! ceiling, and the law's range against the FE's reach. Session 18: the same skin on cylinders
//! and the right-angle edge (`tests/data/fe/{cylinder,edge}/core/`, the 3D quarter model, held
//! out of every fit), force per curve against the number this test printed when they landed
//! (`SOFTGRIP_PRINT_CURVES=1` prints each point).
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
/// when the law was fixed (session 17: the wrapped cap, `core_map`, a geometric coefficient,
/// and `chi_flat` continued past its range in the squeeze excess, `ChiForm::flat_continued`;
/// the confined skin's share `w` refitted on its one curve), rounded up by 0.2 % (so a real
/// change of the law breaks it). One constant of the map is fitted, on one curve
/// (`force_nu0.3_t0.4_k2.csv`, the confined skin's share `w`, 0.0276 -> 0.018246 in session 17);
/// the others saw none (`core_map`: the plane law at Hertz's patch, the bonded pad's squeeze
/// excess at the skin's `delta/t`, the cap's area). In the comments the numbers of session 12,
/// of session 14 before the bonded pad's refit, of session 14, and of session 16 (the last
/// before session 17).
fn stated_force_error(path: &str) -> f64 {
    let pct = match path {
        "ball/core/force_nu0.48_t0.3_k1.csv" => 2.27, // 2.42, 2.42, 2.35, 2.43; session 21 (the thin-layer floor's refit, `w` 0.026): was 2.50; session 24 (the squeezed skin's deviatoric stiffening): was 2.21
        "ball/core/force_nu0.48_t0.3_k3.csv" => 1.92, // 3.74, 3.83, 2.60, 2.62; session 21 (the thin-layer floor's refit, `w` 0.026): was 2.49; session 24 (the squeezed skin's deviatoric stiffening): was 2.90
        "ball/core/force_nu0.48_t0.4_k2.csv" => 1.49, // 1.44, 1.44, 1.48, 1.42; session 21 (the thin-layer floor's refit, `w` 0.026): was 1.43; session 24 (the squeezed skin's deviatoric stiffening): was 1.49
        // Session 15-16's miss (4.65 / 4.19 % too soft at its end, x = 0.38, delta/t 0.76).
        "ball/core/force_nu0.48_t0.5_k1.csv" => 2.94, // 3.26, 3.19, 4.65, 4.19; session 21 (the thin-layer floor's refit, `w` 0.026): was 2.67; session 24 (the squeezed skin's deviatoric stiffening): was 2.07
        "ball/core/force_nu0.48_t0.5_k3.csv" => 2.70, // 2.73, 2.82, 1.20, 1.26; session 21 (the thin-layer floor's refit, `w` 0.026): was 1.53; session 24 (the squeezed skin's deviatoric stiffening): was 1.76
        // Session 13, held out of the constant (the confined skin's form was chosen with them
        // in view): the first cores on a ball away from nu = 0.48, at their FE's ends 3.35 %,
        // 10.38 % and 6.57 % too soft with session 12's map (delta/t 0.77, 0.8, 0.77).
        "ball/core/force_nu0.4_t0.35_k1.5.csv" => 1.17, // -, 0.98, 0.79, 0.70; session 21 (the thin-layer floor's refit, `w` 0.026): was 1.03; session 24 (the squeezed skin's deviatoric stiffening): was 1.67
        "ball/core/force_nu0.33_t0.45_k3.csv" => 1.14, // -, 1.07, 2.20, 2.35; session 21 (the thin-layer floor's refit, `w` 0.026): was 1.50; session 24 (the squeezed skin's deviatoric stiffening): was 1.17
        "ball/core/force_nu0.36_t0.3_k1.csv" => 2.37, // -, 1.66, 1.85, 1.99; session 21 (the thin-layer floor's refit, `w` 0.026): was 2.04; session 24 (the squeezed skin's deviatoric stiffening): was 2.50
        // Session 14, the confined skin's constant fitted on it (14.02 % too soft at its end,
        // x = 0.32, delta/t 0.8, with session 12's map).
        "ball/core/force_nu0.3_t0.4_k2.csv" => 2.37, // -, 0.95, 2.28, 2.32; session 21 (the thin-layer floor's refit, `w` 0.026): was 2.32; session 24 (the squeezed skin's deviatoric stiffening): was 2.08
        // Session 14, blind (run after w was first fitted): nu 0.4, t/R 0.5 on 3R (1.29 %
        // without the confined skin), and nu 0.3, t/R 0.5 on R (9.23 % too soft at its end
        // without it).
        "ball/core/force_nu0.4_t0.5_k3.csv" => 2.11, // -, 2.22, 1.94, 1.87; session 21 (the thin-layer floor's refit, `w` 0.026): was 1.27; session 24 (the squeezed skin's deviatoric stiffening): was 1.58
        "ball/core/force_nu0.3_t0.5_k1.csv" => 2.74, // -, 2.39, 1.38, 1.63; session 21 (the thin-layer floor's refit, `w` 0.026): was 2.32; session 24 (the squeezed skin's deviatoric stiffening): was 2.54
        // Session 16, blind (`fe_campaign.py`'s `held16`): nu 0.47, t/R 0.5 on 0.7 R, 5.67 %
        // with session 14's map, 5.00 % too soft at its end (x = 0.37, delta/t 0.74) with
        // session 16's; the wrapped cap was chosen with it (and the miss above) in view.
        "ball/core/force_nu0.47_t0.5_k0.7.csv" => 2.50, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 2.71; session 24 (the squeezed skin's deviatoric stiffening): was 2.01
        // ... and nu 0.49, t/R 0.45 on 1.5 R (session 14's map: 1.93 %, session 16's 1.71 %).
        "ball/core/force_nu0.49_t0.45_k1.5.csv" => 1.60, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 1.33; session 24 (the squeezed skin's deviatoric stiffening): was 1.65
        // Session 17, blind to the wrapped cap (`fe_campaign.py`'s session-17 cases, run before
        // it was chosen, looked at after it was committed): nu 0.46, t/R 0.55 on 0.6 R (session
        // 16's law 4.06 %, too soft at its end, x = 0.40, delta/t 0.73) ...
        "ball/core/force_nu0.46_t0.55_k0.6.csv" => 1.98, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 1.77; session 24 (the squeezed skin's deviatoric stiffening): was 2.04
        // ... nu 0.49, t/R 0.4 on 0.8 R (1.76 %; the FE diverged at x = 0.24, delta/t 0.6) ...
        "ball/core/force_nu0.49_t0.4_k0.8.csv" => 2.41, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 1.97; session 24 (the squeezed skin's deviatoric stiffening): was 2.45
        // ... and two thick skins on larger balls, too stiff at depth with session 16's law
        // and with the wrapped cap alone (3.04 / 3.44 % at delta/t 0.8; 5.53 / 5.61 % at 0.75):
        // the continuation of chi_flat was chosen on them (not blind to it).
        "ball/core/force_nu0.43_t0.6_k2.csv" => 1.68, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 2.37; session 24 (the squeezed skin's deviatoric stiffening): was 2.21
        "ball/core/force_nu0.48_t0.65_k4.csv" => 2.04, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 2.58; session 24 (the squeezed skin's deviatoric stiffening): was 2.39
        // Session 17, blind to the continuation (launched before it was fixed, looked at after
        // it was committed): nu 0.45, t/R 0.6 on 3R (session 16's law 4.29 %, too stiff at
        // delta/t 0.8) and nu 0.42, t/R 0.5 on 1.5 R (1.47 %).
        "ball/core/force_nu0.45_t0.6_k3.csv" => 1.35, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 2.15; session 24 (the squeezed skin's deviatoric stiffening): was 1.97
        "ball/core/force_nu0.42_t0.5_k1.5.csv" => 1.66, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 1.20; session 24 (the squeezed skin's deviatoric stiffening): was 0.99
        // A curve that landed after: the target.
        _ => 2.8,
    };
    (pct + 0.2) / 100.0
}

#[test]
fn a_skin_on_a_core_on_a_ball_is_within_its_stated_error_of_the_fe() {
    // Every curve is printed before any is asserted (one run shows them all).
    let mut missed = Vec::new();
    let mut seen = 0;
    for file in curves() {
        let law = law_of(file);
        let (err, top) = force_error(file, &law, f64::INFINITY);
        let points = file.points().expect("parses");
        let fe_end = points.last().expect("points").x;
        // Where the worst error is and its sign (+: the law too stiff).
        let (x_worst, signed) = points
            .iter()
            .filter(|p| p.x >= 0.01 - 1e-12 && p.x <= law.x_max())
            .map(|p| (p.x, law.response(p.x).force / p.force_norm - 1.0))
            .fold(
                (0.0, 0.0),
                |w, e| if e.1.abs() > f64::abs(w.1) { e } else { w },
            );
        println!(
            "{:38} force within {:5.2} % for 0.01 <= x <= {top:.2} ({:+.2} % at x = {x_worst}; law's x_max {:.3}, FE's end {fe_end})",
            file.path,
            100.0 * err,
            100.0 * signed,
            law.x_max()
        );
        // Every curve within the 3 % to its FE's end (session 17: the misses of
        // sessions 15-16, 4.19 % and 5.00 %, are 2.67 % and 2.71 %; the blind thick skins on
        // 2R and 4R, 3.44 % and 5.61 % with the wrapped cap alone, 2.37 % and 2.58 %).
        if !(err <= stated_force_error(file.path) && err < 0.03) {
            missed.push(format!("{}: {:.2} %", file.path, 100.0 * err));
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
    assert!(missed.is_empty(), "{missed:#?}");
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
        let tolerance = stated_radius_error(file.path);
        assert!(worst < tolerance, "{}: {:.2} %", file.path, 100.0 * worst);
        seen += 1;
    }
    assert!(seen >= 5, "{seen} curves");
}

/// The largest radius error each curve is allowed for `0.1 <= x <= min(0.4, x_max, FE's
/// end)`: what this test printed when the core's patch took a thin incompressible layer's
/// shrink (session 17, `core_map`, the patch's edge: `1 - (a_H/R2)^2 (R_eff/R2)/12`, theory, no
/// constant), rounded up by 0.2 % and capped at the 3 %. In the comments: before it
/// (sessions 15-17, no shrink; with Sneddon's half-space shrink, session 14, the compressible
/// skins were 3.00-4.52 %).
fn stated_radius_error(path: &str) -> f64 {
    let pct: f64 = match path {
        "ball/core/force_nu0.33_t0.45_k3.csv" => 2.85, // 2.58
        "ball/core/force_nu0.36_t0.3_k1.csv" => 2.89,  // 2.23
        // Narrow at its end (x = 0.31): the worst since the shrink.
        "ball/core/force_nu0.3_t0.4_k2.csv" => 3.00, // 2.68 (2.81)
        "ball/core/force_nu0.3_t0.5_k1.csv" => 2.26, // 1.32
        "ball/core/force_nu0.42_t0.5_k1.5.csv" => 1.38, // 0.93
        "ball/core/force_nu0.43_t0.6_k2.csv" => 1.42, // 1.18
        "ball/core/force_nu0.45_t0.6_k3.csv" => 1.35, // 1.13
        // Session 17's blind run, too wide at its end (x = 0.40, (a_H/R2)^2 = 0.42) without
        // the shrink: the 3 % missed.
        "ball/core/force_nu0.46_t0.55_k0.6.csv" => 2.48, // 4.55
        "ball/core/force_nu0.47_t0.5_k0.7.csv" => 1.73,  // 2.94
        "ball/core/force_nu0.48_t0.3_k1.csv" => 2.09,    // 1.48
        "ball/core/force_nu0.48_t0.3_k3.csv" => 2.45,    // 2.22
        "ball/core/force_nu0.48_t0.4_k2.csv" => 2.48,    // 2.15
        "ball/core/force_nu0.48_t0.5_k1.csv" => 1.85,    // 1.44
        "ball/core/force_nu0.48_t0.5_k3.csv" => 2.32,    // 2.11
        "ball/core/force_nu0.48_t0.65_k4.csv" => 1.97,   // 1.76
        "ball/core/force_nu0.49_t0.45_k1.5.csv" => 2.59, // 2.21
        "ball/core/force_nu0.49_t0.4_k0.8.csv" => 1.11,  // 0.59
        "ball/core/force_nu0.4_t0.35_k1.5.csv" => 1.82,  // 1.45
        "ball/core/force_nu0.4_t0.5_k3.csv" => 1.42,     // 1.15
        other => panic!("{other}: no stated radius error (run with --nocapture and state it)"),
    };
    pct / 100.0
}

/// The FE of the core curve the law missed until session 17 (nu 0.48, t/R 0.5 on R, 4.19 % at
/// x = 0.38; 2.67 % since session 17) is converged where it missed (session 15, `fe_campaign.py` role `conv-reach`: R/60 against
/// the campaign's R/40, to x = 0.36 where the R/60 run diverged): the two meshes' forces agree
/// within 0.13 % at every x, so the miss is the law's, not the mesh's.
#[test]
fn the_missed_core_curve_is_mesh_converged_to_its_end() {
    let rows = common::ball_mesh_convergence("core", 0.48, 1.0);
    let (worst, end) = common::mesh_convergence_summary(&rows);
    println!("core nu 0.48 t/R 0.5 on R: R/40 vs R/60 within {worst:.3} % to x = {end}");
    assert!(rows.len() >= 30, "{} rows", rows.len());
    assert!(end >= 0.36 - 1e-9, "to x = {end}");
    assert!(worst <= 0.15, "{worst} %");
}

/// The calibrated core law (E* = 1 Pa, R = 1 m) of a 3D file's t/R and Poisson ratio on its
/// cylinder or edge.
fn law_3d_of(file: &FeFile) -> ContactLaw {
    let nu = file.nu.expect("a Poisson ratio");
    let thickness = file.thickness_ratio.expect("a core file has t/R");
    let cp = match file.counterpart {
        FeCounterpart::Cylinder { k } => Counterpart::try_cylinder(k).expect("a cylinder"),
        FeCounterpart::Edge => Counterpart::EDGE,
        other => panic!("{}: a 3D core file on {other:?}", file.path),
    };
    let p = ContactParams::try_from_parts(1.0, 1.0, nu)
        .and_then(|p| p.with_backing(Backing::Core { thickness }))
        .expect("valid params");
    ContactLaw::try_new(p, Level::Calibrated)
        .and_then(|l| l.with_counterpart(cp))
        .expect("the law binds")
}

/// The largest force error each 3D curve (session 18: the skin on a core on a cylinder or
/// the edge, 3D quarter model, held out of every fit: no constant of the law saw a core on
/// anything but a plane or a ball) is allowed to the FE's end: what this test printed when
/// the curves landed, rounded up by 0.2 %, so a real change of the law breaks it.
fn stated_force_error_3d(path: &str) -> f64 {
    let pct: f64 = match path {
        // Within 0.7 % to x = 0.15, then too stiff, growing to its FE's end (x = 0.26,
        // delta/t 0.65): the 3 % just met.
        // Session 22: the ellipse's thin-layer factor (CORE_FORM.md, "Cylinders: session 22";
        // not adopted) takes it to 1.00 %, t/R 0.5 on R 2.21 -> 1.36 %, but 3R 3.29 -> 3.80 %.
        // Session 24 (the plane form's deviatoric stiffening of the squeezed skin, fitted on
        // plane curves only: blind here): +2.44 % at x = 0.25, 3R -2.68 % at 0.32; with the
        // ellipse's factor too, 1.07 % and 3.20 % (CORE_FORM.md, "Session 24").
        "cylinder/core/force_nu0.48_t0.4_k1.csv" => 2.44, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 2.99; session 24 (the squeezed skin's deviatoric stiffening): was 3.56
        // Too soft by up to 1.88 % at x = 0.1, then within 0.7 % to x = 0.29, then too soft
        // again at the law's x_max (0.32, short of the FE's end 0.34): the 3 % met.
        "cylinder/core/force_nu0.48_t0.4_k3.csv" => 2.68, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 2.92; session 24 (the squeezed skin's deviatoric stiffening): was 3.29
        // t/R 0.5 on R (to x = 0.36, delta/t 0.72): within 0.6 % to x = 0.23, +1.98 % at 0.32.
        "cylinder/core/force_nu0.48_t0.5_k1.csv" => 1.19, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 1.98; session 24 (the squeezed skin's deviatoric stiffening): was 2.21
        // ... and on 3R (to x = 0.37): too soft by up to 1.51 % at x = 0.15.
        "cylinder/core/force_nu0.48_t0.5_k3.csv" => 2.04, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 1.51; session 24 (the squeezed skin's deviatoric stiffening): was 1.39
        // The edge (session 18, issue 24 item 2's 10 %), through the core's own form since
        // session 18's `core_map` edge (the plane core law at the edge's patch argument rho_H
        // x, rho_H = h^2 = 0.204, times the bonded pad's edge squeeze excess at the squeeze the
        // ridge's narrow patch feels, lambda = b/t with Sneddon's b = (2/pi) delta; no constant
        // fitted, the form chosen with both curves in view). Before it (the bonded pad's edge
        // map over the core's plane curve): +25.49 % at x = 0.13 (t/R 0.4) and +13.45 % at
        // x = 0.09 (t/R 0.5), the core stiffening the narrow patch as much as on a plane.
        // t/R 0.4 (to x = 0.21): -3.90 % at x = 0.01, +4.03 % at 0.06, -1.90 % at its end.
        "edge/core/force_nu0.48_t0.4.csv" => 4.16, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 4.03; session 24 (the squeezed skin's deviatoric stiffening): was 4.15
        // t/R 0.5 (to x = 0.35): -3.89 % at x = 0.01 (the 3D mesh's first point, +2 % stiff
        // against the axisymmetric FE on the plane), +3.62 % at 0.06, -2.20 % at 0.30.
        "edge/core/force_nu0.48_t0.5.csv" => 3.88, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 3.89; session 24 (the squeezed skin's deviatoric stiffening): was 3.88
        // Blind for that form (run after it was merged, end of session 18, nu 0.4 t/R 0.45, to
        // x = 0.19 where the 3D FE diverged): too soft by 8.03 % at its last point. Session 19
        // (the edge's form at the edge FE's nu 0.48 for every skin, `core_map`, the edge's
        // Poisson ratio; chosen with this curve in view): -3.98 % at x = 0.01 (the 3D mesh's
        // first point), +2.9 % at 0.06, -3.1 % at its end.
        "edge/core/force_nu0.4_t0.45.csv" => 3.97, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 3.98; session 24 (the squeezed skin's deviatoric stiffening): was 3.98
        // The other three blind cases of that batch (session 19; run with the law of session
        // 18, no constant or form changed for them). A cylinder of 2R (an R2/R in no core
        // data) at nu 0.42, t/R 0.45, to x = 0.36 where the 3D FE diverged: -1.37 % at x =
        // 0.01, too soft by up to 1.54 % at 0.13, +1.20 % at 0.27, -0.89 % at the end; the
        // issue's 3 % met.
        "cylinder/core/force_nu0.42_t0.45_k2.csv" => 1.74, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 1.54; session 24 (the squeezed skin's deviatoric stiffening): was 1.32
        // The edge at nu 0.45, t/R 0.6 (to x = 0.33, diverged): -4.06 % at x = 0.01 (the 3D
        // mesh's first point, as on the nu 0.48 curves), +2.60 % at 0.06, -3.82 % at its end;
        // the 10 % met. Session 19 (the edge at nu 0.48, as above): -3.82 % at x =
        // 0.01, +3.2 % at 0.06, -1.5 % at its end.
        "edge/core/force_nu0.45_t0.6.csv" => 3.81, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 3.82; session 24 (the squeezed skin's deviatoric stiffening): was 3.81
        // The edge at nu 0.3, t/R 0.5 (to x = 0.17, diverged): missed the 10 %. Too
        // soft everywhere, -0.74 % at x = 0.03 growing steadily to -5.64 % at 0.10 and
        // -11.56 % at the FE's last point. At x = 0.17 the blind edges read -0.94 % (nu 0.45,
        // t/R 0.6), -6.81 % (nu 0.4, t/R 0.45) and -11.56 % (nu 0.3): the law on the edge
        // grows too soft with x on the compressible skins (each run has its own t/R, so nu and
        // t/R are not separated; the felt squeeze's form was chosen on nu 0.48 alone).
        // Session 19 (the edge's whole form at the edge FE's nu 0.48 for every skin: a strip's
        // force per E* does not depend on nu, `core_map`, the edge's Poisson ratio; chosen with
        // this curve in view, no longer blind): -3.55 % at x = 0.01, +2.3 % at 0.03, -3.3 % at
        // its end (the FE's compressible skin stiffer than the law there); the 10 % met.
        "edge/core/force_nu0.3_t0.5.csv" => 3.54, // session 21 (the thin-layer floor's refit, `w` 0.026); before: 3.55; session 24 (the squeezed skin's deviatoric stiffening): was 3.54
        other => panic!("{other}: no stated error (run with --nocapture and state it)"),
    };
    (pct + 0.2) / 100.0
}

#[test]
fn a_skin_on_a_core_on_a_cylinder_or_an_edge_is_within_its_stated_error_of_the_fe() {
    let mut seen = 0;
    for file in CORE_COUNTERPART_FILES
        .iter()
        .filter(|f| f.schema == Schema::Force3d)
    {
        let law = law_3d_of(file);
        let (err, top) = force_error(file, &law, f64::INFINITY);
        let plane = ContactLaw::try_new(*law.params(), Level::Calibrated).expect("binds");
        let (plane_err, _) = force_error(file, &plane, f64::INFINITY);
        let points = file.points().expect("parses");
        let fe_end = points.last().expect("points").x;
        // Where the worst error is and its sign (+: the law too stiff).
        let (x_worst, signed) = points
            .iter()
            .filter(|p| p.x >= 0.01 - 1e-12 && p.x <= law.x_max())
            .map(|p| (p.x, law.response(p.x).force / p.force_norm - 1.0))
            .fold(
                (0.0, 0.0),
                |w, e| if e.1.abs() > f64::abs(w.1) { e } else { w },
            );
        println!(
            "{:40} force within {:5.2} % for 0.01 <= x <= {top:.2} ({:+.2} % at x = {x_worst}; as a plane: {:.0} %; law's x_max {:.3}, FE's end {fe_end})",
            file.path,
            100.0 * err,
            100.0 * signed,
            100.0 * plane_err,
            law.x_max()
        );
        if std::env::var_os("SOFTGRIP_PRINT_CURVES").is_some() {
            for p in points.iter().filter(|p| p.x <= law.x_max()) {
                let f = law.response(p.x).force;
                println!(
                    "  x {:.2} fe {:.6} law {:.6} {:+.2} %",
                    p.x,
                    p.force_norm,
                    f,
                    100.0 * (f / p.force_norm - 1.0)
                );
            }
        }
        assert!(
            err <= stated_force_error_3d(file.path),
            "{}: {:.2} %",
            file.path,
            100.0 * err
        );
        seen += 1;
    }
    assert!(seen >= 1, "{seen} curves");
}
