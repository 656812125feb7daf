//! [`StepFrame`]: one step's data, as plain numbers.

/// The numbers of one soft contact over a step: the law crate's one plain reading, which
/// the plugin produces (`softgrip_rapier::TipContact::reading`) and every sink writes.
pub use softgrip_law::ContactReading;

/// A body's pose.
#[derive(Debug, Clone, PartialEq)]
pub struct BodySample {
    /// Body name.
    pub name: String,
    /// Position \[m\].
    pub translation: [f64; 3],
    /// Orientation quaternion `[x, y, z, w]`.
    pub rotation: [f64; 4],
}

/// The total contact wrench on a fingertip (step averages, world frame).
#[derive(Debug, Clone, PartialEq)]
pub struct WrenchSample {
    /// Fingertip name.
    pub fingertip: String,
    /// Force \[N\].
    pub force: [f64; 3],
    /// Torque about the fingertip's centre [N m].
    pub torque: [f64; 3],
}

/// One soft contact with both sides named.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactSample {
    /// Fingertip name.
    pub fingertip: String,
    /// Name of the other side: a fingertip's name, or the other collider's body name.
    pub other: String,
    /// The contact's numbers.
    pub contact: ContactReading,
}

/// One step's data, in the order of the scene (bodies, fingertips) and of the plugin's
/// readout (contacts). Sections the scene does not record are empty.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct StepFrame {
    /// Step index, from 1 (the state after the first step).
    pub step: u64,
    /// Simulated time at the end of the step \[s\].
    pub time: f64,
    /// Body poses (`record.poses`).
    pub bodies: Vec<BodySample>,
    /// Fingertip wrenches (`record.wrenches`).
    pub wrenches: Vec<WrenchSample>,
    /// Soft contacts (`record.contacts`; with `patch` when `record.pressure`).
    pub contacts: Vec<ContactSample>,
    /// Tactile images of the fingertips with a pad (always, when a fingertip has one).
    pub tactile: Vec<TactileSample>,
    /// Every robot's moving joints after the step (`record.joints`); the ECS gives as velocity
    /// the rate of motion since its previous frame (rapier's own joint velocity lacks the
    /// position correction of its solve).
    pub joints: Vec<JointSample>,
    /// Their targets for the step: position and velocity targets, effort = the motor's force
    /// limit (0 without one) (`record.joints`).
    pub commands: Vec<JointSample>,
}

/// A joint's numbers (a state or a command), by name.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct JointSample {
    /// The joint's name (the URDF's; `<robot>/<joint>` in a scene with several robots).
    pub name: String,
    /// Position \[m or rad\].
    pub position: f64,
    /// Velocity \[m/s or rad/s\].
    pub velocity: f64,
    /// Effort \[N or N m\].
    pub effort: f64,
}

/// A fingertip's tactile image over a step: mean pressure of each taxel.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct TactileSample {
    /// Fingertip name.
    pub fingertip: String,
    /// Rows of taxels (the image's height), >= 1.
    pub rows: u32,
    /// Columns of taxels (the image's width), >= 1.
    pub columns: u32,
    /// Mean pressure of each taxel \[Pa\], >= 0, row-major from the pad's top-left taxel
    /// (`rows * columns` values).
    pub pressure: Vec<f32>,
}
