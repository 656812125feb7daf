#![doc = include_str!("../README.md")]

mod accuracy;
mod bench_law;
mod cli;
mod counterpart_arg;
mod curve;
mod fe;
mod files;
mod level_arg;
mod out;
mod plot;
mod recording;
mod report;
mod run;
mod signals;
mod sweep;
mod timing;
mod xrange;

use std::process::ExitCode;

use cli::Command;

fn main() -> ExitCode {
    let result = match cli::parse().command {
        Command::Curve(args) => curve::run(&args),
        Command::BenchLaw(args) => bench_law::run(&args),
        Command::Run(args) => match run::run(&args) {
            Ok(run::RunEnd::Interrupted(sig)) => {
                out::flush();
                return ExitCode::from(signals::exit_code(sig));
            }
            other => other.map(|_| ()),
        },
        Command::Sweep(args) => sweep::run(&args),
        Command::Inspect(args) => recording::inspect(&args),
        Command::Export(args) => recording::export(&args),
        Command::Plot(args) => recording::plot(&args),
        Command::Recover(args) => recording::recover(&args),
    };
    out::flush();
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", report::one_line(&e));
            ExitCode::FAILURE
        }
    }
}
