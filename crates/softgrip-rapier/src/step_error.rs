//! [`StepError`]: what a step reports when the simulation has gone wrong numerically, and the
//! bounds it is checked against.

use rapier3d::prelude::{ColliderHandle, RigidBodyHandle};
use softgrip_law::Shortest;

/// Largest |coordinate| of a body's position \[m\] (1000 km). rapier stores a position in
/// `f32`, whose spacing at 1e6 m is 6 cm: a body farther out has no position at contact scale
/// (a fingertip is at most [`MAX_RADIUS`](crate::MAX_RADIUS) = 1 km). Ten times the largest
/// coordinate a scene file may give (`softgrip_scene::limits::MAX_COORDINATE`), so a body may
/// fall or fly well beyond its scene before the step calls it diverged.
pub const MAX_POSITION: f64 = 1.0e6;
/// Largest linear speed of a body or a contact's velocity change in one (sub)step \[m/s\]
/// (1000 km/s: 100 times the largest speed a scene may drive a body at,
/// `softgrip_scene::limits::MAX_SPEED`; at it a body crosses [`MAX_POSITION`] in one second).
pub const MAX_LINEAR_SPEED: f64 = 1.0e6;
/// Largest angular speed of a body, and largest |velocity| of a multibody joint coordinate
/// \[rad/s or m/s\] (1e12: the smallest fingertip, [`MIN_RADIUS`](crate::MIN_RADIUS) = 1 nm,
/// rolling at a surface speed of 1 km/s). A joint coordinate of a prismatic axis is a speed
/// and is bounded by the same number; its link's body is bounded by [`MAX_LINEAR_SPEED`].
pub const MAX_ANGULAR_SPEED: f64 = 1.0e12;
/// Largest |multibody joint coordinate| \[rad or m\] (1e6: [`MAX_POSITION`] for a prismatic
/// axis; for a revolute axis, where `f32`'s spacing is 0.06 rad, the angle has no meaning left).
pub const MAX_JOINT_COORDINATE: f64 = 1.0e6;

/// What diverged: a body, a multibody joint's coordinate, or a soft contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Subject {
    /// A rigid body (a multibody link is one too).
    Body(RigidBodyHandle),
    /// Coordinate `dof` (0-based, in rapier's order: free linear axes, then free angular
    /// axes) of the multibody joint whose child link is the body `link`.
    Joint {
        /// The joint's child link.
        link: RigidBodyHandle,
        /// The coordinate's index in the joint.
        dof: usize,
    },
    /// The soft contact of `fingertip` (a collider registered as a fingertip) with `other`.
    Contact {
        /// The fingertip's collider.
        fingertip: ColliderHandle,
        /// The other collider.
        other: ColliderHandle,
    },
}

impl std::fmt::Display for Subject {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Body(h) => write!(f, "body {h:?}"),
            Self::Joint { link, dof } => {
                write!(f, "coordinate {dof} of the joint of link {link:?}")
            }
            Self::Contact { fingertip, other } => {
                write!(f, "soft contact of fingertip {fingertip:?} with {other:?}")
            }
        }
    }
}

/// Which number went out of bounds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    /// A body's position, |x|, |y| or |z| \[m\] (bound [`MAX_POSITION`]).
    Position,
    /// A body's rotation (a quaternion component, which must be finite) [-].
    Rotation,
    /// A body's linear velocity, its largest |component| \[m/s\] (bound [`MAX_LINEAR_SPEED`]).
    LinearVelocity,
    /// A body's angular velocity, its largest |component| \[rad/s\] (bound
    /// [`MAX_ANGULAR_SPEED`]).
    AngularVelocity,
    /// A multibody joint coordinate \[rad or m\] (bound [`MAX_JOINT_COORDINATE`]).
    JointPosition,
    /// A multibody joint coordinate's velocity \[rad/s or m/s\] (bound [`MAX_ANGULAR_SPEED`]).
    JointVelocity,
    /// A soft contact's impulse from the solve, its largest |component| (normal, tangential,
    /// torsional) \[N s or N m s\]: must be finite (the velocities it gives the bodies are
    /// then checked against their bounds).
    ContactImpulse,
    /// A soft contact's end normal velocity as the soft solve's answer predicts it \[m/s\]
    /// (bound [`MAX_LINEAR_SPEED`]): checked before rapier's pipeline takes the answer, since a
    /// multibody or jointed link takes only the joint-space part of its load and its body's
    /// own velocity can stay small under an absurd answer.
    ContactVelocity,
}

impl Quantity {
    /// The quantity's name as errors print it, with its unit.
    pub fn name(self) -> &'static str {
        match self {
            Self::Position => "position [m]",
            Self::Rotation => "rotation (quaternion component)",
            Self::LinearVelocity => "linear velocity [m/s]",
            Self::AngularVelocity => "angular velocity [rad/s]",
            Self::JointPosition => "joint position [rad or m]",
            Self::JointVelocity => "joint velocity [rad/s or m/s]",
            Self::ContactImpulse => "soft contact impulse [N s]",
            Self::ContactVelocity => "soft contact's predicted normal velocity [m/s]",
        }
    }
}

/// When in the step the check failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// Before the step, on the state the user handed over: nothing was advanced, the world is
    /// as it was (not faulted; fix the state and step again).
    Before,
    /// Inside the step, on the soft solve's impulses and the velocities they gave the bodies,
    /// before rapier's pipeline took them: the step was abandoned part way (in a substep) and
    /// the world is faulted.
    SoftSolve,
    /// After rapier's pipeline: the world holds the diverged state and is faulted.
    After,
}

impl std::fmt::Display for Phase {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Before => "before the step",
            Self::SoftSolve => "in the step, after the soft solve",
            Self::After => "after the step",
        })
    }
}

/// What diverged in a [`StepError::Diverged`] (see its fields), borrowed from it by
/// [`StepError::divergence`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Divergence<'a> {
    /// What diverged.
    pub subject: Subject,
    /// Its name, where a layer above the plugin knows it.
    pub name: Option<&'a str>,
    /// Which number.
    pub quantity: Quantity,
    /// The value found (NaN or infinite included).
    pub value: f64,
    /// The bound it broke.
    pub bound: f64,
    /// When in the step it was found.
    pub phase: Phase,
}

/// A step that could not be taken or went wrong numerically. Returned by
/// [`SoftContacts::try_step`](crate::SoftContacts::try_step) and
/// [`SoftWorld::try_step`](crate::SoftWorld::try_step); a world that returned one with a
/// phase other than [`Phase::Before`] is *faulted* (see [`SoftContacts::fault`](crate::SoftContacts::fault)).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StepError {
    /// A number of the state is non-finite or beyond what rapier's `f32` can hold
    /// meaningfully.
    #[error(
        "the simulation diverged at step {step} (t = {} s, {phase}): {subject}{}: {} = {}, beyond its bound {}",
        Shortest(*time),
        name.as_ref().map(|n| format!(" (`{n}`)")).unwrap_or_default(),
        quantity.name(),
        Shortest(*value),
        Shortest(*bound)
    )]
    Diverged {
        /// The step that failed, counted from 1 over this plugin's steps of `dt > 0`.
        step: u64,
        /// Simulated time at the start of that step \[s\] (the sum of the steps' `dt`).
        time: f64,
        /// What diverged.
        subject: Subject,
        /// Its name, where a layer above the plugin knows it (a scene's body, link or joint);
        /// `None` from the plugin itself.
        name: Option<String>,
        /// Which number.
        quantity: Quantity,
        /// The value found (NaN or infinite included).
        value: f64,
        /// The bound it broke (a non-finite value breaks any bound).
        bound: f64,
        /// When in the step it was found.
        phase: Phase,
    },
    /// rapier's pipeline panicked (an assertion on a state it cannot handle). The panic was
    /// caught; the world is faulted.
    #[error(
        "rapier panicked at step {step} (t = {} s): {message}{}",
        Shortest(*time),
        location.as_ref().map(|l| format!(" (at {l})")).unwrap_or_default()
    )]
    EnginePanicked {
        /// The step that failed, counted from 1.
        step: u64,
        /// Simulated time at the start of that step \[s\].
        time: f64,
        /// The panic's message.
        message: String,
        /// The panic's source location (`file:line:column`), where the panic hook saw it.
        location: Option<String>,
    },
}

impl StepError {
    /// The step that failed, counted from 1.
    pub fn step(&self) -> u64 {
        match self {
            Self::Diverged { step, .. } | Self::EnginePanicked { step, .. } => *step,
        }
    }

    /// Simulated time at the start of the failed step \[s\].
    pub fn time(&self) -> f64 {
        match self {
            Self::Diverged { time, .. } | Self::EnginePanicked { time, .. } => *time,
        }
    }

    /// The subject, for a [`StepError::Diverged`].
    pub fn subject(&self) -> Option<Subject> {
        match self {
            Self::Diverged { subject, .. } => Some(*subject),
            Self::EnginePanicked { .. } => None,
        }
    }

    /// The fields of a [`StepError::Diverged`], borrowed: what the layers above (the scene's
    /// tests, Python's `SimulationDiverged`) read, in one place.
    pub fn divergence(&self) -> Option<Divergence<'_>> {
        match self {
            Self::Diverged {
                subject,
                name,
                quantity,
                value,
                bound,
                phase,
                ..
            } => Some(Divergence {
                subject: *subject,
                name: name.as_deref(),
                quantity: *quantity,
                value: *value,
                bound: *bound,
                phase: *phase,
            }),
            Self::EnginePanicked { .. } => None,
        }
    }

    /// Sets the subject's name (a layer that knows its bodies' names, e.g. a scene, calls it).
    pub fn with_name(mut self, new: Option<String>) -> Self {
        if let Self::Diverged { name, .. } = &mut self {
            *name = new;
        }
        self
    }

    /// Whether the error leaves the world faulted (everything but a rejection before the step).
    pub fn faults(&self) -> bool {
        !matches!(
            self,
            Self::Diverged {
                phase: Phase::Before,
                ..
            }
        )
    }
}
