//! rapier's own contacts of a multibody link against a fixed or kinematic body, along a
//! direction the link's multibody cannot move it: dropped before rapier's solver sees them.
//!
//! **Why.** rapier solves such a contact (`generic_contact_constraint.rs`) with the row's
//! generalised jacobian `a = J^T [n; r x n]` (`J` the link's jacobian, `r` the lever from its
//! centre of mass) and the effective mass `1 / (a^T W a)`, `W` the multibody's inverse
//! augmented mass; it adds no regularisation (its `cfm_factor` scales the impulse, not the
//! denominator). rapier's jacobians and `W` are `f32`, so along a direction the multibody's
//! joints cannot move the contact point (a prismatic finger's vertical under a kinematic hand
//! base) `a` is `f32` noise (`|a| ~ eps |J|`), and so is `a^T W a` (6.46e-14 1/kg measured on
//! the parallel gripper's finger, against 8.5 1/kg along its joint). The row's impulse is then
//! `v / (a^T W a) ~ v / eps^2` and the generalised velocity it leaves, `W a lambda ~ v / eps`:
//! the parallel gripper lowered 5.5 mm onto the table after its grasp threw a finger 1e10 pad
//! radii along its joint (peak x 8e10, 47 kN). No motor can stall against such a row: the row
//! is not along any dof.
//!
//! **The criterion** is the coupled soft solve's ([`IMMOBILE`], `rigid.rs`): a row whose own
//! mobility `a^T W a` is at most `IMMOBILE` (`f32::EPSILON`) of the link's mobility at the
//! same point summed over three axes (`sum_k a_k^T W a_k`, the same `J` and `W`) cannot be
//! moved along by the multibody; its solver contact is dropped (its friction with it: a normal
//! carrying nothing carries no friction). The other side is fixed or kinematic (infinite mass)
//! or another such link of an immobile row: the pair is two bodies neither of which can yield,
//! which a rigid solver cannot answer with a finite force; the link goes on along its
//! commanded path and overlaps the other body until its joints can move it out (then rapier's
//! contact acts again, at a mobility seven decades above the noise). A link a motor drives
//! into a fixed body is not such a row: the motor's dof moves the point along the normal, the
//! contact stays, and the motor stalls at its effort limit.
//!
//! **Cost.** rapier recycles a pair's contacts between full narrow-phase updates only if
//! neither collider asks for a hook, so the hook is turned on (before each step, from the
//! pair's last contacts) only for the link colliders that have such a row within rapier's
//! prediction distance, and off again when they have none: every other pair is detected and
//! solved exactly as without this module. The same set carries, for one step, the colliders
//! of pairs whose recycled contacts act across a gap (`stale_contacts`): the hook makes rapier
//! update their pairs afresh.

use std::collections::{HashMap, HashSet};
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use nalgebra::{DMatrix, DVector, Vector3};
use rapier3d::prelude::{
    ActiveHooks, ColliderHandle, ColliderSet, ContactModificationContext, PhysicsWorld,
    RigidBodySet,
};

use crate::boundary::to_f64;
use crate::multibody::rapier_mobility;
use crate::rigid::IMMOBILE;

/// A dynamic multibody link as rapier's contact solver sees it: its jacobian on the free dofs
/// (6 x r, world frame: velocity of its centre of mass, angular velocity) and its multibody's
/// inverse augmented mass (r x r, shared by the multibody's links).
#[derive(Debug, Clone)]
struct LinkMobility {
    com: Vector3<f64>,
    jac: DMatrix<f64>,
    w: Arc<DMatrix<f64>>,
}

impl LinkMobility {
    /// The generalised row of a unit force along `dir` at `point` (`J^T [dir; r x dir]`).
    fn row(&self, point: &Vector3<f64>, dir: &Vector3<f64>) -> DVector<f64> {
        let torque = (point - self.com).cross(dir);
        let f = nalgebra::Vector6::new(dir.x, dir.y, dir.z, torque.x, torque.y, torque.z);
        self.jac.tr_mul(&f)
    }

    /// `(a^T W a, sum_k a_k^T W a_k)`: the point's mobility along `normal` and summed over
    /// three axes \[1/kg\].
    fn mobility(&self, point: &Vector3<f64>, normal: &Vector3<f64>) -> (f64, f64) {
        let quad = |a: DVector<f64>| a.dot(&(&*self.w * &a));
        let along = quad(self.row(point, normal));
        let scale = (0..3)
            .map(|k| quad(self.row(point, &Vector3::ith(k, 1.0))))
            .sum();
        (along, scale)
    }
}

/// The world's dynamic multibody links' colliders with their mobility, the colliders whose
/// `MODIFY_SOLVER_CONTACTS` hook this module turned on, and the solver contacts it dropped.
#[derive(Debug, Default)]
pub(crate) struct LinkContacts {
    links: HashMap<ColliderHandle, LinkMobility>,
    hooked: HashSet<ColliderHandle>,
    dropped: AtomicU64,
    /// Colliders whose pairs were handed back to rapier's full update for a step because a
    /// recycled contact of theirs acted across a gap (`stale_contacts`), since the last
    /// [`Self::take_stale`].
    stale: u64,
}

impl Clone for LinkContacts {
    fn clone(&self) -> Self {
        Self {
            links: self.links.clone(),
            hooked: self.hooked.clone(),
            dropped: AtomicU64::new(self.dropped.load(Ordering::Relaxed)),
            stale: self.stale,
        }
    }
}

/// One side of a pair: a link, a body that cannot yield (fixed, kinematic, no body), or a free
/// rigid body (whose own mobility keeps rapier's row finite).
enum Side<'a> {
    Link(&'a LinkMobility),
    Rigid,
    Free,
}

impl LinkContacts {
    /// Reads every dynamic multibody link's mobility as rapier last factorised it, then turns
    /// the solver-contact hook on for each link collider that has an immobile row against a
    /// body that cannot yield among its pairs' current contacts and for one collider of each
    /// pair whose recycled contacts act across a gap (`stale_contacts`), and off for the
    /// others this module turned on.
    pub(crate) fn refresh(&mut self, world: &mut PhysicsWorld) {
        self.links.clear();
        for mb in world.multibody_joints.multibodies() {
            let Some((free, w)) = rapier_mobility(mb) else {
                continue;
            };
            let w = Arc::new(w);
            for link in mb.links() {
                let Some(rb) = world.bodies.get(link.rigid_body_handle()) else {
                    continue;
                };
                if !rb.is_dynamic() {
                    continue;
                }
                let full = mb.body_jacobian(link.link_id());
                let jac = DMatrix::from_fn(6, free.len(), |r, c| full[(r, free[c])] as f64);
                let entry = LinkMobility {
                    com: to_f64(rb.mass_properties().world_com),
                    jac,
                    w: Arc::clone(&w),
                };
                for &ch in rb.colliders() {
                    self.links.insert(ch, entry.clone());
                }
            }
        }
        let mut wanted = HashSet::new();
        for &ch in self.links.keys() {
            let blocked = world.narrow_phase.contact_pairs_with(ch).any(|pair| {
                let (c1, c2) = (pair.collider1, pair.collider2);
                let (s1, s2) = (
                    self.side(c1, &world.colliders, &world.bodies),
                    self.side(c2, &world.colliders, &world.bodies),
                );
                pair.manifolds().iter().any(|m| {
                    let normal = to_f64(m.data.normal);
                    m.points.iter().any(|p| {
                        let Some(co) = world.colliders.get(c1) else {
                            return false;
                        };
                        let point = to_f64(co.position() * p.local_p1);
                        immobile(&s1, &s2, &point, &normal)
                    })
                })
            });
            if blocked {
                wanted.insert(ch);
            }
        }
        // Pairs whose recycled contacts act across a gap, updated afresh this step.
        let stale = crate::stale_contacts::stale_colliders(world, &self.hooked);
        self.stale += stale.len() as u64;
        wanted.extend(stale);
        for &ch in self.hooked.difference(&wanted) {
            if let Some(co) = world.colliders.get_mut(ch) {
                co.set_active_hooks(co.active_hooks() - ActiveHooks::MODIFY_SOLVER_CONTACTS);
            }
        }
        self.hooked.retain(|ch| wanted.contains(ch));
        for ch in wanted {
            let Some(co) = world.colliders.get_mut(ch) else {
                continue;
            };
            let hooks = co.active_hooks();
            if !hooks.contains(ActiveHooks::MODIFY_SOLVER_CONTACTS) {
                co.set_active_hooks(hooks | ActiveHooks::MODIFY_SOLVER_CONTACTS);
                self.hooked.insert(ch);
            }
        }
    }

    /// How collider `h` takes part in a contact row.
    fn side(&self, h: ColliderHandle, colliders: &ColliderSet, bodies: &RigidBodySet) -> Side<'_> {
        if let Some(l) = self.links.get(&h) {
            return Side::Link(l);
        }
        let body = colliders.get(h).and_then(|c| c.parent());
        match body.and_then(|b| bodies.get(b)) {
            Some(rb) if rb.is_dynamic() => Side::Free,
            _ => Side::Rigid,
        }
    }

    /// Whether the user's hooks asked for this pair's solver contacts (a collider whose hook
    /// the user, not this module, turned on).
    pub(crate) fn user_asked(&self, ctx: &ContactModificationContext) -> bool {
        [ctx.collider1, ctx.collider2].iter().any(|h| {
            !self.hooked.contains(h)
                && ctx.colliders.get(*h).is_some_and(|c| {
                    c.active_hooks()
                        .contains(ActiveHooks::MODIFY_SOLVER_CONTACTS)
                })
        })
    }

    /// Drops the pair's solver contacts along which neither side can move (a link's immobile
    /// row against a body that cannot yield); counts them ([`Self::take_dropped`]).
    pub(crate) fn filter(&self, ctx: &mut ContactModificationContext) {
        let s1 = self.side(ctx.collider1, ctx.colliders, ctx.bodies);
        let s2 = self.side(ctx.collider2, ctx.colliders, ctx.bodies);
        if !matches!((&s1, &s2), (Side::Link(_), _) | (_, Side::Link(_))) {
            return;
        }
        let Some(rigid) = ctx.rigid_mut() else {
            return;
        };
        let normal = to_f64(*rigid.normal);
        let before = rigid.solver_contacts.len();
        // Inside the hook the anchors are world points (rapier's `SolverContact` docs); the
        // row acts at their midpoint.
        rigid.solver_contacts.retain(|c| {
            let point = to_f64((c.anchor1 + c.anchor2) * 0.5);
            !immobile(&s1, &s2, &point, &normal)
        });
        let dropped = (before - rigid.solver_contacts.len()) as u64;
        self.dropped.fetch_add(dropped, Ordering::Relaxed);
    }

    /// The colliders refreshed as stale since the last call.
    pub(crate) fn take_stale(&mut self) -> u64 {
        std::mem::take(&mut self.stale)
    }

    /// The solver contacts dropped since the last call.
    pub(crate) fn take_dropped(&self) -> u64 {
        self.dropped.swap(0, Ordering::Relaxed)
    }
}

/// Whether a row along `normal` at `point` between sides `s1` and `s2` is one neither can move
/// along: at least one link, no free body, and the links' mobility along it at most
/// [`IMMOBILE`] of theirs summed over three axes (not when that sum is 0: rapier gives a row of
/// zero mobility no impulse).
fn immobile(s1: &Side<'_>, s2: &Side<'_>, point: &Vector3<f64>, normal: &Vector3<f64>) -> bool {
    if matches!(s1, Side::Free) || matches!(s2, Side::Free) {
        return false;
    }
    let (mut along, mut scale, mut links) = (0.0, 0.0, 0);
    for s in [s1, s2] {
        match s {
            Side::Link(l) => {
                let (a, k) = l.mobility(point, normal);
                along += a;
                scale += k;
                links += 1;
            }
            Side::Free | Side::Rigid => {}
        }
    }
    links > 0 && scale > 0.0 && along <= IMMOBILE * scale
}
