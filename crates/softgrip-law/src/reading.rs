//! [`ContactReading`]: the numbers of one soft contact over a simulation step, as plain data.
//!
//! It lives here, in the law, because it is the one crate that both sides share: the plugin
//! (`softgrip-rapier`, which depends on the law and not on the recorder) produces it, and the
//! recorder (`softgrip-record`, which depends on the law and not on rapier) consumes it. Its
//! fields are the law's vocabulary (compression, force, stiffness, level, regime, construction,
//! counterpart, patch) and plain vectors: no engine type.

use crate::backing::Backing;
use crate::counterpart::Counterpart;
use crate::law::Regime;
use crate::level::LevelKind;
use crate::pressure::ContactPatch;

/// One soft contact over the last step: what the plugin's readout says, and what the recorder
/// and the ROS 2 publisher write (`softgrip_msgs/SoftContact` adds the two sides' names).
///
/// Forces are step averages (total impulse over the step / dt); the geometry (`point`,
/// `normal`, `delta`) is that of the step's last (sub)step, with `delta` predicted to its end.
/// Vectors are in the world frame of whoever produced it (the scene's axes for the plugin).
///
/// A contact of two fingertips is reported **twice**, once per fingertip (their normals and
/// force vectors opposite; see `softgrip_rapier::TipContact`): sum `normal_force` per
/// fingertip, not over all contacts.
///
/// ```
/// use softgrip_law::{Backing, ContactReading, Counterpart, LevelKind, Regime};
/// let c = ContactReading {
///     point: [0.0, 0.0, -0.01],
///     normal: [0.0, 0.0, 1.0],
///     normal_force: 2.0,
///     friction_force: [0.5, 0.0, 0.0],
///     ..ContactReading::default()
/// };
/// let (f, t) = c.wrench_about([0.0; 3]);
/// assert_eq!((f[0], f[2]), (0.5, 2.0));
/// assert!((t[1] - (-0.01 * 0.5)).abs() < 1e-15); // r x f = (0,0,-0.01) x (0.5,0,2)
/// assert_eq!((c.level, c.regime, c.backing), (LevelKind::Hertz, Regime::Separated, Backing::Free));
/// assert_eq!(c.counterpart, Counterpart::PLANE);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct ContactReading {
    /// Contact point, world \[m\].
    pub point: [f64; 3],
    /// Unit normal, world, from the other body to the fingertip [-].
    pub normal: [f64; 3],
    /// Compression delta \[m\], >= 0 (of two free fingertips: the approach of their surfaces).
    pub delta: f64,
    /// Compression ratio x = delta / R [-] (of two free fingertips: R = the combined radius).
    pub x: f64,
    /// Normal force on the fingertip \[N\], >= 0 (step average; includes the dissipative part).
    pub normal_force: f64,
    /// Friction force on the fingertip, world \[N\] (step average, tangent to the contact).
    pub friction_force: [f64; 3],
    /// Torsional friction moment on the fingertip about `normal` [N m] (step average).
    pub torsional_moment: f64,
    /// Law stiffness K = dF/d delta at `delta` [N/m], >= 0.
    pub stiffness: f64,
    /// The level that computed the force.
    pub level: LevelKind,
    /// Valid, extended (validity excursion) or separated, at `delta` (the end of the step).
    pub regime: Regime,
    /// The compression was past the law's validity range in some substep of the step, or is
    /// at its end.
    pub validity_exceeded: bool,
    /// Friction saturated (the contact slid) in some substep.
    pub sliding: bool,
    /// Largest normal force of any substep \[N\] (an impact's peak).
    pub peak_normal_force: f64,
    /// Largest compression of the step \[m\]: over the start of every substep and the end of
    /// the step (`>= delta`).
    pub max_delta: f64,
    /// Largest compression ratio of the step, `max_delta / R` [-] (`>= x`).
    pub max_x: f64,
    /// Time in contact (compression > 0) during the step \[s\], in [0, dt].
    pub contact_duration: f64,
    /// The construction of the fingertip whose law computed the contact (`Free` for a combined
    /// pair of two free fingertips).
    pub backing: Backing,
    /// What the fingertip touched: a plane, a curved surface or an edge (a plane for two
    /// fingertips: their combined law already has both curvatures).
    pub counterpart: Counterpart,
    /// Unit vector, world, along the patch's first semi-axis (`patch.radius`; the
    /// counterpart's first principal direction), tangent to the contact [-]; `[0, 0, 0]` in
    /// [`Default`] (no contact, no direction).
    pub patch_direction: [f64; 3],
    /// Contact patch (semi-axes `radius` along `patch_direction` and `radius2` across it) and
    /// pressure at `delta`, when someone asked for them (they cost more than the force):
    /// `None` in the plugin's readout (`softgrip_rapier::TipContact::patch` computes it), set
    /// by whoever records pressure or the radius.
    pub patch: Option<ContactPatch>,
}

impl Default for ContactReading {
    /// No contact: zeros, level `hertz`, regime `separated`, a free fingertip on a plane, no
    /// patch direction, no patch.
    fn default() -> Self {
        Self {
            point: [0.0; 3],
            normal: [0.0; 3],
            delta: 0.0,
            x: 0.0,
            normal_force: 0.0,
            friction_force: [0.0; 3],
            torsional_moment: 0.0,
            stiffness: 0.0,
            level: LevelKind::Hertz,
            regime: Regime::Separated,
            validity_exceeded: false,
            sliding: false,
            peak_normal_force: 0.0,
            max_delta: 0.0,
            max_x: 0.0,
            contact_duration: 0.0,
            backing: Backing::Free,
            counterpart: Counterpart::PLANE,
            patch_direction: [0.0; 3],
            patch: None,
        }
    }
}

impl ContactReading {
    /// Magnitude of the friction force \[N\].
    pub fn friction_magnitude(&self) -> f64 {
        let [a, b, c] = self.friction_force;
        (a * a + b * b + c * c).sqrt()
    }

    /// Whether the compression was past the law's validity range during the step
    /// ([`validity_exceeded`](Self::validity_exceeded)).
    pub fn validity_excursion(&self) -> bool {
        self.validity_exceeded
    }

    /// Force and torque the contact puts on the fingertip, the torque about `center` (world
    /// \[m\], e.g. the fingertip's centre): normal plus friction force, `r x f` plus the
    /// torsional moment about the normal. Summed over a fingertip's contacts this is its
    /// contact wrench \[N\], [N m].
    pub fn wrench_about(&self, center: [f64; 3]) -> ([f64; 3], [f64; 3]) {
        let (n, p) = (self.normal, self.point);
        let f: [f64; 3] =
            std::array::from_fn(|i| n[i] * self.normal_force + self.friction_force[i]);
        let r: [f64; 3] = std::array::from_fn(|i| p[i] - center[i]);
        let rxf = [
            r[1] * f[2] - r[2] * f[1],
            r[2] * f[0] - r[0] * f[2],
            r[0] * f[1] - r[1] * f[0],
        ];
        let torque = std::array::from_fn(|i| rxf[i] + n[i] * self.torsional_moment);
        (f, torque)
    }
}
