//! A group's answer where every contact sticks, solved exactly instead of by more passes.
//!
//! A group's outer passes (`solve::solve_group`: the normals solved exactly given the
//! friction, then Gauss-Seidel friction sweeps given the normals) are a fixed-point iteration.
//! Where every row's normal is active, no row slides and no row's torsion is at its limit, that
//! iteration is linear and its fixed point is the solution of one linear system: per row its
//! normal equation (`j_n = h (F - d v_n(end))`, the law linearised over the step as
//! `solve_normal` takes it), its two tangential equations (the friction spring's `v_t(end) + C
//! j_t = target`, or the hard stick's, as `friction_sweep` takes them) and its torsional one
//! (`w_n(end) = 0`). The passes contract towards it slowly where the friction couples the rows
//! strongly: three pads holding a 50 g ball in the air (`scenes/robots/three_finger_hand_ball
//! .toml`) contracted by about 0.988 a pass, so 411 of the scene's 576 group solves ended their
//! 256 passes still moving 2e-4 of the largest normal impulse a pass (about 2 % from the fixed
//! point) and took 87 % of the scene's time. [`stick_exact`] solves the system directly (a
//! dense LU of `4 m` unknowns for `m` rows, its matrix read by applying unit impulses) and
//! keeps the answer where it is one the passes could have converged to: every normal positive,
//! every friction impulse inside its Coulomb disk and every torsional one inside its limit.

use nalgebra::{DMatrix, DVector, Vector3};

use crate::apply::{apply_linear, apply_torque, rel_spin, restore};
use crate::mobility::BodyState;
use crate::problem::{Row, normal_velocity, rel_vel, spring};

/// Unknowns per row: the normal impulse, the two tangential ones, the torsional one.
const PER_ROW: usize = 4;

/// The velocities a row's equations read: normal, along `t1`, along `t2` (relative, at its
/// point) and the relative spin about its normal.
fn velocities(bodies: &[BodyState], r: &Row) -> [f64; PER_ROW] {
    let v = rel_vel(bodies, r);
    [
        normal_velocity(bodies, r),
        v.dot(&r.t1),
        v.dot(&r.t2),
        rel_spin(bodies, r),
    ]
}

/// Applies `x` of unknown `k` of row `r` (0: normal, 1 and 2: tangential, 3: torsional).
fn apply(bodies: &mut [BodyState], r: &Row, k: usize, x: f64) {
    match k {
        0 => apply_linear(bodies, r, &(r.n * x)),
        1 => apply_linear(bodies, r, &(r.t1 * x)),
        2 => apply_linear(bodies, r, &(r.t2 * x)),
        _ => apply_torque(bodies, r, x),
    }
}

/// Solves `rows` (a group of two or more) as if every contact sticks, from the bodies at
/// `base`, and if the answer is one where every normal impulse is positive, every tangential
/// one inside `mu j_n` and every torsional one inside `torsion_arm j_n`, writes it (the rows'
/// impulses, the bodies moved by them from `base`) and returns true. Returns false and
/// changes nothing (the bodies are as the caller left them, up to rounding) where a row is not
/// sticking now (its normal not positive, sliding, its torsion at its limit, no friction), or
/// the answer is not finite or not such a state (the caller's next pass restores the bodies
/// from `base`: call it only where one follows). `h`: the (sub)step \[s\].
pub(crate) fn stick_exact(
    bodies: &mut [BodyState],
    base: &[BodyState],
    rows: &mut [Row],
    h: f64,
) -> bool {
    let m = rows.len();
    // Which torsional impulses are unknowns (a torsional mobility and an arm); the others
    // are held where the passes hold them (`friction_sweep` leaves them).
    let mut twist = Vec::with_capacity(m);
    for r in rows.iter() {
        let Some((Some(_), kt)) = r.friction_mobility else {
            return false;
        };
        let free = kt > 0.0 && r.torsion_arm > 0.0;
        let sticking = r.jn > 0.0 && r.mu > 0.0 && !r.sliding;
        if !sticking || (free && r.jtw.abs() >= r.torsion_arm * r.jn) {
            return false;
        }
        twist.push(free);
    }
    let n = PER_ROW * m;
    // The velocities now (the current answer applied) and the response to each unknown,
    // read by applying an impulse of the group's size (its largest normal impulse, so that
    // taking it back leaves the bodies' velocities as the passes' own arithmetic would: a
    // unit impulse on a 1e-11 kg cell is 1e11 m/s) and taking it back.
    let probe = rows.iter().fold(0.0f64, |s, r| s.max(r.jn));
    let now: Vec<[f64; PER_ROW]> = rows.iter().map(|r| velocities(bodies, r)).collect();
    let mut w = DMatrix::<f64>::zeros(n, n);
    for (c, rc) in rows.iter().enumerate() {
        for k in 0..PER_ROW {
            // A torsional impulse of the row's arm times the probe (N m s).
            let size = if k == 3 {
                probe * rc.torsion_arm.max(1e-300)
            } else {
                probe
            };
            apply(bodies, rc, k, size);
            for (i, ri) in rows.iter().enumerate() {
                let v = velocities(bodies, ri);
                for (q, vq) in v.iter().enumerate() {
                    w[(PER_ROW * i + q, PER_ROW * c + k)] = (vq - now[i][q]) / size;
                }
            }
            apply(bodies, rc, k, -size);
        }
    }
    // The current impulses, to take the velocities back to the bodies without them.
    let current: Vec<[f64; PER_ROW]> = rows
        .iter()
        .map(|r| [r.jn, r.jt.dot(&r.t1), r.jt.dot(&r.t2), r.jtw])
        .collect();
    let u0 = DVector::from_fn(n, |e, _| current[e / PER_ROW][e % PER_ROW]);
    let v_now = DVector::from_fn(n, |e, _| now[e / PER_ROW][e % PER_ROW]);
    // The velocities without any of the group's impulses: v0 = v_now - W u0.
    let v0 = &v_now - &w * &u0;
    let mut a = DMatrix::<f64>::zeros(n, n);
    let mut b = DVector::<f64>::zeros(n);
    for (i, r) in rows.iter().enumerate() {
        let e = PER_ROW * i;
        // Normal: j_n + h d (v0_n + W_n u) = h F.
        let d = r.theta * r.stiffness * h + r.damping;
        a[(e, e)] = 1.0;
        for c in 0..n {
            a[(e, c)] += h * d * w[(e, c)];
        }
        b[e] = h * (r.force - d * v0[e]);
        // Tangential: (v0_t + W_t u - target) + C j_t = 0.
        let (compliance, target) = spring(r, h);
        for (q, t) in [(1, r.t1), (2, r.t2)] {
            for c in 0..n {
                a[(e + q, c)] = w[(e + q, c)];
            }
            a[(e + q, e + q)] += compliance;
            b[e + q] = target.dot(&t) - v0[e + q];
        }
        // Torsional: v0_w + W_w u = 0, or held.
        if twist[i] {
            for c in 0..n {
                a[(e + 3, c)] = w[(e + 3, c)];
            }
            b[e + 3] = -v0[e + 3];
        } else {
            a[(e + 3, e + 3)] = 1.0;
            b[e + 3] = r.jtw;
        }
    }
    let Some(x) = a.lu().solve(&b) else {
        return false;
    };
    if !x.iter().all(|v| v.is_finite()) {
        return false;
    }
    for (i, r) in rows.iter().enumerate() {
        let e = PER_ROW * i;
        let (jn, jt, jtw) = (x[e], x[e + 1].hypot(x[e + 2]), x[e + 3]);
        let inside = jn > 0.0 && jt <= r.mu * jn && (!twist[i] || jtw.abs() <= r.torsion_arm * jn);
        if !inside {
            return false;
        }
    }
    // The answer, applied from `base` in a pass's order.
    restore(bodies, base, rows);
    for (i, r) in rows.iter_mut().enumerate() {
        let e = PER_ROW * i;
        r.jn = x[e];
        r.jt = r.t1 * x[e + 1] + r.t2 * x[e + 2];
        r.jtw = x[e + 3];
        r.sliding = false;
        let jt: Vector3<f64> = r.jt;
        apply_linear(bodies, r, &jt);
        apply_torque(bodies, r, r.jtw);
    }
    for r in rows.iter() {
        apply_linear(bodies, r, &(r.n * r.jn));
    }
    true
}
