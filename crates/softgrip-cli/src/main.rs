#![doc = include_str!("../README.md")]

mod accuracy;
mod bench_law;
mod cli;
mod curve;
mod fe;
mod level_arg;
mod plot;
mod recording;
mod run;
mod timing;
mod xrange;

use std::process::ExitCode;

use cli::Command;

fn main() -> ExitCode {
    let result = match cli::parse().command {
        Command::Curve(args) => curve::run(&args),
        Command::BenchLaw(args) => bench_law::run(&args),
        Command::Run(args) => match run::run(&args) {
            Ok(run::RunEnd::Interrupted) => return ExitCode::from(run::INTERRUPTED_EXIT_CODE),
            other => other.map(|_| ()),
        },
        Command::Inspect(args) => recording::inspect(&args),
        Command::Export(args) => recording::export(&args),
        Command::Plot(args) => recording::plot(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // `{:#}` joins the context chain on one line.
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}
