//! Where a never-asleep resting step's time goes: N fingertips resting on a fixed ground
//! (`softgrip_bench::overhead::OverheadScene`, the scene of `peers_softgrip resting`), the
//! plugin's profiling counters on (`SoftContacts::set_profiling`), per step in µs of the
//! thread's CPU time, with rapier's own contacts for the same balls beside it.
//!
//! ```text
//! cargo run --release -p softgrip-bench --example resting_stages [soft] [N ...]
//! ```
//!
//! Default N: 100 and 1000. With `soft`, rapier's own contacts are not run (for a profiler:
//! `perf record --call-graph dwarf` then sees the softgrip steps alone). The stages are the plugin's counters (`SoftCounters`): rapier's
//! pipeline (`pipeline_time`, the whole `PhysicsPipeline::step`), detection, rows (body table
//! and rows), supports (rapier's rigid contacts gathered for the coupled solve), law (the
//! law's response and the contacts' memory), solve (the impulse solve), apply (impulses on the
//! bodies, checked), readout (the substeps' sums and the step's contacts), and the rest of
//! `try_step` (state checks, kinematic paths, the links' refresh). rapier's pipeline is split
//! further with `perf` (crate README, "Where a resting step's time goes"). The counters read
//! the wall clock; each is scaled by its round's thread CPU time over its wall time (on a
//! loaded machine the wall time carries other processes' turns on the core).

use std::time::Duration;

use softgrip_bench::overhead::OverheadScene;
use softgrip_rapier::SoftCounters;

fn main() {
    let soft_only = std::env::args().any(|a| a == "soft");
    let ns: Vec<usize> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let ns = if ns.is_empty() { vec![100, 1000] } else { ns };
    println!(
        "| N | steps | thread CPU | rapier pipeline | detection | rows | supports | law | solve | apply | readout | rest of try_step | outside try_step | rapier's own contacts |"
    );
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for n in ns {
        // About a second of CPU per round at either N (a round of 50 ms caught too few of
        // the scheduler's turns for the per-round scaling of the counters below to average out).
        let steps = (200_000 / n).clamp(60, 5000);
        let mut soft = OverheadScene::new(n, true);
        soft.world.soft.set_profiling(true);
        let mut rigid = (!soft_only).then(|| OverheadScene::new(n, false));
        // Best of 3 rounds (thread CPU), for both.
        let (mut best, mut best_rigid) = (None::<(f64, SoftCounters)>, f64::MAX);
        for _ in 0..3 {
            let before = *soft.world.soft.counters();
            let mut wall = Duration::ZERO;
            let cpu = cpu_seconds(|| {
                wall = soft.measure(steps).0;
            });
            // The counters read the wall clock: on a shared machine a round's wall time
            // carries the time other processes held the core, spread over its stages alike.
            let d = scaled(
                &diff(soft.world.soft.counters(), &before),
                cpu / wall.as_secs_f64(),
            );
            if best.as_ref().is_none_or(|b| cpu < b.0) {
                best = Some((cpu, d));
            }
            if let Some(rigid) = &mut rigid {
                best_rigid = best_rigid.min(cpu_seconds(|| {
                    rigid.measure(steps);
                }));
            }
        }
        let (cpu, c) = best.expect("three rounds");
        let per = |d: Duration| d.as_secs_f64() * 1e6 / steps as f64;
        let parts = [
            c.pipeline_time,
            c.detect_time,
            c.rows_time,
            c.supports_time,
            c.law_time,
            c.soft_solve_time,
            c.apply_time,
            c.readout_time,
        ];
        let named: Duration = parts.iter().sum();
        let rest = c.step_time.saturating_sub(named);
        let outside = cpu * 1e6 / steps as f64 - per(c.step_time);
        let cells: Vec<String> = parts.iter().map(|&d| format!("{:.2}", per(d))).collect();
        println!(
            "| {n} | {steps} | {:.2} | {} | {:.2} | {outside:.2} | {} |",
            cpu * 1e6 / steps as f64,
            cells.join(" | "),
            per(rest),
            if best_rigid < f64::MAX {
                format!("{:.2}", best_rigid * 1e6 / steps as f64)
            } else {
                "-".into()
            }
        );
    }
}

/// The thread CPU time \[s\] `f` took (`/proc/thread-self/schedstat`; wall time where that is
/// not available).
fn cpu_seconds(f: impl FnOnce()) -> f64 {
    let read = || {
        let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
        s.split_whitespace()
            .next()?
            .parse::<u64>()
            .ok()
            .map(|ns| ns as f64 * 1e-9)
    };
    let t = std::time::Instant::now();
    let a = read();
    f();
    match (a, read()) {
        (Some(a), Some(b)) => b - a,
        _ => t.elapsed().as_secs_f64(),
    }
}

/// The time counters of `c` times `k` (at most 1: a round's CPU time over its wall time).
fn scaled(c: &SoftCounters, k: f64) -> SoftCounters {
    let k = k.min(1.0);
    let s = |d: Duration| d.mul_f64(k);
    SoftCounters {
        pipeline_time: s(c.pipeline_time),
        detect_time: s(c.detect_time),
        rows_time: s(c.rows_time),
        supports_time: s(c.supports_time),
        law_time: s(c.law_time),
        soft_solve_time: s(c.soft_solve_time),
        apply_time: s(c.apply_time),
        readout_time: s(c.readout_time),
        step_time: s(c.step_time),
        ..*c
    }
}

/// The time counters of `c` accumulated since `before`.
fn diff(c: &SoftCounters, before: &SoftCounters) -> SoftCounters {
    SoftCounters {
        pipeline_time: c.pipeline_time - before.pipeline_time,
        detect_time: c.detect_time - before.detect_time,
        rows_time: c.rows_time - before.rows_time,
        supports_time: c.supports_time - before.supports_time,
        law_time: c.law_time - before.law_time,
        soft_solve_time: c.soft_solve_time - before.soft_solve_time,
        apply_time: c.apply_time - before.apply_time,
        readout_time: c.readout_time - before.readout_time,
        step_time: c.step_time - before.step_time,
        ..*c
    }
}
