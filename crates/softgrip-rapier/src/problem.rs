//! The contact problem: what the solvers (`solve`, `rigid`) read and write, and its pure
//! kinematics.
//!
//! A contact problem over one (sub)step of size `h` \[s\] is a table of bodies
//! ([`BodyState`], from `mobility`: velocities, and the mobility of each kind of body: free,
//! fixed or kinematic (zero inverse mass), multibody link or jointed assembly) and the rows
//! between them: [`Row`], a soft contact's point, normal and tangent basis, its law's force and
//! stiffness, damping, friction and the impulses the solve writes; [`RigidRow`], one of
//! rapier's touching contacts of a body the soft contacts move. This module holds no solver:
//! it gives the rows' relative velocities and mobilities on the bodies ([`normal_velocity`],
//! [`normal_mobility`], [`pair_mobility`]) and the static friction spring's velocity equation
//! ([`spring`]). It imports only `mobility`; the solvers (`solve`, `rigid`, `saturation`) and
//! the plugin's step import it.
//!
//! Units: SI, all `f64` (nalgebra): positions \[m\], velocities [m/s], angular velocities
//! [rad/s], inverse masses [1/kg], inverse inertias [1/(kg m^2)], forces \[N\], impulses
//! \[N s\], stiffnesses \[N/m\], damping [N s/m], mobilities [1/kg].

use nalgebra::{Matrix2, Vector3};
use rapier3d::prelude::ColliderHandle;

use crate::mobility::{self, BodyState};

/// A contact's impulses over the previous (sub)step, which warm-start the coupled solve
/// (`rigid::solve_coupled`): kept in the contact's state between (sub)steps (a soft contact's
/// in its `PairState`, a rigid support's in `Scratch::rigid_warm`, keyed by rapier's contact
/// pair and the point's feature ids).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Warm {
    /// Normal impulse \[N s\].
    pub jn: f64,
    /// Tangential impulse (world) \[N s\].
    pub jt: Vector3<f64>,
    /// Torsional impulse about the normal [N m s].
    pub jtw: f64,
    /// The (sub)step they are over \[s\], > 0.
    pub h: f64,
}

impl Warm {
    /// The impulses scaled to a (sub)step of `h` \[s\] (the same forces): normal, along
    /// `t1`, along `t2`, torsion \[N s, N m s\]; zeros if not finite.
    pub(crate) fn over(&self, h: f64, t1: &Vector3<f64>, t2: &Vector3<f64>) -> [f64; 4] {
        let s = h / self.h;
        let out = [
            self.jn * s,
            self.jt.dot(t1) * s,
            self.jt.dot(t2) * s,
            self.jtw * s,
        ];
        if out.iter().all(|x| x.is_finite()) {
            out
        } else {
            [0.0; 4]
        }
    }
}

/// One contact prepared for the solve, and its impulses after it.
#[derive(Debug, Clone)]
pub(crate) struct Row {
    /// Index of the fingertip's body in the body table (`None`: fixed, no body).
    pub a: Option<usize>,
    /// Index of the other body.
    pub b: Option<usize>,
    /// Contact point (world) \[m\].
    pub p: Vector3<f64>,
    /// Unit normal, other -> fingertip.
    pub n: Vector3<f64>,
    /// Tangent basis.
    pub t1: Vector3<f64>,
    /// Tangent basis.
    pub t2: Vector3<f64>,
    /// Law force F \[N\].
    pub force: f64,
    /// Law stiffness K \[N/m\].
    pub stiffness: f64,
    /// Damping coefficient c = alpha F [N s/m].
    pub damping: f64,
    /// Integration blend in [0, 1].
    pub theta: f64,
    /// Friction coefficient.
    pub mu: f64,
    /// Torsion limit per unit normal impulse, `ContactPatch::torsion_limit(mu, 1)` \[m\]
    /// (`(3 pi/16) mu a` for Hertz's pressure shape).
    pub torsion_arm: f64,
    /// Stretch `s` of the static friction spring at the step's start: the contact's
    /// tangential offset from its anchor on the other body (world, in the tangent plane) \[m\].
    pub offset: Vector3<f64>,
    /// Stiffness `k_t = 8 G* a` of the static friction spring (Mindlin; `G*` the pair's
    /// effective shear modulus, `a` the law's contact radius) \[N/m\], >= 0 (0, the default:
    /// the hard stick with its positional correction, [`spring`]).
    pub k_t: f64,
    /// Damping `c_t` of the static friction spring [N s/m], >= 0: the normal's `c k_t / K`
    /// (the same time constant as the normal's Hunt-Crossley damping).
    pub c_t: f64,
    /// Relative tangential velocity (fingertip - other, in the tangent plane) at the end of
    /// the step [m/s]: the slip that stretches the friction spring (`step`).
    pub vt_end: Vector3<f64>,
    /// Normal impulse \[N s\], >= 0.
    pub jn: f64,
    /// Tangential impulse (world, in the tangent plane) \[N s\].
    pub jt: Vector3<f64>,
    /// Torsional impulse about n [N m s].
    pub jtw: f64,
    /// Friction saturated (sliding).
    pub sliding: bool,
    /// Normal separation velocity at the end of the step [m/s].
    pub vn_end: f64,
    /// The compression is past the law's validity range (`Regime::Extended`).
    pub extended: bool,
    /// The compression is past the law's wall: a rigid row (`step::rigid_past_wall`).
    pub past_wall: bool,
    /// Inverse tangential mobility (`None`: no tangential mobility) and torsional mobility
    /// [1/(kg m^2)]: constant over a solve, computed once at its start.
    pub friction_mobility: Option<(Option<Matrix2<f64>>, f64)>,
    /// A contact beginning within the step: the compression its law is linearised at \[m\]
    /// (0: at the start; `step::onset`).
    pub lin: f64,
    /// Its impulses of the previous (sub)step (`None`: a new contact), the coupled solve's
    /// start.
    pub warm: Option<Warm>,
    /// The normal's effective mobility given the rigid rows that held in its coupled solve
    /// (`rigid::solve_coupled`: rapier's active normals and sticking friction pairs, a Schur
    /// complement of the rows' mutual mobility) \[1/kg\]; `None` where the contact was not
    /// solved coupled, no rigid row held, or a body of its group is a jointed link.
    pub supported_mobility: Option<f64>,
}

/// The body at index `i` of the body table (`None`: fixed, no body).
pub(crate) fn body(bodies: &[BodyState], i: Option<usize>) -> Option<&BodyState> {
    i.map(|i| &bodies[i])
}

/// Relative velocity of a row's bodies at its contact point (fingertip - other, world) [m/s].
pub(crate) fn rel_vel(bodies: &[BodyState], r: &Row) -> Vector3<f64> {
    rel_vel_between(bodies, (r.a, r.b, &r.p))
}

/// Relative velocity \[m/s\] of a row's two bodies at its point (`ends`: body a - body b,
/// world; a fixed side moves at 0): a soft row's ([`rel_vel`]) and a rigid row's alike.
pub(crate) fn rel_vel_between(bodies: &[BodyState], (a, b, p): RowEnds<'_>) -> Vector3<f64> {
    let at = |i| body(bodies, i).map(|b| b.vel_at(p)).unwrap_or_default();
    at(a) - at(b)
}

/// Relative mobility between directions of rows i and k (sum over the bodies they share).
#[inline]
pub(crate) fn pair_mobility(
    bodies: &[BodyState],
    ri: &Row,
    di: &Vector3<f64>,
    rk: &Row,
    dk: &Vector3<f64>,
) -> f64 {
    mobility_between(bodies, (ri.a, ri.b, &ri.p), di, (rk.a, rk.b, &rk.p), dk)
}

/// A row's two bodies (table indices, `None`: fixed) and its contact point (world) \[m\].
pub(crate) type RowEnds<'a> = (Option<usize>, Option<usize>, &'a Vector3<f64>);

/// Relative mobility \[1/kg\] between direction `di` of the row with ends `i` and direction
/// `dk` of the row with ends `k` (sum over the bodies they share): the relative velocity
/// change along `di` at `i`'s point from a unit impulse along `dk` at `k`'s point (a soft
/// row's and a rigid row's alike, [`pair_mobility`]).
#[inline]
pub(crate) fn mobility_between(
    bodies: &[BodyState],
    (ia, ib, ip): RowEnds<'_>,
    di: &Vector3<f64>,
    (ka, kb, kp): RowEnds<'_>,
    dk: &Vector3<f64>,
) -> f64 {
    let mut m = 0.0;
    for (bi, si) in [(ia, 1.0), (ib, -1.0)] {
        for (bk, sk) in [(ka, 1.0), (kb, -1.0)] {
            let (Some(x), Some(y)) = (bi, bk) else {
                continue;
            };
            if x == y && bodies[x].link.is_none() {
                m += si * sk * bodies[x].mobility(ip, di, kp, dk);
            } else if mobility::same_multibody(bodies, x, y)
                && let Some(w) = mobility::pair(
                    bodies,
                    x,
                    (di, &(ip - bodies[x].com).cross(di)),
                    y,
                    (dk, &(kp - bodies[y].com).cross(dk)),
                )
            {
                m += si * sk * w;
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

/// Normal separation velocity of a row [m/s] (> 0 separating) from its bodies' velocities
/// without their joint motors' push ([`BodyState::passive`]).
pub(crate) fn passive_normal_velocity(bodies: &[BodyState], r: &Row) -> f64 {
    let at = |i: Option<usize>| {
        body(bodies, i)
            .map(|b| b.passive.0 + b.passive.1.cross(&(r.p - b.com)))
            .unwrap_or_default()
    };
    (at(r.a) - at(r.b)).dot(&r.n)
}

/// Normal separation velocity of a row [m/s] (> 0 separating).
pub(crate) fn normal_velocity(bodies: &[BodyState], r: &Row) -> f64 {
    rel_vel(bodies, r).dot(&r.n)
}

/// The static friction spring of a row over a step `h` as a compliant velocity equation:
/// its impulse `j_t = h [-k_t s(end) - c_t v_t(end)]` with `s(end) = s + h v_t(end)` (the
/// stretch integrated implicitly) is `v_t(end) + C j_t = target`, `C = 1 / (h (h k_t + c_t))`
/// \[1/kg\] and `target = -k_t s / (h k_t + c_t)` [m/s] (world, in the tangent plane). A row
/// without a spring (`k_t = 0`, the default, `SoftContacts::set_friction_spring`): a hard
/// stick, `C = 0`, with a positional correction `target = -FRICTION_BETA s / h`.
pub(crate) fn spring(r: &Row, h: f64) -> (f64, Vector3<f64>) {
    let stiff = h * r.k_t + r.c_t;
    if r.k_t > 0.0 && stiff > 0.0 && h > 0.0 {
        (1.0 / (h * stiff), -r.offset * (r.k_t / stiff))
    } else {
        (0.0, -FRICTION_BETA * r.offset / h)
    }
}

/// Positional correction factor of the hard static friction (fraction of the anchor offset
/// removed per step) where it is not a spring ([`spring`]).
pub(crate) const FRICTION_BETA: f64 = 0.3;

/// One of rapier's touching contact points between a dynamic body `a` that the soft contacts
/// move (directly or through other rigid contacts) and another body `b` (`None`: fixed).
#[derive(Debug, Clone)]
pub(crate) struct RigidRow {
    pub a: usize,
    pub b: Option<usize>,
    /// Contact point (world) \[m\].
    pub p: Vector3<f64>,
    /// Unit normal, b -> a.
    pub n: Vector3<f64>,
    /// Tangent basis.
    pub t1: Vector3<f64>,
    /// Tangent basis.
    pub t2: Vector3<f64>,
    /// rapier's friction coefficient of the manifold.
    pub mu: f64,
    /// The normal impulse the plugin applies (the soft contacts' part) \[N s\].
    pub jn: f64,
    /// The tangential impulse the plugin applies \[N s\].
    pub jt: Vector3<f64>,
    /// Which contact point it is, kept from (sub)step to (sub)step: rapier's pair (collider
    /// handles) and the point's feature ids.
    pub key: Option<RigidKey>,
    /// The point's impulses of the previous (sub)step, without the soft contacts (rapier's
    /// part) and with them (`None`: a new point): the coupled solve's warm start.
    pub warm: Option<[Warm; 2]>,
    /// The same, as the coupled solve answered them this (sub)step (`None`: not answered).
    pub solved: Option<[Warm; 2]>,
    /// rapier's contact softness at this point over the coming (sub)step
    /// ([`ContactSoftness`]); `None`: a hard row (a separated point, which rapier solves
    /// rigidly, or a point whose bodies the soft contacts do not unload: `Step::
    /// prepare_rigid`).
    pub softness: Option<ContactSoftness>,
    /// How far the point's bodies may close its gap within the (sub)step without an impulse
    /// from rapier \[m\]: its gap at the start poses past half the touch tolerance
    /// ([`TOUCH_FRACTION`]), else 0. Read only by `rigid`'s solve of rapier's own part.
    pub closable: f64,
}

/// The share of rapier's allowed linear error (`IntegrationParameters::allowed_linear_error`,
/// 5 mm at rapier 0.36's defaults) within which a rigid contact point touches and joins the
/// coupled solve as a hard row asking `v(end) >= 0`. A point further apart is left to rapier's
/// own solver, whose speculative contact lets it close its gap and stops it there. The deadzone
/// keeps the redundant rows of a resting box (four corners on a table, their gaps f32 noise
/// apart) asking for one rigid motion.
///
/// Why (session 34): before, every point within the whole allowed error asked `v(end) >= 0`,
/// so a body 0.5-5 mm short of another was held there as if touching. The xArm's finger links,
/// 4 mm from the box they closed on, stopped there: every coupled solve of the closing was
/// degenerate and the box, let go to rapier, was kicked 1.2 mm up and turned 0.15 rad in one
/// step (with rapier's contact recycling off; on, a stale manifold hid the links' points: the
/// points were read by their recycled `dist`, not their gap at the current poses, until
/// session 35, `step::push_pair_points`). A
/// box pushed towards a wall from 1-4.5 mm was held at its start gap while the pad pushing it
/// was crushed (89-745 N; `tests/gap_rows.rs`). Session 33 tried keeping such points in the
/// solve with the target `v(end) >= -(gap - TOUCH_FRACTION slop) / h` (rapier's speculative
/// rule): the xArm held, but the pushed box was thrown at 2.2-82 m/s from start gaps of
/// 2.5-4.5 mm, so that rule was reverted.
pub(crate) const TOUCH_FRACTION: f64 = 0.1;

/// What rapier 0.36's contact constraint does with a penetrating point over a pipeline step of
/// `h` seconds, as one row of the coupled solve (`rigid`). rapier runs `N`
/// (`num_solver_iterations`) substeps of `dt = h / N`; in each, its biased pass solves the
/// point's normal impulse `lambda` to the fixed point of `lambda <- cfm_factor (lambda - m
/// (v + rhs))` (`contact_constraint_element.rs`: `cfm_factor = 1 / (1 + cfm_coeff)`, `m` the
/// point's projected mass), i.e. `v + rhs + cfm_coeff w lambda = 0` (`w = 1 / m`), with
/// `rhs = clamp(dist erp_inv_dt, -max_corrective_velocity, 0)` for a penetration `dist < 0`
/// (`contact_with_coulomb_friction.rs`, `update`: no slop deadzone), and integrates the poses
/// with that biased velocity. Over the `N` substeps of a steady hold the impulse of the step is
/// `J = N lambda`: the row `v(end) + cfm_coeff / N w J = target`, `target = -rhs`.
/// `erp_inv_dt` and `cfm_coeff` are `SpringCoefficients::{erp_inv_dt, cfm_coeff}(dt)` of
/// `static_contact_softness` where the other side is not dynamic, else of `contact_softness`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ContactSoftness {
    /// The row's target end velocity, `min(-dist erp_inv_dt, max_corrective_velocity)`
    /// \[m/s\], >= 0.
    pub target: f64,
    /// The row's compliance relative to its own mobility, `cfm_coeff(dt) / N`, > 0.
    pub compliance: f64,
}

impl ContactSoftness {
    /// rapier's softness of a point `gap` \[m\] apart (negative: penetrating) over a
    /// pipeline step of `h` \[s\] with integration parameters `p`, against a body that is
    /// not dynamic (`fixed_other`: the table) or a dynamic one. `None` where rapier solves
    /// the point rigidly (`gap >= 0`) or the coefficients are not finite and positive.
    pub(crate) fn of(
        p: &rapier3d::dynamics::IntegrationParameters,
        h: f64,
        gap: f64,
        fixed_other: bool,
    ) -> Option<Self> {
        if !(gap < 0.0) {
            return None;
        }
        let n = p.num_solver_iterations.max(1) as f64;
        let dt = (h / n) as f32;
        let s = if fixed_other {
            p.static_contact_softness
        } else {
            p.contact_softness
        };
        let (erp_inv_dt, cfm) = (s.erp_inv_dt(dt) as f64, s.cfm_coeff(dt) as f64);
        let max_v = p.max_corrective_velocity() as f64;
        let target = (-gap * erp_inv_dt).min(max_v);
        let compliance = cfm / n;
        (target.is_finite() && target >= 0.0 && compliance.is_finite() && compliance > 0.0)
            .then_some(Self { target, compliance })
    }
}

/// A rigid contact point's persistent id: rapier's collider pair and the point's feature ids
/// on each collider (`TrackedContact::fid1`, `fid2`).
pub(crate) type RigidKey = (ColliderHandle, ColliderHandle, u32, u32);

impl RigidRow {
    pub(crate) fn new(
        a: usize,
        b: Option<usize>,
        p: Vector3<f64>,
        n: Vector3<f64>,
        mu: f64,
    ) -> Self {
        let t1 = if n.x.abs() < 0.9 {
            n.cross(&Vector3::x()).normalize()
        } else {
            n.cross(&Vector3::y()).normalize()
        };
        Self {
            a,
            b,
            p,
            n,
            t1,
            t2: n.cross(&t1),
            mu,
            jn: 0.0,
            jt: Vector3::zeros(),
            key: None,
            warm: None,
            solved: None,
            softness: None,
            closable: 0.0,
        }
    }
}
