//! [`FILES`]: the one table of the embedded FE files on a plane. Adding a file is one row
//! here; the files on other counterparts are [`COUNTERPART_FILES`] and, for a skin on a core,
//! [`CORE_COUNTERPART_FILES`], written by `tools/fe/fe_campaign.py export`.

pub use crate::core_counterpart_files::CORE_COUNTERPART_FILES;
use crate::counterpart::Counterpart;
pub use crate::counterpart_files::COUNTERPART_FILES;
use crate::fe_file::{FeFile, Schema};

/// The provenance of the whole reference set: `tests/data/fe/README.md`, embedded.
pub const PROVENANCE: &str = include_str!("../../../tests/data/fe/README.md");

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
            counterpart: Counterpart::Plane,
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
    fe_file!(
        "core/force_nu0.47_t0.15.csv",
        Force,
        Some(0.47),
        "held out of every fit (the third set, session 11): skin t/R = 0.15 over a rigid core, nu = 0.47, x = 0.01..0.08",
        "core",
        Some(0.15)
    ),
    fe_file!(
        "core/force_nu0.42_t0.25.csv",
        Force,
        Some(0.42),
        "held out of every fit (the third set, session 11): skin t/R = 0.25 over a rigid core, nu = 0.42, x = 0.01..0.18",
        "core",
        Some(0.25)
    ),
    fe_file!(
        "core/force_nu0.38_t0.12.csv",
        Force,
        Some(0.38),
        "held out of every fit (the fourth set, session 13): skin t/R = 0.12 over a rigid core, nu = 0.38, R/75, x = 0.01..0.08",
        "core",
        Some(0.12)
    ),
    fe_file!(
        "core/force_nu0.46_t0.1.csv",
        Force,
        Some(0.46),
        "held out of every fit (the fourth set, session 13): skin t/R = 0.1 over a rigid core, nu = 0.46, R/60, x = 0.01..0.04",
        "core",
        Some(0.1)
    ),
    fe_file!(
        "core/force_nu0.32_t0.14.csv",
        Force,
        Some(0.32),
        "held out of every fit (the fourth set, session 13): skin t/R = 0.14 over a rigid core, nu = 0.32, R/60, x = 0.01..0.1",
        "core",
        Some(0.14)
    ),
    fe_file!(
        "core/force_nu0.49_t0.12.csv",
        Force,
        Some(0.49),
        "held out of every fit (the fourth set, session 13): skin t/R = 0.12 over a rigid core, nu = 0.49, R/60, x = 0.01..0.05",
        "core",
        Some(0.12)
    ),
    fe_file!(
        "core/force_nu0.48_t0.3.csv",
        Force,
        Some(0.48),
        "softgrip's own FE (session 15, fit data between the fitted t/R 0.2 and 0.4): skin t/R = 0.3 over a rigid core, nu = 0.48, x = 0.01..0.2",
        "core",
        Some(0.3)
    ),
    fe_file!(
        "core/force_nu0.35_t0.3.csv",
        Force,
        Some(0.35),
        "softgrip's own FE (session 15, fit data between the fitted t/R 0.2 and 0.4): skin t/R = 0.3 over a rigid core, nu = 0.35, x = 0.01..0.24",
        "core",
        Some(0.3)
    ),
    fe_file!(
        "core/force_nu0.47_t0.25.csv",
        Force,
        Some(0.47),
        "held out of every fit (session 15, blind): skin t/R = 0.25 over a rigid core, nu = 0.47, x = 0.01..0.17",
        "core",
        Some(0.25)
    ),
    fe_file!(
        "core/force_nu0.45_t0.35.csv",
        Force,
        Some(0.45),
        "softgrip's own FE (session 15, fit data between the fitted t/R 0.2 and 0.4): skin t/R = 0.35 over a rigid core, nu = 0.45, x = 0.01..0.25",
        "core",
        Some(0.35)
    ),
    fe_file!(
        "core/force_nu0.49_t0.25.csv",
        Force,
        Some(0.49),
        "softgrip's own FE (session 15, fit data between the fitted t/R 0.2 and 0.4): skin t/R = 0.25 over a rigid core, nu = 0.49, x = 0.01..0.15",
        "core",
        Some(0.25)
    ),
    fe_file!(
        "core/force_nu0.4_t0.08.csv",
        Force,
        Some(0.4),
        "held out of every fit (the sixth set, session 20, blind): skin t/R = 0.08 over a rigid core, nu = 0.4, R/75 (R/100 within 0.16 %), x = 0.01..0.04",
        "core",
        Some(0.08)
    ),
    fe_file!(
        "core/force_nu0.3_t0.08.csv",
        Force,
        Some(0.3),
        "held out of every fit (the sixth set, session 20, blind): skin t/R = 0.08 over a rigid core, nu = 0.3, R/75, x = 0.01..0.05",
        "core",
        Some(0.08)
    ),
    fe_file!(
        "core/force_nu0.3_t0.05.csv",
        Force,
        Some(0.3),
        "softgrip's own FE (session 20, fit data for the thin-layer floor): skin t/R = 0.05 over a rigid core, nu = 0.3, R/120, x = 0.005..0.03",
        "core",
        Some(0.05)
    ),
    fe_file!(
        "core/force_nu0.4_t0.05.csv",
        Force,
        Some(0.4),
        "softgrip's own FE (session 20, fit data for the thin-layer floor): skin t/R = 0.05 over a rigid core, nu = 0.4, R/120, x = 0.005..0.025",
        "core",
        Some(0.05)
    ),
    fe_file!(
        "core/force_nu0.3_t0.1.csv",
        Force,
        Some(0.3),
        "softgrip's own FE (session 20, fit data for the thin-layer floor): skin t/R = 0.1 over a rigid core, nu = 0.3, R/60, x = 0.01..0.07",
        "core",
        Some(0.1)
    ),
    fe_file!(
        "core/force_nu0.48_t0.1.csv",
        Force,
        Some(0.48),
        "softgrip's own FE (session 20, fit data for the thin-layer floor): skin t/R = 0.1 over a rigid core, nu = 0.48, R/60, x = 0.01..0.04",
        "core",
        Some(0.1)
    ),
    fe_file!(
        "core/force_nu0.4_t0.1.csv",
        Force,
        Some(0.4),
        "softgrip's own FE (session 20, fit data for the thin-layer floor): skin t/R = 0.1 over a rigid core, nu = 0.4, R/60, x = 0.01..0.06",
        "core",
        Some(0.1)
    ),
    fe_file!(
        "core/force_nu0.48_t0.08.csv",
        Force,
        Some(0.48),
        "held out of every fit (session 21, blind: run after the thin-layer floor's constants were fixed): skin t/R = 0.08 over a rigid core, nu = 0.48, R/80, increments <= 0.0005, x = 0.0025..0.0325",
        "core",
        Some(0.08)
    ),
    fe_file!(
        "core/force_nu0.4_t0.06.csv",
        Force,
        Some(0.4),
        "held out of every fit (session 21, blind: run after the thin-layer floor's constants were fixed): skin t/R = 0.06 over a rigid core, nu = 0.4, R/100, increments <= 0.001, x = 0.0025..0.03",
        "core",
        Some(0.06)
    ),
    fe_file!(
        "core/force_nu0.48_t0.06.csv",
        Force,
        Some(0.48),
        "held out of every fit (session 21, blind: run after the thin-layer floor's constants were fixed): skin t/R = 0.06 over a rigid core, nu = 0.48, R/100, increments <= 0.0005, x = 0.0025..0.02",
        "core",
        Some(0.06)
    ),
    fe_file!(
        "core/force_nu0.45_t0.07.csv",
        Force,
        Some(0.45),
        "held out of every fit (session 21, blind: run after the thin-layer floor's constants were fixed): skin t/R = 0.07 over a rigid core, nu = 0.45, R/90, increments <= 0.0005, x = 0.0025..0.0275",
        "core",
        Some(0.07)
    ),
];

/// Every embedded file: [`FILES`] (the plane), then [`COUNTERPART_FILES`], then
/// [`CORE_COUNTERPART_FILES`].
pub fn all() -> impl Iterator<Item = &'static FeFile> {
    FILES
        .iter()
        .chain(COUNTERPART_FILES.iter())
        .chain(CORE_COUNTERPART_FILES.iter())
}

/// The file at `path` (relative to `tests/data/fe/`), if it is embedded.
///
/// ```
/// let f = softgrip_fe::file("force_nu0.49.csv").unwrap();
/// assert_eq!(f.nu, Some(0.49));
/// assert_eq!(f.points().unwrap().last().unwrap().x, 0.78);
/// ```
pub fn file(path: &str) -> Option<&'static FeFile> {
    all().find(|f| f.path == path)
}

/// The force reference at Poisson ratio `nu` (the [`Schema::Force`] file of that nu: 0.3 or
/// 0.49), if there is one.
pub fn force_reference(nu: f64) -> Option<&'static FeFile> {
    FILES
        .iter()
        .find(|f| f.schema == Schema::Force && f.nu == Some(nu) && !f.path.contains('/'))
}

/// The campaign's force curve of one case, keyed by what it is pressed on, the construction
/// (`free`, `flat`, `core`), nu and (`core`) t/R: `None` if there is no such run.
///
/// ```
/// use softgrip_fe::Counterpart;
/// let f = softgrip_fe::force_file(Counterpart::Ball { k: 1.0 }, "free", 0.48, None).unwrap();
/// assert_eq!(f.path, "ball/free/force_nu0.48_k1.csv");
/// // At small x a ball of the fingertip's size is Hertz with R_eff = R/2: 0.7x the plane.
/// let p = &f.points().unwrap()[0];
/// let hertz = 4.0 / 3.0 * 0.5f64.sqrt() * p.x.powf(1.5);
/// assert!((p.force_norm / hertz - 1.0).abs() < 0.03);
/// # Ok::<(), softgrip_fe::Error>(())
/// ```
pub fn force_file(
    counterpart: Counterpart,
    geometry: &str,
    nu: f64,
    thickness_ratio: Option<f64>,
) -> Option<&'static FeFile> {
    all().find(|f| {
        matches!(f.schema, Schema::Force | Schema::Force3d)
            && f.path.contains('/')
            && f.counterpart == counterpart
            && f.geometry == geometry
            && f.nu == Some(nu)
            && f.thickness_ratio == thickness_ratio
    })
}
