//! Measured squeeze curves: the CSV file of a `level = { tabulated = "tip.csv" }` fingertip,
//! read with `csv` + serde into two columns. The curve's shape (monotone, range) is checked
//! by the law (`softgrip_law::TabulatedCurve`); this file checks what only it can see: the
//! header, that every row has two finite numbers, and on which line one does not.

use std::path::{Path, PathBuf};

use serde::Deserialize;

use crate::error::SceneError;
use crate::limits::MAX_CURVE_BYTES;
use crate::read::{ReadError, read_regular, strip_bom};

/// The header a curve file must have.
pub const CURVE_HEADER: [&str; 2] = ["delta_m", "force_n"];

/// A measured squeeze curve as read from its file, rows in file order.
#[derive(Debug, Clone, PartialEq)]
pub struct MeasuredCurve {
    /// The file it was read from.
    pub path: PathBuf,
    /// Compression δ of each row \[m\] (column `delta_m`), finite.
    pub delta_m: Vec<f64>,
    /// Normal force F of each row \[N\] (column `force_n`), finite.
    pub force_n: Vec<f64>,
}

/// One row of the file.
#[derive(Debug, Deserialize)]
struct Row {
    delta_m: f64,
    force_n: f64,
}

/// Reads a curve file: CSV with the header `delta_m,force_n` (SI units: m, N), one row per
/// measured point; lines starting with `#` are comments (where the data came from).
pub fn read_curve(path: &Path) -> Result<MeasuredCurve, SceneError> {
    let bytes = read_regular(path, MAX_CURVE_BYTES).map_err(|e| match e {
        ReadError::TooLarge { limit } => SceneError::TooLarge {
            path: path.to_path_buf(),
            what: "curve",
            limit,
        },
        e => error(path, 0, "", e.message()),
    })?;
    parse_curve(&bytes, path)
}

/// Parses the text of a curve file (see [`read_curve`]); `path` names it in errors, which
/// carry the line (from 1) and the column at fault. A leading UTF-8 byte-order mark is not
/// part of the header.
pub fn parse_curve(bytes: &[u8], path: &Path) -> Result<MeasuredCurve, SceneError> {
    let mut reader = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .from_reader(strip_bom(bytes));
    let headers = reader
        .headers()
        .map_err(|e| csv_error(path, &e, &csv::StringRecord::new(), None))?
        .clone();
    let header_line = headers.position().map_or(1, |p| p.line() as usize);
    if headers.iter().ne(CURVE_HEADER) {
        let got = headers.iter().collect::<Vec<_>>().join(",");
        let message = format!("the header must be `delta_m,force_n`, got `{got}`");
        return Err(error(path, header_line, "header", message));
    }
    let mut curve = MeasuredCurve {
        path: path.to_path_buf(),
        delta_m: Vec::new(),
        force_n: Vec::new(),
    };
    let mut record = csv::StringRecord::new();
    while reader
        .read_record(&mut record)
        .map_err(|e| csv_error(path, &e, &headers, None))?
    {
        let line = record.position().map_or(0, |p| p.line() as usize);
        let row: Row = record
            .deserialize(Some(&headers))
            .map_err(|e| csv_error(path, &e, &headers, Some(&record)))?;
        for (field, value) in [("delta_m", row.delta_m), ("force_n", row.force_n)] {
            if !value.is_finite() {
                let message = format!("must be a finite number, got {value}");
                return Err(error(path, line, field, message));
            }
        }
        curve.delta_m.push(row.delta_m);
        curve.force_n.push(row.force_n);
    }
    if curve.delta_m.is_empty() {
        let message = String::from("no data rows after the header");
        return Err(error(path, header_line, "", message));
    }
    Ok(curve)
}

fn error(path: &Path, line: usize, field: &str, message: String) -> SceneError {
    SceneError::Curve {
        path: path.to_path_buf(),
        line,
        field: field.to_string(),
        message,
    }
}

/// A `csv` error as a [`SceneError::Curve`]: its line, and the column's name (and value) when
/// the error is about one field of `record`.
fn csv_error(
    path: &Path,
    e: &csv::Error,
    headers: &csv::StringRecord,
    record: Option<&csv::StringRecord>,
) -> SceneError {
    let line = e.position().map_or(0, |p| p.line() as usize);
    let (field, message) = match e.kind() {
        csv::ErrorKind::Deserialize { err, .. } => {
            let i = err.field().map(|i| i as usize);
            let name = i.and_then(|i| headers.get(i)).unwrap_or_default();
            let value = i.and_then(|i| record?.get(i)).unwrap_or_default();
            let message = match err.kind() {
                csv::DeserializeErrorKind::ParseFloat(_) => format!("`{value}` is not a number"),
                kind => kind.to_string(),
            };
            (name.to_string(), message)
        }
        csv::ErrorKind::UnequalLengths { len, .. } => (
            String::new(),
            format!("{len} fields where the header has 2 (`delta_m,force_n`)"),
        ),
        _ => (String::new(), e.to_string()),
    };
    error(path, line, &field, message)
}
