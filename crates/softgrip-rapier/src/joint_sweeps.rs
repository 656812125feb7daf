//! Whether rapier's own Gauss-Seidel solve of a jointed assembly's rows converges within a
//! solver pass (`jointed`): the soft solve predicts what rapier's *converged* joint solve does,
//! so it sees an assembly only where rapier gets there. rapier solves the rows of impulse
//! joints by Gauss-Seidel sweeps (`num_internal_pgs_iterations` per solver pass, plus the
//! largest `RigidBody::additional_pgs_iterations` of the island component), not warm-started
//! by default, each joint's motor rows one by one and its unbounded (locked) rows together
//! (`JointConstraintHelper::finalize_constraints` orthogonalises them); a motor row's impulse
//! bounds are finite (`max_force * dt`, even at the default `max_force`), so it is not
//! orthogonalised against the locked rows. The error of such sweeps shrinks per sweep by the
//! spectral radius of their propagation matrix ([`sweep_rate`]).

use nalgebra::{DMatrix, DVector, Schur};

/// How far rapier's own Gauss-Seidel sweeps over an assembly's joint rows must converge within
/// one solver pass for the solve to see the assembly: `rate^sweeps <= SWEEP_TOLERANCE`
/// ([`sweep_rate`], `sweeps` = `num_internal_pgs_iterations` plus the members' largest
/// `RigidBody::additional_pgs_iterations`). The plugin predicts what the
/// *converged* joint solve does; rapier's joint rows are not warm-started by default and a
/// motor row is not orthogonalised against the locked ones (its impulse bounds are finite), so
/// where the sweeps do not converge rapier's joints do not carry what the plugin predicts and
/// the prediction throws the bodies (a two-link finger 0.6 rad open in one step at 2 sweeps).
/// An assembly that fails the test is seen as free bodies (the soft force comes out small and
/// the tip sinks; nothing is thrown). The value is measured, on the suite's two-link finger
/// (`rate` 0.948, `tests/jointed.rs`): `|F / F_law - 1|` at rest 0.32 / 0.048 / 5.3e-3 /
/// 3.9e-4 at 128 / 160 / 200 / 256 sweeps, `rate^sweeps` 1.0e-3 / 1.8e-4 / 2.1e-5 / 1.0e-6:
/// the force's error about 300 `rate^sweeps`. 1e-5 admits the finger from 214 sweeps. A body
/// on a fixed base whose motor acts through its centre of mass (a prismatic jaw) has rate ~0
/// and is seen at one sweep.
const SWEEP_TOLERANCE: f64 = 1e-5;

/// Relative diagonal compliance of a hard joint row (keeps `S` invertible when rows are
/// redundant, a closed loop of joints).
pub(crate) const HARD_COMPLIANCE: f64 = 1e-10;

/// One joint row as the sweeps see it: its coefficients on the assembly's coordinates, its
/// compliance (0: hard) and its joint's index among the assembly's joints.
pub(crate) struct SweepRow<'a> {
    pub g: &'a DVector<f64>,
    pub compliance: f64,
    pub joint: usize,
}

/// Whether `sweeps` sweeps over `rows` (free mobility `minv`) converge to
/// [`SWEEP_TOLERANCE`]; `None` if the rate is not finite.
pub(crate) fn converges(minv: &DMatrix<f64>, rows: &[SweepRow<'_>], sweeps: usize) -> Option<bool> {
    let rate = sweep_rate(minv, rows)?;
    Some(rate.powi(sweeps.min(i32::MAX as usize) as i32) <= SWEEP_TOLERANCE)
}

/// The fewest sweeps at which sweeps of `rate` converge to [`SWEEP_TOLERANCE`]: 1 for a rate
/// of 0; `None` if `rate` is not in `[0, 1)`.
pub(crate) fn sweeps_for(rate: f64) -> Option<usize> {
    if !(0.0..1.0).contains(&rate) {
        return None;
    }
    if rate <= SWEEP_TOLERANCE {
        return Some(1);
    }
    let n = (SWEEP_TOLERANCE.ln() / rate.ln()).ceil();
    (n.is_finite() && n < usize::MAX as f64).then_some((n as usize).max(1))
}

/// The rate at which rapier's Gauss-Seidel sweeps over the assembly's joint rows converge: the
/// spectral radius of the error's propagation over one sweep, `E = I - (D + L)^-1 S` with `S =
/// G M^-1 G^T + A`, in rapier's order (per joint its motor rows one by one, then its hard rows
/// as one block: rapier orthogonalises a joint's unbounded rows, which solves them together).
/// `None` if not finite.
pub(crate) fn sweep_rate(minv: &DMatrix<f64>, rows: &[SweepRow<'_>]) -> Option<f64> {
    let mut order: Vec<usize> = (0..rows.len()).collect();
    order.sort_by_key(|&i| (rows[i].joint, rows[i].compliance == 0.0, i));
    let k = order.len();
    if k == 0 {
        return Some(0.0);
    }
    let g = DMatrix::from_fn(k, minv.nrows(), |r, c| rows[order[r]].g[c]);
    let mut s = &g * minv * g.transpose();
    for (r, &i) in order.iter().enumerate() {
        s[(r, r)] += rows[i].compliance + HARD_COMPLIANCE * s[(r, r)].abs().max(1e-300);
    }
    // The block of row r: rows of one joint that are hard share one block.
    let block = |r: usize| {
        let row = &rows[order[r]];
        (
            row.joint,
            if row.compliance == 0.0 { usize::MAX } else { r },
        )
    };
    let lower = DMatrix::from_fn(k, k, |r, c| {
        if c <= r || block(r) == block(c) {
            s[(r, c)]
        } else {
            0.0
        }
    });
    let e = DMatrix::identity(k, k) - lower.lu().solve(&s)?;
    if !e.iter().all(|x| x.is_finite()) {
        return None;
    }
    // A bounded Schur decomposition (nalgebra's `complex_eigenvalues` on the matrix iterates
    // without a bound and unwraps).
    let rate = Schur::try_new(e, f64::EPSILON, 100 * k)?
        .complex_eigenvalues()
        .iter()
        .map(|z| z.norm())
        .fold(0.0f64, f64::max);
    rate.is_finite().then_some(rate)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A compliant (motor) row of `joint` with coefficients `g`.
    fn motor_row(g: &DVector<f64>, joint: usize) -> SweepRow<'_> {
        SweepRow {
            g,
            compliance: 1.0,
            joint,
        }
    }

    /// Two scalar rows on one coordinate of unit mobility, compliance 1 each, `S = [[2, 1], [1,
    /// 2]]`: Gauss-Seidel's error propagation `[[0, -1/2], [0, 1/4]]`, rate 1/4 (the square of
    /// Jacobi's 1/2, as for any consistently ordered matrix).
    #[test]
    fn two_coupled_rows_converge_at_a_quarter_per_sweep() {
        let minv = DMatrix::identity(2, 2);
        let g = DVector::from_column_slice(&[1.0, 0.0]);
        let rows = [motor_row(&g, 0), motor_row(&g, 1)];
        let rate = sweep_rate(&minv, &rows).unwrap();
        // (the hard rows' 1e-10 relative compliance is on every diagonal)
        assert!((rate - 0.25).abs() < 1e-9, "{rate}");
    }

    /// Hard rows of one joint are one block, solved together: the rate is 0 however they
    /// couple.
    #[test]
    fn a_joints_hard_rows_are_solved_as_one_block() {
        let minv = DMatrix::identity(2, 2);
        let (g1, g2) = (
            DVector::from_column_slice(&[1.0, 0.0]),
            DVector::from_column_slice(&[1.0, 1.0]),
        );
        let mut rows = [motor_row(&g1, 0), motor_row(&g2, 0)];
        for r in &mut rows {
            r.compliance = 0.0;
        }
        let rate = sweep_rate(&minv, &rows).unwrap();
        assert!(rate < 1e-9, "{rate}");
    }

    /// The sweeps for a rate meet the tolerance and one fewer does not; rates outside [0, 1)
    /// give none.
    #[test]
    fn sweeps_for_a_rate_are_the_fewest_that_converge() {
        for rate in [1e-6, 0.25, 0.948, 0.978, 0.9999] {
            let n = sweeps_for(rate).unwrap();
            assert!(rate.powi(n as i32) <= SWEEP_TOLERANCE, "{rate} {n}");
            assert!(
                n == 1 || rate.powi(n as i32 - 1) > SWEEP_TOLERANCE,
                "{rate} {n}"
            );
        }
        assert_eq!(sweeps_for(0.978), Some(518));
        assert_eq!(sweeps_for(1.0), None);
        assert_eq!(sweeps_for(f64::NAN), None);
    }

    /// A row that is not finite gives no rate (the assembly is then seen as free bodies), not a
    /// panic or a hang.
    #[test]
    fn a_row_that_is_not_finite_gives_no_rate() {
        let minv = DMatrix::identity(2, 2);
        let (g1, g2) = (
            DVector::from_column_slice(&[1.0, 0.0]),
            DVector::from_column_slice(&[f64::NAN, 1.0]),
        );
        let rows = [motor_row(&g1, 0), motor_row(&g2, 1)];
        assert!(sweep_rate(&minv, &rows).is_none());
    }
}
