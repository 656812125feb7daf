//! [`Extension`]: the law past its validity range, a barrier that keeps a fixed plane
//! impenetrable.
//!
//! In the curve's own normalised units (`x`, `f = F/(E* R²)`, `w = W/(E* R³)`), from the edge
//! `(x_e, f_e, k_e, w_e)` to the wall `x_w`, with `L = x_w - x_e`, `u = (x - x_e)/L` in `[0, 1)`
//! and `c = f_e + k_e L` (the edge's force plus its tangent's rise over `L`):
//!
//! - `f(x) = f_e + k_e (x - x_e) + c u²/(1 - u)`: the tangent at the edge plus a barrier term
//!   that starts with zero value and zero slope (so `f` is C1 at the edge) and grows without
//!   bound as `u -> 1`;
//! - `k(x) = k_e + (c/L) u (2 - u)/(1 - u)²` (the exact derivative, `>= k_e`: monotone);
//! - `w(x) = w_e + f_e s + k_e s²/2 + c L (-ln(1 - u) - u - u²/2)` with `s = x - x_e` (the
//!   exact integral).
//!
//! Past `u_c = 1 -` [`WALL_GAP`] (a hair short of the wall) the barrier is continued by its
//! tangent there (stiffness about `c/(L WALL_GAP²)`, `1e12 c/L`), which keeps every output
//! finite at and past the wall; past `max(x_w + L, 4)` (no real contact gets there, only a
//! tunnelled or corrupt state) the force and the energy are frozen (`k = 0`) so that a finite
//! input never overflows.

use crate::normalised::X_FROZEN;

/// How short of the wall, as a fraction of `L`, the barrier hands over to its tangent [-].
pub(crate) const WALL_GAP: f64 = 1e-6;

/// Smallest distance from the edge to the wall, as a fraction of the edge's `x` [-]: a law
/// whose validity reaches the physical wall (or past it) gets its wall at `1.1 x_e`.
pub(crate) const MIN_WALL_ROOM: f64 = 0.1;

/// The extension of a normalised curve past its edge (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Extension {
    x_e: f64,
    f_e: f64,
    k_e: f64,
    w_e: f64,
    /// `L = x_w - x_e` [-], > 0.
    len: f64,
    /// The barrier's scale `c` [-], > 0.
    c: f64,
    /// Where the barrier hands over to its tangent, `x_e + (1 - WALL_GAP) L`, and the barrier's
    /// `(f, k, w)` there.
    x_c: f64,
    at_c: (f64, f64, f64),
    /// Where the tangent is frozen, `max(x_w + L, 4)`, and `(f, w)` there.
    x_far: f64,
    at_far: (f64, f64),
}

impl Extension {
    /// The extension of a curve whose edge is `x_e` with force `f_e`, stiffness `k_e > 0`,
    /// energy `w_e` (all normalised), against a physical wall at `wall` (the curve's own `x`).
    pub(crate) fn new(x_e: f64, f_e: f64, k_e: f64, w_e: f64, wall: f64) -> Self {
        let x_w = if wall >= x_e * (1.0 + MIN_WALL_ROOM) {
            wall
        } else {
            x_e * (1.0 + MIN_WALL_ROOM)
        };
        let len = x_w - x_e;
        let mut c = f_e + k_e * len;
        if !(c > 0.0 && c.is_finite()) {
            // A law with no force at its edge: Hertz's normalised force there sets the scale.
            c = 4.0 / 3.0 * x_e * x_e.sqrt();
        }
        let mut ext = Self {
            x_e,
            f_e,
            k_e,
            w_e,
            len,
            c,
            x_c: x_e + (1.0 - WALL_GAP) * len,
            at_c: (0.0, 0.0, 0.0),
            x_far: (x_w + len).max(X_FROZEN),
            at_far: (0.0, 0.0),
        };
        ext.at_c = ext.barrier(ext.x_c);
        let (f, _, w) = ext.tangent(ext.x_far);
        ext.at_far = (cap(f), cap(w));
        ext
    }

    /// The wall's `x` [-] (the curve's own): where the barrier diverges.
    pub(crate) fn wall(&self) -> f64 {
        self.x_e + self.len
    }

    /// Where the extension stops growing (`k = 0` past it) [-].
    pub(crate) fn x_far(&self) -> f64 {
        self.x_far
    }

    /// `(f, k)` at `x > x_e` (finite `x`).
    #[inline]
    pub(crate) fn force_stiffness(&self, x: f64) -> (f64, f64) {
        let (f, k, _) = if x <= self.x_c {
            self.barrier(x)
        } else if x <= self.x_far {
            self.tangent(x)
        } else {
            (self.at_far.0, 0.0, 0.0)
        };
        (cap(f), cap(k))
    }

    /// `w` at `x > x_e` (finite `x`), frozen past the freeze with the force.
    pub(crate) fn energy(&self, x: f64) -> f64 {
        if x <= self.x_c {
            cap(self.barrier(x).2)
        } else if x <= self.x_far {
            cap(self.tangent(x).2)
        } else {
            self.at_far.1
        }
    }

    /// The barrier's `(f, k, w)` at `x_e < x <= x_c`.
    fn barrier(&self, x: f64) -> (f64, f64, f64) {
        let s = x - self.x_e;
        let u = s / self.len;
        let v = 1.0 - u;
        let f = self.f_e + self.k_e * s + self.c * u * u / v;
        let k = self.k_e + self.c / self.len * u * (2.0 - u) / (v * v);
        let w = self.w_e + s * (self.f_e + 0.5 * self.k_e * s) + self.c * self.len * log_excess(u);
        (f, k, w)
    }

    /// The tangent at `x_c`, at `x >= x_c`.
    fn tangent(&self, x: f64) -> (f64, f64, f64) {
        let (f_c, k_c, w_c) = self.at_c;
        let d = x - self.x_c;
        (f_c + k_c * d, k_c, w_c + d * (f_c + 0.5 * k_c * d))
    }
}

/// `-ln(1 - u) - u - u²/2` for `0 <= u < 1`, accurate near 0 (where it is `u³/3 + u⁴/4 + ...`).
fn log_excess(u: f64) -> f64 {
    if u < 0.05 {
        // The series to u^16: the first term left out is below 1e-19 of the sum at u = 0.05.
        let mut term = u * u;
        let mut sum = 0.0;
        for n in 3..=16 {
            term *= u;
            sum += term / f64::from(n);
        }
        sum
    } else {
        -(-u).ln_1p() - u - 0.5 * u * u
    }
}

/// A value that overflowed (only for a law whose edge force is itself near `f64::MAX`) becomes
/// the largest finite one.
#[inline]
fn cap(v: f64) -> f64 {
    v.min(f64::MAX)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_excess_is_continuous_at_the_series_switch() {
        let u = 0.05f64;
        let series = log_excess(u.next_down());
        let closed = -(-u).ln_1p() - u - 0.5 * u * u;
        assert!((series / closed - 1.0).abs() < 1e-12, "{series} {closed}");
    }

    #[test]
    fn barrier_is_c1_at_the_edge_and_at_the_hand_over() {
        let ext = Extension::new(0.5, 0.4, 2.0, 0.1, 1.0);
        let (f, k) = ext.force_stiffness(0.5 + 1e-12);
        assert!((f - 0.4).abs() < 1e-11 && (k - 2.0).abs() < 1e-9);
        let (below, above) = (
            ext.force_stiffness(ext.x_c),
            ext.force_stiffness(ext.x_c.next_up()),
        );
        // One ulp of x apart: the force moves by the stiffness times that ulp, no jump.
        let ulp = ext.x_c.next_up() - ext.x_c;
        let jump = above.0 - below.0 - below.1 * ulp;
        assert!(jump.abs() <= 1e-15 * below.0, "{jump}");
        assert!((below.1 / above.1 - 1.0).abs() < 1e-12);
        // c = 0.4 + 2 * 0.5 = 1.4: at u = 1/2 the barrier adds c/2.
        let (f, _) = ext.force_stiffness(0.75);
        assert!((f - (0.4 + 2.0 * 0.25 + 0.7)).abs() < 1e-14);
    }
}
