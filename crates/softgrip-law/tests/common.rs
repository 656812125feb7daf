//! Shared helpers of the law's integration tests.
#![allow(dead_code)]

use softgrip_fe::FeFile;
use softgrip_law::{ContactLaw, ContactParams, Level};

/// A law in normalised units (E* = 1 Pa, R = 1 m): force is f, delta is x.
pub fn normalised(level: Level, nu: f64) -> ContactLaw {
    let p = ContactParams::try_from_parts(1.0, 1.0, nu).expect("valid params");
    ContactLaw::try_new(p, level).expect("level builds")
}

/// Every level that can be built at `nu`.
pub fn levels_at(nu: f64) -> Vec<ContactLaw> {
    Level::ALL
        .iter()
        .filter(|l| nu < 0.5 || !matches!(l, Level::NeoHookean | Level::NeoHookeanExact))
        .map(|l| normalised(*l, nu))
        .collect()
}

/// Compression ratios spread over (0, x_max) that avoid the cell boundaries of tables and of
/// `Auto` (multiples of 1/256 and 1/64).
pub fn grid(x_max: f64, n: usize) -> Vec<f64> {
    (1..n)
        .map(|i| x_max * (i as f64 + 0.293_7) / (n as f64 + 0.5))
        .collect()
}

/// The largest `|F_law / F_FE - 1|` over an FE force curve's points with `0.01 <= x <=
/// min(x_max, to)`, and the last `x` compared (0 when none): the one loop over an FE table that
/// `counterpart_fe.rs` and `core_counterpart_fe.rs` share.
pub fn force_error(file: &FeFile, law: &ContactLaw, to: f64) -> (f64, f64) {
    let mut worst: f64 = 0.0;
    let mut top: f64 = 0.0;
    for p in file.points().expect("parses") {
        if p.x < 0.01 - 1e-12 || p.x > law.x_max() || p.x > to + 1e-9 {
            continue;
        }
        worst = worst.max((law.response(p.x).force / p.force_norm - 1.0).abs());
        top = top.max(p.x);
    }
    (worst, top)
}

/// `(r/R, p/E*)` of an FE pressure profile (R = 1 mm, mu = 1 MPa), the two nodes nearest the
/// axis dropped (the tied on-axis face makes them jitter by up to 20 %: see the file's
/// provenance line); the last row is the contact edge a_lin (p = 0).
pub fn profile(text: &str, nu: f64) -> Vec<(f64, f64)> {
    let e_star = 2.0 * (1.0 + nu) / (1.0 - nu * nu); // MPa
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("r_mm"))
        .skip(2)
        .map(|l| {
            let mut it = l
                .split(',')
                .map(|v| v.trim().parse::<f64>().expect("number"));
            (it.next().expect("r"), it.next().expect("p") / e_star)
        })
        .collect()
}

/// The smooth FE radius of one curve: least squares of `a / sqrt(x)` as a polynomial in
/// `s = sqrt(x)` over `0.05 <= x` (cubic where the curve spans more than 0.25 in x, else
/// quadratic): Hertz's `a = sqrt(R delta)` times a low-order series in `sqrt(x)`.
pub struct Smooth {
    coef: Vec<f64>,
}

impl Smooth {
    /// The fit to the points `(x, f, a/R)` (their `a/R` column).
    pub fn fit(points: &[(f64, f64, f64)]) -> Self {
        let pts: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| p.0 >= 0.05 - 1e-9)
            .map(|p| (p.0.sqrt(), p.2 / p.0.sqrt()))
            .collect();
        let span = pts.last().expect("points").0.powi(2) - 0.05;
        let n = if span > 0.25 { 4 } else { 3 };
        // Normal equations (n <= 4 unknowns, s in [0.22, 0.9]: well enough conditioned).
        let mut m = vec![vec![0.0; n + 1]; n];
        for &(s, y) in &pts {
            for (i, row) in m.iter_mut().enumerate() {
                for (j, v) in row.iter_mut().enumerate().take(n) {
                    *v += s.powi((i + j) as i32);
                }
                row[n] += s.powi(i as i32) * y;
            }
        }
        for c in 0..n {
            let p = (c..n)
                .max_by(|&a, &b| m[a][c].abs().total_cmp(&m[b][c].abs()))
                .expect("rows");
            m.swap(c, p);
            let pivot = m[c].clone();
            for (r, row) in m.iter_mut().enumerate() {
                if r != c {
                    let k = row[c] / pivot[c];
                    for (v, pv) in row.iter_mut().zip(&pivot).skip(c) {
                        *v -= k * pv;
                    }
                }
            }
        }
        Self {
            coef: (0..n).map(|i| m[i][n] / m[i][i]).collect(),
        }
    }

    /// The smooth radius at `x`.
    pub fn at(&self, x: f64) -> f64 {
        let s = x.sqrt();
        s * self.coef.iter().rev().fold(0.0, |acc, c| acc * s + c)
    }
}

/// One mesh-convergence check of the ball campaign (`tests/data/fe/ball/convergence.csv`, rows
/// `<geometry>,<nu>,<k>,mesh,40,60,...`): `(x, F at R/40 [N], F at R/60 [N], reldiff %)` per
/// row, where reldiff = `(F_R/40 - F_R/60) / F_R/60` in %.
pub fn ball_mesh_convergence(geometry: &str, nu: f64, k: f64) -> Vec<[f64; 4]> {
    let text = include_str!("../../../tests/data/fe/ball/convergence.csv");
    let header = "geometry,nu,k,check,campaign,other,delta_over_R,force_N_campaign,";
    let prefix = format!("{geometry},{nu},{k},mesh,40,60,");
    text.lines()
        .skip_while(|l| !l.starts_with(header))
        .skip(1)
        .filter(|l| l.starts_with(&prefix))
        .map(|l| {
            let v: Vec<f64> = l
                .split(',')
                .skip(6)
                .map(|v| v.parse().expect("a number"))
                .collect();
            [v[0], v[1], v[2], v[3]]
        })
        .collect()
}

/// The largest |reldiff| [%] and the last x of [`ball_mesh_convergence`] rows, after checking
/// that each row's reldiff column agrees with its two forces (2e-3 %).
pub fn mesh_convergence_summary(rows: &[[f64; 4]]) -> (f64, f64) {
    for r in rows {
        assert!((100.0 * (r[1] - r[2]) / r[2] - r[3]).abs() < 2e-3, "{r:?}");
    }
    let worst = rows.iter().map(|r| r[3].abs()).fold(0.0, f64::max);
    let end = rows.iter().map(|r| r[0]).fold(0.0, f64::max);
    (worst, end)
}
