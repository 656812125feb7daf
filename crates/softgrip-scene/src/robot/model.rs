//! [`Robot`]: a checked `[[robot]]`: its URDF loaded into rapier objects (`rapier3d-urdf`), its
//! links and joints by name, each joint's limits, motor and mimic.

use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};

use rapier3d_urdf::urdf_rs::JointType;
use rapier3d_urdf::{UrdfLoaderOptions, UrdfRobot};
use softgrip_rapier::rapier3d::prelude::{Pose, RigidBodyBuilder, Rotation};

use crate::error::SceneError;
use crate::robot::spec::{BaseKind, JointModel, RobotSpec};
use crate::robot::urdf::{CheckedUrdf, converter, has_mass, read_urdf};
use crate::validate::Checker;
use crate::vector::vector;

/// Most moving joints of a `joints = "multibody"` robot. rapier's multibody solve is dense
/// (cubic in its joints): a chain of n revolute joints took 0.16, 1.0, 6.7 and 148 s for 5
/// steps at n = 100, 200, 400, 1000 (debug build; `examples/urdf_sweep.rs`), and 4000 did not
/// finish in 300 s. Hands and arms have tens.
pub const MAX_MULTIBODY_JOINTS: usize = 256;

/// How a joint moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum JointKind {
    /// About its axis, within limits \[rad\].
    Revolute,
    /// About its axis, without limits \[rad\].
    Continuous,
    /// Along its axis, within limits \[m\].
    Prismatic,
    /// Not at all.
    Fixed,
}

impl JointKind {
    /// Whether the joint has a coordinate (not fixed).
    pub fn moves(self) -> bool {
        self != JointKind::Fixed
    }
}

/// A joint that follows another: `q = multiplier * q_other + offset` (URDF `<mimic>`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mimic {
    /// Index of the joint it follows, in [`Robot::joints`].
    pub joint: usize,
    /// Multiplier [-] (URDF default 1).
    pub multiplier: f64,
    /// Offset \[m or rad\] (URDF default 0).
    pub offset: f64,
}

/// A joint of a robot (after `rapier3d-urdf` merged the empty links away).
#[derive(Debug, Clone, PartialEq)]
pub struct RobotJoint {
    /// The URDF joint's name (of the moving joint when fixed joints were merged into it).
    pub name: String,
    /// Its type.
    pub kind: JointKind,
    /// Index of the parent link in [`Robot::links`].
    pub parent: usize,
    /// Index of the child link in [`Robot::links`].
    pub child: usize,
    /// Lower and upper limit \[m or rad\] (infinite for a continuous joint).
    pub limits: [f64; 2],
    /// Largest motor force or torque \[N or N m\] (URDF `effort`; `None` where the URDF gives 0).
    pub effort: Option<f64>,
    /// Largest speed \[m/s or rad/s\] a controller commands (URDF `velocity`; `None` for 0).
    pub velocity: Option<f64>,
    /// The joint it follows, if it is a mimic joint.
    pub mimic: Option<Mimic>,
    /// Start position \[m or rad\].
    pub initial: f64,
    /// Motor stiffness (force-based) \[N/m or N m/rad\].
    pub stiffness: f64,
    /// Motor damping \[N s/m or N m s/rad\].
    pub damping: f64,
}

/// A link of a robot.
#[derive(Debug, Clone, PartialEq)]
pub struct RobotLink {
    /// The URDF link's name.
    pub name: String,
    /// Index of the joint whose child it is (`None` for the root).
    pub parent_joint: Option<usize>,
}

/// A checked `[[robot]]`.
#[derive(Debug, Clone)]
pub struct Robot {
    name: String,
    urdf: CheckedUrdf,
    rapier: UrdfRobot,
    links: Vec<RobotLink>,
    joints: Vec<RobotJoint>,
    base: BaseKind,
    model: JointModel,
    self_contacts: bool,
}

impl Robot {
    /// Reads and checks `spec` (`field` = `robot[i]`), paths relative to `base`.
    pub(crate) fn from_spec(
        c: &Checker,
        field: &str,
        spec: &RobotSpec,
        base: &Path,
    ) -> Result<Self, SceneError> {
        let f = |s: &str| format!("{field}.{s}");
        c.coords(f("position"), spec.position)?;
        c.finite3(f("rotation"), spec.rotation)?;
        let angle = spec.rotation.iter().map(|x| x * x).sum::<f64>().sqrt();
        if angle > crate::limits::MAX_ROTATION_ANGLE {
            return Err(c.invalid(f("rotation"), spec.rotation, "an angle <= 100 rad"));
        }
        for (name, v) in [("stiffness", spec.stiffness), ("damping", spec.damping)] {
            c.range(f(name), v, (0.0, 1e12), "")?;
        }
        let packages: BTreeMap<String, PathBuf> = (spec.package_paths.iter())
            .map(|(k, v)| (k.clone(), base.join(v)))
            .collect();
        let path = base.join(&spec.urdf);
        let urdf = read_urdf(&path, &packages, spec.mesh).map_err(|message| SceneError::Urdf {
            origin: c.origin.to_string(),
            field: f("urdf"),
            path: path.clone(),
            message,
        })?;
        let mut options = UrdfLoaderOptions {
            mesh_converter: Some(converter(spec.mesh)),
            rigid_body_blueprint: RigidBodyBuilder::dynamic().can_sleep(false),
            ..UrdfLoaderOptions::default()
        };
        options.shift = Pose::from_parts(
            vector(spec.position),
            Rotation::from_scaled_axis(vector(spec.rotation)),
        );
        let rapier = UrdfRobot::from_robot(&urdf.robot, options, Path::new(""));
        let (links, joints) = links_and_joints(c, field, spec, &urdf, &rapier)?;
        let dofs = joints.iter().filter(|j| j.kind.moves()).count();
        if spec.joints == JointModel::Multibody && dofs > MAX_MULTIBODY_JOINTS {
            return Err(c.invalid(
                f("joints"),
                format!("\"multibody\" with {dofs} moving joints"),
                &format!(
                    "at most {MAX_MULTIBODY_JOINTS} moving joints for \"multibody\" (rapier's \
                     multibody solve is dense: its cost grows as the cube of the joints), or \
                     joints = \"impulse\""
                ),
            ));
        }
        let root = links.iter().position(|l| l.parent_joint.is_none());
        if spec.base == BaseKind::Dynamic
            && let Some(root) = root
            && !has_mass(&urdf.robot.links[rapier.links[root].urdf_link_index])
        {
            return Err(SceneError::Urdf {
                origin: c.origin.to_string(),
                field: f("base"),
                path: urdf.path.clone(),
                message: format!(
                    "base = \"dynamic\" needs a root link with a mass, but link `{}` has none \
                     (mass 0, no collision shape; rapier would hold it still): give it an \
                     <inertial> with a mass > 0 kg or a <collision>, or use base = \"kinematic\" \
                     or \"fixed\"",
                    links[root].name
                ),
            });
        }
        Ok(Self {
            name: spec.name.clone(),
            urdf,
            rapier,
            links,
            joints,
            base: spec.base,
            model: spec.joints,
            self_contacts: spec.self_contacts,
        })
    }

    /// Its name (`[[robot]] name`).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The URDF file's text, as read (`/robot_description`).
    pub fn urdf_text(&self) -> &str {
        &self.urdf.text
    }

    /// The URDF file.
    pub fn urdf_path(&self) -> &Path {
        &self.urdf.path
    }

    /// The rapier objects (bodies, colliders, joints) before insertion.
    pub fn rapier(&self) -> &UrdfRobot {
        &self.rapier
    }

    /// Its links, in `rapier3d-urdf`'s order (the URDF's, empty links merged away).
    pub fn links(&self) -> &[RobotLink] {
        &self.links
    }

    /// Its joints, in `rapier3d-urdf`'s order.
    pub fn joints(&self) -> &[RobotJoint] {
        &self.joints
    }

    /// Index of the link named `name`.
    pub fn link_index(&self, name: &str) -> Option<usize> {
        self.links.iter().position(|l| l.name == name)
    }

    /// Index of the joint named `name`.
    pub fn joint_index(&self, name: &str) -> Option<usize> {
        self.joints.iter().position(|j| j.name == name)
    }

    /// The tf frame of link `i`: `<robot>/<link>`.
    pub fn frame(&self, link: usize) -> String {
        format!("{}/{}", self.name, self.links[link].name)
    }

    /// How its root moves.
    pub fn base(&self) -> BaseKind {
        self.base
    }

    /// How its joints are simulated.
    pub fn joint_model(&self) -> JointModel {
        self.model
    }

    /// Whether its links collide with each other ([`RobotSpec::self_contacts`]).
    pub fn self_contacts(&self) -> bool {
        self.self_contacts
    }

    /// The URDF mass of link `i` \[kg\] (0 where it gives none: its shapes then get
    /// [`FALLBACK_DENSITY`](crate::robot::build::FALLBACK_DENSITY)).
    pub fn link_mass(&self, i: usize) -> f64 {
        let k = self.rapier.links[i].urdf_link_index;
        self.urdf.robot.links[k].inertial.mass.value
    }

    /// Index of the root link (the one that is no joint's child).
    pub fn root(&self) -> usize {
        self.links
            .iter()
            .position(|l| l.parent_joint.is_none())
            .unwrap_or(0)
    }
}

/// The moving joints' names, `a, b` (`none` without), for errors naming what is valid.
pub(crate) fn moving_names(joints: &[RobotJoint]) -> String {
    let names: Vec<&str> = (joints.iter())
        .filter(|j| j.kind.moves())
        .map(|j| j.name.as_str())
        .collect();
    if names.is_empty() {
        "none".to_owned()
    } else {
        names.join(", ")
    }
}

/// The links and joints of `rapier` with names, limits, gains, mimics and start positions;
/// `initial` and `gains` keys must name moving joints.
fn links_and_joints(
    c: &Checker,
    field: &str,
    spec: &RobotSpec,
    urdf: &CheckedUrdf,
    rapier: &UrdfRobot,
) -> Result<(Vec<RobotLink>, Vec<RobotJoint>), SceneError> {
    let src = &urdf.robot;
    let mut links: Vec<RobotLink> = (rapier.links.iter())
        .map(|l| RobotLink {
            name: src.links[l.urdf_link_index].name.clone(),
            parent_joint: None,
        })
        .collect();
    let mut by_name = HashMap::new();
    let mut joints = Vec::new();
    for (i, j) in rapier.joints.iter().enumerate() {
        let s = &src.joints[j.source_urdf_joint_index()];
        let kind = match s.joint_type {
            JointType::Revolute => JointKind::Revolute,
            JointType::Continuous => JointKind::Continuous,
            JointType::Prismatic => JointKind::Prismatic,
            _ => JointKind::Fixed,
        };
        links[j.link2].parent_joint = Some(i);
        by_name.insert(s.name.clone(), i);
        let [k, d] = spec
            .gains
            .get(&s.name)
            .copied()
            .unwrap_or([spec.stiffness, spec.damping]);
        let limits = match kind {
            JointKind::Revolute | JointKind::Prismatic => [s.limit.lower, s.limit.upper],
            JointKind::Continuous => [f64::NEG_INFINITY, f64::INFINITY],
            JointKind::Fixed => [0.0, 0.0],
        };
        let some = |v: f64| (v > 0.0).then_some(v);
        joints.push(RobotJoint {
            name: s.name.clone(),
            kind,
            parent: j.link1,
            child: j.link2,
            limits,
            effort: some(s.limit.effort),
            velocity: some(s.limit.velocity),
            mimic: None,
            initial: 0.0_f64.clamp(limits[0], limits[1]),
            stiffness: k,
            damping: d,
        });
    }
    let f = |s: &str| format!("{field}.{s}");
    for (name, &q) in &spec.initial {
        let Some(&i) = by_name.get(name).filter(|&&i| joints[i].kind.moves()) else {
            return Err(c.name(
                f(&format!("initial.{name}")),
                format!(
                    "no moving joint of the robot has this name (its moving joints: {})",
                    moving_names(&joints)
                ),
            ));
        };
        let [lo, hi] = joints[i].limits;
        if !(q.is_finite() && q >= lo && q <= hi && q.abs() <= crate::limits::MAX_COORDINATE) {
            let expected = format!("finite and within the joint's limits [{lo}, {hi}]");
            return Err(c.invalid(f(&format!("initial.{name}")), q, &expected));
        }
        joints[i].initial = q;
    }
    for (name, [k, d]) in &spec.gains {
        if !by_name.get(name).is_some_and(|&i| joints[i].kind.moves()) {
            return Err(c.name(
                f(&format!("gains.{name}")),
                format!(
                    "no moving joint of the robot has this name (its moving joints: {})",
                    moving_names(&joints)
                ),
            ));
        }
        c.range(f(&format!("gains.{name}[0]")), *k, (0.0, 1e12), "")?;
        c.range(f(&format!("gains.{name}[1]")), *d, (0.0, 1e12), "")?;
    }
    for (i, j) in rapier.joints.iter().enumerate() {
        let s = &src.joints[j.source_urdf_joint_index()];
        if let Some(m) = &s.mimic {
            let Some(&other) = by_name.get(&m.joint) else {
                return Err(SceneError::Urdf {
                    origin: c.origin.to_string(),
                    field: f("urdf"),
                    path: urdf.path.clone(),
                    message: format!(
                        "joint `{}` mimic: joint `{}` was merged away (it leads to an empty link)",
                        s.name, m.joint
                    ),
                });
            };
            joints[i].mimic = Some(Mimic {
                joint: other,
                multiplier: m.multiplier.unwrap_or(1.0),
                offset: m.offset.unwrap_or(0.0),
            });
        }
    }
    mimic_starts(c, field, spec, &mut joints)?;
    Ok((links, joints))
}

/// Sets each mimic joint's start to where it follows its joint (through chains of mimics). A
/// start `spec` gives a mimic joint must be that one (before session 15 it was silently
/// replaced), and a start outside the mimic's own limits is an error on its joint's start (the
/// coupling and the limit would fight from the first step).
fn mimic_starts(
    c: &Checker,
    field: &str,
    spec: &RobotSpec,
    joints: &mut [RobotJoint],
) -> Result<(), SceneError> {
    let f = |s: &str| format!("{field}.initial.{s}");
    // Chains of mimics in any order: as many passes as joints reach every chain's end.
    for _ in 0..joints.len() {
        for i in 0..joints.len() {
            if let Some(m) = joints[i].mimic {
                joints[i].initial = m.multiplier * joints[m.joint].initial + m.offset;
            }
        }
    }
    for j in joints.iter() {
        let Some(m) = j.mimic else { continue };
        let (follows, leader) = (j.initial, &joints[m.joint]);
        if let Some(&q) = spec.initial.get(&j.name)
            && (q - follows).abs() > 1e-9 * follows.abs().max(1.0)
        {
            let expected = format!(
                "{follows}: the joint mimics `{}` ({} x its start + {}); set `initial.{}` instead",
                leader.name, m.multiplier, m.offset, leader.name
            );
            return Err(c.invalid(f(&j.name), q, &expected));
        }
        let [lo, hi] = j.limits;
        if !(lo - 1e-9..=hi + 1e-9).contains(&follows) {
            let expected = format!(
                "such that joint `{}`, which mimics it ({} x its start + {} = {follows}), starts \
                 within its limits [{lo}, {hi}]",
                j.name, m.multiplier, m.offset
            );
            return Err(c.invalid(f(&leader.name), leader.initial, &expected));
        }
    }
    for j in joints.iter_mut().filter(|j| j.mimic.is_some()) {
        j.initial = j.initial.clamp(j.limits[0], j.limits[1]);
    }
    Ok(())
}
