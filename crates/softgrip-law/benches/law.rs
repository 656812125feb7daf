//! ns per evaluation of every level: force + stiffness only (the hot path), and with the
//! contact radius and pressure. `cargo bench -p softgrip-law`.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use softgrip_law::{ContactLaw, ContactParams, Level, Material};

/// 1024 compressions spread over (0, delta_max) in a scrambled order, as contacts of a scene
/// would come.
fn deltas(law: &ContactLaw) -> Vec<f64> {
    (0..1024u64)
        .map(|i| {
            let u = ((i.wrapping_mul(2_654_435_761) % 1024) as f64 + 0.5) / 1024.0;
            u * law.delta_max()
        })
        .collect()
}

fn bench_levels(c: &mut Criterion) {
    let material = Material::try_new(3.0e6, 0.49).expect("valid material");
    let params = ContactParams::try_new(material, 0.01).expect("valid params");
    // The arithmetic floor of the explicit levels: one square root (x^(3/2)) and one division
    // (chi_L = 1/(1 - k x)) per evaluation, on the same inputs, with nothing else. On a core
    // whose divider is not pipelined this, not the law, sets the cost of fit and incompressible.
    let mut floor = c.benchmark_group("floor");
    {
        let law = ContactLaw::try_new(params, Level::fit()).expect("level builds");
        let xs: Vec<f64> = deltas(&law).iter().map(|d| d / 0.01).collect();
        floor.bench_function("sqrt", |b| {
            b.iter(|| {
                let mut sum = 0.0;
                for &x in &xs {
                    sum += black_box(x).sqrt();
                }
                sum
            })
        });
        floor.bench_function("sqrt+div", |b| {
            b.iter(|| {
                let mut sum = 0.0;
                for &x in &xs {
                    let x = black_box(x);
                    sum += x.sqrt() + 1.0 / (1.0 - 0.5 * x);
                }
                sum
            })
        });
    }
    floor.finish();
    let mut force = c.benchmark_group("force_stiffness");
    for level in Level::ALL {
        let law = ContactLaw::try_new(params, level).expect("level builds");
        let ds = deltas(&law);
        force.bench_function(level.name(), |b| {
            b.iter(|| {
                let mut sum = 0.0;
                for &d in &ds {
                    let r = law.response(black_box(d));
                    sum += r.force + r.stiffness;
                }
                sum
            })
        });
    }
    // Auto picks its level by x: with scrambled x the pick is a mispredicted branch about
    // every other call. A contact's x changes little from one step to the next, so also time
    // it on the same compressions in ascending order (the predictable case).
    {
        let law = ContactLaw::try_new(params, Level::auto()).expect("level builds");
        let mut ds = deltas(&law);
        ds.sort_by(f64::total_cmp);
        force.bench_function("auto-ascending-x", |b| {
            b.iter(|| {
                let mut sum = 0.0;
                for &d in &ds {
                    let r = law.response(black_box(d));
                    sum += r.force + r.stiffness;
                }
                sum
            })
        });
    }
    force.finish();
    let mut patch = c.benchmark_group("with_radius_pressure");
    for level in Level::ALL {
        let law = ContactLaw::try_new(params, level).expect("level builds");
        let ds = deltas(&law);
        patch.bench_function(level.name(), |b| {
            b.iter(|| {
                let mut sum = 0.0;
                for &d in &ds {
                    let r = law.response(black_box(d));
                    sum += r.force + law.patch(d).peak_pressure;
                }
                sum
            })
        });
    }
    patch.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(std::time::Duration::from_millis(300))
        .measurement_time(std::time::Duration::from_secs(1))
        .sample_size(20);
    targets = bench_levels
}
criterion_main!(benches);
