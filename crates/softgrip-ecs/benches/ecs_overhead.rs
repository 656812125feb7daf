//! Step time of the default scene through the bevy_ecs schedule vs the plain plugin
//! (`PlainRun`: the same world and controller without ECS). Target: <= 5 % overhead.
//! Each sample runs the whole scene (300 steps), so every phase of the grasp is included.
//!
//! What is timed, so that both sides do the same work:
//!
//! - Only the 300 steps. Building the world is setup on both sides: `PlainRun::new` and
//!   `Simulation::new` build the same rapier world with `softgrip-scene`'s builder, and
//!   `Simulation::initialize` builds the schedule.
//! - Same scene, same physics (the tests check the contact values are bit-identical), same
//!   controller (trajectories and the gripper fed by the last step's compressions).
//! - `plain_plugin` computes nothing else. The ECS also reads back every step what its
//!   components and messages offer: every body's `BodyPose`, one `FingertipContact` entity per
//!   contact, each fingertip's `FingertipWrench`, the transition messages (contact started or
//!   ended, slip started, validity excursion), with their buffers rotated. So `ecs` over
//!   `plain_plugin` is the strict figure: the ECS's machinery plus that readout.
//! - `plain_plugin_readout` is the plain loop plus the same readout written directly against
//!   the plugin (poses into a `Vec`, wrench sums per fingertip, the transitions of a tracked
//!   pair map, events into a `Vec`), i.e. what a plain-plugin user needing the same outputs
//!   would run; `ecs` over it is the cost of the ECS machinery alone.
//!
//! No recorder, publisher or summary is inserted (`Simulation::new` alone), so neither side
//! assembles frames.

#![allow(missing_docs)]

use std::collections::BTreeMap;

use criterion::{Criterion, criterion_group, criterion_main};
use softgrip_ecs::{PlainRun, Scene, Simulation};
use softgrip_law::Regime;

/// A pair's key: both collider handles' (index, generation).
type Pair = (u32, u32, u32, u32);

/// The ECS's per-step readout, written against the plain plugin.
#[derive(Default)]
struct PlainReadout {
    poses: Vec<([f32; 3], [f32; 4])>,
    /// Force and torque about the centre, per fingertip (scene order).
    wrenches: Vec<[f64; 6]>,
    /// Live pairs: (sliding, extended, last step seen).
    live: BTreeMap<Pair, (bool, bool, u64)>,
    /// (kind, pair, time): 0 started, 1 ended, 2 slip started, 3 validity excursion.
    events: Vec<(u8, Pair, f64)>,
}

impl PlainReadout {
    fn read(&mut self, run: &PlainRun, step: u64) {
        let w = &run.world;
        let time = step as f64 * w.physics.integration_parameters.dt as f64;
        self.poses.clear();
        for (_, h) in &run.handles.bodies {
            if let Some(rb) = w.physics.bodies.get(*h) {
                let (t, q) = (rb.translation(), rb.rotation());
                self.poses.push(([t.x, t.y, t.z], [q.x, q.y, q.z, q.w]));
            }
        }
        self.wrenches.clear();
        self.wrenches.resize(run.handles.fingertips.len(), [0.0; 6]);
        self.events.clear();
        let mut seen = 0;
        for c in w.soft.contacts() {
            let (a, b) = (c.fingertip.into_raw_parts(), c.other.into_raw_parts());
            let key = (a.0, a.1, b.0, b.1);
            let (sliding, extended) = (c.sliding, c.regime == Regime::Extended);
            let (was_sliding, was_extended) = match self.live.get_mut(&key) {
                Some(t) => {
                    let old = (t.0, t.1);
                    seen += usize::from(t.2 != step);
                    *t = (sliding, extended, step);
                    old
                }
                None => {
                    self.live.insert(key, (sliding, extended, step));
                    seen += 1;
                    self.events.push((0, key, time));
                    (false, false)
                }
            };
            if sliding && !was_sliding {
                self.events.push((2, key, time));
            }
            if extended && !was_extended {
                self.events.push((3, key, time));
            }
            if let Some(k) = run
                .handles
                .fingertips
                .iter()
                .position(|(_, h)| *h == c.fingertip)
            {
                let center = w
                    .physics
                    .colliders
                    .get(c.fingertip)
                    .map(|co| co.translation())
                    .map(|t| [t.x as f64, t.y as f64, t.z as f64])
                    .unwrap_or(c.point);
                let (f, tau) = c.wrench_about(center);
                for i in 0..3 {
                    self.wrenches[k][i] += f[i];
                    self.wrenches[k][3 + i] += tau[i];
                }
            }
        }
        if seen != self.live.len() {
            let events = &mut self.events;
            self.live.retain(|key, t| {
                if t.2 != step {
                    events.push((1, *key, time));
                }
                t.2 == step
            });
        }
    }
}

fn overhead(c: &mut Criterion) {
    let scene = Scene::default_scene();
    let steps = scene.steps();
    let mut g = c.benchmark_group(format!("default_scene_{steps}_steps"));
    g.sample_size(30);
    g.bench_function("plain_plugin", |b| {
        b.iter_batched(
            || PlainRun::new(&scene),
            |mut run| {
                for _ in 0..steps {
                    run.step();
                }
                run
            },
            criterion::BatchSize::LargeInput,
        )
    });
    g.bench_function("plain_plugin_readout", |b| {
        b.iter_batched(
            || (PlainRun::new(&scene), PlainReadout::default()),
            |(mut run, mut readout)| {
                for k in 0..steps {
                    run.step();
                    readout.read(&run, k + 1);
                }
                (run, readout)
            },
            criterion::BatchSize::LargeInput,
        )
    });
    g.bench_function("ecs", |b| {
        b.iter_batched(
            || {
                let mut sim = Simulation::new(&scene);
                // Not part of a step: the schedule and the rapier world (PlainRun::new builds
                // its world too).
                sim.initialize();
                sim
            },
            |mut sim| {
                for _ in 0..steps {
                    sim.step();
                }
                sim
            },
            criterion::BatchSize::LargeInput,
        )
    });
    g.finish();
}

criterion_group!(benches, overhead);
criterion_main!(benches);
