//! [`PlainRun`]: a scene on the plain plugin, without an ECS: [`Scene::build`] plus a loop
//! that drives the kinematic bodies (trajectories, the gripper program). The baseline of the
//! ECS's overhead benchmark and equivalence tests: the ECS spawns from the same builder and
//! calls the same controller logic, so its contact values are bit-identical.

use softgrip_rapier::SoftWorld;
use softgrip_rapier::rapier3d::prelude::RigidBodyHandle;

use crate::build::SceneHandles;
use crate::control::{ControlEvent, ControlSet};
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
        Self {
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
    /// step, then `SoftWorld::step`.
    pub fn step(&mut self) {
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
        self.world.step();
        self.step += 1;
    }

    /// What the controllers did in the last step, by controller index.
    pub fn events(&self) -> &[(usize, ControlEvent)] {
        &self.events
    }

    /// Steps `n` times; `each(run)` is called after every step.
    pub fn run(&mut self, n: u64, mut each: impl FnMut(&Self)) {
        for _ in 0..n {
            self.step();
            each(self);
        }
    }
}
