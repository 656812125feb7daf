//! [`Scene`]: a whole experiment in TOML (format in SCENES.md). [`Scene::parse`] reads and
//! checks a file once; a [`Scene`] that exists is valid.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use softgrip_rapier::SoftFingertip;
use softgrip_rapier::rapier3d::prelude::SharedShape;

use crate::error::SceneError;
use crate::fingertips;
use crate::format::SceneFile;
use crate::gripper::GripperProgram;
use crate::limits::MAX_SCENE_BYTES;
use crate::read::{ReadError, read_bounded};
use crate::start;
use crate::validate::{self, Checker};

/// The embedded default scene (`scenes/default.toml`): a parallel-jaw gripper with two soft
/// hemispherical fingertips approaches a box, squeezes it, lifts, holds and releases it.
pub const DEFAULT_SCENE: &str = include_str!("../../../scenes/default.toml");

/// A checked scene: the file's description plus what was derived from it (shapes with their
/// meshes loaded, fingertips with their laws bound, the gripper's program).
#[derive(Debug, Clone)]
pub struct Scene {
    origin: String,
    file: SceneFile,
    shapes: Vec<Vec<SharedShape>>,
    fingertips: Vec<SoftFingertip>,
    gripper: Option<GripperProgram>,
    /// The index of each body's name in `file.bodies` (names are unique: checked).
    body_index: HashMap<String, usize>,
}

impl Scene {
    /// Parses and checks TOML text. `origin` names it in errors; mesh and curve files are
    /// looked up relative to `base_dir`.
    pub fn parse(text: &str, origin: &str, base_dir: &Path) -> Result<Self, SceneError> {
        let file: SceneFile = toml::from_str(text).map_err(|e| {
            let (line, column) = e
                .span()
                .map(|s| line_column(text, s.start))
                .unwrap_or((0, 0));
            SceneError::Parse {
                origin: origin.to_string(),
                line,
                column,
                message: e.message().trim().to_string(),
            }
        })?;
        let c = Checker { origin };
        let meshes = validate::check_bodies(&c, &file, base_dir)?;
        let shapes = validate::shapes(&c, &file, meshes)?;
        let fingertips = fingertips::check_fingertips(&c, &file, base_dir)?;
        let gripper = match &file.gripper {
            Some(g) => Some(GripperProgram::from_spec(&c, &file, &fingertips, g)?),
            None => None,
        };
        let body_index = file
            .bodies
            .iter()
            .enumerate()
            .map(|(i, b)| (b.name.clone(), i))
            .collect();
        let scene = Self {
            origin: origin.to_string(),
            file,
            shapes,
            fingertips,
            gripper,
            body_index,
        };
        start::check_start(&c, &scene)?;
        Ok(scene)
    }

    /// Reads and checks a scene file.
    pub fn from_file(path: &Path) -> Result<Self, SceneError> {
        let origin = path.display().to_string();
        let io = |source| SceneError::Io {
            origin: origin.clone(),
            source,
        };
        let bytes = read_bounded(path, MAX_SCENE_BYTES).map_err(|e| match e {
            ReadError::Io(e) => io(e),
            ReadError::TooLarge { limit } => SceneError::TooLarge {
                path: path.to_path_buf(),
                what: "scene",
                limit,
            },
        })?;
        let text = String::from_utf8(bytes)
            .map_err(|e| io(std::io::Error::new(std::io::ErrorKind::InvalidData, e)))?;
        let base = path.parent().map(Path::to_path_buf).unwrap_or_default();
        Self::parse(&text, &origin, &base)
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

    /// The gripper's program, if the scene has a gripper.
    pub fn gripper(&self) -> Option<&GripperProgram> {
        self.gripper.as_ref()
    }

    /// Number of steps: `duration / dt`, rounded to the nearest integer (at least 1).
    pub fn steps(&self) -> u64 {
        ((self.file.duration / self.file.dt).round() as u64).max(1)
    }

    /// Index of the body named `name`.
    pub fn body_index(&self, name: &str) -> Option<usize> {
        self.body_index.get(name).copied()
    }
}

/// Line and column (from 1) of byte `offset` in `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}
