//! What the grasp tests (and the `impulse_grasp` example, through `#[path]`) measure the same
//! way: how far a held object moves against the hand holding it.

/// The largest distance \[m\] of `path[from..]` from `path[from]`: with `from = 0` a grasp's
/// hold slip (the object's position relative to the hand's base at each hold step), with
/// `from = 1` its creep after the step the grasp stopped at. 0 if `path` has no point at
/// `from`.
#[allow(dead_code)] // each test binary uses its own part of this module
pub fn excursion(path: &[[f64; 3]], from: usize) -> f64 {
    let Some(start) = path.get(from) else {
        return 0.0;
    };
    path[from..]
        .iter()
        .map(|p| {
            (0..3)
                .map(|i| (p[i] - start[i]).powi(2))
                .sum::<f64>()
                .sqrt()
        })
        .fold(0.0, f64::max)
}
