//! `softgrip curve`: one level of the law over a grid of compression ratios, as CSV.

use std::io::{self, BufWriter, Write};

use anyhow::{Context, Result};
use softgrip_law::{ContactLaw, ContactParams};

use crate::level_arg::LevelArgs;
use crate::xrange::XRange;

/// The CSV header, one column per normalised quantity.
pub const HEADER: &str = "x,force_norm,stiffness_norm,energy_norm,radius_norm,p_mean_norm,valid";

/// Arguments of `softgrip curve`.
#[derive(Debug, clap::Args)]
#[command(allow_negative_numbers = true)]
pub struct CurveArgs {
    #[command(flatten)]
    level: LevelArgs,
    /// Poisson ratio nu [-], in (-1, 0.5]; below 0.5 for neo-hookean and neo-hookean-exact.
    #[arg(long)]
    nu: f64,
    /// Compression ratios x = delta/R [-] as START:STOP:STEP (STOP included when on the grid).
    #[arg(long, value_name = "START:STOP:STEP", allow_hyphen_values = true)]
    x: XRange,
}

/// Prints the curve to stdout. Rows past the level's validity range show the law's documented
/// extension (tangent continuation) with `valid = 0`.
pub fn run(args: &CurveArgs) -> Result<()> {
    let level = args.level.level()?;
    // E* = 1 Pa and R = 1 m: the law's outputs are then the normalised quantities, delta = x.
    let params = ContactParams::try_from_parts(1.0, 1.0, args.nu).context("invalid `--nu`")?;
    let law = ContactLaw::try_new(params, level)
        .with_context(|| format!("cannot build level `{level}` at nu = {}", args.nu))?;
    match write_csv(&law, &args.x, io::stdout().lock()) {
        // A closed pipe (`| head`) ends the output; it is not an error.
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
        other => other.context("cannot write to stdout"),
    }
}

fn write_csv(law: &ContactLaw, xs: &XRange, out: impl Write) -> io::Result<()> {
    let mut out = BufWriter::new(out);
    writeln!(out, "{HEADER}")?;
    for x in xs.iter() {
        let r = law.response(x);
        let patch = law.patch(x);
        // `{:e}` is the shortest representation that parses back to the same double.
        writeln!(
            out,
            "{x},{:e},{:e},{:e},{:e},{:e},{}",
            r.force,
            r.stiffness,
            law.energy(x),
            patch.radius,
            patch.mean_pressure,
            u8::from(x <= law.x_max()),
        )?;
    }
    out.flush()
}
