//! [`ResultsTable`]: one [`TrialRow`] per trial, in trial order, and its columns: `trial`, one
//! per varied field (named by its path), `held`, the other outcomes, `wall_time`, `error`.

use crate::trial::Outcome;
use crate::value::{Value, ValueKind};

/// The outcome columns after the varied fields, in order (SWEEPS.md, "Results").
pub const OUTCOME_COLUMNS: [&str; 9] = [
    "held",
    "slips",
    "slip_distance",
    "peak_force",
    "peak_x",
    "validity_excursions",
    "hold_force",
    "wall_time",
    "error",
];

/// The outcome column results tables written before softgrip's session 12 lack: such a table
/// has [`OUTCOME_COLUMNS`] without it and still reads back, with `hold_force` NaN.
const LEGACY_MISSING: &str = "hold_force";

/// The outcome columns of a table with (`hold_force`) or without it (legacy), in order.
fn outcome_columns(hold_force: bool) -> impl Iterator<Item = &'static str> {
    (OUTCOME_COLUMNS.into_iter()).filter(move |c| hold_force || *c != LEGACY_MISSING)
}

/// Where a results table's outcome columns are: the index of `held` and whether the table
/// has a `hold_force` column ([`OUTCOME_COLUMNS`]) or not (a table written before it existed).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct OutcomeLayout {
    /// Index of the `held` column (1 + the number of varied fields).
    pub start: usize,
    /// The table has a `hold_force` column.
    pub hold_force: bool,
}

impl OutcomeLayout {
    /// The layout of a table with these column names, `None` if it is not a results table
    /// (`trial`, the varied fields, then either outcome list).
    pub(crate) fn find(names: &[String]) -> Option<Self> {
        if names.first().map(String::as_str) != Some("trial") {
            return None;
        }
        [true, false].into_iter().find_map(|hold_force| {
            let n = outcome_columns(hold_force).count();
            let start = names.len().checked_sub(n).filter(|&o| o > 0)?;
            (names[start..].iter())
                .map(String::as_str)
                .eq(outcome_columns(hold_force))
                .then_some(Self { start, hold_force })
        })
    }

    /// The column index of the outcome `name` (one of [`OUTCOME_COLUMNS`]); `None` for
    /// `hold_force` in a legacy table.
    pub(crate) fn column(&self, name: &str) -> Option<usize> {
        (outcome_columns(self.hold_force))
            .position(|c| c == name)
            .map(|k| self.start + k)
    }

    /// A row's outcome from its cells, read by column index as a boolean (`held`), a count
    /// (`slips`, `validity_excursions`) or a number; `hold_force` NaN in a legacy table. The
    /// one reader of the outcome columns for every table format (CSV, Parquet).
    pub(crate) fn outcome<E>(
        &self,
        flag: impl Fn(usize) -> Result<bool, E>,
        count: impl Fn(usize) -> Result<u64, E>,
        number: impl Fn(usize) -> Result<f64, E>,
    ) -> Result<Outcome, E> {
        let col = |name: &str| self.column(name).expect("invariant: an outcome column");
        Ok(Outcome {
            held: flag(col("held"))?,
            slips: count(col("slips"))? as u32,
            slip_distance: number(col("slip_distance"))?,
            peak_force: number(col("peak_force"))?,
            peak_x: number(col("peak_x"))?,
            validity_excursions: count(col("validity_excursions"))? as u32,
            hold_force: match self.column("hold_force") {
                Some(k) => number(k)?,
                None => f64::NAN,
            },
        })
    }

    /// The error text when no layout is found.
    pub(crate) fn expected() -> String {
        format!(
            "not a sweep results table: the columns must be `trial`, the varied fields, {} \
             (tables written before `hold_force` existed: the same without it)",
            OUTCOME_COLUMNS.join(", ")
        )
    }
}

/// One trial's row.
#[derive(Debug, Clone, PartialEq)]
pub struct TrialRow {
    /// The trial's index in the sweep, from 0.
    pub trial: u64,
    /// The value of each varied field, in the sweep's `[[vary]]` order.
    pub values: Vec<Value>,
    /// What the trial measured, or why it has no outcome (the scene's error naming the field
    /// and the value, a panic, a hold that did not end): a bad trial is a row, never the end
    /// of the sweep. The message is never empty.
    pub outcome: Result<Outcome, String>,
    /// Wall-clock time of the trial (scene check, run, recording) \[s\]: the one figure that
    /// differs between two runs of the same trial.
    pub wall_time: f64,
}

/// The results of a sweep (or of one shard of it): the column names and types and the rows.
#[derive(Debug, Clone, PartialEq)]
pub struct ResultsTable {
    /// The varied fields' paths, the column names between `trial` and `held`.
    pub fields: Vec<String>,
    /// Their column types.
    pub kinds: Vec<ValueKind>,
    /// The rows, by increasing `trial`.
    pub rows: Vec<TrialRow>,
}

impl ResultsTable {
    /// Every column name, in order: `trial`, the fields, [`OUTCOME_COLUMNS`].
    pub fn columns(&self) -> Vec<String> {
        std::iter::once("trial".to_string())
            .chain(self.fields.iter().cloned())
            .chain(OUTCOME_COLUMNS.iter().map(|c| c.to_string()))
            .collect()
    }

    /// Appends `other`'s rows (another shard of the same sweep); `Err` if its columns differ.
    pub fn append(&mut self, other: ResultsTable) -> Result<(), String> {
        if other.fields != self.fields || other.kinds != self.kinds {
            return Err(format!(
                "the tables' columns differ: {:?} and {:?}",
                self.fields, other.fields
            ));
        }
        self.rows.extend(other.rows);
        Ok(())
    }

    /// Rows with an outcome whose `held` is true.
    pub fn held_count(&self) -> usize {
        (self.rows.iter())
            .filter(|r| matches!(r.outcome, Ok(o) if o.held))
            .count()
    }

    /// Rows with an error.
    pub fn error_count(&self) -> usize {
        self.rows.iter().filter(|r| r.outcome.is_err()).count()
    }
}
