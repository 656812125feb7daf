//! Numbers as people read them: [`si`] (significant digits with an SI prefix and a unit,
//! `12.35 µN`) and [`sig`] (significant digits of a plain number). The one formatter of every
//! physical figure softgrip prints (the run summary, `softgrip inspect`); neither ever prints
//! `inf` or `NaN`.

/// Significant digits printed.
pub const DIGITS: i32 = 4;

/// Prefixes from 10^-15 to 10^12, by exponent / 3 + 5.
const PREFIXES: [&str; 10] = ["f", "p", "n", "µ", "m", "", "k", "M", "G", "T"];

/// `value` in `unit` with [`DIGITS`] significant digits and the SI prefix that puts the
/// mantissa in [1, 1000): `si(1.2346e-5, "N")` = `"12.35 µN"`, `si(0.0, "N")` = `"0 N"`.
/// Outside the prefixes' range it is scientific (`"3.000e-18 m"`); a non-finite value is
/// `"n/a"` followed by the unit.
pub fn si(value: f64, unit: &str) -> String {
    if !value.is_finite() {
        return format!("n/a {unit}");
    }
    if value == 0.0 {
        return format!("0 {unit}");
    }
    let rounded = round_sig(value);
    let exp3 = (rounded.abs().log10() / 3.0).floor() as i32;
    let Some(prefix) = usize::try_from(exp3 + 5).ok().and_then(|i| PREFIXES.get(i)) else {
        return format!("{} {unit}", scientific(value));
    };
    let mantissa = rounded / 10f64.powi(3 * exp3);
    format!("{} {prefix}{unit}", fixed(mantissa))
}

/// A plain number with [`DIGITS`] significant digits: fixed point from 1e-3 to 1e6
/// (`sig(0.012346)` = `"0.01235"`), scientific outside (`"1.235e9"`), `"n/a"` if not finite.
pub fn sig(value: f64) -> String {
    if !value.is_finite() {
        return "n/a".into();
    }
    if value == 0.0 {
        return "0".into();
    }
    let a = round_sig(value).abs();
    if (1e-3..1e6).contains(&a) {
        fixed(value)
    } else {
        scientific(value)
    }
}

/// `v` rounded to [`DIGITS`] significant digits (so 999.96 becomes 1000 before a prefix is
/// chosen).
fn round_sig(v: f64) -> f64 {
    format!("{:.*e}", (DIGITS - 1) as usize, v)
        .parse()
        .unwrap_or(v)
}

/// Fixed point with [`DIGITS`] significant digits.
fn fixed(v: f64) -> String {
    let r = round_sig(v);
    let int_digits = (r.abs().log10().floor() as i32 + 1).max(1 - 15);
    let decimals = (DIGITS - int_digits).max(0) as usize;
    format!("{r:.decimals$}")
}

/// Scientific with [`DIGITS`] significant digits.
fn scientific(v: f64) -> String {
    format!("{:.*e}", (DIGITS - 1) as usize, v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn si_prefixes_and_digits() {
        assert_eq!(si(1.2346e-5, "N"), "12.35 µN");
        assert_eq!(si(11.781, "N"), "11.78 N");
        assert_eq!(si(0.0, "N"), "0 N");
        assert_eq!(si(590_000.0, "Pa"), "590.0 kPa");
        assert_eq!(si(999.96, "N"), "1.000 kN");
        assert_eq!(si(-2.5e-3, "m"), "-2.500 mm");
        assert_eq!(si(3e-18, "m"), "3.000e-18 m");
        assert_eq!(si(f64::INFINITY, "N"), "n/a N");
        assert_eq!(si(f64::NAN, "s"), "n/a s");
    }

    #[test]
    fn sig_digits() {
        assert_eq!(sig(0.012346), "0.01235");
        assert_eq!(sig(1.5), "1.500");
        assert_eq!(sig(1234.6), "1235");
        assert_eq!(sig(1.2346e9), "1.235e9");
        assert_eq!(sig(f64::INFINITY), "n/a");
        assert_eq!(sig(0.0), "0");
    }
}
