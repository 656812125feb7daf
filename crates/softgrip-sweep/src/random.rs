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

/// Value `j` of the axis: `low + (high - low) * u_j`, in \[low, high), for finite `low <
/// high`. When `high - low` overflows (a range wider than `f64::MAX`, e.g. -1e308 to 1e308,
/// where the formula gave `low` for every `j`), the same value computed on the halved range:
/// `2 (low/2 + (high/2 - low/2) u_j)`, every term finite (halving and doubling are exact).
pub fn value(low: f64, high: f64, seed: u64, j: u64) -> f64 {
    let u = uniform(seed, j);
    let span = high - low;
    let v = if span.is_finite() {
        low + span * u
    } else {
        2.0 * (0.5 * low + (0.5 * high - 0.5 * low) * u)
    };
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

    /// A range wider than `f64::MAX` (-1e308 to 1e308: `high - low` is infinite) drew `low`
    /// every time. Its values are spread over the range: mean 0 within 4 standard errors
    /// (1e308 / sqrt(3) / 100), a quarter of them in each quarter of the range within 4
    /// standard errors (sqrt(n 3/16) = 43), and each equal to the halved formula.
    #[test]
    fn overflowing_range_is_sampled_uniformly() {
        let (lo, hi, n) = (-1e308, 1e308, 10_000u64);
        let v: Vec<f64> = (0..n).map(|j| value(lo, hi, 7, j)).collect();
        assert!(v.iter().all(|x| x.is_finite() && (lo..hi).contains(x)));
        let mean = v.iter().map(|x| x / n as f64).sum::<f64>();
        assert!(mean.abs() < 4.0 * 1e308 / 3f64.sqrt() / 100.0, "{mean}");
        for q in 0..4 {
            let (a, b) = (lo + 0.5e308 * q as f64, lo + 0.5e308 * (q + 1) as f64);
            let count = v.iter().filter(|x| (a..b).contains(*x)).count() as f64;
            assert!((count - 2500.0).abs() < 4.0 * 43.3, "quarter {q}: {count}");
        }
        for (j, x) in v.iter().enumerate().take(100) {
            let u = uniform(7, j as u64);
            assert_eq!(*x, 2.0 * (-0.5e308 + 1e308 * u));
        }
        // Ranges whose span is finite keep the documented formula, bit for bit.
        let u = uniform(3, 5);
        assert_eq!(value(-1e307, 1e308, 3, 5), -1e307 + (1e308 + 1e307) * u);
    }
}
