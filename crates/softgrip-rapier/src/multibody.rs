//! A link of a rapier multibody (reduced coordinates) as the soft solve sees it.
//!
//! rapier overwrites a multibody link's rigid-body velocity from the multibody's generalised
//! velocities `qdot` at the start of its step, so an impulse applied to the link's rigid body
//! is lost, and the link's response to an impulse is not a free body's. The solve sees a link
//! through its multibody instead:
//! - the velocity of the link (at its centre of mass, linear and angular) is `J qdot`, `J` the
//!   link's 6 x n jacobian (`Multibody::body_jacobian`);
//! - a wrench `f = [F; tau]` on the link (force at its centre of mass, torque) changes `qdot`
//!   by `W J^T f`, `W` the multibody's generalised mobility; two rows on links `a` and `b` of
//!   one multibody are coupled by `g_a^T W g_b`, `g = J^T f` (the links of one multibody are
//!   one body of the group union);
//! - `W` folds in the joint motors as rapier solves them (compliant rows, below), so the solve
//!   predicts what the motors will do in rapier's step: a fingertip on a finger held by a
//!   position motor meets the motor's stiffness, not the bare links' inertia. The plugin
//!   applies only the soft impulses, `W_rapier J^T f` (`W_rapier` = rapier's inverse augmented
//!   mass, motors not folded), to the generalised velocities; rapier's motors then make their
//!   own impulses.
//!
//! **A motor** of a free dof `d` is rapier's compliant row (`unit_joint_motor_constraint`): per
//! solver pass of `dt_s = h / N` (`N = num_solver_iterations`), its impulse `lambda_s` (which
//! pushes `qdot_d` along `-1`) satisfies `cfm_s lambda_s = qdot_d + rhs_s`, `rhs_s = erp (q -
//! q_target) - v_target`, with `(erp, cfm_coeff, cfm_gain)` from
//! `MotorModel::combine_coefficients(dt_s, stiffness, damping)` and `cfm_s = w_dd cfm_coeff +
//! cfm_gain` (`w_dd` the dof's own mobility). Over the `N` passes of one step, with the
//! position error growing by `qdot dt_s` per pass, the step's impulse `L` (along `+qdot_d`)
//! satisfies `a L + b qdot_d(end) = c`, `a = cfm_s / N`, `b = 1 + erp dt_s (N - 1) / 2`, `c =
//! -rhs_s(start)`. Eliminating `L`: the generalised mass the solve sees is `M + (b / a) e_d
//! e_d^T` and the motor adds `(c / a) e_d` to the momentum, so the free velocity (no soft
//! impulse) is `qdot_free = (M + B)^-1 (M qdot + C)`. A motor at its force limit
//! (`max_force`) is not modelled as saturated, nor are joint limits or dry joint friction
//! (see the crate README's Limits). Dof couplings (a URDF `<mimic>`) are hard rows of
//! rapier's solver and are folded in exactly ([`couple`]).

use std::collections::HashMap;

use nalgebra::{DMatrix, DVector, Vector3, Vector6};
use rapier3d::prelude::{
    AngVector, ImpulseJointSet, JointMotor, Multibody, MultibodyIndex, MultibodyJointSet,
    MultibodyLink, PhysicsWorld, Pose, RigidBodyHandle, RigidBodySet, RigidBodyType, Vector,
};

use crate::boundary::{to_f32, to_f64};
use crate::fast_hash::FastMap;
use crate::kinematic::{KinematicPath, interpolate};
use crate::mobility::{BodyState, Fold, Generalised, Link, Motor, couple};

/// What a link's entry needs of the world.
pub(crate) struct LinkCtx<'a> {
    /// rapier's multibodies.
    pub multibodies: &'a MultibodyJointSet,
    /// rapier's impulse joints (`jointed`).
    pub impulse_joints: &'a ImpulseJointSet,
    /// The (sub)step \[s\].
    pub h: f64,
    /// A free body's drift time `h (N + 1) / (2N)` \[s\] (`SoftWorld::prepare`; the body
    /// table's free bodies integrate their external accelerations over it).
    pub h_drift: f64,
    /// rapier's solver passes per step (`num_solver_iterations`).
    pub passes: usize,
    /// rapier's Gauss-Seidel sweeps per solver pass (`num_internal_pgs_iterations`).
    pub sweeps: usize,
    /// The world's gravity \[m/s^2\].
    pub gravity: Vector3<f64>,
}

/// The multibodies already in a body table: their host's index.
pub(crate) type Hosts = FastMap<MultibodyIndex, usize>;

/// The link velocity (linear at its centre of mass, angular) of generalised velocity `q`.
fn link_velocity(jac: &DMatrix<f64>, q: &DVector<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let row = |r: usize| (0..jac.ncols()).map(|c| jac[(r, c)] * q[c]).sum::<f64>();
    (
        Vector3::new(row(0), row(1), row(2)),
        Vector3::new(row(3), row(4), row(5)),
    )
}

/// Moves every position-based kinematic body of `kinematic` that is the root of a multibody
/// to fraction `s` of its path now (a teleport; `set_position`).
///
/// rapier 0.36.1 starts its step by putting each multibody's root joint at its root body's
/// *current* pose and writing every link's `next_position` from the multibody
/// (`Multibody::forward_kinematics(bodies, true)` then `update_rigid_bodies_internal`), so a
/// `set_next_kinematic_*` target on a multibody's root is overwritten and the robot's base
/// never moves. Setting the root body's pose is the way rapier takes: the links follow at the
/// start of the pipeline step, without a velocity of their own, and [`link_state`] gives the
/// soft rows that displacement over the (sub)step. A rotation that does not change along the
/// path is kept bit for bit (a slerp between equal rotations is off by an ulp, which reads as
/// a spin of ~1e-3 rad over a 0.2 ms substep). Bodies that are not a multibody's root
/// (impulse-jointed bases, free kinematic jaws) keep rapier's kinematic path.
pub(crate) fn carry_kinematic_roots(world: &mut PhysicsWorld, kinematic: &[KinematicPath], s: f32) {
    for (handle, start, target) in kinematic {
        let is_root = world
            .multibody_joints
            .rigid_body_link(*handle)
            .is_some_and(|l| l.id == 0);
        if !is_root || start == target {
            continue;
        }
        let mut pose = interpolate(start, target, s);
        if start.rotation == target.rotation {
            pose.rotation = target.rotation;
        }
        if let Some(rb) = world.bodies.get_mut(*handle) {
            rb.set_position(pose, true);
        }
    }
}

/// The kinematic target (`next_position`) of every position-based kinematic body that is the
/// root of a multibody, for [`restore_root_targets`] after a pipeline step of rapier's that
/// overwrites them (the plugin's first, zero-length one).
pub(crate) fn kinematic_root_targets(world: &PhysicsWorld) -> Vec<(RigidBodyHandle, Pose)> {
    world
        .bodies
        .iter()
        .filter(|(h, rb)| {
            rb.body_type() == RigidBodyType::KinematicPositionBased
                && world
                    .multibody_joints
                    .rigid_body_link(*h)
                    .is_some_and(|l| l.id == 0)
        })
        .map(|(h, rb)| (h, *rb.next_position()))
        .collect()
}

/// Sets back the targets saved by [`kinematic_root_targets`].
pub(crate) fn restore_root_targets(world: &mut PhysicsWorld, targets: &[(RigidBodyHandle, Pose)]) {
    for (handle, pose) in targets {
        if let Some(rb) = world.bodies.get_mut(*handle) {
            rb.set_next_kinematic_position(*pose);
        }
    }
}

/// The table entry of `handle` if it is an awake dynamic link of a multibody whose mobility
/// rapier has computed (during its last step): its velocity from the multibody's free
/// generalised velocity, its external acceleration, and its link record. `hosts` maps the
/// multibodies already in the table to their host; `next` is the index the entry will have.
/// `None`: not a link (or no mobility yet: seen as a free body, as before).
pub(crate) fn link_state(
    bodies: &RigidBodySet,
    ctx: &LinkCtx<'_>,
    handle: RigidBodyHandle,
    table: &mut [BodyState],
    hosts: &mut Hosts,
    next: usize,
) -> Option<BodyState> {
    let id = *ctx.multibodies.rigid_body_link(handle)?;
    let rb = bodies.get(handle)?;
    if !rb.is_dynamic() || rb.is_sleeping() {
        return None;
    }
    let mb = ctx.multibodies.get_multibody(id.multibody)?;
    let n = mb.ndofs();
    let jl = mb.body_jacobian(id.id);
    if n == 0 || jl.ncols() != n || jl.nrows() != 6 {
        return None;
    }
    let jac = DMatrix::from_fn(6, n, |r, c| jl[(r, c)] as f64);
    let (host, multi) = match hosts.get(&id.multibody) {
        Some(&host) => (host, None),
        None => (next, Some(generalised(mb, bodies, ctx)?)),
    };
    let (qdot, acc, passive) = {
        let g = multi
            .as_ref()
            .or_else(|| table[host].link.as_deref()?.multi.as_ref())?;
        (g.qdot.clone(), g.acc.clone(), g.passive.clone())
    };
    let com = to_f64(rb.mass_properties().world_com);
    let (mut v, mut w) = link_velocity(&jac, &qdot);
    let (mut vp, mut wp) = link_velocity(&jac, &passive);
    if let Some((carried, wr)) = root_carry(bodies, mb, &com, ctx.h) {
        v += carried;
        w += wr;
        vp += carried;
        wp += wr;
    }
    let (a_ext, _) = link_velocity(&jac, &acc);
    if !(v
        .iter()
        .chain(w.iter())
        .chain(a_ext.iter())
        .all(|x| x.is_finite()))
    {
        return None;
    }
    let (multi, slot) = match multi {
        Some(mut g) => {
            hosts.insert(id.multibody, next);
            let slot = g.add(next, jac);
            (Some(g), slot)
        }
        None => {
            let g = table[host]
                .link
                .as_deref_mut()
                .and_then(|l| l.multi.as_mut())?;
            (None, g.add(next, jac))
        }
    };
    Some(BodyState {
        v,
        w,
        inv_m: Vector3::zeros(),
        inv_i: nalgebra::Matrix3::zeros(),
        com,
        a_ext,
        passive: (vp, wp),
        link: Some(Box::new(Link { host, slot, multi })),
    })
}

/// What a kinematic root (a lifted hand) carries a link at `com` \[m\] along with over the
/// coming (sub)step `h` \[s\]: (linear [m/s], angular [rad/s]); `None` if the multibody's root
/// is not kinematic. rapier moves a multibody's links to its root body's pose at the start of
/// its step (`forward_kinematics`), with no velocity, and the plugin moves the root there
/// before each pipeline step ([`carry_kinematic_roots`]). Over the coming (sub)step the links
/// move by the root's target pose minus where the multibody has it now.
fn root_carry(
    bodies: &RigidBodySet,
    mb: &Multibody,
    com: &Vector3<f64>,
    h: f64,
) -> Option<(Vector3<f64>, Vector3<f64>)> {
    let root = mb.root();
    let rr = bodies
        .get(root.rigid_body_handle())
        .filter(|r| r.is_kinematic())?;
    let (now, frame) = (rr.next_position(), root.local_to_world());
    let (axis, mut angle) = (now.rotation * frame.rotation.inverse()).to_axis_angle();
    if angle > std::f32::consts::PI {
        angle -= 2.0 * std::f32::consts::PI;
    }
    let wr = to_f64(axis * angle) / h;
    let vr = to_f64(now.translation - frame.translation) / h;
    let carried = vr + wr.cross(&(com - to_f64(frame.translation)));
    Some((carried, wr))
}

/// The speed that the joint motors of every awake multibody add to each of its dynamic links
/// over the step `ctx.h`, written to `out` (cleared first) by the link's rigid body: (linear
/// at its centre of mass [m/s], angular [rad/s]), `J (qdot - passive)` of the multibody's
/// generalised velocity with the motors folded in as rapier solves them ([`generalised`])
/// and without them; links of multibodies without a motor are left out.
///
/// The detection's prediction distance reads the bodies' stored velocities, and a link's is
/// its multibody's velocity now: the push a position motor gives a finger within rapier's
/// step is not in it. The shipped gripper's fingers, held 20 mm apart by rapier's contacts
/// of their links on the top of a 2 kg box they failed to lift, shut in one step once they
/// cleared it (the joint 13 mm to -1.2 mm, past its limit), their pads never detected
/// before they overlapped: the next step found them 8 mm deep and read 87.9 N where the
/// motor pushes 10 N per pad (softgrip-rapier README, Limits, "A motor's push").
pub(crate) fn motor_push(
    bodies: &RigidBodySet,
    ctx: &LinkCtx<'_>,
    out: &mut FastMap<RigidBodyHandle, (f32, f32)>,
) {
    out.clear();
    for mb in ctx.multibodies.multibodies() {
        if !mb.links().any(|l| motored_dofs(l).next().is_some()) {
            continue;
        }
        let awake = mb.links().any(|l| {
            bodies
                .get(l.rigid_body_handle())
                .is_some_and(|rb| rb.is_dynamic() && !rb.is_sleeping())
        });
        if !awake {
            continue;
        }
        let Some(g) = generalised(mb, bodies, ctx) else {
            continue;
        };
        let push = &g.qdot - &g.passive;
        let n = mb.ndofs();
        for link in mb.links() {
            let handle = link.rigid_body_handle();
            if !bodies.get(handle).is_some_and(|rb| rb.is_dynamic()) {
                continue;
            }
            let jl = mb.body_jacobian(link.link_id());
            if jl.ncols() != n || jl.nrows() != 6 {
                continue;
            }
            let jac = DMatrix::from_fn(6, n, |r, c| jl[(r, c)] as f64);
            let (v, w) = link_velocity(&jac, &push);
            let (v, w) = (v.norm() as f32, w.norm() as f32);
            if v.is_finite() && w.is_finite() && (v > 0.0 || w > 0.0) {
                out.insert(handle, (v, w));
            }
        }
    }
}

/// A multibody's generalised mobility (see the module's docs), expanded from rapier's reduced
/// order (the dofs of its non-kinematic joints) to all its dofs; `None` if rapier has not
/// factorised its mass matrix (before its first step) or it is not finite.
fn generalised(mb: &Multibody, bodies: &RigidBodySet, ctx: &LinkCtx<'_>) -> Option<Generalised> {
    let n = mb.ndofs();
    let (free, w_r) = rapier_mobility(mb)?;
    let r = free.len();
    let m_r = w_r.clone().try_inverse()?;
    // The external acceleration: gravity and the user's forces (not rapier's last
    // `generalized_acceleration`, which holds the plugin's own force of the last step).
    let force = external_force(mb, bodies, ctx.gravity);
    let force_r = DVector::from_fn(r, |k, _| force[free[k]]);
    let acc_r = &w_r * force_r;
    let mut acc = DVector::<f64>::zeros(n);
    for (k, &d) in free.iter().enumerate() {
        acc[d] = acc_r[k];
    }
    // Over the whole (sub)step, not a free body's drift time `h (N + 1) / (2N)`: a link held
    // by its motors has its weight balanced in every solver pass (the two-link finger under
    // gravity read 1.0 % off the law with the drift time, 4.2e-6 with `h`). Motors folded in.
    let q0: Vec<f64> = mb
        .generalized_velocity()
        .iter()
        .zip(acc.iter())
        .map(|(v, a)| *v as f64 + a * ctx.h)
        .collect();
    let q_r = DVector::from_fn(r, |k, _| q0[free[k]]);
    let pos: HashMap<usize, usize> = free.iter().enumerate().map(|(k, &d)| (d, k)).collect();
    let motors = motors(mb, ctx, &w_r, &pos)
        .into_iter()
        .map(|(dof, b, c, max)| Motor {
            k: pos[&dof],
            dof,
            b,
            c,
            max,
            saturated: None,
        })
        .collect();
    let fold = Fold {
        couplings: couplings(mb, &pos),
        free,
        m_r,
        q_r: q_r.clone(),
        motors,
    };
    let (w_eff, qf_r) = fold.fold()?;
    let passive = passive_velocity(&fold.couplings, &pos, &w_r, q_r, &q0);
    let mut mobility = DMatrix::<f64>::zeros(n, n);
    let mut qdot = DVector::from_vec(q0);
    for (a, &da) in fold.free.iter().enumerate() {
        qdot[da] = qf_r[a];
        for (b, &db) in fold.free.iter().enumerate() {
            mobility[(da, db)] = w_eff[(a, b)];
        }
    }
    let finite = mobility.iter().chain(qdot.iter());
    if !finite.into_iter().all(|x| x.is_finite()) {
        return None;
    }
    let mut g = Generalised::new(mobility, qdot, acc);
    g.passive = passive;
    g.fold = Some(fold);
    Some(g)
}

/// The generalised velocity `q0` (all dofs; `q_r` its free dofs, reduced order, `pos` their
/// place) with the dof couplings applied on the bare mobility `w_r`, without the motors: what
/// the multibody does over the step if no motor pushed (`Generalised::passive`).
fn passive_velocity(
    couplings: &[(usize, usize, f64)],
    pos: &HashMap<usize, usize>,
    w_r: &DMatrix<f64>,
    mut q_r: DVector<f64>,
    q0: &[f64],
) -> DVector<f64> {
    let mut w = w_r.clone();
    couple(couplings, &mut w, &mut q_r);
    let mut passive = DVector::from_column_slice(q0);
    for (&d, &k) in pos {
        passive[d] = q_r[k];
    }
    passive
}

/// rapier's inverse augmented mass of `mb` (the mobility its solver uses for a contact or a
/// joint row: `J W J^T`) \[1/kg, 1/(kg m^2)\], symmetrised, in rapier's reduced order (the
/// dofs of its non-kinematic joints, listed first: their indices in `0..ndofs`); `None` if
/// rapier has not factorised it (before its first step) or it has no free dof.
pub(crate) fn rapier_mobility(mb: &Multibody) -> Option<(Vec<usize>, DMatrix<f64>)> {
    let n = mb.ndofs();
    let mut free = Vec::with_capacity(n);
    for link in mb.links() {
        if !link.joint().kinematic {
            let at = link.assembly_id();
            free.extend(at..at + link.joint().ndofs());
        }
    }
    let lu = mb.inv_augmented_mass();
    let r = free.len();
    if r == 0 || lu.l().nrows() != r || free.iter().any(|&d| d >= n) {
        return None;
    }
    let mut w_r = DMatrix::<f64>::zeros(r, r);
    let mut col = DVector::<f32>::zeros(r);
    for c in 0..r {
        col.fill(0.0);
        col[c] = 1.0;
        if !lu.solve_mut(&mut col) {
            return None;
        }
        for k in 0..r {
            w_r[(k, c)] = col[k] as f64;
        }
    }
    Some((free, 0.5 * (&w_r + w_r.transpose())))
}

/// The multibody's dof couplings (a URDF `<mimic>`: `qdot_2 = coeff qdot_1`, a hard row of
/// rapier's solver) as `(k1, k2, coeff)` in the reduced order `pos` (`mobility::couple`
/// applies them).
fn couplings(mb: &Multibody, pos: &HashMap<usize, usize>) -> Vec<(usize, usize, f64)> {
    let mut out = Vec::new();
    for c in mb.couplings() {
        let (Some(l1), Some(l2)) = (mb.link(c.link1), mb.link(c.link2)) else {
            continue;
        };
        let (d1, d2) = (l1.assembly_id() + c.dof1, l2.assembly_id() + c.dof2);
        if let (Some(&k1), Some(&k2)) = (pos.get(&d1), pos.get(&d2)) {
            out.push((k1, k2, c.coeff as f64));
        }
    }
    out
}

/// The generalised force of gravity and the user's forces and torques on a multibody's links.
fn external_force(mb: &Multibody, bodies: &RigidBodySet, gravity: Vector3<f64>) -> DVector<f64> {
    let n = mb.ndofs();
    let mut force = DVector::<f64>::zeros(n);
    for link in mb.links() {
        let Some(rb) = bodies.get(link.rigid_body_handle()) else {
            continue;
        };
        let jl = mb.body_jacobian(link.link_id());
        if jl.ncols() != n || !rb.is_dynamic() {
            continue;
        }
        let f = to_f64(rb.user_force()) + gravity * (rb.gravity_scale() * rb.mass()) as f64;
        let t = to_f64(rb.user_torque());
        for c in 0..n {
            force[c] += (0..3)
                .map(|r| jl[(r, c)] as f64 * f[r] + jl[(r + 3, c)] as f64 * t[r])
                .sum::<f64>();
        }
    }
    force
}

/// The motors of a multibody's free dofs as `(dof, b / a, c / a, max_force h)` (see the
/// module's docs): what each adds to the generalised mass's diagonal \[kg or kg m^2\] and to
/// the momentum, and its largest impulse over the (sub)step (`saturation`).
fn motors(
    mb: &Multibody,
    ctx: &LinkCtx<'_>,
    w_r: &DMatrix<f64>,
    pos: &HashMap<usize, usize>,
) -> Vec<(usize, f64, f64, f64)> {
    let mut out = Vec::new();
    for link in mb.links() {
        let (data, coords) = (&link.joint().data, link.joint().coords());
        for (i, d, motor) in motored_dofs(link) {
            let limits = (data.limit_axes.bits() & (1 << i) != 0)
                .then(|| [data.limits[i].min as f64, data.limits[i].max as f64]);
            let Some(&k) = pos.get(&d) else { continue };
            if let Some((b, c)) = motor_fold(motor, coords[i] as f64, limits, w_r[(k, k)], ctx) {
                out.push((d, b, c, motor.max_force as f64 * ctx.h));
            }
        }
    }
    out
}

/// The motored free dofs of a link's joint (none for a kinematic joint) as `(axis, dof,
/// motor)`: the joint's axis index, the dof's index in the multibody's coordinates (its free
/// axes in order from the link's `assembly_id`), and the axis's motor.
pub(crate) fn motored_dofs(
    link: &MultibodyLink,
) -> impl Iterator<Item = (usize, usize, &JointMotor)> + '_ {
    let joint = link.joint();
    let data = &joint.data;
    let (locked, motored) = (data.locked_axes.bits(), data.motor_axes.bits());
    let free = (0..data.motors.len()).filter(move |i| !joint.kinematic && locked & (1 << i) == 0);
    free.enumerate()
        .filter(move |&(_, i)| motored & (1 << i) != 0)
        .map(move |(n, i)| (i, link.assembly_id() + n, &data.motors[i]))
}

/// One motor at joint position `q` \[rad or m\] as `(b / a, c / a)` (see the module's docs),
/// with the dof's own mobility `w` and the joint's `limits` (which clamp its target velocity,
/// as rapier does); `None` if it has no compliance to fold (zero stiffness and damping).
/// Also an impulse joint's motor (`jointed`), `w` its row's free-body mobility.
pub(crate) fn motor_fold(
    motor: &JointMotor,
    q: f64,
    limits: Option<[f64; 2]>,
    w: f64,
    ctx: &LinkCtx<'_>,
) -> Option<(f64, f64)> {
    let n_pass = ctx.passes.max(1) as f64;
    let dt_s = ctx.h / n_pass;
    let (erp, cfm_coeff, cfm_gain) =
        motor
            .model
            .combine_coefficients(dt_s as f32, motor.stiffness, motor.damping);
    let (erp, cfm_coeff, cfm_gain) = (erp as f64, cfm_coeff as f64, cfm_gain as f64);
    let mut target_vel = motor.target_vel as f64;
    // (`f64::clamp` panics on a NaN bound: a joint position gone non-finite is left to the
    // step's non-finite checks, not turned into a panic here.)
    if let Some([lo, hi]) = limits
        && (lo - q) / dt_s <= (hi - q) / dt_s
    {
        target_vel = target_vel.clamp((lo - q) / dt_s, (hi - q) / dt_s);
    }
    let mut rhs = -target_vel;
    if erp != 0.0 {
        rhs += (q - motor.target_pos as f64) * erp;
    }
    let a = (w * cfm_coeff + cfm_gain) / n_pass;
    let b = 1.0 + erp * dt_s * (n_pass - 1.0) / 2.0;
    let c = -rhs;
    (a > 0.0 && (b / a).is_finite() && (c / a).is_finite()).then(|| (b / a, c / a))
}

/// The stacked wrench (per link of `g`, in its `links` order: force at the centre of mass,
/// torque) that moves the multibody's free dofs as `f` does, of least norm: `J_f (J_f^T
/// J_f)^+ J_f^T f`, `J_f` the links' jacobians stacked (`6 m x r`, the free dofs' columns).
/// `None` for a generalised body without free dofs to project on (a jointed assembly,
/// `jointed`, whose coordinates are its members' own velocities) or if not finite.
///
/// Why: a kinematic palm driving a finger's links into a table or a wedged box asks the
/// coupled solve for forces along directions no joint can move (the palm carries them): 3.2e6
/// N on a 20 g link while every joint's load was about 2.5e-3 N m s. They move nothing in the
/// solve's prediction (`W J^T f`), but handed to rapier as an `f32` force on the link, their
/// rounding alone took the multibody to 3.7e4 rad/s within one substep (crate README, Limits).
/// The part removed is what the fixed or kinematic root carries, as it physically does.
pub(crate) fn joint_space(g: &Generalised, f: &DVector<f64>) -> Option<DVector<f64>> {
    let Some(fold) = g.fold.as_ref() else {
        return assembly_space(g, f);
    };
    let free = &fold.free;
    let (m, r) = (g.links.len(), free.len());
    if r == 0 || f.len() != 6 * m {
        return None;
    }
    let jf = DMatrix::from_fn(6 * m, r, |row, c| g.jacs[row / 6][(row % 6, free[c])]);
    let load = jf.transpose() * f;
    let gram = jf.transpose() * &jf;
    // The gram matrix's eigenvalues are the squared singular values of `J_f`; rapier's `f32`
    // jacobians leave ~1e-7 of |J| of noise along a locked direction (1e-14 squared).
    let largest = gram.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let pinv = gram.pseudo_inverse(JOINT_SPACE_TOLERANCE * largest).ok()?;
    let out = jf * (pinv * load);
    out.iter().all(|x| x.is_finite()).then_some(out)
}

/// [`joint_space`] for a jointed assembly (`jointed`): its coordinates are its members' own
/// velocities (each link's jacobian selects its six), and the directions its joints lock are
/// the null space of its mobility `W` (the Schur complement of its locked rows, which keep
/// `HARD_COMPLIANCE` of their own mobility): the wrench kept is `W^+ W f`, eigenvalues of `W`
/// under [`JOINT_SPACE_TOLERANCE`]`^(1/2)` of the largest taken as locked.
fn assembly_space(g: &Generalised, f: &DVector<f64>) -> Option<DVector<f64>> {
    let n = g.mobility.nrows();
    if f.len() != 6 * g.links.len() || n == 0 {
        return None;
    }
    // The stacked wrench in the assembly's coordinates (`J^T f`) and back (`J p`).
    let mut q = DVector::<f64>::zeros(n);
    for (s, jac) in g.jacs.iter().enumerate() {
        q += jac.transpose() * f.rows(6 * s, 6);
    }
    let w = 0.5 * (&g.mobility + g.mobility.transpose());
    let eig = w.symmetric_eigen();
    let largest = eig.eigenvalues.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    let tol = JOINT_SPACE_TOLERANCE.sqrt() * largest;
    let mut p = DVector::<f64>::zeros(n);
    for (k, &l) in eig.eigenvalues.iter().enumerate() {
        if l > tol {
            let v = eig.eigenvectors.column(k);
            p += v * v.dot(&q);
        }
    }
    let mut out = DVector::<f64>::zeros(f.len());
    for (s, jac) in g.jacs.iter().enumerate() {
        out.rows_mut(6 * s, 6).copy_from(&(jac * &p));
    }
    out.iter().all(|x| x.is_finite()).then_some(out)
}

/// The squared singular value of a stacked link jacobian, relative to the largest, below
/// which [`joint_space`] takes a direction as locked (`1e-10`: singular values under 1e-5 of
/// the largest; `f32` noise on a locked direction is ~1e-7).
const JOINT_SPACE_TOLERANCE: f64 = 1e-10;

/// The largest linear impulse \[N s\] that [`joint_space`] would take off one link of the
/// table's multibodies for the link wrenches `wrenches` (per table index; zero for other
/// bodies): how hard an answer loads links along directions no joint can move.
pub(crate) fn locked_load(bodies: &[BodyState], wrenches: &[Vector6<f64>]) -> f64 {
    let mut removed = 0.0f64;
    for b in bodies {
        let Some(g) = b.link.as_deref().and_then(|l| l.multi.as_ref()) else {
            continue;
        };
        let f = DVector::from_fn(6 * g.links.len(), |row, _| {
            wrenches[g.links[row / 6]][row % 6]
        });
        if f.iter().all(|x| *x == 0.0) {
            continue;
        }
        let Some(p) = joint_space(g, &f) else {
            continue;
        };
        for s in 0..g.links.len() {
            let o = 6 * s;
            let d = Vector3::new(f[o] - p[o], f[o + 1] - p[o + 1], f[o + 2] - p[o + 2]);
            removed = removed.max(d.norm());
        }
    }
    removed
}

/// Replaces each multibody's link wrenches in `net` (per table index \[N s, N m s\]) by
/// their joint-space part ([`joint_space`]), before they go to rapier (`apply_to_rapier`): the
/// part removed is what the fixed or kinematic root carries.
pub(crate) fn project_net(table: &[BodyState], net: &mut [(Vector3<f64>, Vector3<f64>)]) {
    for b in table {
        let Some(g) = b.link.as_deref().and_then(|l| l.multi.as_ref()) else {
            continue;
        };
        let f = DVector::from_fn(6 * g.links.len(), |row, _| {
            let (lin, ang) = &net[g.links[row / 6]];
            if row % 6 < 3 {
                lin[row % 6]
            } else {
                ang[row % 6 - 3]
            }
        });
        if f.iter().all(|x| *x == 0.0) {
            continue;
        }
        let Some(p) = joint_space(g, &f) else {
            continue;
        };
        for (s, &i) in g.links.iter().enumerate() {
            let o = 6 * s;
            let lin = Vector3::new(p[o], p[o + 1], p[o + 2]);
            let ang = Vector3::new(p[o + 3], p[o + 4], p[o + 5]);
            net[i] = (lin, ang);
        }
    }
}

/// A multibody link's user force and torque before the plugin added its soft contacts' force
/// for one pipeline step (restored after it: `restore_forces`).
pub(crate) type SavedForce = (RigidBodyHandle, Vector, AngVector);

/// Applies the soft impulses' net wrench on each link of the table (`net`, per table index:
/// force at the centre of mass, torque \[N s, N m s\]) as a force and torque over the coming
/// pipeline step of `h` \[s\] on the link's rigid body, which rapier's multibody integrates
/// in every one of its solver passes with its joints and motors (`Multibody::
/// update_acceleration`). Applied to the generalised velocities at once instead, a light link
/// held by a motor gets a velocity kick that the motor's damping absorbs within the first pass
/// and returns within the step: a 2 g jaw on a 2e4 N/m motor pressing with 7.7 N ended every
/// step 0.21 mm off its target and moving, the law 32 % off the geometry's compression.
/// The user's force and torque are saved in `saved` first.
pub(crate) fn apply_to_rapier(
    bodies: &mut RigidBodySet,
    table: &[BodyState],
    handles: &[RigidBodyHandle],
    net: &[(Vector3<f64>, Vector3<f64>)],
    h: f64,
    saved: &mut Vec<SavedForce>,
) -> u64 {
    let mut non_finite = 0;
    for ((b, (lin, ang)), handle) in table.iter().zip(net).zip(handles) {
        if b.link.is_none() || (*lin == Vector3::zeros() && *ang == Vector3::zeros()) {
            continue;
        }
        let (f, t) = (to_f32(&(lin / h)), to_f32(&(ang / h)));
        if !(f.is_finite() && t.is_finite()) {
            non_finite += 1;
            continue;
        }
        let Some(rb) = bodies.get_mut(*handle) else {
            continue;
        };
        saved.push((*handle, rb.user_force(), rb.user_torque()));
        rb.add_force(f, true);
        rb.add_torque(t, true);
    }
    non_finite
}

/// Gives the links of `saved` back their user force and torque (`apply_to_rapier`).
pub(crate) fn restore_forces(bodies: &mut RigidBodySet, saved: &mut Vec<SavedForce>) {
    for (handle, f, t) in saved.drain(..) {
        if let Some(rb) = bodies.get_mut(handle) {
            rb.reset_forces(false);
            rb.reset_torques(false);
            rb.add_force(f, false);
            rb.add_torque(t, false);
        }
    }
}
