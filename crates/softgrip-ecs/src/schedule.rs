//! [`SoftgripSystems`] and [`build_schedule`]: the systems in their documented order.

use bevy_ecs::message::{MessageRegistry, message_update_system};
use bevy_ecs::prelude::{IntoScheduleConfigs, Res, Schedule, SystemSet, World};
use bevy_ecs::schedule::ScheduleLabel;

use crate::resources::{Physics, Publisher, Recorder, SimClock, StepFault};
use crate::summary::{Summary, accumulate_summary};
use crate::systems::{
    assemble_frame, physics_step, publish, readout, record, run_controllers, sync_to_rapier,
};

/// The label of the softgrip schedule (one run = one physics step).
#[derive(ScheduleLabel, Debug, Clone, PartialEq, Eq, Hash)]
pub struct SoftgripStep;

/// The sets of one step, run in this order (chained).
#[derive(SystemSet, Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SoftgripSystems {
    /// Message buffers are rotated; new bodies, colliders and fingertips are created in rapier.
    Sync,
    /// Controllers write kinematic targets (trajectories, grippers, your own controllers).
    Control,
    /// The plugin's `SoftWorld::step` (kinematic targets applied first).
    Physics,
    /// Poses, `FingertipContact` entities, fingertip wrenches, transition messages, the summary.
    Readout,
    /// The frame is assembled and written to the [`Recorder`].
    Record,
    /// The frame is written to the [`Publisher`].
    Publish,
}

/// Builds the step schedule for `world`. Only what is needed is scheduled: the recording
/// system only if a [`Recorder`] resource exists, the publishing system only with a
/// [`Publisher`], the summary only with a [`Summary`], bevy's `message_update_system` only if
/// messages of your own are registered in bevy's `MessageRegistry` (the softgrip messages are
/// rotated by [`sync_to_rapier`]); so insert or register those first.
pub fn build_schedule(world: &World) -> Schedule {
    use SoftgripSystems::*;
    let mut s = Schedule::new(SoftgripStep);
    s.configure_sets((Sync, Control, Physics, Readout, Record, Publish).chain());
    // A step that failed is not read out, recorded or published (its state is the diverged
    // one), and a faulted world's controllers stop too.
    // `distributive_run_if`: each set evaluates it when reached (a plain `run_if` on the tuple
    // is evaluated once for all of them, at `Control`, before the physics step).
    s.configure_sets((Control, Readout, Record, Publish).distributive_run_if(not_faulted));
    s.add_systems(sync_to_rapier.in_set(Sync));
    if world.contains_resource::<MessageRegistry>() {
        // Messages of your own, registered with bevy: rotated by bevy's system.
        s.add_systems(message_update_system.after(sync_to_rapier).in_set(Sync));
    }
    s.add_systems(run_controllers.in_set(Control));
    s.add_systems(physics_step.in_set(Physics));
    s.add_systems(readout.in_set(Readout));
    if world.contains_resource::<Summary>() {
        s.add_systems(accumulate_summary.after(readout).in_set(Readout));
    }
    let recorder = world.contains_resource::<Recorder>();
    let publisher = world.contains_resource::<Publisher>();
    if recorder || publisher {
        // Only on steps some sink takes (the recorder writes every n-th step).
        s.add_systems(assemble_frame.run_if(frame_wanted).in_set(Record));
    }
    if recorder {
        s.add_systems(
            record
                .run_if(recorder_wants_step)
                .after(assemble_frame)
                .in_set(Record),
        );
    }
    if publisher {
        s.add_systems(publish.in_set(Publish));
    }
    s
}

/// Run condition: no step has failed ([`StepFault`], or the world's own fault).
fn not_faulted(fault: Option<Res<StepFault>>, physics: Option<Res<Physics>>) -> bool {
    fault.is_none_or(|f| f.0.is_none()) && physics.is_none_or(|p| p.world.fault().is_none())
}

/// Run condition: the recorder takes this step.
fn recorder_wants_step(clock: Res<SimClock>, recorder: Option<Res<Recorder>>) -> bool {
    recorder.is_some_and(|r| r.0.wants(clock.step))
}

/// Run condition: some sink takes this step (so the frame is assembled).
fn frame_wanted(
    clock: Res<SimClock>,
    recorder: Option<Res<Recorder>>,
    publisher: Option<Res<Publisher>>,
) -> bool {
    publisher.is_some_and(|p| p.0.wants(clock.step))
        || recorder.is_some_and(|r| r.0.wants(clock.step))
}
