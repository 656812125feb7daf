//! The contact problem: what the solvers (`solve`, `rigid`) read and write, and its pure
//! kinematics.
//!
//! A contact problem over one (sub)step of size `h` \[s\] is a table of bodies
//! ([`BodyState`]: velocities, inverse mass and inertia or a multibody link, for each kind of
//! body: free, fixed or kinematic (zero inverse mass), multibody link) and the rows between
//! them ([`Row`]: a soft contact's point, normal and tangent basis, its law's force and
//! stiffness, damping, friction and the impulses the solve writes). This module holds no
//! solver: it gives the rows' relative velocities and mobilities on the bodies
//! ([`normal_velocity`], [`normal_mobility`], [`pair_mobility`]) and the static friction
//! spring's velocity equation ([`spring`]). It imports neither `solve` nor `rigid`; both
//! import it.
//!
//! Units: SI, all `f64` (nalgebra): positions \[m\], velocities [m/s], angular velocities
//! [rad/s], inverse masses [1/kg], inverse inertias [1/(kg m^2)], forces \[N\], impulses
//! \[N s\], stiffnesses \[N/m\], damping [N s/m], mobilities [1/kg].

use nalgebra::{Matrix2, Matrix3, Vector3};

use crate::multibody::{self, Link};

/// Velocity state and inverse mass of one body as the solver sees it.
#[derive(Debug, Clone)]
pub(crate) struct BodyState {
    /// Linear velocity [m/s].
    pub v: Vector3<f64>,
    /// Angular velocity [rad/s].
    pub w: Vector3<f64>,
    /// Per-axis inverse mass [1/kg] (zero for fixed, kinematic or sleeping bodies).
    pub inv_m: Vector3<f64>,
    /// World inverse inertia [1/(kg m^2)].
    pub inv_i: Matrix3<f64>,
    /// World centre of mass \[m\].
    pub com: Vector3<f64>,
    /// External acceleration (gravity, user force / m) [m/s^2]; zero if not dynamic.
    pub a_ext: Vector3<f64>,
    /// The body's linear and angular velocity over the (sub)step without the push of the
    /// joint motors that hold it \[m/s, rad/s\]: its velocity now plus its external
    /// accelerations' (what the step's substep count reads, `step::split`). Equal to `(v, w)`
    /// for a free, fixed or kinematic body.
    pub passive: (Vector3<f64>, Vector3<f64>),
    /// A link of a multibody: its response comes from the multibody (`multibody`; `inv_m`
    /// and `inv_i` are then zero). `None`: a free, fixed or kinematic body.
    pub link: Option<Box<Link>>,
}

impl BodyState {
    /// Velocity of the body's material point at `p` (world) [m/s].
    #[inline]
    pub(crate) fn vel_at(&self, p: &Vector3<f64>) -> Vector3<f64> {
        self.v + self.w.cross(&(p - self.com))
    }

    /// Applies the impulse `imp` \[N s\] at `p` (world) to a free body's velocities (not a
    /// multibody link's: `multibody::apply`).
    #[inline]
    pub(crate) fn apply(&mut self, p: &Vector3<f64>, imp: &Vector3<f64>) {
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

    /// Whether impulses move the body (a free dynamic body or a multibody link).
    pub(crate) fn is_dynamic(&self) -> bool {
        self.inv_m.iter().any(|m| *m > 0.0) || self.link.is_some()
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
}

/// The body at index `i` of the body table (`None`: fixed, no body).
pub(crate) fn body(bodies: &[BodyState], i: Option<usize>) -> Option<&BodyState> {
    i.map(|i| &bodies[i])
}

/// Relative velocity of a row's bodies at its contact point (fingertip - other, world) [m/s].
pub(crate) fn rel_vel(bodies: &[BodyState], r: &Row) -> Vector3<f64> {
    let va = body(bodies, r.a)
        .map(|b| b.vel_at(&r.p))
        .unwrap_or_default();
    let vb = body(bodies, r.b)
        .map(|b| b.vel_at(&r.p))
        .unwrap_or_default();
    va - vb
}

/// Relative mobility between directions of rows i and k (sum over the bodies they share).
pub(crate) fn pair_mobility(
    bodies: &[BodyState],
    ri: &Row,
    di: &Vector3<f64>,
    rk: &Row,
    dk: &Vector3<f64>,
) -> f64 {
    let mut m = 0.0;
    for (bi, si) in [(ri.a, 1.0), (ri.b, -1.0)] {
        for (bk, sk) in [(rk.a, 1.0), (rk.b, -1.0)] {
            let (Some(x), Some(y)) = (bi, bk) else {
                continue;
            };
            if x == y && bodies[x].link.is_none() {
                m += si * sk * bodies[x].mobility(&ri.p, di, &rk.p, dk);
            } else if let Some(w) = multibody::pair(
                bodies,
                x,
                (di, &(ri.p - bodies[x].com).cross(di)),
                y,
                (dk, &(rk.p - bodies[y].com).cross(dk)),
            ) {
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
