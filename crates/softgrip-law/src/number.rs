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
        assert_eq!(Shortest(f64::INFINITY).to_string(), "inf");
    }
}
