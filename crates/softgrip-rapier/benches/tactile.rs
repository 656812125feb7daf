//! Cost of the tactile pads (`cargo bench -p softgrip-rapier --bench tactile`):
//! - `tactile_disc/<pad>`: one contact of the default grasp's size (a = 4.8 mm, 5 N) laid on a
//!   16 mm pad of 16 x 16, 32 x 32 or 64 x 64 taxels ([`TactileImage::add_disc`]); divide by the
//!   taxels under the disc (printed) for the cost per taxel;
//! - `tactile_step/<with|with_16x16_unread|without>`: a step of a kinematic fingertip pressed
//!   to x = 0.2 on a fixed ground, with a 16 x 16 pad whose image is read after the step, with
//!   one nobody reads (the image is laid on its first read) and without one: `with - without`
//!   is the pad's cost per read step.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use rapier3d::prelude::*;
use softgrip_rapier::{Preset, SoftFingertip, SoftWorld, TactileImage, TactilePad};

const R: f64 = 0.01;

fn pad(n: u32) -> TactilePad {
    TactilePad::new(n, n, [0.0, -1.0, 0.0], 0.016, 0.016)
}

fn tip(pad: Option<TactilePad>) -> SoftFingertip {
    let b = SoftFingertip::builder(R).preset(Preset::DragonSkin30);
    match pad {
        Some(p) => b.tactile(p),
        None => b,
    }
    .build()
    .expect("a valid fingertip")
}

fn bench_disc(c: &mut Criterion) {
    let mut group = c.benchmark_group("tactile_disc");
    let a = 0.0048;
    for n in [16u32, 32, 64] {
        let grid = *tip(Some(pad(n))).tactile().expect("a pad");
        let mut image = TactileImage::new(grid);
        // Taxels whose area meets the disc's bounding square (those visited).
        let side = 2.0 * a / grid.taxel_width();
        println!(
            "pad {n} x {n}: about {:.0} taxels visited, {:.0} under the disc",
            (side.ceil() + 1.0).powi(2),
            std::f64::consts::PI * a * a / grid.taxel_area()
        );
        group.bench_function(BenchmarkId::from_parameter(n), |b| {
            b.iter(|| {
                image.clear();
                image.add_disc([1.3e-4, -2.1e-4], a, 5.0);
                image.pressure()[0]
            })
        });
    }
    group.finish();
}

fn pressed_world(pad: Option<TactilePad>) -> SoftWorld {
    let mut world = SoftWorld::new();
    world
        .physics
        .colliders
        .insert(ColliderBuilder::new(SharedShape::halfspace(Vector::Y)));
    let body = world.physics.bodies.insert(
        RigidBodyBuilder::kinematic_position_based().translation(Vector::new(
            0.0,
            (0.8 * R) as f32,
            0.0,
        )),
    );
    let co = world.physics.colliders.insert_with_parent(
        ColliderBuilder::ball(R as f32),
        body,
        &mut world.physics.bodies,
    );
    world.register(co, tip(pad)).expect("registered");
    world.step();
    world
}

fn bench_step(c: &mut Criterion) {
    let mut group = c.benchmark_group("tactile_step");
    for (name, p) in [("without", None), ("with_16x16_unread", Some(pad(16)))] {
        let mut world = pressed_world(p);
        group.bench_function(name, |b| b.iter(|| world.step()));
    }
    // The image is laid on its first read after a step: a step whose image is read.
    let mut world = pressed_world(Some(pad(16)));
    group.bench_function("with_16x16", |b| {
        b.iter(|| {
            world.step();
            world
                .soft
                .tactile_images()
                .map(|(_, i)| i.total_force())
                .sum::<f64>()
        })
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(std::time::Duration::from_millis(500))
        .measurement_time(std::time::Duration::from_secs(2))
        .sample_size(20);
    targets = bench_disc, bench_step
}
criterion_main!(benches);
