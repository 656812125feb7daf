//! [`COUNTERPART_FILES`]: every embedded FE file on a ball, a cylinder or an edge.
//!
//! Written by `tools/fe/fe_campaign.py export` (tools/fe/fe_table.py) from the files of
//! `tests/data/fe/{ball,cylinder,edge}/`; do not edit by hand.

use crate::counterpart::Counterpart;
use crate::fe_file::{FeFile, Schema};

/// One row: path (relative to `tests/data/fe/`), schema, nu, construction, counterpart,
/// description.
macro_rules! counterpart_file {
    ($path:literal, $schema:ident, $nu:expr, $geometry:literal, $cp:expr, $about:literal) => {
        FeFile {
            path: $path,
            schema: Schema::$schema,
            nu: Some($nu),
            about: $about,
            geometry: $geometry,
            thickness_ratio: None,
            counterpart: $cp,
            text: include_str!(concat!("../../../tests/data/fe/", $path)),
        }
    };
}

/// Every embedded file on a counterpart other than the plane (tools/fe: CalculiX 2.20, gmsh
/// 4.15.2; each file's provenance line says how it was made).
#[rustfmt::skip]
pub const COUNTERPART_FILES: &[FeFile] = &[
    counterpart_file!("ball/free/force_nu0.48_k0.5.csv", Force, 0.48, "free", Counterpart::Ball { k: 0.5 }, "ball k = 0.5, free, nu = 0.48, x = 0.01..0.7"),
    counterpart_file!("ball/free/force_nu0.48_k1.csv", Force, 0.48, "free", Counterpart::Ball { k: 1.0 }, "ball k = 1, free, nu = 0.48, x = 0.01..0.7"),
    counterpart_file!("ball/free/force_nu0.48_k2.csv", Force, 0.48, "free", Counterpart::Ball { k: 2.0 }, "ball k = 2, free, nu = 0.48, x = 0.01..0.7"),
    counterpart_file!("ball/free/force_nu0.48_k4.csv", Force, 0.48, "free", Counterpart::Ball { k: 4.0 }, "ball k = 4, free, nu = 0.48, x = 0.01..0.7"),
    counterpart_file!("ball/free/pressure_nu0.48_k0.5_d0.1.csv", Pressure, 0.48, "free", Counterpart::Ball { k: 0.5 }, "ball k = 0.5, free, nu = 0.48, pressure at x = 0.1"),
    counterpart_file!("ball/free/pressure_nu0.48_k0.5_d0.3.csv", Pressure, 0.48, "free", Counterpart::Ball { k: 0.5 }, "ball k = 0.5, free, nu = 0.48, pressure at x = 0.3"),
    counterpart_file!("ball/free/pressure_nu0.48_k0.5_d0.5.csv", Pressure, 0.48, "free", Counterpart::Ball { k: 0.5 }, "ball k = 0.5, free, nu = 0.48, pressure at x = 0.5"),
    counterpart_file!("ball/free/pressure_nu0.48_k1_d0.1.csv", Pressure, 0.48, "free", Counterpart::Ball { k: 1.0 }, "ball k = 1, free, nu = 0.48, pressure at x = 0.1"),
    counterpart_file!("ball/free/pressure_nu0.48_k1_d0.3.csv", Pressure, 0.48, "free", Counterpart::Ball { k: 1.0 }, "ball k = 1, free, nu = 0.48, pressure at x = 0.3"),
    counterpart_file!("ball/free/pressure_nu0.48_k1_d0.5.csv", Pressure, 0.48, "free", Counterpart::Ball { k: 1.0 }, "ball k = 1, free, nu = 0.48, pressure at x = 0.5"),
    counterpart_file!("ball/free/pressure_nu0.48_k2_d0.1.csv", Pressure, 0.48, "free", Counterpart::Ball { k: 2.0 }, "ball k = 2, free, nu = 0.48, pressure at x = 0.1"),
    counterpart_file!("ball/free/pressure_nu0.48_k2_d0.3.csv", Pressure, 0.48, "free", Counterpart::Ball { k: 2.0 }, "ball k = 2, free, nu = 0.48, pressure at x = 0.3"),
    counterpart_file!("ball/free/pressure_nu0.48_k2_d0.5.csv", Pressure, 0.48, "free", Counterpart::Ball { k: 2.0 }, "ball k = 2, free, nu = 0.48, pressure at x = 0.5"),
    counterpart_file!("ball/free/pressure_nu0.48_k4_d0.1.csv", Pressure, 0.48, "free", Counterpart::Ball { k: 4.0 }, "ball k = 4, free, nu = 0.48, pressure at x = 0.1"),
    counterpart_file!("ball/free/pressure_nu0.48_k4_d0.3.csv", Pressure, 0.48, "free", Counterpart::Ball { k: 4.0 }, "ball k = 4, free, nu = 0.48, pressure at x = 0.3"),
    counterpart_file!("ball/free/pressure_nu0.48_k4_d0.5.csv", Pressure, 0.48, "free", Counterpart::Ball { k: 4.0 }, "ball k = 4, free, nu = 0.48, pressure at x = 0.5"),
    counterpart_file!("ball/flat/force_nu0.48_k0.5.csv", Force, 0.48, "flat", Counterpart::Ball { k: 0.5 }, "ball k = 0.5, flat, nu = 0.48, x = 0.01..0.59"),
    counterpart_file!("ball/flat/force_nu0.48_k1.csv", Force, 0.48, "flat", Counterpart::Ball { k: 1.0 }, "ball k = 1, flat, nu = 0.48, x = 0.01..0.66"),
    counterpart_file!("ball/flat/force_nu0.48_k2.csv", Force, 0.48, "flat", Counterpart::Ball { k: 2.0 }, "ball k = 2, flat, nu = 0.48, x = 0.01..0.56"),
    counterpart_file!("ball/flat/force_nu0.48_k4.csv", Force, 0.48, "flat", Counterpart::Ball { k: 4.0 }, "ball k = 4, flat, nu = 0.48, x = 0.01..0.5"),
    counterpart_file!("ball/flat/pressure_nu0.48_k0.5_d0.1.csv", Pressure, 0.48, "flat", Counterpart::Ball { k: 0.5 }, "ball k = 0.5, flat, nu = 0.48, pressure at x = 0.1"),
    counterpart_file!("ball/flat/pressure_nu0.48_k0.5_d0.3.csv", Pressure, 0.48, "flat", Counterpart::Ball { k: 0.5 }, "ball k = 0.5, flat, nu = 0.48, pressure at x = 0.3"),
    counterpart_file!("ball/flat/pressure_nu0.48_k0.5_d0.5.csv", Pressure, 0.48, "flat", Counterpart::Ball { k: 0.5 }, "ball k = 0.5, flat, nu = 0.48, pressure at x = 0.5"),
    counterpart_file!("ball/flat/pressure_nu0.48_k1_d0.1.csv", Pressure, 0.48, "flat", Counterpart::Ball { k: 1.0 }, "ball k = 1, flat, nu = 0.48, pressure at x = 0.1"),
    counterpart_file!("ball/flat/pressure_nu0.48_k1_d0.3.csv", Pressure, 0.48, "flat", Counterpart::Ball { k: 1.0 }, "ball k = 1, flat, nu = 0.48, pressure at x = 0.3"),
    counterpart_file!("ball/flat/pressure_nu0.48_k1_d0.5.csv", Pressure, 0.48, "flat", Counterpart::Ball { k: 1.0 }, "ball k = 1, flat, nu = 0.48, pressure at x = 0.5"),
    counterpart_file!("ball/flat/pressure_nu0.48_k2_d0.1.csv", Pressure, 0.48, "flat", Counterpart::Ball { k: 2.0 }, "ball k = 2, flat, nu = 0.48, pressure at x = 0.1"),
    counterpart_file!("ball/flat/pressure_nu0.48_k2_d0.3.csv", Pressure, 0.48, "flat", Counterpart::Ball { k: 2.0 }, "ball k = 2, flat, nu = 0.48, pressure at x = 0.3"),
    counterpart_file!("ball/flat/pressure_nu0.48_k2_d0.5.csv", Pressure, 0.48, "flat", Counterpart::Ball { k: 2.0 }, "ball k = 2, flat, nu = 0.48, pressure at x = 0.5"),
    counterpart_file!("ball/flat/pressure_nu0.48_k4_d0.1.csv", Pressure, 0.48, "flat", Counterpart::Ball { k: 4.0 }, "ball k = 4, flat, nu = 0.48, pressure at x = 0.1"),
    counterpart_file!("ball/flat/pressure_nu0.48_k4_d0.3.csv", Pressure, 0.48, "flat", Counterpart::Ball { k: 4.0 }, "ball k = 4, flat, nu = 0.48, pressure at x = 0.3"),
    counterpart_file!("ball/flat/pressure_nu0.48_k4_d0.5.csv", Pressure, 0.48, "flat", Counterpart::Ball { k: 4.0 }, "ball k = 4, flat, nu = 0.48, pressure at x = 0.5"),
    counterpart_file!("cylinder/flat/force_nu0.48_k1.csv", Force3d, 0.48, "flat", Counterpart::Cylinder { k: 1.0 }, "cylinder k = 1, flat, nu = 0.48, x = 0.01..0.44"),
    counterpart_file!("cylinder/flat/pressure_nu0.48_k1_d0.1.csv", PressureMap, 0.48, "flat", Counterpart::Cylinder { k: 1.0 }, "cylinder k = 1, flat, nu = 0.48, pressure at x = 0.1"),
    counterpart_file!("cylinder/flat/pressure_nu0.48_k1_d0.3.csv", PressureMap, 0.48, "flat", Counterpart::Cylinder { k: 1.0 }, "cylinder k = 1, flat, nu = 0.48, pressure at x = 0.3"),
];
