//! The finite-element reference of `tests/data/fe/` (CalculiX, compressible neo-Hookean
//! hemisphere, R = 1 mm, mu = 1 MPa), as `softgrip bench-law` uses it: the data sets it plots,
//! loaded through `softgrip-fe` (which embeds the files and parses them) and normalised like
//! the law.
//!
//! Units of the files: `force_N` \[N\], radii \[mm\]. With R = 1 mm the normalised force is
//! `f = F / (E* R^2) = force_N / E*[MPa]`, `E* = 2 mu (1 + nu) / (1 - nu^2)`, and the radius in
//! mm is `a / R`.

use anyhow::{Context, Result};

/// One embedded FE data set.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dataset {
    /// `full_nu0.3.csv`: nu = 0.3, every converged point to x = 0.85, with the smallest
    /// element Jacobian.
    FullNu03,
    /// Any embedded force file, by its path in `tests/data/fe/` (e.g. `flat/force_nu0.48.csv`).
    File(&'static str),
}

/// One FE point, normalised.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FePoint {
    /// Compression ratio x = delta/R [-].
    pub x: f64,
    /// Normalised force f = F / (E* R^2) [-].
    pub force_norm: f64,
    /// Normalised contact radius a / R [-] (resolved to about one element, R/60).
    pub radius_norm: f64,
    /// Smallest element Jacobian J [-] (volume ratio), where the file has it.
    pub min_element_j: Option<f64>,
}

/// A loaded data set.
#[derive(Debug, Clone, PartialEq)]
pub struct FeCurve {
    /// Which file.
    pub dataset: Dataset,
    /// Its points, in increasing x.
    pub points: Vec<FePoint>,
}

impl Dataset {
    /// File name in `tests/data/fe/`.
    pub fn file_name(self) -> &'static str {
        match self {
            Self::FullNu03 => "full_nu0.3.csv",
            Self::File(path) => path,
        }
    }

    /// Loads the embedded file (through `softgrip-fe`), normalised.
    pub fn load(self) -> Result<FeCurve> {
        let file = softgrip_fe::file(self.file_name())
            .with_context(|| format!("FE reference {} is not embedded", self.file_name()))?;
        let points = file
            .points()
            .with_context(|| format!("FE reference {}", self.file_name()))?
            .into_iter()
            .map(|p| FePoint {
                x: p.x,
                force_norm: p.force_norm,
                radius_norm: p.radius_norm,
                min_element_j: p.min_element_j,
            })
            .collect();
        Ok(FeCurve {
            dataset: self,
            points,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn embedded_files_load_with_their_ranges() {
        let f03 = Dataset::File("force_nu0.3.csv").load().expect("loads");
        let f049 = Dataset::File("force_nu0.49.csv").load().expect("loads");
        let full = Dataset::FullNu03.load().expect("loads");
        assert_eq!(f03.points.len(), 61);
        assert_eq!(f03.points.last().map(|p| p.x), Some(0.61));
        assert_eq!(f049.points.last().map(|p| p.x), Some(0.78));
        assert_eq!(full.points.last().map(|p| p.x), Some(0.85));
        assert_eq!(full.points[0].min_element_j, Some(0.9278));
        // x = 0.01, nu = 0.3: 0.00397964 N / E*, E* = 2 (1.3) / (1 - 0.09) MPa.
        let e_star = 2.6 / 0.91;
        assert!((f03.points[0].force_norm - 0.00397964 / e_star).abs() < 1e-15);
        // FE is 1-3.5 % above Hertz at small x (MODEL.md).
        let ratio = f03.points[0].force_norm / (4.0 / 3.0 * 0.01f64.powf(1.5));
        assert!(ratio > 1.01 && ratio < 1.05, "{ratio}");
    }
}
