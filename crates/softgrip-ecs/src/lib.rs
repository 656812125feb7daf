#![doc = include_str!("../README.md")]

mod components;
mod contact;
mod controller;
mod messages;
mod resources;
mod schedule;
mod simulation;
mod spawn;
mod summary;
pub mod systems;
pub mod to_record;

/// The scene format, its builder and the plain runner: `softgrip-scene`, re-exported (also as
/// `softgrip_ecs::scene::...`, its path before it became a crate of its own).
pub use softgrip_scene as scene;

pub use components::{
    AttachedTo, BodyPose, Collider, Fingertip, FingertipWrench, KinematicPath, KinematicTarget,
    RapierBody, RapierCollider, RigidBody,
};
pub use contact::FingertipContact;
pub use controller::{ControllerEntities, ControllerEntity, Controllers, RobotLinkEntity};
pub use messages::{
    ContactEnded, ContactStarted, GoalEnded, GripReached, SlipStarted, ValidityExcursion,
};
pub use resources::{
    CurrentFrame, Names, PatchRequest, Physics, Publisher, RecordSelection, Recorder,
    SceneInfoResource, SimClock, SinkSlot, StepFault,
};
pub use schedule::{SoftgripStep, SoftgripSystems, build_schedule};
pub use simulation::{RunReport, Simulation};
/// The sink interface and its plain data, from softgrip-record (re-exported for now).
pub use softgrip_record::{
    BodySample, ContactReading, ContactSample, FingertipInfo, FingertipLaw, McapReport,
    McapSinkError, RunSummary, SceneInfo, SinkError, StepConverter, StepFrame, StepSink,
    WORLD_FRAME, WrenchSample,
};
pub use softgrip_scene::{
    BodyKind, Carrier, ControlEvent, ControlSet, Controller, GripperEvent, GripperProgram,
    GripperState, JawState, Phase, PlainRun, Scene, SceneError, Squeeze, control::GraspView,
};
pub use spawn::{SceneEntities, init_world, spawn_scene};
pub use summary::{Summary, TipSummary, accumulate_summary};
pub use to_record::{McapSink, contact_reading, fingertip_law, run_summary, scene_info};

/// Re-exports of the crates the API uses.
pub use bevy_ecs;
pub use softgrip_rapier;
pub use softgrip_record;
