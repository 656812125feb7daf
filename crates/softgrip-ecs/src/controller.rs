//! The controllers in the ECS: the scene's [`ControlSet`] as the [`Controllers`] resource
//! (the same plain logic the plain runner steps, so both command alike), one entity per
//! controller ([`ControllerEntity`], named), and each robot link as an entity
//! ([`RobotLinkEntity`]).

use bevy_ecs::prelude::{Component, Entity, Resource};
use softgrip_scene::ControlSet;

/// The scene's controllers (the `[gripper]`, the `[[controller]]`s, each robot's commands from
/// outside), stepped by [`run_controllers`](crate::systems::run_controllers).
#[derive(Resource, Debug, Clone)]
pub struct Controllers(pub ControlSet);

/// A controller's entity: its index in [`Controllers`].
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct ControllerEntity(pub usize);

/// A robot link's body entity: the robot's and the link's index in the scene.
#[derive(Component, Debug, Clone, Copy, PartialEq, Eq)]
pub struct RobotLinkEntity {
    /// The robot's index (scene order).
    pub robot: usize,
    /// The link's index in the robot's links.
    pub link: usize,
}

/// Every controller's entity, by index (what a message names).
#[derive(Resource, Debug, Clone, Default)]
pub struct ControllerEntities(pub Vec<Entity>);
