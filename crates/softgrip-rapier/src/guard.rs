//! The step's guard: the state checks before and after a step, the soft impulses' check, and
//! the catch of a panic inside rapier's pipeline (crate README, "When a step goes wrong").
//!
//! The checks only read: a step that passes them is bit for bit the step without them.

use std::any::Any;
use std::cell::{Cell, RefCell};
use std::panic::{self, AssertUnwindSafe};
use std::sync::Once;

use rapier3d::prelude::{PhysicsWorld, RigidBody, RigidBodyHandle, RigidBodySet};

use crate::problem::Row;
use crate::step_error::{
    MAX_ANGULAR_SPEED, MAX_JOINT_COORDINATE, MAX_LINEAR_SPEED, MAX_POSITION, Phase, Quantity,
    StepError, Subject,
};

/// Where a failed check is reported: the step and its start time.
#[derive(Debug, Clone, Copy)]
pub(crate) struct At {
    pub step: u64,
    pub time: f64,
    pub phase: Phase,
}

impl At {
    fn diverged(self, subject: Subject, quantity: Quantity, value: f64, bound: f64) -> StepError {
        StepError::Diverged {
            step: self.step,
            time: self.time,
            subject,
            name: None,
            quantity,
            value,
            bound,
            phase: self.phase,
        }
    }
}

/// The component of `v` with the largest magnitude, NaN first (a NaN compares false).
fn worst(v: impl IntoIterator<Item = f32>) -> f64 {
    let mut w = 0.0f64;
    for x in v {
        let x = x as f64;
        if x.is_nan() {
            return x;
        }
        if x.abs() > w.abs() {
            w = x;
        }
    }
    w
}

/// `Err` if `value` (finite or not) is beyond `bound`.
fn within(value: f64, bound: f64) -> bool {
    value.abs() <= bound
}

/// Checks every body's pose and velocity, and every multibody joint's coordinates and
/// velocities, against the bounds of [`step_error`](crate::step_error).
pub(crate) fn check_state(world: &PhysicsWorld, at: At) -> Result<(), StepError> {
    if at.phase == Phase::After {
        check_active_bodies(world, at)?;
    } else {
        check_bodies(&world.bodies, at)?;
    }
    for mb in world.multibody_joints.multibodies() {
        for link in mb.links() {
            let coords = link.joint().coords();
            let handle = link.rigid_body_handle();
            // The free coordinates are the joint's first `ndofs` unlocked axes; `coords` holds
            // every axis (locked ones at 0), so all six are checked.
            for (dof, &q) in coords.iter().enumerate() {
                let q = q as f64;
                if !within(q, MAX_JOINT_COORDINATE) {
                    let s = Subject::Joint { link: handle, dof };
                    return Err(at.diverged(s, Quantity::JointPosition, q, MAX_JOINT_COORDINATE));
                }
            }
            for (dof, &v) in mb.joint_velocity(link).iter().enumerate() {
                let v = v as f64;
                if !within(v, MAX_ANGULAR_SPEED) {
                    let s = Subject::Joint { link: handle, dof };
                    return Err(at.diverged(s, Quantity::JointVelocity, v, MAX_ANGULAR_SPEED));
                }
            }
        }
    }
    Ok(())
}

/// After the step: only the bodies in rapier's active set can have changed since the check
/// before it (rapier's pipeline moves those alone; the plugin's velocity sets are checked where
/// they are made, `check_impulses`, and its wakes put the bodies in the active set), so they
/// are checked first; on a failure the whole set is walked as before, so that the error is the
/// one of the first failing body in the set's order, as [`check_bodies`] reports it. A
/// sleeping world is not walked at all (the walk over its sleeping bodies was a third of a
/// sleeping N = 1000 step's state checks).
fn check_active_bodies(world: &PhysicsWorld, at: At) -> Result<(), StepError> {
    let all_ok = world.islands.active_bodies().all(|h| {
        world
            .bodies
            .get(h)
            .is_none_or(|rb| rb.is_sleeping() || body_ok(rb))
    });
    if all_ok {
        Ok(())
    } else {
        check_bodies(&world.bodies, at)
    }
}

/// Whether `rb` passes every check of [`check_bodies`] (the same comparisons, component by
/// component, without finding the worst one): the fast path, the detailed checks run only for
/// a body that fails it, to name what failed.
#[inline]
fn body_ok(rb: &RigidBody) -> bool {
    let p = rb.position();
    let (t, q) = (p.translation, p.rotation);
    let (v, w) = (rb.linvel(), rb.angvel());
    let le = |x: f32, bound: f64| (x as f64).abs() <= bound;
    le(t.x, MAX_POSITION)
        & le(t.y, MAX_POSITION)
        & le(t.z, MAX_POSITION)
        & q.x.is_finite()
        & q.y.is_finite()
        & q.z.is_finite()
        & q.w.is_finite()
        & le(v.x, MAX_LINEAR_SPEED)
        & le(v.y, MAX_LINEAR_SPEED)
        & le(v.z, MAX_LINEAR_SPEED)
        & le(w.x, MAX_ANGULAR_SPEED)
        & le(w.y, MAX_ANGULAR_SPEED)
        & le(w.z, MAX_ANGULAR_SPEED)
}

fn check_bodies(bodies: &RigidBodySet, at: At) -> Result<(), StepError> {
    for (h, rb) in bodies.iter() {
        // After the step, a sleeping body is as it was before it (checked then): rapier's
        // pipeline does not move it, and it fell asleep only if still (a diverged pose or
        // velocity never is).
        if at.phase == Phase::After && rb.is_sleeping() {
            continue;
        }
        if body_ok(rb) {
            continue;
        }
        let p = rb.position();
        let x = worst([p.translation.x, p.translation.y, p.translation.z]);
        if !within(x, MAX_POSITION) {
            return Err(at.diverged(Subject::Body(h), Quantity::Position, x, MAX_POSITION));
        }
        let q = worst([p.rotation.x, p.rotation.y, p.rotation.z, p.rotation.w]);
        if !q.is_finite() {
            return Err(at.diverged(Subject::Body(h), Quantity::Rotation, q, 1.0));
        }
        check_velocity(h, rb, at)?;
    }
    Ok(())
}

fn check_velocity(h: RigidBodyHandle, rb: &RigidBody, at: At) -> Result<(), StepError> {
    let v = rb.linvel();
    let v = worst([v.x, v.y, v.z]);
    if !within(v, MAX_LINEAR_SPEED) {
        let s = Subject::Body(h);
        return Err(at.diverged(s, Quantity::LinearVelocity, v, MAX_LINEAR_SPEED));
    }
    let w = rb.angvel();
    let w = worst([w.x, w.y, w.z]);
    if !within(w, MAX_ANGULAR_SPEED) {
        let s = Subject::Body(h);
        return Err(at.diverged(s, Quantity::AngularVelocity, w, MAX_ANGULAR_SPEED));
    }
    Ok(())
}

/// Checks the soft solve's impulses (each row's normal, tangential and torsional impulse
/// must be finite) and then the velocities they gave the bodies they act on, before rapier's
/// pipeline takes them (the bounds of [`check_state`]). The velocities, not each row's
/// impulse against a bound: a body squeezed between two contacts takes two large opposite
/// impulses whose sum is small (a 5 um cell between plates: 1e6 m/s per row, nothing net).
pub(crate) fn check_impulses(
    rows: &[Row],
    contact: impl Fn(usize) -> Subject,
    bodies: &RigidBodySet,
    touched: &[RigidBodyHandle],
    at: At,
) -> Result<(), StepError> {
    for (i, row) in rows.iter().enumerate() {
        let j = worst_f64([row.jn, row.jt.x, row.jt.y, row.jt.z, row.jtw]);
        if !j.is_finite() {
            return Err(at.diverged(contact(i), Quantity::ContactImpulse, j, f64::MAX));
        }
        // The solve's own prediction of the contact's end normal velocity: a multibody or
        // jointed link takes only the joint-space part of its load (`multibody::project_net`),
        // so its body's velocity below can stay small under an absurd answer (issue 25: pads
        // at 1.9e38 N predicting 1e28 m/s while the links moved at 0.06 m/s).
        if !within(row.vn_end, MAX_LINEAR_SPEED) {
            return Err(at.diverged(
                contact(i),
                Quantity::ContactVelocity,
                row.vn_end,
                MAX_LINEAR_SPEED,
            ));
        }
    }
    for &h in touched {
        if let Some(rb) = bodies.get(h) {
            check_velocity(h, rb, at)?;
        }
    }
    Ok(())
}

fn worst_f64(v: impl IntoIterator<Item = f64>) -> f64 {
    worst(
        v.into_iter()
            .map(|x| if x.is_nan() { f32::NAN } else { x as f32 }),
    )
}

thread_local! {
    /// Set while this thread runs a guarded step: the panic hook then records the panic's
    /// location here instead of printing it.
    static GUARDED: Cell<bool> = const { Cell::new(false) };
    static LOCATION: RefCell<Option<String>> = const { RefCell::new(None) };
}

static HOOK: Once = Once::new();

/// Installs, once per process, a panic hook that stays silent for a panic inside a guarded
/// step (recording its location for the [`StepError::EnginePanicked`]) and hands every other
/// panic to the hook that was installed before (the default one prints it as usual).
fn install_hook() {
    HOOK.call_once(|| {
        let previous = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            if GUARDED.with(Cell::get) {
                let loc = info.location().map(|l| l.to_string());
                LOCATION.with(|c| *c.borrow_mut() = loc);
            } else {
                previous(info);
            }
        }));
    });
}

fn message(payload: &(dyn Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_string()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "a panic without a message".to_string()
    }
}

/// Runs `f` (the step's body, rapier's pipeline inside it), turning a panic into a
/// [`StepError::EnginePanicked`] at `step`, `time`.
pub(crate) fn catch<T>(step: u64, time: f64, f: impl FnOnce() -> T) -> Result<T, StepError> {
    install_hook();
    let was = GUARDED.with(|g| g.replace(true));
    let r = panic::catch_unwind(AssertUnwindSafe(f));
    GUARDED.with(|g| g.set(was));
    r.map_err(|payload| StepError::EnginePanicked {
        step,
        time,
        message: message(payload.as_ref()),
        location: LOCATION.with(|c| c.borrow_mut().take()),
    })
}
