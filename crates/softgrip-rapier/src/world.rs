//! [`SoftWorld`]: rapier's sets and pipeline bundled with the plugin; `step()` advances `dt`.
//!
//! One step:
//! 1. rapier's step is `N = num_solver_iterations` passes of symplectic Euler ("kick, then
//!    drift"), so under gravity its stored velocity lags the true (velocity-Verlet) velocity by
//!    `g dt / (2N)`. A step split into `n` substeps of `h = dt/n` must keep that convention,
//!    or every bounce gains or loses `g (dt - h) / (2N)` of speed (measured: +8 % energy per
//!    bounce of a ball dropped 10 cm at 60 Hz before this rule). So a split step first applies
//!    the impulse `m g (dt - h) / (2N)`, runs its substeps with gravity, and removes
//!    `m g (dt - h) / (2N)` at the end. In free flight that is *exactly* one rapier step of
//!    `dt`; in contact it is a fine symplectic integration.
//! 2. The soft contacts are found fresh at the current poses (`detect`).
//! 3. The substep count `n` is chosen (`substep`); position-based kinematic bodies are moved
//!    along their path in `n` equal parts (linear in translation, slerp in rotation).
//! 4. Per substep: contacts, impulses (`solve`), `apply_impulse_at_point`, then rapier's
//!    pipeline with `dt / n`.
//! 5. The readout is assembled (`SoftContacts::contacts`).

use std::collections::HashMap;
use std::time::Instant;

use nalgebra::{Matrix3, Vector3};
use rapier3d::prelude::{
    BroadPhaseBvh, CCDSolver, ColliderHandle, ColliderSet, ImpulseJointSet, IntegrationParameters,
    IslandManager, MultibodyJointSet, NarrowPhase, PhysicsPipeline, Pose, RigidBodyHandle,
    RigidBodySet, RigidBodyType, SoftBodySet, Vector,
};
use softgrip_law::Regime;

use crate::contacts::{PairState, SoftContacts};
use crate::detect::{self, Model, Scene, compression_from_signed_distance, to_f32, to_f64};
use crate::error::Result;
use crate::fingertip::SoftFingertip;
use crate::readout::SoftContact;
use crate::solve::{self, BodyState, Row};
use crate::substep::{self, theta_blend};

/// A rapier world with soft fingertips. All fields are public: build the scene with rapier's
/// own API on `bodies` and `colliders`, register fingertips, then call [`step`](Self::step).
pub struct SoftWorld {
    /// Gravity [m/s^2].
    pub gravity: Vector,
    /// rapier's integration parameters; `dt` [s] is the step. For micro-scale scenes set
    /// `length_unit` to about the fingertip radius.
    pub params: IntegrationParameters,
    /// Rigid bodies.
    pub bodies: RigidBodySet,
    /// Colliders.
    pub colliders: ColliderSet,
    /// Impulse joints.
    pub impulse_joints: ImpulseJointSet,
    /// Multibody joints.
    pub multibody_joints: MultibodyJointSet,
    /// rapier's own soft bodies (unrelated to the fingertips; passed through).
    pub soft_bodies: SoftBodySet,
    /// Islands.
    pub islands: IslandManager,
    /// Broad phase.
    pub broad_phase: BroadPhaseBvh,
    /// Narrow phase.
    pub narrow_phase: NarrowPhase,
    /// CCD solver.
    pub ccd_solver: CCDSolver,
    /// The pipeline.
    pub pipeline: PhysicsPipeline,
    /// The soft fingertips, their contacts and counters.
    pub soft: SoftContacts,
    started: bool,
}

impl Default for SoftWorld {
    fn default() -> Self {
        Self::new()
    }
}

/// Velocity of a kinematic body over the coming (sub)step.
type KinematicVelocity = HashMap<RigidBodyHandle, (Vector3<f64>, Vector3<f64>)>;

/// Body table and rows of one (sub)step.
struct Prepared {
    table: Vec<BodyState>,
    handles: Vec<RigidBodyHandle>,
    rows: Vec<Row>,
    models: Vec<Model>,
    /// Index into `SoftContacts::geoms` of each row.
    geom: Vec<usize>,
}

/// The solver's body table under construction.
#[derive(Default)]
struct BodyTable {
    index: HashMap<RigidBodyHandle, usize>,
    table: Vec<BodyState>,
    handles: Vec<RigidBodyHandle>,
}

/// Per-contact sums over the substeps of a step.
struct Accum {
    jn: f64,
    jt: Vector3<f64>,
    jtw: f64,
    sliding: bool,
    peak_force: f64,
    max_delta: f64,
    duration: f64,
    point: Vector3<f64>,
    normal: Vector3<f64>,
    delta_end: f64,
    model: Model,
}

impl SoftWorld {
    /// An empty world: gravity -9.81 m/s^2 along y, rapier's default parameters (dt = 1/60 s).
    pub fn new() -> Self {
        Self {
            gravity: Vector::new(0.0, -9.81, 0.0),
            params: IntegrationParameters::default(),
            bodies: RigidBodySet::new(),
            colliders: ColliderSet::new(),
            impulse_joints: ImpulseJointSet::new(),
            multibody_joints: MultibodyJointSet::new(),
            soft_bodies: SoftBodySet::new(),
            islands: IslandManager::new(),
            broad_phase: BroadPhaseBvh::new(),
            narrow_phase: NarrowPhase::new(),
            ccd_solver: CCDSolver::new(),
            pipeline: PhysicsPipeline::new(),
            soft: SoftContacts::new(),
            started: false,
        }
    }

    /// Registers `collider` as the soft fingertip `fingertip` (see [`SoftContacts::register`]).
    pub fn register(&mut self, collider: ColliderHandle, fingertip: SoftFingertip) -> Result<()> {
        self.soft.register(collider, fingertip, &mut self.colliders)
    }

    fn pipeline_step(&mut self, h: f64, gravity: Vector) {
        let t = Instant::now();
        let mut p = self.params;
        p.dt = h as f32;
        self.pipeline.step(
            gravity,
            &p,
            &mut self.islands,
            &mut self.broad_phase,
            &mut self.narrow_phase,
            &mut self.bodies,
            &mut self.colliders,
            &mut self.impulse_joints,
            &mut self.multibody_joints,
            &mut self.soft_bodies,
            &mut self.ccd_solver,
            &self.soft.hooks,
            &(),
        );
        self.soft.counters.pipeline_time += t.elapsed();
    }

    fn detect(&mut self, dt: f64) {
        let t = Instant::now();
        let scene = Scene {
            bodies: &self.bodies,
            colliders: &self.colliders,
            narrow_phase: &self.narrow_phase,
            broad_phase: &self.broad_phase,
        };
        let soft = &mut self.soft;
        detect::detect(&scene, &soft.tips, dt, &mut soft.geoms, &mut soft.counters);
        soft.counters.detect_time += t.elapsed();
    }

    /// Advances the world by `params.dt`.
    pub fn step(&mut self) {
        let dt = self.params.dt as f64;
        if !(dt > 0.0) {
            self.pipeline_step(0.0, self.gravity);
            return;
        }
        if !self.started {
            // Fill the broad phase and narrow phase before the first soft detection.
            self.pipeline_step(0.0, self.gravity);
            self.started = true;
        }
        self.soft.counters.steps += 1;

        // Kinematic paths.
        let kinematic: Vec<(RigidBodyHandle, Pose, Pose)> = self
            .bodies
            .iter()
            .filter(|(_, rb)| rb.body_type() == RigidBodyType::KinematicPositionBased)
            .map(|(h, rb)| (h, *rb.position(), *rb.next_position()))
            .collect();

        // 2.-3. Contacts now, and the substep count.
        self.detect(dt);
        let kin_vel = self.kinematic_velocities(&kinematic, 1.0, dt);
        let pre = self.prepare(dt, &kin_vel, false);
        let theta = self.soft.accuracy.theta();
        let mut n = 1u32;
        for ((row, model), gi) in pre.rows.iter().zip(&pre.models).zip(&pre.geom) {
            let delta = compression_from_signed_distance(self.soft.geoms[*gi].dist);
            let mut vn = solve::normal_velocity(&pre.table, row);
            if delta > 0.0 {
                // A touching contact's velocity is known only up to the external velocity
                // increment of one step (rapier's stored velocity lags or leads the true one
                // by up to |a| dt): only the excess counts as dynamic.
                let a = solve::normal_external_acceleration(&pre.table, row).abs();
                vn = vn.signum() * (vn.abs() - a * dt).max(0.0);
            }
            let w = solve::normal_mobility(&pre.table, row);
            n = n.max(substep::substeps_for(
                &model.law,
                model.radius,
                delta,
                vn,
                w,
                dt,
                theta,
            ));
        }
        if n >= substep::MAX_SUBSTEPS {
            self.soft.counters.substep_cap_hits += 1;
        }
        self.soft.counters.substeps_last = n;
        self.soft.counters.substeps_total += n as u64;
        let h = dt / n as f64;
        // rapier's step of h is N internal "kick, drift" passes (N = num_solver_iterations):
        // its stored velocity lags the true one by g h / (2N).
        let lag = 0.5 / self.params.num_solver_iterations.max(1) as f64;
        if n > 1 {
            self.gravity_kick(lag * (dt - h));
        }

        // 4. Substeps.
        let mut acc: HashMap<(ColliderHandle, ColliderHandle), Accum> = HashMap::new();
        for i in 0..n {
            if i > 0 {
                self.detect(h);
            }
            let s = (i + 1) as f64 / n as f64;
            for (handle, start, target) in &kinematic {
                if let Some(rb) = self.bodies.get_mut(*handle) {
                    rb.set_next_kinematic_position(interpolate(start, target, s as f32));
                }
            }
            let kin_vel = self.kinematic_velocities(&kinematic, s, h);
            self.substep_contacts(h, &kin_vel, &mut acc);
            self.pipeline_step(h, self.gravity);
        }
        if n > 1 {
            self.gravity_kick(-lag * (dt - h));
        }

        // 5. Readout.
        let mut out: Vec<SoftContact> = Vec::with_capacity(acc.len());
        for ((tip, other), a) in acc {
            if a.jn <= 0.0 && a.delta_end <= 0.0 {
                continue;
            }
            let resp = a.model.law.response(a.delta_end);
            out.push(SoftContact {
                fingertip: tip,
                other,
                point: a.point.into(),
                normal: a.normal.into(),
                delta: a.delta_end,
                x: a.delta_end / a.model.radius,
                normal_force: a.jn / dt,
                friction_force: (a.jt / dt).into(),
                torsional_moment: a.jtw / dt,
                stiffness: resp.stiffness,
                level: resp.level,
                regime: resp.regime,
                sliding: a.sliding,
                peak_normal_force: a.peak_force,
                max_delta: a.max_delta,
                contact_duration: a.duration,
                law: a.model.law,
            });
        }
        out.sort_by_key(|c| (detect::raw(c.fingertip), detect::raw(c.other)));
        self.soft.contacts = out;
    }

    /// Applies the gravity impulse `m g tau` to every awake dynamic body.
    fn gravity_kick(&mut self, tau: f64) {
        let g = self.gravity;
        for (_, rb) in self.bodies.iter_mut() {
            if rb.is_dynamic() && !rb.is_sleeping() && rb.is_enabled() {
                let imp = g * (rb.gravity_scale() * rb.mass() * tau as f32);
                rb.apply_impulse(imp, false);
            }
        }
    }

    /// Velocities of the position-based kinematic bodies over the part of their path that
    /// ends at fraction `s` of the step, taking `h` seconds.
    fn kinematic_velocities(
        &self,
        kinematic: &[(RigidBodyHandle, Pose, Pose)],
        s: f64,
        h: f64,
    ) -> KinematicVelocity {
        let mut out = HashMap::new();
        for (handle, start, target) in kinematic {
            let Some(rb) = self.bodies.get(*handle) else {
                continue;
            };
            let goal = interpolate(start, target, s as f32);
            let now = rb.position();
            let v = to_f64(goal.translation - now.translation) / h;
            let (axis, mut angle) = (goal.rotation * now.rotation.inverse()).to_axis_angle();
            if angle > std::f32::consts::PI {
                angle -= 2.0 * std::f32::consts::PI;
            }
            let w = to_f64(axis * angle) / h;
            out.insert(*handle, (v, w));
        }
        out
    }

    /// Body table and rows of the current geometry, for a step of `h` seconds. With
    /// `update_state`, starts and ends the contacts' memory (v_in, anchors).
    fn prepare(&mut self, h: f64, kin_vel: &KinematicVelocity, update_state: bool) -> Prepared {
        let mut tb = BodyTable::default();
        let mut rows = Vec::new();
        let mut models = Vec::new();
        let mut geom = Vec::new();
        let geoms = std::mem::take(&mut self.soft.geoms);
        // rapier's step of h is N passes of "kick h/N, drift h/N": a constant acceleration a
        // moves a body by h (v + a h (N+1)/(2N)). The solver works on that drift velocity.
        let passes = self.params.num_solver_iterations.max(1) as f64;
        let h_drift = h * (passes + 1.0) / (2.0 * passes);
        for (gi, g) in geoms.iter().enumerate() {
            let Some(model) = self.soft.model(g) else {
                continue;
            };
            let a = g
                .body_tip
                .and_then(|b| body_index(&self.bodies, b, h_drift, self.gravity, kin_vel, &mut tb));
            let b = g
                .body_other
                .and_then(|b| body_index(&self.bodies, b, h_drift, self.gravity, kin_vel, &mut tb));
            let n = g.normal;
            let (t1, t2) = tangents(&n);
            let delta = compression_from_signed_distance(g.dist);
            let mut row = Row {
                a,
                b,
                p: g.point,
                n,
                t1,
                t2,
                force: 0.0,
                stiffness: 0.0,
                damping: 0.0,
                theta: 1.0,
                mu: model.friction,
                torsion_arm: 0.0,
                offset: Vector3::zeros(),
                jn: 0.0,
                jt: Vector3::zeros(),
                jtw: 0.0,
                sliding: false,
                vn_end: 0.0,
            };
            let vn = solve::normal_velocity(&tb.table, &row);
            let w = solve::normal_mobility(&tb.table, &row);
            if !(vn.is_finite() && w.is_finite()) {
                self.soft.counters.non_finite += 1;
                continue;
            }
            let key = (g.tip, g.other);
            let other_pose = self.colliders.get(g.other).map(|c| *c.position());
            if update_state && delta > 0.0 {
                let resp = model.law.response(delta);
                match resp.regime {
                    Regime::Extended => self.soft.counters.validity_excursions += 1,
                    Regime::NonFinite => self.soft.counters.non_finite += 1,
                    _ => {}
                }
                self.soft.counters.contacts_evaluated += 1;
                let state = self.soft.pairs.entry(key).or_insert_with(|| PairState {
                    v_in: (-vn).max(model.radius * V_IN_FLOOR_RATE),
                    anchor_local: other_pose
                        .map(|p| to_f64(p.inverse_transform_point(to_f32(&g.point_other))))
                        .unwrap_or(g.point_other),
                });
                // Hunt-Crossley: F_total = F (1 + chi d delta/dt), chi = zeta / v_in.
                let chi = model.zeta / state.v_in;
                row.force = resp.force;
                row.stiffness = resp.stiffness;
                row.damping = chi * resp.force;
                row.theta = if w > 0.0 {
                    theta_blend((resp.stiffness * w).sqrt() * h)
                } else {
                    1.0
                };
                if model.friction > 0.0 {
                    let a = model.law.patch(delta).radius;
                    row.torsion_arm = 3.0 * std::f64::consts::PI / 16.0 * model.friction * a;
                    let anchor = other_pose
                        .map(|p| to_f64(p.transform_point(to_f32(&state.anchor_local))))
                        .unwrap_or(state.anchor_local);
                    let d = g.point_other - anchor;
                    row.offset = d - n * n.dot(&d);
                }
            } else if update_state {
                self.soft.pairs.remove(&key);
            }
            rows.push(row);
            models.push(model);
            geom.push(gi);
        }
        self.soft.geoms = geoms;
        Prepared {
            table: tb.table,
            handles: tb.handles,
            rows,
            models,
            geom,
        }
    }

    fn substep_contacts(
        &mut self,
        h: f64,
        kin_vel: &KinematicVelocity,
        acc: &mut HashMap<(ColliderHandle, ColliderHandle), Accum>,
    ) {
        let t = Instant::now();
        let Prepared {
            mut table,
            handles,
            mut rows,
            models,
            geom,
        } = self.prepare(h, kin_vel, true);
        // Forget pairs that are no longer in contact.
        let live: Vec<(ColliderHandle, ColliderHandle)> = self
            .soft
            .geoms
            .iter()
            .filter(|g| compression_from_signed_distance(g.dist) > 0.0)
            .map(|g| (g.tip, g.other))
            .collect();
        self.soft.pairs.retain(|k, _| live.contains(k));

        if !rows.is_empty() && !solve::solve(&mut table, &mut rows, h) {
            self.soft.counters.non_finite += 1;
        }
        // Apply to rapier (f64 -> f32 at the boundary).
        for row in &rows {
            let imp = row.n * row.jn + row.jt;
            if !(imp.iter().all(|v| v.is_finite()) && row.jtw.is_finite()) {
                self.soft.counters.non_finite += 1;
                continue;
            }
            let (imp32, p32, tw32) = (to_f32(&imp), to_f32(&row.p), to_f32(&(row.n * row.jtw)));
            for (body, sign) in [(row.a, 1.0f32), (row.b, -1.0f32)] {
                let Some(bi) = body else { continue };
                if table[bi].inv_m == Vector3::zeros() {
                    continue;
                }
                if let Some(rb) = self.bodies.get_mut(handles[bi]) {
                    rb.apply_impulse_at_point(imp32 * sign, p32, true);
                    rb.apply_torque_impulse(tw32 * sign, true);
                }
            }
        }
        for ((row, model), gi) in rows.into_iter().zip(models).zip(geom) {
            let g = &self.soft.geoms[gi];
            let key = (g.tip, g.other);
            // Contact memory: a sliding contact drags its anchor along.
            if row.sliding
                && let Some(state) = self.soft.pairs.get_mut(&key)
                && let Some(co) = self.colliders.get(g.other)
            {
                state.anchor_local = to_f64(
                    co.position()
                        .inverse_transform_point(to_f32(&g.point_other)),
                );
            }
            let delta_end = compression_from_signed_distance(g.dist) - h * row.vn_end;
            let e = acc.entry(key).or_insert_with(|| Accum {
                jn: 0.0,
                jt: Vector3::zeros(),
                jtw: 0.0,
                sliding: false,
                peak_force: 0.0,
                max_delta: 0.0,
                duration: 0.0,
                point: row.p,
                normal: row.n,
                delta_end,
                model: model.clone(),
            });
            e.jn += row.jn;
            e.jt += row.jt;
            e.jtw += row.jtw;
            e.sliding |= row.sliding;
            let delta = compression_from_signed_distance(g.dist);
            e.peak_force = e.peak_force.max(row.jn / h);
            e.max_delta = e.max_delta.max(delta);
            if delta > 0.0 {
                e.duration += h;
            }
            e.point = row.p;
            e.normal = row.n;
            e.delta_end = delta_end;
            e.model = model;
        }
        self.soft.counters.solve_time += t.elapsed();
    }
}

/// Floor of Flores' impact speed v_in, as a rate: v_in >= R * 1/s (one radius per second).
/// Below it the Hunt-Crossley damping `chi = 8(1-e)/(5 e v_in)` would grow without bound for
/// contacts that start slowly (a grasp closing at 1 mm/s).
pub(crate) const V_IN_FLOOR_RATE: f64 = 1.0;

fn interpolate(start: &Pose, target: &Pose, s: f32) -> Pose {
    Pose::from_parts(
        start.translation.lerp(target.translation, s),
        start.rotation.slerp(target.rotation, s),
    )
}

fn tangents(n: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let a = if n.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    let t1 = n.cross(&a).normalize();
    (t1, n.cross(&t1))
}

/// The body's row in the solver's table: for a dynamic body, its velocity with the external
/// accelerations (gravity, user force and torque) integrated over `h_drift` [s] (see
/// `prepare`), its inverse mass and inertia.
fn body_index(
    bodies: &RigidBodySet,
    handle: RigidBodyHandle,
    h_drift: f64,
    gravity: Vector,
    kin_vel: &KinematicVelocity,
    tb: &mut BodyTable,
) -> Option<usize> {
    if let Some(i) = tb.index.get(&handle) {
        return Some(*i);
    }
    let rb = bodies.get(handle)?;
    let mp = rb.mass_properties();
    let com = to_f64(mp.world_com);
    let state = if rb.is_dynamic() && !rb.is_sleeping() {
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
        let inv_m = to_f64(mp.effective_inv_mass);
        // rapier adds gravity, the user force and torque during its step: predict them.
        let gravity = to_f64(gravity) * rb.gravity_scale() as f64;
        let v = to_f64(rb.linvel())
            + (inv_m.component_mul(&to_f64(rb.user_force())) + gravity) * h_drift;
        let w = to_f64(rb.angvel()) + inv_i * to_f64(rb.user_torque()) * h_drift;
        let a_ext = inv_m.component_mul(&to_f64(rb.user_force())) + gravity;
        BodyState {
            v,
            w,
            inv_m,
            inv_i,
            com,
            a_ext,
        }
    } else if rb.is_kinematic() {
        let (v, w) = kin_vel
            .get(&handle)
            .copied()
            .unwrap_or((to_f64(rb.linvel()), to_f64(rb.angvel())));
        BodyState {
            v,
            w,
            inv_m: Vector3::zeros(),
            inv_i: Matrix3::zeros(),
            com,
            a_ext: Vector3::zeros(),
        }
    } else {
        BodyState {
            v: Vector3::zeros(),
            w: Vector3::zeros(),
            inv_m: Vector3::zeros(),
            inv_i: Matrix3::zeros(),
            com,
            a_ext: Vector3::zeros(),
        }
    };
    if !(state.v.iter().chain(state.w.iter()).all(|x| x.is_finite())) {
        return None;
    }
    tb.table.push(state);
    tb.handles.push(handle);
    tb.index.insert(handle, tb.table.len() - 1);
    Some(tb.table.len() - 1)
}
