//! [`Counterpart`]: the rigid body a file's fingertip is pressed on.

/// The rigid body the fingertip is pressed on in a file's runs (issue 24). Every file made
/// before counterparts is [`Counterpart::Plane`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Counterpart {
    /// A rigid frictionless plane.
    Plane,
    /// A rigid frictionless ball of radius `k` R (axisymmetric runs). `free`: the sphere
    /// squeezed between two such balls, each contact compressed by delta.
    Ball {
        /// Ball radius over the fingertip's radius, R2/R [-], > 0.
        k: f64,
    },
    /// A rigid frictionless cylinder of radius `k` R, its axis in the contact plane (3D
    /// quarter models).
    Cylinder {
        /// Cylinder radius over the fingertip's radius, R2/R [-], > 0.
        k: f64,
    },
    /// A rigid frictionless right-angle edge pressed along its bisector (3D quarter models; its
    /// ridge rounded with radius 0.01 R, each file's provenance says why).
    Edge,
}

impl Counterpart {
    /// The name used in paths and by `tools/fe`: `plane`, `ball`, `cylinder` or `edge`.
    pub fn kind(&self) -> &'static str {
        match self {
            Counterpart::Plane => "plane",
            Counterpart::Ball { .. } => "ball",
            Counterpart::Cylinder { .. } => "cylinder",
            Counterpart::Edge => "edge",
        }
    }

    /// R2/R of a ball or cylinder [-]; `None` for the plane and the edge.
    pub fn k(&self) -> Option<f64> {
        match *self {
            Counterpart::Ball { k } | Counterpart::Cylinder { k } => Some(k),
            Counterpart::Plane | Counterpart::Edge => None,
        }
    }
}
