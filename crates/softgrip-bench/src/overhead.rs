//! Overhead scene: `n` fingertips (R = 10 mm, E = 3 MPa, nu = 0.49, `Level::auto()`, e = 0.5)
//! resting on a fixed ground, on a grid that keeps them apart, with softgrip's contacts or
//! with rapier's own (the same balls, not registered; the same `IntegrationParameters`).

use std::time::{Duration, Instant};

use rapier3d::prelude::*;
use softgrip_law::{Level, Material};
use softgrip_rapier::{SoftCounters, SoftFingertip, SoftWorld};

/// Fingertip radius \[m\].
pub const RADIUS: f64 = 0.01;
/// Fingertip density [kg/m^3] (silicone).
pub const DENSITY: f32 = 1070.0;
/// Grid pitch \[m\]: three radii, so neighbours never touch.
pub const PITCH: f32 = 0.03;
/// Steps run before measuring: long enough for the e = 0.5 contacts to come to rest.
pub const SETTLE_STEPS: usize = 120;

/// The overhead scene. Bodies never sleep in either variant (a sleeping rapier ball costs
/// nothing, the comparison is about the contact work).
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
        let mut world = SoftWorld::new();
        let side = (n as f64).sqrt().ceil() as usize;
        let half = 0.5 * side as f32 * PITCH + PITCH;
        world.physics.colliders.insert(
            ColliderBuilder::cuboid(half, 0.01, half).translation(Vector::new(0.0, -0.01, 0.0)),
        );
        let tip = SoftFingertip::builder(RADIUS)
            .material(Material::try_new(3.0e6, 0.49).expect("invariant: valid material"))
            .level(Level::auto())
            .restitution(0.5)
            .build()
            .expect("invariant: valid fingertip");
        let mass = DENSITY as f64 * 4.0 / 3.0 * std::f64::consts::PI * RADIUS.powi(3);
        let rest = tip
            .law()
            .compression_for_force(mass * 9.81)
            .expect("invariant: the weight is within the law's range");
        for i in 0..n {
            let (row, col) = (i / side, i % side);
            let x = (col as f32 - 0.5 * (side - 1) as f32) * PITCH;
            let z = (row as f32 - 0.5 * (side - 1) as f32) * PITCH;
            let body = world.physics.bodies.insert(
                RigidBodyBuilder::dynamic()
                    .translation(Vector::new(x, (RADIUS - rest) as f32, z))
                    .can_sleep(false),
            );
            let ball = world.physics.colliders.insert_with_parent(
                ColliderBuilder::ball(RADIUS as f32).density(DENSITY),
                body,
                &mut world.physics.bodies,
            );
            if soft {
                world
                    .register(ball, tip.clone())
                    .expect("invariant: a ball of the fingertip's radius");
            }
        }
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
