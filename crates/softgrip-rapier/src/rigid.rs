//! The soft contacts of a body that rests on rapier's rigid contacts (a box on a table pressed
//! by a fingertip): one coupled direct solve of the soft rows and of rapier's touching contacts
//! of the bodies they move, normal and friction.
//!
//! **Why.** The soft impulse over a step is implicit in the bodies' end velocity, `j = h [F -
//! D v(end)]`, and `v(end)` depends on the bodies' mobility. A box on the table, pressed down
//! by a fingertip, cannot move down. Seen as free, it falls away under gravity within the
//! step, the predicted separation outweighs the law's force and the impulse is zero: the tip
//! sank through the box with no force at all (`tests/press_on_table.rs`). With rapier's
//! touching contacts in the solve as hard rows, the soft impulses see the constrained
//! mobility and carry the law's force.
//!
//! **The rows.** Every scalar unknown is a row with a Jacobian on (at most) two bodies:
//! - a soft contact's normal: `j + h D (W j) = h (F - D v0)` (as in `solve`), its two
//!   tangential impulses and its torsion, which target the same velocities as `solve`'s
//!   friction sweep (zero relative tangential velocity plus the anchor correction, zero
//!   relative spin) with the compliance `1 / (h D)` of the normal row: a box held fast by the
//!   table and a kinematic fingertip cannot both meet a tip's anchor correction, and a hard
//!   row would then take an unbounded impulse; with the compliance the anchor pulls with the
//!   stiffness `beta D / h` (about `0.3 K`, a tangential stiffness of the order of the
//!   normal one, as Mindlin's). Where the other body is free the compliance changes the
//!   friction impulse by `1 / (1 + h D w)`, a few 1e-4;
//! - a rigid contact's normal (`v(end) >= 0`, hard) and its two tangential impulses (`v_t(end) =
//!   0`, hard), in rapier's friction disk `mu j_n` (`mu` the manifold's).
//!
//! The linear system is solved by a dense LU with an active set: a normal with a negative
//! impulse leaves, one whose end velocity is penetrating enters; a friction pair past its disk
//! slides (its impulse fixed on the disk, opposite to its sliding velocity), until no set
//! changes (at most [`MAX_PASSES`]). The four corners of a box on a table are redundant (twelve
//! rows for six degrees of freedom): each hard row's diagonal carries [`RIGID_COMPLIANCE`] of
//! its own mobility, which picks the least-impulse distribution and changes the soft impulses
//! by that fraction at most. The hard rows all target `v(end) = 0` (not the point's
//! sub-tolerance gap): redundant rows are consistent only if they ask for one rigid motion.
//!
//! **Who applies what.** The rigid rows' impulses without any soft contact (the bodies'
//! weight on the table, `rest`) are rapier's: its own solver makes them, its contact forces
//! and events see them. The part the soft contacts add (`j - rest`) is applied by the plugin
//! with the soft impulses: left to rapier, a kick of `h F / m` (6 m/s for a 16 g box under 6 N
//! at 60 Hz) is only partly cancelled per solver pass by rapier's soft contact constraint, and
//! the box sank into the table and was thrown out.

use nalgebra::{DMatrix, DVector, Vector2, Vector3};

use crate::solve::{BodyState, Row};

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
}

impl RigidRow {
    pub(crate) fn new(a: usize, b: Option<usize>, p: Vector3<f64>, n: Vector3<f64>, mu: f64) -> Self {
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
        }
    }
}

/// Relative diagonal compliance of a hard row (see the module's docs).
const RIGID_COMPLIANCE: f64 = 1e-9;
fn soft_compliance() -> f64 {
    std::env::var("SG_C").ok().and_then(|s| s.parse().ok()).unwrap_or(1e-3)
}

/// Most active-set passes of one coupled solve.
const MAX_PASSES: usize = 24;

/// What a scalar row is.
#[derive(Debug, Clone, Copy)]
enum Kind {
    /// A soft normal: `force`, `d = theta K h + c`.
    SoftNormal { force: f64, d: f64 },
    /// A hard unilateral normal.
    HardNormal,
    /// A tangential impulse of the contact whose normal is row `normal`, paired with row
    /// `other` (its other tangent), in the disk `mu j_normal`.
    Tangent { normal: usize, other: usize, mu: f64 },
    /// A torsion about the normal of row `normal`, limited by `arm j_normal`.
    Torsion { normal: usize, arm: f64 },
}

/// A scalar row: Jacobian on body a (`lin`, `ang_a`) and on body b (`-lin`, `-ang_b`).
#[derive(Debug, Clone, Copy)]
struct Scalar {
    a: Option<usize>,
    b: Option<usize>,
    lin: Vector3<f64>,
    ang_a: Vector3<f64>,
    ang_b: Vector3<f64>,
    kind: Kind,
    /// Target end velocity [m/s or rad/s].
    target: f64,
    /// Diagonal compliance relative to the row's own mobility.
    compliance: f64,
}

impl Scalar {
    fn point(
        bodies: &[BodyState],
        a: Option<usize>,
        b: Option<usize>,
        p: &Vector3<f64>,
        d: &Vector3<f64>,
        kind: Kind,
    ) -> Self {
        let arm = |i: Option<usize>| {
            i.map(|i| (p - bodies[i].com).cross(d))
                .unwrap_or_default()
        };
        Self {
            a,
            b,
            lin: *d,
            ang_a: arm(a),
            ang_b: arm(b),
            kind,
            target: 0.0,
            compliance: RIGID_COMPLIANCE,
        }
    }

    /// The Jacobian of this row on body `i` (sign included), if it acts on it.
    fn on(&self, i: usize) -> Option<(f64, Vector3<f64>, Vector3<f64>)> {
        if self.a == Some(i) {
            Some((1.0, self.lin, self.ang_a))
        } else if self.b == Some(i) {
            Some((-1.0, self.lin, self.ang_b))
        } else {
            None
        }
    }

    fn velocity(&self, bodies: &[BodyState]) -> f64 {
        let mut v = 0.0;
        for (i, s) in [(self.a, 1.0), (self.b, -1.0)] {
            if let Some(i) = i {
                let (lin, ang) = if s > 0.0 {
                    (self.lin, self.ang_a)
                } else {
                    (self.lin, self.ang_b)
                };
                v += s * (lin.dot(&bodies[i].v) + ang.dot(&bodies[i].w));
            }
        }
        v
    }

    fn apply(&self, bodies: &mut [BodyState], j: f64) {
        for (i, s, ang) in [(self.a, 1.0, self.ang_a), (self.b, -1.0, self.ang_b)] {
            if let Some(i) = i {
                let b = &mut bodies[i];
                b.v += b.inv_m.component_mul(&self.lin) * (s * j);
                b.w += b.inv_i * ang * (s * j);
            }
        }
    }
}

/// Mobility between two scalar rows (sum over the bodies they share).
fn mobility(bodies: &[BodyState], x: &Scalar, y: &Scalar) -> f64 {
    let mut m = 0.0;
    for i in [x.a, x.b].into_iter().flatten() {
        if let (Some((sx, lx, ax)), Some((sy, ly, ay))) = (x.on(i), y.on(i)) {
            let b = &bodies[i];
            m += sx * sy * (lx.dot(&b.inv_m.component_mul(&ly)) + ax.dot(&(b.inv_i * ay)));
        }
    }
    m
}

/// A row's state in the active set.
#[derive(Debug, Clone, Copy, PartialEq)]
enum State {
    /// Its equation holds.
    Active,
    /// Its impulse is fixed.
    Fixed(f64),
}

/// Reusable buffers of the coupled solve.
#[derive(Debug, Clone, Default)]
pub(crate) struct CoupledScratch {
    scalars: Vec<Scalar>,
    state: Vec<State>,
}

/// The scalar rows of soft rows `soft` and rigid rows `rigid` (`rigid` only: `soft` empty),
/// with their index of the first scalar of each soft row.
fn build(
    bodies: &[BodyState],
    soft: &[Row],
    rigid: &[RigidRow],
    h: f64,
    out: &mut Vec<Scalar>,
    first: &mut Vec<usize>,
) {
    out.clear();
    first.clear();
    for r in soft {
        let nrm = out.len();
        first.push(nrm);
        let d = r.theta * r.stiffness * h + r.damping;
        out.push(Scalar::point(
            bodies,
            r.a,
            r.b,
            &r.p,
            &r.n,
            Kind::SoftNormal { force: r.force, d },
        ));
        if r.mu > 0.0 {
            let target = -crate::solve::FRICTION_BETA * r.offset / h;
            for (k, t) in [r.t1, r.t2].iter().enumerate() {
                let mut s = Scalar::point(
                    bodies,
                    r.a,
                    r.b,
                    &r.p,
                    t,
                    Kind::Tangent {
                        normal: nrm,
                        other: nrm + 2 - k,
                        mu: r.mu,
                    },
                );
                s.target = target.dot(t);
                s.compliance = soft_compliance();
                out.push(s);
            }
            if r.torsion_arm > 0.0 {
                out.push(Scalar {
                    a: r.a,
                    b: r.b,
                    lin: Vector3::zeros(),
                    ang_a: r.n,
                    ang_b: r.n,
                    kind: Kind::Torsion {
                        normal: nrm,
                        arm: r.torsion_arm,
                    },
                    target: 0.0,
                    compliance: soft_compliance(),
                });
            }
        }
    }
    for r in rigid {
        let nrm = out.len();
        out.push(Scalar::point(
            bodies,
            Some(r.a),
            r.b,
            &r.p,
            &r.n,
            Kind::HardNormal,
        ));
        if r.mu > 0.0 {
            for (k, t) in [r.t1, r.t2].iter().enumerate() {
                out.push(Scalar::point(
                    bodies,
                    Some(r.a),
                    r.b,
                    &r.p,
                    t,
                    Kind::Tangent {
                        normal: nrm,
                        other: nrm + 2 - k,
                        mu: r.mu,
                    },
                ));
            }
        }
    }
}

/// Solves the scalar rows from the body velocities `bodies`, returning their impulses (`None`
/// if not finite).
fn solve_scalars(
    bodies: &[BodyState],
    rows: &[Scalar],
    h: f64,
    state: &mut Vec<State>,
) -> Option<Vec<f64>> {
    let m = rows.len();
    let v0: Vec<f64> = rows.iter().map(|r| r.velocity(bodies)).collect();
    let w = DMatrix::from_fn(m, m, |i, k| mobility(bodies, &rows[i], &rows[k]));
    state.clear();
    state.extend(rows.iter().zip(&v0).map(|(r, v)| match r.kind {
        Kind::SoftNormal { force, d } => {
            if h * (force - d * v) > 0.0 {
                State::Active
            } else {
                State::Fixed(0.0)
            }
        }
        _ => State::Active,
    }));
    let mut j = vec![0.0; m];
    for _ in 0..MAX_PASSES {
        let mut a = DMatrix::<f64>::zeros(m, m);
        let mut b = DVector::<f64>::zeros(m);
        for i in 0..m {
            match (state[i], rows[i].kind) {
                (State::Fixed(x), _) => {
                    a[(i, i)] = 1.0;
                    b[i] = x;
                }
                (State::Active, Kind::SoftNormal { force, d }) => {
                    for k in 0..m {
                        a[(i, k)] = h * d * w[(i, k)];
                    }
                    a[(i, i)] += 1.0;
                    b[i] = h * (force - d * v0[i]);
                }
                (State::Active, _) if w[(i, i)] == 0.0 => {
                    // No mobility at all: the row cannot act.
                    a[(i, i)] = 1.0;
                }
                (State::Active, _) => {
                    for k in 0..m {
                        a[(i, k)] = w[(i, k)];
                    }
                    a[(i, i)] += rows[i].compliance * w[(i, i)];
                    b[i] = rows[i].target - v0[i];
                }
            }
        }
        let x = a.lu().solve(&b)?;
        if !x.iter().all(|v| v.is_finite()) {
            return None;
        }
        j.copy_from_slice(x.as_slice());
        if std::env::var("SG_DEBUG").is_ok() {
            eprintln!("   pass j {:?}", j.iter().map(|x| format!("{x:.3e}")).collect::<Vec<_>>());
            eprintln!("   state {:?}", state);
        }
        if !update(rows, &v0, &w, &j, h, state) {
            break;
        }
    }
    Some(j)
}

/// Updates the active set from the impulses `j`; returns whether it changed.
fn update(
    rows: &[Scalar],
    v0: &[f64],
    w: &DMatrix<f64>,
    j: &[f64],
    h: f64,
    state: &mut [State],
) -> bool {
    let m = rows.len();
    let v_end = |i: usize| v0[i] + (0..m).map(|k| w[(i, k)] * j[k]).sum::<f64>();
    let mut changed = false;
    for i in 0..m {
        match rows[i].kind {
            Kind::SoftNormal { force, d } => match state[i] {
                State::Active if j[i] < 0.0 => {
                    state[i] = State::Fixed(0.0);
                    changed = true;
                }
                State::Fixed(_) => {
                    let rhs = h * (force - d * v0[i]);
                    let resid = rhs - h * d * (v_end(i) - v0[i]);
                    if resid > 1e-12 * rhs.abs().max(1e-300) && resid > 0.0 {
                        state[i] = State::Active;
                        changed = true;
                    }
                }
                _ => {}
            },
            Kind::HardNormal => match state[i] {
                State::Active if j[i] < 0.0 => {
                    state[i] = State::Fixed(0.0);
                    changed = true;
                }
                State::Fixed(_) => {
                    let v = v_end(i);
                    if v < -1e-9 * v0[i].abs().max(1e-9) {
                        state[i] = State::Active;
                        changed = true;
                    }
                }
                _ => {}
            },
            Kind::Tangent { normal, other, mu } => {
                if other < i {
                    continue; // the pair is handled at its first tangent
                }
                let limit = mu * j[normal].max(0.0);
                let jt = Vector2::new(j[i], j[other]);
                let fixed = match (state[i], state[other]) {
                    (State::Fixed(x), State::Fixed(y)) => Some(Vector2::new(x, y)),
                    _ => None,
                };
                let new = match fixed {
                    None if jt.norm() > limit * (1.0 + 1e-9) => {
                        // Sticking past the disk: slides along its trial impulse.
                        Some(if jt.norm() > 0.0 {
                            jt * (limit / jt.norm())
                        } else {
                            Vector2::zeros()
                        })
                    }
                    None => None,
                    Some(old) => {
                        // Sliding along the direction it started to slide in, on the disk;
                        // back to sticking where the friction would drive the sliding
                        // instead of opposing it.
                        let vs = Vector2::new(
                            v_end(i) - rows[i].target,
                            v_end(other) - rows[other].target,
                        );
                        if vs.dot(&old) > 0.0 || limit == 0.0 {
                            Some(Vector2::new(f64::NAN, f64::NAN))
                        } else {
                            let new = old * (limit / old.norm());
                            ((new - old).norm() > 1e-9 * limit).then_some(new)
                        }
                    }
                };
                if limit == 0.0 {
                    // No normal impulse: no friction.
                    if fixed != Some(Vector2::zeros()) {
                        state[i] = State::Fixed(0.0);
                        state[other] = State::Fixed(0.0);
                        changed = true;
                    }
                } else if fixed == Some(Vector2::zeros()) || new.is_some_and(|v| v.x.is_nan()) {
                    // Released (its normal was inactive), or sliding the wrong way: sticking.
                    state[i] = State::Active;
                    state[other] = State::Active;
                    changed = true;
                } else if let Some(v) = new {
                    state[i] = State::Fixed(v.x);
                    state[other] = State::Fixed(v.y);
                    changed = true;
                }
            }
            Kind::Torsion { normal, arm } => {
                let limit = arm * j[normal].max(0.0);
                match state[i] {
                    State::Active if j[i].abs() > limit * (1.0 + 1e-9) => {
                        state[i] = State::Fixed(j[i].clamp(-limit, limit));
                        changed = true;
                    }
                    State::Fixed(old) if limit == 0.0 => {
                        if old != 0.0 {
                            state[i] = State::Fixed(0.0);
                            changed = true;
                        }
                    }
                    State::Fixed(old) if old == 0.0 || v_end(i) * old > 0.0 => {
                        // Released, or twisting the wrong way: sticking.
                        state[i] = State::Active;
                        changed = true;
                    }
                    State::Fixed(old) => {
                        let new = old.signum() * limit;
                        if (new - old).abs() > 1e-9 * limit {
                            state[i] = State::Fixed(new);
                            changed = true;
                        }
                    }
                    _ => {}
                }
            }
        }
    }
    changed
}

/// Solves a coupled group: soft rows `soft` and the rigid rows `rigid` of their bodies, from
/// the velocities `bodies` (at the group's base: no impulse of the step yet). On return the
/// soft rows hold their impulses, the rigid rows the part the plugin applies (`j - rest`), and
/// `bodies` the velocities after all impulses (rapier's `rest` included: the end of the step).
/// Returns false if a system was not finite (nothing is then changed).
pub(crate) fn solve_coupled(
    bodies: &mut [BodyState],
    soft: &mut [Row],
    rigid: &mut [RigidRow],
    h: f64,
    scratch: &mut CoupledScratch,
) -> bool {
    let mut first = Vec::with_capacity(soft.len());
    let CoupledScratch { scalars, state } = scratch;
    // rapier's part: the rigid rows alone.
    build(bodies, &[], rigid, h, scalars, &mut first);
    let Some(rest) = solve_scalars(bodies, scalars, h, state) else {
        return false;
    };
    // Everything.
    build(bodies, soft, rigid, h, scalars, &mut first);
    let Some(j) = solve_scalars(bodies, scalars, h, state) else {
        return false;
    };
    if std::env::var("SG_DEBUG").is_ok() {
        eprintln!("coupled: {} soft, {} rigid", soft.len(), rigid.len());
        for (i, (s, x)) in scalars.iter().zip(&j).enumerate() {
            eprintln!("  {i} {:?} j {x:.3e} state {:?} target {:.3e} p {:?}", s.kind, state[i], s.target, s.lin);
        }
        eprintln!("  rest {rest:?}");
        for r in rigid.iter() {
            eprintln!("  rigid p {:?} n {:?} mu {}", r.p, r.n, r.mu);
        }
    }
    for (s, x) in scalars.iter().zip(&j) {
        s.apply(bodies, *x);
    }
    for (k, r) in soft.iter_mut().enumerate() {
        let i = first[k];
        r.jn = j[i].max(0.0);
        r.jt = Vector3::zeros();
        r.jtw = 0.0;
        r.sliding = false;
        if r.mu > 0.0 {
            r.jt = r.t1 * j[i + 1] + r.t2 * j[i + 2];
            r.sliding = matches!(state[i + 1], State::Fixed(_)) && r.jn > 0.0;
            if r.torsion_arm > 0.0 {
                r.jtw = j[i + 3];
            }
        }
        r.vn_end = crate::solve::normal_velocity(bodies, r);
    }
    // rapier's part of each rigid row: its impulse without the soft contacts, scaled down to
    // the row's impulse with them (a box lifted off the table gets none from rapier).
    let mut i = scalars.len() - rigid_scalars(rigid);
    let mut k = 0;
    for r in rigid.iter_mut() {
        let s = if rest[k] > 0.0 {
            (j[i].max(0.0) / rest[k]).min(1.0)
        } else {
            0.0
        };
        r.jn = j[i] - s * rest[k];
        r.jt = Vector3::zeros();
        i += 1;
        k += 1;
        if r.mu > 0.0 {
            r.jt = r.t1 * (j[i] - s * rest[k]) + r.t2 * (j[i + 1] - s * rest[k + 1]);
            i += 2;
            k += 2;
        }
    }
    true
}

fn rigid_scalars(rigid: &[RigidRow]) -> usize {
    rigid.iter().map(|r| if r.mu > 0.0 { 3 } else { 1 }).sum()
}
