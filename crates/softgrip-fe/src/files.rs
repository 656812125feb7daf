//! [`FILES`]: the one table of the embedded FE files. Adding a file is one row here.

use serde::de::DeserializeOwned;

use crate::error::{Error, Result};
use crate::points::FePoint;
use crate::rows::{ForceRow, FullRow, MeshConvergenceRow, SmallXRow};

/// The provenance of the whole reference set: `tests/data/fe/README.md`, embedded.
pub const PROVENANCE: &str = include_str!("../../../tests/data/fe/README.md");

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
    text: &'static str,
}

/// One row of [`FILES`]: the path (relative to `tests/data/fe/`), schema, nu and description.
macro_rules! fe_file {
    ($path:literal, $schema:ident, $nu:expr, $about:literal) => {
        fe_file!($path, $schema, $nu, $about, "free", None)
    };
    ($path:literal, $schema:ident, $nu:expr, $about:literal, $geometry:literal, $t:expr) => {
        FeFile {
            path: $path,
            schema: Schema::$schema,
            nu: $nu,
            about: $about,
            geometry: $geometry,
            thickness_ratio: $t,
            text: include_str!(concat!("../../../tests/data/fe/", $path)),
        }
    };
}

/// Every embedded file. CalculiX 2.20, axisymmetric compressible neo-Hookean hemisphere,
/// R = 1 mm, mu = 1 MPa ([`PROVENANCE`]).
pub const FILES: &[FeFile] = &[
    fe_file!(
        "force_nu0.3.csv",
        Force,
        Some(0.3),
        "nu = 0.3, x = 0.01..0.61 (beyond, the material collapses in volume)"
    ),
    fe_file!(
        "force_nu0.49.csv",
        Force,
        Some(0.49),
        "nu = 0.49, x = 0.01..0.78"
    ),
    fe_file!(
        "full_nu0.3.csv",
        Full,
        Some(0.3),
        "nu = 0.3, every converged point to x = 0.85, with radius estimators and the smallest element J"
    ),
    fe_file!(
        "full_nu0.49.csv",
        Full,
        Some(0.49),
        "nu = 0.49, the runs of force_nu0.49.csv with the same extra columns"
    ),
    fe_file!(
        "small_x_check.csv",
        SmallX,
        None,
        "x = 0.001..0.01 at nu = 0.3 and 0.49 on the fine (R/60) and extra-fine (R/120) mesh"
    ),
    fe_file!(
        "mesh_convergence_nu0.49.csv",
        MeshConvergence,
        Some(0.49),
        "nu = 0.49 on the R/30, R/60 and R/120 meshes at seven x"
    ),
    fe_file!(
        "free/force_nu0.3.csv",
        Force,
        Some(0.3),
        "softgrip's own FE (tools/fe), free sphere, nu = 0.3, x = 0.01..0.53",
        "free",
        None
    ),
    fe_file!(
        "free/force_nu0.4.csv",
        Force,
        Some(0.4),
        "softgrip's own FE (tools/fe), free sphere, nu = 0.4, x = 0.01..0.78",
        "free",
        None
    ),
    fe_file!(
        "free/force_nu0.45.csv",
        Force,
        Some(0.45),
        "softgrip's own FE (tools/fe), free sphere, nu = 0.45, x = 0.01..0.81",
        "free",
        None
    ),
    fe_file!(
        "free/force_nu0.49.csv",
        Force,
        Some(0.49),
        "softgrip's own FE (tools/fe), free sphere, nu = 0.49, x = 0.01..0.52",
        "free",
        None
    ),
    fe_file!(
        "flat/force_nu0.3.csv",
        Force,
        Some(0.3),
        "softgrip's own FE, hemisphere bonded at its flat face, nu = 0.3, x = 0.01..0.53",
        "flat",
        None
    ),
    fe_file!(
        "flat/force_nu0.4.csv",
        Force,
        Some(0.4),
        "softgrip's own FE, hemisphere bonded at its flat face, nu = 0.4, x = 0.01..0.46",
        "flat",
        None
    ),
    fe_file!(
        "flat/force_nu0.48.csv",
        Force,
        Some(0.48),
        "softgrip's own FE, hemisphere bonded at its flat face, nu = 0.48, x = 0.01..0.44",
        "flat",
        None
    ),
    fe_file!(
        "flat/force_nu0.499.csv",
        Force,
        Some(0.499),
        "softgrip's own FE, hemisphere bonded at its flat face, nu = 0.499, x = 0.01..0.31",
        "flat",
        None
    ),
    fe_file!(
        "core/force_nu0.3_t0.2.csv",
        Force,
        Some(0.3),
        "softgrip's own FE, skin t/R = 0.2 over a rigid core, nu = 0.3",
        "core",
        Some(0.2)
    ),
    fe_file!(
        "core/force_nu0.48_t0.2.csv",
        Force,
        Some(0.48),
        "softgrip's own FE, skin t/R = 0.2 over a rigid core, nu = 0.48",
        "core",
        Some(0.2)
    ),
    fe_file!(
        "core/force_nu0.499_t0.2.csv",
        Force,
        Some(0.499),
        "softgrip's own FE, skin t/R = 0.2 over a rigid core, nu = 0.499",
        "core",
        Some(0.2)
    ),
    fe_file!(
        "core/force_nu0.4_t0.2.csv",
        Force,
        Some(0.4),
        "softgrip's own FE, skin t/R = 0.2 over a rigid core, nu = 0.4, x = 0.01..0.15",
        "core",
        Some(0.2)
    ),
    fe_file!(
        "core/force_nu0.4_t0.4.csv",
        Force,
        Some(0.4),
        "softgrip's own FE, skin t/R = 0.4 over a rigid core, nu = 0.4, x = 0.01..0.3",
        "core",
        Some(0.4)
    ),
    fe_file!(
        "core/force_nu0.3_t0.4.csv",
        Force,
        Some(0.3),
        "softgrip's own FE, skin t/R = 0.4 over a rigid core, nu = 0.3",
        "core",
        Some(0.4)
    ),
    fe_file!(
        "core/force_nu0.48_t0.4.csv",
        Force,
        Some(0.48),
        "softgrip's own FE, skin t/R = 0.4 over a rigid core, nu = 0.48",
        "core",
        Some(0.4)
    ),
    fe_file!(
        "core/force_nu0.499_t0.4.csv",
        Force,
        Some(0.499),
        "softgrip's own FE, skin t/R = 0.4 over a rigid core, nu = 0.499",
        "core",
        Some(0.4)
    ),
    fe_file!(
        "core/force_nu0.3_t0.6.csv",
        Force,
        Some(0.3),
        "softgrip's own FE, skin t/R = 0.6 over a rigid core, nu = 0.3",
        "core",
        Some(0.6)
    ),
    fe_file!(
        "core/force_nu0.48_t0.6.csv",
        Force,
        Some(0.48),
        "softgrip's own FE, skin t/R = 0.6 over a rigid core, nu = 0.48",
        "core",
        Some(0.6)
    ),
    fe_file!(
        "core/force_nu0.499_t0.6.csv",
        Force,
        Some(0.499),
        "softgrip's own FE, skin t/R = 0.6 over a rigid core, nu = 0.499",
        "core",
        Some(0.6)
    ),
    fe_file!(
        "core/force_nu0.3_t0.8.csv",
        Force,
        Some(0.3),
        "softgrip's own FE, skin t/R = 0.8 over a rigid core, nu = 0.3",
        "core",
        Some(0.8)
    ),
    fe_file!(
        "core/force_nu0.48_t0.8.csv",
        Force,
        Some(0.48),
        "softgrip's own FE, skin t/R = 0.8 over a rigid core, nu = 0.48",
        "core",
        Some(0.8)
    ),
    fe_file!(
        "core/force_nu0.499_t0.8.csv",
        Force,
        Some(0.499),
        "softgrip's own FE, skin t/R = 0.8 over a rigid core, nu = 0.499",
        "core",
        Some(0.8)
    ),
    fe_file!(
        "flat/force_nu0.35.csv",
        Force,
        Some(0.35),
        "held out of every fit: hemisphere bonded at its flat face, nu = 0.35, x = 0.01..0.5 (end of the load)",
        "flat",
        None
    ),
    fe_file!(
        "flat/force_nu0.45.csv",
        Force,
        Some(0.45),
        "held out of every fit: hemisphere bonded at its flat face, nu = 0.45, x = 0.01..0.43",
        "flat",
        None
    ),
    fe_file!(
        "core/force_nu0.4_t0.3.csv",
        Force,
        Some(0.4),
        "held out of every fit: skin t/R = 0.3 over a rigid core, nu = 0.4, x = 0.01..0.23",
        "core",
        Some(0.3)
    ),
    fe_file!(
        "core/force_nu0.49_t0.3.csv",
        Force,
        Some(0.49),
        "held out of every fit: skin t/R = 0.3 over a rigid core, nu = 0.49, x = 0.01..0.2",
        "core",
        Some(0.3)
    ),
    fe_file!(
        "core/force_nu0.45_t0.5.csv",
        Force,
        Some(0.45),
        "held out of every fit: skin t/R = 0.5 over a rigid core, nu = 0.45, x = 0.01..0.39",
        "core",
        Some(0.5)
    ),
    fe_file!(
        "core/force_nu0.35_t0.7.csv",
        Force,
        Some(0.35),
        "held out of every fit: skin t/R = 0.7 over a rigid core, nu = 0.35, x = 0.01..0.5 (end of the load)",
        "core",
        Some(0.7)
    ),
    fe_file!(
        "core/force_nu0.46_t0.25.csv",
        Force,
        Some(0.46),
        "held out of every fit (the second set): skin t/R = 0.25 over a rigid core, nu = 0.46, x = 0.01..0.18",
        "core",
        Some(0.25)
    ),
    fe_file!(
        "core/force_nu0.33_t0.25.csv",
        Force,
        Some(0.33),
        "held out of every fit (the second set): skin t/R = 0.25 over a rigid core, nu = 0.33, x = 0.01..0.2",
        "core",
        Some(0.25)
    ),
    fe_file!(
        "core/force_nu0.42_t0.55.csv",
        Force,
        Some(0.42),
        "held out of every fit (the second set): skin t/R = 0.55 over a rigid core, nu = 0.42, x = 0.01..0.42",
        "core",
        Some(0.55)
    ),
    fe_file!(
        "core/force_nu0.36_t0.2.csv",
        Force,
        Some(0.36),
        "held out of every fit (the second set): skin t/R = 0.2 over a rigid core, nu = 0.36, x = 0.01..0.16",
        "core",
        Some(0.2)
    ),
    fe_file!(
        "core/force_nu0.44_t0.8.csv",
        Force,
        Some(0.44),
        "held out of every fit (the second set): skin t/R = 0.8 over a rigid core, nu = 0.44, x = 0.01..0.43",
        "core",
        Some(0.8)
    ),
    fe_file!(
        "core/force_nu0.495_t0.35.csv",
        Force,
        Some(0.495),
        "held out of every fit (the second set): skin t/R = 0.35 over a rigid core, nu = 0.495, x = 0.01..0.2",
        "core",
        Some(0.35)
    ),
];

/// The file at `path` (relative to `tests/data/fe/`), if it is embedded.
///
/// ```
/// let f = softgrip_fe::file("force_nu0.49.csv").unwrap();
/// assert_eq!(f.nu, Some(0.49));
/// assert_eq!(f.points().unwrap().last().unwrap().x, 0.78);
/// ```
pub fn file(path: &str) -> Option<&'static FeFile> {
    FILES.iter().find(|f| f.path == path)
}

/// The force reference at Poisson ratio `nu` (the [`Schema::Force`] file of that nu: 0.3 or
/// 0.49), if there is one.
pub fn force_reference(nu: f64) -> Option<&'static FeFile> {
    FILES
        .iter()
        .find(|f| f.schema == Schema::Force && f.nu == Some(nu) && !f.path.contains('/'))
}

impl FeFile {
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
    /// order. The radius is the file's contact radius: `contact_radius_mm`, `a_lin_mm` or, for
    /// [`Schema::MeshConvergence`], the fine (R/60) mesh's force and radius, the mesh of the
    /// other files.
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
