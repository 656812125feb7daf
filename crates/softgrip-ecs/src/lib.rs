#![doc = include_str!("../README.md")]

mod components;
mod contact;
mod gripper;
mod mcap_sink;
mod messages;
mod plain;
mod resources;
pub mod scene;
mod schedule;
mod simulation;
mod sink;
mod spawn;
mod summary;
pub mod systems;

pub use components::{
    AttachedTo, BodyKind, BodyPose, Collider, Fingertip, FingertipWrench, KinematicPath,
    KinematicTarget, RapierBody, RapierCollider, RigidBody,
};
pub use contact::SoftContact;
pub use gripper::{Gripper, GripperEvent, GripperProgram, GripperState, JawState, Phase, Squeeze};
pub use mcap_sink::{
    FingertipLaw, McapReport, McapSink, McapSinkError, StepConverter, WORLD_FRAME, soft_contact,
};
pub use messages::{ContactEnded, ContactStarted, GripReached, SlipStarted, ValidityExcursion};
pub use plain::PlainRun;
pub use resources::{
    CurrentFrame, PatchRequest, Physics, Publisher, RecordSelection, Recorder, SceneInfoResource,
    SimClock, SinkSlot,
};
pub use scene::{Scene, SceneError};
pub use schedule::{SoftgripSet, SoftgripStep, build_schedule};
pub use simulation::{RunReport, Simulation};
pub use sink::{
    BodySample, ContactSample, SceneInfo, SinkError, StepFrame, StepSink, WrenchSample,
};
pub use spawn::{SceneEntities, init_world, soft_world_for, spawn_scene};
pub use summary::{Summary, TipSummary, accumulate_summary};

/// Re-exports of the crates the API uses.
pub use bevy_ecs;
pub use softgrip_rapier;
pub use softgrip_record;
