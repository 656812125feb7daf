//! Fixed-length arrays read with their length checked: serde's `[T; N]` reads the first `N`
//! elements of a TOML array and ignores the rest (a 4-component gravity ran as its first 3).
//! Used through `#[serde(deserialize_with = "...")]`, so the public fields stay `[T; N]`.

use serde::de::{Deserialize, Deserializer, Error};

/// An array of exactly `N` elements; any other length is an error naming both counts.
pub(crate) fn exact<'de, D, T, const N: usize>(d: D) -> Result<[T; N], D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de>,
{
    let v: Vec<T> = Vec::deserialize(d)?;
    let len = v.len();
    v.try_into()
        .map_err(|_| D::Error::custom(format!("expected exactly {N} components, got {len}")))
}

/// An optional array of exactly `N` elements (`#[serde(default)]` gives `None` when absent).
pub(crate) fn exact_opt<'de, D, T, const N: usize>(d: D) -> Result<Option<[T; N]>, D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de>,
{
    exact(d).map(Some)
}

/// An optional list of arrays of exactly `N` elements each.
pub(crate) fn exact_list_opt<'de, D, T, const N: usize>(
    d: D,
) -> Result<Option<Vec<[T; N]>>, D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de>,
{
    let v: Vec<Vec<T>> = Vec::deserialize(d)?;
    v.into_iter()
        .enumerate()
        .map(|(i, x)| {
            let len = x.len();
            x.try_into().map_err(|_| {
                D::Error::custom(format!(
                    "element {i}: expected exactly {N} components, got {len}"
                ))
            })
        })
        .collect::<Result<Vec<_>, _>>()
        .map(Some)
}
