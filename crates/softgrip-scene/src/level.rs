//! [`LevelSpec`]: a fingertip's `level` key, a built-in level by name or a measured curve.

use std::fmt;

use serde::de::{self, Deserializer, MapAccess, Visitor};

/// A fingertip's `level` as written: `level = "hertz"` (a built-in level by name, parsed by
/// `softgrip_law::Level`'s `FromStr`) or `level = { tabulated = "tip.csv" }` (a measured
/// squeeze curve, CSV with the header `delta_m,force_n`, the path relative to the scene file).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum LevelSpec {
    /// A built-in level by name (`linear`, `hertz`, ..., `auto`).
    Named(String),
    /// A measured squeeze curve: the CSV file's path, relative to the scene file.
    Tabulated(String),
}

impl Default for LevelSpec {
    /// `auto`.
    fn default() -> Self {
        LevelSpec::Named(String::from("auto"))
    }
}

impl fmt::Display for LevelSpec {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LevelSpec::Named(name) => write!(f, "{name:?}"),
            LevelSpec::Tabulated(path) => write!(f, "{{ tabulated = {path:?} }}"),
        }
    }
}

impl<'de> serde::Deserialize<'de> for LevelSpec {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(LevelVisitor)
    }
}

/// A string, or a table whose only key is `tabulated` (anything else is an error the TOML
/// parser reports with its line).
struct LevelVisitor;

impl<'de> Visitor<'de> for LevelVisitor {
    type Value = LevelSpec;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a level name (e.g. \"auto\") or { tabulated = \"file.csv\" }")
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<LevelSpec, E> {
        Ok(LevelSpec::Named(v.to_string()))
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<LevelSpec, A::Error> {
        let mut path = None;
        while let Some(key) = map.next_key::<String>()? {
            if key != "tabulated" {
                return Err(de::Error::unknown_field(&key, &["tabulated"]));
            }
            if path.is_some() {
                return Err(de::Error::duplicate_field("tabulated"));
            }
            path = Some(map.next_value::<String>()?);
        }
        path.map(LevelSpec::Tabulated)
            .ok_or_else(|| de::Error::missing_field("tabulated"))
    }
}
