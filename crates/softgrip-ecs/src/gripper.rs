//! [`Gripper`]: a gripper program's entity. The program and its state machine are
//! `softgrip-scene`'s ([`GripperProgram`], [`GripperState`]), shared with the plain runner.

use bevy_ecs::prelude::{Component, Entity};
use softgrip_scene::{GripperProgram, GripperState};

/// A gripper entity: its program, state, jaw bodies and each jaw's fingertip entities.
#[derive(Component, Debug, Clone)]
pub struct Gripper {
    /// The program.
    pub program: GripperProgram,
    /// The controller state.
    pub state: GripperState,
    /// The jaw body entities.
    pub jaws: [Entity; 2],
    /// Fingertip entities of each jaw.
    pub tips: [Vec<Entity>; 2],
}
