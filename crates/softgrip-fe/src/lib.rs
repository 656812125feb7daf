#![doc = include_str!("../README.md")]

mod error;
mod files;
mod points;
mod rows;

pub use error::{Error, Result};
pub use files::{FILES, FeFile, PROVENANCE, Schema, file, force_reference};
pub use points::{FePoint, RADIUS_MM, SHEAR_MODULUS_MPA, effective_modulus_mpa};
pub use rows::{ForceRow, FullRow, MeshConvergenceRow, SmallXRow};
