//! The results table as Parquet, through the `parquet` crate's column writer and row reader
//! (no arrow): one row group, uncompressed (a sweep's table is small; pyarrow, polars and
//! DuckDB read it). `trial` INT64, a varied field DOUBLE, INT64, BOOLEAN or STRING, `held`
//! BOOLEAN, `slips` and `validity_excursions` INT64, `slip_distance`, `peak_force`, `peak_x`,
//! `hold_force` and `wall_time` DOUBLE, `error` STRING; the outcomes and `error` are optional (null in an
//! error row and in an ok row respectively).

use std::fs::File;
use std::path::Path;
use std::sync::Arc;

use parquet::basic::{LogicalType, Repetition, Type as Physical};
use parquet::data_type::{BoolType, ByteArray, ByteArrayType, DoubleType, Int64Type};
use parquet::file::properties::WriterProperties;
use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::file::writer::SerializedFileWriter;
use parquet::record::Field;
use parquet::schema::types::Type;

use crate::csv_io::write_whole;
use crate::error::SweepError;
use crate::table::{OutcomeLayout, ResultsTable, TrialRow};
use crate::trial::Outcome;
use crate::value::{Value, ValueKind};

/// One column's cells: values of the non-null rows and a definition level per row (1 = a
/// value, 0 = null) for optional columns.
enum Cells {
    Long(Vec<i64>),
    Double(Vec<f64>),
    Bool(Vec<bool>),
    Text(Vec<ByteArray>),
}

struct Column {
    name: String,
    cells: Cells,
    /// `None` for a required column.
    defined: Option<Vec<i16>>,
}

impl Column {
    fn physical(&self) -> (Physical, Option<LogicalType>) {
        match self.cells {
            Cells::Long(_) => (Physical::INT64, None),
            Cells::Double(_) => (Physical::DOUBLE, None),
            Cells::Bool(_) => (Physical::BOOLEAN, None),
            Cells::Text(_) => (Physical::BYTE_ARRAY, Some(LogicalType::String)),
        }
    }
}

/// `(value, defined)` of each row into an optional column.
fn optional<T>(rows: impl Iterator<Item = Option<T>>) -> (Vec<T>, Vec<i16>) {
    let mut values = Vec::new();
    let mut defined = Vec::new();
    for v in rows {
        defined.push(i16::from(v.is_some()));
        values.extend(v);
    }
    (values, defined)
}

impl ResultsTable {
    fn parquet_columns(&self) -> Vec<Column> {
        let rows = &self.rows;
        let required = |name: &str, cells| Column {
            name: name.to_string(),
            cells,
            defined: None,
        };
        let mut cols = vec![required(
            "trial",
            Cells::Long(rows.iter().map(|r| r.trial as i64).collect()),
        )];
        for (k, (field, kind)) in self.fields.iter().zip(&self.kinds).enumerate() {
            let at = |r: &TrialRow| r.values[k].clone();
            let cells = match kind {
                ValueKind::Float => Cells::Double(
                    rows.iter()
                        .map(|r| match at(r) {
                            Value::Float(v) => v,
                            _ => f64::NAN,
                        })
                        .collect(),
                ),
                ValueKind::Int => Cells::Long(
                    rows.iter()
                        .map(|r| match at(r) {
                            Value::Int(v) => v,
                            _ => 0,
                        })
                        .collect(),
                ),
                ValueKind::Bool => {
                    Cells::Bool(rows.iter().map(|r| at(r) == Value::Bool(true)).collect())
                }
                ValueKind::Text => Cells::Text(
                    rows.iter()
                        .map(|r| ByteArray::from(at(r).to_cell().into_bytes()))
                        .collect(),
                ),
            };
            cols.push(required(field, cells));
        }
        let outcome = |r: &TrialRow| r.outcome.as_ref().ok().copied();
        let opt = |name: &str, (values, defined): (Cells, Vec<i16>)| Column {
            name: name.to_string(),
            cells: values,
            defined: Some(defined),
        };
        let doubles = |f: fn(&Outcome) -> f64| {
            let (v, d) = optional(rows.iter().map(|r| outcome(r).map(|o| f(&o))));
            (Cells::Double(v), d)
        };
        let longs = |f: fn(&Outcome) -> i64| {
            let (v, d) = optional(rows.iter().map(|r| outcome(r).map(|o| f(&o))));
            (Cells::Long(v), d)
        };
        let (held, held_def) = optional(rows.iter().map(|r| outcome(r).map(|o| o.held)));
        cols.push(opt("held", (Cells::Bool(held), held_def)));
        cols.push(opt("slips", longs(|o| o.slips as i64)));
        cols.push(opt("slip_distance", doubles(|o| o.slip_distance)));
        cols.push(opt("peak_force", doubles(|o| o.peak_force)));
        cols.push(opt("peak_x", doubles(|o| o.peak_x)));
        cols.push(opt(
            "validity_excursions",
            longs(|o| o.validity_excursions as i64),
        ));
        cols.push(opt("hold_force", doubles(|o| o.hold_force)));
        cols.push(required(
            "wall_time",
            Cells::Double(rows.iter().map(|r| r.wall_time).collect()),
        ));
        let (err, err_def) = optional(rows.iter().map(|r| {
            r.outcome
                .as_ref()
                .err()
                .map(|e| ByteArray::from(e.clone().into_bytes()))
        }));
        cols.push(opt("error", (Cells::Text(err), err_def)));
        cols
    }

    /// Writes the table to `path` as Parquet: the whole file or none (written to a temporary
    /// file beside it, then renamed over `path`).
    pub fn write_parquet(&self, path: &Path) -> Result<(), SweepError> {
        let bytes = self.to_parquet().map_err(|message| SweepError::Results {
            path: path.to_path_buf(),
            message,
        })?;
        write_whole(path, &bytes)
    }

    /// The table as the bytes of a Parquet file.
    pub fn to_parquet(&self) -> Result<Vec<u8>, String> {
        let fail = |e: parquet::errors::ParquetError| e.to_string();
        let cols = self.parquet_columns();
        let fields = cols
            .iter()
            .map(|c| {
                let (physical, logical) = c.physical();
                let repetition = if c.defined.is_some() {
                    Repetition::OPTIONAL
                } else {
                    Repetition::REQUIRED
                };
                Type::primitive_type_builder(&c.name, physical)
                    .with_repetition(repetition)
                    .with_logical_type(logical)
                    .build()
                    .map(Arc::new)
            })
            .collect::<Result<Vec<_>, _>>()
            .map_err(fail)?;
        let schema = Type::group_type_builder("softgrip_sweep")
            .with_fields(fields)
            .build()
            .map_err(fail)?;
        let props = Arc::new(WriterProperties::builder().build());
        let mut writer =
            SerializedFileWriter::new(Vec::new(), Arc::new(schema), props).map_err(fail)?;
        let mut group = writer.next_row_group().map_err(fail)?;
        for c in &cols {
            let mut w = group
                .next_column()
                .map_err(fail)?
                .expect("invariant: one writer per schema column");
            let def = c.defined.as_deref();
            match &c.cells {
                Cells::Long(v) => w.typed::<Int64Type>().write_batch(v, def, None),
                Cells::Double(v) => w.typed::<DoubleType>().write_batch(v, def, None),
                Cells::Bool(v) => w.typed::<BoolType>().write_batch(v, def, None),
                Cells::Text(v) => w.typed::<ByteArrayType>().write_batch(v, def, None),
            }
            .map_err(fail)?;
            w.close().map_err(fail)?;
        }
        group.close().map_err(fail)?;
        writer.into_inner().map_err(fail)
    }

    /// Reads a results Parquet file back (one written by [`ResultsTable::write_parquet`], or
    /// any file with the same columns and types).
    pub fn read_parquet(path: &Path) -> Result<Self, SweepError> {
        let bad = |message: String| SweepError::Results {
            path: path.to_path_buf(),
            message,
        };
        let file = File::open(path).map_err(|source| SweepError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        let reader = SerializedFileReader::new(file).map_err(|e| bad(e.to_string()))?;
        let schema = reader.metadata().file_metadata().schema_descr_ptr();
        let names: Vec<String> = (schema.columns().iter())
            .map(|c| c.name().to_string())
            .collect();
        let layout = OutcomeLayout::find(&names).ok_or_else(|| bad(OutcomeLayout::expected()))?;
        let o = layout.start;
        let col = |name: &str| layout.column(name).expect("invariant: an outcome column");
        let fields = names[1..o].to_vec();
        let kinds = (schema.columns()[1..o].iter())
            .map(|c| match c.physical_type() {
                Physical::DOUBLE => Ok(ValueKind::Float),
                Physical::INT64 => Ok(ValueKind::Int),
                Physical::BOOLEAN => Ok(ValueKind::Bool),
                Physical::BYTE_ARRAY => Ok(ValueKind::Text),
                other => Err(bad(format!("`{}`: unexpected type {other}", c.name()))),
            })
            .collect::<Result<Vec<_>, _>>()?;
        let mut rows = Vec::new();
        for row in reader.get_row_iter(None).map_err(|e| bad(e.to_string()))? {
            let row = row.map_err(|e| bad(e.to_string()))?;
            let cells: Vec<&Field> = row.get_column_iter().map(|(_, f)| f).collect();
            let at = |k: usize, m: &str| bad(format!("row {}: `{}`: {m}", rows.len(), names[k]));
            let long = |k: usize| match cells[k] {
                Field::Long(v) => Ok(*v),
                other => Err(at(k, &format!("{other} is not an INT64"))),
            };
            let double = |k: usize| match cells[k] {
                Field::Double(v) => Ok(*v),
                other => Err(at(k, &format!("{other} is not a DOUBLE"))),
            };
            let trial = long(0)? as u64;
            let values = (1..o)
                .map(|k| match cells[k] {
                    Field::Double(v) => Ok(Value::Float(*v)),
                    Field::Long(v) => Ok(Value::Int(*v)),
                    Field::Bool(v) => Ok(Value::Bool(*v)),
                    Field::Str(v) => Ok(Value::Text(v.clone())),
                    other => Err(at(k, &format!("unexpected value {other}"))),
                })
                .collect::<Result<Vec<_>, _>>()?;
            let wall_time = double(col("wall_time"))?;
            let error = col("error");
            let outcome = match cells[error] {
                Field::Str(e) => Err(e.clone()),
                Field::Null => {
                    let flag = |k: usize| match cells[k] {
                        Field::Bool(v) => Ok(*v),
                        other => Err(at(k, &format!("{other} is not a BOOLEAN"))),
                    };
                    let count = |k: usize| long(k).map(|v| v as u64);
                    Ok(layout.outcome(flag, count, double)?)
                }
                other => return Err(at(error, &format!("{other} is not a STRING"))),
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
