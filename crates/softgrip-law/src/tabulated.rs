//! [`TabulatedCurve`]: a user's own measured squeeze curve, validated once, for the `tabulated`
//! level ([`crate::ContactLaw::tabulated`]).

use crate::Shortest;
use crate::error::{Error, Result};

/// Fewest samples with `delta > 0` a curve needs (with the origin, two cells: one interior node
/// for the slopes).
pub const MIN_TABULATED_SAMPLES: usize = 2;

/// A measured squeeze curve: compressions `delta_m` \[m\] and forces `force_n` \[N\], as in a CSV
/// file with the header `delta_m,force_n` (the law has no I/O: `softgrip-scene` reads the file).
///
/// Checked at construction ([`TabulatedCurve::try_new`]), each failure an
/// [`Error::InvalidTable`] naming the column, the sample's index, its value and the valid range:
/// - the two columns have the same length;
/// - every value is finite, `>= 0` and representable in `f32` (0, or a magnitude between
///   1.2e-38 and 3.4e38: the engine and the recordings are `f32`);
/// - `delta_m` is strictly increasing, `force_n` non-decreasing (a contact law may not soften);
/// - **the origin**: a squeeze starts from no contact, `F(0) = 0`. If the first sample has
///   `delta = 0` its force must be 0 (subtract a load cell's offset first); otherwise the point
///   `(0, 0)` is prepended. The curve holds that origin (`delta_m()[0] = 0`);
/// - at least [`MIN_TABULATED_SAMPLES`] samples with `delta > 0`, and a last force `> 0`.
///
/// ```
/// use softgrip_law::{Error, TabulatedCurve};
/// let curve = TabulatedCurve::try_new(vec![0.001, 0.002, 0.004], vec![0.5, 1.5, 4.0])?;
/// assert_eq!(curve.delta_m(), &[0.0, 0.001, 0.002, 0.004]); // the origin was prepended
/// assert_eq!(curve.force_max(), 4.0);
/// let err = TabulatedCurve::try_new(vec![0.001, 0.002], vec![1.5, 0.5]).unwrap_err();
/// assert!(matches!(err, Error::InvalidTable { field: "force_n", index: Some(1), .. }));
/// # Ok::<(), Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct TabulatedCurve {
    delta_m: Vec<f64>,
    force_n: Vec<f64>,
}

impl TabulatedCurve {
    /// Validates the samples (see the type's docs) and prepends the origin if needed.
    pub fn try_new(delta_m: Vec<f64>, force_n: Vec<f64>) -> Result<Self> {
        if force_n.len() != delta_m.len() {
            return Err(table_error(
                "force_n",
                None,
                force_n.len() as f64,
                format!("as many samples as `delta_m` ({})", delta_m.len()),
            ));
        }
        for (i, (&d, &f)) in delta_m.iter().zip(&force_n).enumerate() {
            check_value("delta_m", i, d, "m")?;
            check_value("force_n", i, f, "N")?;
            if i > 0 {
                check_order(&delta_m, &force_n, i)?;
            }
        }
        let (mut delta_m, mut force_n) = (delta_m, force_n);
        if delta_m.first() == Some(&0.0) {
            if force_n[0] != 0.0 {
                return Err(table_error(
                    "force_n",
                    Some(0),
                    force_n[0],
                    "0 N at delta = 0 (F(0) = 0: subtract the load cell's offset)".into(),
                ));
            }
        } else {
            delta_m.insert(0, 0.0);
            force_n.insert(0, 0.0);
        }
        let positive = delta_m.len() - 1;
        if positive < MIN_TABULATED_SAMPLES {
            return Err(table_error(
                "delta_m",
                None,
                positive as f64,
                format!("at least {MIN_TABULATED_SAMPLES} samples with delta > 0 m"),
            ));
        }
        let last = force_n.len() - 1;
        if force_n[last] <= 0.0 {
            return Err(table_error(
                "force_n",
                Some(last),
                force_n[last],
                "> 0 N at the last sample (a curve that never loads is no contact law)".into(),
            ));
        }
        Ok(Self { delta_m, force_n })
    }

    /// Compressions delta \[m\], strictly increasing, starting at 0.
    pub fn delta_m(&self) -> &[f64] {
        &self.delta_m
    }

    /// Forces F \[N\], non-decreasing, starting at 0.
    pub fn force_n(&self) -> &[f64] {
        &self.force_n
    }

    /// The last (largest) compression of the table \[m\].
    pub fn delta_max(&self) -> f64 {
        self.delta_m[self.delta_m.len() - 1]
    }

    /// The last (largest) force of the table \[N\].
    pub fn force_max(&self) -> f64 {
        self.force_n[self.force_n.len() - 1]
    }
}

fn table_error(field: &'static str, index: Option<usize>, value: f64, range: String) -> Error {
    Error::InvalidTable {
        field,
        index,
        value,
        range,
    }
}

/// Finite, `>= 0` and an `f32` that is 0 or normal.
fn check_value(field: &'static str, i: usize, v: f64, unit: &str) -> Result<()> {
    let single = v as f32;
    let ok = v.is_finite() && v >= 0.0 && (v == 0.0 || single.is_normal());
    if ok {
        Ok(())
    } else {
        Err(table_error(
            field,
            Some(i),
            v,
            format!("finite, >= 0 {unit} and representable in f32 (0 or 1.2e-38 to 3.4e38)"),
        ))
    }
}

/// `delta_m` strictly increasing and `force_n` non-decreasing at sample `i > 0`.
fn check_order(delta_m: &[f64], force_n: &[f64], i: usize) -> Result<()> {
    if delta_m[i] <= delta_m[i - 1] {
        return Err(table_error(
            "delta_m",
            Some(i),
            delta_m[i],
            format!(
                "> delta_m[{}] = {} m (strictly increasing)",
                i - 1,
                Shortest(delta_m[i - 1])
            ),
        ));
    }
    if force_n[i] < force_n[i - 1] {
        return Err(table_error(
            "force_n",
            Some(i),
            force_n[i],
            format!(
                ">= force_n[{}] = {} N (non-decreasing: a contact law may not soften)",
                i - 1,
                Shortest(force_n[i - 1])
            ),
        ));
    }
    Ok(())
}
