//! The command line: one binary, one subcommand per task.

use clap::error::ErrorKind;
use clap::{Parser, Subcommand};

use crate::bench_law::BenchLawArgs;
use crate::curve::CurveArgs;
use crate::recording::{ExportArgs, InspectArgs, PlotArgs, RecoverArgs};
use crate::run::RunArgs;
use crate::sweep::SweepArgs;

/// Soft-fingertip contact: the law's curves, its speed-vs-error table and figures.
#[derive(Debug, Parser)]
#[command(name = "softgrip", version, about)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Print one level of the law over a range of compression ratios, as CSV.
    Curve(CurveArgs),
    /// Print the speed-vs-error table of every level and draw its figures.
    BenchLaw(BenchLawArgs),
    /// Run a scene file (or the embedded default grasp), print a per-fingertip summary, and
    /// record it to MCAP with `--out`.
    Run(RunArgs),
    /// Run a sweep file's trials (a base scene with fields varied) on all local cores and
    /// write the results table (trial, the varied fields, held, slips, peaks, error) as
    /// Parquet or CSV.
    Sweep(SweepArgs),
    /// Summarise a recording: topics, duration, per-fingertip peaks, slip events, excursions.
    Inspect(InspectArgs),
    /// Write a recording's topics as CSV files (contacts, wrenches, poses, clock).
    Export(ExportArgs),
    /// Draw a recording: force vs x with the law's curves, force and contact radius vs time.
    Plot(PlotArgs),
    /// Rewrite a killed or damaged recording as a finished, indexed MCAP file.
    Recover(RecoverArgs),
}

/// Parses the command line. Help and version are printed as clap prints them; a usage error
/// is printed as one line on stderr (clap's first paragraph, joined) with exit code 2.
pub fn parse() -> Cli {
    match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => match e.kind() {
            ErrorKind::DisplayHelp
            | ErrorKind::DisplayVersion
            | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => e.exit(),
            _ => {
                eprintln!("{}", one_line(&e.render().to_string()));
                std::process::exit(e.exit_code());
            }
        },
    }
}

/// The first paragraph of a clap message (up to the first blank line), on one line.
fn one_line(message: &str) -> String {
    message
        .lines()
        .take_while(|l| !l.trim().is_empty())
        .map(str::trim)
        .collect::<Vec<_>>()
        .join(" ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_line_keeps_the_first_paragraph() {
        let m =
            "error: the following required arguments were not provided:\n  --x <X>\n\nUsage: x\n";
        assert_eq!(
            one_line(m),
            "error: the following required arguments were not provided: --x <X>"
        );
    }
}
