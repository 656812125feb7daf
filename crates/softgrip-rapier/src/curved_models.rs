//! [`CurvedModels`]: the contact models of fingertips on counterparts other than a plane
//! (`curvature`), one per contact, kept while the counterpart and the patch's direction stay
//! the same (a ball, a cylinder at rest: built once per contact, not per substep).

use std::sync::Arc;

use rapier3d::prelude::ColliderHandle;

use crate::counters::SoftCounters;
use crate::curvature::Touch;
use crate::fast_hash::FastMap;
use crate::model::Model;

/// A contact: (fingertip, other).
type Key = (ColliderHandle, ColliderHandle);

/// The models of the contacts on curved counterparts and edges.
#[derive(Debug, Clone, Default)]
pub(crate) struct CurvedModels {
    map: FastMap<Key, (Touch, Arc<Model>)>,
}

impl CurvedModels {
    /// The model of contact `key` of a fingertip whose own model (on a plane) is `base`,
    /// touching `touch` (not a plane). The fingertip's law bound to the counterpart
    /// (`ContactLaw::with_counterpart`); a counterpart the law refuses (a groove tighter than
    /// the fingertip) is computed as a plane and counted. `in_contact` tells the contacts
    /// still alive: entries of the others are dropped once the map outgrows them.
    pub(crate) fn model(
        &mut self,
        key: Key,
        base: &Arc<Model>,
        touch: &Touch,
        counters: &mut SoftCounters,
        in_contact: impl Fn(&Key) -> bool,
    ) -> Arc<Model> {
        if let Some((t, m)) = self.map.get(&key)
            && t == touch
        {
            return m.clone();
        }
        let model = match base.law.with_counterpart(touch.counterpart) {
            Ok(law) => Arc::new(Model {
                law,
                patch_direction: touch.direction,
                ..(**base).clone()
            }),
            Err(_) => {
                counters.counterpart_fallbacks += 1;
                return base.clone();
            }
        };
        if self.map.len() >= 16 {
            self.map.retain(|k, _| in_contact(k));
        }
        self.map.insert(key, (*touch, model.clone()));
        model
    }
}
