//! Normal and friction impulses of the soft contacts over one (sub)step of size `h`.
//!
//! All algebra is `f64` (nalgebra); rapier's `f32` glam values are converted once, at the
//! boundary, by the caller.
//!
//! **Normal.** Per contact i, with the law's force `F`, stiffness `K`, the Hunt-Crossley /
//! Flores damping coefficient `c = chi F` and the blend `theta` (0: explicit, 1: linearised
//! implicit), the impulse over the step is
//!   `j_i = h [F_i - D_i v_i(end)]`, `D_i = theta_i K_i h + c_i`,
//! where `v_i(end)` is the normal separation velocity at the end of the step, which depends on
//! all impulses through the bodies' mobility `W`: `v(end) = v0 + W j`. Hence the small linear
//! complementarity problem `(I + h D W) j = h (F - D v0)`, `j >= 0`. Contacts that share a
//! dynamic body are coupled through `W` (a box squeezed between two fingertips gets the right
//! net impulse). Projected Gauss-Seidel converges like `(hDW/(1+hDW))^2` per sweep, which is
//! hopeless for stiff contacts (h^2 K w ~ 1e4), so the normal problem is solved directly: a
//! dense LU on the active set, with the set updated until no impulse is negative (a few
//! passes; soft contacts per world are few).
//!
//! **Friction.** Coulomb with true static friction: each contact keeps a tangential anchor on
//! the other body; the tangential impulse targets zero relative tangential velocity plus a
//! positional correction `beta * offset / h` back to the anchor, and is clamped to the disk
//! `mu_f j_n`. If clamped, the contact slides. Torsion about the normal targets zero relative
//! spin and is clamped to `(3 pi / 16) mu_f a j_n` (a Hertz-shaped pressure over the law's
//! contact radius `a`). Friction is solved by Gauss-Seidel sweeps, alternated with the normal
//! solve.

use nalgebra::{DMatrix, DVector, Matrix2, Matrix3, Vector2, Vector3};

/// Velocity state and inverse mass of one body as the solver sees it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct BodyState {
    /// Linear velocity [m/s].
    pub v: Vector3<f64>,
    /// Angular velocity [rad/s].
    pub w: Vector3<f64>,
    /// Per-axis inverse mass [1/kg] (zero for fixed, kinematic or sleeping bodies).
    pub inv_m: Vector3<f64>,
    /// World inverse inertia [1/(kg m^2)].
    pub inv_i: Matrix3<f64>,
    /// World centre of mass [m].
    pub com: Vector3<f64>,
    /// External acceleration (gravity, user force / m) [m/s^2]; zero if not dynamic.
    pub a_ext: Vector3<f64>,
}

impl BodyState {
    #[inline]
    fn vel_at(&self, p: &Vector3<f64>) -> Vector3<f64> {
        self.v + self.w.cross(&(p - self.com))
    }

    #[inline]
    fn apply(&mut self, p: &Vector3<f64>, imp: &Vector3<f64>) {
        self.v += self.inv_m.component_mul(imp);
        self.w += self.inv_i * (p - self.com).cross(imp);
    }

    /// Relative velocity change along `dir_i` at `p_i` from a unit impulse along `dir_k` at `p_k`.
    #[inline]
    fn mobility(
        &self,
        p_i: &Vector3<f64>,
        dir_i: &Vector3<f64>,
        p_k: &Vector3<f64>,
        dir_k: &Vector3<f64>,
    ) -> f64 {
        let (ri, rk) = (p_i - self.com, p_k - self.com);
        let dw = self.inv_i * rk.cross(dir_k);
        dir_i.dot(&(self.inv_m.component_mul(dir_k) + dw.cross(&ri)))
    }

    fn is_dynamic(&self) -> bool {
        self.inv_m.iter().any(|m| *m > 0.0)
    }
}

/// One contact prepared for the solve, and its impulses after it.
#[derive(Debug, Clone)]
pub(crate) struct Row {
    /// Index of the fingertip's body in the body table (`None`: fixed, no body).
    pub a: Option<usize>,
    /// Index of the other body.
    pub b: Option<usize>,
    /// Contact point (world) [m].
    pub p: Vector3<f64>,
    /// Unit normal, other -> fingertip.
    pub n: Vector3<f64>,
    /// Tangent basis.
    pub t1: Vector3<f64>,
    /// Tangent basis.
    pub t2: Vector3<f64>,
    /// Law force F [N].
    pub force: f64,
    /// Law stiffness K [N/m].
    pub stiffness: f64,
    /// Damping coefficient c = chi F [N s/m].
    pub damping: f64,
    /// Integration blend in [0, 1].
    pub theta: f64,
    /// Friction coefficient.
    pub mu: f64,
    /// Torsion limit per unit normal impulse, (3 pi/16) mu a [m].
    pub torsion_arm: f64,
    /// Tangential offset of the contact from its anchor (world, in the tangent plane) [m].
    pub offset: Vector3<f64>,
    /// Normal impulse [N s], >= 0.
    pub jn: f64,
    /// Tangential impulse (world, in the tangent plane) [N s].
    pub jt: Vector3<f64>,
    /// Torsional impulse about n [N m s].
    pub jtw: f64,
    /// Friction saturated (sliding).
    pub sliding: bool,
    /// Normal separation velocity at the end of the step [m/s].
    pub vn_end: f64,
}

/// Positional correction factor of static friction (fraction of the anchor offset removed
/// per step).
pub(crate) const FRICTION_BETA: f64 = 0.3;
const OUTER_ITERATIONS: usize = 3;
const FRICTION_SWEEPS: usize = 4;

fn body(bodies: &[BodyState], i: Option<usize>) -> Option<&BodyState> {
    i.map(|i| &bodies[i])
}

fn rel_vel(bodies: &[BodyState], r: &Row) -> Vector3<f64> {
    let va = body(bodies, r.a)
        .map(|b| b.vel_at(&r.p))
        .unwrap_or_default();
    let vb = body(bodies, r.b)
        .map(|b| b.vel_at(&r.p))
        .unwrap_or_default();
    va - vb
}

fn rel_spin(bodies: &[BodyState], r: &Row) -> f64 {
    let wa = body(bodies, r.a).map(|b| b.w).unwrap_or_default();
    let wb = body(bodies, r.b).map(|b| b.w).unwrap_or_default();
    (wa - wb).dot(&r.n)
}

fn apply_linear(bodies: &mut [BodyState], r: &Row, imp: &Vector3<f64>) {
    if let Some(a) = r.a {
        bodies[a].apply(&r.p, imp);
    }
    if let Some(b) = r.b {
        bodies[b].apply(&r.p, &-imp);
    }
}

fn apply_torque(bodies: &mut [BodyState], r: &Row, t: f64) {
    let tv = r.n * t;
    if let Some(a) = r.a {
        bodies[a].w += bodies[a].inv_i * tv;
    }
    if let Some(b) = r.b {
        bodies[b].w -= bodies[b].inv_i * tv;
    }
}

/// Relative mobility between directions of rows i and k (sum over the bodies they share).
fn pair_mobility(
    bodies: &[BodyState],
    ri: &Row,
    di: &Vector3<f64>,
    rk: &Row,
    dk: &Vector3<f64>,
) -> f64 {
    let mut m = 0.0;
    for (bi, si) in [(ri.a, 1.0), (ri.b, -1.0)] {
        for (bk, sk) in [(rk.a, 1.0), (rk.b, -1.0)] {
            if let (Some(x), Some(y)) = (bi, bk)
                && x == y
            {
                m += si * sk * bodies[x].mobility(&ri.p, di, &rk.p, dk);
            }
        }
    }
    m
}

/// Effective normal mobility w = n.(W n) of one row [1/kg].
pub(crate) fn normal_mobility(bodies: &[BodyState], r: &Row) -> f64 {
    pair_mobility(bodies, r, &r.n, r, &r.n)
}

/// Relative external acceleration of a row along its normal [m/s^2].
pub(crate) fn normal_external_acceleration(bodies: &[BodyState], r: &Row) -> f64 {
    let aa = body(bodies, r.a).map(|b| b.a_ext).unwrap_or_default();
    let ab = body(bodies, r.b).map(|b| b.a_ext).unwrap_or_default();
    (aa - ab).dot(&r.n)
}

/// Normal separation velocity of a row [m/s] (> 0 separating).
pub(crate) fn normal_velocity(bodies: &[BodyState], r: &Row) -> f64 {
    rel_vel(bodies, r).dot(&r.n)
}

/// Solves the normal impulses given the body velocities `v0` (everything but the normal
/// impulses), writing `jn` of every row. Returns false if the system was not finite.
fn solve_normal(bodies: &[BodyState], rows: &mut [Row], h: f64) -> bool {
    let n = rows.len();
    let d: Vec<f64> = rows
        .iter()
        .map(|r| r.theta * r.stiffness * h + r.damping)
        .collect();
    let rhs: Vec<f64> = rows
        .iter()
        .zip(&d)
        .map(|(r, di)| h * (r.force - di * normal_velocity(bodies, r)))
        .collect();
    // A = I + h D W
    let mut a = DMatrix::<f64>::identity(n, n);
    for i in 0..n {
        if d[i] == 0.0 {
            continue;
        }
        for k in 0..n {
            let w = pair_mobility(bodies, &rows[i], &rows[i].n, &rows[k], &rows[k].n);
            a[(i, k)] += h * d[i] * w;
        }
    }
    let mut active: Vec<bool> = rhs.iter().map(|v| *v > 0.0).collect();
    let mut j = vec![0.0; n];
    for _ in 0..(2 * n + 2) {
        let idx: Vec<usize> = (0..n).filter(|i| active[*i]).collect();
        j.iter_mut().for_each(|v| *v = 0.0);
        if !idx.is_empty() {
            let m = idx.len();
            let sub = DMatrix::from_fn(m, m, |r, c| a[(idx[r], idx[c])]);
            let b = DVector::from_fn(m, |r, _| rhs[idx[r]]);
            let Some(x) = sub.lu().solve(&b) else {
                return false;
            };
            for (r, &i) in idx.iter().enumerate() {
                j[i] = x[r];
            }
        }
        let mut changed = false;
        for i in 0..n {
            if active[i] && j[i] < 0.0 {
                active[i] = false;
                changed = true;
            } else if !active[i] {
                let resid = rhs[i] - (0..n).map(|k| a[(i, k)] * j[k]).sum::<f64>();
                if resid > 1e-12 * rhs[i].abs().max(1e-300) && resid > 0.0 {
                    active[i] = true;
                    changed = true;
                }
            }
        }
        if !changed {
            break;
        }
    }
    for (r, ji) in rows.iter_mut().zip(&j) {
        r.jn = ji.max(0.0);
    }
    j.iter().all(|v| v.is_finite())
}

/// One Gauss-Seidel sweep of friction and torsion over all rows.
fn friction_sweep(bodies: &mut [BodyState], rows: &mut [Row], h: f64) {
    for r in rows.iter_mut() {
        if r.mu <= 0.0 || r.jn <= 0.0 {
            if r.jt != Vector3::zeros() {
                let undo = -r.jt;
                apply_linear(bodies, r, &undo);
                r.jt = Vector3::zeros();
            }
            if r.jtw != 0.0 {
                apply_torque(bodies, r, -r.jtw);
                r.jtw = 0.0;
            }
            continue;
        }
        let (t1, t2) = (r.t1, r.t2);
        let k = Matrix2::new(
            pair_mobility(bodies, r, &t1, r, &t1),
            pair_mobility(bodies, r, &t1, r, &t2),
            pair_mobility(bodies, r, &t2, r, &t1),
            pair_mobility(bodies, r, &t2, r, &t2),
        );
        if let Some(k_inv) = k.try_inverse()
            && k.trace() > 0.0
        {
            let v = rel_vel(bodies, r);
            let target = -FRICTION_BETA * r.offset / h;
            let err = Vector2::new((v - target).dot(&t1), (v - target).dot(&t2));
            let dj = -(k_inv * err);
            let old = Vector2::new(r.jt.dot(&t1), r.jt.dot(&t2));
            let mut new = old + dj;
            let limit = r.mu * r.jn;
            r.sliding = new.norm() > limit;
            if r.sliding {
                new *= limit / new.norm();
            }
            let delta = t1 * (new.x - old.x) + t2 * (new.y - old.y);
            if delta.iter().all(|x| x.is_finite()) {
                apply_linear(bodies, r, &delta);
                r.jt += delta;
            }
        }
        let kt = body(bodies, r.a)
            .map(|b| r.n.dot(&(b.inv_i * r.n)))
            .unwrap_or(0.0)
            + body(bodies, r.b)
                .map(|b| r.n.dot(&(b.inv_i * r.n)))
                .unwrap_or(0.0);
        if kt > 0.0 {
            let limit = r.torsion_arm * r.jn;
            let new = (r.jtw - rel_spin(bodies, r) / kt).clamp(-limit, limit);
            if new.is_finite() {
                apply_torque(bodies, r, new - r.jtw);
                r.jtw = new;
            }
        }
    }
}

/// Solves all rows over a step `h` [s], starting from the body velocities `bodies` (external
/// impulses of the step already included). On return `bodies` holds the velocities after the
/// impulses and every row its impulses. Returns false if the normal system was not finite (the
/// impulses are then zero).
pub(crate) fn solve(bodies: &mut [BodyState], rows: &mut [Row], h: f64) -> bool {
    let base: Vec<BodyState> = bodies.to_vec();
    let any_dynamic = bodies.iter().any(BodyState::is_dynamic);
    let mut ok = true;
    let outer = if any_dynamic { OUTER_ITERATIONS } else { 1 };
    for it in 0..outer {
        bodies.copy_from_slice(&base);
        for r in rows.iter() {
            apply_linear(bodies, r, &r.jt);
            apply_torque(bodies, r, r.jtw);
        }
        ok = solve_normal(bodies, rows, h);
        if !ok {
            break;
        }
        for r in rows.iter() {
            apply_linear(bodies, r, &(r.n * r.jn));
        }
        if !any_dynamic {
            break;
        }
        for _ in 0..FRICTION_SWEEPS {
            friction_sweep(bodies, rows, h);
        }
        let _ = it;
    }
    if !ok {
        bodies.copy_from_slice(&base);
        for r in rows.iter_mut() {
            r.jn = 0.0;
            r.jt = Vector3::zeros();
            r.jtw = 0.0;
        }
    }
    for r in rows.iter_mut() {
        r.vn_end = normal_velocity(bodies, r);
    }
    ok
}
