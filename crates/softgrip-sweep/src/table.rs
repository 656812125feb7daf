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
