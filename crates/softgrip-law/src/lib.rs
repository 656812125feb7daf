#![doc = include_str!("../README.md")]

mod backing;
mod counterpart;
mod curve;
mod elliptic;
mod error;
pub mod fitting;
mod law;
mod level;
mod levels;
mod mapping;
mod material;
mod normalised;
mod number;
mod pressure;
mod quadrature;
mod root;
mod tabulated;

pub use backing::{Backing, MIN_CORE_THICKNESS_RATIO};
pub use counterpart::{
    Counterpart, CounterpartKind, MAX_RELATIVE_CURVATURE, MIN_RELATIVE_CURVATURE,
};
pub use error::{Error, Result};
pub use law::{ContactLaw, ContactState, NormalResponse, Regime};
pub use level::{DEFAULT_AUTO_TOLERANCE, DEFAULT_FIT_K, DEFAULT_LINEAR_MATCH_X, Level, LevelKind};
pub use levels::neo_hookean::neo_hookean_limit_point;
pub use material::{ContactParams, Material};
pub use normalised::NormalisedLaw;
pub use number::{MAX_SHORTEST_DIGITS, Shortest, shorten_numbers};
pub use pressure::ContactPatch;
pub use tabulated::{MIN_TABULATED_SAMPLES, TabulatedCurve};
