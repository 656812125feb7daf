//! Reading a robot's URDF file: bounded read, `urdf-rs`, mesh paths resolved (`package://`,
//! `file://`, relative) and every mesh loaded here first, so that a mesh that cannot be loaded
//! is an error naming its file (`rapier3d-urdf` drops such a mesh without a word), and every
//! number checked against what the engine can hold.

use std::collections::{BTreeMap, HashMap, HashSet};
use std::path::{Path, PathBuf};

use rapier3d_urdf::urdf_rs::{Geometry, JointType, Pose, Robot};
use softgrip_rapier::rapier3d::prelude::{MeshConverter, TriMeshFlags, Vector};

use crate::limits::{MAX_COORDINATE, MAX_MESH_BYTES, MAX_SCENE_BYTES, MAX_SIZE, MIN_SIZE};
use crate::read::{ReadError, read_regular, size, strip_bom};
use crate::robot::inertial::check_inertial;
use crate::robot::numbers::first_bad_number;
use crate::robot::spec::MeshShape;

/// A URDF read and checked: the robot with every collision mesh's `filename` replaced by the
/// resolved path, and the file's text (the `/robot_description` published).
#[derive(Debug, Clone)]
pub(crate) struct CheckedUrdf {
    /// The robot, meshes resolved.
    pub robot: Robot,
    /// The URDF file's text, as read.
    pub text: String,
    /// The URDF file.
    pub path: PathBuf,
}

/// What is wrong, naming where in the URDF (link or joint and the value).
pub(crate) type UrdfProblem = String;

/// The URDF converter of meshes for `mesh`.
pub(crate) fn converter(mesh: MeshShape) -> MeshConverter {
    match mesh {
        MeshShape::ConvexHull => MeshConverter::ConvexHull,
        MeshShape::Trimesh => MeshConverter::TriMeshWithFlags(TriMeshFlags::all()),
    }
}

/// Reads `path` (a regular file of at most [`MAX_SCENE_BYTES`]; a leading byte-order mark is
/// skipped), parses it and checks it; mesh files are
/// resolved with `packages` (name -> folder) and loaded once with `mesh`'s converter.
pub(crate) fn read_urdf(
    path: &Path,
    packages: &BTreeMap<String, PathBuf>,
    mesh: MeshShape,
) -> Result<CheckedUrdf, UrdfProblem> {
    // A regular file (a FIFO would block the read forever), at most the scene size limit.
    let bytes = read_regular(path, MAX_SCENE_BYTES).map_err(|e| match e {
        ReadError::TooLarge { limit } => format!("larger than the {} limit", size(limit)),
        other => other.message(),
    })?;
    let text =
        String::from_utf8(strip_bom(&bytes).to_vec()).map_err(|e| format!("not UTF-8: {e}"))?;
    check_root_element(&text)?;
    let mut robot = rapier3d_urdf::urdf_rs::read_from_string(&sanitize(&text)).map_err(|e| {
        match first_bad_number(&text) {
            Some(at) => format!("not a URDF robot: {at} ({e})"),
            None => format!("not a URDF robot: {e}"),
        }
    })?;
    check_structure(&robot)?;
    check_limits_given(&text)?;
    let dir = path.parent().unwrap_or(Path::new(""));
    for link in &mut robot.links {
        for (k, c) in link.collision.iter_mut().enumerate() {
            let at = format!("link `{}` collision[{k}]", link.name);
            check_pose(&at, &c.origin)?;
            check_geometry(&at, &mut c.geometry, dir, packages, mesh)?;
        }
        let at = format!("link `{}` inertial", link.name);
        check_pose(&at, &link.inertial.origin)?;
        check_inertial(&at, &link.inertial)?;
    }
    check_massless(&robot)?;
    Ok(CheckedUrdf {
        robot,
        text,
        path: path.to_path_buf(),
    })
}

/// An empty `<geometry></geometry>` (which some URDFs have and `urdf-rs` rejects) as a
/// zero box, which `rapier3d-urdf` skips (as its own loader does).
fn sanitize(input: &str) -> String {
    const EMPTY: &str = "<box size=\"0 0 0\"/>";
    let mut out = String::with_capacity(input.len());
    let mut rem = input;
    while let Some(open) = rem.find("<geometry") {
        out.push_str(&rem[..open]);
        let tag = &rem[open..];
        let Some(end) = tag.find('>') else {
            out.push_str(tag);
            return out;
        };
        let (head, body) = tag.split_at(end + 1);
        out.push_str(head);
        if head.ends_with("/>") {
            rem = body;
            continue;
        }
        let Some(close) = body.find("</geometry>") else {
            out.push_str(body);
            return out;
        };
        let inner = &body[..close];
        out.push_str(if inner.trim().is_empty() {
            EMPTY
        } else {
            inner
        });
        out.push_str("</geometry>");
        rem = &body[close + "</geometry>".len()..];
    }
    out.push_str(rem);
    out
}

/// Unique names, joints between existing links, one parent per link, no loop, a single
/// root, supported joint types, finite axes and limits, mimic joints that exist.
fn check_structure(robot: &Robot) -> Result<(), UrdfProblem> {
    if robot.links.is_empty() {
        return Err("has no <link>".into());
    }
    let mut links = HashSet::new();
    for l in &robot.links {
        if !links.insert(l.name.as_str()) {
            return Err(format!("link `{}` is defined twice", l.name));
        }
    }
    let mut joints = HashMap::new();
    let mut parent_of = HashMap::new();
    for (i, j) in robot.joints.iter().enumerate() {
        let at = format!("joint `{}`", j.name);
        if joints.insert(j.name.as_str(), i).is_some() {
            return Err(format!("{at} is defined twice"));
        }
        for (end, link) in [("parent", &j.parent.link), ("child", &j.child.link)] {
            if !links.contains(link.as_str()) {
                return Err(format!(
                    "{at}: {end} link `{link}` is not a <link> of the robot"
                ));
            }
        }
        if j.parent.link == j.child.link {
            return Err(format!(
                "{at}: parent and child are the same link `{}`",
                j.child.link
            ));
        }
        if let Some(other) = parent_of.insert(j.child.link.as_str(), j.name.as_str()) {
            return Err(format!(
                "{at}: link `{}` is already the child of joint `{other}` (a URDF is a tree)",
                j.child.link
            ));
        }
        check_pose(&at, &j.origin)?;
        check_joint(&at, j)?;
    }
    let roots: Vec<_> = (robot.links.iter())
        .filter(|l| !parent_of.contains_key(l.name.as_str()))
        .map(|l| l.name.as_str())
        .collect();
    if roots.len() != 1 {
        return Err(format!(
            "must have exactly one root link (a link that is no joint's child), found {}: {:?}",
            roots.len(),
            roots
        ));
    }
    for j in &robot.joints {
        if let Some(m) = &j.mimic {
            let at = format!("joint `{}` mimic", j.name);
            let Some(&k) = joints.get(m.joint.as_str()) else {
                return Err(format!(
                    "{at}: joint `{}` is not a joint of the robot",
                    m.joint
                ));
            };
            let other = &robot.joints[k];
            if other.name == j.name || !moves(&other.joint_type) || !moves(&j.joint_type) {
                return Err(format!(
                    "{at}: `{}` ({:?}) cannot be mimicked by `{}` ({:?}): both must be other, moving joints",
                    m.joint, other.joint_type, j.name, j.joint_type
                ));
            }
            for (name, v) in [("multiplier", m.multiplier), ("offset", m.offset)] {
                if v.is_some_and(|v| !(v.is_finite() && v.abs() <= MAX_COORDINATE)) {
                    return Err(format!(
                        "{at}: {name} must be finite and within ±{MAX_COORDINATE:e}, got {v:?}"
                    ));
                }
            }
        }
    }
    check_mimic_cycles(robot)
}

/// No mimic joint follows itself through a chain of mimics (`a` mimics `b` mimics `a`): such a
/// coupling has no solution rapier can hold.
fn check_mimic_cycles(robot: &Robot) -> Result<(), UrdfProblem> {
    let index: HashMap<&str, usize> = (robot.joints.iter().enumerate())
        .map(|(i, j)| (j.name.as_str(), i))
        .collect();
    // Each joint is walked once (linear in the joints): 0 unseen, 1 on the current walk, 2 done.
    let mut state = vec![0_u8; robot.joints.len()];
    for start in 0..robot.joints.len() {
        let mut walk = Vec::new();
        let mut at = Some(start);
        while let Some(k) = at.filter(|&k| state[k] != 2) {
            if state[k] == 1 {
                let from = walk.iter().position(|&w| w == k).unwrap_or(0);
                let names: Vec<_> = (walk[from..].iter().chain([&k]))
                    .map(|&w| format!("`{}`", robot.joints[w].name))
                    .collect();
                return Err(format!(
                    "joint `{}` mimic: the mimic joints form a cycle ({}): one of them must \
                     follow a joint that is not a mimic joint",
                    robot.joints[k].name,
                    names.join(" mimics ")
                ));
            }
            state[k] = 1;
            walk.push(k);
            at =
                (robot.joints[k].mimic.as_ref()).and_then(|m| index.get(m.joint.as_str()).copied());
        }
        for w in walk {
            state[w] = 2;
        }
    }
    Ok(())
}

/// Every `revolute` and `prismatic` joint has a `<limit>` (URDF requires it; `urdf-rs` would
/// read a missing one as lower = upper = 0: a joint locked at 0 without a word).
fn check_limits_given(text: &str) -> Result<(), UrdfProblem> {
    let attr = |tag: &str, key: &str| -> Option<String> {
        let k = tag.find(&format!(" {key}="))? + key.len() + 2;
        let quote = tag[k..].chars().next()?;
        let rest = &tag[k + 1..];
        Some(rest[..rest.find(quote)?].to_string())
    };
    let mut rest = text;
    while let Some(open) = rest.find("<joint") {
        rest = &rest[open + "<joint".len()..];
        let Some(end) = rest.find('>') else { break };
        let tag = &rest[..end];
        if !tag.starts_with(char::is_whitespace) {
            continue;
        }
        let kind = attr(tag, "type").unwrap_or_default();
        if kind != "revolute" && kind != "prismatic" {
            continue;
        }
        let body = if tag.ends_with('/') {
            ""
        } else {
            let b = &rest[end..];
            &b[..b.find("</joint>").unwrap_or(b.len())]
        };
        if !body.contains("<limit") {
            return Err(format!(
                "joint `{}`: a {kind} joint needs a <limit lower upper effort velocity> (URDF \
                 requires it; without one it would be locked at 0): add one, or make it \
                 `continuous`",
                attr(tag, "name").unwrap_or_default()
            ));
        }
    }
    Ok(())
}

/// The document's first element is `<robot>` (`urdf-rs` reads any root element as a robot).
fn check_root_element(text: &str) -> Result<(), UrdfProblem> {
    let mut rest = text.trim_start();
    loop {
        let skip = if rest.starts_with("<?") {
            rest.find("?>").map(|k| k + 2)
        } else if rest.starts_with("<!--") {
            rest.find("-->").map(|k| k + 3)
        } else if rest.starts_with("<!") {
            rest.find('>').map(|k| k + 1)
        } else {
            break;
        };
        let Some(k) = skip else { break };
        rest = rest[k..].trim_start();
    }
    let name: String = (rest.strip_prefix('<').unwrap_or(""))
        .chars()
        .take_while(|c| !c.is_whitespace() && *c != '>' && *c != '/')
        .collect();
    if name == "robot" {
        Ok(())
    } else {
        let got = if name.is_empty() {
            rest.chars().take(20).collect::<String>()
        } else {
            format!("<{name}>")
        };
        Err(format!(
            "not a URDF robot: the root element must be <robot>, got `{got}`"
        ))
    }
}

/// Whether link `l` has a mass: its own, or its collision shapes' (an empty `<geometry>`, read
/// as a zero box, has none).
pub(crate) fn has_mass(l: &rapier3d_urdf::urdf_rs::Link) -> bool {
    l.inertial.mass.value > 0.0
        || (l.collision.iter())
            .any(|c| !matches!(c.geometry, Geometry::Box { ref size } if size.0 == [0.0; 3]))
}

/// Every link that a moving joint moves has some mass: its own, its collision shapes' (given
/// [`FALLBACK_DENSITY`](crate::robot::build::FALLBACK_DENSITY)) or a descendant's. A massless
/// subtree on a joint has no inertia along it: rapier's solve of that joint is singular.
fn check_massless(robot: &Robot) -> Result<(), UrdfProblem> {
    let by_name: HashMap<&str, usize> = (robot.links.iter().enumerate())
        .map(|(i, l)| (l.name.as_str(), i))
        .collect();
    let mut massive: Vec<bool> = robot.links.iter().map(has_mass).collect();
    // Mass flows up from children to parents: links in breadth-first order from the root (the
    // structure check made the joints a tree), then children before parents.
    let mut children: Vec<Vec<usize>> = vec![Vec::new(); robot.links.len()];
    let mut parent = vec![None; robot.links.len()];
    for j in &robot.joints {
        if let (Some(&p), Some(&c)) = (
            by_name.get(j.parent.link.as_str()),
            by_name.get(j.child.link.as_str()),
        ) {
            children[p].push(c);
            parent[c] = Some(p);
        }
    }
    let mut order: Vec<usize> = (0..robot.links.len())
        .filter(|&l| parent[l].is_none())
        .collect();
    let mut k = 0;
    while k < order.len() {
        order.extend(children[order[k]].iter().copied());
        k += 1;
    }
    for &l in order.iter().rev() {
        if let Some(p) = parent[l] {
            massive[p] |= massive[l];
        }
    }
    for j in robot.joints.iter().filter(|j| moves(&j.joint_type)) {
        let Some(&c) = by_name.get(j.child.link.as_str()) else {
            continue;
        };
        let l = &robot.links[c];
        let kept = !(l.visual.is_empty() && l.collision.is_empty()) || l.inertial.mass.value != 0.0;
        if kept && !massive[c] {
            return Err(format!(
                "link `{}` (moved by joint `{}`): has no mass (mass {}, no collision shape) and \
                 neither has any link below it: give it an <inertial> with a mass > 0 kg or a \
                 <collision>",
                l.name, j.name, l.inertial.mass.value
            ));
        }
    }
    Ok(())
}

/// Whether a joint type moves (revolute, continuous, prismatic).
pub(crate) fn moves(t: &JointType) -> bool {
    matches!(
        t,
        JointType::Revolute | JointType::Continuous | JointType::Prismatic
    )
}

/// A joint's type, axis and limits.
fn check_joint(at: &str, j: &rapier3d_urdf::urdf_rs::Joint) -> Result<(), UrdfProblem> {
    match j.joint_type {
        JointType::Fixed => return Ok(()),
        JointType::Revolute | JointType::Continuous | JointType::Prismatic => {}
        ref t => {
            return Err(format!(
                "{at}: type {t:?} is not supported (revolute, continuous, prismatic, fixed)"
            ));
        }
    }
    let a = j.axis.xyz.0;
    let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    if !(n.is_finite() && n > 1e-12) {
        return Err(format!(
            "{at}: axis must be a finite, non-zero direction, got {a:?}"
        ));
    }
    let l = &j.limit;
    if j.joint_type != JointType::Continuous {
        let bound = if j.joint_type == JointType::Prismatic {
            MAX_COORDINATE
        } else {
            crate::limits::MAX_ROTATION_ANGLE
        };
        if !(l.lower.is_finite() && l.upper.is_finite() && l.lower <= l.upper)
            || l.lower.abs() > bound
            || l.upper.abs() > bound
        {
            return Err(format!(
                "{at}: limit lower = {}, upper = {}: must be finite, lower <= upper, within ±{bound:e}",
                l.lower, l.upper
            ));
        }
    }
    for (name, v) in [("effort", l.effort), ("velocity", l.velocity)] {
        if !(v.is_finite() && (0.0..=1e9).contains(&v)) {
            return Err(format!(
                "{at}: limit {name} must be finite and in [0, 1e9] (0: none given), got {v}"
            ));
        }
    }
    Ok(())
}

/// An origin: finite, within the coordinate range, angles within 100 rad.
fn check_pose(at: &str, p: &Pose) -> Result<(), UrdfProblem> {
    let (xyz, rpy) = (p.xyz.0, p.rpy.0);
    if !xyz
        .iter()
        .all(|c| c.is_finite() && c.abs() <= MAX_COORDINATE)
    {
        return Err(format!(
            "{at}: origin xyz must be finite and within ±{MAX_COORDINATE:e} m, got {xyz:?}"
        ));
    }
    if !rpy
        .iter()
        .all(|c| c.is_finite() && c.abs() <= crate::limits::MAX_ROTATION_ANGLE)
    {
        return Err(format!(
            "{at}: origin rpy must be finite angles within ±100 rad, got {rpy:?}"
        ));
    }
    Ok(())
}

/// A collision geometry's sizes; a mesh's path resolved (written back into `g`) and the mesh
/// loaded with the converter the robot will use.
fn check_geometry(
    at: &str,
    g: &mut Geometry,
    dir: &Path,
    packages: &BTreeMap<String, PathBuf>,
    mesh: MeshShape,
) -> Result<(), UrdfProblem> {
    let size = |name: &str, v: f64| {
        if v.is_finite() && (MIN_SIZE..=MAX_SIZE).contains(&v) {
            Ok(())
        } else {
            Err(format!(
                "{at}: {name} must be in [{MIN_SIZE:e}, {MAX_SIZE:e}] m, got {v}"
            ))
        }
    };
    match g {
        Geometry::Box { size: s } if s.0 == [0.0; 3] => Ok(()), // an empty <geometry>
        Geometry::Box { size: s } => {
            for (k, v) in s.0.iter().enumerate() {
                size(&format!("box size[{k}]"), *v)?;
            }
            Ok(())
        }
        Geometry::Cylinder { radius, length } | Geometry::Capsule { radius, length } => {
            size("radius", *radius)?;
            size("length", *length)
        }
        Geometry::Sphere { radius } => size("radius", *radius),
        Geometry::Mesh { filename, scale } => {
            let file = resolve(filename, dir, packages).map_err(|e| format!("{at}: {e}"))?;
            let s = scale.map_or([1.0; 3], |s| s.0);
            if !s
                .iter()
                .all(|c| c.is_finite() && (1e-9..=1e9).contains(&c.abs()))
            {
                return Err(format!(
                    "{at}: mesh `{filename}`: scale must be finite with |s| in [1e-9, 1e9], got {s:?}"
                ));
            }
            load_mesh(&file, s, mesh)
                .map_err(|e| format!("{at}: mesh `{filename}` ({}): {e}", file.display()))?;
            *filename = file.to_string_lossy().into_owned();
            Ok(())
        }
    }
}

/// A mesh reference as a path: `package://name/rest` in the package's folder, `file://path`
/// (absolute, or relative to the URDF's folder), an absolute path as it is, anything else
/// relative to the URDF's folder `dir`.
pub(crate) fn resolve(
    filename: &str,
    dir: &Path,
    packages: &BTreeMap<String, PathBuf>,
) -> Result<PathBuf, String> {
    if let Some(rest) = filename.strip_prefix("package://") {
        let (name, path) = rest
            .split_once('/')
            .ok_or_else(|| format!("mesh `{filename}`: expected package://<package>/<path>"))?;
        let folder = packages.get(name).ok_or_else(|| {
            let known: Vec<_> = packages.keys().map(String::as_str).collect();
            format!(
                "mesh `{filename}`: package `{name}` is not in the robot's `package_paths` (given: {known:?})"
            )
        })?;
        return Ok(folder.join(path));
    }
    let path = Path::new(filename.strip_prefix("file://").unwrap_or(filename));
    Ok(if path.is_absolute() {
        path.to_path_buf()
    } else {
        dir.join(path)
    })
}

/// Loads `file` as `rapier3d-urdf` will (the same loader and converter): an error if it cannot
/// be read, parsed or converted, is larger than the mesh limit, holds no triangle, or has a
/// vertex that is not finite.
fn load_mesh(file: &Path, scale: [f64; 3], mesh: MeshShape) -> Result<(), String> {
    let meta = std::fs::metadata(file).map_err(|e| format!("cannot read: {e}"))?;
    if !meta.is_file() {
        return Err("not a regular file".into());
    }
    if meta.len() > MAX_MESH_BYTES {
        return Err(format!(
            "larger than the {} mesh limit",
            size(MAX_MESH_BYTES)
        ));
    }
    // The loader `rapier3d_meshloader::load_from_path` uses, then its conversion of each mesh,
    // after the raw mesh is checked (a NaN vertex makes the convex hull fail unexplained).
    let scene = rapier3d_meshloader::mesh_loader::Loader::default()
        .load(file)
        .map_err(|e| format!("cannot load: {e}"))?;
    if scene.meshes.is_empty() {
        return Err("holds no mesh".into());
    }
    let s32 = Vector::new(scale[0] as f32, scale[1] as f32, scale[2] as f32);
    for (k, raw) in scene.meshes.iter().enumerate() {
        if raw.faces.is_empty() {
            return Err(format!("mesh {k}: holds no triangle"));
        }
        if let Some(v) = raw
            .vertices
            .iter()
            .position(|v| !v.iter().all(|c| c.is_finite()))
        {
            return Err(format!(
                "mesh {k}: vertex {v} is not finite: {:?}",
                raw.vertices[v]
            ));
        }
        check_extent(&raw.vertices, scale).map_err(|e| format!("mesh {k}: {e}"))?;
        rapier3d_meshloader::load_from_raw_mesh(raw, &converter(mesh), s32)
            .map_err(|e| format!("mesh {k}: cannot be converted: {e}"))?;
    }
    Ok(())
}

/// The mesh `vertices` scaled by `scale`: finite, within the coordinate range, and at least
/// [`MIN_SIZE`] and at most [`MAX_SIZE`] across (its largest extent) \[m\].
fn check_extent(vertices: &[[f32; 3]], scale: [f64; 3]) -> Result<(), String> {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for v in vertices {
        for a in 0..3 {
            let x = f64::from(v[a]) * scale[a];
            lo[a] = lo[a].min(x);
            hi[a] = hi[a].max(x);
        }
    }
    let extent = (0..3).map(|a| hi[a] - lo[a]).fold(0.0_f64, f64::max);
    let far = (0..3)
        .map(|a| lo[a].abs().max(hi[a].abs()))
        .fold(0.0_f64, f64::max);
    if !(extent.is_finite() && (MIN_SIZE..=MAX_SIZE).contains(&extent)) {
        return Err(format!(
            "scaled by {scale:?} it is {extent:.3e} m across: its extent must be in [{MIN_SIZE:e}, {MAX_SIZE:e}] m"
        ));
    }
    if far.is_nan() || far > MAX_COORDINATE {
        return Err(format!(
            "scaled by {scale:?} a vertex is {far:.3e} m from the link: must be within {MAX_COORDINATE:e} m"
        ));
    }
    Ok(())
}
