//! [`SceneError`]: everything that can be wrong with a scene file, with where it is.

use std::path::PathBuf;

/// A scene that cannot be loaded. Every variant names the file (`origin`) and the field or
/// line at fault.
#[derive(Debug, thiserror::Error)]
pub enum SceneError {
    /// The scene file could not be read.
    #[error("{origin}: cannot read: {source}")]
    Io {
        /// The file.
        origin: String,
        /// The I/O error.
        source: std::io::Error,
    },
    /// The TOML is malformed, has an unknown field or a value of the wrong type.
    #[error("{origin}:{line}:{column}: {message}")]
    Parse {
        /// The file.
        origin: String,
        /// Line of the error, from 1.
        line: usize,
        /// Column of the error, from 1.
        column: usize,
        /// What the TOML parser says (for an unknown field: its name and the expected ones).
        message: String,
    },
    /// A value is outside its valid range.
    #[error("{origin}: `{field}` must be {expected}, got {value}")]
    Invalid {
        /// The file.
        origin: String,
        /// Path of the field, e.g. `body[1].shape[0].half_extents`.
        field: String,
        /// The value found.
        value: String,
        /// The valid range, with its unit.
        expected: String,
    },
    /// A name refers to nothing, or is used twice.
    #[error("{origin}: `{field}`: {message}")]
    Name {
        /// The file.
        origin: String,
        /// Path of the field.
        field: String,
        /// What is wrong.
        message: String,
    },
    /// A fingertip's parameters were rejected by the plugin or the law.
    #[error("{origin}: `{field}`: {source}")]
    Fingertip {
        /// The file.
        origin: String,
        /// Path of the fingertip, e.g. `fingertip[0]`.
        field: String,
        /// The plugin's error.
        source: softgrip_rapier::Error,
    },
    /// A fingertip's measured curve (CSV) could not be read or parsed: a wrong header, a
    /// row without two numbers, a value that is not a finite number.
    #[error("{}:{line}: {}", path.display(), with_field(field, message))]
    Curve {
        /// The curve file.
        path: PathBuf,
        /// Line of the error, from 1 (0 for I/O errors).
        line: usize,
        /// The column at fault (`delta_m`, `force_n`, `header`), empty for a whole row.
        field: String,
        /// What is wrong.
        message: String,
    },
    /// The law rejected a fingertip's measured curve (e.g. not monotone, too few points).
    #[error("{origin}: `{field}` ({}): {source}", path.display())]
    Law {
        /// The scene file.
        origin: String,
        /// Path of the field, e.g. `fingertip[0].level`.
        field: String,
        /// The curve file.
        path: PathBuf,
        /// The law's error.
        source: Box<softgrip_law::Error>,
    },
    /// A mesh file could not be read or parsed.
    #[error("{}:{line}: {message}", path.display())]
    Mesh {
        /// The mesh file.
        path: PathBuf,
        /// Line of the error (0 for binary files or I/O errors).
        line: usize,
        /// What is wrong.
        message: String,
    },
    /// A robot's URDF file could not be read, parsed or checked, or one of its meshes could not
    /// be loaded: the message names the link or joint and the value.
    #[error("{origin}: `{field}` ({}): {message}", path.display())]
    Urdf {
        /// The scene file.
        origin: String,
        /// The robot's field, e.g. `robot[0].urdf`.
        field: String,
        /// The URDF file.
        path: PathBuf,
        /// What is wrong, and where in the URDF.
        message: String,
    },
    /// A scene, mesh or curve file is larger than its read limit (`/dev/zero`, a wrong path).
    #[error(
        "{}: larger than the {} limit for a {what} file (limits in SCENES.md)",
        path.display(),
        crate::read::size(*limit)
    )]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// `scene`, `mesh` or `curve`.
        what: &'static str,
        /// The limit \[bytes\].
        limit: u64,
    },
    /// `duration / dt` is more steps than the scene's cap (`max_steps`, default
    /// [`DEFAULT_MAX_STEPS`](crate::DEFAULT_MAX_STEPS)).
    #[error(
        "{origin}: `duration` = {} s at `dt` = {} s is {steps:.4e} steps, more than the cap of {max_steps}: raise it with `max_steps = ...` at the top of the scene file, or use a larger `dt` or a shorter `duration`",
        softgrip_law::Shortest(*duration),
        softgrip_law::Shortest(*dt)
    )]
    TooManySteps {
        /// The file.
        origin: String,
        /// Simulated time \[s\].
        duration: f64,
        /// Time step \[s\].
        dt: f64,
        /// `duration / dt`, rounded.
        steps: f64,
        /// The cap in force.
        max_steps: u64,
    },
    /// A backed fingertip starts with its centre inside another shape (deeper than its radius),
    /// whichever side of it the nearest surface is on.
    #[error(
        "{origin}: `{fingertip}` starts buried in `{other}`: {} m deep, more than its radius R = {} m (its centre is inside): move the bodies apart (SCENES.md, \"Starting in contact\")",
        softgrip_law::Shortest(*depth),
        softgrip_law::Shortest(*radius)
    )]
    StartBuried {
        /// The file.
        origin: String,
        /// The fingertip, e.g. `fingertip[0]` (`left_tip`).
        fingertip: String,
        /// The other shape or fingertip.
        other: String,
        /// Penetration depth at the start \[m\].
        depth: f64,
        /// The fingertip's radius R \[m\].
        radius: f64,
    },
    /// A robot's link starts inside a fixed or kinematic body (at any depth) along a direction
    /// its joints cannot move it (a prismatic finger pressed into the table under a kinematic
    /// base): rapier's contact pushes it out through a mobility of `f32` noise and throws the
    /// link along its joint (0.5 mm into the table: the finger 2.7 km along its joint in the
    /// first step; 0.1 um blows up too).
    #[error(
        "{origin}: `{link}` starts {} m inside `{other}` along a direction its joints cannot move it (rapier's contact would throw it along its joints): raise the robot or move the body by at least that much (SCENES.md, \"Starting in contact\")",
        softgrip_law::Shortest(*depth)
    )]
    StartBlocked {
        /// The file.
        origin: String,
        /// The robot's link shape, e.g. `robot[0] (`gripper`) link `left_finger` collision[0]`.
        link: String,
        /// The fixed or kinematic body's shape, e.g. `body[0].shape[0] (`table`)`.
        other: String,
        /// Penetration depth at the start \[m\].
        depth: f64,
    },
    /// A fingertip sits on a link of a robot with `joints = "impulse"` that the soft solve
    /// cannot see through its joints: its assembly needs more Gauss-Seidel sweeps per solver
    /// pass than [`MAX_JOINTED_SWEEPS`](crate::robot::MAX_JOINTED_SWEEPS), or is not one the
    /// solve reads (more than 8 bodies held together by impulse joints, or rapier's sweeps over
    /// it never converge). The solve would take the link as a free body and get its contact
    /// force wrong; as a multibody (the default) the solve reads the link through rapier's
    /// multibody.
    #[error(
        "{origin}: `{field}` = \"impulse\": the contact solve cannot see `{link}` through its impulse joints ({}): the fingertip's force would be computed as on a free body; use joints = \"multibody\" (the default) (SCENES.md, `[[robot]]`, `joints`)",
        match needed {
            Some(n) => format!("rapier would need {n} Gauss-Seidel sweeps per solver pass over its joints, at most {max} are given"),
            None => "its assembly has more than 8 bodies held by impulse joints, or rapier's sweeps over its joints never converge".to_string(),
        }
    )]
    JointedUnseen {
        /// The file.
        origin: String,
        /// The robot's field, e.g. `robot[0].joints`.
        field: String,
        /// The padded link, e.g. `robot[0] (`hand`) link `f0_distal``.
        link: String,
        /// The sweeps per solver pass it would need (with the margin); `None` where its
        /// assembly is not one the solve reads.
        needed: Option<usize>,
        /// [`MAX_JOINTED_SWEEPS`](crate::robot::MAX_JOINTED_SWEEPS).
        max: usize,
    },
    /// A robot's link starts inside a dynamic body deeper than rapier's allowed linear error:
    /// rapier would push the two apart in the first steps, through whatever holds the body.
    #[error(
        "{origin}: `{link}` starts {} m inside `{other}` (more than rapier's allowed linear error, {} m; rapier would push the body out through whatever holds it): move the body or the robot (SCENES.md, \"Starting in contact\")",
        softgrip_law::Shortest(*depth),
        softgrip_law::Shortest(*allowed)
    )]
    StartOverlap {
        /// The file.
        origin: String,
        /// The robot's link shape, e.g. `robot[0] (`gripper`) link `base_link` collision[0]`.
        link: String,
        /// The body's shape, e.g. `body[1].shape[0] (`cylinder`)`.
        other: String,
        /// Penetration depth at the start \[m\].
        depth: f64,
        /// rapier's allowed linear error (the depth it leaves alone) \[m\].
        allowed: f64,
    },
    /// A fingertip starts pressed into another body deeper than its law's validity range.
    #[error(
        "{origin}: `{fingertip}` starts {depth:.4e} m inside `{other}` (x = {x:.4}, past the law's validity x <= {x_max:.4}): move the bodies apart (SCENES.md, \"Starting in contact\")"
    )]
    StartPenetration {
        /// The file.
        origin: String,
        /// The fingertip, e.g. `fingertip[0]` (`left_tip`).
        fingertip: String,
        /// The other shape, e.g. `body[1].shape[0]` (`box`) or another fingertip.
        other: String,
        /// Penetration depth at the start \[m\].
        depth: f64,
        /// Compression ratio depth / R of the pair [-].
        x: f64,
        /// The law's largest valid compression ratio [-].
        x_max: f64,
    },
}

impl SceneError {
    /// The scene field path this error is about, if it is about one (a curve file's column
    /// is in [`SceneError::Curve`]'s `field`).
    pub fn field(&self) -> Option<&str> {
        match self {
            SceneError::Invalid { field, .. }
            | SceneError::Name { field, .. }
            | SceneError::Fingertip { field, .. }
            | SceneError::Law { field, .. }
            | SceneError::Urdf { field, .. }
            | SceneError::JointedUnseen { field, .. } => Some(field),
            _ => None,
        }
    }
}

/// `` `field`: message ``, or the message alone without a field.
fn with_field(field: &str, message: &str) -> String {
    if field.is_empty() {
        message.to_string()
    } else {
        format!("`{field}`: {message}")
    }
}
