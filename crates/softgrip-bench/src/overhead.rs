//! Overhead scene: `n` fingertips (R = 10 mm, E = 3 MPa, nu = 0.49, `Level::auto()`, e = 0.5)
//! resting on a fixed ground, on a grid that keeps them apart, with softgrip's contacts or
//! with rapier's own (the same balls, not registered; the same `IntegrationParameters`).

use std::time::{Duration, Instant};

use softgrip_rapier::{SoftCounters, SoftWorld};
use softgrip_testkit::resting::{resting_grid, resting_grid_with};

pub use softgrip_testkit::resting::PITCH;
pub use softgrip_testkit::scenes::{DENSITY, RADIUS};
/// Steps run before measuring: long enough for the e = 0.5 contacts to come to rest.
pub const SETTLE_STEPS: usize = 120;

/// The overhead scene. Bodies never sleep in either variant of [`new`](Self::new) (the
/// comparison is about the contact work); [`new_sleeping`](Self::new_sleeping) lets them.
pub struct OverheadScene {
    /// The world (`soft` is empty in the rapier-only variant).
    pub world: SoftWorld,
    /// Whether the balls are registered as soft fingertips.
    pub soft: bool,
}

impl OverheadScene {
    /// `n` balls on a square grid over a fixed ground; registered with softgrip if `soft`.
    /// Each ball starts at its softgrip resting depth (where F(delta) = m g).
    pub fn new(n: usize, soft: bool) -> Self {
        let world = resting_grid(n, PITCH, soft);
        let mut scene = Self { world, soft };
        for _ in 0..SETTLE_STEPS {
            scene.step();
        }
        scene
    }

    /// One step: `SoftWorld::step` with softgrip, rapier's own `PhysicsWorld::step` (no hooks,
    /// no events) without.
    pub fn step(&mut self) {
        if self.soft {
            self.world.step();
        } else {
            self.world.physics.step();
        }
    }

    /// [`new`](Self::new) with every ball allowed to sleep (rapier's default thresholds:
    /// still for 0.5 s), settled the same [`SETTLE_STEPS`] (2 s), by which time they sleep:
    /// the resting scene as a user would build it (`RigidBodyBuilder::dynamic()` sleeps).
    pub fn new_sleeping(n: usize, soft: bool) -> Self {
        let world = resting_grid_with(n, PITCH, soft, true);
        let mut scene = Self { world, soft };
        for _ in 0..SETTLE_STEPS {
            scene.step();
        }
        scene
    }

    /// Runs `steps` steps; returns the wall time and what the plugin did over them.
    pub fn measure(&mut self, steps: usize) -> (Duration, StageTimes) {
        let before = StageTimes::of(self.world.soft.counters());
        let t = Instant::now();
        for _ in 0..steps {
            self.step();
        }
        let wall = t.elapsed();
        (
            wall,
            StageTimes::of(self.world.soft.counters()).since(&before),
        )
    }
}

/// The plugin's counters that explain a step's time, accumulated.
#[derive(Debug, Clone, Copy, Default)]
pub struct StageTimes {
    /// Steps.
    pub steps: u64,
    /// Substeps (equal to `steps` when no step was split).
    pub substeps: u64,
    /// Soft contacts evaluated.
    pub contacts: u64,
    /// Soft contact detection.
    pub detect: Duration,
    /// Impulse solve.
    pub solve: Duration,
    /// rapier's pipeline.
    pub pipeline: Duration,
}

impl StageTimes {
    /// The totals of `c`.
    pub fn of(c: &SoftCounters) -> Self {
        Self {
            steps: c.steps,
            substeps: c.substeps_total,
            contacts: c.contacts_evaluated,
            detect: c.detect_time,
            solve: c.solve_time,
            pipeline: c.pipeline_time,
        }
    }

    /// What accumulated since `before`.
    pub fn since(&self, before: &Self) -> Self {
        Self {
            steps: self.steps - before.steps,
            substeps: self.substeps - before.substeps,
            contacts: self.contacts - before.contacts,
            detect: self.detect - before.detect,
            solve: self.solve - before.solve,
            pipeline: self.pipeline - before.pipeline,
        }
    }
}
