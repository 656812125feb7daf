//! [`ControlIo`]: what a controller reads and writes in a step, over the rapier world and the
//! scene's handles, by scene index (bodies, fingertips, robots' joints).

use softgrip_rapier::SoftWorld;
use softgrip_rapier::rapier3d::prelude::RigidBodyHandle;

use crate::build::SceneHandles;
use crate::robot::{JointState, Robot, joint_state_loaded, set_joint_target};
use crate::vector::vector;

/// What carries a fingertip, or what a controller moves: a body, or a robot's link.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Carrier {
    /// Body `i` of the scene (file order).
    Body(usize),
    /// Link `link` of robot `robot` (scene order; link in [`Robot::links`] order).
    Link {
        /// The robot's index.
        robot: usize,
        /// The link's index.
        link: usize,
    },
}

/// A controller's view of one step: the state after the last step and the targets of the
/// coming one.
pub struct ControlIo<'a> {
    /// Time at the end of the coming step \[s\].
    pub time: f64,
    /// The step \[s\].
    pub dt: f64,
    world: &'a mut SoftWorld,
    handles: &'a SceneHandles,
    robots: &'a [Robot],
}

impl<'a> ControlIo<'a> {
    /// A step of `dt` \[s\] ending at `time` \[s\] over `world` built with `handles`.
    pub fn new(
        world: &'a mut SoftWorld,
        handles: &'a SceneHandles,
        robots: &'a [Robot],
        time: f64,
        dt: f64,
    ) -> Self {
        Self {
            time,
            dt,
            world,
            handles,
            robots,
        }
    }

    /// The scene's robots.
    pub fn robots(&self) -> &[Robot] {
        self.robots
    }

    /// The rapier body of a carrier.
    pub fn body_handle(&self, c: Carrier) -> Option<RigidBodyHandle> {
        match c {
            Carrier::Body(i) => self.handles.bodies.get(i).map(|b| b.1),
            Carrier::Link { robot, link } => {
                self.handles.robots.get(robot)?.1.links.get(link).copied()
            }
        }
    }

    /// The largest compression `delta` \[m\] among the last step's contacts of the
    /// fingertips `tips` (scene indices); `None` without contact.
    pub fn compression(&self, tips: &[usize]) -> Option<f64> {
        let mut delta: Option<f64> = None;
        for c in self.world.soft.contacts() {
            if tips.iter().any(|&t| {
                self.handles
                    .fingertips
                    .get(t)
                    .is_some_and(|h| h.1 == c.fingertip)
            }) {
                delta = Some(delta.map_or(c.delta, |m| m.max(c.delta)));
            }
        }
        delta
    }

    /// The total normal force \[N\] of the last step's contacts of fingertip `tip`.
    pub fn normal_force(&self, tip: usize) -> f64 {
        let Some(h) = self.handles.fingertips.get(tip).map(|h| h.1) else {
            return 0.0;
        };
        self.world.soft.contacts_of(h).map(|c| c.normal_force).sum()
    }

    /// A body's or link's position \[m\].
    pub fn position(&self, c: Carrier) -> Option<[f64; 3]> {
        let rb = self.world.physics.bodies.get(self.body_handle(c)?)?;
        let t = rb.translation();
        Some([t.x as f64, t.y as f64, t.z as f64])
    }

    /// Moves a kinematic body or link to `position` \[m\] at the end of the coming step.
    pub fn set_translation(&mut self, c: Carrier, position: [f64; 3]) {
        if let Some(h) = self.body_handle(c)
            && let Some(rb) = self.world.physics.bodies.get_mut(h)
        {
            rb.set_next_kinematic_translation(vector(position));
        }
    }

    /// The state of joint `joint` of robot `robot` after the last step.
    pub fn joint(&self, robot: usize, joint: usize) -> JointState {
        let (Some(r), Some((_, h))) = (self.robots.get(robot), self.handles.robots.get(robot))
        else {
            return JointState::default();
        };
        let n = self.world.soft.counters().substeps_last.max(1) as f64;
        let dt = self.world.physics.integration_parameters.dt as f64;
        joint_state_loaded(r, self.world, h, joint, dt / n)
    }

    /// Sets joint `joint` of robot `robot`'s motor target: `position` \[m or rad\] and
    /// `velocity` \[m/s or rad/s\].
    pub fn set_joint(&mut self, robot: usize, joint: usize, position: f64, velocity: f64) {
        if let (Some(r), Some((_, h))) = (self.robots.get(robot), self.handles.robots.get(robot)) {
            set_joint_target(r, &mut self.world.physics, h, joint, position, velocity);
        }
    }
}
