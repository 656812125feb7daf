//! Sweep throughput: trials per second of `sweeps/throughput.toml` (the default grasp over a
//! grid of fingertip stiffnesses and squeeze depths) on 1 and 2 threads, as a table.
//!
//! ```text
//! cargo run --release -p softgrip-sweep --example sweep_throughput [SWEEP.toml] [THREADS...]
//! ```
//!
//! Speed is measured here, never asserted in a test. Each thread count runs the whole sweep
//! once after a warm-up trial; the rows must be identical across thread counts (checked).
//! `cores used` is the process's CPU time over the wall time (Linux `/proc/self/stat`): on a
//! shared machine it shows whether 2 threads got 2 cores.

use std::path::PathBuf;
use std::time::Instant;

use anyhow::{Context, Result, bail};
use softgrip_sweep::{RunOptions, Shard, Sweep};

fn main() -> Result<()> {
    let mut args = std::env::args().skip(1);
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let path = args
        .next()
        .map(PathBuf::from)
        .unwrap_or_else(|| root.join("sweeps/throughput.toml"));
    let threads: Vec<usize> = {
        let t: Vec<usize> = args.map(|a| a.parse()).collect::<Result<_, _>>()?;
        if t.is_empty() { vec![1, 2] } else { t }
    };
    let sweep = Sweep::from_path(&path).with_context(|| format!("{}", path.display()))?;
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    println!(
        "sweep {}: {} trials of {}; {cores} cores on this machine",
        path.display(),
        sweep.trials(),
        sweep.fields().join(" x ")
    );
    sweep.run_trial(0)?; // warm-up: page in the code, the law tables
    println!(
        "| threads | trials | wall time [s] | trials/s | speed-up | cores used | held | errors |"
    );
    println!("|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut first: Option<(f64, Vec<_>)> = None;
    for &t in &threads {
        let start = Instant::now();
        let cpu0 = cpu_seconds();
        let table = sweep.run(
            &RunOptions {
                threads: t,
                shard: Shard::WHOLE,
            },
            &|_, _| {},
        )?;
        let wall = start.elapsed().as_secs_f64();
        let cores = match (cpu0, cpu_seconds()) {
            (Some(a), Some(b)) => format!("{:.2}", (b - a) / wall),
            _ => "n/a".to_string(),
        };
        let rate = table.rows.len() as f64 / wall;
        let outcomes: Vec<_> = table.rows.iter().map(|r| r.outcome.clone()).collect();
        let base = first.get_or_insert((rate, outcomes.clone()));
        if base.1 != outcomes {
            bail!("{t} threads gave other rows than {} threads", threads[0]);
        }
        println!(
            "| {t} | {} | {wall:.2} | {rate:.2} | {:.2} | {cores} | {} | {} |",
            table.rows.len(),
            rate / base.0,
            table.held_count(),
            table.error_count()
        );
    }
    Ok(())
}

/// User + system CPU time of this process \[s\] (Linux: `/proc/self/stat` fields 14 and 15,
/// in clock ticks of 1/100 s); `None` elsewhere.
fn cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // The command name (field 2) is in parentheses and may hold spaces: count after it.
    let rest = stat.rsplit_once(')')?.1;
    let fields: Vec<&str> = rest.split_whitespace().collect();
    // `rest` starts at field 3 (state): utime is field 14, stime field 15.
    let ticks = |i: usize| fields.get(i - 3)?.parse::<f64>().ok();
    Some((ticks(14)? + ticks(15)?) / 100.0)
}
