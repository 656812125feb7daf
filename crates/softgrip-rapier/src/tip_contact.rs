//! [`TipContact`]: what one soft contact did over the last step (its assembly from the
//! substeps' impulses: `readout`).

use std::ops::Deref;
use std::sync::Arc;

use nalgebra::Vector3;
use rapier3d::prelude::ColliderHandle;
use softgrip_law::{ContactLaw, ContactPatch, ContactReading};

use crate::model::Model;

/// One soft contact after a step: the law crate's plain [`ContactReading`] (`reading`; the
/// struct dereferences to it, so `c.normal_force`, `c.delta`, `c.wrench_about(..)` read it)
/// plus what only the plugin has: the two colliders and the contact's law. Cheap to produce:
/// the contact patch and pressure are only computed when [`patch`](Self::patch) is called
/// (`reading.patch` is `None`).
///
/// Forces are step averages (total impulse over the step / dt); the geometry (`point`,
/// `normal`, `delta`) is that of the last (sub)step, with `delta` predicted to the end of it
/// (`delta - h v_n`, what rapier's position update produces), so `normal_force` and
/// `law(delta)` agree for a quasi-static contact. `counterpart` is what the other collider's
/// shape is at the contact (see the crate's README; a plane for two fingertips: their combined
/// law already has both curvatures); `patch_direction` is along the counterpart's first
/// principal direction (a cylinder's axis, an edge), and for a disc (a plane, a ball, two
/// fingertips) the tangent nearest the world's x axis (z when the normal is nearly x).
///
/// A contact of two fingertips is reported **twice**, once per fingertip: `fingertip` and
/// `other` swapped, each with its own normal (from the other fingertip to it), the force and
/// friction vectors exactly opposite. Two free fingertips are one pair with one combined law
/// (`ContactParams::try_combine`): `delta` is the approach of the two surfaces and
/// `x = delta / R_eff` (R_eff the combined radius) in both rows. When either is backed, the two
/// are pressed in series on their rigid mid-surface: each row is its own fingertip's, `delta`
/// its share of the approach (the shares add up to the approach, their forces are equal),
/// `x = delta / R` with its own radius, and its own law's stiffness, level, regime and patch.
/// Sum `normal_force` per fingertip, not over all contacts, to avoid counting such a pair
/// twice.
#[derive(Debug, Clone)]
pub struct TipContact {
    /// The fingertip's collider.
    pub fingertip: ColliderHandle,
    /// The other collider (a rigid body, or a second fingertip).
    pub other: ColliderHandle,
    /// The contact's numbers (without its patch: [`patch`](Self::patch) computes it).
    pub reading: ContactReading,
    pub(crate) model: Arc<Model>,
}

impl Deref for TipContact {
    type Target = ContactReading;

    /// The contact's [`reading`](field@TipContact::reading).
    fn deref(&self) -> &ContactReading {
        &self.reading
    }
}

impl AsRef<ContactReading> for TipContact {
    fn as_ref(&self) -> &ContactReading {
        &self.reading
    }
}

impl TipContact {
    /// The contact's numbers, owned: the law crate's plain [`ContactReading`], the one shape
    /// that the recorder, the ROS 2 publisher, the ECS and Python take (its patch is `None`:
    /// [`patch`](Self::patch) computes it when wanted).
    pub fn reading(&self) -> ContactReading {
        self.reading.clone()
    }

    /// Contact patch and pressure at `delta` (computed now): a disc on a plane or a ball, an
    /// ellipse on a cylinder or an edge, its first semi-axis (`radius`) along
    /// `patch_direction`.
    pub fn patch(&self) -> ContactPatch {
        self.model.law.patch(self.reading.delta)
    }

    /// The contact's law (for a fingertip on a rigid body, the fingertip's own).
    pub fn law(&self) -> &ContactLaw {
        &self.model.law
    }

    /// Sets what the contact's model says about it (after the model was chosen): the
    /// counterpart and the patch's direction.
    pub(crate) fn set_counterpart(&mut self) {
        self.reading.counterpart = self.model.law.counterpart();
        self.reading.patch_direction = patch_direction(&self.model, self.reading.normal);
    }
}

/// Unit vector, world, along the patch's first semi-axis: the model's (the counterpart's first
/// principal direction), or for a disc the tangent to `normal` nearest the world's x axis (z
/// when the normal is nearly x).
fn patch_direction(model: &Model, normal: [f64; 3]) -> [f64; 3] {
    let d = model.patch_direction;
    if d.norm() > 0.0 {
        return d.into();
    }
    let n = Vector3::from(normal);
    let seed = if n.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::z()
    };
    let t = seed - n * n.dot(&seed);
    (t / t.norm()).into()
}
