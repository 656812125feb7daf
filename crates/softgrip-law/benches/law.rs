//! ns per evaluation of every level: force + stiffness only (the hot path), and with the
//! contact radius and pressure; plus the arithmetic floor. `cargo bench -p softgrip-law`.
//! Each benchmark is one pass over 1024 compressions: divide its time by 1024.

use std::hint::black_box;

use criterion::{
    BenchmarkGroup, Criterion, criterion_group, criterion_main, measurement::WallTime,
};
use softgrip_law::{Backing, ContactLaw, ContactParams, Counterpart, Level, Material};

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

/// Times one pass of `eval` over `inputs`, summing its results (so nothing is optimised away).
fn bench_pass(
    group: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    inputs: &[f64],
    eval: impl Fn(f64) -> f64,
) {
    group.bench_function(name, |b| {
        b.iter(|| inputs.iter().map(|&v| eval(black_box(v))).sum::<f64>())
    });
}

fn bench_levels(c: &mut Criterion) {
    let material = Material::try_new(3.0e6, 0.49).expect("valid material");
    let params = ContactParams::try_new(material, 0.01).expect("valid params");
    let law = |level| ContactLaw::try_new(params, level).expect("level builds");

    // The arithmetic floor of the explicit levels: one square root (x^(3/2)) and one division
    // (chi_L = 1/(1 - k x)) per evaluation, on the same inputs, with nothing else. On a core
    // whose divider is not pipelined this, not the law, sets the cost of fit and incompressible.
    let mut floor = c.benchmark_group("floor");
    let xs: Vec<f64> = deltas(&law(Level::fit()))
        .iter()
        .map(|d| d / 0.01)
        .collect();
    bench_pass(&mut floor, "sqrt", &xs, f64::sqrt);
    bench_pass(&mut floor, "sqrt+div", &xs, |x| {
        x.sqrt() + 1.0 / (1.0 - 0.5 * x)
    });
    floor.finish();

    let mut force = c.benchmark_group("force_stiffness");
    for level in Level::ALL {
        let law = law(level);
        bench_pass(&mut force, level.name(), &deltas(&law), |d| {
            let r = law.response(d);
            r.force + r.stiffness
        });
    }
    // Auto picks its level by x. A contact's x changes little from one step to the next, so
    // also time it on the same compressions in ascending order (predictable picks).
    let auto = law(Level::auto());
    let mut ascending = deltas(&auto);
    ascending.sort_by(f64::total_cmp);
    bench_pass(&mut force, "auto-ascending-x", &ascending, |d| {
        let r = auto.response(d);
        r.force + r.stiffness
    });
    // The backed constructions' calibrated levels (target: at most 2x fit's cost).
    for (name, backing) in [
        ("calibrated-flat", Backing::Flat),
        ("calibrated-core", Backing::Core { thickness: 0.004 }),
        // t/R 0.12 (between the shell table's t/R nodes: all eight weighted): the thin-skin form
        // (session 28), tabulated like the rest.
        ("calibrated-core-thin", Backing::Core { thickness: 0.0012 }),
    ] {
        let backed = params.with_backing(backing).expect("valid backing");
        let law = ContactLaw::try_new(backed, Level::Calibrated).expect("level builds");
        bench_pass(&mut force, name, &deltas(&law), |d| {
            let r = law.response(d);
            r.force + r.stiffness
        });
    }
    // On a counterpart (target: at most 2x calibrated's cost on a plane): a ball of the
    // fingertip's size, a cylinder of 3 R, an edge.
    let calibrated = law(Level::Calibrated);
    let counterparts = [
        (
            "calibrated-ball",
            Counterpart::try_ball(0.01).expect("valid ball"),
        ),
        (
            "calibrated-cylinder",
            Counterpart::try_cylinder(0.03).expect("valid cylinder"),
        ),
        ("calibrated-edge", Counterpart::EDGE),
    ];
    for (name, cp) in counterparts {
        let on = calibrated.with_counterpart(cp).expect("binds");
        bench_pass(&mut force, name, &deltas(&on), |d| {
            let r = on.response(d);
            r.force + r.stiffness
        });
    }
    let flat_ball = ContactLaw::try_new(
        params.with_backing(Backing::Flat).expect("valid backing"),
        Level::Calibrated,
    )
    .and_then(|l| l.with_counterpart(Counterpart::try_ball(0.01)?))
    .expect("binds");
    bench_pass(
        &mut force,
        "calibrated-flat-ball",
        &deltas(&flat_ball),
        |d| {
            let r = flat_ball.response(d);
            r.force + r.stiffness
        },
    );
    force.finish();

    // Binding the law to a counterpart (what the plugin does per contact when the counterpart
    // changes): a ball (a circle), a cylinder (Hertz's ellipse solved), an edge.
    let mut bind = c.benchmark_group("with_counterpart");
    for (name, cp) in counterparts {
        bind.bench_function(name, |b| {
            b.iter(|| {
                calibrated
                    .with_counterpart(black_box(cp))
                    .expect("binds")
                    .x_max()
            })
        });
    }
    // A skin on a core on a ball builds its own table when bound (`core_map`).
    let core = ContactLaw::try_new(
        params
            .with_backing(Backing::Core { thickness: 0.004 })
            .expect("valid backing"),
        Level::Calibrated,
    )
    .expect("level builds");
    let ball = Counterpart::try_ball(0.01).expect("valid ball");
    bind.bench_function("calibrated-core-ball", |b| {
        b.iter(|| {
            core.with_counterpart(black_box(ball))
                .expect("binds")
                .x_max()
        })
    });
    // The same for a thin skin (t/R 0.12), whose table evaluates the shell's (session 28).
    let thin = ContactLaw::try_new(
        params
            .with_backing(Backing::Core { thickness: 0.0012 })
            .expect("valid backing"),
        Level::Calibrated,
    )
    .expect("level builds");
    bind.bench_function("calibrated-core-thin-ball", |b| {
        b.iter(|| {
            thin.with_counterpart(black_box(ball))
                .expect("binds")
                .x_max()
        })
    });
    // A flat pad on a ball builds its plane table with the cap scaled (`cap_map`), and its hot
    // path is then the plane flat pad's.
    let flat = ContactLaw::try_new(
        params.with_backing(Backing::Flat).expect("valid backing"),
        Level::Calibrated,
    )
    .expect("level builds");
    bind.bench_function("calibrated-flat-ball", |b| {
        b.iter(|| {
            flat.with_counterpart(black_box(ball))
                .expect("binds")
                .x_max()
        })
    });
    bind.finish();

    let mut patch = c.benchmark_group("with_radius_pressure");
    for level in Level::ALL {
        let law = law(level);
        bench_pass(&mut patch, level.name(), &deltas(&law), |d| {
            let r = law.response(d);
            let p = law.patch(d);
            r.force + r.stiffness + p.radius + p.peak_pressure
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
