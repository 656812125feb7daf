//! Robots from URDF (`[[robot]]`): the format, the URDF reader and its checks, the checked
//! [`Robot`], its insertion into a rapier world, its joints' state and targets and the loads
//! they carry.

mod build;
mod inertial;
mod load;
mod model;
mod numbers;
mod overlap;
mod spec;
mod state;
mod urdf;

pub use build::{
    FALLBACK_DENSITY, JOINTED_SWEEPS_MARGIN, JointedUnseen, MAX_JOINTED_SWEEPS, RobotHandles,
    RobotJointHandle,
};
pub use inertial::MAX_LINK_MASS;
pub use load::{joint_load, joint_state_loaded};
pub(crate) use model::moving_names;
pub use model::{JointKind, MAX_MULTIBODY_JOINTS, Mimic, Robot, RobotJoint, RobotLink};
pub(crate) use overlap::keep_apart;
pub use overlap::{ALWAYS_SHARE, SAMPLES, StartOverlap, always_in_contact, start_overlaps};
pub use spec::{BaseKind, JointModel, MeshShape, RobotSpec};
pub use state::{JointState, joint_state, joint_target, set_joint_target};
