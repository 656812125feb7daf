//! The systems, one file per set (see [`SoftgripSystems`](crate::SoftgripSystems) for the order).

mod control;
mod physics;
mod readout;
mod record;
mod sync;

pub use control::run_controllers;
pub use physics::physics_step;
pub use readout::readout;
pub use record::{assemble_frame, publish, record};
pub(crate) use sync::create_in_rapier;
pub use sync::{Unsynchronised, sync_to_rapier};
