//! The mobility of each kind of body the contact problem sees: how an impulse on a body
//! changes its velocity.
//!
//! - A **free** dynamic body: [`BodyState`]'s per-axis inverse mass and world inverse inertia
//!   (rapier's effective ones, [`free_mobility`]).
//! - A **fixed**, **kinematic** or sleeping body: zero inverse mass (impulses do not move it).
//! - A **multibody link** (rapier's reduced coordinates) and a member of a **jointed**
//!   assembly (bodies held by impulse joints, `jointed`): a [`Link`] of a [`Generalised`]
//!   body, whose response is `J W J^T` (`multibody` builds it from rapier's multibody,
//!   `jointed` from the assembly's joint rows); its motors' fold is a [`Fold`].
//!
//! This module imports nothing of the plugin's but the `f32`/`f64` boundary: the problem
//! (`problem`), the solvers (`solve`, `rigid`, `saturation`) and the builders of the body
//! table (`bodies`, `multibody`, `jointed`) import it.
//!
//! Units: SI, all `f64` (nalgebra): velocities [m/s], angular velocities [rad/s], inverse
//! masses [1/kg], inverse inertias [1/(kg m^2)], impulses \[N s\], angular impulses [N m s].

use nalgebra::{DMatrix, DVector, Matrix3, Matrix6, Vector3, Vector6};
use rapier3d::prelude::RigidBody;

use crate::boundary::to_f64;

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
    /// accelerations' (what the step's substep count reads, `step::split`), for a member of an
    /// impulse-jointed assembly with its joints' hard rows (locked axes, active limits:
    /// `jointed`). Equal to `(v, w)` for a free, fixed or kinematic body.
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
    /// multibody link's: [`apply`]).
    #[inline]
    pub(crate) fn apply(&mut self, p: &Vector3<f64>, imp: &Vector3<f64>) {
        self.v += self.inv_m.component_mul(imp);
        self.w += self.inv_i * (p - self.com).cross(imp);
    }

    /// Relative velocity change along `dir_i` at `p_i` from a unit impulse along `dir_k` at `p_k`.
    #[inline]
    pub(crate) fn mobility(
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

    /// A body that impulses do not move (fixed, kinematic, or welded to a kinematic root) at
    /// centre of mass `com` \[m\], moving at `v` [m/s] and `w` [rad/s] over the (sub)step.
    pub(crate) fn immobile(v: Vector3<f64>, w: Vector3<f64>, com: Vector3<f64>) -> Self {
        Self {
            v,
            w,
            inv_m: Vector3::zeros(),
            inv_i: Matrix3::zeros(),
            com,
            a_ext: Vector3::zeros(),
            passive: (v, w),
            link: None,
        }
    }

    /// Whether impulses move the body (a free dynamic body or a multibody link).
    pub(crate) fn is_dynamic(&self) -> bool {
        self.inv_m.iter().any(|m| *m > 0.0) || self.link.is_some()
    }
}
/// A link of a multibody in the solver's body table.
#[derive(Debug, Clone)]
pub(crate) struct Link {
    /// Table index of the body that holds the multibody's generalised mobility (the first of
    /// its links entered in the table; this body itself if it is that one).
    pub host: usize,
    /// The link's place in its multibody's `links` (and `blocks`).
    pub slot: usize,
    /// On the host only: the multibody.
    pub multi: Option<Generalised>,
}

/// A multibody's generalised mobility, held by its host link.
#[derive(Debug, Clone)]
pub(crate) struct Generalised {
    /// The mobility the solve sees (motors folded in) \[1/kg, 1/(kg m^2)\], n x n.
    pub mobility: DMatrix<f64>,
    /// The free generalised velocity over the (sub)step (external accelerations and motors).
    pub qdot: DVector<f64>,
    /// The generalised acceleration of gravity and the user's forces.
    pub acc: DVector<f64>,
    /// The generalised velocity over the (sub)step without the joint motors' push (the
    /// velocity now plus `acc` over the step; an impulse-jointed assembly's with its hard
    /// rows, `jointed`).
    pub passive: DVector<f64>,
    /// Table indices of the multibody's links in the table (the host first).
    pub links: Vec<usize>,
    /// Each link's jacobian (6 x n: the linear velocity of its centre of mass, then its
    /// angular velocity, per generalised velocity), world frame, by slot.
    pub jacs: Vec<DMatrix<f64>>,
    /// `W J^T` of each link (n x 6), by slot.
    pub wj: Vec<DMatrix<f64>>,
    /// The links' spatial mobility blocks `J_a W J_b^T` (6 x 6), by slots `[a][b]`: what a
    /// wrench on link `b` does to the velocity of link `a`.
    pub blocks: Vec<Vec<Matrix6<f64>>>,
    /// What folding the motors again needs (`saturation`); `None` for a generalised body
    /// whose motors are not folded here (`jointed`).
    pub fold: Option<Fold>,
}

impl Generalised {
    /// A generalised body of mobility `mobility`, free velocity `qdot` and external
    /// acceleration `acc`, with no links yet ([`Generalised::add`]).
    pub(crate) fn new(mobility: DMatrix<f64>, qdot: DVector<f64>, acc: DVector<f64>) -> Self {
        Self {
            mobility,
            passive: qdot.clone(),
            qdot,
            acc,
            links: Vec::with_capacity(2),
            jacs: Vec::with_capacity(2),
            wj: Vec::with_capacity(2),
            blocks: Vec::with_capacity(2),
            fold: None,
        }
    }

    /// Recomputes every link's `W J^T` and the blocks from `mobility` (after a new fold:
    /// `saturation`).
    pub(crate) fn refresh(&mut self) {
        let jacs = std::mem::take(&mut self.jacs);
        let links = std::mem::take(&mut self.links);
        self.wj.clear();
        self.blocks.clear();
        for (index, jac) in links.into_iter().zip(jacs) {
            self.add(index, jac);
        }
    }

    /// Adds a link of jacobian `jac` at table index `index`, returning its slot.
    pub(crate) fn add(&mut self, index: usize, jac: DMatrix<f64>) -> usize {
        let wj = &self.mobility * jac.transpose();
        let block = |j: &DMatrix<f64>, w: &DMatrix<f64>| -> Matrix6<f64> {
            let m = j * w;
            Matrix6::from_fn(|r, c| m[(r, c)])
        };
        let slot = self.links.len();
        for a in 0..slot {
            let b = block(&self.jacs[a], &wj);
            self.blocks[a].push(b);
        }
        let mut row: Vec<Matrix6<f64>> = (0..slot).map(|b| block(&jac, &self.wj[b])).collect();
        row.push(block(&jac, &wj));
        self.blocks.push(row);
        self.links.push(index);
        self.jacs.push(jac);
        self.wj.push(wj);
        slot
    }
}
/// One motor of a free dof, in the multibody's reduced order.
#[derive(Debug, Clone)]
pub(crate) struct Motor {
    /// Its place in the reduced order.
    pub k: usize,
    /// Its dof (all dofs' order).
    pub dof: usize,
    /// What it adds to the generalised mass while it holds (`b / a`) \[kg or kg m^2\].
    pub b: f64,
    /// What it adds to the momentum while it holds (`c / a`) \[N s or N m s\].
    pub c: f64,
    /// Its largest impulse over the (sub)step, `max_force h` \[N s or N m s\].
    pub max: f64,
    /// The impulse it pushes once saturated (`+-max`); `None` while it holds.
    pub saturated: Option<f64>,
}

/// What a multibody's motor folding needs to be done again with some motors saturated.
#[derive(Debug, Clone)]
pub(crate) struct Fold {
    /// The free dofs (reduced order -> all dofs).
    pub free: Vec<usize>,
    /// rapier's generalised mass of the free dofs (reduced order).
    pub m_r: DMatrix<f64>,
    /// The free velocity without motors over the (sub)step (reduced order).
    pub q_r: DVector<f64>,
    /// The motors.
    pub motors: Vec<Motor>,
    /// The dof couplings `(k1, k2, coeff)`: `qdot_k2 = coeff qdot_k1` (reduced order).
    pub couplings: Vec<(usize, usize, f64)>,
}

impl Fold {
    /// The folded mobility and free velocity (reduced order): `(M + B)^-1` and `(M + B)^-1 (M
    /// q + C)` over the motors that hold, each saturated one's impulse in the momentum, the
    /// couplings applied as rank-one Schur complements; `None` if singular.
    pub(crate) fn fold(&self) -> Option<(DMatrix<f64>, DVector<f64>)> {
        let mut m_eff = self.m_r.clone();
        let mut momentum = &self.m_r * &self.q_r;
        for m in &self.motors {
            match m.saturated {
                None => {
                    m_eff[(m.k, m.k)] += m.b;
                    momentum[m.k] += m.c;
                }
                Some(l) => momentum[m.k] += l,
            }
        }
        let mut w = m_eff.try_inverse()?;
        let mut qf = &w * momentum;
        couple(&self.couplings, &mut w, &mut qf);
        Some((w, qf))
    }
}

/// The dof couplings `couplings` applied to the reduced mobility `w` and free velocity `qf`:
/// each a rank-one Schur complement, `w - (w g)(w g)^T / (g^T w g)`, `qf - w g (g^T qf) / (g^T
/// w g)` with `g = e_2 - coeff e_1` (one after the other on the updated `w`).
pub(crate) fn couple(
    couplings: &[(usize, usize, f64)],
    w: &mut DMatrix<f64>,
    qf: &mut DVector<f64>,
) {
    for &(k1, k2, coeff) in couplings {
        let mut g = DVector::<f64>::zeros(w.nrows());
        g[k2] += 1.0;
        g[k1] -= coeff;
        let wg = &*w * &g;
        let gwg = g.dot(&wg);
        if !(gwg > 0.0 && gwg.is_finite()) {
            continue;
        }
        let along = g.dot(qf) / gwg;
        *qf -= &wg * along;
        *w -= (&wg * wg.transpose()) / gwg;
    }
}
/// A dynamic body's mobility as a free body: rapier's effective inverse mass (zero along locked
/// translations) \[1/kg\] and world inverse inertia tensor \[1/(kg m^2)\].
pub(crate) fn free_mobility(rb: &RigidBody) -> (Vector3<f64>, Matrix3<f64>) {
    let mp = rb.mass_properties();
    let ii = &mp.effective_world_inv_inertia;
    let inv_i = Matrix3::new(
        ii.m11 as f64,
        ii.m12 as f64,
        ii.m13 as f64,
        ii.m12 as f64,
        ii.m22 as f64,
        ii.m23 as f64,
        ii.m13 as f64,
        ii.m23 as f64,
        ii.m33 as f64,
    );
    (to_f64(mp.effective_inv_mass), inv_i)
}
/// The multibody of link `i` (held by its host) and the link's slot in it.
fn multi_of(bodies: &[BodyState], i: usize) -> Option<(&Generalised, usize)> {
    let link = bodies[i].link.as_deref()?;
    let multi = bodies[link.host].link.as_deref()?.multi.as_ref()?;
    Some((multi, link.slot))
}

/// Applies the wrench `[lin; ang]` (force at its centre of mass \[N s\], torque \[N m s\]) to
/// link `i`: the multibody's generalised velocity changes by `W J^T f`, and every link of it in
/// the table moves with it (by its block `J_k W J_i^T f`).
pub(crate) fn apply(bodies: &mut [BodyState], i: usize, lin: &Vector3<f64>, ang: &Vector3<f64>) {
    let f = Vector6::new(lin.x, lin.y, lin.z, ang.x, ang.y, ang.z);
    let count = multi_of(bodies, i).map(|(m, _)| m.links.len()).unwrap_or(0);
    for k in 0..count {
        let Some((b, d)) = multi_of(bodies, i).map(|(m, s)| (m.links[k], m.blocks[k][s] * f))
        else {
            return;
        };
        bodies[b].v += Vector3::new(d[0], d[1], d[2]);
        bodies[b].w += Vector3::new(d[3], d[4], d[5]);
    }
}

/// The mobility between a wrench direction `(lin_x, ang_x)` on body `x` and `(lin_y, ang_y)`
/// on body `y` if both are links of one multibody (`f_x^T J_x W J_y^T f_y`), else `None`.
pub(crate) fn pair(
    bodies: &[BodyState],
    x: usize,
    (lin_x, ang_x): (&Vector3<f64>, &Vector3<f64>),
    y: usize,
    (lin_y, ang_y): (&Vector3<f64>, &Vector3<f64>),
) -> Option<f64> {
    if !same_multibody(bodies, x, y) {
        return None;
    }
    let (multi, sx) = multi_of(bodies, x)?;
    let sy = bodies[y].link.as_deref()?.slot;
    let fx = Vector6::new(lin_x.x, lin_x.y, lin_x.z, ang_x.x, ang_x.y, ang_x.z);
    let fy = Vector6::new(lin_y.x, lin_y.y, lin_y.z, ang_y.x, ang_y.y, ang_y.z);
    Some(fx.dot(&(multi.blocks[sx][sy] * fy)))
}

/// Whether bodies `x` and `y` are links of one multibody.
pub(crate) fn same_multibody(bodies: &[BodyState], x: usize, y: usize) -> bool {
    match (bodies[x].link.as_deref(), bodies[y].link.as_deref()) {
        (Some(a), Some(b)) => a.host == b.host,
        _ => false,
    }
}
