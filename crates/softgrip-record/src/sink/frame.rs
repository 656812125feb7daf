//! [`StepFrame`]: one step's data, as plain numbers.

use softgrip_law::{Backing, ContactPatch, Counterpart, LevelKind, Regime};

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

/// The numbers of one soft contact over a step, as the plugin reads them out.
#[derive(Debug, Clone, PartialEq)]
pub struct ContactReading {
    /// Contact point, world \[m\].
    pub point: [f64; 3],
    /// Unit normal, world, from the other body to the fingertip [-].
    pub normal: [f64; 3],
    /// Compression delta \[m\], >= 0.
    pub delta: f64,
    /// Compression ratio x = delta / R [-].
    pub x: f64,
    /// Normal force on the fingertip \[N\], >= 0 (step average).
    pub normal_force: f64,
    /// Friction force on the fingertip, world \[N\] (step average).
    pub friction_force: [f64; 3],
    /// Torsional friction moment about the normal [N m] (step average).
    pub torsional_moment: f64,
    /// Law stiffness K = dF/d delta at `delta` [N/m], >= 0.
    pub stiffness: f64,
    /// The level that computed the force.
    pub level: LevelKind,
    /// Valid, extended (validity excursion) or separated, at the end of the step.
    pub regime: Regime,
    /// The compression was past the law's validity range in some substep of the step.
    pub validity_exceeded: bool,
    /// Friction saturated (the contact slid) in some substep.
    pub sliding: bool,
    /// Largest normal force of any substep \[N\].
    pub peak_normal_force: f64,
    /// Largest compression of the step \[m\]: over the start of every substep and the end
    /// of the step (`>= delta`).
    pub max_delta: f64,
    /// Time in contact during the step \[s\], in [0, dt].
    pub contact_duration: f64,
    /// Contact radius and pressure, when the scene records pressure.
    pub patch: Option<ContactPatch>,
    /// The construction of the fingertip whose law computed the contact.
    pub backing: Backing,
    /// What the fingertip touched (a plane for two fingertips).
    pub counterpart: Counterpart,
    /// Unit vector, world, along the patch's first semi-axis (`patch.radius`) [-].
    pub patch_direction: [f64; 3],
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
