//! [`Value`]: one value of a varied field (a cell of its results column), and the column's
//! [`ValueKind`].

use std::fmt;

/// A varied field's value in one trial, as it is written into the scene and the results.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// A number (TOML float).
    Float(f64),
    /// An integer (TOML integer).
    Int(i64),
    /// A boolean.
    Bool(bool),
    /// A string (a preset, a level name, ...).
    Text(String),
}

/// The type of a varied field's column: every value of a `[[vary]]` has the same.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ValueKind {
    /// `f64` (Parquet DOUBLE).
    Float,
    /// `i64` (Parquet INT64).
    Int,
    /// `bool` (Parquet BOOLEAN).
    Bool,
    /// UTF-8 text (Parquet BYTE_ARRAY, logical type STRING).
    Text,
}

impl Value {
    /// The column type of this value.
    pub fn kind(&self) -> ValueKind {
        match self {
            Value::Float(_) => ValueKind::Float,
            Value::Int(_) => ValueKind::Int,
            Value::Bool(_) => ValueKind::Bool,
            Value::Text(_) => ValueKind::Text,
        }
    }

    /// The TOML value written into the scene.
    pub fn to_toml(&self) -> toml::Value {
        match self {
            Value::Float(v) => toml::Value::Float(*v),
            Value::Int(v) => toml::Value::Integer(*v),
            Value::Bool(v) => toml::Value::Boolean(*v),
            Value::Text(v) => toml::Value::String(v.clone()),
        }
    }

    /// The value of a TOML scalar; `None` for arrays, tables and dates.
    pub fn from_toml(v: &toml::Value) -> Option<Self> {
        Some(match v {
            toml::Value::Float(x) => Value::Float(*x),
            toml::Value::Integer(x) => Value::Int(*x),
            toml::Value::Boolean(x) => Value::Bool(*x),
            toml::Value::String(x) => Value::Text(x.clone()),
            _ => return None,
        })
    }

    /// The value as a CSV cell: floats in Rust's shortest round-trip form that always has a
    /// `.` or an exponent (`3000000.0`, `1e-5`), so the cell reads back as the same `f64` and
    /// not as an integer.
    pub fn to_cell(&self) -> String {
        match self {
            Value::Float(v) => format!("{v:?}"),
            Value::Int(v) => v.to_string(),
            Value::Bool(v) => v.to_string(),
            Value::Text(v) => v.clone(),
        }
    }
}

impl fmt::Display for Value {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Text(v) => write!(f, "{v:?}"),
            other => f.write_str(&other.to_cell()),
        }
    }
}
