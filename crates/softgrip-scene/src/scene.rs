//! [`Scene`]: a whole experiment in TOML (format in SCENES.md). [`Scene::parse`] reads and
//! checks a file once; a [`Scene`] that exists is valid.

use std::collections::HashMap;
use std::io::Read;
use std::path::{Path, PathBuf};

use softgrip_rapier::SoftFingertip;
use softgrip_rapier::rapier3d::prelude::SharedShape;

use crate::build::SceneHandles;
use crate::control::{
    Carrier, ControlSet, Controller, ControllerSpec, Grasp, GripperProgram, JointCommands,
    JointTrajectory, ParallelJaws,
};
use crate::error::SceneError;
use crate::fingertips;
use crate::format::SceneFile;
use crate::level::LevelSpec;
use crate::limits::MAX_SCENE_BYTES;
use crate::read::{ReadError, read_bounded, read_limited, strip_bom_str};
use crate::robot::Robot;
use crate::start;
use crate::validate::{self, Checker};
use softgrip_law::shorten_numbers;

/// The embedded default scene (`scenes/default.toml`): a parallel-jaw gripper with two soft
/// hemispherical fingertips approaches a box, squeezes it, lifts, holds and releases it.
pub const DEFAULT_SCENE: &str = include_str!("../../../scenes/default.toml");

/// A checked scene: the file's description plus what was derived from it (shapes with their
/// meshes loaded, fingertips with their laws bound, the gripper's program).
#[derive(Debug, Clone)]
pub struct Scene {
    origin: String,
    /// The folder mesh and curve paths are relative to.
    base_dir: PathBuf,
    file: SceneFile,
    shapes: Vec<Vec<SharedShape>>,
    robots: Vec<Robot>,
    fingertips: Vec<SoftFingertip>,
    carriers: Vec<Carrier>,
    gripper: Option<GripperProgram>,
    controllers: Vec<Box<dyn Controller>>,
    /// The index of each body's name in `file.bodies` (names are unique: checked).
    body_index: HashMap<String, usize>,
}

impl Scene {
    /// Parses and checks TOML text. `origin` names it in errors; mesh and curve files are
    /// looked up relative to `base_dir`. A leading byte-order mark (U+FEFF) is skipped.
    pub fn parse(text: &str, origin: &str, base_dir: &Path) -> Result<Self, SceneError> {
        let text = strip_bom_str(text);
        let file: SceneFile = toml::from_str(text).map_err(|e| {
            let (line, column) = e
                .span()
                .map(|s| line_column(text, s.start))
                .unwrap_or((0, 0));
            SceneError::Parse {
                origin: origin.to_string(),
                line,
                column,
                message: shorten_numbers(e.message().trim()),
            }
        })?;
        let c = Checker { origin };
        let meshes = validate::check_bodies(&c, &file, base_dir)?;
        let shapes = validate::shapes(&c, &file, meshes)?;
        let robots = crate::robots::check_robots(&c, &file, base_dir)?;
        let (fingertips, carriers) = fingertips::check_fingertips(&c, &file, &robots, base_dir)?;
        let gripper = match &file.gripper {
            Some(g) => Some(GripperProgram::from_spec(&c, &file, &fingertips, g)?),
            None => None,
        };
        let mut controllers: Vec<Box<dyn Controller>> = Vec::new();
        if let Some(p) = &gripper {
            controllers.push(Box::new(jaws(&file, p.clone())));
        }
        for (i, spec) in file.controllers.iter().enumerate() {
            let field = format!("controller[{i}]");
            controllers.push(match spec {
                ControllerSpec::ParallelJaws(g) => {
                    let p = GripperProgram::from_spec(&c, &file, &fingertips, g)?;
                    Box::new(jaws(&file, p))
                }
                ControllerSpec::Trajectory(t) => {
                    Box::new(JointTrajectory::from_spec(&c, &field, &robots, t)?)
                }
                ControllerSpec::Grasp(g) => Box::new(Grasp::from_spec(
                    &c,
                    &field,
                    &robots,
                    &carriers,
                    file.gravity,
                    g,
                )?),
            });
        }
        let mut names = std::collections::HashSet::new();
        for (i, ctrl) in controllers.iter().enumerate() {
            if !names.insert(ctrl.name().to_string()) {
                return Err(c.name(
                    format!("controller[{i}].name"),
                    format!("`{}` is used twice (the `[gripper]` counts)", ctrl.name()),
                ));
            }
        }
        for (i, r) in robots.iter().enumerate() {
            controllers.push(Box::new(JointCommands::new(i, r)));
        }
        let body_index = file
            .bodies
            .iter()
            .enumerate()
            .map(|(i, b)| (b.name.clone(), i))
            .collect();
        let scene = Self {
            origin: origin.to_string(),
            base_dir: base_dir.to_path_buf(),
            file,
            shapes,
            robots,
            fingertips,
            carriers,
            gripper,
            controllers,
            body_index,
        };
        start::check_start(&c, &scene)?;
        Ok(scene)
    }

    /// Reads and checks a scene file.
    pub fn from_file(path: &Path) -> Result<Self, SceneError> {
        Self::from_file_with_text(path).map(|(scene, _)| scene)
    }

    /// Reads a scene file once (any kind of file: a pipe such as `/dev/stdin` can be read only
    /// once) and checks it; also returns its text as read, for a recording's metadata.
    pub fn from_file_with_text(path: &Path) -> Result<(Self, String), SceneError> {
        let text = read_text(path)?;
        let base = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Ok((
            Self::parse(&text, &path.display().to_string(), &base)?,
            text,
        ))
    }

    /// The embedded default scene ([`DEFAULT_SCENE`]).
    pub fn default_scene() -> Self {
        Self::parse(DEFAULT_SCENE, "scenes/default.toml", &PathBuf::from("."))
            .expect("invariant: the embedded default scene is valid (tested)")
    }

    /// Where the scene came from (file name or `scenes/default.toml`).
    pub fn origin(&self) -> &str {
        &self.origin
    }

    /// The scene as written (with defaults filled in).
    pub fn file(&self) -> &SceneFile {
        &self.file
    }

    /// The shapes of body `i`, in file order.
    pub fn shapes(&self, body: usize) -> &[SharedShape] {
        &self.shapes[body]
    }

    /// The fingertips, in file order.
    pub fn fingertips(&self) -> &[SoftFingertip] {
        &self.fingertips
    }

    /// The `[gripper]`'s program, if the scene has one.
    pub fn gripper(&self) -> Option<&GripperProgram> {
        self.gripper.as_ref()
    }

    /// The robots, in file order.
    pub fn robots(&self) -> &[Robot] {
        &self.robots
    }

    /// Index of the robot named `name`.
    pub fn robot_index(&self, name: &str) -> Option<usize> {
        self.robots.iter().position(|r| r.name() == name)
    }

    /// What carries each fingertip (a body or a robot's link), in file order.
    pub fn carriers(&self) -> &[Carrier] {
        &self.carriers
    }

    /// The name of a carrier: the body's, or `<robot>/<link>` (its tf frame).
    pub fn carrier_name(&self, c: Carrier) -> String {
        match c {
            Carrier::Body(i) => self.file.bodies[i].name.clone(),
            Carrier::Link { robot, link } => self.robots[robot].frame(link),
        }
    }

    /// The controllers in their start state, in the order they run: the `[gripper]`, the
    /// `[[controller]]`s, then each robot's commands from outside.
    pub fn controllers(&self) -> Vec<Box<dyn Controller>> {
        self.controllers.clone()
    }

    /// The controllers over a world built with `handles` ([`Scene::build_into`]).
    pub fn control_set(&self, handles: &SceneHandles) -> ControlSet {
        ControlSet::new(self.controllers(), handles.clone(), self.robots.clone())
    }

    /// Number of steps: `duration / dt`, rounded to the nearest integer (at least 1).
    pub fn steps(&self) -> u64 {
        ((self.file.duration / self.file.dt).round() as u64).max(1)
    }

    /// The folder the scene's mesh and curve paths are relative to.
    pub fn base_dir(&self) -> &Path {
        &self.base_dir
    }

    /// The files the scene reads besides itself: every mesh and measured curve, each once, as
    /// resolved against [`base_dir`](Self::base_dir) (what an output must never replace).
    pub fn input_files(&self) -> Vec<PathBuf> {
        let meshes = (self.file.bodies.iter())
            .flat_map(|b| &b.shapes)
            .filter_map(|s| s.file.as_deref());
        let curves = self.file.fingertips.iter().filter_map(|t| match &t.level {
            LevelSpec::Tabulated(p) => Some(p.as_str()),
            LevelSpec::Named(_) => None,
        });
        let mut files: Vec<PathBuf> = Vec::new();
        for p in meshes.chain(curves).map(|p| self.base_dir.join(p)) {
            if !files.contains(&p) {
                files.push(p);
            }
        }
        files
    }

    /// Index of the body named `name`.
    pub fn body_index(&self, name: &str) -> Option<usize> {
        self.body_index.get(name).copied()
    }
}

/// A scene file's text: at most [`MAX_SCENE_BYTES`], UTF-8, a leading byte-order mark
/// dropped. The file is opened and read once, whatever it is (a regular file, a pipe).
pub fn read_text(path: &Path) -> Result<String, SceneError> {
    let origin = path.display().to_string();
    let bytes = read_bounded(path, MAX_SCENE_BYTES).map_err(|e| read_error(e, path, &origin))?;
    utf8(bytes, &origin)
}

/// A scene's text from `reader` (standard input), as [`read_text`]; `origin` names it.
pub fn read_text_from(reader: impl Read, origin: &str) -> Result<String, SceneError> {
    let bytes = read_limited(reader, MAX_SCENE_BYTES)
        .map_err(|e| read_error(e, Path::new(origin), origin))?;
    utf8(bytes, origin)
}

fn read_error(e: ReadError, path: &Path, origin: &str) -> SceneError {
    match e {
        ReadError::Io(source) => SceneError::Io {
            origin: origin.to_string(),
            source,
        },
        ReadError::TooLarge { limit } => SceneError::TooLarge {
            path: path.to_path_buf(),
            what: "scene",
            limit,
        },
        ReadError::NotRegular(kind) => SceneError::Io {
            origin: origin.to_string(),
            source: std::io::Error::other(format!("is {kind}")),
        },
    }
}

fn utf8(bytes: Vec<u8>, origin: &str) -> Result<String, SceneError> {
    let text = String::from_utf8(bytes).map_err(|e| SceneError::Io {
        origin: origin.to_string(),
        source: std::io::Error::new(std::io::ErrorKind::InvalidData, e),
    })?;
    Ok(strip_bom_str(&text).to_string())
}

/// Line and column (from 1) of byte `offset` in `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// The parallel jaws of `program`, at their bodies' start positions.
fn jaws(file: &SceneFile, program: GripperProgram) -> ParallelJaws {
    let positions = program
        .jaws
        .iter()
        .map(|&i| file.bodies[i].position)
        .collect();
    ParallelJaws::new(program, positions)
}
