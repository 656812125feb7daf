//! The soft contacts of a body that rests on rapier's rigid contacts (a box on a table pressed
//! by a fingertip): one coupled solve of the soft rows and of rapier's touching contacts of the
//! bodies they move (`Step::prepare_rigid`), normal and friction.
//!
//! **Why.** The soft impulse over a step is implicit in the bodies' end velocity, `j = h [F -
//! D v(end)]`, and `v(end)` depends on the bodies' mobility. A box on the table, pressed down
//! by a fingertip, cannot move down. Seen as free, it falls away under gravity within the
//! step, the predicted separation outweighs the law's force and the impulse is zero: the tip
//! sank through the box with no force at all (`tests/press_on_table.rs`). With rapier's
//! touching contacts in the solve as rows, the soft impulses see the constrained mobility and
//! carry the law's force.
//!
//! **The rows.** Every scalar unknown is a row with a Jacobian on (at most) two bodies:
//! - a soft contact's normal, `j + h D (W j) = h (F - D v0)` (as in `solve`), its two
//!   tangential impulses and its torsion, which solve what `solve`'s friction sweep solves
//!   (`problem::spring`: by default zero relative tangential velocity plus the anchor
//!   correction, with [`SOFT_FRICTION_COMPLIANCE`] of their own mobility (see there); with
//!   the friction spring on, `v_t(end) + C j_t = target`, in the LU while they stick; zero
//!   relative spin), in the disk `mu j_n` and the torsion limit;
//! - a rigid contact's normal, `v(end) >= 0`, and its two tangential impulses, `v_t(end) = 0`,
//!   hard ([`RIGID_COMPLIANCE`]: the four corners of a box on a table are twelve rows for six
//!   degrees of freedom; it picks the least-impulse distribution). Only points that touch
//!   are rows (their gap within a tenth of rapier's allowed linear error,
//!   `problem::TOUCH_FRACTION`; one further apart is rapier's own speculative contact), and
//!   they target `v(end) = 0`, not the point's sub-tolerance gap: redundant rows are
//!   consistent only if they ask for one rigid motion.
//!
//! **The solve** (`solve_scalars`), started where the fingertips' friction is a spring and no
//! body is a link from the previous (sub)step's answer (each row at its contact's impulse
//! then, scaled by the step ratio: [`warm_start`]; a new contact at 0), else from zero: block
//! Gauss-Seidel, [`OUTER`] times (its slow tail extrapolated where no body is a link:
//! [`extrapolate`]): a dense LU of the
//! normals (on their active set) and of the rigid friction pairs that stick and whose normal
//! load comes mostly from the soft contacts, then up to [`SWEEPS`] sweeps of the friction pairs
//! and torsions, each in closed form on its own mobility and clamped (the sweeps stop once one
//! moves no impulse by more than [`CONVERGED`] of the largest). Rows that compete for one
//! degree of freedom (the table's normal and a pressing fingertip's normal; a wall's friction
//! and a fingertip's) are solved together by the LU, which alternating sweeps would take tens
//! of iterations to do. A rigid pair that slides leaves the LU for good (the set must not
//! cycle: it did, and a squeezed box on the ground rang at 2.5 cm/s).
//!
//! **rapier's soft rows.** One rule for every rigid row (`Step::prepare_rigid`): a row is
//! solved as rapier's soft contact (`problem::ContactSoftness`: its biased row over the step,
//! `v(end) + (c / N) w j = -dist erp_inv_dt`), its normal impulse left to rapier whole and the
//! plugin's impulses on its bodies given as a force over rapier's passes
//! (`bodies::apply_impulses`), where the soft contacts took the rigid load off its dynamic
//! bodies at the previous (sub)step: each body's rigid normal impulse summed over all its
//! pairs, with the soft contacts, at most half of it without them (kept while at most all of
//! it). Then rapier's own contacts carry what is left of the body's weight, as rapier solves
//! them, and the plugin's one-pass prediction has to be rapier's. Where the soft contacts press
//! a body onto its rigid contacts (a fingertip on a box; a box pushed into a wall, whose
//! friction then takes the weight off the table: the load moves between the body's pairs, it
//! is not taken off them) the rows stay hard: rapier's contact is a spring of `m erp_inv_dt /
//! (c dt)` (about 2.3e3 N/m for a 16 g box at 60 Hz), which the press would sink the box into,
//! so the plugin applies the pressing part itself (below).
//!
//! **Who applies what.** The rigid rows' normal impulses without any soft contact (the
//! bodies' weight on the table, `rest`, scaled down to the row's impulse with the soft
//! contacts: a box lifted off the table gets none) are rapier's: its own solver makes them and
//! their friction (the rigid friction rows' disk is `mu (j_n - rest)`). The hard rows'
//! compliance pulls a rigid normal towards `rest`, not towards 0 (`Scalar::prox`): among
//! redundant rows (the table's normal and a wall's friction both able to hold the weight) the
//! answer is the one closest to what rapier makes anyway. Pulled towards 0, the wall's friction
//! took part of the weight that rapier still carried on the table, and a box pressed against a
//! wall rattled at 1.4 cm/s, 0.56 % off the law (now 2e-7 m/s, 8e-5). The part the soft
//! contacts add is applied by the plugin with the soft impulses: left to rapier, a kick of `h
//! F / m` (6 m/s for a 16 g box under 6 N at 60 Hz) is only partly cancelled per solver pass by
//! rapier's soft contact constraint, and the box sank into the table and was thrown out.

use nalgebra::{Cholesky, DMatrix, DVector, Dyn, LU, Matrix2, Vector2, Vector3, Vector6};

use crate::mobility::{self, BodyState};
use crate::multibody;
use crate::problem::{RigidRow, Row, Warm};
use crate::saturation;

/// Relative diagonal compliance of a hard row (see the module's docs).
const RIGID_COMPLIANCE: f64 = 1e-9;
/// Relative diagonal compliance of a fingertip's tangential and torsional rows: a kinematic
/// fingertip's velocity (from `f32` poses) and its anchor correction are noise that a box held
/// fast by the table cannot follow; hard rows would answer it with unbounded impulses. It
/// changes the friction impulse on a free body by this fraction.
const SOFT_FRICTION_COMPLIANCE: f64 = 1e-2;

/// Outer iterations (normals, then friction) of one coupled solve.
const OUTER: usize = 32;
/// Most friction sweeps per outer iteration (fewer once a sweep settles: [`solve_scalars`]).
const SWEEPS: usize = 4;
/// Relative change of the impulses between outer passes below which the solve stops early
/// (the tests hold the soft force to the law within 1e-5).
const CONVERGED: f64 = 1e-6;

/// What a scalar row is.
#[derive(Debug, Clone, Copy)]
enum Kind {
    /// A soft normal: `force`, `d = theta K h + c`; `rigid`: past its law's wall, a rigid row
    /// (`step::rigid_past_wall`).
    SoftNormal { force: f64, d: f64, rigid: bool },
    /// A hard unilateral normal.
    HardNormal,
    /// A tangential impulse of the contact whose normal is row `normal`, paired with row
    /// `other` (its other tangent), in the disk `mu (j_normal - base)` (`base`: the part of a
    /// rigid row's normal impulse that rapier makes, whose friction rapier makes too).
    Tangent {
        normal: usize,
        other: usize,
        mu: f64,
        base: f64,
    },
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
    /// The contact point of a point row (a normal or a tangent) \[m\]; `None`: a torsion.
    at: Option<Vector3<f64>>,
    /// Target end velocity [m/s or rad/s].
    target: f64,
    /// Diagonal compliance relative to the row's own mobility.
    compliance: f64,
    /// The impulse the compliance pulls towards (rapier's own part of a hard normal) \[N s\].
    prox: f64,
    /// A fingertip's tangential row: its friction spring's absolute compliance `C` \[1/kg\]
    /// (`problem::spring`: the row's equation is `v(end) + C j = target`); 0 for every other row.
    spring: f64,
    /// The velocity change of body a (linear, angular) per unit impulse, and of body b per
    /// unit impulse on it (`-1` times the row's), set by `build` (`set_response`): the
    /// sweeps apply each row hundreds of times per solve.
    response: [(Vector3<f64>, Vector3<f64>); 2],
    /// Of body a and body b (set by `set_response`): `None` where an impulse can move it (a
    /// body with mass, a multibody link), else the row's velocity term of that body, fixed
    /// over the solve (a fixed, kinematic or sleeping body: no impulse of the solve changes
    /// its velocity), as [`Scalar::velocity`] sums it \[m/s or rad/s\]. Every soft and rigid
    /// row of the default grasp has one such side (a kinematic fingertip, the table):
    /// `velocity` and `apply` skip it (session 20, `sweep sweeps/throughput.toml`: see the
    /// crate README's profile).
    fixed: [Option<f64>; 2],
    /// What each side (a, b) is to [`Scalar::velocity`] and [`Scalar::apply`] (set by
    /// `set_response` with `fixed`): read once per row, not per side and body per call.
    reach: [Reach; 2],
}

/// A side of a scalar row as the solve's passes see it (fixed over a solve).
#[derive(Debug, Clone, Copy, Default)]
enum Reach {
    /// No body on this side.
    #[default]
    Absent,
    /// A body no impulse moves: its velocity term \[m/s or rad/s\] (`Scalar::fixed`).
    Fixed(f64),
    /// A body with mass, not a link: index into the body table.
    Free(usize),
    /// A multibody or jointed link: index into the body table.
    Link(usize),
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
        let arm = |i: Option<usize>| i.map(|i| (p - bodies[i].com).cross(d)).unwrap_or_default();
        Self {
            a,
            b,
            lin: *d,
            ang_a: arm(a),
            ang_b: arm(b),
            kind,
            at: Some(*p),
            target: 0.0,
            compliance: RIGID_COMPLIANCE,
            prox: 0.0,
            spring: 0.0,
            response: Default::default(),
            fixed: [None; 2],
            reach: Default::default(),
        }
    }

    /// Sets `response` from the bodies' inverse mass and inertia (fixed over a solve), and
    /// `fixed` from the velocities of the bodies no impulse moves.
    fn set_response(&mut self, bodies: &[BodyState]) {
        for (k, (i, ang)) in [(self.a, self.ang_a), (self.b, self.ang_b)]
            .into_iter()
            .enumerate()
        {
            self.response[k] = i
                .map(|i| {
                    let b = &bodies[i];
                    (b.inv_m.component_mul(&self.lin), b.inv_i * ang)
                })
                .unwrap_or_default();
            self.fixed[k] = i.filter(|&i| immovable(&bodies[i])).map(|i| {
                let (s, b) = ([1.0, -1.0][k], &bodies[i]);
                s * (self.lin.dot(&b.v) + ang.dot(&b.w))
            });
            self.reach[k] = match (i, self.fixed[k]) {
                (_, Some(u)) => Reach::Fixed(u),
                (Some(i), None) if bodies[i].link.is_some() => Reach::Link(i),
                (Some(i), None) => Reach::Free(i),
                (None, None) => Reach::Absent,
            };
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

    /// The row's velocity split into the part of its dynamic bodies (which impulses move) and
    /// the part of its fixed or kinematic ones \[m/s or rad/s\].
    fn velocity_parts(&self, bodies: &[BodyState]) -> (f64, f64) {
        let (mut dynamic, mut other) = (0.0, 0.0);
        for (i, s, ang) in [(self.a, 1.0, self.ang_a), (self.b, -1.0, self.ang_b)] {
            if let Some(i) = i {
                let b = &bodies[i];
                let u = s * (self.lin.dot(&b.v) + ang.dot(&b.w));
                if b.is_dynamic() {
                    dynamic += u;
                } else {
                    other += u;
                }
            }
        }
        (dynamic, other)
    }

    /// The row's velocity \[m/s or rad/s\]: the sum over its bodies (a, then b) of `s (lin . v +
    /// ang . w)`, `s` 1 on a and -1 on b; a body's term read from `fixed` where no impulse
    /// moves it (the same operands, so the same bits).
    #[inline(always)]
    fn velocity(&self, bodies: &[BodyState]) -> f64 {
        let mut v = 0.0;
        for (reach, s, ang) in [
            (self.reach[0], 1.0, &self.ang_a),
            (self.reach[1], -1.0, &self.ang_b),
        ] {
            match reach {
                Reach::Fixed(u) => v += u,
                Reach::Free(i) | Reach::Link(i) => {
                    v += s * (self.lin.dot(&bodies[i].v) + ang.dot(&bodies[i].w));
                }
                Reach::Absent => {}
            }
        }
        v
    }

    /// Applies the impulse `j` \[N s or N m s\] to the row's bodies (none to a body that no
    /// impulse moves: `fixed`).
    #[inline(always)]
    fn apply(&self, bodies: &mut [BodyState], j: f64) {
        for (reach, s, ang, (dv, dw)) in [
            (self.reach[0], 1.0, &self.ang_a, &self.response[0]),
            (self.reach[1], -1.0, &self.ang_b, &self.response[1]),
        ] {
            match reach {
                Reach::Free(i) => {
                    let b = &mut bodies[i];
                    b.v += dv * (s * j);
                    b.w += dw * (s * j);
                }
                Reach::Link(i) => {
                    mobility::apply(bodies, i, &(self.lin * (s * j)), &(ang * (s * j)));
                }
                Reach::Fixed(_) | Reach::Absent => {}
            }
        }
    }
}

/// Whether no impulse moves body `b` (no inverse mass or inertia and not a multibody link: a
/// fixed, kinematic or sleeping body), over a whole solve.
fn immovable(b: &BodyState) -> bool {
    b.link.is_none() && b.inv_m == Vector3::zeros() && b.inv_i == nalgebra::Matrix3::zeros()
}

/// Mobility between two scalar rows (sum over the bodies they share; the links of one
/// multibody are one body).
fn mobility(bodies: &[BodyState], x: &Scalar, y: &Scalar) -> f64 {
    let mut m = 0.0;
    for i in [x.a, x.b].into_iter().flatten() {
        if bodies[i].link.is_some() {
            link_mobility(bodies, i, x, y, &mut m);
            continue;
        }
        if let (Some((sx, lx, ax)), Some((sy, ly, ay))) = (x.on(i), y.on(i)) {
            let b = &bodies[i];
            m += sx * sy * (lx.dot(&b.inv_m.component_mul(&ly)) + ax.dot(&(b.inv_i * ay)));
        }
    }
    m
}

/// [`mobility`] of two rows whose `response` is set ([`build`]): the same products, read from
/// `y`'s response instead of recomputed (`inv_m . lin` and `inv_i ang` of the same operands,
/// so the same bits), for the solve's whole matrix of them.
///
/// A body no impulse moves (`Scalar::fixed`) is skipped: its part is a zero of either sign
/// (zero inverse mass and inertia), and `m` starts at +0, which such a part leaves as it is.
fn built_mobility(bodies: &[BodyState], x: &Scalar, y: &Scalar) -> f64 {
    let mut m = 0.0;
    let moved = |k: usize| x.fixed[k].is_none();
    for i in [x.a.filter(|_| moved(0)), x.b.filter(|_| moved(1))]
        .into_iter()
        .flatten()
    {
        if bodies[i].link.is_some() {
            link_mobility(bodies, i, x, y, &mut m);
            continue;
        }
        // `on`'s side of `y` on body `i`: a first.
        let side = if y.a == Some(i) {
            Some((1.0, 0))
        } else if y.b == Some(i) {
            Some((-1.0, 1))
        } else {
            None
        };
        if let (Some((sx, lx, ax)), Some((sy, k))) = (x.on(i), side) {
            let (rl, ra) = &y.response[k];
            m += sx * sy * (lx.dot(rl) + ax.dot(ra));
        }
    }
    m
}

/// The rows' mutual mobility (`built_mobility` of every pair) into `mob`, resized to `m x m`;
/// returns whether a row moves a multibody or jointed link.
///
/// Where no row moves a multibody or jointed link, the same products in the same order, each
/// row's moved sides gathered once into `sides` (body, sign, Jacobian and response of the
/// sides `built_mobility` visits, and of every row the side it takes on each body): the same
/// bits without `built_mobility`'s per-pair look-ups, which were 3.8 % of a sweep trial's CPU
/// samples (the whole matrix, session 20), nor the rows' own fields (session 26: 16.2 k
/// instructions a call in the default grasp -> see the crate README). With a link,
/// `built_mobility` itself.
///
/// `prior`: the mobility of the last `k` rows, `k x k`, as this function computed it for
/// the same rows on the same bodies (the coupled solve's rigid rows, solved alone first),
/// copied rather than recomputed: the same bits. Unused with a link. (Session 22: the
/// matrix was 7.5 % of a sweep trial's CPU samples, `fill_mobility` kept out of line; the
/// rigid block is 144 of the default grasp's 400 entries.)
fn fill_mobility(
    bodies: &[BodyState],
    rows: &[Scalar],
    mob: &mut DMatrix<f64>,
    prior: Option<&DMatrix<f64>>,
    sides: &mut Vec<Sides>,
) -> bool {
    let m = rows.len();
    if mob.shape() != (m, m) {
        *mob = DMatrix::zeros(m, m);
    }
    let moved = |r: &Scalar| {
        [
            r.a.filter(|_| r.fixed[0].is_none()),
            r.b.filter(|_| r.fixed[1].is_none()),
        ]
    };
    let links = rows
        .iter()
        .flat_map(moved)
        .flatten()
        .any(|i| bodies[i].link.is_some());
    let out = mob.as_mut_slice();
    if links {
        for c in 0..m {
            for r in 0..m {
                out[c * m + r] = built_mobility(bodies, &rows[r], &rows[c]);
            }
        }
        return true;
    }
    // `x.on(i)` of each moved side `i` of each row `x` (a first), with its response.
    sides.clear();
    sides.extend(rows.iter().map(|x| {
        let mut out = Sides::default();
        for i in moved(x).into_iter().flatten() {
            let (sign, k, ang) = if x.a == Some(i) {
                (1.0, 0, x.ang_a)
            } else {
                (-1.0, 1, x.ang_b)
            };
            out.side[out.n] = Side {
                body: i,
                sign,
                lin: x.lin,
                ang,
                dv: x.response[k].0,
                dw: x.response[k].1,
            };
            out.n += 1;
        }
        out
    }));
    let (k, prior) = match prior {
        Some(p) if p.nrows() <= m && p.shape() == (p.nrows(), p.nrows()) => {
            (p.nrows(), p.as_slice())
        }
        _ => (0, &[][..]),
    };
    let off = m - k;
    for c in 0..m {
        // `built_mobility`'s side of row `c` on a body: a first. A body that a row's side
        // moves is moved by every row's side on it (no impulse moves a fixed, kinematic or
        // sleeping body: `Scalar::fixed`), so the moved sides are all it can be.
        let ys = &sides[c];
        let column = &mut out[c * m..(c + 1) * m];
        let computed = if c >= off {
            column[off..].copy_from_slice(&prior[(c - off) * k..(c - off + 1) * k]);
            off
        } else {
            m
        };
        for (xs, w_out) in sides[..computed].iter().zip(column[..computed].iter_mut()) {
            let mut w = 0.0;
            for x in &xs.side[..xs.n] {
                // (An unused side's body is `usize::MAX`: no body's.)
                let y = if ys.side[0].body == x.body {
                    &ys.side[0]
                } else if ys.side[1].body == x.body {
                    &ys.side[1]
                } else {
                    continue;
                };
                w += x.sign * y.sign * (x.lin.dot(&y.dv) + x.ang.dot(&y.dw));
            }
            *w_out = w;
        }
    }
    false
}

/// The part of [`mobility`] through the multibody of link `i` (a body of `x`), added to `m`.
fn link_mobility(bodies: &[BodyState], i: usize, x: &Scalar, y: &Scalar, m: &mut f64) {
    let (sx, lx, ax) = x.on(i).unwrap_or((0.0, Vector3::zeros(), Vector3::zeros()));
    for k in [y.a, y.b].into_iter().flatten() {
        if let Some((sy, ly, ay)) = y.on(k)
            && let Some(w) = mobility::pair(bodies, i, (&lx, &ax), k, (&ly, &ay))
        {
            *m += sx * sy * w;
        }
    }
}

/// A row's state in the active set.
#[derive(Debug, Clone, Copy, PartialEq)]
enum State {
    /// Its equation holds.
    Active,
    /// Its impulse is fixed.
    Fixed(f64),
}

/// Reusable buffers of the coupled solve (kept from solve to solve: once grown to a group's
/// size, a solve allocates only its LU factorisations and a multibody's copies).
#[derive(Debug, Clone, Default)]
pub(crate) struct CoupledScratch {
    scalars: Vec<Scalar>,
    state: Vec<State>,
    /// [`solve_scalars`]'s buffers of each stage (0: the rigid rows alone, 1: everything;
    /// kept apart, their sizes differ and each stays the same from solve to solve, so nothing
    /// is reallocated; stage 1 reads stage 0's mobility, [`fill_mobility`]); the answer in
    /// `buffers[1].j`.
    buffers: [Buffers; 2],
    /// The bodies at the group's base ([`solve_coupled`]).
    base: Vec<BodyState>,
    /// The answer of the rigid rows alone, and rapier's normal impulse per rigid row.
    rest: Vec<f64>,
    rest_n: Vec<f64>,
    /// Each soft row's first scalar row ([`build`]).
    first: Vec<usize>,
    /// The warm start ([`warm_start`]).
    warm: Vec<Option<f64>>,
    /// Full coupled solves, their outer passes, those that did not settle, the rows found
    /// immobile ([`immobile`]) and the solves found degenerate ([`degenerate`]), total
    /// (`SoftCounters::coupled_*`, `immobile_rows`).
    pub stats: [u64; 5],
}

/// The scalar rows of soft rows `soft` and rigid rows `rigid` (`rigid` only: `soft` empty),
/// with their index of the first scalar of each soft row; `closable`: the rigid rows' points
/// apart may close their gap (rapier's part, [`push_rigid`]).
#[allow(clippy::too_many_arguments)]
fn build(
    bodies: &[BodyState],
    soft: &[Row],
    rigid: &[RigidRow],
    rest_n: &[f64],
    h: f64,
    closable: bool,
    out: &mut Vec<Scalar>,
    first: &mut Vec<usize>,
) {
    out.clear();
    first.clear();
    for r in soft {
        first.push(out.len());
        push_soft(bodies, r, h, out);
    }
    for (ri, r) in rigid.iter().enumerate() {
        let closing = if closable { r.closable / h } else { 0.0 };
        push_rigid(
            bodies,
            r,
            rest_n.get(ri).copied().unwrap_or(0.0),
            closing,
            out,
        );
    }
    for s in out.iter_mut() {
        s.set_response(bodies);
    }
}

/// The scalar rows of soft row `r` over a step `h`: its normal, and with friction its
/// tangential pair (the friction spring's equation, `problem::spring`) and its torsion.
fn push_soft(bodies: &[BodyState], r: &Row, h: f64, out: &mut Vec<Scalar>) {
    let nrm = out.len();
    let d = r.theta * r.stiffness * h + r.damping;
    out.push(Scalar::point(
        bodies,
        r.a,
        r.b,
        &r.p,
        &r.n,
        Kind::SoftNormal {
            force: r.force,
            d,
            rigid: r.past_wall,
        },
    ));
    if r.mu > 0.0 {
        // The friction spring (`problem::spring`).
        let (spring, target) = crate::problem::spring(r, h);
        let first = out.len();
        push_friction_pair(bodies, (r.a, r.b), &r.p, [r.t1, r.t2], nrm, r.mu, 0.0, out);
        for s in &mut out[first..] {
            // `lin` is the row's tangent.
            // With a spring, its compliance bounds the impulse (the relative one would make
            // the LU's answer and the sweeps' differ, and the solve never settle).
            s.compliance = if spring > 0.0 {
                0.0
            } else {
                SOFT_FRICTION_COMPLIANCE
            };
            s.target = target.dot(&s.lin);
            s.spring = spring;
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
                at: None,
                target: 0.0,
                compliance: SOFT_FRICTION_COMPLIANCE,
                prox: 0.0,
                spring: 0.0,
                response: Default::default(),
                fixed: [None; 2],
                reach: Default::default(),
            });
        }
    }
}

/// The scalar rows of rapier's contact `r`: its hard normal and its friction pair, whose
/// normal impulse without the soft contacts is `rest` \[N s\] (0 while that is computed).
/// The normal asks `v(end) >= -closing` [m/s]: in the solve of rapier's own part, a point
/// apart by more than half the touch tolerance may close the rest of its gap within the
/// (sub)step, as rapier's speculative contact lets it, without an impulse
/// ([`RigidRow::closable`](crate::problem::RigidRow::closable) over `h`); 0 in the solve with
/// the soft contacts, where a point within the touch tolerance is held as touching.
///
/// Why (session 35): held at `v(end) >= 0` in both solves, a box 0.3-0.5 mm short of a wall
/// that it was moving towards got a wall impulse in rapier's part, which the plugin left to
/// rapier, which makes none across a gap: the box was kicked towards the wall, stopped there
/// by rapier with a rebound, dropped out of the touch tolerance, and a pad pushing it read 58 N
/// and 0.02 N on alternate steps (`tests/gap_rows.rs`, from 30 mm). The deadzone of half the
/// tolerance keeps a resting box's redundant points (their gaps some 1e-5 m apart) and a box
/// held against a wall by a rigid stick (0.16-0.26 mm) as one rigid motion: with no deadzone
/// that box rattled at 1.1 cm/s (`press_on_table::rigid_stick_presses_a_box_against_a_wall`,
/// bound 1 um/s; it holds from a deadzone of 0.2 mm). Only where no row of the group moves a
/// multibody or jointed link (`Stage::fast`): with links, the three-finger hand driven into
/// the table with its pads pressing flung a link at 8.3 m/s (softgrip-scene's
/// `driven_into_table`, bound 0.5 m/s).
fn push_rigid(bodies: &[BodyState], r: &RigidRow, rest: f64, closing: f64, out: &mut Vec<Scalar>) {
    let nrm = out.len();
    let mut normal = Scalar::point(bodies, Some(r.a), r.b, &r.p, &r.n, Kind::HardNormal);
    normal.prox = rest;
    normal.target = -closing;
    if let Some(s) = r.softness {
        // rapier's own soft contact (`problem::ContactSoftness`): `v(end) + c w j = target`,
        // its compliance pulling towards 0 as rapier's does.
        normal.target = s.target;
        normal.compliance = s.compliance;
        normal.prox = 0.0;
    }
    out.push(normal);
    if r.mu > 0.0 {
        let base = rest;
        push_friction_pair(
            bodies,
            (Some(r.a), r.b),
            &r.p,
            [r.t1, r.t2],
            nrm,
            r.mu,
            base,
            out,
        );
    }
}

/// Pushes onto `out` the two tangential rows of the contact at `p` between bodies `ab` whose
/// normal is row `normal` (pushed just before them), in the disk `mu (j_normal - base)`.
/// (Pushed one by one: built as an array and copied, these ~400-byte rows were 2.3 % of a
/// sweep trial's CPU samples in `memmove`, session 21.)
#[allow(clippy::too_many_arguments)]
fn push_friction_pair(
    bodies: &[BodyState],
    ab: (Option<usize>, Option<usize>),
    p: &Vector3<f64>,
    tangents: [Vector3<f64>; 2],
    normal: usize,
    mu: f64,
    base: f64,
    out: &mut Vec<Scalar>,
) {
    for (k, t) in tangents.iter().enumerate() {
        out.push(Scalar::point(
            bodies,
            ab.0,
            ab.1,
            p,
            t,
            Kind::Tangent {
                normal,
                other: normal + 2 - k,
                mu,
                base,
            },
        ));
    }
}

/// Solves the scalar rows from the body velocities `bodies` (left at the velocities after the
/// impulses), leaving their impulses in `buffers.j` and returning the group's impulse scale
/// ([`impulse_bound`]; `None` if not finite).
///
/// Block Gauss-Seidel, [`OUTER`] times: a dense LU of the normals (soft and hard, on their
/// active set) and of the rigid friction pairs that stick and carry mostly soft load, the
/// other rows held at their impulses; then up to [`SWEEPS`] sweeps of the friction pairs and
/// torsions, each in closed form on its own mobility and clamped to its disk or limit, until
/// one moves no impulse by more than [`CONVERGED`] of the largest ([`settled`]). The
/// fingertips' friction stays in the sweeps (its targets carry a kinematic tip's noise).
/// Where no row moves a multibody or jointed link, the passes' geometric tail is summed
/// ([`extrapolate`]) and a solve whose LU holds every moving row stops after a pass the
/// sweeps did not move ([`all_in_lu`]).
#[allow(clippy::too_many_arguments)]
fn solve_scalars(
    bodies: &mut [BodyState],
    rows: &[Scalar],
    warm: &[Option<f64>],
    h: f64,
    state: &mut Vec<State>,
    passes: &mut usize,
    immobile_count: &mut u64,
    buffers: &mut Buffers,
    prior: Option<&DMatrix<f64>>,
    fast: bool,
) -> Option<f64> {
    let m = rows.len();
    let Buffers {
        j,
        slid,
        lu,
        previous,
        previous_lu,
        pair_inv,
        items,
        zero,
        cache,
        sides,
        pure,
        tail,
        ..
    } = buffers;
    cache.reset();
    // The rows' mutual mobility: the impulses change the bodies' velocities, never their mass,
    // inertia or centre, so it is computed once per solve (was: once per LU pass).
    let links = fill_mobility(bodies, rows, &mut cache.mob, prior, sides);
    let zeroed = immobile(bodies, rows, &mut cache.mob, zero);
    *pure = !links && zeroed == 0;
    *immobile_count += zeroed;
    let bound = impulse_bound(bodies, rows, &cache.mob, h);
    pair_inverses(rows, &cache.mob, pair_inv);
    sweep_items(rows, &cache.mob, pair_inv, items);
    j.clear();
    j.resize(m, 0.0);
    start_rows(bodies, rows, warm, &cache.mob, j);
    slid.clear();
    slid.resize(m, false);
    lu_rows(rows, j, slid, lu);
    state.clear();
    state.resize(m, State::Active);
    previous.clone_from(j);
    *passes = OUTER + 1;
    // The last plain pass's change, for the extrapolation (`extrapolate`; empty where the set
    // of LU rows changed or the pass extrapolated).
    tail.clear();
    // The shortcuts of session 27 (`extrapolate`, `all_in_lu`) only where no row moves a
    // multibody or jointed link (`fast`, for the whole group: `solve_coupled`): there the
    // solves decide the path of a hand jammed into the table (session 24), and with them the
    // pads-pressing descent took 15 616 substeps against main's 5 715 (`softgrip-scene`'s
    // `driven_into_table`, bound 6 000).
    let fast = fast && !links;
    for pass in 0..OUTER {
        lu_pass(bodies, rows, j, lu, h, state, cache)?;
        // The sweeps stop once one moves no impulse by more than CONVERGED of the largest, the
        // outer passes' own stop (session 24: 1.7 sweeps a pass, not 4, in `softgrip sweep
        // sweeps/throughput.toml`; the answers move within that stop, so not bit for bit).
        // Whether the first sweep moved no impulse by more than CONVERGED of the largest.
        let mut kept = false;
        for k in 0..SWEEPS {
            let moved = sweep(bodies, rows, items, j)?;
            if settled(moved, j) {
                kept = k == 0;
                break;
            }
        }
        mark_slid(rows, lu, j, slid);
        previous_lu.clone_from(lu);
        lu_rows(rows, j, slid, lu);
        // Every row that moves solved by the LU, whose answer the sweeps kept: the next pass
        // would solve the same system from the same impulses (session 27: the rigid rows'
        // solve alone, all twelve rows of the default grasp's box in the LU, took a second
        // pass that only confirmed the first; one LU pass and a sweep of 12 rows saved).
        if fast && kept && lu == previous_lu && all_in_lu(&cache.mob, lu) {
            *passes = pass + 1;
            break;
        }
        // Converged: the same rows in the LU and no impulse moved by more than CONVERGED of the
        // largest since the last pass (`moved_within`).
        if lu == previous_lu && moved_within(j, previous) {
            *passes = pass + 1;
            break;
        }
        if fast && lu == previous_lu {
            extrapolate(bodies, rows, j, previous, tail);
        } else {
            tail.clear();
        }
        previous.copy_from_slice(j);
    }
    Some(bound)
}

/// Largest ratio (in size) of two successive passes' changes that [`extrapolate`] takes as
/// the geometric tail of one slow mode.
const TAIL_RATIO: f64 = 0.5;

/// Largest part of a pass's change, relative to it, that may lie off the last pass's
/// direction for [`extrapolate`] to take the two as one mode.
const TAIL_FIT: f64 = 0.05;

/// The outer passes' tail, extrapolated: where this pass's change `d = j - previous` is the
/// last plain pass's `last` times a ratio `r` (least squares, the rest within [`TAIL_FIT`] of
/// `d`; `|r|` below [`TAIL_RATIO`]), every impulse moves on by `r / (1 - r)` of `d` (applied
/// to `bodies`): the sum of the geometric tail. Leaves this pass's change in `last` where it
/// did not extrapolate (the next pass may extrapolate from it), else empties it (the next
/// change is not the tail's).
///
/// Why: in the default grasp the table's four normals trade their load along the one
/// direction that leaves the box's net force and torque as they are (two diagonal corners
/// against the other two), with the corners' friction, clamped on its disk in the sweeps
/// while the LU solves the normals: each pass changes it by -0.23 times the last (session
/// 27; session 26: 4.79 passes a coupled solve, the last three or four of them that tail).
fn extrapolate(
    bodies: &mut [BodyState],
    rows: &[Scalar],
    j: &mut [f64],
    previous: &[f64],
    last: &mut Vec<f64>,
) {
    let fit = (last.len() == j.len()).then(|| {
        let (mut dl, mut ll, mut dd) = (0.0, 0.0, 0.0);
        for ((x, y), l) in j.iter().zip(previous).zip(last.iter()) {
            let d = x - y;
            dl += d * l;
            ll += l * l;
            dd += d * d;
        }
        let r = dl / ll;
        // |d - r l|^2 = |d|^2 - r (d . l) at the least-squares r.
        (r, (dd - r * dl).max(0.0) <= TAIL_FIT * TAIL_FIT * dd)
    });
    match fit {
        Some((r, true)) if r.abs() < TAIL_RATIO && r != 0.0 => {
            let f = r / (1.0 - r);
            for (i, row) in rows.iter().enumerate() {
                let d = (j[i] - previous[i]) * f;
                if d != 0.0 {
                    row.apply(bodies, d);
                    j[i] += d;
                }
            }
            last.clear();
        }
        _ => {
            last.clear();
            last.extend(j.iter().zip(previous).map(|(x, y)| x - y));
        }
    }
}

/// [`solve_scalars`]'s buffers, kept between solves.
#[derive(Debug, Clone, Default)]
struct Buffers {
    /// The impulses (the answer, once solved).
    j: Vec<f64>,
    /// The friction rows that slid out of the LU for good.
    slid: Vec<bool>,
    /// The rows in the LU, in this pass and the previous one.
    lu: Vec<usize>,
    previous_lu: Vec<usize>,
    /// The impulses after the previous pass.
    previous: Vec<f64>,
    /// The last plain outer pass's change of the impulses ([`extrapolate`]).
    tail: Vec<f64>,
    /// The friction pairs' inverse mobility ([`pair_inverses`]).
    pair_inv: Vec<Option<Matrix2<f64>>>,
    /// What the sweeps solve, in row order ([`sweep_items`]).
    items: Vec<Item>,
    /// The rows found immobile ([`immobile`]).
    zero: Vec<bool>,
    /// The LU passes' matrices and buffers.
    cache: LuCache,
    /// Each row's moved sides ([`fill_mobility`]).
    sides: Vec<Sides>,
    /// `cache.mob` is [`fill_mobility`]'s matrix of the last solve's rows as computed without
    /// a multibody or jointed link, no row zeroed by [`immobile`].
    pure: bool,
    /// The rows' velocity parts before the solve ([`solve_saturating`]).
    u0: Vec<(f64, f64)>,
}

/// The sides of a row that an impulse moves ([`fill_mobility`]): the first `n` of `side`, in
/// the row's order (a, then b).
#[derive(Debug, Clone, Copy, Default)]
struct Sides {
    n: usize,
    side: [Side; 2],
}

/// A side of a row that an impulse moves ([`Sides`]).
#[derive(Debug, Clone, Copy)]
struct Side {
    /// The body (index into the body table).
    body: usize,
    /// 1 on the row's body a, -1 on b.
    sign: f64,
    /// The row's linear Jacobian and its angular one on this body.
    lin: Vector3<f64>,
    ang: Vector3<f64>,
    /// The body's velocity change (linear, angular) per unit impulse on it (`Scalar::response`).
    dv: Vector3<f64>,
    dw: Vector3<f64>,
}

impl Default for Side {
    /// An unused side: on no body (`usize::MAX`).
    fn default() -> Self {
        Self {
            body: usize::MAX,
            sign: 0.0,
            lin: Vector3::zeros(),
            ang: Vector3::zeros(),
            dv: Vector3::zeros(),
            dw: Vector3::zeros(),
        }
    }
}

/// The friction pairs' inverse 2 x 2 mobility (by the pair's first row; `None` elsewhere), from
/// the rows' mutual mobility `mob`, into `out`.
fn pair_inverses(rows: &[Scalar], mob: &DMatrix<f64>, out: &mut Vec<Option<Matrix2<f64>>>) {
    out.clear();
    out.extend((0..rows.len()).map(|i| match rows[i].kind {
        Kind::Tangent { other, .. } if other > i => {
            let (x, y) = (&rows[i], &rows[other]);
            // A fingertip's friction spring adds its compliance where the row moves.
            let mut k = Matrix2::new(
                mob[(i, i)] * (1.0 + x.compliance),
                mob[(i, other)],
                mob[(other, i)],
                mob[(other, other)] * (1.0 + y.compliance),
            );
            for (d, r, s) in [(0, i, x), (1, other, y)] {
                if s.spring > 0.0 && mob[(r, r)] > 0.0 {
                    k[(d, d)] += s.spring;
                }
            }
            pair_inverse(&k)
        }
        _ => None,
    }));
}

/// Starts each row that moves at its warm start (`warm`: its impulse of the previous
/// (sub)step), applied to `bodies`: a row without one at zero, but a fingertip's friction
/// spring, which starts at the spring's force (see inside).
fn start_rows(
    bodies: &mut [BodyState],
    rows: &[Scalar],
    warm: &[Option<f64>],
    mob: &DMatrix<f64>,
    j: &mut [f64],
) {
    // A fingertip's friction without a warm start starts at its spring's force at the current
    // stretch, `-h k_t s` (`target / C`, `problem::spring`): where a rigid row holds the body
    // (a box pressed against a wall, whose friction is in the LU), that is the answer, which
    // alternating passes from zero approach by `C / (W + C)` a pass (all 32 passes, never
    // settled).
    for (i, r) in rows.iter().enumerate() {
        if !row_moves(mob, i) {
            continue;
        }
        j[i] = match warm.get(i).copied().flatten() {
            Some(w) => w,
            None if matches!(r.kind, Kind::Tangent { .. }) && r.spring > 0.0 => r.target / r.spring,
            None => continue,
        };
        r.apply(bodies, j[i]);
    }
}

/// Whether row `i` is solved in the LU (with the normals) in the coming pass, after the
/// impulses `j`; `slid` marks the friction rows that slid out of it for good. A rigid friction
/// pair is solved with the normals where the soft contacts carry most of its normal's load,
/// and stays in the sweeps for good once it slid out of the LU (the set does not cycle).
#[inline(always)]
fn in_lu(rows: &[Scalar], i: usize, j: &[f64], slid: &[bool]) -> bool {
    match rows[i].kind {
        Kind::SoftNormal { .. } | Kind::HardNormal => true,
        Kind::Tangent {
            normal, base, mu, ..
        } if matches!(rows[normal].kind, Kind::HardNormal) => {
            // (at the start, before any normal impulse: the pairs rapier carries nothing of)
            !slid[i] && mu > 0.0 && (j[normal] - base > base || (j[normal] == 0.0 && base == 0.0))
        }
        // A fingertip's friction spring that has not slid: with the rows it competes with (a
        // wall's friction holding the box the tip presses), which alternating passes
        // reconcile by `C / (W + C)` a pass.
        Kind::Tangent { .. } => rows[i].spring > 0.0 && !slid[i],
        _ => false,
    }
}

/// The rows [`in_lu`] puts in the coming pass's LU, in order, into `lu`.
fn lu_rows(rows: &[Scalar], j: &[f64], slid: &[bool], lu: &mut Vec<usize>) {
    lu.clear();
    for i in 0..rows.len() {
        if in_lu(rows, i, j, slid) {
            lu.push(i);
        }
    }
}

/// Marks in `slid` the friction rows of the LU (`lu`) that reached their disk.
fn mark_slid(rows: &[Scalar], lu: &[usize], j: &[f64], slid: &mut [bool]) {
    for &i in lu {
        if let Kind::Tangent {
            normal,
            other,
            mu,
            base,
        } = rows[i].kind
        {
            let limit = mu * (j[normal] - base).max(0.0);
            if Vector2::new(j[i], j[other]).norm() >= limit * (1.0 - 1e-6) {
                slid[i] = true;
            }
        }
    }
}

/// Whether every row that moves (a nonzero own mobility in `mob`) is in the LU's rows `lu`
/// (ascending).
fn all_in_lu(mob: &DMatrix<f64>, lu: &[usize]) -> bool {
    let mut next = lu.iter().peekable();
    (0..mob.nrows()).all(|i| {
        if next.peek() == Some(&&i) {
            next.next();
            true
        } else {
            !row_moves(mob, i)
        }
    })
}

/// Whether no impulse of `j` moved by more than [`CONVERGED`] of the largest since `previous`
/// (each pass is a dense LU: the default scene's groups without friction cycling settle in 2
/// passes; 124 -> 71 ms for `softgrip run`).
fn moved_within(j: &[f64], previous: &[f64]) -> bool {
    let moved = j
        .iter()
        .zip(previous)
        .fold(0.0f64, |a, (x, y)| a.max((x - y).abs()));
    settled(moved, j)
}

/// Whether a change of at most `moved` \[N s\] to the impulses `j` is within [`CONVERGED`] of
/// the largest of them.
fn settled(moved: f64, j: &[f64]) -> bool {
    let scale = j.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    moved <= CONVERGED * scale
}

/// How far past a group's impulse scale (`impulse_bound`) an answer may reach before it is
/// taken as carried by the hard rows' compliance. A physical answer exceeds the scale only
/// through a wedge or a lever (a wedge of angle `a` multiplies a load by about `1 / a`): 1000
/// admits a wedge of 0.06 degrees. Measured on the three-finger hand driven into the table
/// (`softgrip-scene/tests/driven_into_table.rs`, pads pressing each other, 40 mm): 44 solves
/// within 10 times the scale, one each near 10, 100 and 1000, then 1e4 to 5e7 times it, where
/// the compliance carries the answer (`RIGID_COMPLIANCE` is 1e-9: a missed velocity `dv`
/// asks `dv / (1e-9 w)`). The gap is not clean: with the factor at 100 that run took another
/// path and 393 solves fell between 100 and 1e4 times the scale.
const DEGENERATE_FACTOR: f64 = 1000.0;

/// How far past a group's impulse scale (`impulse_bound`) an answer may load one of a
/// multibody's (or a jointed assembly's) links along directions no joint can move
/// (`multibody::locked_load`: the largest linear impulse the fixed or kinematic root would
/// carry) before the answer is taken as degenerate. Such a load moves nothing in the solve's
/// prediction, so the rows are met however large it is: a kinematic palm jamming a link
/// between a table and a wedged box asks it without bound (3.2e6 N on a 20 g link, session
/// 15), and the answer's joint-space part next to it is a balance of huge rows too. In the
/// three-finger hand's box descent, with the projection before rapier alone
/// (`multibody::project_net`), the first accepted answer after 51 degenerate substeps put
/// 2.0e3 N of joint-space force on a link and rapier's multibody went from 0.45 to 9.4e4
/// rad/s in that substep (session 16). The shipped robot scenes never reach 2 (none of their
/// coupled solves is degenerate, `driven_into_table::shipped_robot_scenes_have_no_degenerate_solve`).
const LOCKED_FACTOR: f64 = 2.0;

/// How much faster than the group's speed scale (`speed_ratio`) an answer may leave a contact
/// point of its dynamic bodies before it is taken as degenerate. Hard rows are inelastic (they
/// only take relative velocity away) and a soft row gives at most `h F w_ii` over a substep,
/// so a physical answer leaves its points about as fast as they came in or as the kinematic
/// bodies drive them; past that only a lever multiplies a speed. Measured: the shipped robot
/// scenes' accepted answers reach at most 1.16 (`driven_into_table::
/// shipped_robot_scenes_have_no_degenerate_solve`); in the three-finger hand dragged into a
/// wall an answer that passed both size checks (its impulse scale inflated to 1e10 times its
/// largest impulse by a nearly locked row between two fingers' links, `w_ii` 3.2e-6 1/kg)
/// left the box at 220 m/s and a link at 585 m/s from points at most 1.1 m/s, ratios 48
/// (the whole answer) and 269 (rapier's part alone), and rapier's multibody went from 2.4 to
/// 3.0e3 rad/s in that substep (session 17).
const SPEED_FACTOR: f64 = 10.0;

/// What a soft normal's law impulse `h F` is divided by in the checks' scales
/// ([`impulse_bound`], [`speed_ratio`]): 1, or for a `rigid` row (past its law's wall,
/// `step::rigid_past_wall`) `1 + h D w_ii` (`hdw`), the implicit row's own reach. Such a row's
/// `F` is the barrier's at the wall (1e8 N and more on the three-finger hand's pad), and its
/// raw `h F` made every answer of its group pass the checks (a wild one diverged, session 17).
/// Below the wall the raw `h F` stays: with the reach there, an impulse-jointed finger's
/// answers (its pad's own `w_ii` far above what its joints leave) were all found degenerate
/// and its pad read 0 N (`tests/jointed.rs`).
fn reach_factor(rigid: bool, hdw: f64) -> f64 {
    if rigid { 1.0 + hdw } else { 1.0 }
}

/// The impulse scale of a group \[N s\]: each mobile row's impulse that would stop it alone,
/// `|v0 - target| / w_ii` (`v0` its velocity before the solve, `w_ii` its own mobility), plus
/// each soft normal's law force over the step `h F` and each hard normal's rapier part
/// (`prox`), summed over the rows. Any physical answer of the group (its bodies brought to
/// rest against each other, the soft forces carried through wedges and redundant supports)
/// stays within a modest factor of it.
fn impulse_bound(bodies: &[BodyState], rows: &[Scalar], mob: &DMatrix<f64>, h: f64) -> f64 {
    let mut sum = 0.0;
    for (i, r) in rows.iter().enumerate() {
        let w = mob[(i, i)];
        if w > 0.0 {
            sum += (r.velocity(bodies) - r.target).abs() / w;
        }
        sum += r.prox.abs();
        if let Kind::SoftNormal { force, d, rigid } = r.kind {
            sum += h * force.abs() / reach_factor(rigid, h * d * w.max(0.0));
        }
    }
    sum
}

/// Whether the answer `j` is degenerate: some impulse past [`DEGENERATE_FACTOR`] times the
/// group's impulse scale `bound` ([`impulse_bound`]). This happens where hard rows that are
/// each mobile cannot all be met together: a finger link pressing a box that a table holds
/// (the three-finger hand driven down onto its wedged box, issue 25), whose direction into
/// the box is free for the link-box row alone and locked once the box-table rows hold the box.
/// The hard rows then balance by their compliance, at `1 / RIGID_COMPLIANCE` times the
/// velocity they miss: 2e8 N on a 20 g link, which rapier's multibody (integrating it in
/// `f32` against its own contacts) turned into 1e24 rad/s within five substeps.
fn degenerate(j: &[f64], bound: f64) -> bool {
    let largest = j.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    largest > DEGENERATE_FACTOR * bound
}

/// A row's own mobility, relative to its bodies' mobility at its point summed over three
/// axes, below which the coupled soft solve takes the row as immobile (no impulse; counted in
/// [`SoftCounters::immobile_rows`](crate::SoftCounters::immobile_rows)). rapier's jacobians,
/// poses and velocities are `f32`: a direction a link cannot move along (a prismatic finger's vertical,
/// its base kinematic) reads a mobility of `(eps_f32 |J|)^2 W`, ~1e-14 of its axis's (measured
/// 7.6e-15 on the parallel gripper), never 0. `f32::EPSILON` (1.2e-7, a direction within
/// 3.5e-4 rad of a locked one) sits seven decades above that noise and below any mobility a
/// real geometry gives at a contact.
pub const IMMOBILE: f64 = f32::EPSILON as f64;

/// Zeroes the mobility (row and column of `mob`) of every row that its bodies cannot move
/// along ([`IMMOBILE`]), and of the friction rows of such a normal; returns how many rows it
/// zeroed (normals and torsions counted once each, tangents each).
///
/// Why: a hard row `W j = -v0` on an immobile direction takes an impulse `v0 / w` with `w` at
/// `f32` noise. On a multibody link that impulse leaks into the link's free dof through the
/// same noise, `J_free W J_row^T j ~ v0 / sqrt(w_rel)`: a parallel gripper's finger touching
/// the table (its base 5 mm lower than the shipped scene) got 1e17 N s on its table rows and
/// 79 m/s along its joint in one substep, and the scene blew up to 1e9 m
/// (`softgrip-scene/tests/gripper_on_table.rs`). An immobile row has no impulse (the body
/// does not move along it whatever the row does); a normal that carries nothing carries no
/// friction either.
fn immobile(
    bodies: &[BodyState],
    rows: &[Scalar],
    mob: &mut DMatrix<f64>,
    zero: &mut Vec<bool>,
) -> u64 {
    let m = rows.len();
    zero.clear();
    zero.resize(m, false);
    for (i, r) in rows.iter().enumerate() {
        // Clear of the threshold by the bound: the decision the scale would make.
        if scale_bound(bodies, r).is_some_and(|b| mob[(i, i)] > IMMOBILE * b * (1.0 + 1e-9)) {
            continue;
        }
        let scale: f64 = (0..3)
            .map(|k| {
                let e = Vector3::ith(k, 1.0);
                let axis = match r.at {
                    Some(p) => Scalar::point(bodies, r.a, r.b, &p, &e, r.kind),
                    None => Scalar {
                        lin: Vector3::zeros(),
                        ang_a: e,
                        ang_b: e,
                        ..*r
                    },
                };
                mobility(bodies, &axis, &axis)
            })
            .sum();
        zero[i] = !(mob[(i, i)] > IMMOBILE * scale);
    }
    for i in 0..m {
        if let Kind::Tangent { normal, .. } | Kind::Torsion { normal, .. } = rows[i].kind
            && zero[normal]
            && matches!(rows[normal].kind, Kind::HardNormal)
        {
            zero[i] = true;
        }
    }
    for i in (0..m).filter(|&i| zero[i]) {
        mob.row_mut(i).fill(0.0);
        mob.column_mut(i).fill(0.0);
    }
    zero.iter().filter(|z| **z).count() as u64
}

/// An upper bound of [`immobile`]'s scale of row `r` (its bodies' mobility at its point summed
/// over three axes), `None` where a body is a multibody or jointed link: per body, the sum of
/// `|m_k|` plus `2 |p - com|^2` times the sum of `|I_kl|` (`m` the inverse mass, `I` the
/// inverse inertia; a torsion's: the sum of `|I_kl|`), each axis's angular part being a quadratic form of `I` on `(p - com) x e_k`,
/// whose squares sum to `2 |p - com|^2`. Where a row's own mobility is clear of the threshold
/// on the bound, the scale's three `mobility` products per row (4.7 % of a sweep trial's CPU
/// samples, session 21) are not needed to decide.
fn scale_bound(bodies: &[BodyState], r: &Scalar) -> Option<f64> {
    let mut bound = 0.0;
    for i in [r.a, r.b].into_iter().flatten() {
        let b = &bodies[i];
        if b.link.is_some() {
            return None;
        }
        let inertia: f64 = b.inv_i.iter().map(|v| v.abs()).sum();
        bound += match r.at {
            Some(p) => {
                b.inv_m.iter().map(|v| v.abs()).sum::<f64>()
                    + 2.0 * (p - b.com).norm_squared() * inertia
            }
            None => inertia,
        };
    }
    Some(bound)
}

/// Whether row `i` moves (a nonzero own mobility; an immobile row's is zeroed, [`immobile`]).
fn row_moves(mob: &DMatrix<f64>, i: usize) -> bool {
    mob[(i, i)] > 0.0
}

/// The inverse of a friction pair's 2 x 2 mobility `k`; where one tangent is immobile (its row
/// and column zero: [`immobile`]), the other's alone (`1 / k_ii` on its diagonal, 0 on the
/// immobile one's), so that the sweeps still clamp it to its disk; `None` if neither moves.
fn pair_inverse(k: &Matrix2<f64>) -> Option<Matrix2<f64>> {
    match (k[(0, 0)] > 0.0, k[(1, 1)] > 0.0) {
        (true, true) => k.try_inverse(),
        (true, false) => Some(Matrix2::new(1.0 / k[(0, 0)], 0.0, 0.0, 0.0)),
        (false, true) => Some(Matrix2::new(0.0, 0.0, 0.0, 1.0 / k[(1, 1)])),
        (false, false) => None,
    }
}

/// A friction pair or a torsion of the sweeps ([`sweep`]), with what the sweeps read of it
/// that is fixed over a solve (the mobility and the rows' coefficients).
#[derive(Debug, Clone, Copy)]
enum Item {
    /// The tangential rows `i` and `other` (`i < other`) of normal row `normal`, in the disk
    /// `mu (j_normal - base)`; `k_inv`: the pair's inverse mobility ([`pair_inverses`]);
    /// `spring`: each row's friction spring compliance `C` \[1/kg\] where it acts (a spring row
    /// that moves), else `None`.
    Pair {
        i: usize,
        other: usize,
        normal: usize,
        mu: f64,
        base: f64,
        k_inv: Matrix2<f64>,
        spring: [Option<f64>; 2],
    },
    /// The torsion row `i` of normal row `normal`, limited by `arm j_normal`; `kt` its own
    /// mobility with its compliance (> 0: a torsion that does not move is left out).
    Torsion {
        i: usize,
        normal: usize,
        arm: f64,
        kt: f64,
    },
}

/// The sweeps' work list of `rows` (mobility `mob`, pairs' inverses `pair_inv`) into `out`,
/// in row order: each friction pair with an inverse, at its first row, and each torsion that
/// moves. The same decisions [`sweep`] made row by row, made once per solve (session 23: the
/// per-row `match` and the spring tests were a tenth of a sweep's instructions).
fn sweep_items(
    rows: &[Scalar],
    mob: &DMatrix<f64>,
    pair_inv: &[Option<Matrix2<f64>>],
    out: &mut Vec<Item>,
) {
    out.clear();
    for (i, r) in rows.iter().enumerate() {
        match r.kind {
            Kind::Tangent {
                normal,
                other,
                mu,
                base,
            } if other > i => {
                let Some(k_inv) = pair_inv[i] else { continue };
                let spring = |k: usize| {
                    let s = &rows[k];
                    (s.spring > 0.0 && mob[(k, k)] > 0.0).then_some(s.spring)
                };
                out.push(Item::Pair {
                    i,
                    other,
                    normal,
                    mu,
                    base,
                    k_inv,
                    spring: [spring(i), spring(other)],
                });
            }
            Kind::Torsion { normal, arm } => {
                let kt = mob[(i, i)] * (1.0 + r.compliance);
                if kt > 0.0 {
                    out.push(Item::Torsion { i, normal, arm, kt });
                }
            }
            _ => {}
        }
    }
}

/// One sweep of the friction pairs and torsions `items` ([`sweep_items`]; see
/// [`solve_scalars`]): the largest change it made to an impulse \[N s\], `None` if one was not
/// finite.
///
/// A compliant row (a fingertip's friction) is solved here as the hard equation `v(end) =
/// target` under-relaxed by `1 / (1 + compliance)`, where the LU solves the compliant one
/// (`+ compliance w (j - prox)`): against a box the table holds, its impulse moves by the same
/// amount every pass, and [`OUTER`] is what bounds it (crate README, Limits, session 12: made
/// consistent, the solve converges to an answer the wall box fails).
fn sweep(bodies: &mut [BodyState], rows: &[Scalar], items: &[Item], j: &mut [f64]) -> Option<f64> {
    let mut moved = 0.0f64;
    for item in items {
        match *item {
            Item::Pair {
                i,
                other,
                normal,
                mu,
                base,
                k_inv,
                spring,
            } => {
                let (x, y) = (&rows[i], &rows[other]);
                // A fingertip's friction spring: `v(end) + C j = target` (`Scalar::spring`).
                let mut err =
                    Vector2::new(x.velocity(bodies) - x.target, y.velocity(bodies) - y.target);
                for (d, r) in [(0, i), (1, other)] {
                    if let Some(c) = spring[d] {
                        err[d] += c * j[r];
                    }
                }
                let old = Vector2::new(j[i], j[other]);
                let mut new = old - k_inv * err;
                let limit = mu * (j[normal] - base).max(0.0);
                if !inside_disk(&new, limit) {
                    let norm = new.norm();
                    if norm > limit {
                        new *= limit / norm;
                    }
                }
                if !(new.x.is_finite() && new.y.is_finite()) {
                    return None;
                }
                let change = new - old;
                x.apply(bodies, change.x);
                y.apply(bodies, change.y);
                moved = moved.max(change.x.abs()).max(change.y.abs());
                j[i] = new.x;
                j[other] = new.y;
            }
            Item::Torsion { i, normal, arm, kt } => {
                let r = &rows[i];
                let limit = arm * j[normal].max(0.0);
                let new = (j[i] - r.velocity(bodies) / kt).clamp(-limit, limit);
                if !new.is_finite() {
                    return None;
                }
                let change = new - j[i];
                r.apply(bodies, change);
                moved = moved.max(change.abs());
                j[i] = new;
            }
        }
    }
    Some(moved)
}

/// Whether `v` is surely within the disk of radius `limit`, `|v| <= limit`, decided without
/// the square root: `|v|^2` below `limit^2` by a margin of 4 ulps, which the rounding of the
/// two squares and of `norm`'s root cannot cross (so where it says yes, `v.norm() > limit` is
/// false, bit for bit the same decision); `false` (undecided: take the root) near the rim,
/// outside, and where `limit^2` is subnormal, overflows or is not a number. The sweep's disk
/// test was its hottest line (`norm`'s root, 11 % of a sweep trial's CPU samples, session 20).
fn inside_disk(v: &Vector2<f64>, limit: f64) -> bool {
    let l2 = limit * limit;
    l2 >= f64::MIN_POSITIVE && v.norm_squared() < l2 * (1.0 - 4.0 * f64::EPSILON)
}

/// What the LU passes of one solve share: the rows' mutual mobility, the last factorisation
/// with the scalar rows it is of, and the passes' buffers (a pass allocates nothing unless its
/// set of rows changes; kept from solve to solve, [`LuCache::reset`] at each one's start).
#[derive(Debug, Clone, Default)]
struct LuCache {
    mob: DMatrix<f64>,
    rows: Vec<usize>,
    lu: Option<LU<f64, Dyn, Dyn>>,
    /// The LU rows' velocities before their impulses.
    v0: Vec<f64>,
    /// The system of the LU rows and its right-hand side.
    a: DMatrix<f64>,
    /// The LU rows `a` is of (it depends on nothing else that changes within a solve).
    a_rows: Vec<usize>,
    b: Vec<f64>,
    /// The solution (0 for the rows that do not act).
    x: Vec<f64>,
    /// The acting rows (positions in the LU's rows).
    idx: Vec<usize>,
    /// The right-hand side of the acting rows, then their solution.
    rhs: DVector<f64>,
}

/// The normal row a row's friction belongs to (itself for a normal).
fn normal_of(rows: &[Scalar], i: usize) -> usize {
    match rows[i].kind {
        Kind::Tangent { normal, .. } | Kind::Torsion { normal, .. } => normal,
        _ => i,
    }
}

/// The LU of the rows `lu` given the impulses `j` of the others, on the normals' active set
/// (`state`, kept from pass to pass): a soft normal `(I + h D W) j = h (F - D v0)`, a hard
/// normal `W j = -v0` and a sticking friction row `W j = target - v0`, each hard row with
/// [`RIGID_COMPLIANCE`] of its own mobility on its diagonal; a friction row of an inactive
/// normal has no impulse. Writes `j` and applies it to `bodies`.
fn lu_pass(
    bodies: &mut [BodyState],
    rows: &[Scalar],
    j: &mut [f64],
    lu: &[usize],
    h: f64,
    state: &mut [State],
    cache: &mut LuCache,
) -> Option<()> {
    for &i in lu {
        rows[i].apply(bodies, -j[i]);
    }
    cache.v0.clear();
    cache
        .v0
        .extend(lu.iter().map(|&i| rows[i].velocity(bodies)));
    cache.assemble(rows, lu, h);
    cache.right_hand_side(rows, lu, h);
    cache.active_set(rows, lu, state)?;
    let x = &cache.x;
    if !x.iter().all(|v| v.is_finite()) {
        return None;
    }
    for (r, &i) in lu.iter().enumerate() {
        j[i] = x[r];
        rows[i].apply(bodies, j[i]);
    }
    Some(())
}

impl LuCache {
    /// Forgets the previous solve's system and factorisation (its rows are not this one's).
    fn reset(&mut self) {
        self.rows.clear();
        self.lu = None;
        self.a_rows.clear();
    }

    /// The system `a` of the LU rows `lu` over a step `h`.
    fn assemble(&mut self, rows: &[Scalar], lu: &[usize], h: f64) {
        let n = lu.len();
        let Self { mob, a, a_rows, .. } = self;
        let w = |r: usize, c: usize| mob[(lu[r], lu[c])];
        // The matrix depends on the rows only (the mobility and coefficients are fixed over a
        // solve): rebuilt when the set of LU rows changes, not every pass.
        if a_rows.as_slice() != lu || a.nrows() != n {
            // (Reallocated only when the size changes: `resize_mut` copied it every time.)
            if a.shape() != (n, n) {
                *a = DMatrix::zeros(n, n);
            }
            a.fill(0.0);
            for (r, &i) in lu.iter().enumerate() {
                match rows[i].kind {
                    Kind::SoftNormal { d, .. } => {
                        for c in 0..n {
                            a[(r, c)] = h * d * w(r, c);
                        }
                        a[(r, r)] += 1.0;
                    }
                    _ if w(r, r) == 0.0 => {}
                    _ => {
                        for c in 0..n {
                            a[(r, c)] = w(r, c);
                        }
                        a[(r, r)] += rows[i].compliance * w(r, r);
                        if rows[i].spring > 0.0 {
                            a[(r, r)] += rows[i].spring;
                        }
                    }
                }
            }
            a_rows.clear();
            a_rows.extend_from_slice(lu);
        }
    }

    /// The right-hand side `b` of the LU rows `lu` from their velocities `v0`.
    fn right_hand_side(&mut self, rows: &[Scalar], lu: &[usize], h: f64) {
        let n = lu.len();
        let Self { mob, v0, b, .. } = self;
        let w = |r: usize, c: usize| mob[(lu[r], lu[c])];
        b.clear();
        b.resize(n, 0.0);
        for (r, &i) in lu.iter().enumerate() {
            match rows[i].kind {
                Kind::SoftNormal { force, d, .. } => b[r] = h * (force - d * v0[r]),
                _ if w(r, r) == 0.0 => {}
                // The compliance acts on the change from rapier's own part (`prox`): among
                // redundant rows it picks the answer closest to what rapier makes anyway.
                _ => b[r] = rows[i].target - v0[r] + rows[i].compliance * w(r, r) * rows[i].prox,
            }
        }
    }

    /// The active set of the LU rows' normals (`state`) and the solution `x` on it: the
    /// acting rows solved by the LU, a normal with a negative impulse dropped, an inactive one
    /// whose velocity equation is violated taken in, until the set stays. `None` if the
    /// factorisation cannot solve.
    fn active_set(&mut self, rows: &[Scalar], lu: &[usize], state: &mut [State]) -> Option<()> {
        let n = lu.len();
        let Self {
            mob,
            rows: lu_rows,
            lu: factor,
            a,
            b,
            x,
            idx,
            rhs,
            ..
        } = self;
        let w = |r: usize, c: usize| mob[(lu[r], lu[c])];
        x.clear();
        x.resize(n, 0.0);
        for _ in 0..(2 * n + 2) {
            // A row acts if it is an active normal (a hard one with some mobility), or the
            // friction of one (with some mobility; the normals are all in the LU).
            let acts = |r: usize| {
                let i = lu[r];
                let soft = matches!(rows[i].kind, Kind::SoftNormal { .. });
                (soft || w(r, r) != 0.0) && state[normal_of(rows, i)] == State::Active
            };
            idx.clear();
            idx.extend((0..n).filter(|&r| acts(r)));
            x.iter_mut().for_each(|v| *v = 0.0);
            if !idx.is_empty() {
                // The matrix of a set of rows is the same in every pass of a solve (the mobility
                // and the rows' coefficients are fixed; only the right-hand side changes): its
                // factorisation is reused while the set stays (the same arithmetic, so the same
                // bits).
                if !lu_rows.iter().copied().eq(idx.iter().map(|&r| lu[r])) || factor.is_none() {
                    let sub = DMatrix::from_fn(idx.len(), idx.len(), |p, q| a[(idx[p], idx[q])]);
                    lu_rows.clear();
                    lu_rows.extend(idx.iter().map(|&r| lu[r]));
                    *factor = Some(sub.lu());
                }
                // Every entry is written below.
                if rhs.len() != idx.len() {
                    *rhs = DVector::zeros(idx.len());
                }
                for (p, &r) in idx.iter().enumerate() {
                    rhs[p] = b[r];
                }
                if !factor.as_ref()?.solve_mut(rhs) {
                    return None;
                }
                for (p, &r) in idx.iter().enumerate() {
                    x[r] = rhs[p];
                }
            }
            let mut changed = false;
            for r in 0..n {
                let i = lu[r];
                if !matches!(rows[i].kind, Kind::SoftNormal { .. } | Kind::HardNormal) {
                    continue;
                }
                if state[i] == State::Active && x[r] < 0.0 {
                    state[i] = State::Fixed(0.0);
                    changed = true;
                } else if state[i] != State::Active && w(r, r) != 0.0 {
                    let resid = b[r] - (0..n).map(|c| a[(r, c)] * x[c]).sum::<f64>();
                    if resid > 1e-12 * b[r].abs().max(1e-300) && resid > 0.0 {
                        state[i] = State::Active;
                        changed = true;
                    }
                }
            }
            if !changed {
                break;
            }
        }
        Some(())
    }
}

/// Solves a coupled group: soft rows `soft` and the rigid rows `rigid` of their bodies, from
/// the velocities `bodies` (at the group's base: no impulse of the step yet). On return the
/// soft rows hold their impulses, the rigid rows the part the plugin applies (`j - rest`), and
/// `bodies` the velocities after all impulses (rapier's `rest` included: the end of the step).
/// Returns what came of it; on anything but [`Coupled::Solved`] nothing is changed.
pub(crate) fn solve_coupled(
    bodies: &mut [BodyState],
    soft: &mut [Row],
    rigid: &mut [RigidRow],
    h: f64,
    scratch: &mut CoupledScratch,
) -> Coupled {
    let scratch_degenerate_before = scratch.stats[4];
    let mut passes = 0;
    // rapier's part: the rigid rows alone.
    let mut base = std::mem::take(&mut scratch.base);
    base.clear();
    base.extend_from_slice(bodies);
    let mut first = std::mem::take(&mut scratch.first);
    let mut warm = std::mem::take(&mut scratch.warm);
    // Warm-started only where the fingertips' friction is a spring (`problem::spring`): the
    // hard stick's solves stop at the pass cap on a drift (crate README, session 14), which a
    // warm start carries on from step to step; measured (session 19), the 1 kg box of
    // `tests/large_step.rs` then slipped 0.21 mm in the grip (bound 10 um).
    let warmed = soft.iter().any(|r| r.k_t > 0.0);
    // Decided for the group, both solves alike: with the rigid rows' solve alone taking its
    // shortcut and the whole group's not (a pad on a link pressing a box on the table), the
    // box of `tests/jointed_mimic.rs`'s friction-spring jaws moved at 0.86 mm/s in the hold
    // (bound 1 um/s; session 27).
    let fast = !soft
        .iter()
        .flat_map(|r| [r.a, r.b])
        .chain(rigid.iter().flat_map(|r| [Some(r.a), r.b]))
        .flatten()
        .any(|i| bodies[i].link.is_some());
    let mut stage = Stage {
        h,
        warmed,
        first: &mut first,
        warm: &mut warm,
        passes: &mut passes,
        fast,
    };
    let solved = stage.solve(bodies, &[], rigid, &[], 0, scratch).is_some();
    bodies.clone_from_slice(&base);
    let outcome = if !solved {
        failure(scratch_degenerate_before, scratch.stats[4])
    } else {
        std::mem::swap(&mut scratch.rest, &mut scratch.buffers[0].j);
        let mut rest_n = std::mem::take(&mut scratch.rest_n);
        rest_normals(rigid, &scratch.rest, &mut rest_n);
        // Everything.
        let solved = stage
            .solve(bodies, soft, rigid, &rest_n, 1, scratch)
            .is_some();
        scratch.rest_n = rest_n;
        if !solved {
            bodies.clone_from_slice(&base);
            failure(scratch_degenerate_before, scratch.stats[4])
        } else {
            let CoupledScratch {
                scalars,
                stats,
                buffers,
                rest,
                ..
            } = scratch;
            let passes = *stage.passes;
            stats[0] += 1;
            stats[1] += passes.min(OUTER) as u64;
            stats[2] += u64::from(passes > OUTER);
            write_soft(bodies, soft, stage.first, &buffers[1].j);
            supported_mobility(
                bodies,
                soft,
                &scalars[..],
                stage.first,
                &buffers[1],
                stage.fast,
            );
            write_rigid(soft, rigid, &scalars[..], &buffers[1].j, rest, h);
            Coupled::Solved
        }
    };
    scratch.base = base;
    scratch.first = first;
    scratch.warm = warm;
    outcome
}

/// What the two solves of [`solve_coupled`] (the rigid rows alone, then everything) share.
struct Stage<'a> {
    /// The (sub)step \[s\].
    h: f64,
    /// Whether the solves start from the previous (sub)step's answer ([`warm_start`]).
    warmed: bool,
    /// Each soft row's first scalar row ([`build`]).
    first: &'a mut Vec<usize>,
    /// The warm start's buffer (left empty when not `warmed`: every row starts cold).
    warm: &'a mut Vec<Option<f64>>,
    /// Outer passes of the last solve.
    passes: &'a mut usize,
    /// Whether the solves may take session 27's shortcuts ([`solve_scalars`]): no body of the
    /// group (soft and rigid rows) is a multibody or jointed link.
    fast: bool,
}

impl Stage<'_> {
    /// Builds the scalar rows of `soft` and `rigid` (rapier's part `rest_n`, per rigid row),
    /// warm-started from their answer `which` (0: rigid rows alone, 1: with the soft rows) if
    /// `warmed`, and solves them ([`solve_saturating`]); `None` as it does.
    fn solve(
        &mut self,
        bodies: &mut [BodyState],
        soft: &[Row],
        rigid: &[RigidRow],
        rest_n: &[f64],
        which: usize,
        scratch: &mut CoupledScratch,
    ) -> Option<()> {
        let CoupledScratch {
            scalars,
            state,
            stats,
            buffers,
            ..
        } = scratch;
        // rapier's part lets points apart close where no row moves a link (`push_rigid`).
        let closable = which == 0 && self.fast;
        build(
            bodies, soft, rigid, rest_n, self.h, closable, scalars, self.first,
        );
        // Not built at all when unused (a row past the buffer's end starts cold: `start_rows`).
        self.warm.clear();
        if self.warmed {
            warm_start(soft, rigid, which, self.h, self.warm);
        }
        let [.., immobile, degenerate] = stats;
        let [first, all] = buffers;
        // Stage 1's rigid rows are stage 0's, built from the same bodies (`solve_coupled`
        // restores them): their block of the mobility is stage 0's, where that is
        // `fill_mobility`'s own (`Buffers::pure`).
        let (buffers, prior) = if which == 0 {
            (first, None)
        } else {
            let k = rigid_scalars(rigid);
            let pure = first.pure && first.cache.mob.nrows() == k && k <= scalars.len();
            (all, pure.then_some(&first.cache.mob))
        };
        solve_saturating(
            bodies,
            scalars,
            self.warm,
            self.h,
            state,
            self.passes,
            immobile,
            degenerate,
            buffers,
            prior,
            self.fast,
        )
    }
}

/// Writes each soft row's `supported_mobility` after the whole group's solve (`rows`, its
/// scalar rows; `first`, each soft row's first scalar; `buffers`, the solve's answer): its
/// normal's mobility given the rigid rows that held, `w_eff = W_cc - W_cS A_SS^-1 W_Sc` (the
/// Schur complement of the rows' mutual mobility `W`), `S` rapier's normals with an impulse and
/// their friction pairs that hold (the impulse stopping their points, from the velocities
/// `bodies` after the solve, inside the whole disk `mu j_n`), `A_SS` their mobility with each
/// row's compliance (the LU's) on its diagonal \[1/kg\]. `None` where no friction pair held,
/// where a body of the group is a jointed link (`fast` false: their groups keep the free
/// mobility) or where the block cannot be factored. (A fingertip on the hard stick was left
/// out in session 27: its box pressed against a wall was pushed 1.8 mm off when a step was
/// split after unsplit ones; the cause was the split step's carry, `bodies::unsplit_carry`,
/// fixed in session 28.)
///
/// Why: the substep count resolves a touching contact's approach as an impact at its
/// mobility (`substep::substeps_for`); a box the table's friction holds against a closing jaw
/// took the free box's (session 27: the throughput sweep's squeeze split 490 steps 40 to 103
/// ways, 20 219 of its 22 749 coupled solves, with the box moving at most 0.23 mm/s).
fn supported_mobility(
    bodies: &[BodyState],
    soft: &mut [Row],
    rows: &[Scalar],
    first: &[usize],
    buffers: &Buffers,
    fast: bool,
) {
    for r in soft.iter_mut() {
        r.supported_mobility = None;
    }
    if !fast {
        return;
    }
    let Buffers { j, cache, .. } = buffers;
    let mob = &cache.mob;
    if mob.nrows() != rows.len() || j.len() != rows.len() {
        return;
    }
    let Some((support, chol)) = held_supports(bodies, rows, j, mob) else {
        return;
    };
    for (r, &f) in soft.iter_mut().zip(first) {
        if !matches!(rows[f].kind, Kind::SoftNormal { .. }) || !(mob[(f, f)] > 0.0) {
            continue;
        }
        let b = DVector::from_fn(support.len(), |k, _| mob[(support[k], f)]);
        let x = chol.solve(&b);
        let w_eff = (mob[(f, f)] - b.dot(&x)).max(0.0);
        if w_eff.is_finite() {
            r.supported_mobility = Some(w_eff);
        }
    }
}

/// The rigid rows that held in the solve whose answer is `j` (rows `rows`, mutual mobility
/// `mob` \[1/kg\], end velocities on `bodies`) and the Cholesky factor of their block `A_SS`
/// (mobility with each row's compliance on its diagonal), for [`supported_mobility`]. `None`
/// where no friction pair holds (the normals alone give no hold across the surface) or where
/// the block cannot be factored.
///
/// The candidates are rapier's normals with an impulse and their friction pairs; a pair holds
/// where the impulse that stops its point, with the normals that held, lies inside its whole
/// disk `mu j_normal` (rapier's part of it included: the coupled rows carry only
/// `mu (j_normal - base)`, rapier's friction the rest). One that would slide is dropped and the
/// others judged again, at most [`SUPPORT_PASSES`] times.
fn held_supports(
    bodies: &[BodyState],
    rows: &[Scalar],
    j: &[f64],
    mob: &DMatrix<f64>,
) -> Option<(Vec<usize>, Cholesky<f64, Dyn>)> {
    let held_normal = |i: usize| matches!(rows[i].kind, Kind::HardNormal) && j[i] > 0.0;
    let mut support: Vec<usize> = (0..rows.len())
        .filter(|&i| mob[(i, i)] > 0.0)
        .filter(|&i| match rows[i].kind {
            Kind::HardNormal => held_normal(i),
            Kind::Tangent { normal, mu, .. } => held_normal(normal) && mu > 0.0,
            _ => false,
        })
        .collect();
    for _ in 0..=SUPPORT_PASSES {
        if support.is_empty() {
            return None;
        }
        let chol = support_block(rows, mob, &support).cholesky()?;
        let v = DVector::from_fn(support.len(), |k, _| {
            let s = &rows[support[k]];
            s.velocity(bodies) - s.target
        });
        let dj = chol.solve(&v);
        let after = |i: usize| {
            let k = support.iter().position(|&k| k == i);
            j[i] - k.map_or(0.0, |k| dj[k])
        };
        let slides = |i: usize| match rows[i].kind {
            Kind::Tangent {
                normal, other, mu, ..
            } => {
                let limit = mu * after(normal).max(0.0);
                Vector2::new(after(i), after(other)).norm() >= limit * (1.0 - 1e-6)
            }
            _ => false,
        };
        let kept: Vec<usize> = support.iter().copied().filter(|&i| !slides(i)).collect();
        if kept.len() == support.len() {
            let friction = support
                .iter()
                .any(|&i| matches!(rows[i].kind, Kind::Tangent { .. }));
            return friction.then_some((support, chol));
        }
        support = kept;
    }
    None
}

/// The mutual mobility of the rows `support` (indices into `rows`, matrix `mob` \[1/kg\]) with
/// each row's compliance added on the diagonal (`w (1 + compliance)`, as the LU has it).
fn support_block(rows: &[Scalar], mob: &DMatrix<f64>, support: &[usize]) -> DMatrix<f64> {
    let n = support.len();
    DMatrix::from_fn(n, n, |r, c| {
        let w = mob[(support[r], support[c])];
        if r == c {
            w + rows[support[r]].compliance * w
        } else {
            w
        }
    })
}

/// Most passes of [`supported_mobility`]'s judgement of the friction pairs (each drops the
/// pairs that would slide).
const SUPPORT_PASSES: usize = 4;

/// rapier's normal impulse of each rigid row (its friction goes with it: see `Kind::Tangent`)
/// from the solve of the rigid rows alone, `rest` (per scalar row), into `rest_n`.
fn rest_normals(rigid: &[RigidRow], rest: &[f64], rest_n: &mut Vec<f64>) {
    rest_n.clear();
    let mut k = 0;
    for r in rigid.iter() {
        rest_n.push(rest[k].max(0.0));
        k += if r.mu > 0.0 { 3 } else { 1 };
    }
}

/// The soft rows' impulses from the answer `j` (`first`: each soft row's first scalar) and
/// their end velocity on `bodies`.
fn write_soft(bodies: &[BodyState], soft: &mut [Row], first: &[usize], j: &[f64]) {
    for (k, r) in soft.iter_mut().enumerate() {
        let i = first[k];
        r.jn = j[i].max(0.0);
        r.jt = Vector3::zeros();
        r.jtw = 0.0;
        r.sliding = false;
        if r.mu > 0.0 {
            r.jt = r.t1 * j[i + 1] + r.t2 * j[i + 2];
            r.sliding = r.jn > 0.0 && r.jt.norm() >= r.mu * r.jn * (1.0 - 1e-9);
            if r.torsion_arm > 0.0 {
                r.jtw = j[i + 3];
            }
        }
        r.vn_end = crate::problem::normal_velocity(bodies, r);
    }
}

/// The rigid rows' impulses the plugin applies from the answer `j` and rapier's part `rest`
/// (see inside), `scalars` the solve's rows, `h` the (sub)step \[s\] (kept with the answer for
/// the next warm start).
fn write_rigid(
    soft: &[Row],
    rigid: &mut [RigidRow],
    scalars: &[Scalar],
    j: &[f64],
    rest: &[f64],
    h: f64,
) {
    // rapier's part of each rigid row: its impulse without the soft contacts, scaled down to
    // the row's impulse with them (a box lifted off the table gets none from rapier). With a
    // friction spring in the group, one scale per pair of bodies (`pair_scales`).
    let first_rigid = scalars.len() - rigid_scalars(rigid);
    let pair = soft.iter().any(|r| r.k_t > 0.0);
    let scales = if pair {
        pair_scales(rigid, &j[first_rigid..], rest)
    } else {
        Vec::new()
    };
    let mut i = first_rigid;
    let mut k = 0;
    for (ri, r) in rigid.iter_mut().enumerate() {
        let s = if pair {
            scales[ri]
        } else if rest[k] > 0.0 {
            (j[i].max(0.0) / rest[k]).min(1.0)
        } else {
            0.0
        };
        r.jn = j[i] - s * rest[k];
        if r.softness.is_some() {
            // rapier's soft row: its whole normal impulse is rapier's own answer to the
            // state the plugin leaves (applying a part of it too made the box move 1.7 um a
            // step; `SPRING_DEFAULT_STATUS.md`, 21).
            r.jn = 0.0;
        }
        r.jt = Vector3::zeros();
        // The next (sub)step's warm start: rapier's part and the whole, as solved.
        let mut solved = [(rest[k], Vector3::zeros()), (j[i], Vector3::zeros())];
        i += 1;
        k += 1;
        if r.mu > 0.0 {
            // The friction the soft contacts add (the disk of `j - rest`): rapier makes the
            // friction of its own part.
            r.jt = r.t1 * j[i] + r.t2 * j[i + 1];
            solved[0].1 = r.t1 * rest[k] + r.t2 * rest[k + 1];
            solved[1].1 = r.jt;
            i += 2;
            k += 2;
        }
        r.solved = Some(solved.map(|(jn, jt)| Warm {
            jn,
            jt,
            jtw: 0.0,
            h,
        }));
    }
}

/// The scale of rapier's part of each rigid row where a friction spring is in the group: per
/// pair of bodies (a manifold's points), the pair's total normal impulse with the soft contacts
/// over its total without them, at most 1 (`j_rigid`: the rigid rows' scalars, normals first;
/// `rest`: their impulses without the soft contacts, from the start of the rigid rows).
///
/// rapier's part is then its own distribution over the pair's points, scaled, whatever the
/// soft contacts do to the split between them. Row by row (`min(j, rest)` each, the default),
/// a tip's friction spring that shifts a box's load between its corners on the table left
/// rapier a part with a torque its own solve does not make: the 4 g box pressed against a wall
/// went from the plugin's impulses at up to 7.6 rad/s, which rapier's first kick-drift pass
/// turned into jumps of ~0.1 mm along the wall before its contacts stopped it; the spring then
/// held every jump (8 N along the wall, the box moving at 11 mm/s in the hold and thrown when
/// the tip withdrew; `press_on_table::tip_presses_a_box_against_a_wall`, the spring being the
/// default).
fn pair_scales(rigid: &[RigidRow], j_rigid: &[f64], rest: &[f64]) -> Vec<f64> {
    // Each rigid row's normal (index into `j_rigid` and `rest`, which share the layout).
    let mut normals = Vec::with_capacity(rigid.len());
    let mut i = 0;
    for r in rigid {
        normals.push(i);
        i += if r.mu > 0.0 { 3 } else { 1 };
    }
    let same = |x: &RigidRow, y: &RigidRow| x.a == y.a && x.b == y.b;
    rigid
        .iter()
        .map(|r| {
            let (with, without) = rigid
                .iter()
                .zip(&normals)
                .filter(|(o, _)| same(o, r))
                .fold((0.0, 0.0), |(w, wo), (_, &n)| {
                    (w + j_rigid[n].max(0.0), wo + rest[n].max(0.0))
                });
            if without > 0.0 {
                (with / without).min(1.0)
            } else {
                0.0
            }
        })
        .collect()
}

/// [`solve_scalars`] with the joint motors of the rows' multibodies held to their effort
/// (`saturation`): after each answer the motors it pushes past their effort are saturated and
/// the rows solved again from the velocities at the start (the set of saturated motors only
/// grows: at most one more solve per motor). Leaves `bodies` at the last answer's end, with
/// the multibodies' last fold.
#[allow(clippy::too_many_arguments)]
fn solve_saturating(
    bodies: &mut [BodyState],
    rows: &[Scalar],
    warm: &[Option<f64>],
    h: f64,
    state: &mut Vec<State>,
    passes: &mut usize,
    immobile_count: &mut u64,
    degenerate_count: &mut u64,
    buffers: &mut Buffers,
    prior: Option<&DMatrix<f64>>,
    fast: bool,
) -> Option<()> {
    let links = rows
        .iter()
        .flat_map(|r| [r.a, r.b])
        .flatten()
        .any(|i| bodies[i].link.is_some());
    // A group with a multibody or impulse-jointed link starts cold: warm-started, the jointed
    // fingers of `tests/jointed.rs` held their box 43-75 % off the law (session 19; why is not
    // known yet).
    let cold: Vec<Option<f64>>;
    let warm = if links {
        cold = vec![None; rows.len()];
        &cold[..]
    } else {
        warm
    };
    let mut start = if links { bodies.to_vec() } else { Vec::new() };
    let mut wrenches = vec![Vector6::zeros(); if links { bodies.len() } else { 0 }];
    let mut u0 = std::mem::take(&mut buffers.u0);
    loop {
        let mut immobile = 0;
        u0.clear();
        u0.extend(rows.iter().map(|r| r.velocity_parts(bodies)));
        let Some(bound) = solve_scalars(
            bodies,
            rows,
            warm,
            h,
            state,
            passes,
            &mut immobile,
            buffers,
            prior,
            fast,
        ) else {
            buffers.u0 = u0;
            return None;
        };
        let j = &buffers.j;
        if links {
            wrenches.iter_mut().for_each(|w| *w = Vector6::zeros());
            for (r, &ji) in rows.iter().zip(j) {
                for (i, s, ang) in [(r.a, 1.0, r.ang_a), (r.b, -1.0, r.ang_b)] {
                    if let Some(i) = i.filter(|&i| bodies[i].link.is_some()) {
                        let (l, a) = (r.lin * (s * ji), ang * (s * ji));
                        wrenches[i] += Vector6::new(l.x, l.y, l.z, a.x, a.y, a.z);
                    }
                }
            }
            let Some(saturated) = saturation::saturate(&mut start, &wrenches) else {
                buffers.u0 = u0;
                return None;
            };
            if saturated > 0 {
                bodies.clone_from_slice(&start);
                continue;
            }
        }
        *immobile_count += immobile;
        let locked = if links {
            multibody::locked_load(bodies, &wrenches)
        } else {
            0.0
        };
        let failed = degenerate(j, bound)
            || locked > LOCKED_FACTOR * bound
            || speed_ratio(bodies, rows, &u0, h) > SPEED_FACTOR;
        buffers.u0 = u0;
        if failed {
            *degenerate_count += 1;
            return None;
        }
        return Some(());
    }
}

/// How much faster than the group's speed scale the answer leaves a contact point of its
/// dynamic bodies: the largest `|u|` over the point rows (normals and tangents; `u` the row's
/// velocity of its dynamic bodies after the impulses, `bodies`) over the scale, the largest
/// `|u0| + |u_kin| + |target|` (`u0` the same before the impulses, `u_kin` the row's fixed or
/// kinematic bodies' part: `parts`) plus the largest speed a soft normal's law force gives
/// its bodies alone over the (sub)step of `h` \[s\], `h F w_ii`. 0 if nothing moves.
fn speed_ratio(bodies: &[BodyState], rows: &[Scalar], parts: &[(f64, f64)], h: f64) -> f64 {
    let (mut start, mut soft, mut end) = (0.0f64, 0.0f64, 0.0f64);
    for (r, &(u0, kin)) in rows.iter().zip(parts) {
        if r.at.is_none() {
            continue;
        }
        start = start.max(u0.abs() + kin.abs() + r.target.abs());
        end = end.max(r.velocity_parts(bodies).0.abs());
        if let Kind::SoftNormal { force, d, rigid } = r.kind {
            let w = mobility(bodies, r, r);
            soft = soft.max(h * force.abs() * w / reach_factor(rigid, h * d * w.max(0.0)));
        }
    }
    if end == 0.0 {
        0.0
    } else {
        end / (start + soft)
    }
}

/// What came of a coupled solve ([`solve_coupled`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Coupled {
    /// Solved: the rows hold their impulses.
    Solved,
    /// A system was not finite.
    NotFinite,
    /// The answer was degenerate (`degenerate`): the hard rows could not all be met and their
    /// compliance carried the answer.
    Degenerate,
}

/// The failure of a solve whose degenerate count went from `before` to `after`.
fn failure(before: u64, after: u64) -> Coupled {
    if after > before {
        Coupled::Degenerate
    } else {
        Coupled::NotFinite
    }
}

/// The warm start of the scalar rows [`build`] makes of `soft` and `rigid`, in its order, into
/// `out`: each row's impulse of the previous (sub)step scaled to this one's `h` \[s\]
/// ([`Warm::over`]; of a rigid row the solve without the soft contacts, `which` 0, or with
/// them, 1), `None` for a new contact.
fn warm_start(soft: &[Row], rigid: &[RigidRow], which: usize, h: f64, out: &mut Vec<Option<f64>>) {
    out.clear();
    for r in soft {
        let w = r.warm.map(|w| w.over(h, &r.t1, &r.t2));
        out.push(w.map(|w| w[0].max(0.0)));
        if r.mu > 0.0 {
            out.extend([w.map(|w| w[1]), w.map(|w| w[2])]);
            if r.torsion_arm > 0.0 {
                out.push(w.map(|w| w[3]));
            }
        }
    }
    for r in rigid {
        let w = r.warm.map(|w| w[which].over(h, &r.t1, &r.t2));
        out.push(w.map(|w| w[0].max(0.0)));
        if r.mu > 0.0 {
            out.extend([w.map(|w| w[1]), w.map(|w| w[2])]);
        }
    }
}

fn rigid_scalars(rigid: &[RigidRow]) -> usize {
    rigid.iter().map(|r| if r.mu > 0.0 { 3 } else { 1 }).sum()
}
