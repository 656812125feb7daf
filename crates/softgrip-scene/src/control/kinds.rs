//! [`CONTROLLERS`]: the one table of controller kinds. Every name, file code and description
//! of a controller kind is here and nowhere else: [`ControllerKind`]
//! reads it, and so do the scene files (`[[controller]] type = ...` is parsed through it, an
//! unknown `type` is refused listing it), every [`Controller`](super::Controller)'s
//! [`kind`](super::Controller::kind), SCENES.md's table (a test checks it row for row) and the
//! default names of the controllers that have one.
//!
//! A new kind is one new row (and its [`ControllerKind`] variant; `tests/controller_kinds.rs`
//! fails until the row exists) with a new code: a code once written to a file keeps its
//! meaning for ever, so codes are never reused or derived from the enum's order. A kind a
//! scene file names also needs its arm in [`ControllerSpec`](super::ControllerSpec)'s reader
//! (the compiler asks for it: the match is exhaustive).

use std::fmt;

/// A controller kind, as a plain name (its row of [`CONTROLLERS`] says everything else).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ControllerKind {
    /// Kinematic jaws ([`ParallelJaws`](super::ParallelJaws), the `[gripper]`).
    ParallelJaws,
    /// Joint position targets over time ([`JointTrajectory`](super::JointTrajectory)).
    Trajectory,
    /// The grasp primitive of a group of joints ([`Grasp`](super::Grasp)).
    Grasp,
    /// A robot's commands from outside ([`JointCommands`](super::JointCommands)).
    JointCommands,
}

/// Who creates a controller of a kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ControllerSource {
    /// A scene file, `[[controller]] type = "<name>"`.
    SceneFile,
    /// The scene itself, one for every robot (never written in a scene file).
    EveryRobot,
}

/// One row of [`CONTROLLERS`]: everything softgrip says about a controller kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ControllerInfo {
    /// The kind.
    pub kind: ControllerKind,
    /// Its name: a scene file's `type`, [`Controller::kind`](super::Controller::kind)'s name,
    /// SCENES.md; the default name of a controller of the kind where the kind has one.
    pub name: &'static str,
    /// Its fixed code in files: never reused, never derived from the enum's order.
    pub code: u8,
    /// Who creates it.
    pub source: ControllerSource,
    /// What it does, on one line (SCENES.md's "what" column starts with it).
    pub description: &'static str,
}

/// Every controller kind. The codes: 0 = parallel_jaws, 1 = trajectory, 2 = grasp,
/// 3 = joint_commands.
pub const CONTROLLERS: [ControllerInfo; 4] = [
    ControllerInfo {
        kind: ControllerKind::ParallelJaws,
        name: "parallel_jaws",
        code: 0,
        source: ControllerSource::SceneFile,
        description: "kinematic jaws, as `[gripper]`",
    },
    ControllerInfo {
        kind: ControllerKind::Trajectory,
        name: "trajectory",
        code: 1,
        source: ControllerSource::SceneFile,
        description: "joint position targets over time: linear between points, the velocity target the segment's slope, held before the first and after the last",
    },
    ControllerInfo {
        kind: ControllerKind::Grasp,
        name: "grasp",
        code: 2,
        source: ControllerSource::SceneFile,
        description: "a grasp primitive for a group of joints",
    },
    ControllerInfo {
        kind: ControllerKind::JointCommands,
        name: "joint_commands",
        code: 3,
        source: ControllerSource::EveryRobot,
        description: "a robot's commands from outside (ROS 2's joint commands and gripper action, Python), named `<robot>/commands`",
    },
];

/// A `type` that names no controller a scene file can hold.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownControllerKind {
    /// The name given.
    pub name: String,
}

impl fmt::Display for UnknownControllerKind {
    /// "unknown controller type \`NAME\`, expected one of \`a\`, \`b\`, ..." (the table's
    /// scene kinds), plus why when the name is a kind no scene file names.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names: Vec<String> = (CONTROLLERS.iter())
            .filter(|row| row.source == ControllerSource::SceneFile)
            .map(|row| format!("`{}`", row.name))
            .collect();
        write!(
            f,
            "unknown controller type `{}`, expected one of {}",
            self.name,
            names.join(", ")
        )?;
        if let Some(row) = CONTROLLERS.iter().find(|row| row.name == self.name) {
            write!(f, " (`{}` is added for every robot, not written)", row.name)?;
        }
        Ok(())
    }
}

impl std::error::Error for UnknownControllerKind {}

impl ControllerKind {
    /// The kind's row of [`CONTROLLERS`].
    pub fn info(self) -> &'static ControllerInfo {
        CONTROLLERS.iter().find(|row| row.kind == self).expect(
            "invariant: every ControllerKind has a row in CONTROLLERS (tests/controller_kinds.rs)",
        )
    }

    /// Its name ([`ControllerInfo::name`]).
    pub fn name(self) -> &'static str {
        self.info().name
    }

    /// Its fixed code in files ([`ControllerInfo::code`]).
    pub fn code(self) -> u8 {
        self.info().code
    }

    /// The kind of code `code`, if any.
    ///
    /// ```
    /// use softgrip_scene::control::ControllerKind;
    /// assert_eq!(ControllerKind::from_code(2), Some(ControllerKind::Grasp));
    /// assert_eq!(ControllerKind::from_code(200), None);
    /// ```
    pub fn from_code(code: u8) -> Option<Self> {
        (CONTROLLERS.iter())
            .find(|row| row.code == code)
            .map(|row| row.kind)
    }

    /// The kind a scene file's `type = "<name>"` names: a row of [`CONTROLLERS`] created by
    /// a scene file. Anything else is an error listing those rows.
    ///
    /// ```
    /// use softgrip_scene::control::ControllerKind;
    /// assert_eq!(ControllerKind::from_scene_name("grasp"), Ok(ControllerKind::Grasp));
    /// let e = ControllerKind::from_scene_name("joint_commands").unwrap_err().to_string();
    /// assert!(e.contains("`parallel_jaws`, `trajectory`, `grasp`"), "{e}");
    /// assert!(e.contains("added for every robot"), "{e}");
    /// ```
    pub fn from_scene_name(name: &str) -> Result<Self, UnknownControllerKind> {
        (CONTROLLERS.iter())
            .find(|row| row.name == name && row.source == ControllerSource::SceneFile)
            .map(|row| row.kind)
            .ok_or_else(|| UnknownControllerKind { name: name.into() })
    }
}

impl fmt::Display for ControllerKind {
    /// Its name.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
