//! [`TipRecord`]: everything the plugin keeps of one registered fingertip.

use std::sync::Arc;

use rapier3d::prelude::InteractionGroups;

use crate::fingertip::SoftFingertip;
use crate::model::Model;
use crate::taxels::TactileSlot;

/// Everything the plugin keeps of one registered fingertip.
#[derive(Debug, Clone)]
pub(crate) struct TipRecord {
    /// The fingertip as registered.
    pub(crate) fingertip: SoftFingertip,
    /// The collision groups its collider had at registration (a free fingertip's own are set
    /// to `InteractionGroups::none()`, which keeps rapier's narrow phase off it).
    pub(crate) groups: InteractionGroups,
    /// The solver groups its collider had at registration.
    pub(crate) solver_groups: InteractionGroups,
    /// Its contact model on a rigid body (shared by its contacts).
    pub(crate) model: Arc<Model>,
    /// Its tactile image, if it has a pad.
    pub(crate) tactile: Option<TactileSlot>,
}
