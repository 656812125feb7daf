//! [`Shortest`]: how every message of softgrip prints a number it was given or computed: the
//! shortest text that reads back as the same `f64`, in positional form for magnitudes in
//! [1e-4, 1e16) and in scientific form outside (as Rust's `{:?}` switches) (Rust's `{}` of `1e300` is a 301-digit
//! integer, of `1e-300` a 300-digit fraction).

use std::fmt;

/// `f64` displayed in its shortest round-trip form (see the module's documentation):
/// `0.01`, `590000`, `1e300`, `1.5e-7`, `-inf`, `NaN`.
///
/// ```
/// use softgrip_law::Shortest;
/// assert_eq!(Shortest(1e300).to_string(), "1e300");
/// assert_eq!(Shortest(-1.5e-7).to_string(), "-1.5e-7");
/// assert_eq!(Shortest(0.004).to_string(), "0.004");
/// assert_eq!(Shortest(590000.0).to_string(), "590000");
/// assert_eq!(Shortest(f64::NEG_INFINITY).to_string(), "-inf");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shortest(pub f64);

/// Smallest magnitude printed positionally.
const POSITIONAL_MIN: f64 = 1e-4;
/// Magnitudes from here on are printed in scientific form.
const POSITIONAL_MAX: f64 = 1e16;

impl fmt::Display for Shortest {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        let a = v.abs();
        // Both forms are Rust's shortest round-trip digits; only the notation differs.
        if !v.is_finite() || a == 0.0 || (POSITIONAL_MIN..POSITIONAL_MAX).contains(&a) {
            write!(f, "{v}")
        } else {
            write!(f, "{v:e}")
        }
    }
}

/// Digits a number in [`Shortest`] form can have at most: 17 significant digits, 4 leading
/// zeros of a positional fraction, and the integer digits below 1e16.
pub const MAX_SHORTEST_DIGITS: usize = 24;

/// `text` with every decimal number longer than [`MAX_SHORTEST_DIGITS`] digits rewritten in
/// [`Shortest`] form: for messages that quote numbers formatted by other crates (serde's
/// "invalid type: floating point `1000...0.0`" of a TOML value of 1e300).
///
/// ```
/// use softgrip_law::shorten_numbers;
/// let long = format!("floating point `{}`, expected a sequence", 1e300);
/// assert_eq!(shorten_numbers(&long), "floating point `1e300`, expected a sequence");
/// assert_eq!(shorten_numbers("x = 0.25 at line 12"), "x = 0.25 at line 12");
/// ```
pub fn shorten_numbers(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let (mut i, mut copied) = (0, 0);
    while i < b.len() {
        if !b[i].is_ascii_digit() {
            i += 1;
            continue;
        }
        // A run of digits, optionally `.` and more digits.
        let start = i;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
        if i + 1 < b.len() && b[i] == b'.' && b[i + 1].is_ascii_digit() {
            i += 1;
            while i < b.len() && b[i].is_ascii_digit() {
                i += 1;
            }
        }
        let digits = text[start..i].bytes().filter(u8::is_ascii_digit).count();
        if digits > MAX_SHORTEST_DIGITS
            && let Ok(v) = text[start..i].parse::<f64>()
        {
            out.push_str(&text[copied..start]);
            out.push_str(&Shortest(v).to_string());
            copied = i;
        }
    }
    out.push_str(&text[copied..]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every form reads back as the same bits, and none is longer than 24 characters.
    #[test]
    fn round_trips_and_stays_short() {
        let mut values = vec![
            0.0,
            -0.0,
            1.0,
            0.1,
            1e-4,
            9.999e-5,
            1e16,
            9.999_999_999_999_998e15,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            -1e300,
            1.234_567_890_123_456_7e-200,
            std::f64::consts::PI,
        ];
        let mut x = 1.0f64;
        for _ in 0..2000 {
            x = (x * 1.618_033_988_749_895 + 0.377).fract()
                * 10f64.powi((x * 1e3) as i32 % 600 - 300);
            values.push(x);
            values.push(-x);
        }
        for v in values {
            let s = Shortest(v).to_string();
            let back: f64 = s.parse().expect("parses");
            assert_eq!(back.to_bits(), v.to_bits(), "{v:e} -> {s}");
            assert!(s.len() <= 24, "{v:e} -> {s}");
        }
        assert_eq!(Shortest(f64::NAN).to_string(), "NaN");
        let tiny = format!("{}", 1.5e-300);
        assert_eq!(shorten_numbers(&format!("got -{tiny}!")), "got -1.5e-300!");
        assert_eq!(
            shorten_numbers("12345678901234567890123"),
            "12345678901234567890123"
        );
        assert_eq!(Shortest(f64::INFINITY).to_string(), "inf");
    }
}
