//! Scene files: a whole experiment in TOML (format in SCENES.md). [`Scene::parse`] reads and
//! checks a file once; a [`Scene`] that exists is valid.

mod build;
mod error;
mod format;
mod mesh;
pub(crate) mod validate;

use std::path::{Path, PathBuf};

use softgrip_rapier::SoftFingertip;
use softgrip_rapier::rapier3d::prelude::SharedShape;

pub use build::{body_from_spec, collider_from_spec, fingertip_from_spec};
pub use error::SceneError;
pub use format::{
    BodyKindSpec, BodySpec, DEFAULT_EVERY_N_STEPS, FingertipSpec, GripperSpec, MaterialSpec,
    MoveSpec, RecordSpec, SceneFile, ShapeKind, ShapeSpec, SqueezeSpec, WaypointSpec,
};
pub use mesh::{Mesh, load_mesh, parse_obj, parse_stl};

use crate::gripper::GripperProgram;
use validate::Checker;

/// The embedded default scene (`scenes/default.toml`): a parallel-jaw gripper with two soft
/// hemispherical fingertips approaches a box, squeezes it, lifts, holds and releases it.
pub const DEFAULT_SCENE: &str = include_str!("../../../../scenes/default.toml");

/// A checked scene: the file's description plus what was derived from it (shapes with their
/// meshes loaded, fingertips with their laws bound, the gripper's program).
#[derive(Debug, Clone)]
pub struct Scene {
    origin: String,
    file: SceneFile,
    shapes: Vec<Vec<SharedShape>>,
    fingertips: Vec<SoftFingertip>,
    gripper: Option<GripperProgram>,
}

impl Scene {
    /// Parses and checks TOML text. `origin` names it in errors; mesh files are looked up
    /// relative to `base_dir`.
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
        let mut shapes = Vec::new();
        for (i, (body, body_meshes)) in file.bodies.iter().zip(meshes).enumerate() {
            let mut list = Vec::new();
            for (j, (spec, mesh)) in body.shapes.iter().zip(body_meshes).enumerate() {
                let shape = build::shape(spec, mesh).ok_or_else(|| {
                    c.invalid(
                        format!("body[{i}].shape[{j}].file"),
                        spec.file.clone().unwrap_or_default(),
                        "a mesh with a non-degenerate hull and valid triangles",
                    )
                })?;
                list.push(shape);
            }
            shapes.push(list);
        }
        let fingertips = validate::check_fingertips(&c, &file)?;
        let gripper = match &file.gripper {
            Some(g) => Some(GripperProgram::from_spec(&c, &file, &fingertips, g)?),
            None => None,
        };
        Ok(Self {
            origin: origin.to_string(),
            file,
            shapes,
            fingertips,
            gripper,
        })
    }

    /// Reads and checks a scene file.
    pub fn from_file(path: &Path) -> Result<Self, SceneError> {
        let origin = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|source| SceneError::Io {
            origin: origin.clone(),
            source,
        })?;
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
        self.file.bodies.iter().position(|b| b.name == name)
    }
}

/// Line and column (from 1) of byte `offset` in `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = &text[..offset.min(text.len())];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// A scripted path: waypoints `(t [s], position [m])`, linear in between, held before the
/// first and after the last.
#[derive(Debug, Clone, PartialEq)]
pub struct Trajectory {
    /// The waypoints, `t` strictly increasing.
    pub waypoints: Vec<(f64, [f64; 3])>,
}

impl Trajectory {
    /// The trajectory of a body spec (empty if it has none).
    pub fn of(body: &BodySpec) -> Self {
        Self {
            waypoints: body.trajectory.iter().map(|w| (w.t, w.position)).collect(),
        }
    }

    /// Position at time `t` [s]; `None` for an empty trajectory.
    pub fn position_at(&self, t: f64) -> Option<[f64; 3]> {
        let (first, last) = (self.waypoints.first()?, self.waypoints.last()?);
        if t <= first.0 {
            return Some(first.1);
        }
        if t >= last.0 {
            return Some(last.1);
        }
        let k = self.waypoints.iter().position(|w| w.0 > t)?;
        let ((t0, p0), (t1, p1)) = (self.waypoints[k - 1], self.waypoints[k]);
        let s = (t - t0) / (t1 - t0);
        Some([0, 1, 2].map(|i| p0[i] + s * (p1[i] - p0[i])))
    }
}
