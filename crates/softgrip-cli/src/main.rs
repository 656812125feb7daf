#![doc = include_str!("../README.md")]

mod accuracy;
mod bench_law;
mod cli;
mod curve;
mod fe;
mod level_arg;
mod plot;
mod timing;
mod xrange;

use std::process::ExitCode;

use cli::Command;

fn main() -> ExitCode {
    let result = match cli::parse().command {
        Command::Curve(args) => curve::run(&args),
        Command::BenchLaw(args) => bench_law::run(&args),
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
