//! [`PlainRun`]: the same scene on the plain plugin, without bevy_ecs: the baseline of the
//! overhead benchmark and of the equivalence tests.
//!
//! It builds the rapier world in the order the sync system uses (bodies, colliders,
//! fingertips, each in scene order), and drives kinematic bodies with the same trajectory and
//! gripper logic, so its contact forces are bit-identical to the ECS run.

use softgrip_rapier::SoftWorld;
use softgrip_rapier::rapier3d::prelude::{ColliderHandle, RigidBodyHandle};

use crate::components::v32;
use crate::gripper::{GripperProgram, GripperState};
use crate::scene::{Scene, Trajectory, body_from_spec, collider_from_spec, fingertip_from_spec};
use crate::spawn::soft_world_for;

/// A scene on the plain plugin.
pub struct PlainRun {
    /// The plugin world.
    pub world: SoftWorld,
    /// Body handles, in scene order.
    pub bodies: Vec<RigidBodyHandle>,
    /// Fingertip collider handles, in scene order.
    pub fingertips: Vec<ColliderHandle>,
    paths: Vec<(RigidBodyHandle, Trajectory)>,
    gripper: Option<(GripperProgram, GripperState, [Vec<ColliderHandle>; 2])>,
    step: u64,
}

impl PlainRun {
    /// Builds the scene's world.
    pub fn new(scene: &Scene) -> Self {
        let f = scene.file();
        let mut world = soft_world_for(scene);
        let bodies: Vec<_> = f
            .bodies
            .iter()
            .map(|b| world.bodies.insert(body_from_spec(b).builder()))
            .collect();
        for (i, b) in f.bodies.iter().enumerate() {
            for (spec, shape) in b.shapes.iter().zip(scene.shapes(i)) {
                let c = collider_from_spec(spec, shape.clone()).builder();
                world
                    .colliders
                    .insert_with_parent(c, bodies[i], &mut world.bodies);
            }
        }
        let mut fingertips = Vec::new();
        for (t, tip) in f.fingertips.iter().zip(scene.fingertips()) {
            let body = bodies[scene
                .body_index(&t.body)
                .expect("invariant: checked by Scene::parse")];
            let c = fingertip_from_spec(t, tip.clone()).builder();
            let h = world
                .colliders
                .insert_with_parent(c, body, &mut world.bodies);
            world
                .register(h, tip.clone())
                .expect("invariant: the fingertip's own ball collider was just inserted");
            fingertips.push(h);
        }
        let paths = f
            .bodies
            .iter()
            .zip(&bodies)
            .filter(|(b, _)| !b.trajectory.is_empty())
            .map(|(b, h)| (*h, Trajectory::of(b)))
            .collect();
        let gripper = scene.gripper().map(|p| {
            let tips = p.jaws.map(|i| {
                f.fingertips
                    .iter()
                    .zip(&fingertips)
                    .filter(|(t, _)| t.body == f.bodies[i].name)
                    .map(|(_, h)| *h)
                    .collect()
            });
            (
                p.clone(),
                GripperState::new(p.jaws.map(|i| f.bodies[i].position)),
                tips,
            )
        });
        Self {
            world,
            bodies,
            fingertips,
            paths,
            gripper,
            step: 0,
        }
    }

    /// One step: trajectories and gripper, then `SoftWorld::step`.
    pub fn step(&mut self) {
        let dt = self.world.params.dt as f64;
        let t = (self.step + 1) as f64 * dt;
        for (h, path) in &self.paths {
            if let (Some(p), Some(rb)) = (path.position_at(t), self.world.bodies.get_mut(*h)) {
                rb.set_next_kinematic_translation(v32(p));
            }
        }
        if let Some((program, state, tips)) = &mut self.gripper {
            let mut delta = [None, None];
            for c in self.world.soft.contacts() {
                for k in 0..2 {
                    if tips[k].contains(&c.fingertip) {
                        delta[k] = Some(delta[k].map_or(c.delta, |m: f64| m.max(c.delta)));
                    }
                }
            }
            state.advance(program, dt, delta);
            for k in 0..2 {
                let h = self.bodies[program.jaws[k]];
                if let Some(rb) = self.world.bodies.get_mut(h) {
                    rb.set_next_kinematic_translation(v32(state.jaws[k].position));
                }
            }
        }
        self.world.step();
        self.step += 1;
    }
}
