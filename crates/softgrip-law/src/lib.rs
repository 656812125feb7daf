#![doc = include_str!("../README.md")]

mod backing;
mod backing_table;
mod cap_map;
mod core_map;
mod counterpart;
mod curve;
mod elliptic;
mod error;
mod extension;
pub mod fitting;
mod law;
mod level;
mod level_table;
mod levels;
mod mapping;
mod material;
mod normalised;
mod number;
mod pressure;
mod quadrature;
mod reading;
mod recorded_curve;
mod root;
mod setting;
mod tabulated;
mod tail;

pub use backing::{Backing, MIN_CORE_THICKNESS_RATIO};
pub use backing_table::{BACKINGS, BackingInfo, BackingKind, BackingParameter};
pub use counterpart::{
    Counterpart, CounterpartKind, MAX_RELATIVE_CURVATURE, MIN_RELATIVE_CURVATURE,
};
pub use error::{Error, Result};
pub use law::{ContactLaw, ContactState, NormalResponse, Regime};
pub use level::{
    DEFAULT_AUTO_TOLERANCE, DEFAULT_FIT_K, DEFAULT_LINEAR_MATCH_X, Level, LevelKind, setting_keys,
};
pub use level_table::{LEVELS, LevelData, LevelInfo};
pub use levels::neo_hookean::neo_hookean_limit_point;
pub use material::{ContactParams, Material};
pub use normalised::NormalisedLaw;
pub use number::{MAX_SHORTEST_DIGITS, Shortest, shorten_numbers};
pub use pressure::ContactPatch;
pub use reading::ContactReading;
pub use recorded_curve::CUSTOM_CURVE_SAMPLES;
pub use setting::{Interval, LevelSetting};
pub use tabulated::{MIN_TABULATED_SAMPLES, TabulatedCurve};
