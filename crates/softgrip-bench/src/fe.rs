//! The FE reference of the project (`tests/data/fe/force_nu0.49.csv`, CalculiX, through
//! `softgrip-fe`): normalised force `f = F / (E* R^2)` against `x`, for nu = 0.49.

/// Poisson ratio of the file.
pub const FE_NU: f64 = 0.49;

/// `(x, f)` of the FE reference at nu = 0.49, increasing in x.
pub fn fe_curve() -> Vec<(f64, f64)> {
    softgrip_fe::force_reference(FE_NU)
        .and_then(|file| file.points().ok())
        .unwrap_or_default()
        .into_iter()
        .map(|p| (p.x, p.force_norm))
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_curve_is_the_embedded_file() {
        let curve = fe_curve();
        assert_eq!(curve.len(), 78);
        assert_eq!(curve.last().map(|p| p.0), Some(0.78));
        assert!(fe_at(&curve, 0.5).is_some() && fe_at(&curve, 0.9).is_none());
    }
}
