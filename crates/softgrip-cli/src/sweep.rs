//! `softgrip sweep SWEEP.toml [--out results.parquet|.csv] [--shard i/n] [--threads N]
//! [--trial I]`: a sweep's trials on all local cores with a progress bar (softgrip-sweep,
//! format in crates/softgrip-sweep/SWEEPS.md), the results as Parquet or CSV (CSV on stdout
//! without `--out`), and a one-line summary on stderr.

use std::path::PathBuf;
use std::time::Instant;

use anyhow::{Result, bail};
use indicatif::{ProgressBar, ProgressStyle};
use softgrip_sweep::{RunOptions, Shard, Sweep};

use crate::files::check_output;
use crate::out;

/// Arguments of `softgrip sweep`.
#[derive(Debug, Clone, clap::Args)]
pub struct SweepArgs {
    /// Sweep file (TOML, see crates/softgrip-sweep/SWEEPS.md).
    pub sweep: PathBuf,
    /// Write the results table: `.parquet` or `.csv` by the extension. Default: CSV on stdout.
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Overwrite `--out` if it exists.
    #[arg(long)]
    pub force: bool,
    /// Run only slice i of n of the trials (from 0: `0/4` .. `3/4`); the slices' results
    /// concatenate, in slice order, to the whole sweep's.
    #[arg(long, value_name = "i/n")]
    pub shard: Option<Shard>,
    /// Worker threads (default: one per core).
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

/// Runs the command.
pub fn run(args: &SweepArgs) -> Result<()> {
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
    let sweep = Sweep::from_path(&args.sweep)?;
    if let Some(out) = &args.out {
        check_output(out, &[args.sweep.as_path()], args.force)?;
    }
    let start = Instant::now();
    let table = match args.trial {
        Some(i) => {
            let mut t = sweep.table();
            t.rows.push(sweep.run_trial(i)?);
            t
        }
        None => {
            let shard = args.shard.unwrap_or_default();
            let bar = ProgressBar::new(shard.range(sweep.trials()).count() as u64);
            bar.set_style(
                ProgressStyle::with_template(
                    "{bar:40} {pos}/{len} trials, {per_sec}, {elapsed_precise} (eta {eta})",
                )
                .expect("invariant: the template is valid"),
            );
            let table = sweep.run(
                &RunOptions {
                    threads: args.threads,
                    shard,
                },
                &|done, _| bar.set_position(done),
            )?;
            bar.finish_and_clear();
            table
        }
    };
    let wall = start.elapsed().as_secs_f64();
    match (&args.out, format) {
        (None, _) => out::text(&table.to_csv()),
        (Some(path), Format::Csv) => table.write_csv(path)?,
        (Some(path), Format::Parquet) => table.write_parquet(path)?,
    }
    let n = table.rows.len();
    eprintln!(
        "sweep {}: {n} of {} trials, {} held, {} errors; wall time {wall:.2} s ({:.2} trials/s){}",
        sweep.origin(),
        sweep.trials(),
        table.held_count(),
        table.error_count(),
        n as f64 / wall.max(1e-9),
        args.out
            .as_ref()
            .map(|p| format!("; results in {}", p.display()))
            .unwrap_or_default()
    );
    Ok(())
}
