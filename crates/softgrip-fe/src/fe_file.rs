//! [`FeFile`]: one embedded FE file, its [`Schema`] and its typed rows and points.

use serde::de::DeserializeOwned;

use crate::counterpart::Counterpart;
use crate::error::{Error, Result};
use crate::points::FePoint;
use crate::rows::{Force3dRow, ForceRow, FullRow, MeshConvergenceRow, SmallXRow};

/// The column layout of a file, i.e. which row type it parses into.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Schema {
    /// `delta_over_R, force_N, contact_radius_mm`: [`ForceRow`].
    Force,
    /// The force with radius estimators and run diagnostics: [`FullRow`].
    Full,
    /// Small-x points of both nu on two meshes: [`SmallXRow`].
    SmallX,
    /// Force and radius on three meshes: [`MeshConvergenceRow`].
    MeshConvergence,
    /// A 3D run's force and the patch's two semi-axes: [`Force3dRow`].
    Force3d,
    /// A pressure profile `r_mm, pressure_MPa` at one x: [`crate::PressureRow`] (no points).
    Pressure,
    /// A 3D run's pressure map `x_mm, z_mm, pressure_MPa, gap_mm` at one x:
    /// [`crate::PressureMapRow`] (no points).
    PressureMap,
}

/// One embedded FE file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FeFile {
    /// Path relative to `tests/data/fe/`.
    pub path: &'static str,
    /// Its column layout.
    pub schema: Schema,
    /// Poisson ratio of every run in the file [-] (`None`: per row, [`Schema::SmallX`]).
    pub nu: Option<f64>,
    /// What it holds.
    pub about: &'static str,
    /// The construction it models: `free` (a sphere between two plates), `flat` (a hemisphere
    /// bonded at its flat face) or `core` (a skin over a rigid core).
    pub geometry: &'static str,
    /// For `core`: skin thickness over outer radius t/R [-].
    pub thickness_ratio: Option<f64>,
    /// What the fingertip is pressed on.
    pub counterpart: Counterpart,
    pub(crate) text: &'static str,
}

impl FeFile {
    /// Whether the file is held out of every fit of the law (its `about` says so): a blind test.
    pub fn held_out(&self) -> bool {
        self.about.contains("held out")
    }

    /// The file's text as embedded.
    pub fn text(&self) -> &'static str {
        self.text
    }

    /// The file's own provenance: its comment lines (starting with `#`), without the `#`.
    pub fn provenance(&self) -> Vec<&'static str> {
        self.text
            .lines()
            .filter_map(|l| l.strip_prefix('#'))
            .map(str::trim)
            .collect()
    }

    /// The rows, typed (`T` is the row type of the file's [`Schema`]; lines starting with `#`
    /// are comments).
    pub fn rows<T: DeserializeOwned>(&self) -> Result<Vec<T>> {
        csv::ReaderBuilder::new()
            .comment(Some(b'#'))
            .trim(csv::Trim::All)
            .from_reader(self.text.as_bytes())
            .deserialize()
            .collect::<std::result::Result<Vec<T>, _>>()
            .map_err(|source| Error {
                path: self.path,
                source,
            })
    }

    /// The points, normalised like the law (force by `E*(nu)`, radius by R), in the file's
    /// order. The radius is the file's contact radius: `contact_radius_mm`, `a_lin_mm`, for
    /// [`Schema::MeshConvergence`] the fine (R/60) mesh's force and radius, the mesh of the
    /// other files, and for [`Schema::Force3d`] the semi-axis across the cylinder or edge
    /// (the one along it in [`FePoint::radius_along_norm`]). Files that are not force curves
    /// ([`Schema::Pressure`], [`Schema::PressureMap`]) have no
    /// points: an empty list (read their rows).
    pub fn points(&self) -> Result<Vec<FePoint>> {
        let nu = self.nu.unwrap_or(f64::NAN);
        Ok(match self.schema {
            Schema::Force => self
                .rows::<ForceRow>()?
                .into_iter()
                .map(|r| FePoint::from_si(nu, r.delta_over_r, r.force_n, r.contact_radius_mm))
                .collect(),
            Schema::Full => self
                .rows::<FullRow>()?
                .into_iter()
                .map(|r| FePoint {
                    min_element_j: Some(r.min_element_j),
                    ..FePoint::from_si(nu, r.delta_over_r, r.force_n, r.a_lin_mm)
                })
                .collect(),
            Schema::SmallX => self
                .rows::<SmallXRow>()?
                .into_iter()
                .map(|r| FePoint::from_si(r.nu, r.delta_over_r, r.force_n, r.a_lin_mm))
                .collect(),
            Schema::MeshConvergence => self
                .rows::<MeshConvergenceRow>()?
                .into_iter()
                .map(|r| FePoint::from_si(nu, r.delta_over_r, r.force_fine_n, r.a_fine))
                .collect(),
            Schema::Force3d => self
                .rows::<Force3dRow>()?
                .into_iter()
                .map(|r| FePoint {
                    radius_along_norm: Some(r.semi_axis_along_mm / crate::points::RADIUS_MM),
                    min_element_j: Some(r.min_element_j),
                    ..FePoint::from_si(nu, r.delta_over_r, r.force_n, r.semi_axis_across_mm)
                })
                .collect(),
            Schema::Pressure | Schema::PressureMap => Vec::new(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comment_lines_are_provenance_not_rows() {
        let f = FeFile {
            path: "free/example.csv",
            schema: Schema::Force,
            nu: Some(0.49),
            about: "a file of the next campaign",
            geometry: "free",
            thickness_ratio: None,
            counterpart: Counterpart::Plane,
            text: "# CalculiX 2.21, free sphere\n# mesh R/60\ndelta_over_R,force_N,contact_radius_mm\n\
                   0.01,0.0054149,0.0915245\n# a comment between rows\n0.02,0.0155219,0.141968\n",
        };
        assert_eq!(
            f.provenance(),
            [
                "CalculiX 2.21, free sphere",
                "mesh R/60",
                "a comment between rows"
            ]
        );
        let points = f.points().expect("parses");
        assert_eq!(points.len(), 2);
        assert_eq!(points[1].x, 0.02);
        assert_eq!(points[1].radius_norm, 0.141968);
    }

    #[test]
    fn a_malformed_number_names_the_file_and_line() {
        let f = FeFile {
            path: "bad.csv",
            schema: Schema::Force,
            nu: Some(0.3),
            about: "",
            geometry: "free",
            thickness_ratio: None,
            counterpart: Counterpart::Plane,
            text: "delta_over_R,force_N,contact_radius_mm\n0.1,abc,0.3\n",
        };
        let err = f.points().expect_err("bad number");
        let text = err.to_string();
        assert!(
            text.contains("bad.csv") && text.contains("line: 2"),
            "{text}"
        );
    }
}
