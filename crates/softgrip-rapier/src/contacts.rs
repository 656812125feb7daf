//! [`SoftContacts`]: the plugin's state: registered fingertips, per-contact memory, readout.

use std::collections::HashMap;

use nalgebra::Vector3;
use rapier3d::prelude::{ActiveCollisionTypes, ActiveHooks, ColliderHandle, ColliderSet};

use crate::counters::SoftCounters;
use crate::detect::{Geom, Model};
use crate::error::{Error, Result};
use crate::fingertip::SoftFingertip;
use crate::hooks::SoftHooks;
use crate::readout::SoftContact;
use crate::substep::SoftAccuracy;

/// Memory of one contact between steps.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PairState {
    /// Approach speed when the contact started [m/s] (Flores' v_in).
    pub v_in: f64,
    /// Friction anchor on the other body, in its collider's frame [m].
    pub anchor_local: Vector3<f64>,
}

/// The plugin's state: which colliders are soft, their contacts' memory and the readout.
#[derive(Debug, Clone, Default)]
pub struct SoftContacts {
    pub(crate) tips: HashMap<ColliderHandle, SoftFingertip>,
    pub(crate) hooks: SoftHooks,
    pub(crate) pairs: HashMap<(ColliderHandle, ColliderHandle), PairState>,
    pub(crate) soft_pairs: HashMap<(ColliderHandle, ColliderHandle), Option<Model>>,
    pub(crate) contacts: Vec<SoftContact>,
    pub(crate) counters: SoftCounters,
    pub(crate) accuracy: SoftAccuracy,
    pub(crate) geoms: Vec<Geom>,
}

impl SoftContacts {
    /// An empty plugin state with the default accuracy.
    pub fn new() -> Self {
        Self::default()
    }

    /// Marks `collider` as the soft fingertip `fingertip`.
    ///
    /// The collider must be a ball of the fingertip's radius (to 1e-5 relative). Sets its
    /// `ActiveHooks::FILTER_CONTACT_PAIRS` and adds `KINEMATIC_FIXED | KINEMATIC_KINEMATIC` to
    /// its active collision types (a fingertip on a kinematic finger must still see fixed and
    /// kinematic objects).
    pub fn register(
        &mut self,
        collider: ColliderHandle,
        fingertip: SoftFingertip,
        colliders: &mut ColliderSet,
    ) -> Result<()> {
        let co = colliders
            .get_mut(collider)
            .ok_or(Error::UnknownCollider(collider))?;
        let Some(ball) = co.shape().as_ball() else {
            return Err(Error::NotABall {
                handle: collider,
                shape: format!("{:?}", co.shape().shape_type()),
            });
        };
        let r = ball.radius as f64;
        if !((r - fingertip.radius()).abs() <= 1e-5 * fingertip.radius()) {
            return Err(Error::RadiusMismatch {
                handle: collider,
                collider_radius: r,
                fingertip_radius: fingertip.radius(),
            });
        }
        co.set_active_hooks(co.active_hooks() | ActiveHooks::FILTER_CONTACT_PAIRS);
        co.set_active_collision_types(
            co.active_collision_types()
                | ActiveCollisionTypes::KINEMATIC_FIXED
                | ActiveCollisionTypes::KINEMATIC_KINEMATIC,
        );
        self.hooks.insert(collider);
        self.tips.insert(collider, fingertip);
        Ok(())
    }

    /// Whether `collider` is a registered fingertip.
    pub fn is_soft(&self, collider: ColliderHandle) -> bool {
        self.tips.contains_key(&collider)
    }

    /// The fingertip registered on `collider`.
    pub fn fingertip(&self, collider: ColliderHandle) -> Option<&SoftFingertip> {
        self.tips.get(&collider)
    }

    /// The soft contacts of the last step.
    pub fn contacts(&self) -> &[SoftContact] {
        &self.contacts
    }

    /// The contacts of one fingertip in the last step.
    pub fn contacts_of(&self, fingertip: ColliderHandle) -> impl Iterator<Item = &SoftContact> {
        self.contacts
            .iter()
            .filter(move |c| c.fingertip == fingertip)
    }

    /// The hooks to pass to rapier's `PhysicsPipeline::step` (`SoftWorld` does it for you).
    pub fn hooks(&self) -> &SoftHooks {
        &self.hooks
    }

    /// Diagnostics counters.
    pub fn counters(&self) -> &SoftCounters {
        &self.counters
    }

    /// The accuracy setting (phase per substep).
    pub fn accuracy(&self) -> SoftAccuracy {
        self.accuracy
    }

    /// Sets the accuracy (phase per substep).
    pub fn set_accuracy(&mut self, accuracy: SoftAccuracy) {
        self.accuracy = accuracy;
    }

    /// The contact model of a geometry (the fingertip's, or the combined one of two).
    pub(crate) fn model(&mut self, g: &Geom) -> Option<Model> {
        if g.soft_pair {
            let (a, b) = (self.tips.get(&g.tip)?, self.tips.get(&g.other)?);
            self.soft_pairs
                .entry((g.tip, g.other))
                .or_insert_with(|| Model::of_pair(a, b))
                .clone()
        } else {
            self.tips.get(&g.tip).map(Model::of_tip)
        }
    }
}
