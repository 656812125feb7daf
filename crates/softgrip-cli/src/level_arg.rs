//! Choosing a level of the law on the command line: `--level` and its settings, read from the
//! law's table (`softgrip_law::LEVELS`): the names `--level` takes, their descriptions in
//! `--help`, the settings' flags and their checks.

use anyhow::Result;
use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
use softgrip_law::{LEVELS, Level, LevelData};

/// `--level NAME` with the settings that only some levels take.
#[derive(Debug, Clone, clap::Args)]
pub struct LevelArgs {
    /// Level of the law (every level of softgrip_law::LEVELS that parameters alone build; a
    /// measured curve is a scene's `level = { tabulated = "tip.csv" }`).
    #[arg(long, value_name = "NAME", value_parser = level_parser())]
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

/// The levels `--level` takes: every row of [`LEVELS`] that needs no data, with the row's
/// description as its help.
fn level_parser() -> impl TypedValueParser<Value = Level> {
    let values = LEVELS
        .iter()
        .filter(|row| row.data == LevelData::None)
        .map(|row| PossibleValue::new(row.name).help(row.description));
    PossibleValuesParser::new(values).try_map(|name| Level::from_name(&name))
}

impl LevelArgs {
    /// The level's settings as given, by their key in the table (`k`, `tolerance`,
    /// `match_x`; a test checks that these are every key of the table).
    pub fn settings(&self) -> [(&'static str, Option<f64>); 3] {
        [
            ("match_x", self.match_x),
            ("k", self.k),
            ("tolerance", self.tolerance),
        ]
    }

    /// The level with its settings, each set and checked by the law
    /// ([`Level::with_setting`]): a setting given to a level that does not take it, or
    /// outside its range, is an error naming the flag, the value and the level that takes
    /// it.
    pub fn level(&self) -> Result<Level> {
        let mut level = self.level;
        for (key, value) in self.settings() {
            if let Some(value) = value {
                level = level
                    .with_setting(key, value)
                    .map_err(|e| anyhow::anyhow!("`--{}`: {e}", key.replace('_', "-")))?;
            }
        }
        Ok(level)
    }
}
