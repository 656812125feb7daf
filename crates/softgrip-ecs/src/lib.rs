#![doc = include_str!("../README.md")]

mod components;
mod contact;
mod gripper;
mod mcap_sink;
mod messages;
mod resources;
mod schedule;
mod simulation;
mod sink;
mod spawn;
mod summary;
pub mod systems;

/// The scene format, its builder and the plain runner: `softgrip-scene`, re-exported (also as
/// `softgrip_ecs::scene::...`, its path before it became a crate of its own).
pub use softgrip_scene as scene;

pub use components::{
    AttachedTo, BodyPose, Collider, Fingertip, FingertipWrench, KinematicPath, KinematicTarget,
    RapierBody, RapierCollider, RigidBody,
};
pub use contact::FingertipContact;
pub use gripper::Gripper;
pub use mcap_sink::{
    FingertipLaw, McapReport, McapSink, McapSinkError, StepConverter, WORLD_FRAME, soft_contact,
};
pub use messages::{ContactEnded, ContactStarted, GripReached, SlipStarted, ValidityExcursion};
pub use resources::{
    CurrentFrame, PatchRequest, Physics, Publisher, RecordSelection, Recorder, SceneInfoResource,
    SimClock, SinkSlot,
};
pub use schedule::{SoftgripStep, SoftgripSystems, build_schedule};
pub use simulation::{RunReport, Simulation};
pub use sink::{
    BodySample, ContactSample, SceneInfo, SinkError, StepFrame, StepSink, WrenchSample,
};
pub use softgrip_scene::{
    BodyKind, GripperEvent, GripperProgram, GripperState, JawState, Phase, PlainRun, Scene,
    SceneError, Squeeze,
};
pub use spawn::{SceneEntities, init_world, spawn_scene};
pub use summary::{Summary, TipSummary, accumulate_summary};

/// Re-exports of the crates the API uses.
pub use bevy_ecs;
pub use softgrip_rapier;
pub use softgrip_record;
