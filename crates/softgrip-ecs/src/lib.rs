#![doc = include_str!("../README.md")]

mod components;
mod contact;
mod gripper;
mod messages;
mod plain;
mod resources;
pub mod scene;
mod schedule;
mod simulation;
mod spawn;
mod summary;
pub mod systems;
pub mod to_record;

pub use components::{
    AttachedTo, BodyKind, BodyPose, Collider, Fingertip, FingertipWrench, KinematicPath,
    KinematicTarget, RapierBody, RapierCollider, RigidBody,
};
pub use contact::SoftContact;
pub use gripper::{Gripper, GripperEvent, GripperProgram, GripperState, JawState, Phase, Squeeze};
pub use messages::{ContactEnded, ContactStarted, GripReached, SlipStarted, ValidityExcursion};
pub use plain::PlainRun;
pub use resources::{
    CurrentFrame, PatchRequest, Physics, Publisher, RecordSelection, Recorder, SceneInfoResource,
    SimClock, SinkSlot,
};
pub use scene::{Scene, SceneError};
pub use schedule::{SoftgripSet, SoftgripStep, build_schedule};
pub use simulation::{RunReport, Simulation};
/// The sink interface and its plain data, from softgrip-record (re-exported for now).
pub use softgrip_record::{
    BodySample, ContactReading, ContactSample, FingertipInfo, FingertipLaw, McapReport,
    McapSinkError, RunSummary, SceneInfo, SinkError, StepConverter, StepFrame, StepSink,
    WORLD_FRAME, WrenchSample,
};
pub use spawn::{SceneEntities, init_world, soft_world_for, spawn_scene};
pub use summary::{Summary, TipSummary, accumulate_summary};
pub use to_record::{McapSink, contact_reading, fingertip_law, run_summary, scene_info};

/// Re-exports of the crates the API uses.
pub use bevy_ecs;
pub use softgrip_rapier;
pub use softgrip_record;
