//! [`PlainRun`]: a scene on the plain plugin, without an ECS: [`Scene::build`] plus a loop
//! that drives the kinematic bodies (trajectories, the gripper program). The baseline of the
//! ECS's overhead benchmark and equivalence tests: the ECS spawns from the same builder and
//! calls the same controller logic, so its contact values are bit-identical.

use softgrip_rapier::rapier3d::prelude::RigidBodyHandle;
use softgrip_rapier::{SoftWorld, StepError};

use crate::build::SceneHandles;
use crate::control::{ControlEvent, ControlSet};
use crate::names::SubjectNames;
use crate::scene::Scene;
use crate::trajectory::Trajectory;
use crate::vector::vector;

/// A scene on the plain plugin.
pub struct PlainRun {
    /// The plugin world.
    pub world: SoftWorld,
    /// The scene's handles, by name and in file order.
    pub handles: SceneHandles,
    /// The controllers (the `[gripper]`, the `[[controller]]`s, each robot's commands).
    pub control: ControlSet,
    paths: Vec<(RigidBodyHandle, Trajectory)>,
    events: Vec<(usize, ControlEvent)>,
    step: u64,
    names: SubjectNames,
}

impl PlainRun {
    /// Builds the scene's world ([`Scene::build`]).
    pub fn new(scene: &Scene) -> Self {
        let f = scene.file();
        let built = scene.build();
        let bodies = &built.handles.bodies;
        let paths = (f.bodies.iter().zip(bodies))
            .filter(|(b, _)| !b.trajectory.is_empty())
            .map(|(b, (_, h))| (*h, Trajectory::of(b)))
            .collect();
        let control = scene.control_set(&built.handles);
        let names = SubjectNames::new(scene, &built.handles);
        Self {
            names,
            world: built.world,
            handles: built.handles,
            control,
            paths,
            events: Vec::new(),
            step: 0,
        }
    }

    /// Steps taken.
    pub fn steps(&self) -> u64 {
        self.step
    }

    /// One step: trajectories and gripper write the kinematic targets for the end of the
    /// step, then `SoftWorld::step`. A step that goes wrong is not reported here (see
    /// [`try_step`](Self::try_step)): a faulted world stops advancing, and so does the count
    /// of steps.
    pub fn step(&mut self) {
        // The error stays in the world's fault (`SoftWorld::fault`).
        let _ = self.try_step();
    }

    /// [`step`](Self::step), with a [`StepError`] naming the step, its start time and what
    /// diverged by its scene name (a body, `<robot>/<link>`, `<robot>/<joint>`, or a
    /// fingertip's contact), if the world's state is non-finite or out of the engine's bounds
    /// before or after the step, or rapier panicked (`SoftWorld::try_step`). A faulted run
    /// returns its error again on every call and advances no more ([`fault`](Self::fault)).
    pub fn try_step(&mut self) -> Result<(), StepError> {
        if let Some(e) = self.world.fault() {
            return Err(self.names.named(e.clone()));
        }
        let dt = self.world.physics.integration_parameters.dt as f64;
        let t = (self.step + 1) as f64 * dt;
        for (h, path) in &self.paths {
            if let (Some(p), Some(rb)) =
                (path.position_at(t), self.world.physics.bodies.get_mut(*h))
            {
                rb.set_next_kinematic_translation(vector(p));
            }
        }
        self.events = self.control.step(&mut self.world, t, dt);
        self.world.try_step().map_err(|e| self.names.named(e))?;
        self.step += 1;
        Ok(())
    }

    /// The error that faulted the run, with its scene names, if any.
    pub fn fault(&self) -> Option<StepError> {
        self.world.fault().map(|e| self.names.named(e.clone()))
    }

    /// The scene's names of the handles a [`StepError`] points at.
    pub fn names(&self) -> &SubjectNames {
        &self.names
    }

    /// What the controllers did in the last step, by controller index.
    pub fn events(&self) -> &[(usize, ControlEvent)] {
        &self.events
    }

    /// Steps `n` times; `each(run)` is called after every step. A faulted world stops
    /// advancing ([`step`](Self::step)); [`try_run`](Self::try_run) says why.
    pub fn run(&mut self, n: u64, mut each: impl FnMut(&Self)) {
        for _ in 0..n {
            self.step();
            each(self);
        }
    }

    /// Steps `n` times; `each(run)` is called after every step. Stops at the first step
    /// that fails and returns its error ([`try_step`](Self::try_step)).
    pub fn try_run(&mut self, n: u64, mut each: impl FnMut(&Self)) -> Result<(), StepError> {
        for _ in 0..n {
            self.try_step()?;
            each(self);
        }
        Ok(())
    }
}
