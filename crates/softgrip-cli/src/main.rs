#![doc = include_str!("../README.md")]

mod accuracy;
mod bench_law;
mod cli;
mod counterpart_arg;
mod curve;
mod fe;
mod files;
mod gripper_action;
mod joint_commands;
mod level_arg;
mod out;
mod plot;
mod recording;
mod report;
mod run;
mod signals;
mod sweep;
mod timing;
mod worker;
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
        Command::Sweep(args) => interrupted(sweep::run(&args)),
        Command::Inspect(args) => recording::inspect(&args),
        Command::Export(args) => interrupted(recording::export(&args)),
        Command::Plot(args) => recording::plot(&args),
        Command::Recover(args) => recording::recover(&args),
    };
    out::flush();
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => match e.downcast_ref::<Interrupted>() {
            Some(Interrupted(sig)) => ExitCode::from(signals::exit_code(*sig)),
            None => {
                eprintln!("error: {}", report::one_line(&e));
                ExitCode::FAILURE
            }
        },
    }
}

/// A command stopped by a signal (its message is already printed): exit 128 + signal.
#[derive(Debug)]
struct Interrupted(i32);

impl std::fmt::Display for Interrupted {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "interrupted by {}", signals::name(self.0))
    }
}

impl std::error::Error for Interrupted {}

/// `Ok(Some(signal))` of a command a signal stopped, as the [`Interrupted`] error.
fn interrupted(result: anyhow::Result<Option<i32>>) -> anyhow::Result<()> {
    match result? {
        Some(sig) => Err(Interrupted(sig).into()),
        None => Ok(()),
    }
}
