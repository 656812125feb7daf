//! [`Simulation`]: a scene's world and schedule, stepped for the scene's duration (what
//! `softgrip run` uses).

use std::time::{Duration, Instant};

use bevy_ecs::prelude::{FromWorld, Schedule, World};

use crate::resources::{Physics, Publisher, Recorder, SimClock, StepFault};
use crate::schedule::build_schedule;
use crate::spawn::{SceneEntities, spawn_scene};
use crate::summary::Summary;
use crate::systems::{Unsynchronised, create_in_rapier};
use softgrip_rapier::StepError;
use softgrip_record::{SinkError, StepSink};
use softgrip_scene::Scene;

/// What a run took.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunReport {
    /// Steps taken.
    pub steps: u64,
    /// Simulated time \[s\].
    pub sim_time: f64,
    /// Wall-clock time of the steps.
    pub wall: Duration,
}

impl RunReport {
    /// Simulated seconds per wall-clock second.
    pub fn real_time_factor(&self) -> f64 {
        self.sim_time / self.wall.as_secs_f64().max(1e-12)
    }
}

/// A scene spawned into a bevy_ecs [`World`] with the softgrip schedule.
///
/// Insert sinks ([`with_recorder`](Self::with_recorder), ...) before the first step: the
/// schedule is built then, with only the systems that something needs.
pub struct Simulation {
    /// The ECS world.
    pub world: World,
    /// The scene's entities.
    pub entities: SceneEntities,
    schedule: Option<Schedule>,
    steps: u64,
}

impl Simulation {
    /// Spawns `scene` into a new world.
    pub fn new(scene: &Scene) -> Self {
        let mut world = World::new();
        let entities = spawn_scene(&mut world, scene);
        Self {
            world,
            entities,
            schedule: None,
            steps: scene.steps(),
        }
    }

    /// Adds a recorder sink.
    pub fn with_recorder(mut self, sink: impl StepSink) -> Self {
        self.world.insert_resource(Recorder::new(sink));
        self
    }

    /// Adds a publisher sink.
    pub fn with_publisher(mut self, sink: impl StepSink) -> Self {
        self.world.insert_resource(Publisher::new(sink));
        self
    }

    /// Accumulates a [`Summary`].
    pub fn with_summary(mut self) -> Self {
        self.world.init_resource::<Summary>();
        self
    }

    /// The schedule (built on first use).
    pub fn schedule_mut(&mut self) -> &mut Schedule {
        let world = &self.world;
        self.schedule.get_or_insert_with(|| build_schedule(world))
    }

    /// Does now what the first step would otherwise do before stepping: builds and initialises
    /// the schedule (system state, the dependency graph and its sync points) and creates the
    /// rapier bodies, colliders and fingertips of the entities spawned so far (what
    /// [`sync_to_rapier`](crate::systems::sync_to_rapier) does in the `Sync` set, in the same
    /// order). Entities spawned later are created by the `Sync` set of the next step.
    pub fn initialize(&mut self) {
        self.schedule_mut();
        if let Some(s) = self.schedule.as_mut() {
            s.initialize(&mut self.world)
                .expect("invariant: the softgrip sets are acyclic");
        }
        let mut new = Unsynchronised::from_world(&mut self.world);
        create_in_rapier(&mut self.world, &mut new);
    }

    /// One step. A faulted simulation ([`fault`](Self::fault)) does not step any more.
    pub fn step(&mut self) {
        if self.fault().is_some() {
            return;
        }
        self.schedule_mut();
        if let Some(s) = self.schedule.as_mut() {
            s.run(&mut self.world);
        }
    }

    /// [`step`](Self::step), with the [`StepError`] that stopped it (this step's, or an
    /// earlier one's: a faulted simulation does not step any more).
    pub fn try_step(&mut self) -> Result<(), StepError> {
        self.step();
        self.fault().map_or(Ok(()), |e| Err(e.clone()))
    }

    /// The error that stopped the simulation: a step whose state was non-finite or out of the
    /// engine's bounds before or after it, or a panic inside rapier ([`StepFault`], named with
    /// the scene's names). The steps before it were read out, recorded and published; the
    /// failed one was not.
    pub fn fault(&self) -> Option<&StepError> {
        let fault = self
            .world
            .get_resource::<StepFault>()
            .and_then(|f| f.0.as_ref());
        fault.or_else(|| {
            let physics = self.world.get_resource::<Physics>()?;
            physics.world.fault()
        })
    }

    /// Steps of the scene's duration.
    pub fn total_steps(&self) -> u64 {
        self.steps
    }

    /// Runs the scene's duration; `progress(step, total)` is called after every step. Stops at
    /// a step that fails ([`fault`](Self::fault) says why): the report then counts the steps
    /// taken before it.
    pub fn run(&mut self, mut progress: impl FnMut(u64, u64)) -> RunReport {
        let start = Instant::now();
        let dt = self
            .world
            .resource::<Physics>()
            .world
            .physics
            .integration_parameters
            .dt as f64;
        let mut steps = 0;
        for k in 0..self.steps {
            if self.try_step().is_err() {
                break;
            }
            steps = k + 1;
            progress(steps, self.steps);
        }
        RunReport {
            steps,
            sim_time: steps as f64 * dt,
            wall: start.elapsed(),
        }
    }

    /// Finishes the sinks (flush, close); returns the first error of either. With a
    /// [`Summary`] ([`with_summary`](Self::with_summary)), the sinks first get it as a
    /// [`RunSummary`](crate::RunSummary) (the MCAP recorder writes it into the file: counted over every
    /// step, where the recording may hold only every n-th).
    pub fn finish(&mut self) -> Result<(), SinkError> {
        let steps = self.world.get_resource::<SimClock>().map_or(0, |c| c.step);
        let summary = self
            .world
            .get_resource::<Summary>()
            .map(|s| crate::to_record::run_summary(s, steps));
        let r = match self.world.get_resource_mut::<Recorder>() {
            Some(mut r) => {
                if let Some(s) = &summary {
                    r.0.run_summary(s);
                }
                r.0.finish()
            }
            None => Ok(()),
        };
        let p = match self.world.get_resource_mut::<Publisher>() {
            Some(mut p) => {
                if let Some(s) = &summary {
                    p.0.run_summary(s);
                }
                p.0.finish()
            }
            None => Ok(()),
        };
        r.and(p)
    }
}
