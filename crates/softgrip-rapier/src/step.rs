//! One step of the plugin on a rapier [`PhysicsWorld`] ([`SoftContacts::step`]).
//!
//! 1. rapier's step is `N = num_solver_iterations` passes of symplectic Euler ("kick, then
//!    drift"), so under gravity its stored velocity lags the true (velocity-Verlet) velocity by
//!    `g dt / (2N)`. A step split into `n` substeps of `h = dt/n` must keep that convention,
//!    or every bounce gains or loses `g (dt - h) / (2N)` of speed (measured: +8 % energy per
//!    bounce of a ball dropped 10 cm at 60 Hz before this rule). So a split step first applies
//!    the impulse `m g f (dt - h) / (2N)`, runs its substeps with gravity, and removes
//!    `m g f (dt - h) / (2N)` at the end. `f` in \[0, 1\] is the share of gravity the body
//!    feels in rapier's passes (the lag is the passes' acceleration's, `a h / (2N)`): 1 in
//!    free flight and for a body the plugin's impulses hold (they act before the passes), 0
//!    for a body resting on rapier's own contact, whose stored velocity is its true one. The
//!    give-back's `f` is measured over the substeps after the first (rapier's change of the
//!    body's velocity, the plugin's impulses excluded, along gravity), and is the next split
//!    step's lead-in's (1 when not known: after an unsplit step, or for a body asleep at the
//!    end of the last step). With `f = 1` for every body, the table took the lead-in from a
//!    resting box and the give-back left it moving up at `g (dt - h) / (2N)` = 0.0163 m/s
//!    (issue 23; `bodies::SplitLag`). In free flight a split step is *exactly* one rapier step
//!    of `dt`; in contact it is a fine symplectic integration.
//! 2. The soft contacts are found fresh at the current poses (`detect`).
//! 3. The substep count `n` is chosen (`substep`); position-based kinematic bodies are moved
//!    along their path in `n` equal parts (linear in translation, slerp in rotation).
//! 4. Per substep: contacts, impulses (`solve`), `apply_impulse_at_point`, then rapier's
//!    pipeline with `dt / n`, the user's hooks and events passed through (`hooks`).
//! 5. The readout is assembled (`SoftContacts::contacts`).
//!
//! When a step is split and what it carries over from an unsplit one: [`split`]; a contact that
//! begins within a (sub)step: [`onset`].

use std::time::Instant;

use nalgebra::{Isometry3, Point3, Vector3};
use rapier3d::prelude::{
    Collider, ColliderHandle, ContactPair, EventHandler, IntegrationParameters, PhysicsHooks,
    PhysicsWorld, RigidBodyHandle,
};
use softgrip_law::Regime;

use crate::bodies::{self, body_index};
use crate::boundary::{pose_f64, to_f32, to_f64};
use crate::contacts::{MotorPush, PairState, Scratch, SoftContacts};
use crate::counters::Lap;
use crate::detect::{self, Geom, Scene, compression_from_signed_distance};
use crate::fast_hash::{FastMap, FastSet};
use crate::guard::{self, At};
use crate::hooks::{SoftEvents, SoftHooks};
use crate::kinematic::{self, KinematicPath, KinematicVelocity, interpolate};
use crate::model::Model;
use crate::multibody::{self, LinkCtx};
use crate::problem::{self, ContactSoftness, RigidKey, RigidRow, Row, TOUCH_FRACTION, Warm};
use crate::readout;
use crate::step_error::{Phase, StepError, Subject};
use crate::substep;
use memo::Plan;
use onset::update_blend;

pub(crate) mod memo;
mod onset;
mod split;
pub(crate) mod stale_island;
mod wake;

pub(crate) use split::GapMemory;

impl SoftContacts {
    /// Advances `world` by `world.integration_parameters.dt` with the soft contacts: the law's
    /// impulses on the fingertips' bodies, then rapier's pipeline (once, or once per substep
    /// while a contact is dynamic).
    ///
    /// `hooks` and `events` are the user's, as for `PhysicsPipeline::step`: rapier calls them
    /// for every pair that is not a soft contact, exactly as it would without the plugin (a pair
    /// with a fingertip never reaches them; see [`register`](Self::register)). Pass `&()` for
    /// none. A split step runs rapier's pipeline `n` times with `dt / n`
    /// ([`SoftCounters::substeps_last`](crate::SoftCounters::substeps_last)), so the
    /// user's hooks and events are called per substep then. The first step of this
    /// `SoftContacts` runs one pipeline step of `dt = 0` first (with the same hooks and
    /// events), which fills rapier's broad and narrow phases for the first detection.
    ///
    /// A step that goes wrong is not reported here: see [`try_step`](Self::try_step), which
    /// this calls, discarding its error. A faulted plugin ([`fault`](Self::fault)) does not
    /// advance `world` any more.
    pub fn step(
        &mut self,
        world: &mut PhysicsWorld,
        hooks: &dyn PhysicsHooks,
        events: &dyn EventHandler,
    ) {
        // The error stays in `self.fault` when it faults the world.
        let _ = self.try_step(world, hooks, events);
    }

    /// [`step`](Self::step), with what went wrong as a [`StepError`]: the state handed over
    /// is checked first ([`Phase::Before`]: `world` is left untouched, not faulted), the soft
    /// solve's impulses before they are applied ([`Phase::SoftSolve`]), the state after
    /// rapier's pipeline ([`Phase::After`]), against the bounds of the crate README ("When a
    /// step goes wrong"); a panic inside rapier's pipeline is caught
    /// ([`StepError::EnginePanicked`]). Every error but a `Before` one faults the plugin: the
    /// step was abandoned part way or left a diverged state, and rapier's sets may be
    /// half-updated after a panic, so this and every later call return the same error
    /// without touching `world` ([`fault`](Self::fault)). The checks only read: a step that
    /// passes them is bit-identical to the step without them.
    pub fn try_step(
        &mut self,
        world: &mut PhysicsWorld,
        hooks: &dyn PhysicsHooks,
        events: &dyn EventHandler,
    ) -> Result<(), StepError> {
        if let Some(f) = &self.fault {
            return Err(f.clone());
        }
        let mut started = Lap::start(self.profiling);
        let at = At {
            step: self.counters.steps + 1,
            time: self.time,
            phase: Phase::Before,
        };
        guard::check_state(world, at)?;
        let dt = world.integration_parameters.dt as f64;
        // The set is read by the adapters while the rest of `self` is written.
        let soft = std::mem::take(&mut self.hook_view);
        let mut links = std::mem::take(&mut self.link_contacts);
        let excluded = std::mem::take(&mut self.excluded);
        let r = guard::catch(at.step, at.time, || {
            links.refresh(world);
            let (hooks, events) = (
                SoftHooks::new(&soft, &links, &excluded, hooks),
                SoftEvents::new(&soft, events),
            );
            Step {
                physics: world,
                soft: self,
                hooks: &hooks,
                events: &events,
                excluded: &excluded,
                at,
            }
            .run()
        });
        if r.is_err() {
            // A panic inside rapier's pipeline step may have left the carrier in the set.
            let stale = &mut self.stale_island;
            let _ = guard::catch(at.step, at.time, || stale.remove_carrier(world));
        }
        self.hook_view = soft;
        let dropped = links.take_dropped();
        self.counters.locked_link_contacts += dropped;
        self.counters.immobile_rows += dropped;
        self.counters.stale_contacts += links.take_stale();
        self.link_contacts = links;
        self.excluded = excluded;
        let after = At {
            phase: Phase::After,
            ..at
        };
        let r = r
            .and_then(|r| r)
            .and_then(|()| guard::check_state(world, after));
        started.lap(&mut self.counters.step_time);
        match r {
            Ok(()) => {
                if dt > 0.0 {
                    self.time += dt;
                }
                Ok(())
            }
            Err(e) => {
                self.fault = Some(e.clone());
                Err(e)
            }
        }
    }

    /// The error that faulted this plugin ([`try_step`](Self::try_step)), if any: a faulted
    /// plugin does not step its world any more.
    pub fn fault(&self) -> Option<&StepError> {
        self.fault.as_ref()
    }

    /// Simulated time of the steps taken \[s\]: the sum of their `dt`.
    pub fn time(&self) -> f64 {
        self.time
    }
}

/// A step in progress: the world, the plugin's state and the hooks passed to rapier.
struct Step<'a> {
    physics: &'a mut PhysicsWorld,
    soft: &'a mut SoftContacts,
    hooks: &'a SoftHooks<'a>,
    events: &'a SoftEvents<'a>,
    /// Pairs of bodies that never touch (the detection skips them).
    excluded: &'a crate::excluded::ExcludedPairs,
    /// The step's number and start time, for a [`StepError`].
    at: At,
}

impl Step<'_> {
    fn pipeline_step(&mut self, h: f64) {
        let t = Instant::now();
        let w = &mut *self.physics;
        let mut p = w.integration_parameters;
        p.dt = h as f32;
        self.soft.stale_island.before_step(w);
        w.physics_pipeline.step(
            w.gravity,
            &p,
            &mut w.islands,
            &mut w.broad_phase,
            &mut w.narrow_phase,
            &mut w.bodies,
            &mut w.colliders,
            &mut w.impulse_joints,
            &mut w.multibody_joints,
            &mut w.soft_bodies,
            &mut w.ccd_solver,
            self.hooks,
            self.events,
        );
        if self.soft.stale_island.after_step(w) {
            self.soft.counters.awake_islands_cleared += 1;
        }
        self.soft.counters.pipeline_time += t.elapsed();
    }

    /// Detection for a (sub)step of `dt` \[s\]; `fastest`: the world's fastest motion if the
    /// caller found it at the current state (else found here).
    fn detect(&mut self, dt: f64, fastest: Option<(f32, f32)>, s: &mut Scratch) {
        let t = Instant::now();
        if fastest.is_some() {
            self.find_motor_push(dt, s);
        }
        // The motors' push over this (sub)step: a substep's share of the step's.
        let (push_max, push_dt) = (&s.motor_push.max, &s.motor_push.dt);
        let push_scale = if *push_dt > 0.0 {
            (dt / push_dt) as f32
        } else {
            0.0
        };
        let fastest = fastest.unwrap_or_else(|| detect::fastest_motion(&self.physics.bodies));
        let fastest = (
            fastest.0 + push_max.0 * push_scale,
            fastest.1 + push_max.1 * push_scale,
        );
        let soft = &mut *self.soft;
        let scene = Scene {
            bodies: &self.physics.bodies,
            colliders: &self.physics.colliders,
            narrow_phase: &self.physics.narrow_phase,
            broad_phase: &self.physics.broad_phase,
            islands: &self.physics.islands,
            tip_order: &soft.tip_order,
            gravity: self.physics.gravity.length(),
            max_radius: soft.max_radius,
            impulse_joints: &self.physics.impulse_joints,
            multibody_joints: &self.physics.multibody_joints,
            motor_push: (&s.motor_push.by_link, push_scale),
            excluded: self.excluded,
        };
        detect::detect(
            &scene,
            &soft.tips,
            dt,
            Some(fastest),
            &mut soft.geoms,
            &mut s.candidates,
            &mut s.detected,
            &mut soft.counters,
        );
        soft.counters.detect_time += t.elapsed();
    }

    /// The speed the joint motors add to each multibody link over the step `dt` \[s\]
    /// (`multibody::motor_push`), for the step's detections (`s.motor_push`).
    fn find_motor_push(&mut self, dt: f64, s: &mut Scratch) {
        let MotorPush {
            by_link: map,
            max,
            dt: at,
        } = &mut s.motor_push;
        map.clear();
        *max = (0.0, 0.0);
        *at = dt;
        if self.physics.multibody_joints.multibodies().next().is_none() {
            return;
        }
        let p = &self.physics.integration_parameters;
        let passes = p.num_solver_iterations.max(1) as f64;
        let ctx = LinkCtx {
            multibodies: &self.physics.multibody_joints,
            impulse_joints: &self.physics.impulse_joints,
            h: dt,
            h_drift: dt * (passes + 1.0) / (2.0 * passes),
            passes: passes as usize,
            sweeps: p.num_internal_pgs_iterations,
            gravity: to_f64(self.physics.gravity),
        };
        multibody::motor_push(&self.physics.bodies, &ctx, map);
        for &(v, w) in map.values() {
            *max = (max.0.max(v), max.1.max(w));
        }
    }

    /// The step: `physics.integration_parameters.dt`.
    fn run(&mut self) -> Result<(), StepError> {
        let dt = self.physics.integration_parameters.dt as f64;
        if !(dt > 0.0) {
            self.pipeline_step(0.0);
            return Ok(());
        }
        if !self.soft.started {
            // Fill the broad phase and narrow phase before the first soft detection (a
            // multibody root's kinematic target survives it: rapier's step overwrites it).
            let targets = multibody::kinematic_root_targets(self.physics);
            self.pipeline_step(0.0);
            multibody::restore_root_targets(self.physics, &targets);
            self.soft.started = true;
        }
        self.soft.counters.steps += 1;
        // The resting fast path (`memo`): a step whose inputs equal the last step's.
        let substeps_before = self.soft.counters.substeps_last;
        let held_before = self.soft.counters.held_tips;
        let plan = self
            .soft
            .rest
            .begin(self.physics, &self.soft.counters, &self.soft.pairs);
        if let Plan::Replay(slot) = plan {
            self.replay(slot, dt);
            return Ok(());
        }
        self.soft.materialize_rest();

        // Kinematic paths.
        let (kinematic, fastest) = kinematic::kinematic_paths(&self.physics.bodies);

        // The plugin's buffers, reused from step to step (no allocation once warm).
        let mut scratch = self.soft.scratch.take().unwrap_or_default();

        // 2.-3. Contacts now, and the substep count.
        // Nothing writes to the bodies between the walk above and the detection.
        self.detect(dt, Some(fastest), &mut scratch);
        let kin_vel = kinematic::kinematic_velocities(&self.physics.bodies, &kinematic, 1.0, dt);
        self.prepare(dt, &kin_vel, &mut scratch);
        let n = self.substep_count(dt, &scratch);
        let h = dt / n as f64;
        // rapier's step of h is N internal "kick, drift" passes (N = num_solver_iterations):
        // its stored velocity lags the true one by g h / (2N).
        let lag = 0.5
            / self
                .physics
                .integration_parameters
                .num_solver_iterations
                .max(1) as f64;
        self.carry_unsplit(n, dt, &mut scratch);
        let gravity = self.physics.gravity;
        if n > 1 {
            let tau = lag * (dt - h);
            bodies::lag_lead_in(
                &mut self.physics.bodies,
                gravity,
                &mut scratch.split_lag,
                tau,
            );
        } else {
            scratch.split_lag.forget();
        }

        // 4. Substeps.
        let substeps = self.substeps(n, h, &kinematic, &mut scratch);
        if substeps.is_err() {
            self.soft.scratch = Some(scratch);
            return substeps;
        }
        if n > 1 {
            let (bodies, lag_state) = (&mut self.physics.bodies, &mut scratch.split_lag);
            let span = dt - h;
            bodies::lag_give_back(bodies, gravity, lag_state, span, lag * (dt - h));
        }

        // 5. Readout.
        let mut lap = Lap::start(self.soft.profiling);
        readout::assemble(
            &mut scratch.accums,
            dt,
            &scratch.detected,
            &self.soft.tips,
            &mut self.soft.contacts,
        );
        lap.lap(&mut self.soft.counters.readout_time);
        let eligible = n == 1
            && kinematic.is_empty()
            && self.physics.impulse_joints.is_empty()
            && self.physics.multibody_joints.iter().next().is_none()
            && scratch.rigid.is_empty()
            && !scratch.rigid_read
            && scratch.link_forces.is_empty()
            && self.soft.counters.held_tips == held_before;
        self.soft.rest.note_full(eligible);
        if plan == Plan::Record {
            let soft = &mut *self.soft;
            soft.rest.finish(
                eligible,
                substeps_before,
                &soft.counters,
                &soft.pairs,
                &soft.contacts,
                &soft.geoms,
                &scratch.unsplit_carry,
                scratch.stamp,
            );
        }
        self.soft.scratch = Some(scratch);
        self.soft.update_tactile(&self.physics.colliders);
        Ok(())
    }

    /// Replays the recorded step of `slot` (`memo`): its wakes and velocity sets through the
    /// same calls in the same order, its counts, then rapier's pipeline of `dt` \[s\], as the
    /// full unsplit step does. The plugin's state it ended with (the contacts' memory,
    /// readout, geometry and unsplit carry) stays in the slot, read from there
    /// (`SoftContacts::contacts`) until a full step or a setting moves it back
    /// (`SoftContacts::materialize_rest`).
    fn replay(&mut self, slot: usize, dt: f64) {
        let soft = &mut *self.soft;
        let (writes, before, after) = soft.rest.replay(slot);
        for &h in &writes.wakes {
            if let Some(rb) = self.physics.bodies.get_mut(h) {
                rb.wake_up(true);
            }
        }
        for &(h, v, w) in &writes.sets {
            if let Some(rb) = self.physics.bodies.get_mut(h) {
                rb.set_linvel(v, false);
                rb.set_angvel(w, false);
            }
        }
        soft.counters.add_increments(before, after);
        soft.counters.replayed_steps += 1;
        if let Some(scratch) = soft.scratch.as_mut() {
            scratch.split_lag.forget();
        }
        self.pipeline_step(dt);
        self.soft.update_tactile(&self.physics.colliders);
    }

    /// `n` substeps of `h` \[s\]: fresh contacts (the first substep's are the prepared ones),
    /// kinematic bodies along their paths, impulses, rapier's pipeline.
    fn substeps(
        &mut self,
        n: u32,
        h: f64,
        kinematic: &[KinematicPath],
        scratch: &mut Scratch,
    ) -> Result<(), StepError> {
        scratch.accums.clear();
        for i in 0..n {
            if i > 0 {
                self.detect(h, None, scratch);
            }
            // An unsplit step's rows are those of the substep count's pass above: same
            // geometry, same step, same kinematic velocities (they read the current poses).
            let fresh = n == 1;
            let s = (i + 1) as f64 / n as f64;
            for (handle, start, target) in kinematic {
                if let Some(rb) = self.physics.bodies.get_mut(*handle) {
                    rb.set_next_kinematic_position(interpolate(start, target, s as f32));
                }
            }
            let kin_vel = kinematic::kinematic_velocities(&self.physics.bodies, kinematic, s, h);
            multibody::carry_kinematic_roots(self.physics, kinematic, s as f32);
            self.substep_contacts(h, &kin_vel, fresh, scratch)?;
            // The lead-in is taken by a support in the first substep: the share is read after.
            let measure = n > 1 && i > 0;
            if measure {
                bodies::lag_pass(&self.physics.bodies, &mut scratch.split_lag, true);
            }
            self.pipeline_step(h);
            if measure {
                bodies::lag_pass(&self.physics.bodies, &mut scratch.split_lag, false);
            }
            if !scratch.link_forces.is_empty() {
                multibody::restore_forces(&mut self.physics.bodies, &mut scratch.link_forces);
            }
        }
        Ok(())
    }

    /// Body table and rows of the current geometry, for a step of `h` seconds, written to
    /// `s` (`body_table`, `rows`, `models`, `geom`, `mobility`), without the law's response
    /// (see [`prepare_state`](Self::prepare_state)).
    fn prepare(&mut self, h: f64, kin_vel: &KinematicVelocity, s: &mut Scratch) {
        let mut lap = Lap::start(self.soft.profiling);
        s.body_table.clear();
        s.rows.clear();
        s.models.clear();
        s.geom.clear();
        s.mobility.clear();
        s.skipped.clear();
        self.wake_touched(s);
        let tb = &mut s.body_table;
        let geoms = std::mem::take(&mut self.soft.geoms);
        // rapier's step of h is N passes of "kick h/N, drift h/N": a constant acceleration a
        // moves a body by h (v + a h (N+1)/(2N)). The solver works on that drift velocity.
        let passes = self
            .physics
            .integration_parameters
            .num_solver_iterations
            .max(1) as f64;
        let h_drift = h * (passes + 1.0) / (2.0 * passes);
        let ctx = LinkCtx {
            multibodies: &self.physics.multibody_joints,
            impulse_joints: &self.physics.impulse_joints,
            h,
            h_drift,
            passes: passes as usize,
            sweeps: self
                .physics
                .integration_parameters
                .num_internal_pgs_iterations,
            gravity: to_f64(self.physics.gravity),
        };
        for (gi, g) in geoms.iter().enumerate() {
            let Some(model) = self.soft.model(g) else {
                if compression_from_signed_distance(g.dist) > 0.0 {
                    s.skipped.push((g.tip, g.other));
                }
                continue;
            };
            let a = g.body_tip.and_then(|b| {
                body_index(
                    &self.physics.bodies,
                    b,
                    &ctx,
                    self.physics.gravity,
                    kin_vel,
                    tb,
                )
            });
            let b = g.body_other.and_then(|b| {
                body_index(
                    &self.physics.bodies,
                    b,
                    &ctx,
                    self.physics.gravity,
                    kin_vel,
                    tb,
                )
            });
            let row = new_row(a, b, g, model.friction);
            let vn = problem::normal_velocity(&tb.table, &row);
            let w = problem::normal_mobility(&tb.table, &row);
            if !(vn.is_finite() && w.is_finite()) {
                self.soft.counters.non_finite += 1;
                if compression_from_signed_distance(g.dist) > 0.0 {
                    s.skipped.push((g.tip, g.other));
                }
                continue;
            }
            s.rows.push(row);
            s.models.push(model);
            s.geom.push(gi);
            s.mobility.push(w);
        }
        self.soft.geoms = geoms;
        lap.lap(&mut self.soft.counters.rows_time);
        self.prepare_rigid(h, h_drift, kin_vel, s);
        lap.lap(&mut self.soft.counters.supports_time);
        self.soft.counters.jointed_free += s.body_table.jointed_free;
    }

    /// rapier's touching rigid contacts of every dynamic body a soft contact moves, and of the
    /// dynamic bodies those touch in turn (a box on a box on the table), as rows of the
    /// coupled solve (`rigid`, which says why), at most [`MAX_RIGID_ROWS`] of them (past it,
    /// the remaining bodies are seen as free). Pairs with a fingertip are left out (they are
    /// the plugin's, or, behind a backed pad's face, rapier's own with the pad), and so are
    /// manifolds without solver contacts (a pair the user's hooks keep out of rapier's solver)
    /// and points farther apart than rapier's allowed linear error. Joints are not rows: a
    /// jointed body is seen as free.
    fn prepare_rigid(
        &mut self,
        h: f64,
        h_drift: f64,
        kin_vel: &KinematicVelocity,
        s: &mut Scratch,
    ) {
        s.rigid.clear();
        s.rigid_read = false;
        if s.rows.is_empty() {
            return;
        }
        let (queue, queued, pairs) = &mut s.rigid_visit;
        queue.clear();
        queued.clear();
        pairs.clear();
        let tb = &mut s.body_table;
        queue_touching(&s.rows, &s.geom, &self.soft.geoms, tb, queue, queued);
        let w = &*self.physics;
        let slop = w.integration_parameters.allowed_linear_error() as f64;
        let ctx = LinkCtx {
            multibodies: &w.multibody_joints,
            impulse_joints: &w.impulse_joints,
            h,
            h_drift,
            passes: w.integration_parameters.num_solver_iterations.max(1),
            sweeps: w.integration_parameters.num_internal_pgs_iterations,
            gravity: to_f64(w.gravity),
        };
        let mut next = 0;
        while next < queue.len() && s.rigid.len() < MAX_RIGID_ROWS {
            let body = queue[next];
            next += 1;
            let Some(rb) = w.bodies.get(body) else {
                continue;
            };
            for &ch in rb.colliders() {
                // Every pair of a fingertip's collider is left out below: its narrow-phase
                // pairs (the fattened AABBs' neighbours, dozens in a grid) are not walked.
                if self.soft.tips.contains_key(&ch) {
                    continue;
                }
                for pair in w.narrow_phase.contact_pairs_with(ch) {
                    // rapier's narrow phase is read (not in the resting fast path's inputs).
                    s.rigid_read = true;
                    let (c1, c2) = (pair.collider1, pair.collider2);
                    if self.soft.tips.contains_key(&c1)
                        || self.soft.tips.contains_key(&c2)
                        || !pair.has_any_active_contact()
                        || !pairs.insert((c1, c2))
                    {
                        continue;
                    }
                    let (Some(co1), Some(co2)) = (w.colliders.get(c1), w.colliders.get(c2)) else {
                        continue;
                    };
                    // This body's side: the row's normal points from the other side to it
                    // (rapier's manifold normal points from collider 1 to collider 2).
                    let (sign, other) = if c1 == ch { (-1.0, co2) } else { (1.0, co1) };
                    let Some(a) = body_index(&w.bodies, body, &ctx, w.gravity, kin_vel, tb) else {
                        continue;
                    };
                    let b = other.parent().and_then(|ob| {
                        let i = body_index(&w.bodies, ob, &ctx, w.gravity, kin_vel, tb)?;
                        if tb.table[i].is_dynamic() && queued.insert(ob) {
                            queue.push(ob);
                        }
                        Some(i)
                    });
                    // rapier's contact softness of the pair: its static one where the other
                    // side is not a dynamic body (`ContactSoftness`).
                    let fixed_other = other
                        .parent()
                        .and_then(|ob| w.bodies.get(ob))
                        .is_none_or(|ob| !ob.is_dynamic());
                    push_pair_points(
                        pair,
                        (co1, co2),
                        sign,
                        (a, b),
                        (slop, h, fixed_other, &w.integration_parameters),
                        &s.rigid_warm,
                        &mut s.rigid,
                    );
                }
            }
        }
        // One rule for every rigid row (`rigid`, rapier's soft rows): a row is rapier's soft
        // contact where the soft contacts took the rigid load off its dynamic bodies at the
        // previous (sub)step (each body's rigid normal impulse over all its pairs, with the
        // soft contacts against without them: its whole normal impulse is then rapier's,
        // `rigid::write_rigid`); hard where they press a body onto its rigid contacts (a
        // fingertip on a box, a box pushed into a wall whose friction then takes its weight
        // off the table: the load moves between rigid pairs, it is not taken off them).
        // Hysteresis: soft from half the load taken off, kept while any load is.
        let mut load = vec![(0.0, 0.0); tb.table.len()];
        for o in &s.rigid {
            if let Some([rest, all]) = o.warm {
                for x in std::iter::once(o.a).chain(o.b) {
                    load[x].0 += all.jn.max(0.0);
                    load[x].1 += rest.jn.max(0.0);
                }
            }
        }
        let unloaded = |x: usize, limit: f64| {
            let (with, without) = load[x];
            without > 0.0 && with <= limit * without
        };
        for r in s.rigid.iter_mut() {
            let was_soft = r.key.is_some_and(|k| s.rigid_soft.contains(&k));
            let limit = if was_soft { 1.0 } else { 0.5 };
            let soft = unloaded(r.a, limit)
                && r.b
                    .is_none_or(|b| !tb.table[b].is_dynamic() || unloaded(b, limit));
            if !soft {
                r.softness = None;
            }
        }
    }

    /// The law's response of the prepared rows over a (sub)step of `h` seconds, and the
    /// contacts' memory (friction anchors): started for new contacts, ended for pairs that are
    /// no longer in contact.
    fn prepare_state(&mut self, h: f64, s: &mut Scratch) {
        // Implicit (damped, never gaining energy) where the step is not resolved: at the
        // substep cap, and in an unsplit step, whose touching contacts were judged at rest by
        // their velocity. A turning point of a bounce is at rest too: taken nearly explicit
        // (`omega dt = 0.58`) between split steps, each such step gained energy, and a 4.6 mm
        // ball of E = 194 kPa dropped 1.7 um at dt = 0.8 ms rose 65 % above its start.
        let substeps = self.soft.counters.substeps_last;
        let capped = substeps >= substep::MAX_SUBSTEPS || substeps == 1;
        s.stamp = s.stamp.wrapping_add(1);
        let stamp = s.stamp;
        let rigid_bias = RigidBias::of(&self.physics.integration_parameters, h);
        let soft = &mut self.soft;
        for (((row, model), &gi), &w) in s
            .rows
            .iter_mut()
            .zip(&s.models)
            .zip(&s.geom)
            .zip(&s.mobility)
        {
            let g = &soft.geoms[gi];
            let delta = compression_from_signed_distance(g.dist);
            let key = (g.tip, g.other);
            if !(delta > 0.0) {
                soft.pairs.remove(&key);
                continue;
            }
            let other_pose = self.physics.colliders.get(g.other).map(|c| *c.position());
            // The friction spring's material points are carried through the poses in `f64`
            // (`boundary::pose_f64`).
            let other_iso = other_pose.as_ref().map(pose_f64);
            let tip_iso = self
                .physics
                .colliders
                .get(g.tip)
                .map(|c| pose_f64(c.position()));
            let resp = model.law.response(delta);
            match resp.regime {
                Regime::Extended => {
                    soft.counters.validity_excursions += 1;
                    row.extended = true;
                }
                Regime::NonFinite => soft.counters.non_finite += 1,
                // A pair in series: past either fingertip's own range.
                _ if model.series.as_ref().is_some_and(|s| s.law.extended(delta)) => {
                    soft.counters.validity_excursions += 1;
                    row.extended = true;
                }
                _ => {}
            }
            soft.counters.contacts_evaluated += 1;
            let state = soft.pairs.entry(key).or_insert_with(|| PairState {
                anchor_local: other_iso
                    .map(|p| p.inverse_transform_point(&g.point_other.into()).coords)
                    .unwrap_or(g.point_other),
                stretch_local: Vector3::zeros(),
                tip_local: tip_iso
                    .map(|p| p.inverse_transform_point(&g.point_other.into()).coords)
                    .unwrap_or(g.point_other),
                stamp,
                warm: None,
            });
            state.stamp = stamp;
            row.warm = state.warm;
            // Hunt-Crossley: F_total = F (1 + alpha d delta/dt), alpha a material constant.
            row.force = resp.force;
            row.stiffness = resp.stiffness;
            row.damping = model.alpha * resp.force;
            row.theta = update_blend(resp.stiffness, w, h, capped);
            let wall = past_wall(&model.law, delta);
            row.past_wall = wall > 0.0;
            if row.past_wall {
                rigid_past_wall(row, &model.law, delta, wall, h, &rigid_bias);
                soft.counters.past_wall += 1;
            }
            if model.friction > 0.0 && (model.torsion || soft.friction_spring) {
                patch_friction(row, model, delta, resp.stiffness, soft.friction_spring);
            }
            if model.friction > 0.0 && row.k_t > 0.0 {
                // The spring's stretch: the last step's, carried in the other body's frame, plus
                // the slip since between the material points that touched then (`PairState`).
                let at = |pose: Option<Isometry3<f64>>, v: &Vector3<f64>, point: bool| match pose {
                    Some(p) if point => (p * Point3::from(*v)).coords,
                    Some(p) => p * v,
                    None => *v,
                };
                let slip =
                    at(tip_iso, &state.tip_local, true) - at(other_iso, &state.anchor_local, true);
                let d = at(other_iso, &state.stretch_local, false) + slip;
                row.offset = d - n_proj(&row.n, &d);
            } else if model.friction > 0.0 {
                let anchor = other_pose
                    .map(|p| to_f64(p.transform_point(to_f32(&state.anchor_local))))
                    .unwrap_or(state.anchor_local);
                let d = g.point_other - anchor;
                row.offset = d - n_proj(&row.n, &d);
            }
        }
        forget_pairs(soft, &s.skipped, &s.detected, stamp);
    }

    fn substep_contacts(
        &mut self,
        h: f64,
        kin_vel: &KinematicVelocity,
        fresh: bool,
        s: &mut Scratch,
    ) -> Result<(), StepError> {
        let t = Instant::now();
        if !fresh {
            self.prepare(h, kin_vel, s);
        }
        let mut lap = Lap::start(self.soft.profiling);
        self.prepare_state(h, s);
        s.accums.begin_substep();
        lap.lap(&mut self.soft.counters.law_time);

        if !s.rows.is_empty() {
            self.solve_with_onsets(h, s);
        }
        lap.lap(&mut self.soft.counters.soft_solve_time);
        bodies::apply_impulses(
            &mut self.physics.bodies,
            h,
            &mut s.link_forces,
            &s.body_table.table,
            &s.body_table.handles,
            &s.rows,
            &s.rigid,
            &mut self.soft.counters,
            &mut s.net,
            self.soft.rest.log().map(|w| &mut w.sets),
        );
        // The rigid rows' warm start of the next (sub)step: those the coupled solve answered.
        s.rigid_warm.clear();
        s.rigid_soft.clear();
        for r in &s.rigid {
            if let (Some(key), Some(w)) = (r.key, r.solved) {
                s.rigid_warm.insert(key, w);
                if r.softness.is_some() {
                    s.rigid_soft.insert(key);
                }
            }
        }
        if !s.rows.is_empty() {
            let geoms = &self.soft.geoms;
            let contact = |i: usize| {
                let g = &geoms[s.geom[i]];
                Subject::Contact {
                    fingertip: g.tip,
                    other: g.other,
                }
            };
            let at = At {
                phase: Phase::SoftSolve,
                ..self.at
            };
            let (bodies, touched) = (&self.physics.bodies, &s.body_table.handles);
            guard::check_impulses(&s.rows, contact, bodies, touched, at)?;
        }
        if fresh {
            bodies::unsplit_carry(
                &s.body_table,
                &s.rows,
                &s.rigid,
                &mut s.unsplit_carry,
                &mut s.carry_sums,
            );
        }
        lap.lap(&mut self.soft.counters.apply_time);
        for ((row, model), gi) in s.rows.iter().zip(s.models.drain(..)).zip(&s.geom) {
            let g = &self.soft.geoms[*gi];
            let key = (g.tip, g.other);
            if let Some(state) = self.soft.pairs.get_mut(&key) {
                let colliders = &self.physics.colliders;
                remember(
                    state,
                    row,
                    g,
                    colliders.get(g.tip),
                    colliders.get(g.other),
                    h,
                );
            }
            // The last substep's supported mobility is the next step's (`substep_count`).
            if let Some(m) = self.soft.gaps.get_mut(&key) {
                m.supported = row.supported_mobility;
            }
            let delta_end = compression_from_signed_distance(g.dist) - h * row.vn_end;
            let delta = compression_from_signed_distance(g.dist);
            readout::accumulate(&mut s.accums, key, row, model, delta, delta_end, h);
        }
        lap.lap(&mut self.soft.counters.readout_time);
        self.soft.counters.solve_time += t.elapsed();
        Ok(())
    }
}

/// A contact's row before the law's response: bodies `a` (the fingertip's) and `b` (the
/// other's) in the body table, the geometry `g` and the friction coefficient `mu`.
/// A contact's memory after the solve of a (sub)step of `h` \[s\]: the next (sub)step's warm
/// start (`problem::Warm`), and the friction spring's stretch or the rigid stick's anchor.
///
/// With the spring (`k_t > 0`): sticking, the stretch stays (`row.offset`) and the coming
/// step's slip is measured on the poses between the material points that touch now (`tip` the
/// fingertip's collider, `other` the other body's; `PairState::stretch_local`); sliding, the
/// stretch is the one that will carry the Coulomb cap, `-j_t / (h k_t)` (along the slip), once
/// the slip over this step (`h v_t(end)`) is added, not more. Without the spring a sliding
/// contact's anchor goes to the contact point.
fn remember(
    state: &mut PairState,
    row: &Row,
    g: &Geom,
    tip: Option<&Collider>,
    other: Option<&Collider>,
    h: f64,
) {
    state.warm = Some(Warm {
        jn: row.jn,
        jt: row.jt,
        jtw: row.jtw,
        h,
    });
    let Some(co) = other else {
        return;
    };
    if row.k_t > 0.0 {
        let s = if row.sliding {
            -row.jt / (h * row.k_t) - row.vt_end * h
        } else {
            row.offset
        };
        if s.iter().chain(g.point_other.iter()).all(|x| x.is_finite())
            && let Some(tip) = tip
        {
            let (other, tip) = (pose_f64(co.position()), pose_f64(tip.position()));
            let p = Point3::from(g.point_other);
            state.stretch_local = other.inverse_transform_vector(&s);
            state.anchor_local = other.inverse_transform_point(&p).coords;
            state.tip_local = tip.inverse_transform_point(&p).coords;
        }
    } else if row.sliding && g.point_other.iter().all(|x| x.is_finite()) {
        state.anchor_local = to_f64(
            co.position()
                .inverse_transform_point(to_f32(&g.point_other)),
        );
    }
}

/// The patch's part of a contact's friction (`row`, compressed `delta` \[m\] with `model`,
/// which has friction, torsion or a friction spring): the torsion limit (the integral of mu p r
/// dA over the law's pressure profile, per unit normal force) and, with `spring`, Mindlin's
/// tangential stiffness of the patch, damped with the normal's time constant `c / K`
/// (`SoftContacts::set_friction_spring`; `stiffness` the law's at `delta` \[N/m\], `row.damping`
/// the row's).
fn patch_friction(row: &mut Row, model: &Model, delta: f64, stiffness: f64, spring: bool) {
    let patch = model.law.patch(delta);
    if model.torsion {
        row.torsion_arm = patch.torsion_limit(model.friction, 1.0);
    }
    let k_t = 8.0 * model.shear_modulus * patch.equivalent_radius();
    if spring && k_t.is_finite() && k_t > 0.0 {
        row.k_t = k_t;
        if stiffness > 0.0 {
            row.c_t = row.damping * k_t / stiffness;
        }
    }
}

/// Ends the memory of the pairs of `soft` no longer in contact (not stamped `stamp` this
/// substep), but for the pairs in contact without a row (`skipped`: no model, non-finite),
/// which keep it, and the held ones (`detected`: a sleeping fingertip's, not detected).
fn forget_pairs(
    soft: &mut SoftContacts,
    skipped: &[(ColliderHandle, ColliderHandle)],
    detected: &detect::Detected,
    stamp: u64,
) {
    for key in skipped {
        if let Some(state) = soft.pairs.get_mut(key) {
            state.stamp = stamp;
        }
    }
    if detected.all {
        soft.pairs.retain(|_, v| v.stamp == stamp);
    } else if !detected.tips.is_empty() {
        let tips = &soft.tips;
        soft.pairs
            .retain(|k, v| v.stamp == stamp || detected.held(detect::owner(tips, k.0, k.1)));
    }
}

/// Queues the dynamic bodies of the touching soft contacts `rows` (their geometries `geom`
/// into `geoms`; one that does not touch has no impulse), each once (`queued`: a set, not a
/// scan of the queue, which was quadratic in the resting fingertips).
fn queue_touching(
    rows: &[Row],
    geom: &[usize],
    geoms: &[Geom],
    tb: &bodies::BodyTable,
    queue: &mut Vec<RigidBodyHandle>,
    queued: &mut FastSet<RigidBodyHandle>,
) {
    for (row, &gi) in rows.iter().zip(geom) {
        if !(compression_from_signed_distance(geoms[gi].dist) > 0.0) {
            continue;
        }
        for i in [row.a, row.b].into_iter().flatten() {
            let handle = tb.handles[i];
            if tb.table[i].is_dynamic() && queued.insert(handle) {
                queue.push(handle);
            }
        }
    }
}

/// Pushes the touching points of `pair`'s manifolds that have solver contacts onto `rigid`
/// (at most [`MAX_RIGID_ROWS`]) as rows between body `a`, on this side (rapier's manifold
/// normal times `sign`), and `b` (`None`: fixed), each with its warm start from `warm`;
/// `slop`: rapier's allowed linear error \[m\]; `h`: the coming pipeline step \[s\],
/// `fixed_other`: whether the other side is not dynamic, and `params` rapier's integration
/// parameters, for the point's softness (`ContactSoftness`).
fn push_pair_points(
    pair: &ContactPair,
    (co1, co2): (&Collider, &Collider),
    sign: f64,
    (a, b): (usize, Option<usize>),
    (slop, h, fixed_other, params): (f64, f64, bool, &IntegrationParameters),
    warm: &FastMap<RigidKey, [Warm; 2]>,
    rigid: &mut Vec<RigidRow>,
) {
    let (c1, c2) = (pair.collider1, pair.collider2);
    for m in pair.manifolds() {
        if m.data.solver_contacts.is_empty() {
            continue;
        }
        let n = to_f64(m.data.normal) * sign;
        let mu = m.data.friction as f64;
        for pt in &m.points {
            // Not rapier's `pt.dist`: with its contact recycling (on by default) a manifold's
            // points and `dist` are those of the pair's last full narrow-phase update, kept
            // while the pair's relative pose drifts less than ten allowed linear errors (5 cm);
            // rapier's solver re-derives the separation from the points' body-local anchors
            // and the current poses, as `gap` below does. Read from `dist`, a box pushed 8 mm
            // to a wall kept the wall's points 8 mm apart and the wall never held it here.
            if rigid.len() >= MAX_RIGID_ROWS {
                continue;
            }
            let p1 = to_f64(co1.position().transform_point(pt.local_p1));
            let p2 = to_f64(co2.position().transform_point(pt.local_p2));
            // The gap at the current poses: a manifold's points can outlive the touch (a box
            // lifted 5 cm kept its ground pair's four points, `dist` 0, for the whole lift, and
            // the coupled solve held it on that table).
            let gap = (p2 - p1).dot(&to_f64(m.data.normal));
            // A point further apart than the touch tolerance is rapier's own speculative
            // contact (`problem::TOUCH_FRACTION`): it does not hold the coupled solve.
            if !(gap <= TOUCH_FRACTION * slop) {
                continue;
            }
            let p = 0.5 * (p1 + p2);
            if p.iter().chain(n.iter()).all(|v| v.is_finite()) && mu >= 0.0 {
                let mut row = RigidRow::new(a, b, p, n, mu);
                let key = (c1, c2, pt.fid1.0, pt.fid2.0);
                row.key = Some(key);
                row.closable = (gap - 0.5 * TOUCH_FRACTION * slop).max(0.0);
                row.warm = warm.get(&key).copied();
                // rapier's softness of the point; kept only where the soft contacts took the
                // rigid load off its bodies (`Step::prepare_rigid`, after the gathering).
                row.softness = ContactSoftness::of(params, h, gap, fixed_other);
                rigid.push(row);
            }
        }
    }
}

fn new_row(a: Option<usize>, b: Option<usize>, g: &Geom, mu: f64) -> Row {
    let n = g.normal;
    let (t1, t2) = tangents(&n);
    Row {
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
        mu,
        torsion_arm: 0.0,
        offset: Vector3::zeros(),
        k_t: 0.0,
        c_t: 0.0,
        vt_end: Vector3::zeros(),
        jn: 0.0,
        jt: Vector3::zeros(),
        jtw: 0.0,
        sliding: false,
        vn_end: 0.0,
        extended: false,
        past_wall: false,
        friction_mobility: None,
        lin: 0.0,
        warm: None,
        supported_mobility: None,
    }
}

/// The most rigid contact points one (sub)step gathers (`Step::prepare_rigid`): a few boxes in
/// a stack, four corners each.
const MAX_RIGID_ROWS: usize = 32;

/// How far past its wall a contact of compression `delta` \[m\] is \[m\] (`> 0` past it; the
/// wall `ContactLaw::x_wall` times the law's radius: where the fingertip's rigid part meets the
/// surface it presses).
pub(crate) fn past_wall(law: &softgrip_law::ContactLaw, delta: f64) -> f64 {
    delta - law.x_wall() * law.params().radius()
}

/// rapier's position correction of its own contacts over a (sub)step of `h` \[s\]
/// (`IntegrationParameters`: `contact_softness.erp_inv_dt(h)` \[1/s\], the separation
/// velocity asked per metre of penetration, and `max_corrective_velocity()` \[m/s\], its cap).
#[derive(Debug, Clone, Copy)]
pub(crate) struct RigidBias {
    erp_inv_dt: f64,
    max_velocity: f64,
}

impl RigidBias {
    pub(crate) fn of(p: &rapier3d::prelude::IntegrationParameters, h: f64) -> Self {
        Self {
            erp_inv_dt: p.contact_softness.erp_inv_dt(h as f32) as f64,
            max_velocity: p.max_corrective_velocity() as f64,
        }
    }

    /// The separation velocity rapier asks of a contact `depth` \[m\] deep \[m/s\].
    fn velocity(&self, depth: f64) -> f64 {
        let v = (self.erp_inv_dt * depth).min(self.max_velocity);
        if v.is_finite() { v.max(0.0) } else { 0.0 }
    }
}

/// `row`, of a contact compressed `depth` \[m\] past its law's wall (`delta` \[m\] in all),
/// made a rigid contact as rapier makes its own: the fingertip's rigid part has met the surface.
///
/// The row's equation is `v(end) + j / (h D) = F / D` (`D = theta K h + c`). Past the wall the
/// law is the barrier's tangent just short of it (about `1e12` times its scale over its range:
/// 6.7e16 N/m, 1e14 N for the three-finger hand's pad), which read as a row asks the bodies
/// to undo the whole penetration in one substep, `v(end) = depth / h`: a palm driving a pad past
/// its wall into a box the table holds (a kinematic jam, which no force undoes) took 4.9e8 N.
/// Here `K` and `F` are the law's at the wall, `theta = 1`, no damping, and the force is
/// raised by `D v_c`: a hard row whose end separation velocity is `v_c`, rapier's bias for
/// that depth ([`RigidBias`]: at its default, 9.4 /s times the depth, at most 3 m/s), plus
/// `F / (K h)` (under a micrometre per substep). Below the wall the law is unchanged.
fn rigid_past_wall(
    row: &mut Row,
    law: &softgrip_law::ContactLaw,
    delta: f64,
    depth: f64,
    h: f64,
    bias: &RigidBias,
) {
    let at = law.response(delta - depth);
    row.stiffness = at.stiffness;
    row.theta = 1.0;
    row.damping = 0.0;
    row.force = at.force + at.stiffness * h * bias.velocity(depth);
}

/// The component of `d` along the unit normal `n`.
#[inline]
fn n_proj(n: &Vector3<f64>, d: &Vector3<f64>) -> Vector3<f64> {
    n * n.dot(d)
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
