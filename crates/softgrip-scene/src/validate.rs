//! Range and cross-reference checks of a parsed [`SceneFile`], into typed [`SceneError`]s
//! naming the field.

use std::collections::HashSet;
use std::path::Path;

use softgrip_law::Shortest;
use softgrip_rapier::SoftAccuracy;
use softgrip_rapier::rapier3d::prelude::SharedShape;

use crate::error::SceneError;
use crate::format::{BodyKind, SceneFile, ShapeKind, ShapeSpec};
use crate::limits::{
    MAX_COORDINATE, MAX_DENSITY, MAX_DT, MAX_FRICTION, MAX_GRAVITY, MAX_ROTATION_ANGLE, MAX_SIZE,
    MAX_TIME, MIN_DENSITY, MIN_DT, MIN_SIZE, RESERVED_FRAME_NAMES,
};
use crate::mesh::{Mesh, check_geometry, load_mesh};
use crate::shape::shape;

/// Builds typed errors for one file.
pub(crate) struct Checker<'a> {
    /// The file, named in every error.
    pub origin: &'a str,
}

impl Checker<'_> {
    pub fn invalid(
        &self,
        field: impl Into<String>,
        value: impl std::fmt::Debug,
        expected: &str,
    ) -> SceneError {
        SceneError::Invalid {
            origin: self.origin.to_string(),
            field: field.into(),
            value: format!("{value:?}"),
            expected: expected.to_string(),
        }
    }

    pub fn name(&self, field: impl Into<String>, message: impl Into<String>) -> SceneError {
        SceneError::Name {
            origin: self.origin.to_string(),
            field: field.into(),
            message: message.into(),
        }
    }

    /// `v` finite and > 0.
    pub fn positive(&self, field: impl Into<String>, v: f64, unit: &str) -> Result<(), SceneError> {
        if v.is_finite() && v > 0.0 {
            Ok(())
        } else {
            Err(self.invalid(field, v, &format!("finite and > 0 {unit}")))
        }
    }

    /// `v` finite and in `[lo, hi]`.
    pub fn range(
        &self,
        field: impl Into<String>,
        v: f64,
        (lo, hi): (f64, f64),
        unit: &str,
    ) -> Result<(), SceneError> {
        if v.is_finite() && (lo..=hi).contains(&v) {
            Ok(())
        } else {
            Err(self.invalid(field, v, &format!("in [{lo:e}, {hi:e}] {unit}")))
        }
    }

    /// A position \[m\]: every component finite and within [`MAX_COORDINATE`].
    pub fn coords(&self, field: impl Into<String>, v: [f64; 3]) -> Result<(), SceneError> {
        if v.iter().all(|c| c.is_finite() && c.abs() <= MAX_COORDINATE) {
            Ok(())
        } else {
            let expected = format!("three finite numbers within ±{MAX_COORDINATE:e} m");
            Err(self.invalid(field, v, &expected))
        }
    }

    /// A shape's size \[m\], in [[`MIN_SIZE`], [`MAX_SIZE`]].
    pub fn size(&self, field: impl Into<String>, v: f64) -> Result<(), SceneError> {
        self.range(field, v, (MIN_SIZE, MAX_SIZE), "m")
    }

    /// Every component finite.
    pub fn finite3(&self, field: impl Into<String>, v: [f64; 3]) -> Result<(), SceneError> {
        if v.iter().all(|c| c.is_finite()) {
            Ok(())
        } else {
            Err(self.invalid(field, v, "three finite numbers"))
        }
    }

    /// A non-zero finite vector, normalised.
    pub fn direction(&self, field: impl Into<String>, v: [f64; 3]) -> Result<[f64; 3], SceneError> {
        let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        if n.is_finite() && n > 0.0 {
            Ok(v.map(|c| c / n))
        } else {
            Err(self.invalid(field, v, "a finite, non-zero direction"))
        }
    }
}

/// Checks the simulation settings and bodies; loads the meshes (one per shape, `None` for
/// primitive shapes).
pub(crate) fn check_bodies(
    c: &Checker,
    file: &SceneFile,
    base: &Path,
) -> Result<Vec<Vec<Option<Mesh>>>, SceneError> {
    check_time(c, file)?;
    c.finite3("gravity", file.gravity)?;
    let g = file.gravity.iter().map(|x| x * x).sum::<f64>().sqrt();
    if g > MAX_GRAVITY {
        let expected = format!("of magnitude <= {MAX_GRAVITY:e} m/s^2");
        return Err(c.invalid("gravity", file.gravity, &expected));
    }
    SoftAccuracy::try_new(file.accuracy)
        .map_err(|_| c.invalid("accuracy", file.accuracy, "in (0, 2] rad"))?;
    if file.record.every_n_steps == 0 {
        return Err(c.invalid("record.every_n_steps", 0u64, ">= 1 (1 = every step)"));
    }
    let mut names = HashSet::new();
    let mut meshes = Vec::new();
    for (i, b) in file.bodies.iter().enumerate() {
        let f = |s: &str| format!("body[{i}].{s}");
        if b.name.is_empty() || !names.insert(b.name.as_str()) {
            return Err(c.name(f("name"), format!("`{}` is empty or used twice", b.name)));
        }
        if RESERVED_FRAME_NAMES.contains(&b.name.as_str()) {
            return Err(c.name(
                f("name"),
                format!(
                    "`{}` is reserved: it is the recordings' fixed root frame, the parent of every body's frame on /tf (REP 103); rename the body",
                    b.name
                ),
            ));
        }
        c.coords(f("position"), b.position)?;
        c.finite3(f("rotation"), b.rotation)?;
        let angle = b.rotation.iter().map(|x| x * x).sum::<f64>().sqrt();
        if angle > MAX_ROTATION_ANGLE {
            let expected = format!("a rotation vector of angle <= {MAX_ROTATION_ANGLE} rad");
            return Err(c.invalid(f("rotation"), b.rotation, &expected));
        }
        if !b.trajectory.is_empty() && b.kind != BodyKind::Kinematic {
            return Err(c.invalid(f("trajectory"), b.kind, "given only for a `kinematic` body"));
        }
        let mut last = -1.0;
        for (k, w) in b.trajectory.iter().enumerate() {
            if !(w.t.is_finite() && w.t >= 0.0 && w.t > last && w.t <= MAX_TIME) {
                return Err(c.invalid(
                    f(&format!("trajectory[{k}].t")),
                    w.t,
                    &format!("finite, in [0, {MAX_TIME:e}] s and increasing"),
                ));
            }
            last = w.t;
            c.coords(f(&format!("trajectory[{k}].position")), w.position)?;
        }
        let mut body_meshes = Vec::new();
        for (j, s) in b.shapes.iter().enumerate() {
            let g = |x: &str| format!("body[{i}].shape[{j}].{x}");
            body_meshes.push(check_shape(c, s, b.kind, base, &g)?);
        }
        meshes.push(body_meshes);
    }
    Ok(meshes)
}

fn check_shape(
    c: &Checker,
    s: &ShapeSpec,
    kind: BodyKind,
    base: &Path,
    g: &dyn Fn(&str) -> String,
) -> Result<Option<Mesh>, SceneError> {
    let need = |name: &str, present: bool| {
        if present {
            Ok(())
        } else {
            Err(c.name(g(name), format!("required by shape type {:?}", s.kind)))
        }
    };
    let allowed: &[&str] = match s.kind {
        ShapeKind::Plane => &["normal"],
        ShapeKind::Cuboid => &["half_extents"],
        ShapeKind::Ball => &["radius"],
        ShapeKind::Cylinder => &["radius", "half_height"],
        ShapeKind::ConvexMesh | ShapeKind::TriangleMesh => &["file", "scale"],
    };
    let given = [
        ("normal", s.normal.is_some()),
        ("half_extents", s.half_extents.is_some()),
        ("radius", s.radius.is_some()),
        ("half_height", s.half_height.is_some()),
        ("file", s.file.is_some()),
        ("scale", s.scale.is_some()),
    ];
    for (name, present) in given {
        if present && !allowed.contains(&name) {
            return Err(c.name(g(name), format!("not a field of shape type {:?}", s.kind)));
        }
    }
    c.coords(g("offset"), s.offset)?;
    c.range(
        g("density"),
        s.density,
        (MIN_DENSITY, MAX_DENSITY),
        "kg/m^3",
    )?;
    c.range(g("friction"), s.friction, (0.0, MAX_FRICTION), "")?;
    if !(0.0..=1.0).contains(&s.restitution) {
        return Err(c.invalid(g("restitution"), s.restitution, "in [0, 1]"));
    }
    match s.kind {
        ShapeKind::Plane => {
            need("normal", s.normal.is_some())?;
            c.direction(g("normal"), s.normal.unwrap_or_default())?;
            if kind != BodyKind::Fixed {
                return Err(c.invalid(g("type"), "plane", "used on a `fixed` body only"));
            }
        }
        ShapeKind::Cuboid => {
            need("half_extents", s.half_extents.is_some())?;
            for (k, h) in s.half_extents.unwrap_or_default().iter().enumerate() {
                c.size(g(&format!("half_extents[{k}]")), *h)?;
            }
        }
        ShapeKind::Ball => {
            need("radius", s.radius.is_some())?;
            c.size(g("radius"), s.radius.unwrap_or_default())?;
        }
        ShapeKind::Cylinder => {
            need("radius", s.radius.is_some())?;
            need("half_height", s.half_height.is_some())?;
            c.size(g("radius"), s.radius.unwrap_or_default())?;
            c.size(g("half_height"), s.half_height.unwrap_or_default())?;
        }
        ShapeKind::ConvexMesh | ShapeKind::TriangleMesh => {
            need("file", s.file.is_some())?;
            let scale = s.scale.unwrap_or(1.0);
            c.range(g("scale"), scale, (1e-9, 1e9), "")?;
            let path = base.join(s.file.as_deref().unwrap_or_default());
            let mut mesh = load_mesh(&path)?;
            for v in &mut mesh.vertices {
                *v = v.map(|x| x * scale);
            }
            let convex = s.kind == ShapeKind::ConvexMesh;
            check_geometry(&mesh, convex).map_err(|message| SceneError::Mesh {
                path,
                line: 0,
                message,
            })?;
            return Ok(Some(mesh));
        }
    }
    Ok(None)
}

/// The geometry of every shape, per body in file order (meshes as loaded by [`check_bodies`]).
pub(crate) fn shapes(
    c: &Checker,
    file: &SceneFile,
    meshes: Vec<Vec<Option<Mesh>>>,
) -> Result<Vec<Vec<SharedShape>>, SceneError> {
    let mut shapes = Vec::new();
    for (i, (body, body_meshes)) in file.bodies.iter().zip(meshes).enumerate() {
        let mut list = Vec::new();
        for (j, (spec, mesh)) in body.shapes.iter().zip(body_meshes).enumerate() {
            let geometry = shape(spec, mesh).ok_or_else(|| {
                c.invalid(
                    format!("body[{i}].shape[{j}].file"),
                    spec.file.clone().unwrap_or_default(),
                    "a mesh with a non-degenerate hull and valid triangles",
                )
            })?;
            list.push(geometry);
        }
        shapes.push(list);
    }
    Ok(shapes)
}

/// `dt` in [[`MIN_DT`], [`MAX_DT`]], `duration` >= `dt`, and `duration / dt` within the
/// scene's step cap (`max_steps`).
fn check_time(c: &Checker, file: &SceneFile) -> Result<(), SceneError> {
    c.range("dt", file.dt, (MIN_DT, MAX_DT), "s")?;
    if !(file.duration.is_finite() && file.duration >= file.dt) {
        let expected = format!("finite and >= `dt` = {} s", Shortest(file.dt));
        return Err(c.invalid("duration", file.duration, &expected));
    }
    if file.max_steps == 0 {
        return Err(c.invalid("max_steps", 0u64, ">= 1"));
    }
    let steps = (file.duration / file.dt).round();
    if steps > file.max_steps as f64 {
        return Err(SceneError::TooManySteps {
            origin: c.origin.to_string(),
            duration: file.duration,
            dt: file.dt,
            steps,
            max_steps: file.max_steps,
        });
    }
    Ok(())
}
