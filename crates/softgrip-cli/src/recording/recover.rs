//! `softgrip recover IN.mcap OUT.mcap`: a killed or damaged recording rewritten as a finished,
//! indexed MCAP file that any reader opens (softgrip-record's `recover`). OUT is written whole
//! (a temporary file beside it, put in place at the end); nothing is written, and the exit
//! code is 1, when no message could be kept.

use std::path::PathBuf;

use anyhow::{Result, anyhow};
use softgrip_record::{self, Error};

use crate::files::Output;
use crate::out::outln;

/// Arguments of `softgrip recover`.
#[derive(Debug, Clone, clap::Args)]
pub struct RecoverArgs {
    /// The killed or damaged recording (MCAP).
    pub input: PathBuf,
    /// The finished recording to write (never the input).
    pub output: PathBuf,
    /// Overwrite OUT.mcap if it exists.
    #[arg(long)]
    pub force: bool,
}

/// Runs the command: prints what was kept and each damaged part skipped.
pub fn recover(args: &RecoverArgs) -> Result<()> {
    let mut out = Output::create(&args.output, std::slice::from_ref(&args.input), args.force)?;
    let r =
        softgrip_record::recover_into(&args.input, out.file(), &args.output).map_err(
            |e| match e {
                // Errors of a file name it (the input's or the output's, and the OS error).
                e @ (Error::Io { .. } | Error::Write { .. }) => anyhow!(e),
                e => anyhow!("{}: {e}", args.input.display()),
            },
        )?;
    out.commit()?;
    outln!(
        "recovered {} messages ({} from an unfinished chunk), {} complete chunks, {} of {} bytes read, to {}",
        r.messages,
        r.from_unfinished_chunk,
        r.chunks,
        r.bytes_read,
        r.file_len,
        args.output.display()
    );
    if r.unknown_records > 0 {
        outln!(
            "  {} records of unknown opcodes (extension records) skipped by their length",
            r.unknown_records
        );
    }
    for s in &r.skipped {
        outln!("  {s}");
    }
    Ok(())
}
