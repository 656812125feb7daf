//! [`CORE_COUNTERPART_FILES`]: every embedded FE file of a skin on a core pressed on a
//! ball, a cylinder or an edge.
//!
//! Written by `tools/fe/fe_campaign.py export` (tools/fe/fe_table.py) from the files of
//! `tests/data/fe/{ball,cylinder,edge}/core/`; do not edit by hand.

use crate::counterpart::Counterpart;
use crate::fe_file::{FeFile, Schema};

/// One row: path (relative to `tests/data/fe/`), schema, nu, t/R, counterpart, description.
macro_rules! core_counterpart_file {
    ($path:literal, $schema:ident, $nu:expr, $t:expr, $cp:expr, $about:literal) => {
        FeFile {
            path: $path,
            schema: Schema::$schema,
            nu: Some($nu),
            about: $about,
            geometry: "core",
            thickness_ratio: Some($t),
            counterpart: $cp,
            text: include_str!(concat!("../../../tests/data/fe/", $path)),
        }
    };
}

/// Every embedded file of a skin on a rigid core pressed on a rigid ball, cylinder or edge
/// (tools/fe: CalculiX 2.20, gmsh 4.15.2; each file's provenance line says how it was
/// made).
#[rustfmt::skip]
pub const CORE_COUNTERPART_FILES: &[FeFile] = &[
    core_counterpart_file!("ball/core/force_nu0.33_t0.45_k3.csv", Force, 0.33, 0.45, Counterpart::Ball { k: 3.0 }, "held out of every fit: ball k = 3, core t/R = 0.45, nu = 0.33, x = 0.01..0.36"),
    core_counterpart_file!("ball/core/force_nu0.36_t0.3_k1.csv", Force, 0.36, 0.3, Counterpart::Ball { k: 1.0 }, "held out of every fit: ball k = 1, core t/R = 0.3, nu = 0.36, x = 0.01..0.23"),
    core_counterpart_file!("ball/core/force_nu0.3_t0.4_k2.csv", Force, 0.3, 0.4, Counterpart::Ball { k: 2.0 }, "ball k = 2, core t/R = 0.4, nu = 0.3, x = 0.01..0.33"),
    core_counterpart_file!("ball/core/force_nu0.3_t0.5_k1.csv", Force, 0.3, 0.5, Counterpart::Ball { k: 1.0 }, "held out of every fit: ball k = 1, core t/R = 0.5, nu = 0.3, x = 0.01..0.4"),
    core_counterpart_file!("ball/core/force_nu0.42_t0.5_k1.5.csv", Force, 0.42, 0.5, Counterpart::Ball { k: 1.5 }, "held out of every fit: ball k = 1.5, core t/R = 0.5, nu = 0.42, x = 0.01..0.39"),
    core_counterpart_file!("ball/core/force_nu0.43_t0.6_k2.csv", Force, 0.43, 0.6, Counterpart::Ball { k: 2.0 }, "held out of every fit: ball k = 2, core t/R = 0.6, nu = 0.43, x = 0.01..0.48"),
    core_counterpart_file!("ball/core/force_nu0.45_t0.6_k3.csv", Force, 0.45, 0.6, Counterpart::Ball { k: 3.0 }, "held out of every fit: ball k = 3, core t/R = 0.6, nu = 0.45, x = 0.01..0.48"),
    core_counterpart_file!("ball/core/force_nu0.46_t0.55_k0.6.csv", Force, 0.46, 0.55, Counterpart::Ball { k: 0.6 }, "held out of every fit: ball k = 0.6, core t/R = 0.55, nu = 0.46, x = 0.01..0.4"),
    core_counterpart_file!("ball/core/force_nu0.47_t0.5_k0.7.csv", Force, 0.47, 0.5, Counterpart::Ball { k: 0.7 }, "held out of every fit: ball k = 0.7, core t/R = 0.5, nu = 0.47, x = 0.01..0.37"),
    core_counterpart_file!("ball/core/force_nu0.48_t0.3_k1.csv", Force, 0.48, 0.3, Counterpart::Ball { k: 1.0 }, "ball k = 1, core t/R = 0.3, nu = 0.48, x = 0.01..0.2"),
    core_counterpart_file!("ball/core/force_nu0.48_t0.3_k3.csv", Force, 0.48, 0.3, Counterpart::Ball { k: 3.0 }, "ball k = 3, core t/R = 0.3, nu = 0.48, x = 0.01..0.2"),
    core_counterpart_file!("ball/core/force_nu0.48_t0.4_k2.csv", Force, 0.48, 0.4, Counterpart::Ball { k: 2.0 }, "held out of every fit: ball k = 2, core t/R = 0.4, nu = 0.48, x = 0.01..0.29"),
    core_counterpart_file!("ball/core/force_nu0.48_t0.5_k1.csv", Force, 0.48, 0.5, Counterpart::Ball { k: 1.0 }, "ball k = 1, core t/R = 0.5, nu = 0.48, x = 0.01..0.38"),
    core_counterpart_file!("ball/core/force_nu0.48_t0.5_k3.csv", Force, 0.48, 0.5, Counterpart::Ball { k: 3.0 }, "ball k = 3, core t/R = 0.5, nu = 0.48, x = 0.01..0.38"),
    core_counterpart_file!("ball/core/force_nu0.48_t0.65_k4.csv", Force, 0.48, 0.65, Counterpart::Ball { k: 4.0 }, "held out of every fit: ball k = 4, core t/R = 0.65, nu = 0.48, x = 0.01..0.49"),
    core_counterpart_file!("ball/core/force_nu0.49_t0.45_k1.5.csv", Force, 0.49, 0.45, Counterpart::Ball { k: 1.5 }, "held out of every fit: ball k = 1.5, core t/R = 0.45, nu = 0.49, x = 0.01..0.32"),
    core_counterpart_file!("ball/core/force_nu0.49_t0.4_k0.8.csv", Force, 0.49, 0.4, Counterpart::Ball { k: 0.8 }, "held out of every fit: ball k = 0.8, core t/R = 0.4, nu = 0.49, x = 0.01..0.24"),
    core_counterpart_file!("ball/core/force_nu0.4_t0.35_k1.5.csv", Force, 0.4, 0.35, Counterpart::Ball { k: 1.5 }, "held out of every fit: ball k = 1.5, core t/R = 0.35, nu = 0.4, x = 0.01..0.27"),
    core_counterpart_file!("ball/core/force_nu0.4_t0.5_k3.csv", Force, 0.4, 0.5, Counterpart::Ball { k: 3.0 }, "held out of every fit: ball k = 3, core t/R = 0.5, nu = 0.4, x = 0.01..0.4"),
    core_counterpart_file!("ball/core/pressure_nu0.33_t0.45_k3_d0.1.csv", Pressure, 0.33, 0.45, Counterpart::Ball { k: 3.0 }, "held out of every fit: ball k = 3, core t/R = 0.45, nu = 0.33, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.33_t0.45_k3_d0.3.csv", Pressure, 0.33, 0.45, Counterpart::Ball { k: 3.0 }, "held out of every fit: ball k = 3, core t/R = 0.45, nu = 0.33, pressure at x = 0.3"),
    core_counterpart_file!("ball/core/pressure_nu0.36_t0.3_k1_d0.1.csv", Pressure, 0.36, 0.3, Counterpart::Ball { k: 1.0 }, "held out of every fit: ball k = 1, core t/R = 0.3, nu = 0.36, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.3_t0.4_k2_d0.1.csv", Pressure, 0.3, 0.4, Counterpart::Ball { k: 2.0 }, "ball k = 2, core t/R = 0.4, nu = 0.3, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.3_t0.4_k2_d0.3.csv", Pressure, 0.3, 0.4, Counterpart::Ball { k: 2.0 }, "ball k = 2, core t/R = 0.4, nu = 0.3, pressure at x = 0.3"),
    core_counterpart_file!("ball/core/pressure_nu0.3_t0.5_k1_d0.1.csv", Pressure, 0.3, 0.5, Counterpart::Ball { k: 1.0 }, "held out of every fit: ball k = 1, core t/R = 0.5, nu = 0.3, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.3_t0.5_k1_d0.3.csv", Pressure, 0.3, 0.5, Counterpart::Ball { k: 1.0 }, "held out of every fit: ball k = 1, core t/R = 0.5, nu = 0.3, pressure at x = 0.3"),
    core_counterpart_file!("ball/core/pressure_nu0.42_t0.5_k1.5_d0.1.csv", Pressure, 0.42, 0.5, Counterpart::Ball { k: 1.5 }, "held out of every fit: ball k = 1.5, core t/R = 0.5, nu = 0.42, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.42_t0.5_k1.5_d0.3.csv", Pressure, 0.42, 0.5, Counterpart::Ball { k: 1.5 }, "held out of every fit: ball k = 1.5, core t/R = 0.5, nu = 0.42, pressure at x = 0.3"),
    core_counterpart_file!("ball/core/pressure_nu0.43_t0.6_k2_d0.1.csv", Pressure, 0.43, 0.6, Counterpart::Ball { k: 2.0 }, "held out of every fit: ball k = 2, core t/R = 0.6, nu = 0.43, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.43_t0.6_k2_d0.3.csv", Pressure, 0.43, 0.6, Counterpart::Ball { k: 2.0 }, "held out of every fit: ball k = 2, core t/R = 0.6, nu = 0.43, pressure at x = 0.3"),
    core_counterpart_file!("ball/core/pressure_nu0.45_t0.6_k3_d0.1.csv", Pressure, 0.45, 0.6, Counterpart::Ball { k: 3.0 }, "held out of every fit: ball k = 3, core t/R = 0.6, nu = 0.45, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.45_t0.6_k3_d0.3.csv", Pressure, 0.45, 0.6, Counterpart::Ball { k: 3.0 }, "held out of every fit: ball k = 3, core t/R = 0.6, nu = 0.45, pressure at x = 0.3"),
    core_counterpart_file!("ball/core/pressure_nu0.46_t0.55_k0.6_d0.1.csv", Pressure, 0.46, 0.55, Counterpart::Ball { k: 0.6 }, "held out of every fit: ball k = 0.6, core t/R = 0.55, nu = 0.46, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.46_t0.55_k0.6_d0.3.csv", Pressure, 0.46, 0.55, Counterpart::Ball { k: 0.6 }, "held out of every fit: ball k = 0.6, core t/R = 0.55, nu = 0.46, pressure at x = 0.3"),
    core_counterpart_file!("ball/core/pressure_nu0.47_t0.5_k0.7_d0.1.csv", Pressure, 0.47, 0.5, Counterpart::Ball { k: 0.7 }, "held out of every fit: ball k = 0.7, core t/R = 0.5, nu = 0.47, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.47_t0.5_k0.7_d0.3.csv", Pressure, 0.47, 0.5, Counterpart::Ball { k: 0.7 }, "held out of every fit: ball k = 0.7, core t/R = 0.5, nu = 0.47, pressure at x = 0.3"),
    core_counterpart_file!("ball/core/pressure_nu0.48_t0.3_k1_d0.1.csv", Pressure, 0.48, 0.3, Counterpart::Ball { k: 1.0 }, "ball k = 1, core t/R = 0.3, nu = 0.48, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.48_t0.3_k3_d0.1.csv", Pressure, 0.48, 0.3, Counterpart::Ball { k: 3.0 }, "ball k = 3, core t/R = 0.3, nu = 0.48, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.48_t0.4_k2_d0.1.csv", Pressure, 0.48, 0.4, Counterpart::Ball { k: 2.0 }, "held out of every fit: ball k = 2, core t/R = 0.4, nu = 0.48, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.48_t0.5_k1_d0.1.csv", Pressure, 0.48, 0.5, Counterpart::Ball { k: 1.0 }, "ball k = 1, core t/R = 0.5, nu = 0.48, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.48_t0.5_k1_d0.3.csv", Pressure, 0.48, 0.5, Counterpart::Ball { k: 1.0 }, "ball k = 1, core t/R = 0.5, nu = 0.48, pressure at x = 0.3"),
    core_counterpart_file!("ball/core/pressure_nu0.48_t0.5_k3_d0.1.csv", Pressure, 0.48, 0.5, Counterpart::Ball { k: 3.0 }, "ball k = 3, core t/R = 0.5, nu = 0.48, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.48_t0.5_k3_d0.3.csv", Pressure, 0.48, 0.5, Counterpart::Ball { k: 3.0 }, "ball k = 3, core t/R = 0.5, nu = 0.48, pressure at x = 0.3"),
    core_counterpart_file!("ball/core/pressure_nu0.48_t0.65_k4_d0.1.csv", Pressure, 0.48, 0.65, Counterpart::Ball { k: 4.0 }, "held out of every fit: ball k = 4, core t/R = 0.65, nu = 0.48, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.48_t0.65_k4_d0.3.csv", Pressure, 0.48, 0.65, Counterpart::Ball { k: 4.0 }, "held out of every fit: ball k = 4, core t/R = 0.65, nu = 0.48, pressure at x = 0.3"),
    core_counterpart_file!("ball/core/pressure_nu0.49_t0.45_k1.5_d0.1.csv", Pressure, 0.49, 0.45, Counterpart::Ball { k: 1.5 }, "held out of every fit: ball k = 1.5, core t/R = 0.45, nu = 0.49, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.49_t0.45_k1.5_d0.3.csv", Pressure, 0.49, 0.45, Counterpart::Ball { k: 1.5 }, "held out of every fit: ball k = 1.5, core t/R = 0.45, nu = 0.49, pressure at x = 0.3"),
    core_counterpart_file!("ball/core/pressure_nu0.49_t0.4_k0.8_d0.1.csv", Pressure, 0.49, 0.4, Counterpart::Ball { k: 0.8 }, "held out of every fit: ball k = 0.8, core t/R = 0.4, nu = 0.49, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.4_t0.35_k1.5_d0.1.csv", Pressure, 0.4, 0.35, Counterpart::Ball { k: 1.5 }, "held out of every fit: ball k = 1.5, core t/R = 0.35, nu = 0.4, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.4_t0.5_k3_d0.1.csv", Pressure, 0.4, 0.5, Counterpart::Ball { k: 3.0 }, "held out of every fit: ball k = 3, core t/R = 0.5, nu = 0.4, pressure at x = 0.1"),
    core_counterpart_file!("ball/core/pressure_nu0.4_t0.5_k3_d0.3.csv", Pressure, 0.4, 0.5, Counterpart::Ball { k: 3.0 }, "held out of every fit: ball k = 3, core t/R = 0.5, nu = 0.4, pressure at x = 0.3"),
    core_counterpart_file!("cylinder/core/force_nu0.42_t0.45_k2.csv", Force3d, 0.42, 0.45, Counterpart::Cylinder { k: 2.0 }, "held out of every fit: cylinder k = 2, core t/R = 0.45, nu = 0.42, x = 0.01..0.36"),
    core_counterpart_file!("cylinder/core/force_nu0.48_t0.4_k1.csv", Force3d, 0.48, 0.4, Counterpart::Cylinder { k: 1.0 }, "held out of every fit: cylinder k = 1, core t/R = 0.4, nu = 0.48, x = 0.01..0.26"),
    core_counterpart_file!("cylinder/core/force_nu0.48_t0.4_k3.csv", Force3d, 0.48, 0.4, Counterpart::Cylinder { k: 3.0 }, "held out of every fit: cylinder k = 3, core t/R = 0.4, nu = 0.48, x = 0.01..0.34"),
    core_counterpart_file!("cylinder/core/force_nu0.48_t0.5_k1.csv", Force3d, 0.48, 0.5, Counterpart::Cylinder { k: 1.0 }, "held out of every fit: cylinder k = 1, core t/R = 0.5, nu = 0.48, x = 0.01..0.36"),
    core_counterpart_file!("cylinder/core/force_nu0.48_t0.5_k3.csv", Force3d, 0.48, 0.5, Counterpart::Cylinder { k: 3.0 }, "held out of every fit: cylinder k = 3, core t/R = 0.5, nu = 0.48, x = 0.01..0.37"),
    core_counterpart_file!("cylinder/core/pressure_nu0.42_t0.45_k2_d0.1.csv", PressureMap, 0.42, 0.45, Counterpart::Cylinder { k: 2.0 }, "held out of every fit: cylinder k = 2, core t/R = 0.45, nu = 0.42, pressure at x = 0.1"),
    core_counterpart_file!("cylinder/core/pressure_nu0.42_t0.45_k2_d0.3.csv", PressureMap, 0.42, 0.45, Counterpart::Cylinder { k: 2.0 }, "held out of every fit: cylinder k = 2, core t/R = 0.45, nu = 0.42, pressure at x = 0.3"),
    core_counterpart_file!("cylinder/core/pressure_nu0.48_t0.4_k1_d0.1.csv", PressureMap, 0.48, 0.4, Counterpart::Cylinder { k: 1.0 }, "held out of every fit: cylinder k = 1, core t/R = 0.4, nu = 0.48, pressure at x = 0.1"),
    core_counterpart_file!("cylinder/core/pressure_nu0.48_t0.4_k3_d0.1.csv", PressureMap, 0.48, 0.4, Counterpart::Cylinder { k: 3.0 }, "held out of every fit: cylinder k = 3, core t/R = 0.4, nu = 0.48, pressure at x = 0.1"),
    core_counterpart_file!("cylinder/core/pressure_nu0.48_t0.4_k3_d0.3.csv", PressureMap, 0.48, 0.4, Counterpart::Cylinder { k: 3.0 }, "held out of every fit: cylinder k = 3, core t/R = 0.4, nu = 0.48, pressure at x = 0.3"),
    core_counterpart_file!("cylinder/core/pressure_nu0.48_t0.5_k1_d0.1.csv", PressureMap, 0.48, 0.5, Counterpart::Cylinder { k: 1.0 }, "held out of every fit: cylinder k = 1, core t/R = 0.5, nu = 0.48, pressure at x = 0.1"),
    core_counterpart_file!("cylinder/core/pressure_nu0.48_t0.5_k1_d0.3.csv", PressureMap, 0.48, 0.5, Counterpart::Cylinder { k: 1.0 }, "held out of every fit: cylinder k = 1, core t/R = 0.5, nu = 0.48, pressure at x = 0.3"),
    core_counterpart_file!("cylinder/core/pressure_nu0.48_t0.5_k3_d0.1.csv", PressureMap, 0.48, 0.5, Counterpart::Cylinder { k: 3.0 }, "held out of every fit: cylinder k = 3, core t/R = 0.5, nu = 0.48, pressure at x = 0.1"),
    core_counterpart_file!("cylinder/core/pressure_nu0.48_t0.5_k3_d0.3.csv", PressureMap, 0.48, 0.5, Counterpart::Cylinder { k: 3.0 }, "held out of every fit: cylinder k = 3, core t/R = 0.5, nu = 0.48, pressure at x = 0.3"),
    core_counterpart_file!("edge/core/force_nu0.3_t0.5.csv", Force3d, 0.3, 0.5, Counterpart::Edge, "held out of every fit: edge, core t/R = 0.5, nu = 0.3, x = 0.01..0.17"),
    core_counterpart_file!("edge/core/force_nu0.45_t0.6.csv", Force3d, 0.45, 0.6, Counterpart::Edge, "held out of every fit: edge, core t/R = 0.6, nu = 0.45, x = 0.01..0.33"),
    core_counterpart_file!("edge/core/force_nu0.48_t0.4.csv", Force3d, 0.48, 0.4, Counterpart::Edge, "held out of every fit: edge, core t/R = 0.4, nu = 0.48, x = 0.01..0.21"),
    core_counterpart_file!("edge/core/force_nu0.48_t0.5.csv", Force3d, 0.48, 0.5, Counterpart::Edge, "held out of every fit: edge, core t/R = 0.5, nu = 0.48, x = 0.01..0.35"),
    core_counterpart_file!("edge/core/force_nu0.4_t0.45.csv", Force3d, 0.4, 0.45, Counterpart::Edge, "held out of every fit: edge, core t/R = 0.45, nu = 0.4, x = 0.01..0.19"),
    core_counterpart_file!("edge/core/pressure_nu0.3_t0.5_d0.1.csv", PressureMap, 0.3, 0.5, Counterpart::Edge, "held out of every fit: edge, core t/R = 0.5, nu = 0.3, pressure at x = 0.1"),
    core_counterpart_file!("edge/core/pressure_nu0.45_t0.6_d0.1.csv", PressureMap, 0.45, 0.6, Counterpart::Edge, "held out of every fit: edge, core t/R = 0.6, nu = 0.45, pressure at x = 0.1"),
    core_counterpart_file!("edge/core/pressure_nu0.45_t0.6_d0.3.csv", PressureMap, 0.45, 0.6, Counterpart::Edge, "held out of every fit: edge, core t/R = 0.6, nu = 0.45, pressure at x = 0.3"),
    core_counterpart_file!("edge/core/pressure_nu0.48_t0.4_d0.1.csv", PressureMap, 0.48, 0.4, Counterpart::Edge, "held out of every fit: edge, core t/R = 0.4, nu = 0.48, pressure at x = 0.1"),
    core_counterpart_file!("edge/core/pressure_nu0.48_t0.5_d0.1.csv", PressureMap, 0.48, 0.5, Counterpart::Edge, "held out of every fit: edge, core t/R = 0.5, nu = 0.48, pressure at x = 0.1"),
    core_counterpart_file!("edge/core/pressure_nu0.48_t0.5_d0.3.csv", PressureMap, 0.48, 0.5, Counterpart::Edge, "held out of every fit: edge, core t/R = 0.5, nu = 0.48, pressure at x = 0.3"),
    core_counterpart_file!("edge/core/pressure_nu0.4_t0.45_d0.1.csv", PressureMap, 0.4, 0.45, Counterpart::Edge, "held out of every fit: edge, core t/R = 0.45, nu = 0.4, pressure at x = 0.1"),
];
