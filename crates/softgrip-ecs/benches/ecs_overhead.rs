//! Step time of the default scene through the bevy_ecs schedule vs the plain plugin
//! (`PlainRun`: the same world and controller without ECS). Target: <= 5 % overhead.
//! Each sample runs the whole scene (300 steps), so every phase of the grasp is included.

#![allow(missing_docs)]

use criterion::{Criterion, criterion_group, criterion_main};
use softgrip_ecs::{PlainRun, Scene, Simulation};

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
    g.bench_function("ecs", |b| {
        b.iter_batched(
            || {
                let mut sim = Simulation::new(&scene);
                sim.initialize(); // not part of a step: the plain run has no schedule to build
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
