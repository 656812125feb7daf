//! `softgrip sweep SWEEP.toml [--out results.parquet|.csv] [--shard i/n] [--threads N]
//! [--trial I]`: a sweep's trials on all local cores with a progress bar (softgrip-sweep,
//! format in crates/softgrip-sweep/SWEEPS.md), the results as Parquet or CSV (CSV on stdout
//! without `--out`), and a one-line summary on stderr.
//!
//! SIGINT, SIGTERM and SIGHUP stop it as they stop `run`: no trial starts after the signal,
//! the running ones finish, every finished row is written, and the exit code is 128 + the
//! signal. `--out` is written whole at the end (a temporary file beside it, linked into place):
//! never over an input of the sweep (the sweep file, the base scene, its meshes and curves),
//! and never over a file that appeared while the trials ran (unless `--force`).

use std::path::PathBuf;
use std::time::Instant;

use anyhow::{Result, bail};
use indicatif::{ProgressBar, ProgressStyle};
use softgrip_sweep::{ResultsTable, RunOptions, Shard, Sweep, check_threads};

use crate::files::Output;
use crate::out;
use crate::signals::Stop;

/// Arguments of `softgrip sweep`.
#[derive(Debug, Clone, clap::Args)]
pub struct SweepArgs {
    /// Sweep file (TOML, see crates/softgrip-sweep/SWEEPS.md).
    pub sweep: PathBuf,
    /// Write the results table: `.parquet` or `.csv` by the extension. Default: CSV on stdout.
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Overwrite `--out` if it exists (never an input of the sweep).
    #[arg(long)]
    pub force: bool,
    /// Run only slice i of n of the trials (from 0: `0/4` .. `3/4`); the slices' results
    /// concatenate, in slice order, to the whole sweep's.
    #[arg(long, value_name = "i/n")]
    pub shard: Option<Shard>,
    /// Worker threads: 0 = one per core (the default), at most 4 per core.
    #[arg(long, value_name = "N", default_value_t = 0)]
    pub threads: usize,
    /// Run only trial I (its row; what a Ray task or an array job of one trial calls).
    #[arg(long, value_name = "I", conflicts_with = "shard")]
    pub trial: Option<u64>,
}

/// The results file's format, by `--out`'s extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Format {
    Csv,
    Parquet,
}

/// Runs the command; `Some(signal)` when a signal stopped it (the finished rows are written).
pub fn run(args: &SweepArgs) -> Result<Option<i32>> {
    // Before anything is read or written: a signal from now on stops the sweep cleanly.
    let stop = Stop::install();
    let format = match &args.out {
        None => Format::Csv,
        Some(out) => match out.extension().and_then(|e| e.to_str()) {
            Some("csv") => Format::Csv,
            Some("parquet") => Format::Parquet,
            _ => bail!(
                "{}: `--out` must end in .parquet or .csv (the format is taken from it)",
                out.display()
            ),
        },
    };
    check_threads(args.threads)?;
    let sweep = Sweep::from_path(&args.sweep)?;
    // Checked (and its temporary file created) before the trials: a wrong `--out` costs no
    // trial; put in place after them.
    let mut output = match &args.out {
        Some(out) => Some(Output::create(out, sweep.input_files(), args.force)?),
        None => None,
    };
    let start = Instant::now();
    let table = match args.trial {
        Some(i) => {
            let mut t = sweep.table();
            t.rows.push(sweep.run_trial(i)?);
            t
        }
        None => run_trials(&sweep, args, &stop)?,
    };
    let wall = start.elapsed().as_secs_f64();
    let written = match output.take() {
        None => {
            out::text(&table.to_csv());
            None
        }
        Some(mut o) => {
            let bytes = match format {
                Format::Csv => table.to_csv().into_bytes(),
                Format::Parquet => table
                    .to_parquet()
                    .map_err(|e| anyhow::anyhow!("{}: {e}", o.path().display()))?,
            };
            o.write_all(&bytes)?;
            Some(o.commit_or_keep(true)?)
        }
    };
    let signal = stop.received();
    summary(&sweep, &table, wall, written, signal);
    Ok(signal)
}

/// The trials of the shard on the worker threads with a progress bar, until a signal.
fn run_trials(sweep: &Sweep, args: &SweepArgs, stop: &Stop) -> Result<ResultsTable> {
    let shard = args.shard.unwrap_or_default();
    let bar = ProgressBar::new(shard.range(sweep.trials()).count() as u64);
    bar.set_style(
        ProgressStyle::with_template(
            "{bar:40} {pos}/{len} trials, {per_sec}, {elapsed_precise} (eta {eta})",
        )
        .expect("invariant: the template is valid"),
    );
    let table = sweep.run_until(
        &RunOptions {
            threads: args.threads,
            shard,
        },
        &|done, _| bar.set_position(done),
        &|| stop.received().is_some(),
    )?;
    bar.finish_and_clear();
    Ok(table)
}

/// The one-line summary on stderr.
fn summary(
    sweep: &Sweep,
    table: &ResultsTable,
    wall: f64,
    written: Option<PathBuf>,
    signal: Option<i32>,
) {
    let n = table.rows.len();
    let stopped = signal
        .map(|s| {
            format!(
                "; stopped by {} (the running trials finished, no other started)",
                crate::signals::name(s)
            )
        })
        .unwrap_or_default();
    eprintln!(
        "sweep {}: {n} of {} trials, {} held, {} errors; wall time {wall:.2} s ({:.2} trials/s){}{stopped}",
        sweep.origin(),
        sweep.trials(),
        table.held_count(),
        table.error_count(),
        n as f64 / wall.max(1e-9),
        written
            .map(|p| format!("; results in {}", p.display()))
            .unwrap_or_default()
    );
}
