//! The results table as CSV (`csv` crate): one header line of [`ResultsTable::columns`], one
//! line per trial; an error row has empty outcome cells and its message in `error`.

use std::io::Write;
use std::path::Path;

use crate::error::SweepError;
use crate::table::{OutcomeLayout, ResultsTable, TrialRow};
use crate::value::{Value, ValueKind};

impl ResultsTable {
    /// The table as CSV text. Floats are written in their shortest round-trip form with a
    /// `.` or an exponent, so [`ResultsTable::from_csv`] reads back the same bits.
    pub fn to_csv(&self) -> String {
        let mut w = csv::Writer::from_writer(Vec::new());
        let mut write = |record: Vec<String>| {
            w.write_record(&record)
                .expect("invariant: writing CSV to memory cannot fail");
        };
        write(self.columns());
        for r in &self.rows {
            let mut cells = vec![r.trial.to_string()];
            cells.extend(r.values.iter().map(Value::to_cell));
            let f = |v: f64| format!("{v:?}");
            match &r.outcome {
                Ok(o) => cells.extend([
                    o.held.to_string(),
                    o.slips.to_string(),
                    f(o.slip_distance),
                    f(o.peak_force),
                    f(o.peak_x),
                    o.validity_excursions.to_string(),
                    f(o.hold_force),
                    f(r.wall_time),
                    String::new(),
                ]),
                Err(e) => {
                    cells.extend(std::iter::repeat_n(String::new(), 7));
                    cells.extend([f(r.wall_time), e.clone()]);
                }
            }
            write(cells);
        }
        let bytes = w
            .into_inner()
            .expect("invariant: flushing CSV to memory cannot fail");
        String::from_utf8(bytes).expect("invariant: the cells are UTF-8")
    }

    /// Writes [`ResultsTable::to_csv`] to `path`: the whole file or none (written to a
    /// temporary file beside it, then renamed over `path`).
    pub fn write_csv(&self, path: &Path) -> Result<(), SweepError> {
        write_whole(path, self.to_csv().as_bytes())
    }

    /// Reads a results CSV file back.
    pub fn read_csv(path: &Path) -> Result<Self, SweepError> {
        let text = std::fs::read_to_string(path).map_err(|source| SweepError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        Self::from_csv(&text).map_err(|message| SweepError::Results {
            path: path.to_path_buf(),
            message,
        })
    }

    /// Parses results CSV text. A varied field's column type is taken from its cells: integers
    /// if every cell is one, else numbers if every cell is one, else booleans, else text (a
    /// text field whose every value looks like a number reads back as numbers; Parquet keeps
    /// the type).
    pub fn from_csv(text: &str) -> Result<Self, String> {
        let mut r = csv::Reader::from_reader(text.as_bytes());
        let header: Vec<String> = r
            .headers()
            .map_err(|e| e.to_string())?
            .iter()
            .map(str::to_string)
            .collect();
        let layout = OutcomeLayout::find(&header).ok_or_else(OutcomeLayout::expected)?;
        let fields = header[1..layout.start].to_vec();
        let records: Vec<csv::StringRecord> = r
            .records()
            .collect::<Result<_, _>>()
            .map_err(|e| e.to_string())?;
        let kinds: Vec<ValueKind> = (0..fields.len())
            .map(|k| column_kind(records.iter().map(|rec| &rec[1 + k])))
            .collect();
        let mut rows = Vec::with_capacity(records.len());
        for (line, rec) in records.iter().enumerate() {
            let at = |col: usize, m: &str| format!("row {}: `{}`: {m}", line + 1, header[col]);
            let num = |col: usize| -> Result<f64, String> {
                rec[col]
                    .parse()
                    .map_err(|_| at(col, &format!("`{}` is not a number", &rec[col])))
            };
            let int = |col: usize| -> Result<u64, String> {
                rec[col]
                    .parse()
                    .map_err(|_| at(col, &format!("`{}` is not a count", &rec[col])))
            };
            let trial = int(0)?;
            let values = (0..fields.len())
                .map(|k| cell_value(kinds[k], &rec[1 + k]))
                .collect();
            let col = |name: &str| layout.column(name).expect("invariant: an outcome column");
            let wall_time = num(col("wall_time"))?;
            let error = &rec[col("error")];
            let outcome = if error.is_empty() {
                let flag = |k: usize| match &rec[k] {
                    "true" => Ok(true),
                    "false" => Ok(false),
                    other => Err(at(k, &format!("`{other}` is not true or false"))),
                };
                Ok(layout.outcome(flag, int, num)?)
            } else {
                Err(error.to_string())
            };
            rows.push(TrialRow {
                trial,
                values,
                outcome,
                wall_time,
            });
        }
        Ok(Self {
            fields,
            kinds,
            rows,
        })
    }
}

/// Writes `bytes` to a temporary file in `path`'s folder and renames it to `path` (replacing
/// a file there): a reader of `path` sees the old file or the whole new one, and an
/// interrupted write leaves no file cut mid-row.
pub(crate) fn write_whole(path: &Path, bytes: &[u8]) -> Result<(), SweepError> {
    let io = |source| SweepError::Io {
        path: path.to_path_buf(),
        source,
    };
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut tmp = tempfile::Builder::new()
        .prefix(".softgrip-")
        .suffix(".tmp")
        .tempfile_in(dir)
        .map_err(io)?;
    tmp.write_all(bytes).map_err(io)?;
    tmp.persist(path).map_err(|e| io(e.error))?;
    Ok(())
}

/// The type of a column of cells (see [`ResultsTable::from_csv`]).
fn column_kind<'a>(cells: impl Iterator<Item = &'a str> + Clone) -> ValueKind {
    let mut c = cells;
    if c.clone().all(|s| s.parse::<i64>().is_ok()) {
        ValueKind::Int
    } else if c.clone().all(|s| s.parse::<f64>().is_ok()) {
        ValueKind::Float
    } else if c.all(|s| s == "true" || s == "false") {
        ValueKind::Bool
    } else {
        ValueKind::Text
    }
}

/// A cell of a column of type `kind` (checked by [`column_kind`]).
fn cell_value(kind: ValueKind, cell: &str) -> Value {
    match kind {
        ValueKind::Int => Value::Int(cell.parse().unwrap_or_default()),
        ValueKind::Float => Value::Float(cell.parse().unwrap_or(f64::NAN)),
        ValueKind::Bool => Value::Bool(cell == "true"),
        ValueKind::Text => Value::Text(cell.to_string()),
    }
}
