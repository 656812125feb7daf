//! Joint motors at their effort limit in the coupled solve (issue 25: the three-finger hand
//! driven into the table).
//!
//! **Why.** A multibody's mobility as the soft solve sees it folds each joint motor in as the
//! compliant row rapier solves (`multibody`'s module docs): a position motor adds `B = b / a`
//! to the dof's generalised mass, so a stiff motor reads as a heavy dof. That is what rapier's
//! motor does only while its impulse over the (sub)step, `L = C - B qdot(end)`, stays within
//! its effort, `|L| <= max_force h` (rapier clamps each solver pass's motor impulse to
//! `max_force dt_s`, `JointMotor::max_impulse`). Past it the motor pushes its effort and no
//! more, and the dof moves as the bare links' inertia lets it. Folded unsaturated, a link
//! driven by a kinematic palm into a box that the table holds met a 2 N m motor as if it could
//! push back with any torque: the coupled answer held the wedge with 5543 N s on a 20 g link
//! (2.4e8 N over a 5.9e-5 s substep, 35 times the group's impulse scale), which the plugin
//! applied to rapier's multibody, whose motor then pushed 2 N m: the joints went from 10 to
//! 2.9e6 rad/s in that substep and on to NaN (rapier 0.36.1 panicked in `f32::clamp`).
//!
//! **What is done.** Each motor is a box-constrained row: after a coupled answer, every
//! unsaturated motor's impulse is read from the answer's end velocity; one past its effort is
//! saturated (its `B` leaves the generalised mass, `+-max_force h` joins the momentum), the
//! multibody's mobility and free velocity are folded again (`mobility::Fold::fold`) and the group is
//! solved again. The set only grows within a solve (at most one pass per motor), so it ends.
//! A motor within its effort is folded as before: a grasp whose motors hold is unchanged.

use nalgebra::{DVector, Vector6};

use crate::mobility::BodyState;
use crate::problem::Row;

/// Saturates the motors of the multibodies in `bodies` that the impulses `wrenches` (per table
/// index: force at the centre of mass, torque \[N s, N m s\]; zero for the bodies that are not
/// links) push past their effort, and folds those multibodies again, moving their links'
/// velocities (`v`, `w`) with the new free velocity. Returns how many motors it saturated;
/// `None` if a fold is singular or not finite.
pub(crate) fn saturate(bodies: &mut [BodyState], wrenches: &[Vector6<f64>]) -> Option<usize> {
    let mut count = 0;
    for host in 0..bodies.len() {
        let Some(multi) = bodies[host].link.as_deref().and_then(|l| l.multi.as_ref()) else {
            continue;
        };
        let Some(fold) = multi.fold.as_ref() else {
            continue;
        };
        // The generalised impulse of the wrenches on the multibody's links, and the end velocity.
        let n = multi.qdot.len();
        let mut g = DVector::<f64>::zeros(n);
        for (slot, &l) in multi.links.iter().enumerate() {
            if wrenches[l] != Vector6::zeros() {
                g += multi.jacs[slot].transpose() * wrenches[l];
            }
        }
        if g.iter().all(|x| *x == 0.0) {
            // Not pushed by these impulses: left as folded (another group's, or none's).
            continue;
        }
        let end = &multi.qdot + &multi.mobility * g;
        let mut fold = fold.clone();
        let mut changed = 0;
        for m in fold.motors.iter_mut().filter(|m| m.saturated.is_none()) {
            let load = m.c - m.b * end[m.dof];
            if load.abs() > m.max {
                m.saturated = Some(m.max.copysign(load));
                changed += 1;
            }
        }
        if changed == 0 {
            continue;
        }
        let (w, qf) = fold.fold()?;
        if !w.iter().chain(qf.iter()).all(|x| x.is_finite()) {
            return None;
        }
        let link = bodies[host].link.as_deref_mut()?;
        let multi = link.multi.as_mut()?;
        let old = multi.qdot.clone();
        for (a, &da) in fold.free.iter().enumerate() {
            multi.qdot[da] = qf[a];
            for (b, &db) in fold.free.iter().enumerate() {
                multi.mobility[(da, db)] = w[(a, b)];
            }
        }
        multi.refresh();
        multi.fold = Some(fold);
        let dq = &multi.qdot - old;
        let moved: Vec<(usize, Vector6<f64>)> = (multi.links.iter().zip(&multi.jacs))
            .map(|(&l, jac)| {
                let d = jac * &dq;
                (l, Vector6::from_fn(|r, _| d[r]))
            })
            .collect();
        for (l, d) in moved {
            bodies[l].v += d.fixed_rows::<3>(0);
            bodies[l].w += d.fixed_rows::<3>(3);
        }
        count += changed;
    }
    Some(count)
}

/// The wrench of soft rows `rows` (their impulses `jn`, `jt`, `jtw`) on each link of `bodies`
/// (force at its centre of mass, torque \[N s, N m s\], by table index; zero elsewhere), into
/// `out` (resized to the table).
pub(crate) fn soft_wrenches(bodies: &[BodyState], rows: &[Row], out: &mut Vec<Vector6<f64>>) {
    out.clear();
    out.resize(bodies.len(), Vector6::zeros());
    for r in rows {
        let f = r.n * r.jn + r.jt;
        for (i, s) in [(r.a, 1.0), (r.b, -1.0)] {
            if let Some(i) = i.filter(|&i| bodies[i].link.is_some()) {
                let t = (r.p - bodies[i].com).cross(&f) + r.n * r.jtw;
                let (f, t) = (f * s, t * s);
                out[i] += Vector6::new(f.x, f.y, f.z, t.x, t.y, t.z);
            }
        }
    }
}
