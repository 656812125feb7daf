//! Choosing a level of the law on the command line: `--level` and its settings.

use anyhow::{Result, bail};
use softgrip_law::Level;

/// `--level NAME` with the settings that only some levels take.
#[derive(Debug, Clone, clap::Args)]
pub struct LevelArgs {
    /// Level of the law: linear, hertz, fit, incompressible, neo-hookean, neo-hookean-exact,
    /// tatara, calibrated or auto.
    #[arg(long, value_name = "NAME", value_parser = parse_level)]
    pub level: Level,
    /// Slope k of 1/chi = 1 - k x, in [0, 10] (only with `--level fit`; default 10/9).
    #[arg(long)]
    pub k: Option<f64>,
    /// Relative force tolerance against the full theory, in (0, 0.5] (only with
    /// `--level auto`; default 0.01).
    #[arg(long)]
    pub tolerance: Option<f64>,
    /// Compression ratio where the spring's force equals Hertz's, in (0, 1] (only with
    /// `--level linear`; default 0.05).
    #[arg(long)]
    pub match_x: Option<f64>,
}

fn parse_level(s: &str) -> std::result::Result<Level, String> {
    s.parse()
}

impl LevelArgs {
    /// The level with its settings. Fails if a setting is given to a level that does not take
    /// it; the values themselves are checked by the law when it is built.
    pub fn level(&self) -> Result<Level> {
        let mut level = self.level;
        if let Some(k) = self.k {
            match level {
                Level::Fit { .. } => level = Level::Fit { k },
                other => bail!("`--k` applies only to `--level fit`, not to `--level {other}`"),
            }
        }
        if let Some(tolerance) = self.tolerance {
            match level {
                Level::Auto { .. } => level = Level::Auto { tolerance },
                other => {
                    bail!("`--tolerance` applies only to `--level auto`, not to `--level {other}`")
                }
            }
        }
        if let Some(match_x) = self.match_x {
            match level {
                Level::Linear { .. } => level = Level::Linear { match_x },
                other => {
                    bail!("`--match-x` applies only to `--level linear`, not to `--level {other}`")
                }
            }
        }
        Ok(level)
    }
}
