//! In-process timing of the law's hot path: a plain loop with `black_box`, no statistics
//! beyond the best of a few repeats. Good enough for a table; `benches/` has criterion.

use std::hint::black_box;
use std::time::{Duration, Instant};

/// Number of compressions in one pass of a timing loop.
const SAMPLES: usize = 1024;
/// Repeats per measurement; the fastest is kept (the machine is shared).
const REPEATS: u32 = 5;

/// `SAMPLES` fixed pseudo-random points in `(0, x_max)`, the same on every run.
pub fn sample_points(x_max: f64) -> Vec<f64> {
    // xorshift64*, fixed seed: reproducible and spread over the range.
    let mut state: u64 = 0x9E37_79B9_7F4A_7C15;
    (0..SAMPLES)
        .map(|_| {
            state ^= state >> 12;
            state ^= state << 25;
            state ^= state >> 27;
            let u = (state.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64;
            // u in [0, 1): keep x strictly inside (0, x_max).
            x_max * (0.5 + u * (SAMPLES as f64 - 1.0)) / SAMPLES as f64
        })
        .collect()
}

/// Nanoseconds per call of `eval` over `points`, measured for about `budget` in total: the
/// fastest of [`REPEATS`] runs of whole passes.
pub fn ns_per_eval(points: &[f64], budget: Duration, mut eval: impl FnMut(f64) -> f64) -> f64 {
    let mut pass = |acc: &mut f64| {
        for &x in points {
            *acc += eval(black_box(x));
        }
    };
    let mut acc = 0.0;
    pass(&mut acc); // warm-up: caches, lazily built tables
    let per_repeat = budget / REPEATS;
    let mut best = f64::INFINITY;
    for _ in 0..REPEATS {
        let start = Instant::now();
        let mut passes = 0u32;
        while passes == 0 || start.elapsed() < per_repeat {
            pass(&mut acc);
            passes += 1;
        }
        let ns = start.elapsed().as_nanos() as f64 / (f64::from(passes) * points.len() as f64);
        best = best.min(ns);
    }
    black_box(acc);
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sample_points_are_inside_the_range_and_fixed() {
        let p = sample_points(0.8);
        assert_eq!(p.len(), SAMPLES);
        assert!(p.iter().all(|&x| x > 0.0 && x < 0.8));
        assert_eq!(p, sample_points(0.8));
        let mean = p.iter().sum::<f64>() / p.len() as f64;
        assert!((mean - 0.4).abs() < 0.04, "{mean}");
    }

    #[test]
    fn timing_is_positive_and_finite() {
        let ns = ns_per_eval(&sample_points(1.0), Duration::from_millis(5), |x| x.sqrt());
        assert!(ns > 0.0 && ns.is_finite(), "{ns}");
    }
}
