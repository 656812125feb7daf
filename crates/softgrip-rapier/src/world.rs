//! [`SoftWorld`]: rapier's own [`PhysicsWorld`] with the plugin's [`SoftContacts`] beside it.

use rapier3d::prelude::{
    ColliderHandle, EventHandler, PhysicsHooks, PhysicsWorld, RigidBodyHandle,
};

use crate::contacts::SoftContacts;
use crate::error::Result;
use crate::fingertip::SoftFingertip;
use crate::step_error::StepError;

/// A rapier [`PhysicsWorld`] with soft fingertips. Build the scene with rapier's own API on
/// `physics` (`physics.insert(..)`, or `physics.bodies` and `physics.colliders`), register
/// fingertips, then call [`step`](Self::step) (or [`step_with`](Self::step_with) to pass your
/// own hooks and event handler).
///
/// A thin bundle: everything it does is [`SoftContacts::register`] and
/// [`SoftContacts::step`] on `physics`, which work the same on a `PhysicsWorld` of your own.
#[derive(Default)]
pub struct SoftWorld {
    /// rapier's world: gravity [m/s^2] (default -9.81 along y), `integration_parameters`
    /// (`dt` \[s\] is the step, default 1/60 s; for micro-scale scenes set `length_unit` to about
    /// the fingertip radius), the body and collider sets, the pipeline and its phases.
    pub physics: PhysicsWorld,
    /// The soft fingertips, their contacts and counters.
    pub soft: SoftContacts,
}

impl SoftWorld {
    /// An empty world: rapier's `PhysicsWorld::default()` (gravity -9.81 m/s^2 along y,
    /// dt = 1/60 s) and no fingertip.
    pub fn new() -> Self {
        Self::default()
    }

    /// The Gauss-Seidel sweeps per solver pass (`num_internal_pgs_iterations` plus the largest
    /// `RigidBody::additional_pgs_iterations` of the island) at which the soft solve sees
    /// `body` through its impulse joints (crate README, What one step does, 9), at a (sub)step
    /// of `h` \[s\] (> 0; rapier's `num_solver_iterations` passes) and the bodies' present
    /// pose: 1 for a body on a fixed or kinematic base whose motor acts through its centre of
    /// mass (a prismatic jaw anchored there), 214 for the suite's two-link finger, 518 for a
    /// finger of the shipped three-finger hand. `None` if `body` is not held by impulse joints
    /// in an assembly the solve can see (not dynamic, asleep, a multibody link, more than 8
    /// bodies) or rapier's sweeps over it never converge.
    pub fn jointed_sweeps_needed(&self, body: RigidBodyHandle, h: f64) -> Option<usize> {
        if !(h > 0.0 && h.is_finite()) {
            return None;
        }
        let w = &self.physics;
        let ctx = sweeps_ctx(w, h);
        crate::jointed::sweeps_needed(&w.bodies, &ctx, body)
    }

    /// The Gauss-Seidel sweeps per solver pass (`num_internal_pgs_iterations` plus the largest
    /// `RigidBody::additional_pgs_iterations` of the island) at which rapier's sweeps over the
    /// internal rows of the multibody that holds `body` (its joint motors and dof couplings, a
    /// URDF `<mimic>`) converge as the soft solve requires (crate README, What one step does,
    /// 9), at a (sub)step of `h` \[s\] (> 0; rapier's `num_solver_iterations` passes) and the
    /// multibody's present pose: 1 where no two rows share inertia (a single prismatic jaw),
    /// 17 for the suite's mimic-coupled jaws at 1/60 s (the largest over its step and its
    /// substeps; `tests/jointed_mimic.rs`), 348 for the shipped three-finger hand. Give the
    /// multibody's links `need - num_internal_pgs_iterations` with
    /// `RigidBody::set_additional_pgs_iterations` where it is more than rapier's own, and raise
    /// the world's `num_internal_stabilization_iterations` to `need`: rapier's unbiased pass
    /// runs that count on every body whatever they ask, and at its 1 the coupled joints end
    /// each substep with velocities their couplings do not allow (softgrip-scene
    /// `tests/xarm.rs`: a drive joint mimicked by five joints read its effort 14 % off). Reads
    /// rapier's factorisation of the multibody's mass from its last step, or before its first
    /// step makes one at the present pose (`Multibody::dof_inverse_inertia`, which runs its
    /// forward kinematics from its joint coordinates and leaves out the step's joint damping
    /// and springs). `None` if `body` is not a
    /// multibody link, rapier's `f32` factorisation of its mass there is not positive definite
    /// (the Franka Panda of pybullet_data: diagonal entries of -1.6e10), or the sweeps never
    /// converge.
    pub fn multibody_sweeps_needed(&mut self, body: RigidBodyHandle, h: f64) -> Option<usize> {
        if !(h > 0.0 && h.is_finite()) {
            return None;
        }
        let w = &mut self.physics;
        let id = *w.multibody_joints.rigid_body_link(body)?;
        let mb = w.multibody_joints.get_multibody_mut(id.multibody)?;
        // Before rapier's first step its mass is not factorised: factorise it here.
        if crate::multibody::rapier_mobility(mb).is_none() {
            mb.dof_inverse_inertia(&w.bodies);
        }
        let ctx = sweeps_ctx(w, h);
        crate::multibody_sweeps::sweeps_needed(&ctx, body)
    }

    /// Keeps bodies `a` and `b` from touching each other (see [`SoftContacts::exclude_pair`]).
    pub fn exclude_pair(&mut self, a: RigidBodyHandle, b: RigidBodyHandle) -> Result<()> {
        self.soft.exclude_pair(&mut self.physics, a, b)
    }

    /// Registers `collider` as the soft fingertip `fingertip` (see [`SoftContacts::register`]).
    pub fn register(&mut self, collider: ColliderHandle, fingertip: SoftFingertip) -> Result<()> {
        self.soft.register(&mut self.physics, collider, fingertip)
    }

    /// Advances the world by `physics.integration_parameters.dt`, with no user hooks and no
    /// event handler. A step that goes wrong is not reported here: a faulted world
    /// ([`fault`](Self::fault)) stops advancing; [`try_step`](Self::try_step) says why.
    pub fn step(&mut self) {
        self.step_with(&(), &());
    }

    /// [`step`](Self::step), with a [`StepError`] if the state is non-finite or out of the
    /// engine's bounds before or after the step, or rapier panicked (see
    /// [`SoftContacts::try_step`]).
    pub fn try_step(&mut self) -> std::result::Result<(), StepError> {
        self.try_step_with(&(), &())
    }

    /// [`step_with`](Self::step_with), with a [`StepError`] (see [`SoftContacts::try_step`]).
    pub fn try_step_with(
        &mut self,
        hooks: &dyn PhysicsHooks,
        events: &dyn EventHandler,
    ) -> std::result::Result<(), StepError> {
        self.soft.try_step(&mut self.physics, hooks, events)
    }

    /// The error that faulted this world, if any ([`SoftContacts::fault`]): a faulted world
    /// does not advance any more.
    pub fn fault(&self) -> Option<&StepError> {
        self.soft.fault()
    }

    /// Advances the world by `physics.integration_parameters.dt`, passing the user's `hooks`
    /// and `events` to rapier's pipeline for every pair that is not a soft contact (see
    /// [`SoftContacts::step`]).
    pub fn step_with(&mut self, hooks: &dyn PhysicsHooks, events: &dyn EventHandler) {
        self.soft.step(&mut self.physics, hooks, events);
    }
}

/// What the sweep counts read of `w` at a (sub)step of `h` \[s\] (`h_drift` is `h`: they read
/// no drift).
fn sweeps_ctx(w: &PhysicsWorld, h: f64) -> crate::multibody::LinkCtx<'_> {
    crate::multibody::LinkCtx {
        multibodies: &w.multibody_joints,
        impulse_joints: &w.impulse_joints,
        h,
        h_drift: h,
        passes: w.integration_parameters.num_solver_iterations.max(1),
        sweeps: w.integration_parameters.num_internal_pgs_iterations,
        gravity: crate::boundary::to_f64(w.gravity),
    }
}
