//! [`PlainRun`]: a scene on the plain plugin, without an ECS: [`Scene::build`] plus a loop
//! that drives the kinematic bodies (trajectories, the gripper program). The baseline of the
//! ECS's overhead benchmark and equivalence tests: the ECS spawns from the same builder and
//! calls the same controller logic, so its contact values are bit-identical.

use softgrip_rapier::SoftWorld;
use softgrip_rapier::rapier3d::prelude::{ColliderHandle, RigidBodyHandle};

use crate::build::SceneHandles;
use crate::gripper::{GripperProgram, GripperState, jaw_compressions};
use crate::scene::Scene;
use crate::trajectory::Trajectory;
use crate::vector::vector;

/// The gripper of a plain run: program, state, and each jaw's fingertip colliders.
struct PlainGripper {
    program: GripperProgram,
    state: GripperState,
    tips: [Vec<ColliderHandle>; 2],
    jaws: [RigidBodyHandle; 2],
}

/// A scene on the plain plugin.
pub struct PlainRun {
    /// The plugin world.
    pub world: SoftWorld,
    /// The scene's handles, by name and in file order.
    pub handles: SceneHandles,
    paths: Vec<(RigidBodyHandle, Trajectory)>,
    gripper: Option<PlainGripper>,
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
        let gripper = scene.gripper().map(|p| PlainGripper {
            program: p.clone(),
            state: GripperState::new(p.jaws.map(|i| f.bodies[i].position)),
            tips: p.tips.clone().map(|tips| {
                tips.iter()
                    .map(|&i| built.handles.fingertips[i].1)
                    .collect()
            }),
            jaws: p.jaws.map(|i| bodies[i].1),
        });
        Self {
            world: built.world,
            handles: built.handles,
            paths,
            gripper,
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
        if let Some(g) = &mut self.gripper {
            let contacts = self.world.soft.contacts().iter();
            let delta = jaw_compressions(&g.tips, contacts.map(|c| (c.fingertip, c.delta)));
            g.state.advance(&g.program, dt, delta);
            for k in 0..2 {
                if let Some(rb) = self.world.physics.bodies.get_mut(g.jaws[k]) {
                    rb.set_next_kinematic_translation(vector(g.state.jaws[k].position));
                }
            }
        }
        self.world.step();
        self.step += 1;
    }

    /// Steps `n` times; `each(run)` is called after every step.
    pub fn run(&mut self, n: u64, mut each: impl FnMut(&Self)) {
        for _ in 0..n {
            self.step();
            each(self);
        }
    }
}
