//! The law's contact-patch semi-axes on a cylinder against the 3D FE on the finer mesh (issue 24
//! item 2: "semi-axes within 5 %"), per point, through the reading that validates on the plane.
//!
//! The data (`tests/data/fe/cylinder/flat/axes_*_n40.csv`, written by `tools/fe/fe_campaign.py
//! export`, role `axes`; `tools/calibration/AXES_R40.md`): the flat pad at nu = 0.48, 3D quarter
//! model, element edge R/40 at the pole, to x = 0.3, once on the cylinder R2 = R and once on a
//! plane. A semi-axis read from the last surface node in contact (or from the gap's edge fit
//! through the first open nodes) only ever lags the true edge, by up to one node spacing: the
//! raw columns are a saw-tooth 3.5-18 % deep. Their upper envelope (fit `a/sqrt(x)` as a
//! quadratic in `sqrt(x)` on x >= 0.05, keep the points on or above it, refit; the files'
//! `envelope_*` columns) is the reading compared:
//!
//! 1. the test recomputes the envelope from the raw columns and finds the stored one (the
//!    comparisons below evaluate it between the rows too: 0.02 apart past x = 0.2);
//! 2. on the plane the envelope is checked against the axisymmetric R/40 run's radius
//!    (`flat/force_nu0.48.csv`, smoothed plus half an element, as `radius_pressure.rs`) at
//!    x = 0.10, 0.11, ..., 0.30 — where the reading is validated;
//! 3. over the same x the law's semi-axes (across and along the cylinder) are within 5 % of the
//!    cylinder's envelope, and within their measured worst plus 0.2 %.
//!
//! UNVERIFIED here: convergence beyond R/40 (the across semi-axis moved 6-10 % from R/20 to
//! R/40), other cylinders (R2/R != 1), other nu, the free fingertip, and x > 0.3.
//!
//! `cargo test -p softgrip-law --test cylinder_axes_r40 -- --nocapture` prints every number.

mod common;

use common::Smooth;
use softgrip_law::{Backing, ContactLaw, ContactParams, Counterpart, Level};

/// The flat pad on the cylinder R2 = R, R/40 at the pole.
const CYLINDER_K1: &str =
    include_str!("../../../tests/data/fe/cylinder/flat/axes_nu0.48_k1_n40.csv");
/// The same pad and mesh on a plane.
/// Session 20: the same pad and mesh on the cylinder R2 = 3R, run after the claim was made on
/// R2 = R (blind: nothing was chosen with it in view).
const CYLINDER_K3: &str =
    include_str!("../../../tests/data/fe/cylinder/flat/axes_nu0.48_k3_n40.csv");
const PLANE: &str = include_str!("../../../tests/data/fe/cylinder/flat/axes_nu0.48_plane_n40.csv");

/// The four semi-axis readings of a file: (raw column, its envelope column, name).
const COLUMNS: [(&str, &str, &str); 4] = [
    ("semi_axis_across_mm", "envelope_across_mm", "across"),
    ("semi_axis_along_mm", "envelope_along_mm", "along"),
    (
        "semi_axis_across_32_mm",
        "envelope_across_32_mm",
        "across, edge fit",
    ),
    (
        "semi_axis_along_32_mm",
        "envelope_along_32_mm",
        "along, edge fit",
    ),
];

/// Where the envelope is validated on the plane and compared on the cylinder: x = 0.10..0.30.
fn grid() -> impl Iterator<Item = f64> {
    (0..=20).map(|i| 0.1 + 0.01 * f64::from(i))
}

/// An `axes_*.csv` file: its x column and every named column (R = 1 mm: a [mm] is a/R).
struct AxesFile {
    x: Vec<f64>,
    header: Vec<String>,
    rows: Vec<Vec<f64>>,
}

impl AxesFile {
    fn parse(text: &str) -> Self {
        let mut lines = text.lines().filter(|l| !l.starts_with('#'));
        let header: Vec<String> = lines
            .next()
            .expect("a header")
            .split(',')
            .map(str::to_owned)
            .collect();
        assert_eq!(header[0], "delta_over_R");
        let rows: Vec<Vec<f64>> = lines
            .map(|l| {
                l.split(',')
                    .map(|v| v.parse::<f64>().expect("a number"))
                    .collect()
            })
            .collect();
        assert!(rows.iter().all(|r| r.len() == header.len()));
        Self {
            x: rows.iter().map(|r| r[0]).collect(),
            header,
            rows,
        }
    }

    fn column(&self, name: &str) -> Vec<f64> {
        let i = self
            .header
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("no column {name}"));
        self.rows.iter().map(|r| r[i]).collect()
    }
}

/// Least squares `y/sqrt(x) = c0 + c1 s + c2 s^2`, `s = sqrt(x)`, over the points given.
fn fit_sqrt(pts: &[(f64, f64)]) -> [f64; 3] {
    let mut m = [[0.0; 4]; 3];
    for &(x, y) in pts {
        let s = x.sqrt();
        for (i, row) in m.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate().take(3) {
                *v += s.powi((i + j) as i32);
            }
            row[3] += s.powi(i as i32) * y / s;
        }
    }
    for c in 0..3 {
        let p = (c..3)
            .max_by(|&a, &b| m[a][c].abs().total_cmp(&m[b][c].abs()))
            .expect("rows");
        m.swap(c, p);
        let pivot = m[c];
        for (r, row) in m.iter_mut().enumerate() {
            if r != c {
                let k = row[c] / pivot[c];
                for (v, pv) in row.iter_mut().zip(&pivot).skip(c) {
                    *v -= k * pv;
                }
            }
        }
    }
    [m[0][3] / m[0][0], m[1][3] / m[1][1], m[2][3] / m[2][2]]
}

fn eval(c: &[f64; 3], x: f64) -> f64 {
    let s = x.sqrt();
    s * (c[0] + c[1] * s + c[2] * s * s)
}

/// The upper envelope of a raw semi-axis column (`fe_campaign.py`'s `axes_envelope`): the fit
/// on x >= 0.05, the points on or above it refitted once. Returns the fit and the points kept.
fn envelope(x: &[f64], y: &[f64]) -> ([f64; 3], usize) {
    let pts: Vec<(f64, f64)> = x
        .iter()
        .zip(y)
        .filter(|(x, y)| **x >= 0.05 - 1e-9 && y.is_finite())
        .map(|(x, y)| (*x, *y))
        .collect();
    let first = fit_sqrt(&pts);
    let kept: Vec<(f64, f64)> = pts
        .into_iter()
        .filter(|&(x, y)| y >= eval(&first, x) * (1.0 - 1e-9))
        .collect();
    (fit_sqrt(&kept), kept.len())
}

/// The calibrated flat pad (E* = 1 Pa, R = 1 m) at nu = 0.48 on a cylinder of radius K R.
fn flat_on_cylinder(k: f64) -> ContactLaw {
    let p = ContactParams::try_from_parts(1.0, 1.0, 0.48)
        .and_then(|p| p.with_backing(Backing::Flat))
        .expect("valid params");
    ContactLaw::try_new(p, Level::Calibrated)
        .and_then(|l| l.with_counterpart(Counterpart::try_cylinder(k).expect("k > 0")))
        .expect("the law binds")
}

#[test]
fn the_stored_envelope_is_the_reading_of_the_stored_columns() {
    for (name, text) in [
        ("cylinder k = 1", CYLINDER_K1),
        ("cylinder k = 3", CYLINDER_K3),
        ("plane", PLANE),
    ] {
        let f = AxesFile::parse(text);
        for (raw, env, what) in COLUMNS {
            let (c, kept) = envelope(&f.x, &f.column(raw));
            let stored = f.column(env);
            let mut worst: f64 = 0.0;
            for (x, s) in f.x.iter().zip(&stored) {
                if *x < 0.05 - 1e-9 {
                    assert!(s.is_nan(), "{name} {what}: no envelope below x = 0.05");
                } else {
                    worst = worst.max((eval(&c, *x) / s - 1.0).abs());
                }
            }
            println!("{name:14} {what:17}: {kept} points kept, stored within {worst:.1e}");
            // The file's 6 significant digits.
            assert!(worst < 1e-5, "{name} {what}: {worst:e}");
            // The envelope keeps the upper half or so of the saw-tooth (a third to two thirds of
            // the 22 points at x >= 0.05; 13 on the cylinder of 3R), never one or two points.
            assert!((8..=14).contains(&kept), "{name} {what}: {kept} points");
        }
    }
}

/// Each column's measured worst |envelope / axisymmetric - 1| on the plane, x = 0.10..0.30 [%]
/// (the envelope reads low: across -2.20..-0.84, along -2.42..-0.85, edge fits -1.28..-0.00
/// and -1.55..-0.01 %; R/20's envelope read it 2.9-8.0 % low and does not validate), rounded
/// up to 0.1 %; the test allows 0.2 % more.
const PLANE_STATED: [f64; 4] = [2.2, 2.5, 1.3, 1.6];

#[test]
fn the_envelope_reads_the_plane_within_its_stated_error_of_the_axisymmetric_radius() {
    let axi = softgrip_fe::file("flat/force_nu0.48.csv")
        .expect("embedded")
        .points()
        .expect("parses");
    let axi: Vec<(f64, f64, f64)> = axi.iter().map(|p| (p.x, 0.0, p.radius_norm)).collect();
    let smooth = Smooth::fit(&axi);
    let lag = 0.485 / 40.0;
    let f = AxesFile::parse(PLANE);
    for ((raw, _, what), stated) in COLUMNS.iter().zip(PLANE_STATED) {
        let (c, _) = envelope(&f.x, &f.column(raw));
        let (lo, hi) = grid()
            .map(|x| eval(&c, x) / (smooth.at(x) + lag) - 1.0)
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), e| {
                (lo.min(e), hi.max(e))
            });
        println!(
            "plane {what:17}: envelope / axisymmetric - 1 = {:+.2} .. {:+.2} %",
            100.0 * lo,
            100.0 * hi
        );
        let worst = lo.abs().max(hi.abs());
        assert!(
            worst <= (stated + 0.2) / 100.0 && worst < 0.03,
            "plane {what}: {:.2} %",
            100.0 * worst
        );
    }
}

/// The law's measured worst |law / envelope - 1| on the cylinder R2 = R, x = 0.10..0.30 [%],
/// rounded up to 0.1 % (the test allows 0.2 % more): across +2.78..+3.98, along +1.11..+4.41,
/// against the edge-fit envelopes -0.59..+3.48 and +0.06..+0.84 % (the law on the wide side, about
/// as much as the envelope reads the plane low).
const CYLINDER_K1_STATED: [f64; 4] = [4.0, 4.5, 3.5, 0.9];

/// The same on the cylinder R2 = 3R (session 20, blind: run after the K = 1 claim and its
/// tolerances were set), rounded up to 0.1 %: across +0.46..+2.91, along +2.14..+3.31, against
/// the edge-fit envelopes -0.69..-0.06 and -0.55..+2.88 %.
const CYLINDER_K3_STATED: [f64; 4] = [3.0, 3.4, 0.7, 2.9];

#[test]
fn cylinder_semi_axes_are_within_five_percent_of_the_r40_envelope() {
    for (k, text, stated) in [
        (1.0, CYLINDER_K1, CYLINDER_K1_STATED),
        (3.0, CYLINDER_K3, CYLINDER_K3_STATED),
    ] {
        let law = flat_on_cylinder(k);
        assert!(law.x_max() > 0.3, "the law ends at {}", law.x_max());
        let f = AxesFile::parse(text);
        for ((raw, _, what), stated) in COLUMNS.iter().zip(stated) {
            let (c, _) = envelope(&f.x, &f.column(raw));
            let along = what.starts_with("along");
            let (lo, hi) = grid()
                .map(|x| {
                    let p = law.patch(x);
                    // The cylinder's first principal direction is its axis (curvature 0).
                    let l = if along { p.radius } else { p.radius2 };
                    l / eval(&c, x) - 1.0
                })
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), e| {
                    (lo.min(e), hi.max(e))
                });
            println!(
                "cylinder k = {k} {what:17}: law / envelope - 1 = {:+.2} .. {:+.2} %",
                100.0 * lo,
                100.0 * hi
            );
            let worst = lo.abs().max(hi.abs());
            assert!(
                worst <= (stated + 0.2) / 100.0 && worst < 0.05,
                "cylinder k = {k} {what}: {:.2} %",
                100.0 * worst
            );
        }
    }
}

/// The R/40 run's force against the campaign's R/20 export of the same case
/// (`cylinder/flat/force_nu0.48_k1.csv`): the mesh moved the semi-axes by up to 22 % per raw
/// point but the force by 1.10 % at x = 0.01 and at most 0.43 % from x = 0.05 (R/40 below R/20
/// at every x); and the law's force against the R/40 run.
#[test]
fn the_r40_force_agrees_with_the_r20_campaign_and_the_law() {
    let r20 = softgrip_fe::file("cylinder/flat/force_nu0.48_k1.csv")
        .expect("embedded")
        .points()
        .expect("parses");
    let f = AxesFile::parse(CYLINDER_K1);
    let force = f.column("force_N");
    // force_norm is F / (E* R^2), E* = 2 mu (1 + nu) / (1 - nu^2) MPa, mu = 1 MPa, R = 1 mm.
    let e_star = 2.0 * 1.48 / (1.0 - 0.48 * 0.48);
    let (mut lo, mut hi, mut late, mut seen) = (f64::INFINITY, f64::NEG_INFINITY, 0.0f64, 0);
    for (x, fn40) in f.x.iter().zip(&force) {
        let Some(p) = r20.iter().find(|p| (p.x - x).abs() < 1e-9) else {
            continue;
        };
        let d = fn40 / (p.force_norm * e_star) - 1.0;
        lo = lo.min(d);
        hi = hi.max(d);
        if *x >= 0.05 - 1e-9 {
            late = late.max(d.abs());
        }
        seen += 1;
    }
    println!(
        "cylinder k = 1 force R/40 / R/20 - 1 = {:+.3} .. {:+.3} % ({seen} points; {:.3} % from \
         x = 0.05)",
        100.0 * lo,
        100.0 * hi,
        100.0 * late
    );
    assert!(seen >= 20, "{seen} common points");
    assert!(lo > -0.0112 && hi < 0.0, "{lo} .. {hi}");
    assert!(late < 0.0045, "{late}");
    let law = flat_on_cylinder(1.0);
    let worst =
        f.x.iter()
            .zip(&force)
            .map(|(x, fe)| (law.response(*x).force / (fe / e_star) - 1.0).abs())
            .fold(0.0, f64::max);
    println!(
        "cylinder k = 1 force: law within {:.2} % of R/40",
        100.0 * worst
    );
    assert!(worst < LAW_FORCE_K1 / 100.0, "{:.2} %", 100.0 * worst);
}

/// The law's force against the R/40 cylinder, 0.01 <= x <= 0.3 [%]: measured 0.68 %, rounded
/// up to 0.1 % and 0.2 % allowed (against the campaign's R/20, `counterpart_fe.rs`: 1.11 % to
/// x = 0.44).
const LAW_FORCE_K1: f64 = 0.9;
