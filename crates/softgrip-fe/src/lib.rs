#![doc = include_str!("../README.md")]

mod core_counterpart_files;
mod counterpart;
mod counterpart_files;
mod error;
mod fe_file;
mod files;
mod points;
mod rows;

pub use counterpart::Counterpart;
pub use error::{Error, Result};
pub use fe_file::{FeFile, Schema};
pub use files::{
    CORE_COUNTERPART_FILES, COUNTERPART_FILES, FILES, PROVENANCE, all, file, force_file,
    force_reference,
};
pub use points::{FePoint, RADIUS_MM, SHEAR_MODULUS_MPA, effective_modulus_mpa};
pub use rows::{
    Force3dRow, ForceRow, FullRow, MeshConvergenceRow, PressureMapRow, PressureRow, SmallXRow,
};
