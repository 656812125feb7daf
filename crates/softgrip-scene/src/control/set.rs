//! [`ControlSet`]: a scene's controllers in order (the `[gripper]`, the `[[controller]]`s, then
//! each robot's [`JointCommands`]), stepped over a rapier world by the plain runner and the ECS
//! alike.

use softgrip_rapier::SoftWorld;

use crate::build::SceneHandles;
use crate::control::controller::{ControlEvent, Controller};
use crate::control::external::{JointCommands, SharedInbox};
use crate::control::io::ControlIo;
use crate::robot::Robot;

/// A scene's controllers with what they need to run: the handles and the robots' models.
#[derive(Debug, Clone)]
pub struct ControlSet {
    controllers: Vec<Box<dyn Controller>>,
    handles: SceneHandles,
    robots: Vec<Robot>,
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
        let mut io = ControlIo::new(world, &self.handles, &self.robots, time, dt);
        let mut events = Vec::new();
        for (i, c) in self.controllers.iter_mut().enumerate() {
            if let Some(e) = c.update(&mut io) {
                events.push((i, e));
            }
        }
        events
    }
}
