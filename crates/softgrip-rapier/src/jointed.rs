//! Bodies held by rapier *impulse* joints as the soft solve sees them (a jointed assembly).
//!
//! A fingertip on a link of a finger built with impulse joints pushes on a body that its joints
//! hold: seen as a free body, a light link is predicted to fly off under the soft impulse, the
//! impulse comes out near zero and the tip sinks into what it presses (the two-link finger read
//! 0.004 N where the law asks 6.3 N). The solve sees the *assembly* instead: the dynamic, awake
//! bodies connected through enabled impulse joints (at most [`MAX_ASSEMBLY_BODIES`]), each a
//! link of one generalised body whose coordinates are the members' velocities `V` (per member
//! the linear velocity of its centre of mass and its angular velocity, world frame) and whose
//! joints are rows on `V`, rapier's own (`dynamics/solver/joint_constraint`):
//! - a **locked axis** is a hard bilateral row: the relative velocity of the two anchors along
//!   the axis of body 1's joint frame (rapier's anchor on body 1 is frame 2's origin snapped onto
//!   frame 1's along the locked axes), or the relative spin about it, is zero at the end of the
//!   step (rapier's joint softness, 1e6 Hz by default, and its position bias, removed in its
//!   unbiased pass, are left out);
//! - a **motor** of a free axis is rapier's compliant row, per solver pass
//!   `cfm_s lambda_s = g V + rhs_s` with `MotorModel::combine_coefficients` and
//!   `cfm_s = dot_jj cfm_coeff + cfm_gain` (`dot_jj` the row's free-body mobility): over the
//!   `N` passes of a step it reads `a L + b g V(end) = c` (`multibody::motor_fold`, whose
//!   derivation is the same), the step's impulse `L` along `+g`;
//! - an active **limit** (the joint at or past it, as rapier enables it) is a hard one-sided
//!   row: `g V(end) = 0` with an impulse that pushes away from the limit only. Which limit rows
//!   act is decided on the motion without the soft impulses (an active set on the assembly's
//!   own rows); the soft impulses do not re-decide it within the step (crate README, Limits).
//!
//! With `G` the rows, `M^-1` the members' free inverse mass and inertia (rapier's effective
//! ones), `A` the rows' compliance (`a / b`, zero for hard rows), `C` their targets (`c / b`
//! minus the known velocity of a fixed or kinematic other body) and `V*` the members' velocity
//! with gravity and the user's forces over the whole (sub)step (the joints balance them in every
//! solver pass, as a multibody's motors do), the rows' impulses are `L = S^-1 (C - G V* - G M^-1
//! f)`, `S = G M^-1 G^T + A`, for a wrench `f` of the soft contacts: the assembly's free
//! velocity is `V* + M^-1 G^T S^-1 (C - G V*)` and its mobility `M^-1 - M^-1 G^T S^-1 G M^-1`
//! (the Schur complement: the rows solved exactly, as rapier's PGS converges to). That is a
//! [`Generalised`] whose links' jacobians select their member's six coordinates, so the soft
//! rows, the rigid supports and the group union see a jointed body exactly as a multibody link
//! (`multibody`).
//!
//! **Who applies what.** The plugin applies only the soft impulses (and the rigid supports'
//! soft part), as a force over the coming pipeline step on the member's rigid body
//! (`multibody::apply_to_rapier`); rapier's joint solver makes every joint impulse itself
//! (locked axes, motors, limits), pass by pass, with the soft force in each pass as it has
//! gravity. The prediction is what that converged solve does, so at rest the contact carries
//! the law's force and each motor `J^T F`. Applied as a velocity change instead, a light link's
//! kick has to be taken back by the joints within the step (as a multibody link's was).
//!
//! **When the solve sees an assembly.** The prediction is rapier's *converged* joint solve, and
//! rapier reaches it only if its Gauss-Seidel sweeps over the joint rows converge within a
//! solver pass. The solve sees an assembly only where they do (`joint_sweeps`): a body on a fixed or kinematic base whose motor acts through its
//! centre of mass (a prismatic jaw) at any number of sweeps; a chain of light links with an
//! offset centre of mass (the suite's two-link finger, rate 0.948) from 214 sweeps
//! (`num_internal_pgs_iterations` plus the members' largest `additional_pgs_iterations`: a
//! user can ask them of a finger's links alone). Otherwise its bodies are free bodies to the
//! solve, as before session 12. Why rapier's chain needs so many (crate README, Limits; plain rapier,
//! `tests/impulse_chain_plain.rs`): a motor row is solved against the body's free inertia
//! about its centre of mass and not orthogonalised against the joint's locked rows, so each
//! sweep passes only part of the load between the motor and the locked anchor.

use nalgebra::{DMatrix, DVector, Matrix3, Vector3};
use rapier3d::prelude::{
    ImpulseJoint, JointMotor, Pose, RigidBody, RigidBodyHandle, RigidBodySet, Vector,
};

use crate::boundary::to_f64;
use crate::joint_sweeps::{self, HARD_COMPLIANCE, SweepRow};
use crate::kinematic::KinematicVelocity;
use crate::mobility::{BodyState, Generalised, Link, free_mobility};
use crate::multibody::{LinkCtx, motor_fold};

/// The most bodies one jointed assembly may hold (its rows and mobility are dense, `6k x 6k`);
/// a larger one is seen as free bodies.
pub(crate) const MAX_ASSEMBLY_BODIES: usize = 8;

/// One member of an assembly.
struct Member {
    handle: RigidBodyHandle,
    inv_m: Vector3<f64>,
    inv_i: Matrix3<f64>,
    com: Vector3<f64>,
}

/// Which impulses a joint row may carry (its impulse `L` along `+g`).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Sign {
    Free,
    NonNegative,
    NonPositive,
}

/// One joint row on the assembly's coordinates: `g V + known + compliance L = target`.
struct JointRow {
    g: DVector<f64>,
    known: f64,
    compliance: f64,
    target: f64,
    sign: Sign,
    /// A locked axis (the external acceleration is taken through these alone).
    locked: bool,
    /// The joint's index among the assembly's joints (rapier solves a joint's rows together).
    joint: usize,
}

/// Whether `handle` can be a member: an awake, enabled dynamic body that is not a multibody
/// link (those are seen through their multibody).
fn can_join(bodies: &RigidBodySet, ctx: &LinkCtx<'_>, handle: RigidBodyHandle) -> bool {
    bodies
        .get(handle)
        .is_some_and(|rb| rb.is_dynamic() && !rb.is_sleeping() && rb.is_enabled())
        && ctx.multibodies.rigid_body_link(handle).is_none()
}

/// Whether `handle` is a body the solve would see through its impulse joints if it could: an
/// awake, enabled dynamic body (not a multibody link) with an enabled impulse joint. Such a body
/// that [`assembly_states`] leaves out (rapier's sweeps do not converge, the assembly is larger
/// than [`MAX_ASSEMBLY_BODIES`], or its numbers are not finite) is solved as a free body
/// (`SoftCounters::jointed_free`).
pub(crate) fn is_jointed(
    bodies: &RigidBodySet,
    ctx: &LinkCtx<'_>,
    handle: RigidBodyHandle,
) -> bool {
    can_join(bodies, ctx, handle)
        && ctx
            .impulse_joints
            .attached_enabled_joints(handle)
            .next()
            .is_some()
}

/// The assembly of `handle`: the bodies that can join, connected to it through enabled impulse
/// joints; `None` if it has no such joint or the assembly is larger than
/// [`MAX_ASSEMBLY_BODIES`].
fn members(
    bodies: &RigidBodySet,
    ctx: &LinkCtx<'_>,
    handle: RigidBodyHandle,
) -> Option<Vec<RigidBodyHandle>> {
    if !can_join(bodies, ctx, handle) {
        return None;
    }
    ctx.impulse_joints.attached_enabled_joints(handle).next()?;
    let mut out = vec![handle];
    let mut next = 0;
    while next < out.len() {
        let body = out[next];
        next += 1;
        for (b1, b2, _, _) in ctx.impulse_joints.attached_enabled_joints(body) {
            let other = if b1 == body { b2 } else { b1 };
            if !out.contains(&other) && can_join(bodies, ctx, other) {
                out.push(other);
                if out.len() > MAX_ASSEMBLY_BODIES {
                    return None;
                }
            }
        }
    }
    Some(out)
}

fn member(rb: &RigidBody, handle: RigidBodyHandle) -> Member {
    let (inv_m, inv_i) = free_mobility(rb);
    Member {
        handle,
        inv_m,
        inv_i,
        com: to_f64(rb.mass_properties().world_com),
    }
}

/// The entries of the assembly of `handle` in the body table (`None`: not held by impulse
/// joints, or not an assembly the solve can see): each member's handle and its state, the
/// first member (`handle`) the host, at table index `next`, the others after it in order.
pub(crate) fn assembly_states(
    bodies: &RigidBodySet,
    ctx: &LinkCtx<'_>,
    kin_vel: &KinematicVelocity,
    handle: RigidBodyHandle,
    next: usize,
) -> Option<Vec<(RigidBodyHandle, BodyState)>> {
    let handles = members(bodies, ctx, handle)?;
    let ms: Vec<Member> = handles
        .iter()
        .map(|h| bodies.get(*h).map(|rb| member(rb, *h)))
        .collect::<Option<_>>()?;
    let n = 6 * ms.len();
    let (minv, v_star, force) = free_motion(bodies, ctx, &ms)?;
    let rows = assembly_rows(bodies, ctx, kin_vel, &ms, &minv);
    if !rapier_converges(bodies, ctx, &handles, &rows, &minv)? {
        return None;
    }
    let (mobility, qdot) = constrained(&minv, &rows, &v_star, |_| true)?;
    let (locked_mobility, _) = constrained(&minv, &rows, &v_star, |r| r.locked)?;
    // The motion without the motors' push: the hard rows alone (locked axes, active limits),
    // as a multibody's `passive` leaves its motors out (`Generalised::passive`).
    let (_, passive) = constrained(&minv, &rows, &v_star, |r| r.compliance == 0.0)?;
    let acc = locked_mobility * force;
    let mut g = Generalised::new(mobility, qdot.clone(), acc.clone());
    g.passive = passive.clone();
    let mut out = Vec::with_capacity(ms.len());
    for (k, m) in ms.iter().enumerate() {
        let index = next + k;
        let jac = DMatrix::from_fn(6, n, |r, c| if c == 6 * k + r { 1.0 } else { 0.0 });
        let slot = g.add(index, jac);
        let o = 6 * k;
        let part = |x: &DVector<f64>, s: usize| Vector3::new(x[o + s], x[o + s + 1], x[o + s + 2]);
        out.push((
            m.handle,
            BodyState {
                v: part(&qdot, 0),
                w: part(&qdot, 3),
                inv_m: Vector3::zeros(),
                inv_i: Matrix3::zeros(),
                com: m.com,
                a_ext: part(&acc, 0),
                passive: (part(&passive, 0), part(&passive, 3)),
                link: Some(Box::new(Link {
                    host: next,
                    slot,
                    multi: None,
                })),
            },
        ));
    }
    let finite = out
        .iter()
        .all(|(_, b)| b.v.iter().chain(b.w.iter()).all(|x| x.is_finite()));
    if !finite {
        return None;
    }
    out[0].1.link.as_deref_mut()?.multi = Some(g);
    Some(out)
}

/// The rows of every enabled impulse joint attached to the members `ms` (each joint once,
/// numbered in the order met), on the members' free inverse mass `minv`.
fn assembly_rows(
    bodies: &RigidBodySet,
    ctx: &LinkCtx<'_>,
    kin_vel: &KinematicVelocity,
    ms: &[Member],
    minv: &DMatrix<f64>,
) -> Vec<JointRow> {
    let mut rows = Vec::new();
    let mut seen = Vec::new();
    for m in ms {
        for (b1, b2, jh, joint) in ctx.impulse_joints.attached_enabled_joints(m.handle) {
            if seen.contains(&jh) {
                continue;
            }
            seen.push(jh);
            let first = rows.len();
            joint_rows(bodies, ctx, kin_vel, ms, minv, (b1, b2), joint, &mut rows);
            for r in &mut rows[first..] {
                r.joint = seen.len() - 1;
            }
        }
    }
    rows
}

/// Whether rapier's Gauss-Seidel sweeps over the assembly's joint rows `rows` converge within
/// a solver pass (`joint_sweeps`); `None` if their rate cannot be read.
fn rapier_converges(
    bodies: &RigidBodySet,
    ctx: &LinkCtx<'_>,
    handles: &[RigidBodyHandle],
    rows: &[JointRow],
    minv: &DMatrix<f64>,
) -> Option<bool> {
    // rapier runs its sweeps plus the largest `additional_pgs_iterations` of a body in the
    // island component, which holds every member (a lower bound: a body outside the assembly
    // may ask for more).
    let extra = handles
        .iter()
        .filter_map(|h| bodies.get(*h).map(RigidBody::additional_pgs_iterations))
        .max()
        .unwrap_or(0);
    let sweeps = ctx.sweeps.saturating_add(extra);
    let sweep_rows = sweep_rows(rows);
    joint_sweeps::converges(minv, &sweep_rows, sweeps)
}

/// The joint rows as `joint_sweeps` reads them.
fn sweep_rows(rows: &[JointRow]) -> Vec<SweepRow<'_>> {
    rows.iter()
        .map(|r| SweepRow {
            g: &r.g,
            compliance: r.compliance,
            joint: r.joint,
        })
        .collect()
}

/// The Gauss-Seidel sweeps per solver pass at which rapier's sweeps over the joint rows of the
/// assembly of `handle` converge as the solve requires (`rate^sweeps <= 1e-5`,
/// `joint_sweeps::converges`), at the (sub)step `ctx.h` and the bodies' present pose: 1 for a
/// rate of 0; `None` if `handle` is not in an assembly the solve can see (see [`members`]) or the
/// sweeps never converge (rate >= 1, or not finite).
pub(crate) fn sweeps_needed(
    bodies: &RigidBodySet,
    ctx: &LinkCtx<'_>,
    handle: RigidBodyHandle,
) -> Option<usize> {
    let handles = members(bodies, ctx, handle)?;
    let ms: Vec<Member> = handles
        .iter()
        .map(|h| bodies.get(*h).map(|rb| member(rb, *h)))
        .collect::<Option<_>>()?;
    let (minv, _, _) = free_motion(bodies, ctx, &ms)?;
    let kin_vel = KinematicVelocity::default();
    let mut rows = Vec::new();
    let mut seen = Vec::new();
    for m in &ms {
        for (b1, b2, jh, joint) in ctx.impulse_joints.attached_enabled_joints(m.handle) {
            if seen.contains(&jh) {
                continue;
            }
            seen.push(jh);
            let first = rows.len();
            joint_rows(
                bodies,
                ctx,
                &kin_vel,
                &ms,
                &minv,
                (b1, b2),
                joint,
                &mut rows,
            );
            for r in &mut rows[first..] {
                r.joint = seen.len() - 1;
            }
        }
    }
    let sweep_rows = sweep_rows(&rows);
    joint_sweeps::sweeps_for(joint_sweeps::sweep_rate(&minv, &sweep_rows)?)
}

/// The members' free inverse mass and inertia (`6k x 6k`, block diagonal), their velocity with
/// gravity and the user's forces over the whole (sub)step, and those forces (per member: the
/// force at the centre of mass, then the torque).
fn free_motion(
    bodies: &RigidBodySet,
    ctx: &LinkCtx<'_>,
    ms: &[Member],
) -> Option<(DMatrix<f64>, DVector<f64>, DVector<f64>)> {
    let n = 6 * ms.len();
    let mut minv = DMatrix::<f64>::zeros(n, n);
    let mut v_star = DVector::<f64>::zeros(n);
    let mut force = DVector::<f64>::zeros(n);
    for (k, m) in ms.iter().enumerate() {
        let rb = bodies.get(m.handle)?;
        let o = 6 * k;
        for r in 0..3 {
            minv[(o + r, o + r)] = m.inv_m[r];
            for c in 0..3 {
                minv[(o + 3 + r, o + 3 + c)] = m.inv_i[(r, c)];
            }
        }
        let f = to_f64(rb.user_force()) + ctx.gravity * (rb.gravity_scale() * rb.mass()) as f64;
        let t = to_f64(rb.user_torque());
        let (v, w) = (to_f64(rb.linvel()), to_f64(rb.angvel()));
        let (dv, dw) = (m.inv_m.component_mul(&f), m.inv_i * t);
        for r in 0..3 {
            force[o + r] = f[r];
            force[o + 3 + r] = t[r];
            v_star[o + r] = v[r] + dv[r] * ctx.h;
            v_star[o + 3 + r] = w[r] + dw[r] * ctx.h;
        }
    }
    Some((minv, v_star, force))
}

/// The assembly's mobility and free velocity with the rows `use_row` selects (see the module's
/// docs), deciding which one-sided rows act on the motion without soft impulses; `None` if not
/// finite.
fn constrained(
    minv: &DMatrix<f64>,
    rows: &[JointRow],
    v_star: &DVector<f64>,
    use_row: impl Fn(&JointRow) -> bool,
) -> Option<(DMatrix<f64>, DVector<f64>)> {
    let mut active: Vec<bool> = rows.iter().map(&use_row).collect();
    for _ in 0..(2 * rows.len() + 2) {
        let idx: Vec<usize> = (0..rows.len()).filter(|&i| active[i]).collect();
        if idx.is_empty() {
            return Some((minv.clone(), v_star.clone()));
        }
        let g = DMatrix::from_fn(idx.len(), minv.nrows(), |r, c| rows[idx[r]].g[c]);
        let mg = minv * g.transpose();
        let mut s = &g * &mg;
        for (r, &i) in idx.iter().enumerate() {
            let d = s[(r, r)];
            s[(r, r)] += rows[i].compliance + HARD_COMPLIANCE * d.abs().max(1e-300);
        }
        let rhs = DVector::from_fn(idx.len(), |r, _| {
            let row = &rows[idx[r]];
            row.target - row.known - row.g.dot(v_star)
        });
        let lu = s.lu();
        let l = lu.solve(&rhs)?;
        let mut changed = false;
        for (r, &i) in idx.iter().enumerate() {
            let wrong = match rows[i].sign {
                Sign::Free => false,
                Sign::NonNegative => l[r] < 0.0,
                Sign::NonPositive => l[r] > 0.0,
            };
            if wrong {
                active[i] = false;
                changed = true;
            }
        }
        if changed {
            continue;
        }
        let s_inv = lu.try_inverse()?;
        let mobility = minv - &mg * s_inv * mg.transpose();
        let qdot = v_star + &mg * l;
        let finite = mobility.iter().chain(qdot.iter()).all(|x| x.is_finite());
        return finite.then_some((mobility, qdot));
    }
    None
}

/// A joint's frames as rapier's `JointConstraintHelper` reads them.
struct Frame {
    /// The axes of frame 1 (world).
    axes: [Vector3<f64>; 3],
    /// The anchor on body 1: frame 2's origin snapped onto frame 1's along the locked linear
    /// axes \[m\].
    anchor1: Vector3<f64>,
    /// The anchor on body 2: frame 2's origin \[m\].
    anchor2: Vector3<f64>,
    /// Frame 2's origin minus frame 1's \[m\].
    lin_err: Vector3<f64>,
    /// The imaginary part and the real part of `frame1^-1 frame2`, in the hemisphere of `w >=
    /// 0`.
    ang_err: (Vector3<f64>, f64),
}

impl Frame {
    fn new(f1: &Pose, f2: &Pose, locked: u8) -> Self {
        let axes = [Vector::X, Vector::Y, Vector::Z].map(|a| to_f64(f1.rotation * a));
        let (t1, t2) = (to_f64(f1.translation), to_f64(f2.translation));
        let lin_err = t2 - t1;
        let mut anchor1 = t2;
        for (i, a) in axes.iter().enumerate() {
            if locked & (1 << i) != 0 {
                anchor1 -= a * lin_err.dot(a);
            }
        }
        let mut q = f1.rotation.inverse() * f2.rotation;
        if f1.rotation.dot(f2.rotation) < 0.0 {
            q = -q;
        }
        Self {
            axes,
            anchor1,
            anchor2: t2,
            lin_err,
            ang_err: (Vector3::new(q.x as f64, q.y as f64, q.z as f64), q.w as f64),
        }
    }

    /// The joint's position along axis `i` (0-2: the frames' offset \[m\]; 3-5: the angle
    /// `2 asin(q_i)` \[rad\]), as rapier's motor rows read it.
    fn position(&self, i: usize) -> f64 {
        if i < 3 {
            self.lin_err.dot(&self.axes[i])
        } else {
            2.0 * self.ang_err.0[i - 3].clamp(-1.0, 1.0).asin()
        }
    }

    /// The angle about axis `i` (3-5) measured from the middle of `[lo, hi]`, wrapped, as
    /// rapier's angular limit rows read it (`recentered_angle`), and half the range.
    fn recentered(&self, i: usize, lo: f64, hi: f64) -> Option<(f64, f64)> {
        let half_range = (hi - lo) * 0.5;
        if !(half_range < std::f64::consts::PI) {
            return None;
        }
        let (s, c) = ((lo + hi) * 0.25).sin_cos();
        let (x, w) = (self.ang_err.0[i - 3], self.ang_err.1);
        let half = (c * x - s * w).atan2(c * w + s * x);
        let half = if half.abs() > std::f64::consts::FRAC_PI_2 {
            half - std::f64::consts::PI.copysign(half)
        } else {
            half
        };
        Some((2.0 * half, half_range))
    }
}

/// What the rows of one joint need: the world, the assembly and the joint's frames.
struct Sides<'a> {
    bodies: &'a RigidBodySet,
    kin_vel: &'a KinematicVelocity,
    ms: &'a [Member],
    /// The assembly's coordinates (`6k`).
    n: usize,
    /// rapier's body 1 and body 2.
    pair: (RigidBodyHandle, RigidBodyHandle),
    frame: Frame,
}

impl Sides<'_> {
    /// rapier's row velocity `J (v2 - v1)` along (0-2) or about (3-5) axis `i`: its
    /// coefficients on the assembly's coordinates, and the part a fixed or kinematic side
    /// contributes (known).
    fn row(&self, i: usize) -> (DVector<f64>, f64) {
        let axis = self.frame.axes[i % 3];
        let mut g = DVector::<f64>::zeros(self.n);
        let mut known = 0.0;
        for (handle, anchor, s) in [
            (self.pair.1, self.frame.anchor2, 1.0),
            (self.pair.0, self.frame.anchor1, -1.0),
        ] {
            let Some(rb) = self.bodies.get(handle) else {
                continue;
            };
            let com = to_f64(rb.mass_properties().world_com);
            let (lin, ang) = if i < 3 {
                (axis, (anchor - com).cross(&axis))
            } else {
                (Vector3::zeros(), axis)
            };
            if let Some(k) = self.ms.iter().position(|m| m.handle == handle) {
                for r in 0..3 {
                    g[6 * k + r] += s * lin[r];
                    g[6 * k + 3 + r] += s * ang[r];
                }
            } else if !rb.is_fixed() {
                let (v, w) = self
                    .kin_vel
                    .get(&handle)
                    .copied()
                    .unwrap_or((to_f64(rb.linvel()), to_f64(rb.angvel())));
                known += s * (lin.dot(&v) + ang.dot(&w));
            }
        }
        (g, known)
    }

    /// A hard row along or about axis `i`.
    fn hard(&self, i: usize, sign: Sign, locked: bool) -> JointRow {
        let (g, known) = self.row(i);
        JointRow {
            g,
            known,
            compliance: 0.0,
            target: 0.0,
            sign,
            locked,
            joint: 0,
        }
    }

    /// The compliant row of `motor` on axis `i` at the joint's position `q`, its target
    /// velocity clamped by a linear axis' `limits` as rapier does; `None` if it has no
    /// compliance (`multibody::motor_fold`).
    fn motor(
        &self,
        i: usize,
        motor: &JointMotor,
        q: f64,
        limits: Option<[f32; 2]>,
        minv: &DMatrix<f64>,
        ctx: &LinkCtx<'_>,
    ) -> Option<JointRow> {
        let (g, known) = self.row(i);
        let w = g.dot(&(minv * &g));
        let mut motor = *motor;
        if i >= 3 {
            // rapier aims an angular motor the shorter way round.
            motor.target_pos = (q - smallest_abs_diff(q, motor.target_pos as f64)) as f32;
        }
        let lim = limits
            .filter(|_| i < 3)
            .map(|[lo, hi]| [lo as f64, hi as f64]);
        let (b_a, c_a) = motor_fold(&motor, q, lim, w, ctx)?;
        Some(JointRow {
            g,
            known,
            compliance: 1.0 / b_a,
            target: c_a / b_a,
            sign: Sign::Free,
            locked: false,
            joint: 0,
        })
    }
}

/// The rows of one impulse joint between rapier's `pair` (body 1, body 2), appended to `out`.
#[allow(clippy::too_many_arguments)]
fn joint_rows(
    bodies: &RigidBodySet,
    ctx: &LinkCtx<'_>,
    kin_vel: &KinematicVelocity,
    ms: &[Member],
    minv: &DMatrix<f64>,
    pair: (RigidBodyHandle, RigidBodyHandle),
    joint: &ImpulseJoint,
    out: &mut Vec<JointRow>,
) {
    let (Some(rb1), Some(rb2)) = (bodies.get(pair.0), bodies.get(pair.1)) else {
        return;
    };
    let data = &joint.data;
    let (locked, coupled) = (data.locked_axes.bits(), data.coupled_axes.bits());
    let sides = Sides {
        bodies,
        kin_vel,
        ms,
        n: minv.nrows(),
        pair,
        frame: Frame::new(
            &(*rb1.position() * data.local_frame1),
            &(*rb2.position() * data.local_frame2),
            locked,
        ),
    };
    for i in 0..6usize {
        let bit = 1u8 << i;
        if locked & bit != 0 {
            out.push(sides.hard(i, Sign::Free, true));
            continue;
        }
        if coupled & bit != 0 {
            continue;
        }
        let q = sides.frame.position(i);
        let limits =
            (data.limit_axes.bits() & bit != 0).then(|| [data.limits[i].min, data.limits[i].max]);
        if data.motor_axes.bits() & bit != 0 {
            out.extend(sides.motor(i, &data.motors[i], q, limits, minv, ctx));
        }
        let Some([lo, hi]) = limits.map(|[lo, hi]| [lo as f64, hi as f64]) else {
            continue;
        };
        let (x, lo, hi) = if i < 3 {
            (q, lo, hi)
        } else {
            match sides.frame.recentered(i, lo, hi) {
                Some((x, half)) => (x, -half, half),
                None => continue,
            }
        };
        if x <= lo {
            out.push(sides.hard(i, Sign::NonNegative, false));
        }
        if x >= hi {
            out.push(sides.hard(i, Sign::NonPositive, false));
        }
    }
}

/// `a - b` wrapped to the shorter way round (rapier's `smallest_abs_diff_between_angles`).
fn smallest_abs_diff(a: f64, b: f64) -> f64 {
    let e = a - b;
    let other = e - e.signum() * std::f64::consts::TAU;
    if e.abs() < other.abs() { e } else { other }
}
