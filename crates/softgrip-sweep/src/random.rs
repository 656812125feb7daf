//! The random values of a `random = { low, high, n, seed }` axis: value `j` is a function of
//! `seed` and `j` alone (a counter-based generator), so any trial is reproduced from its index
//! without drawing the values before it, by this code or by another language.

/// SplitMix64's output function (Steele, Lea and Flood 2014; the seeding generator of
/// xoshiro): a bijective 64-bit mix.
fn splitmix64(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// Uniform in \[0, 1): `u_j = (splitmix64(seed + (j + 1) * 0x9e3779b97f4a7c15) >> 11) / 2^53`
/// (wrapping arithmetic: SplitMix64's j-th output from state `seed`).
pub fn uniform(seed: u64, j: u64) -> f64 {
    let z = splitmix64(seed.wrapping_add((j.wrapping_add(1)).wrapping_mul(0x9e37_79b9_7f4a_7c15)));
    (z >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
}

/// Value `j` of the axis: `low + (high - low) * u_j`, in \[low, high).
pub fn value(low: f64, high: f64, seed: u64, j: u64) -> f64 {
    let v = low + (high - low) * uniform(seed, j);
    // Rounding can land on `high` when the range is tiny next to `low`.
    if v < high { v } else { low }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix64_reference_outputs() {
        // SplitMix64 from state 0: the first outputs of the reference implementation
        // (Vigna's splitmix64.c), as listed by many ports.
        assert_eq!(splitmix64(0x9e37_79b9_7f4a_7c15), 0xe220_a839_7b1d_cdaf);
        assert_eq!(
            splitmix64(0x9e37_79b9_7f4a_7c15u64.wrapping_mul(2)),
            0x6e78_9e6a_a1b9_65f4
        );
    }

    #[test]
    fn values_are_in_range_and_spread() {
        let n = 10_000;
        let (lo, hi) = (2.0, 5.0);
        let v: Vec<f64> = (0..n).map(|j| value(lo, hi, 42, j)).collect();
        assert!(v.iter().all(|&x| (lo..hi).contains(&x)));
        let mean = v.iter().sum::<f64>() / n as f64;
        // Uniform on [2, 5): mean 3.5, standard error of the mean 0.866 / 100.
        assert!((mean - 3.5).abs() < 0.03, "{mean}");
        assert_ne!(value(lo, hi, 42, 0), value(lo, hi, 43, 0));
    }
}
