//! `softgrip curve`: one level of the law over a grid of compression ratios, as CSV; or its
//! pressure profile at one compression ratio (`--profile X`); on a plane or, with
//! `--counterpart`, on a ball, a cylinder or an edge.

use std::io::{self, BufWriter, Write};

use anyhow::{Context, Result, bail};
use softgrip_law::{Backing, ContactLaw, ContactParams, Level, Shortest};

use crate::counterpart_arg::CounterpartArg;
use crate::level_arg::LevelArgs;
use crate::xrange::{MAX_POINTS, XRange};

/// The CSV header, one column per normalised quantity.
pub const HEADER: &str = "x,force_norm,stiffness_norm,energy_norm,radius_norm,p_mean_norm,valid";

/// The extra column on a counterpart other than a plane: the patch's second semi-axis over R
/// (`radius_norm` is then its first, along the counterpart's first principal direction).
pub const HEADER_SECOND_AXIS: &str = ",radius2_norm";

/// The CSV header of `--profile`: radius over the outer radius R, pressure over E*.
pub const PROFILE_HEADER: &str = "r_norm,p_norm";

/// Rows of a `--profile`: r/R from 0 to a/R in equal steps.
pub const PROFILE_ROWS: usize = 50;

/// Most points of a `--level neo-hookean-exact` curve: it solves the compressible theory at
/// every point (5001 points took 0.48 s in a debug build on the shared 2-core machine: about
/// 0.1 ms each), so its million allowed points ran for over a minute; 20 000 take about 2 s. `neo-hookean` tabulates the same
/// theory (within its documented tolerance) and takes the full [`MAX_POINTS`].
pub const MAX_POINTS_EXACT: usize = 20_000;

/// The most points `level` evaluates in one call.
pub fn max_points(level: Level) -> usize {
    match level {
        Level::NeoHookeanExact => MAX_POINTS_EXACT,
        _ => MAX_POINTS,
    }
}

/// Arguments of `softgrip curve`.
#[derive(Debug, clap::Args)]
#[command(allow_negative_numbers = true)]
pub struct CurveArgs {
    #[command(flatten)]
    level: LevelArgs,
    /// Poisson ratio nu [-], in (-1, 0.5]; below 0.5 for neo-hookean and neo-hookean-exact.
    #[arg(long)]
    nu: f64,
    /// Compression ratios x = delta/R [-] as START:STOP:STEP (STOP included when on the grid);
    /// R is the outer radius for every backing. Not with `--profile`.
    #[arg(
        long,
        value_name = "START:STOP:STEP",
        allow_hyphen_values = true,
        required_unless_present = "profile",
        conflicts_with = "profile"
    )]
    x: Option<XRange>,
    /// How the fingertip is built (softgrip_law::BACKINGS; `core` needs `--thickness`).
    #[arg(long, value_name = "NAME", default_value = "free", value_parser = backing_names())]
    backing: String,
    /// Skin thickness over outer radius t/R [-] of `--backing core`, in (0, 1); only there.
    #[arg(long, value_name = "T")]
    thickness: Option<f64>,
    /// What the fingertip is pressed on: plane (default), ball:K, cylinder:K (K = R2/R, the
    /// counterpart's radius over the fingertip's, > 0) or edge (a sharp edge). Off a plane the
    /// patch is an ellipse: a column radius2_norm is added (radius_norm is then its semi-axis
    /// along a cylinder's axis or an edge) and `--profile` runs along that first semi-axis.
    #[arg(
        long,
        value_name = "plane|ball:K|cylinder:K|edge",
        default_value = "plane"
    )]
    counterpart: CounterpartArg,
    /// Instead of the curve: the level's pressure profile at compression ratio x = X [-]
    /// (0 < X <= the level's x_max), as CSV `r_norm,p_norm` (r/R from 0 to a/R, 50 rows; p/E*).
    #[arg(long, value_name = "X")]
    profile: Option<f64>,
}

/// The constructions `--backing` takes: every row of `softgrip_law::BACKINGS`, with its
/// description as its help.
fn backing_names() -> clap::builder::PossibleValuesParser {
    clap::builder::PossibleValuesParser::new(
        softgrip_law::BACKINGS
            .iter()
            .map(|row| clap::builder::PossibleValue::new(row.name).help(row.description)),
    )
}

/// The construction of `--backing` and `--thickness` (T = t/R; with R = 1 m, t = T m),
/// through the law's one parser ([`Backing::try_from_parts`], the table
/// `softgrip_law::BACKINGS`); the thickness then against R = 1.
fn backing(args: &CurveArgs) -> Result<Backing> {
    let backing = Backing::try_from_parts(&args.backing, args.thickness).map_err(|e| match e {
        softgrip_law::Error::InvalidParameter { value, .. } => anyhow::anyhow!(
            "`--thickness` is t/R and must be in (0, 1), got {}",
            Shortest(value)
        ),
        // The law's messages in the flags' words (`--thickness` is t/R here).
        softgrip_law::Error::UnexpectedSetting { name, .. } => anyhow::anyhow!(
            "`--thickness` applies only to `--backing {}`, not to `--backing {name}`",
            e.takes().join("|")
        ),
        softgrip_law::Error::MissingSetting { name, .. } => {
            anyhow::anyhow!("`--backing {name}` needs `--thickness T` (t/R, in (0, 1))")
        }
        e => anyhow::anyhow!("invalid `--backing`: {e}"),
    })?;
    match backing.thickness() {
        Some(t) if t >= 1.0 => bail!(
            "`--thickness` is t/R and must be in (0, 1), got {}",
            Shortest(t)
        ),
        _ => Ok(backing),
    }
}

/// Prints the curve (or the profile) to stdout. Rows past the level's validity range show the
/// law's documented extension (tangent continuation) with `valid = 0`.
pub fn run(args: &CurveArgs) -> Result<()> {
    let level = args.level.level()?;
    let backing = backing(args)?;
    // E* = 1 Pa and R = 1 m: the law's outputs are then the normalised quantities, delta = x.
    let params = ContactParams::try_from_parts(1.0, 1.0, args.nu)
        .context("invalid `--nu`")?
        .with_backing(backing)
        .context("invalid `--thickness`")?;
    // The construction as the user gave it: t/R, not the law's t in metres (R = 1 m here).
    let named = match backing {
        Backing::Core { thickness } => format!("core (t/R = {})", Shortest(thickness)),
        other => other.to_string(),
    };
    let law = ContactLaw::try_new(params, level).with_context(|| {
        format!(
            "cannot build level `{level}` at nu = {} for backing {named}",
            Shortest(args.nu)
        )
    })?;
    let cp = args.counterpart;
    let law = cp
        .counterpart(1.0)
        .and_then(|c| law.with_counterpart(c))
        .with_context(|| format!("invalid `--counterpart {cp}`"))?;
    let named = if cp.is_plane() {
        named
    } else {
        format!("{named} on {cp}")
    };
    let written = match (args.profile, &args.x) {
        (Some(x), _) => {
            if !(x > 0.0 && x <= law.x_max()) {
                bail!(
                    "`--profile` must be in (0, {}] (level `{level}`'s validity range for backing {named}), got {}",
                    Shortest(law.x_max()),
                    Shortest(x)
                );
            }
            write_profile(&law, x, io::stdout().lock())
        }
        (None, Some(xs)) => {
            let cap = max_points(level);
            if xs.len() > cap {
                bail!(
                    "`--x` has {} points; level `{level}` evaluates at most {cap} per call (it solves the theory at each point): use a larger STEP, or `--level neo-hookean` (the same theory, tabulated; up to {MAX_POINTS} points)",
                    xs.len()
                );
            }
            write_csv(&law, xs, io::stdout().lock())
        }
        (None, None) => bail!("give `--x START:STOP:STEP` or `--profile X`"),
    };
    match written {
        // A closed pipe (`| head`) ends the output; it is not an error.
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
        other => other.context("cannot write to stdout"),
    }
}

fn write_csv(law: &ContactLaw, xs: &XRange, out: impl Write) -> io::Result<()> {
    let mut out = BufWriter::new(out);
    let ellipse = !law.counterpart().is_plane();
    let extra = if ellipse { HEADER_SECOND_AXIS } else { "" };
    writeln!(out, "{HEADER}{extra}")?;
    for x in xs.iter() {
        let r = law.response(x);
        let patch = law.patch(x);
        // `{:e}` is the shortest representation that parses back to the same double.
        write!(
            out,
            "{},{:e},{:e},{:e},{:e},{:e},{}",
            Shortest(x),
            r.force,
            r.stiffness,
            law.energy(x),
            patch.radius,
            patch.mean_pressure,
            u8::from(x <= law.x_max()),
        )?;
        if ellipse {
            write!(out, ",{:e}", patch.radius2)?;
        }
        writeln!(out)?;
    }
    out.flush()
}

/// The pressure profile of `law` (E* = 1, R = 1) at compression ratio `x`: `PROFILE_ROWS`
/// rows from r = 0 to r = a (where p = 0), `ContactPatch::pressure_at` (on an ellipse along
/// its first semi-axis a; along the second it is the same at `r b/a`).
fn write_profile(law: &ContactLaw, x: f64, out: impl Write) -> io::Result<()> {
    let mut out = BufWriter::new(out);
    writeln!(out, "{PROFILE_HEADER}")?;
    let patch = law.patch(x);
    for i in 0..PROFILE_ROWS {
        // The last row is the edge itself (a 49 / 49 rounds 1 ulp off a for some a).
        let r = if i == PROFILE_ROWS - 1 {
            patch.radius
        } else {
            patch.radius * i as f64 / (PROFILE_ROWS - 1) as f64
        };
        writeln!(out, "{r:e},{:e}", patch.pressure_at(r))?;
    }
    out.flush()
}
