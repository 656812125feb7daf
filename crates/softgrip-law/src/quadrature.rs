//! Gauss-Legendre quadrature on an interval, used where a level's energy or radius has no
//! closed form.

/// 8-point Gauss-Legendre nodes on [0, 1] (exact for polynomials of degree <= 15).
const NODES: [f64; 8] = [
    0.019855071751231856,
    0.10166676129318658,
    0.2372337950418355,
    0.4082826787521751,
    0.591717321247825,
    0.7627662049581645,
    0.8983332387068135,
    0.9801449282487682,
];

/// Weights matching [`NODES`]; they sum to 1.
const WEIGHTS: [f64; 8] = [
    0.05061426814518809,
    0.11119051722668723,
    0.1568533229389437,
    0.181341891689181,
    0.181341891689181,
    0.1568533229389437,
    0.11119051722668723,
    0.05061426814518809,
];

/// Integral of `f` over `[a, b]` with `panels` equal panels of 8-point Gauss-Legendre.
pub(crate) fn integrate(a: f64, b: f64, panels: usize, mut f: impl FnMut(f64) -> f64) -> f64 {
    let panels = panels.max(1);
    let h = (b - a) / panels as f64;
    let mut sum = 0.0;
    for p in 0..panels {
        let lo = a + h * p as f64;
        for (t, w) in NODES.iter().zip(WEIGHTS.iter()) {
            sum += w * f(lo + h * t);
        }
    }
    sum * h
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_degree_15_polynomial_exactly() {
        let got = integrate(0.0, 2.0, 1, |x| x.powi(15));
        let want = 2f64.powi(16) / 16.0;
        assert!((got / want - 1.0).abs() < 1e-14, "{got} vs {want}");
    }

    #[test]
    fn integrates_smooth_function_with_panels() {
        let got = integrate(0.0, 1.0, 4, f64::exp);
        assert!((got - (1f64.exp() - 1.0)).abs() < 1e-14);
    }
}
