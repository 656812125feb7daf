//! Step time of N resting fingertips with softgrip and with rapier's own contacts
//! (`cargo bench -p softgrip-bench`). The ratio is the plugin's overhead.

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use softgrip_bench::overhead::OverheadScene;

fn bench_overhead(c: &mut Criterion) {
    let mut group = c.benchmark_group("overhead_step");
    for n in [1usize, 10, 100, 1000] {
        for (name, soft) in [("rapier", false), ("softgrip", true)] {
            let mut scene = OverheadScene::new(n, soft);
            group.bench_function(BenchmarkId::new(name, n), |b| b.iter(|| scene.step()));
        }
    }
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .warm_up_time(std::time::Duration::from_millis(500))
        .measurement_time(std::time::Duration::from_secs(2))
        .sample_size(20);
    targets = bench_overhead
}
criterion_main!(benches);
