//! The one root finder of the law: Newton's method safeguarded by bisection inside a bracket.
//!
//! Every implicit solve of the law goes through [`newton_bracketed`]: the volume change `J` of
//! the neo-Hookean bar (Eq. 33), Tatara's force at a given compression, and the inverse
//! [`crate::ContactLaw::compression_for_force`]. Each caller finds its own bracket (that part is
//! problem-specific: Eq. 33 has up to three roots and the physical one is the largest) and
//! decides, at each iterate, on which side of the root it lies; the solver keeps the bracket,
//! takes the Newton step when it lands strictly inside the bracket and bisects otherwise, so it
//! cannot leave the bracket (the property tests once caught a plain Newton iteration jumping to
//! a collapsed root of Eq. 33 at nu = 0.452).

/// One evaluation at an iterate `x`, as the caller sees it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Probe {
    /// `true` if the root lies above `x` (then `x` becomes the bracket's lower end).
    pub(crate) below_root: bool,
    /// The Newton step `g(x) / g'(x)`; the next iterate is `x - step` (NaN or infinite steps
    /// fall back to bisection).
    pub(crate) step: f64,
}

/// When to stop: after the step that is small relative to the iterate, or (optionally) once the
/// bracket is narrow relative to its upper end, or after `max_iterations`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Stop {
    /// Stop when `|x_next - x| <= step * |x|`.
    pub(crate) step: f64,
    /// Stop when `hi - lo <= width * |hi|` (`None`: no width test).
    pub(crate) width: Option<f64>,
    /// Largest number of iterations.
    pub(crate) max_iterations: usize,
}

/// Newton's method from `start`, safeguarded by bisection in the bracket `[lo, hi]`.
///
/// Returns the last iterate: the one computed by the step that met `stop` (it is always inside
/// the bracket, which every probe narrows).
pub(crate) fn newton_bracketed(
    mut lo: f64,
    mut hi: f64,
    start: f64,
    stop: Stop,
    mut probe: impl FnMut(f64) -> Probe,
) -> f64 {
    let mut x = start;
    for _ in 0..stop.max_iterations {
        let p = probe(x);
        if p.below_root {
            lo = x;
        } else {
            hi = x;
        }
        let mut next = x - p.step;
        // NaN fails both comparisons and bisects too.
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        let narrow = stop.width.is_some_and(|w| hi - lo <= w * hi.abs());
        let done = (next - x).abs() <= stop.step * x.abs() || narrow;
        x = next;
        if done {
            break;
        }
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    const STOP: Stop = Stop {
        step: 1e-15,
        width: Some(1e-16),
        max_iterations: 100,
    };

    #[test]
    fn finds_a_square_root() {
        let x = newton_bracketed(0.0, 2.0, 1.0, STOP, |x| Probe {
            below_root: x * x < 2.0,
            step: (x * x - 2.0) / (2.0 * x),
        });
        assert!((x - 2f64.sqrt()).abs() < 1e-15);
    }

    #[test]
    fn stays_in_the_bracket_where_newton_would_leave_it() {
        // atan's Newton iteration diverges from x = 2; the bracket keeps it on the root.
        let x = newton_bracketed(-1.0, 3.0, 2.0, STOP, |x| Probe {
            below_root: x.atan() < 0.0,
            step: x.atan() * (1.0 + x * x),
        });
        assert!(x.abs() < 1e-12, "{x}");
    }

    #[test]
    fn a_zero_derivative_bisects() {
        let x = newton_bracketed(0.0, 1.0, 0.0, STOP, |x| Probe {
            below_root: x < 0.25,
            step: (x - 0.25) / 0.0,
        });
        assert!((x - 0.25).abs() < 1e-15, "{x}");
    }
}
