#![doc = include_str!("../README.md")]

mod error;
pub mod fitting;
mod law;
mod level;
mod levels;
mod material;
mod pressure;
mod quadrature;

pub use error::{Error, Result};
pub use law::{ContactLaw, ContactState, NormalResponse, Regime};
pub use level::{DEFAULT_AUTO_TOLERANCE, DEFAULT_FIT_K, DEFAULT_LINEAR_MATCH_X, Level, LevelKind};
pub use levels::neo_hookean::neo_hookean_limit_point;
pub use material::{ContactParams, Material};
pub use pressure::ContactPatch;
