//! [`SceneInfo`]: what a sink learns once, before the first step.

use crate::metadata::FingertipLaw;

/// A fingertip of the scene: where it is mounted and its law.
#[derive(Debug, Clone, PartialEq)]
pub struct FingertipInfo {
    /// Fingertip name (its `/tf` frame and `/softgrip/<name>/wrench`).
    pub name: String,
    /// Name of the body that carries it.
    pub body: String,
    /// Centre of the fingertip sphere in its body's frame \[m\].
    pub offset: [f64; 3],
    /// Radius R \[m\], > 0.
    pub radius: f64,
    /// The law's parameters (written in the recording's metadata).
    pub law: FingertipLaw,
}

/// What a sink learns once, before the first step.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct SceneInfo {
    /// Where the scene came from (a file path, or a description).
    pub origin: String,
    /// Time step \[s\], > 0.
    pub dt: f64,
    /// Steps the run takes.
    pub steps: u64,
    /// Body names, in scene order.
    pub bodies: Vec<String>,
    /// Fingertips, in scene order.
    pub fingertips: Vec<FingertipInfo>,
}
