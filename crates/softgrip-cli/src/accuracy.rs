//! Errors of a level of the law against the FE reference.

use softgrip_law::ContactLaw;

use crate::fe::FePoint;

/// Largest relative error over a range of FE points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaxError {
    /// max |(law - FE) / FE| [-].
    pub max_abs: f64,
    /// Smallest and largest x of the points compared.
    pub x_range: (f64, f64),
    /// Number of points compared.
    pub points: usize,
}

/// Which quantity to compare.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// Normalised force f.
    Force,
    /// Normalised contact radius a / R: of an elliptical patch its second semi-axis (across a
    /// cylinder or an edge: what the 3D FE files give as their radius), of a disc its radius.
    Radius,
}

/// Largest relative error of `law` (normalised: E* = 1, R = 1) against the FE points with
/// `x_lo <= x <= x_hi` that are inside the law's validity range; `None` if there are none.
pub fn max_error(
    law: &ContactLaw,
    fe: &[FePoint],
    quantity: Quantity,
    x_lo: f64,
    x_hi: f64,
) -> Option<MaxError> {
    let x_max = law.x_max();
    let mut result: Option<MaxError> = None;
    for p in fe
        .iter()
        .filter(|p| p.x >= x_lo && p.x <= x_hi && p.x <= x_max)
    {
        let (model, reference) = match quantity {
            Quantity::Force => (law.response(p.x).force, p.force_norm),
            Quantity::Radius => (law.patch(p.x).radius2, p.radius_norm),
        };
        if !reference.is_finite() {
            // An edge's FE has no semi-axis where its patch is not resolved (NaN).
            continue;
        }
        let e = ((model - reference) / reference).abs();
        result = Some(match result {
            None => MaxError {
                max_abs: e,
                x_range: (p.x, p.x),
                points: 1,
            },
            Some(m) => MaxError {
                max_abs: m.max_abs.max(e),
                x_range: (m.x_range.0, p.x),
                points: m.points + 1,
            },
        });
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;
    use softgrip_law::{ContactParams, Level};

    #[test]
    fn errors_are_relative_and_stop_at_x_max() {
        let law = ContactLaw::try_new(
            ContactParams::try_from_parts(1.0, 1.0, 0.3).expect("valid"),
            Level::fit(),
        )
        .expect("builds");
        // Fit at nu = 0.3: x_max = 0.81. Points made from the law itself, one 10 % off.
        let point = |x: f64, scale: f64| FePoint {
            x,
            force_norm: law.response(x).force * scale,
            radius_norm: law.patch(x).radius,
            min_element_j: None,
        };
        let fe = [point(0.1, 1.0), point(0.5, 1.0 / 1.1), point(0.85, 2.0)];
        let m = max_error(&law, &fe, Quantity::Force, 0.0, 1.0).expect("points");
        assert!((m.max_abs - 0.1).abs() < 1e-12, "{m:?}");
        assert_eq!((m.x_range, m.points), ((0.1, 0.5), 2));
        let r = max_error(&law, &fe, Quantity::Radius, 0.0, 1.0).expect("points");
        assert!(r.max_abs < 1e-15);
        assert!(max_error(&law, &fe, Quantity::Force, 0.6, 0.7).is_none());
    }
}
