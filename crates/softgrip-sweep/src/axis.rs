//! [`Axis`]: one varied field and its values (a `values` list or `n` random draws), and the
//! grid: trial index -> one value index per axis, the last axis fastest.

use softgrip_scene::softgrip_rapier::softgrip_law::Shortest;

use crate::file::VarySpec;
use crate::path::FieldPath;
use crate::random;
use crate::value::{Value, ValueKind};

/// The largest number of trials of a sweep (product of the axes' lengths), 10^9.
pub const MAX_TRIALS: u64 = 1_000_000_000;

/// One varied field: its path and its values (all of one [`ValueKind`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// The field.
    pub path: FieldPath,
    /// The values, in order.
    pub values: Vec<Value>,
}

/// A `[[vary]]` table that is not an axis: the field (`vary[k].xxx`), the value and what was
/// expected.
pub(crate) type AxisError = (String, String, String);

impl Axis {
    /// The axis of `vary[k]`.
    pub(crate) fn from_spec(k: usize, spec: &VarySpec) -> Result<Self, AxisError> {
        let at = |f: &str| format!("vary[{k}].{f}");
        let path = FieldPath::parse(&spec.field).map_err(|m| {
            (
                at("field"),
                format!("{:?}", spec.field),
                format!("a scene field path like `fingertip[0].radius` ({m})"),
            )
        })?;
        let values = match (&spec.values, &spec.random) {
            (Some(values), None) => list(&at("values"), values)?,
            (None, Some(r)) => {
                let field = |f: &str| at(&format!("random.{f}"));
                if !r.low.is_finite() {
                    return Err((field("low"), Shortest(r.low).to_string(), "finite".into()));
                }
                if !(r.high.is_finite() && r.high > r.low) {
                    return Err((
                        field("high"),
                        Shortest(r.high).to_string(),
                        format!("finite and > `low` = {}", Shortest(r.low)),
                    ));
                }
                if !(1..=MAX_TRIALS as i64).contains(&r.n) {
                    return Err((field("n"), r.n.to_string(), format!("in 1..={MAX_TRIALS}")));
                }
                if r.seed < 0 {
                    return Err((field("seed"), r.seed.to_string(), ">= 0".into()));
                }
                (0..r.n as u64)
                    .map(|j| Value::Float(random::value(r.low, r.high, r.seed as u64, j)))
                    .collect()
            }
            _ => {
                return Err((
                    at("values"),
                    "both or neither of `values` and `random`".into(),
                    "exactly one of `values = [...]` and `random = { low, high, n, seed }`".into(),
                ));
            }
        };
        Ok(Self { path, values })
    }

    /// The column type.
    pub fn kind(&self) -> ValueKind {
        self.values[0].kind()
    }
}

/// The values of a `values = [...]` list: at least one, scalars of one type (integers among
/// floats become floats).
fn list(field: &str, values: &[toml::Value]) -> Result<Vec<Value>, AxisError> {
    if values.is_empty() {
        return Err((field.into(), "[]".into(), "at least one value".into()));
    }
    if values.len() as u64 > MAX_TRIALS {
        return Err((
            field.into(),
            format!("{} values", values.len()),
            format!("at most {MAX_TRIALS}"),
        ));
    }
    let mut out = Vec::with_capacity(values.len());
    for (j, v) in values.iter().enumerate() {
        let value = Value::from_toml(v).ok_or_else(|| {
            (
                format!("{field}[{j}]"),
                v.to_string(),
                "a number, an integer, a boolean or a string".into(),
            )
        })?;
        out.push(value);
    }
    // NaN and infinities are no value of any scene field, and would reach the results.
    if let Some(j) = out
        .iter()
        .position(|v| matches!(v, Value::Float(x) if !x.is_finite()))
    {
        return Err((
            format!("{field}[{j}]"),
            out[j].to_string(),
            "a finite number (not nan or inf)".into(),
        ));
    }
    let any_float = out.iter().any(|v| v.kind() == ValueKind::Float);
    if any_float {
        for v in &mut out {
            if let Value::Int(i) = *v {
                *v = Value::Float(i as f64);
            }
        }
    }
    let kind = out[0].kind();
    if let Some(j) = out.iter().position(|v| v.kind() != kind) {
        return Err((
            format!("{field}[{j}]"),
            out[j].to_string(),
            format!("of the same type as `{field}[0]` = {}", out[0]),
        ));
    }
    Ok(out)
}

/// The number of trials of `axes` (1 without axes: the base scene alone), or `None` past
/// [`MAX_TRIALS`].
pub(crate) fn trial_count(axes: &[Axis]) -> Option<u64> {
    axes.iter().try_fold(1u64, |n, a| {
        n.checked_mul(a.values.len() as u64)
            .filter(|&n| n <= MAX_TRIALS)
    })
}

/// The value index of each axis in trial `index` (mixed radix, the last axis fastest, as
/// `itertools.product` and `numpy.ndindex` order them).
pub(crate) fn grid_indices(axes: &[Axis], mut index: u64) -> Vec<usize> {
    let mut out = vec![0; axes.len()];
    for (k, a) in axes.iter().enumerate().rev() {
        let n = a.values.len() as u64;
        out[k] = (index % n) as usize;
        index /= n;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn axis(n: usize) -> Axis {
        Axis {
            path: FieldPath::parse("a").expect("valid"),
            values: (0..n as i64).map(Value::Int).collect(),
        }
    }

    #[test]
    fn grid_order_is_last_axis_fastest() {
        let axes = [axis(2), axis(3)];
        assert_eq!(trial_count(&axes), Some(6));
        let all: Vec<Vec<usize>> = (0..6).map(|i| grid_indices(&axes, i)).collect();
        let expected = [[0, 0], [0, 1], [0, 2], [1, 0], [1, 1], [1, 2]];
        assert_eq!(all, expected.map(|e| e.to_vec()));
        assert_eq!(trial_count(&[]), Some(1));
    }

    #[test]
    fn mixed_or_empty_lists_are_errors() {
        let spec = |values: &str| VarySpec {
            field: "gripper.hold".into(),
            values: Some(
                toml::from_str::<toml::Table>(&format!("v = {values}")).expect("toml")["v"]
                    .as_array()
                    .expect("array")
                    .clone(),
            ),
            random: None,
        };
        let ok = Axis::from_spec(0, &spec("[1, 2.5]")).expect("ints among floats");
        assert_eq!(ok.values, vec![Value::Float(1.0), Value::Float(2.5)]);
        let e = Axis::from_spec(3, &spec("[1.0, \"x\"]")).expect_err("mixed");
        assert_eq!(e.0, "vary[3].values[1]");
        let e = Axis::from_spec(0, &spec("[]")).expect_err("empty");
        assert_eq!(e.0, "vary[0].values");
        let e = Axis::from_spec(0, &spec("[[1.0]]")).expect_err("array");
        assert_eq!(e.0, "vary[0].values[0]");
    }

    /// `values = [nan, inf]` was accepted and NaN reached the results: each non-finite value
    /// is an error naming its index.
    #[test]
    fn nan_and_inf_values_are_errors_naming_the_index() {
        let spec = |values: &str| VarySpec {
            field: "gripper.hold".into(),
            values: Some(
                toml::from_str::<toml::Table>(&format!("v = {values}")).expect("toml")["v"]
                    .as_array()
                    .expect("array")
                    .clone(),
            ),
            random: None,
        };
        for (values, index, shown) in [
            ("[nan, inf]", 0, "NaN"),
            ("[1.0, inf]", 1, "inf"),
            ("[1, 2, -inf]", 2, "-inf"),
            ("[0.5, -nan]", 1, "NaN"),
        ] {
            let e = Axis::from_spec(2, &spec(values)).expect_err(values);
            assert_eq!(e.0, format!("vary[2].values[{index}]"), "{values}");
            assert_eq!(e.1, shown, "{values}");
            assert!(e.2.contains("finite"), "{values}: {}", e.2);
        }
    }
}
