//! [`ControlSet`]: a scene's controllers in order (the `[gripper]`, the `[[controller]]`s, then
//! each robot's [`JointCommands`]), stepped over a rapier world by the plain runner and the ECS
//! alike.

use softgrip_rapier::SoftWorld;

use crate::build::SceneHandles;
use crate::control::controller::{ControlEvent, Controller};
use crate::control::external::{JointCommands, SharedInbox};
use crate::control::io::ControlIo;
use crate::robot::{JointModel, Robot};

/// A scene's controllers with what they need to run: the handles and the robots' models.
#[derive(Debug, Clone)]
pub struct ControlSet {
    controllers: Vec<Box<dyn Controller>>,
    handles: SceneHandles,
    robots: Vec<Robot>,
    /// Whether the multibody sweeps have been asked again after rapier's first step
    /// ([`ControlSet::step`]).
    sweeps_asked: bool,
}

impl ControlSet {
    /// `controllers` over a world built with `handles`, with the scene's `robots`.
    pub fn new(
        controllers: Vec<Box<dyn Controller>>,
        handles: SceneHandles,
        robots: Vec<Robot>,
    ) -> Self {
        Self {
            controllers,
            handles,
            robots,
            sweeps_asked: false,
        }
    }

    /// The controllers, in the order they run.
    pub fn controllers(&self) -> &[Box<dyn Controller>] {
        &self.controllers
    }

    /// The controllers, mutable (to feed one of your own kind).
    pub fn controllers_mut(&mut self) -> &mut [Box<dyn Controller>] {
        &mut self.controllers
    }

    /// Adds a controller, run after the others.
    pub fn push(&mut self, controller: Box<dyn Controller>) {
        self.controllers.push(controller);
    }

    /// The handles the controllers address.
    pub fn handles(&self) -> &SceneHandles {
        &self.handles
    }

    /// The robots' models.
    pub fn robots(&self) -> &[Robot] {
        &self.robots
    }

    /// The inbox of commands from outside of robot `robot` (index): its [`JointCommands`].
    pub fn inbox(&mut self, robot: usize) -> Option<SharedInbox> {
        (self.controllers.iter_mut())
            .filter_map(|c| c.as_any_mut().downcast_mut::<JointCommands>())
            .find(|c| c.robot() == robot)
            .map(|c| c.inbox())
    }

    /// One step of every controller, in order: the coming step ends at `time` \[s\] and lasts
    /// `dt` \[s\]. Returns what happened, by controller index.
    pub fn step(
        &mut self,
        world: &mut SoftWorld,
        time: f64,
        dt: f64,
    ) -> Vec<(usize, ControlEvent)> {
        if !self.sweeps_asked && time > 1.5 * dt {
            self.sweeps_asked = true;
            self.ask_sweeps_again(world);
        }
        let mut io = ControlIo::new(world, &self.handles, &self.robots, time, dt);
        let mut events = Vec::new();
        for (i, c) in self.controllers.iter_mut().enumerate() {
            if let Some(e) = c.update(&mut io) {
                events.push((i, e));
            }
        }
        events
    }

    /// Before the second step: the multibody robots whose links the loader could give no
    /// sweeps (`Robot::set_jointed_sweeps` found none to read: rapier's `f32` factorisation
    /// of the mass at the start pose, without the step's joint damping, was not positive
    /// definite, as for the Franka Panda of pybullet_data) are asked again, now that rapier's
    /// first step has factorised it with the damping. Robots that got sweeps keep theirs (the
    /// figures of the shipped gripper are the loader's).
    fn ask_sweeps_again(&self, world: &mut SoftWorld) {
        for (robot, (_, h)) in self.robots.iter().zip(&self.handles.robots) {
            let given = h.links.iter().any(|&l| {
                world
                    .physics
                    .bodies
                    .get(l)
                    .is_some_and(|rb| rb.additional_pgs_iterations() > 0)
            });
            let mimic = robot.joints().iter().any(|j| j.mimic.is_some());
            if given || !mimic || robot.joint_model() != JointModel::Multibody {
                continue;
            }
            let pads: Vec<usize> = (self.handles.fingertips.iter())
                .filter_map(|(_, tip)| world.physics.colliders.get(*tip)?.parent())
                .filter_map(|body| h.links.iter().position(|&l| l == body))
                .collect();
            // A multibody robot's are never refused (only raised).
            let _ = robot.set_jointed_sweeps(world, h, &pads);
        }
    }
}
