//! [`Shard`]: slice `i` of `n` of a sweep's trials, for array jobs (Slurm, Kubernetes indexed
//! Jobs): contiguous, disjoint, and in shard order they concatenate to the whole sweep.

use std::fmt;
use std::ops::Range;
use std::str::FromStr;

use crate::error::SweepError;

/// Slice `index` of `count` (from 0, as `SLURM_ARRAY_TASK_ID` with `--array=0-(n-1)` and
/// `JOB_COMPLETION_INDEX` count).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    index: u64,
    count: u64,
}

impl Shard {
    /// The whole sweep (`0/1`).
    pub const WHOLE: Shard = Shard { index: 0, count: 1 };

    /// Slice `index` of `count`: `count` >= 1, `index` < `count`.
    pub fn new(index: u64, count: u64) -> Result<Self, SweepError> {
        let err = |message: &str| SweepError::Shard {
            value: format!("{index}/{count}"),
            message: message.to_string(),
        };
        if count == 0 {
            return Err(err("the count n of `i/n` must be >= 1"));
        }
        if index >= count {
            return Err(err("the index i of `i/n` must be in 0..n (from 0)"));
        }
        Ok(Self { index, count })
    }

    /// The index i.
    pub fn index(&self) -> u64 {
        self.index
    }

    /// The count n.
    pub fn count(&self) -> u64 {
        self.count
    }

    /// The trials of this slice of `trials`: `[i * trials / n, (i + 1) * trials / n)` (sizes
    /// differ by at most one; a slice may be empty when n > trials).
    pub fn range(&self, trials: u64) -> Range<u64> {
        let at = |i: u64| (i as u128 * trials as u128 / self.count as u128) as u64;
        at(self.index)..at(self.index + 1)
    }
}

impl Default for Shard {
    fn default() -> Self {
        Self::WHOLE
    }
}

impl FromStr for Shard {
    type Err = SweepError;

    /// `i/n`, e.g. `0/4` .. `3/4`.
    fn from_str(s: &str) -> Result<Self, SweepError> {
        let err = || SweepError::Shard {
            value: s.to_string(),
            message: "must be `i/n` with integers 0 <= i < n, e.g. `0/4`".to_string(),
        };
        let (i, n) = s.split_once('/').ok_or_else(err)?;
        let (i, n) = (
            i.trim().parse().map_err(|_| err())?,
            n.trim().parse().map_err(|_| err())?,
        );
        Self::new(i, n)
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slices_cover_every_trial_once() {
        for trials in [0, 1, 5, 7, 100] {
            for n in 1..=9 {
                let ranges: Vec<_> = (0..n)
                    .map(|i| Shard::new(i, n).expect("valid").range(trials))
                    .collect();
                assert_eq!(ranges[0].start, 0);
                assert_eq!(ranges[n as usize - 1].end, trials);
                for w in ranges.windows(2) {
                    assert_eq!(w[0].end, w[1].start);
                }
                let sizes: Vec<u64> = ranges.iter().map(|r| r.end - r.start).collect();
                let (lo, hi) = (sizes.iter().min(), sizes.iter().max());
                assert!(hi.zip(lo).is_some_and(|(h, l)| h - l <= 1), "{sizes:?}");
            }
        }
    }

    #[test]
    fn parses_and_refuses() {
        assert_eq!("2/4".parse::<Shard>().ok(), Shard::new(2, 4).ok());
        for bad in ["4/4", "1/0", "x/2", "1", "-1/2"] {
            assert!(bad.parse::<Shard>().is_err(), "{bad}");
        }
    }
}
