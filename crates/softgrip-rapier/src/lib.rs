#![doc = include_str!("../README.md")]
// `!(x > 0.0)` is used on purpose: it is true for NaN, which must be rejected too.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

mod apply;
mod bodies;
mod boundary;
mod contacts;
mod counters;
mod curvature;
mod curved_models;
mod detect;
mod error;
mod excluded;
mod fast_hash;
mod fingertip;
mod guard;
mod hooks;
mod joint_sweeps;
mod jointed;
mod kinematic;
mod link_contacts;
mod mobility;
mod model;
mod multibody;
mod multibody_sweeps;
mod presets;
mod problem;
mod readout;
mod rigid;
mod rounded;
mod saturation;
mod series;
mod solve;
mod stale_contacts;
mod step;
mod step_error;
mod stick;
mod substep;
mod tactile;
mod taxels;
mod tip_contact;
mod tip_record;
mod world;

pub use contacts::SoftContacts;
pub use counters::SoftCounters;
pub use curvature::SHARP_DIHEDRAL;
pub use detect::compression_from_signed_distance;
pub use error::{Error, Result};
pub use fingertip::{
    DEFAULT_FRICTION, DEFAULT_RESTITUTION, DEFAULT_RESTITUTION_SPEED, MAX_FRICTION, MAX_RADIUS,
    MAX_YOUNGS_MODULUS, MIN_RADIUS, RESTITUTION_SPEED_RANGE, SoftFingertip, SoftFingertipBuilder,
    hunt_crossley_zeta,
};
pub use presets::Preset;
pub use rigid::IMMOBILE;
pub use step_error::{
    Divergence, MAX_ANGULAR_SPEED, MAX_JOINT_COORDINATE, MAX_LINEAR_SPEED, MAX_POSITION, Phase,
    Quantity, StepError, Subject,
};
pub use substep::{AMPLITUDE_FRACTION, MAX_SUBSTEPS, SoftAccuracy};
pub use tactile::{MAX_TAXELS_PER_SIDE, MIN_TAXEL_SIDE_OVER_RADIUS, TactileGrid, TactilePad};
pub use taxels::TactileImage;
pub use tip_contact::TipContact;
pub use world::SoftWorld;

/// Re-exports of the crates the API uses.
pub use rapier3d;
pub use softgrip_law;
