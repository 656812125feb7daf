//! Whether rapier's own Gauss-Seidel sweeps over a multibody's internal rows converge within a
//! solver pass: the multibody counterpart of `jointed`'s test for impulse joints.
//!
//! The soft solve sees a multibody link through the multibody's mobility with its motors and
//! its dof couplings (a URDF `<mimic>`) folded in *exactly* (`multibody`, `mobility::couple`):
//! what rapier's converged solve does. rapier solves those rows one by one, by Gauss-Seidel in
//! `num_internal_pgs_iterations` sweeps per solver pass (plus the island's largest
//! `RigidBody::additional_pgs_iterations`), from a zero impulse (its internal multibody rows are
//! not warm-started): per link in the island's order, its joint's motor rows (compliant:
//! `cfm_gain = w_dd cfm_coeff + cfm_gain`, rapier's `unit_joint_motor_constraint`), then the
//! couplings it owns (hard: `q2 - coeff q1`, rapier's `coupling_velocity_constraints`). Where
//! those sweeps do not converge, rapier does not do what the solve predicts: two prismatic jaws
//! coupled by a mimic and squeezing a box at 2 sweeps were thrown 36 mm open where the solve
//! predicted 0.3 mm (crate README, Limits). [`sweeps_needed`] says how many sweeps they need, for
//! the caller to give the links (`RigidBody::set_additional_pgs_iterations`), as
//! `SoftWorld::jointed_sweeps_needed` does for impulse joints.

use std::collections::HashMap;

use nalgebra::DVector;
use rapier3d::prelude::{Multibody, RigidBodyHandle};

use crate::joint_sweeps::{self, SweepRow};
use crate::multibody::{LinkCtx, motored_dofs, rapier_mobility};

/// One internal row of a multibody: coefficients on its free dofs (rapier's reduced order) and
/// compliance (0: hard).
struct Row {
    g: DVector<f64>,
    compliance: f64,
}

/// The Gauss-Seidel sweeps per solver pass at which rapier's sweeps over the internal rows of
/// the multibody that holds `handle` converge as the solve requires (`rate^sweeps <= 1e-5`,
/// `joint_sweeps::converges`), at the (sub)step `ctx.h` (its `ctx.passes` solver passes) and
/// the multibody's factorised mass (rapier's `inv_augmented_mass`: call after a step or
/// `Multibody::dof_inverse_inertia`): 1 for no coupled rows (one motor, or motors on dofs that
/// do not share inertia). `None` if `handle` is not a multibody link, the mass is not
/// factorised or its factorisation is not positive definite (not a mobility), or the sweeps
/// never converge.
pub(crate) fn sweeps_needed(ctx: &LinkCtx<'_>, handle: RigidBodyHandle) -> Option<usize> {
    let id = ctx.multibodies.rigid_body_link(handle)?;
    let mb = ctx.multibodies.get_multibody(id.multibody)?;
    let (free, w_r) = rapier_mobility(mb)?;
    // rapier's `f32` factorisation of a badly conditioned mass matrix is not a mobility: the
    // Franka Panda of pybullet_data (light wrist and finger links on a 7-joint arm) read
    // diagonal entries of -1.6e10 at its start pose (`Multibody::dof_inverse_inertia`, which
    // leaves out the step's joint damping), and its sweeps a rate of 7.
    w_r.clone().cholesky()?;
    let pos: HashMap<usize, usize> = free.iter().enumerate().map(|(k, &d)| (d, k)).collect();
    let rows = internal_rows(mb, ctx, &w_r, &pos);
    let sweep_rows: Vec<SweepRow<'_>> = rows
        .iter()
        .enumerate()
        .map(|(i, r)| SweepRow {
            g: &r.g,
            compliance: r.compliance,
            // One "joint" per row, in rapier's order: rapier solves each internal row alone.
            joint: i,
        })
        .collect();
    joint_sweeps::sweeps_for(joint_sweeps::sweep_rate(&w_r, &sweep_rows)?)
}

/// The multibody's internal rows in rapier's order (per link: its motor rows, then the dof
/// couplings it owns), on its free dofs `pos` (rapier's reduced order, mobility `w_r`). Joint
/// limits are left out (rows only while a limit is reached; nor does the solve model them).
fn internal_rows(
    mb: &Multibody,
    ctx: &LinkCtx<'_>,
    w_r: &nalgebra::DMatrix<f64>,
    pos: &HashMap<usize, usize>,
) -> Vec<Row> {
    let r = w_r.nrows();
    let dt_s = (ctx.h / ctx.passes.max(1) as f64) as f32;
    let mut rows = Vec::new();
    for link in mb.links() {
        for (_, d, motor) in motored_dofs(link) {
            let Some(&k) = pos.get(&d) else { continue };
            let (_, cfm_coeff, cfm_gain) =
                motor
                    .model
                    .combine_coefficients(dt_s, motor.stiffness, motor.damping);
            let compliance = w_r[(k, k)] * cfm_coeff as f64 + cfm_gain as f64;
            // A row of infinite compliance (no stiffness, no damping) does nothing.
            if compliance.is_finite() {
                let mut g = DVector::zeros(r);
                g[k] = 1.0;
                rows.push(Row { g, compliance });
            }
        }
        for c in mb.couplings().iter().filter(|c| c.link1 == link.link_id()) {
            let (Some(l1), Some(l2)) = (mb.link(c.link1), mb.link(c.link2)) else {
                continue;
            };
            let (d1, d2) = (l1.assembly_id() + c.dof1, l2.assembly_id() + c.dof2);
            if let (Some(&k1), Some(&k2)) = (pos.get(&d1), pos.get(&d2)) {
                let mut g = DVector::zeros(r);
                g[k2] += 1.0;
                g[k1] -= c.coeff as f64;
                rows.push(Row { g, compliance: 0.0 });
            }
        }
    }
    rows
}
