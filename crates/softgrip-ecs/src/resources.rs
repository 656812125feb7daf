//! Resources: the physics world, the clock, and the hooks of the recorder and publisher.

use std::collections::{BTreeMap, HashMap};

use bevy_ecs::prelude::{Entity, Resource};
use softgrip_rapier::SoftWorld;
use softgrip_rapier::rapier3d::prelude::{ColliderHandle, RigidBodyHandle};

use softgrip_record::{RunSummary, SceneInfo, SinkError, StepFrame, StepSink};
use softgrip_scene::RecordSpec;

/// What the readout remembers of a live contact.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Tracked {
    pub entity: Entity,
    pub sliding: bool,
    pub extended: bool,
    /// The last step whose readout had the contact.
    pub seen: u64,
}

/// The entity of each synchronised rapier handle, addressed by the handle's arena index and
/// checked against its generation: the readout looks up two or three handles per contact
/// every step, and this costs an index instead of a hash.
#[derive(Debug, Clone, Default)]
pub(crate) struct HandleEntities(Vec<Option<(u32, Entity)>>);

impl HandleEntities {
    pub(crate) fn insert(&mut self, (index, generation): (u32, u32), entity: Entity) {
        let i = index as usize;
        if self.0.len() <= i {
            self.0.resize(i + 1, None);
        }
        self.0[i] = Some((generation, entity));
    }

    pub(crate) fn get(&self, (index, generation): (u32, u32)) -> Option<Entity> {
        match self.0.get(index as usize) {
            Some(&Some((g, e))) if g == generation => Some(e),
            _ => None,
        }
    }
}

/// The plugin's world and the maps between rapier handles and entities.
#[derive(Resource)]
pub struct Physics {
    /// The rapier world with the soft-fingertip plugin (gravity, `params.dt`, accuracy).
    pub world: SoftWorld,
    pub(crate) body_entity: HandleEntities,
    pub(crate) collider_entity: HandleEntities,
    pub(crate) entity_body: HashMap<Entity, RigidBodyHandle>,
    pub(crate) contacts: BTreeMap<(Entity, Entity), Tracked>,
}

impl Physics {
    /// Wraps a world (normally empty: `spawn_scene` builds a scene into it, the sync system
    /// adds the components you spawn yourself).
    pub fn new(world: SoftWorld) -> Self {
        Self {
            world,
            body_entity: HandleEntities::default(),
            collider_entity: HandleEntities::default(),
            entity_body: HashMap::new(),
            contacts: BTreeMap::new(),
        }
    }

    /// Records that `entity` is the rapier body `handle` (the sync system, or the spawn of a
    /// scene built by `softgrip-scene`).
    pub(crate) fn link_body(&mut self, handle: RigidBodyHandle, entity: Entity) {
        self.body_entity.insert(handle.into_raw_parts(), entity);
        self.entity_body.insert(entity, handle);
    }

    /// Records that `entity` is the rapier collider `handle` (a `Collider` or a `Fingertip`).
    pub(crate) fn link_collider(&mut self, handle: ColliderHandle, entity: Entity) {
        self.collider_entity.insert(handle.into_raw_parts(), entity);
    }

    /// The entity of a rapier body.
    pub fn body_entity(&self, handle: RigidBodyHandle) -> Option<Entity> {
        self.body_entity.get(handle.into_raw_parts())
    }

    /// The entity of a rapier collider (a `Collider` or a `Fingertip`).
    pub fn collider_entity(&self, handle: ColliderHandle) -> Option<Entity> {
        self.collider_entity.get(handle.into_raw_parts())
    }

    /// The rapier body of an entity.
    pub fn body_handle(&self, entity: Entity) -> Option<RigidBodyHandle> {
        self.entity_body.get(&entity).copied()
    }
}

/// Simulated time.
#[derive(Resource, Debug, Clone, Copy, PartialEq, Default)]
pub struct SimClock {
    /// Steps taken.
    pub step: u64,
    /// Time at the end of the last step \[s\] (`step * dt`).
    pub time: f64,
}

/// The error that stopped the simulation ([`StepError`](softgrip_rapier::StepError)), with the
/// scene's names where the world was spawned from a scene (`SubjectNames`). Set by the
/// physics system when `SoftWorld::try_step` fails; from then on the schedule's readout,
/// record and publish sets do not run (the diverged state is never read out or recorded),
/// the physics system does not step, and [`Simulation`](crate::Simulation) stops.
#[derive(Resource, Debug, Clone, Default)]
pub struct StepFault(pub Option<softgrip_rapier::StepError>);

/// The scene's names of the rapier handles, for a [`StepFault`] (inserted by `spawn_scene`).
#[derive(Resource, Debug, Clone, Default)]
pub struct Names(pub softgrip_scene::SubjectNames);

/// Its presence makes the readout compute every contact's radius and pressure
/// (`FingertipContact::patch`). Without it no pressure is computed.
#[derive(Resource, Debug, Clone, Copy, Default)]
pub struct PatchRequest;

/// What the sinks receive (a scene's `[record]`).
#[derive(Resource, Debug, Clone, PartialEq, Default)]
pub struct RecordSelection(pub RecordSpec);

/// The scene description handed to the sinks' `start`.
#[derive(Resource, Debug, Clone)]
pub struct SceneInfoResource(pub SceneInfo);

/// The step's data, assembled once for the recorder and the publisher.
#[derive(Resource, Debug, Clone, Default)]
pub struct CurrentFrame(pub StepFrame);

/// A sink with its lifecycle state.
pub struct SinkSlot {
    sink: Box<dyn StepSink>,
    started: bool,
    error: Option<SinkError>,
    frames: u64,
}

impl SinkSlot {
    fn new(sink: Box<dyn StepSink>) -> Self {
        Self {
            sink,
            started: false,
            error: None,
            frames: 0,
        }
    }

    /// Starts the sink if needed and writes the frame; the first error stops the sink.
    pub(crate) fn write(&mut self, info: Option<&SceneInfo>, frame: &StepFrame) {
        if self.error.is_some() {
            return;
        }
        if !self.started {
            self.started = true;
            if let Some(Err(e)) = info.map(|i| self.sink.start(i)) {
                self.error = Some(e);
                return;
            }
        }
        match self.sink.write(frame) {
            Ok(()) => self.frames += 1,
            Err(e) => self.error = Some(e),
        }
    }

    /// Finishes the sink; returns its first error, if any.
    pub fn finish(&mut self) -> Result<(), SinkError> {
        if let Some(e) = self.error.take() {
            return Err(e);
        }
        self.sink.finish()
    }

    /// Hands the sink the run's summary (before [`finish`](Self::finish)).
    pub fn run_summary(&mut self, summary: &RunSummary) {
        if self.error.is_none() {
            self.sink.run_summary(summary);
        }
    }

    /// Whether the sink takes step `step` (not once it stopped on an error).
    pub fn wants(&self, step: u64) -> bool {
        self.error.is_none() && self.sink.wants(step)
    }

    /// Frames written.
    pub fn frames(&self) -> u64 {
        self.frames
    }

    /// The error that stopped the sink.
    pub fn error(&self) -> Option<&SinkError> {
        self.error.as_ref()
    }
}

/// The recorder (e.g. the MCAP writer). Without it, the recording system is not scheduled.
#[derive(Resource)]
pub struct Recorder(pub SinkSlot);

impl Recorder {
    /// Wraps a sink.
    pub fn new(sink: impl StepSink) -> Self {
        Self(SinkSlot::new(Box::new(sink)))
    }
}

/// The live publisher (e.g. ROS 2). Without it, the publishing system is not scheduled.
#[derive(Resource)]
pub struct Publisher(pub SinkSlot);

impl Publisher {
    /// Wraps a sink.
    pub fn new(sink: impl StepSink) -> Self {
        Self(SinkSlot::new(Box::new(sink)))
    }
}
