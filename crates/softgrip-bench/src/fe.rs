//! The FE reference of the project (`tests/data/fe/force_nu0.49.csv`, CalculiX): normalised
//! force `f = F / (E* R^2)` against `x`, for nu = 0.49.

/// The FE data file, compiled in.
const FORCE_NU049: &str = include_str!("../../../tests/data/fe/force_nu0.49.csv");
/// The FE model's radius [m] and shear modulus [Pa].
const FE_RADIUS: f64 = 1.0e-3;
const FE_MU: f64 = 1.0e6;
/// Poisson ratio of the file.
pub const FE_NU: f64 = 0.49;

/// `(x, f)` of the FE reference at nu = 0.49, increasing in x.
pub fn fe_curve() -> Vec<(f64, f64)> {
    let e_star = 2.0 * FE_MU * (1.0 + FE_NU) / (1.0 - FE_NU * FE_NU);
    FORCE_NU049
        .lines()
        .skip(1)
        .filter_map(|line| {
            let mut cols = line.split(',');
            let x = cols.next()?.trim().parse::<f64>().ok()?;
            let force = cols.next()?.trim().parse::<f64>().ok()?;
            Some((x, force / (e_star * FE_RADIUS * FE_RADIUS)))
        })
        .collect()
}

/// The FE force `f` at `x` (linear interpolation of `f / x^1.5`, which is smooth; `None`
/// outside the data).
pub fn fe_at(curve: &[(f64, f64)], x: f64) -> Option<f64> {
    let i = curve.windows(2).position(|w| w[0].0 <= x && x <= w[1].0)?;
    let ((x0, f0), (x1, f1)) = (curve[i], curve[i + 1]);
    let (g0, g1) = (f0 / x0.powf(1.5), f1 / x1.powf(1.5));
    let s = (x - x0) / (x1 - x0);
    Some((g0 + s * (g1 - g0)) * x.powf(1.5))
}
