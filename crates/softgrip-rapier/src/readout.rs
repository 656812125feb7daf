//! [`SoftContact`]: what one soft contact did over the last step.

use rapier3d::prelude::ColliderHandle;
use softgrip_law::{ContactLaw, ContactPatch, LevelKind, Regime};

/// One soft contact after a step. Cheap to produce: the contact radius and pressure are only
/// computed when [`patch`](Self::patch) is called.
///
/// Forces are step averages (total impulse over the step / dt); the geometry (`point`,
/// `normal`, `delta`) is that of the last (sub)step, with `delta` predicted to the end of it
/// (`delta - h v_n`, what rapier's position update produces), so `normal_force` and
/// `law(delta)` agree for a quasi-static contact.
#[derive(Debug, Clone)]
pub struct SoftContact {
    /// The fingertip's collider.
    pub fingertip: ColliderHandle,
    /// The other collider (a rigid body, or a second fingertip).
    pub other: ColliderHandle,
    /// Contact point, world [m].
    pub point: [f64; 3],
    /// Unit normal, world, from the other body to the fingertip.
    pub normal: [f64; 3],
    /// Compression delta [m] (> 0 in contact).
    pub delta: f64,
    /// Compression ratio x = delta / R [-].
    pub x: f64,
    /// Normal force on the fingertip [N], >= 0 (step average; includes the dissipative part).
    pub normal_force: f64,
    /// Friction force on the fingertip, world [N] (step average, tangent to the contact).
    pub friction_force: [f64; 3],
    /// Torsional friction moment on the fingertip about `normal` [N m] (step average).
    pub torsional_moment: f64,
    /// Law stiffness K = dF/d delta at `delta` [N/m].
    pub stiffness: f64,
    /// The level that computed the force.
    pub level: LevelKind,
    /// Valid, extended (validity excursion) or separated.
    pub regime: Regime,
    /// Friction was saturated (the contact slid) in some substep of the step.
    pub sliding: bool,
    /// Largest normal force of any substep of the step [N] (an impact's peak; equals
    /// `normal_force` for an unsplit step).
    pub peak_normal_force: f64,
    /// Largest compression at the start of any substep of the step [m].
    pub max_delta: f64,
    /// Time in contact (compression > 0) during the step [s].
    pub contact_duration: f64,
    pub(crate) law: ContactLaw,
}

impl SoftContact {
    /// Contact radius and pressure at `delta` (computed now).
    pub fn patch(&self) -> ContactPatch {
        self.law.patch(self.delta)
    }

    /// Whether the compression is past the law's validity range.
    pub fn validity_excursion(&self) -> bool {
        self.regime == Regime::Extended
    }

    /// Magnitude of the friction force [N].
    pub fn friction_magnitude(&self) -> f64 {
        let [a, b, c] = self.friction_force;
        (a * a + b * b + c * c).sqrt()
    }

    /// The contact's law (for a fingertip on a rigid body, the fingertip's own).
    pub fn law(&self) -> &ContactLaw {
        &self.law
    }
}
