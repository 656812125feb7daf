//! A grid of compression ratios given as `start:stop:step`.

use std::str::FromStr;

use softgrip_law::Shortest;

/// Largest number of points a grid may have.
pub const MAX_POINTS: usize = 1_000_000;

/// The points `x_i = start + i step`, `i = 0, 1, ..`, up to `stop` included when `stop` is on
/// the grid (within `step * 1e-9`). Each point is computed from `i` (no accumulated sum) and
/// rounded to the decimals of `start` and `step`, so `0.01:0.8:0.01` gives exactly the
/// doubles nearest to 0.01, 0.02, .., 0.8.
///
/// Parsing checks: three finite numbers, `start >= 0`, `step > 0`, `stop >= start`, and at
/// most [`MAX_POINTS`] points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct XRange {
    start: f64,
    stop: f64,
    step: f64,
    count: usize,
    /// Decimal places of `start` and `step`, when they have a few.
    decimals: Option<usize>,
}

impl XRange {
    /// The number of points.
    pub fn len(&self) -> usize {
        self.count
    }

    /// The points, in increasing order.
    pub fn iter(&self) -> impl Iterator<Item = f64> + '_ {
        (0..self.count).map(move |i| self.point(i))
    }

    fn point(&self, i: usize) -> f64 {
        let x = self.start + i as f64 * self.step;
        if i + 1 == self.count && (x - self.stop).abs() <= self.step * 1e-9 {
            return self.stop;
        }
        match self.decimals {
            Some(d) => format!("{x:.d$}").parse().unwrap_or(x),
            None => x,
        }
    }
}

impl FromStr for XRange {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let parts: Vec<&str> = s.split(':').collect();
        let [start_s, stop_s, step_s] = parts[..] else {
            return Err(format!(
                "expected START:STOP:STEP (e.g. 0.01:0.8:0.01), got `{s}`"
            ));
        };
        let number = |name: &str, t: &str| -> Result<f64, String> {
            match t.trim().parse::<f64>() {
                Ok(v) if v.is_finite() => Ok(v),
                _ => Err(format!("{name} `{t}` is not a finite number (in `{s}`)")),
            }
        };
        let (start, stop, step) = (
            number("START", start_s)?,
            number("STOP", stop_s)?,
            number("STEP", step_s)?,
        );
        if start < 0.0 {
            return Err(format!(
                "START must be >= 0 (x = delta/R is a compression), got {}",
                Shortest(start)
            ));
        }
        if step <= 0.0 {
            return Err(format!("STEP must be > 0, got {}", Shortest(step)));
        }
        if stop < start {
            return Err(format!(
                "STOP ({}) must be >= START ({})",
                Shortest(stop),
                Shortest(start)
            ));
        }
        // Finite or +inf (tiny step), never NaN: stop - start >= 0 and step > 0.
        let span = (stop - start) / step;
        if span >= MAX_POINTS as f64 {
            return Err(format!(
                "`{s}` has more than {MAX_POINTS} points; use a larger STEP"
            ));
        }
        // floor() may land one short when the division rounds down (0.79 / 0.01 = 78.99..):
        // take the next point too when it is within step * 1e-9 of stop.
        let mut n = span.floor() as usize;
        if start + (n + 1) as f64 * step <= stop + step * 1e-9 {
            n += 1;
        }
        let count = n + 1;
        if count > MAX_POINTS {
            return Err(format!(
                "`{s}` has more than {MAX_POINTS} points; use a larger STEP"
            ));
        }
        let decimals = match (decimals(start_s), decimals(step_s)) {
            (Some(a), Some(b)) => Some(a.max(b)),
            _ => None,
        };
        Ok(Self {
            start,
            stop,
            step,
            count,
            decimals,
        })
    }
}

/// Decimal places of a number as written (`0.01` -> 2, `2.5e-4` -> 5, `3` -> 0); `None` past
/// 17, where rounding to them would not clean anything.
fn decimals(s: &str) -> Option<usize> {
    let s = s.trim();
    let (mantissa, exponent) = match s.find(['e', 'E']) {
        Some(i) => (&s[..i], s[i + 1..].parse::<i64>().ok()?),
        None => (s, 0),
    };
    let fraction = mantissa.split_once('.').map_or(0, |(_, f)| f.len()) as i64;
    let d = (fraction - exponent).max(0);
    (d <= 17).then_some(d as usize)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn points(s: &str) -> Vec<f64> {
        s.parse::<XRange>().expect("valid range").iter().collect()
    }

    #[test]
    fn stop_is_included_and_points_are_the_nearest_doubles() {
        let p = points("0.01:0.8:0.01");
        assert_eq!(p.len(), 80);
        assert_eq!(p[2], 0.03);
        assert_eq!(p[79], 0.8);
        let p = points("0:0.79:0.01");
        assert_eq!((p.len(), p[79]), (80, 0.79));
    }

    #[test]
    fn stop_off_the_grid_is_not_included() {
        let p = points("0.1:0.35:0.1");
        assert_eq!(p, vec![0.1, 0.2, 0.3]);
    }

    #[test]
    fn exponent_notation_is_cleaned() {
        assert_eq!(decimals("2.5e-4"), Some(5));
        assert_eq!(decimals("3"), Some(0));
        assert_eq!(points("1e-3:3e-3:1e-3"), vec![0.001, 0.002, 0.003]);
    }

    #[test]
    fn single_point() {
        assert_eq!(points("0.5:0.5:0.1"), vec![0.5]);
    }

    #[test]
    fn bad_ranges_are_rejected() {
        for bad in [
            "0.1:0.5",
            "a:0.5:0.1",
            "0.1:0.5:0",
            "0.5:0.1:0.1",
            "-0.1:0.5:0.1",
        ] {
            assert!(bad.parse::<XRange>().is_err(), "{bad}");
        }
        // 1e6 points pass, 1e6 + 1 do not.
        assert_eq!(
            "1e-6:1:1e-6".parse::<XRange>().map(|r| r.iter().count()),
            Ok(MAX_POINTS)
        );
        assert!("0:1:1e-6".parse::<XRange>().is_err());
    }
}
