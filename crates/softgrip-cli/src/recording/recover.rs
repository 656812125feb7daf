//! `softgrip recover IN.mcap OUT.mcap`: a killed or damaged recording rewritten as a finished,
//! indexed MCAP file that any reader opens (softgrip-record's `recover`).

use std::path::PathBuf;

use anyhow::{Result, anyhow};
use softgrip_ecs::softgrip_record;

use crate::files::check_output;
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
    check_output(&args.output, &[&args.input], args.force)?;
    let r = softgrip_record::recover(&args.input, &args.output)
        .map_err(|e| anyhow!("{}: {e}", args.input.display()))?;
    outln!(
        "recovered {} messages ({} from an unfinished chunk), {} complete chunks, {} of {} bytes read, to {}",
        r.messages,
        r.from_unfinished_chunk,
        r.chunks,
        r.bytes_read,
        r.file_len,
        args.output.display()
    );
    for s in &r.skipped {
        outln!("  {s}");
    }
    Ok(())
}
