//! A [`Robot`] inserted into a rapier world: its links, colliders and joints (multibody or
//! impulse), the root's body type, each moving joint's position motor (limits, effort),
//! start positions, and mimic joints coupled.

use rapier3d_urdf::UrdfMultibodyOptions;
use softgrip_rapier::rapier3d::prelude::{
    ColliderHandle, ImpulseJointHandle, JointAxis, LockedAxes, MotorModel, MultibodyDofCoupling,
    MultibodyJointHandle, PhysicsWorld, Pose, RigidBodyHandle, RigidBodyType,
};

use crate::robot::model::{JointKind, Robot, RobotJoint};
use crate::robot::spec::{BaseKind, JointModel};
use crate::robot::state::fk_impulse;
use softgrip_rapier::SoftWorld;

/// Density given to the collision shapes of a link whose URDF has no mass [kg/m³] (so that
/// every dynamic link has one).
pub const FALLBACK_DENSITY: f64 = 1000.0;

/// The factor on the sweeps a padded link's assembly needs at the start pose
/// ([`Robot::set_jointed_sweeps`]): the rate of rapier's sweeps moves with the pose as a finger
/// curls, and with 25 % more sweeps a rate up to `r^0.8` of the start's `r` still converges
/// (the three-finger hand's fingers need 520 at the start and 520 closed on the ball, the box
/// and the cylinder, `tests/impulse_hand.rs`; given 650).
pub const JOINTED_SWEEPS_MARGIN: f64 = 1.25;

/// The most Gauss-Seidel sweeps per solver pass [`Robot::set_jointed_sweeps`] gives an
/// impulse-jointed robot's links: rapier's step time grows with them (the three-finger hand:
/// see SCENES.md); an assembly that needs more is seen as free bodies.
pub const MAX_JOINTED_SWEEPS: usize = 4096;

/// A padded link of an impulse-jointed robot that the soft solve cannot see through its joints
/// ([`Robot::set_jointed_sweeps`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct JointedUnseen {
    /// The link (index into [`Robot::links`]).
    pub link: usize,
    /// The Gauss-Seidel sweeps per solver pass it would need, with the margin (more than
    /// [`MAX_JOINTED_SWEEPS`]); `None` where its assembly is not one the solve reads (more than
    /// 8 bodies held together by impulse joints, or rapier's sweeps over it never converge).
    pub needed: Option<usize>,
}

/// How a robot joint is held in rapier.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RobotJointHandle {
    /// A multibody joint (reduced coordinates).
    Multibody(MultibodyJointHandle),
    /// An impulse joint.
    Impulse(ImpulseJointHandle),
    /// Not in rapier (a multibody joint rapier refused, e.g. one that would close a loop).
    None,
}

/// The rapier handles of an inserted robot.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RobotHandles {
    /// Each link's body, in [`Robot::links`] order.
    pub links: Vec<RigidBodyHandle>,
    /// Each link's collision shapes (its colliders), in [`Robot::links`] order.
    pub colliders: Vec<Vec<ColliderHandle>>,
    /// Each joint, in [`Robot::joints`] order.
    pub joints: Vec<RobotJointHandle>,
}

/// The motor axis of a joint kind (the URDF loader puts every joint's axis on its local x).
pub(crate) fn motor_axis(kind: JointKind) -> JointAxis {
    match kind {
        JointKind::Prismatic => JointAxis::LinX,
        _ => JointAxis::AngX,
    }
}

impl Robot {
    /// Inserts the robot into `world` and returns its handles.
    pub fn insert(&self, world: &mut PhysicsWorld) -> RobotHandles {
        let mut rapier = self.rapier().clone();
        let root = self.root();
        for (i, link) in rapier.links.iter_mut().enumerate() {
            if i == root {
                let kind = match self.base() {
                    BaseKind::Fixed => RigidBodyType::Fixed,
                    BaseKind::Kinematic => RigidBodyType::KinematicPositionBased,
                    BaseKind::Dynamic => RigidBodyType::Dynamic,
                };
                link.body.set_body_type(kind, false);
            }
            if self.link_mass(i) == 0.0 {
                for c in &mut link.colliders {
                    c.collider.set_density(FALLBACK_DENSITY as f32);
                }
            }
        }
        // Every joint's motor and limits on the GenericJoint before insertion.
        for (j, uj) in self.joints().iter().zip(rapier.joints.iter_mut()) {
            if j.kind.moves() && !(self.joint_model() == JointModel::Multibody && j.mimic.is_some())
            {
                set_motor(&mut uj.joint, j, j.initial, 0.0);
            }
        }
        let w = world;
        let (links, colliders, joints) = match self.joint_model() {
            JointModel::Multibody => {
                let h = rapier.insert_using_multibody_joints(
                    &mut w.bodies,
                    &mut w.colliders,
                    &mut w.multibody_joints,
                    if self.self_contacts() {
                        UrdfMultibodyOptions::empty()
                    } else {
                        UrdfMultibodyOptions::DISABLE_SELF_CONTACTS
                    },
                );
                let joints = (h.joints.iter())
                    .map(|j| {
                        j.joint
                            .map_or(RobotJointHandle::None, RobotJointHandle::Multibody)
                    })
                    .collect();
                split(h.links, joints)
            }
            JointModel::Impulse => {
                let h = rapier.insert_using_impulse_joints(
                    &mut w.bodies,
                    &mut w.colliders,
                    &mut w.impulse_joints,
                );
                let joints = h
                    .joints
                    .iter()
                    .map(|j| RobotJointHandle::Impulse(j.joint))
                    .collect();
                split(h.links, joints)
            }
        };
        let handles = RobotHandles {
            links,
            colliders,
            joints,
        };
        match self.joint_model() {
            JointModel::Multibody => self.start_multibody(w, &handles),
            JointModel::Impulse => {
                self.anchor_prismatic_at_com(w, &handles);
                fk_impulse(self, w, &handles, |j| j.initial);
            }
        }
        handles
    }

    /// Moves each impulse prismatic joint's anchors (both local frames, by the same offset in
    /// the joint frame) to its child link's centre of mass, recomputed from the link's
    /// colliders and URDF inertial (call it again after attaching colliders to a link, as
    /// [`Scene::build`](crate::Scene::build) does after the fingertips; it is idempotent). The
    /// joint is the same: a prismatic joint's child only translates relative to its frame 1, and
    /// a translation commutes with the joint's motion, so positions, velocities, limits, the
    /// motor and the forward kinematics are unchanged. What changes is how rapier's
    /// Gauss-Seidel sweeps converge (`softgrip_rapier` README, What one step does, 9): with the
    /// anchor off the centre of mass (the URDF's joint origin, a finger's root) the motor's row
    /// also turns the link, and rapier solves it against the link's free inertia without
    /// orthogonalising it against the locked rows, so each sweep passes only part of the load:
    /// the shipped gripper's finger (anchor 31 mm from its centre of mass) needs about 50
    /// sweeps to converge to 1e-5 where rapier runs one per solver pass, so the soft solve saw
    /// it as a free body and its 5 N grasp peaked at 15 N. Through the centre of mass the rows
    /// decouple, one sweep converges, and the soft solve sees the finger through its joint at
    /// rapier's default iterations. Multibody joints and other joint kinds are left as they are
    /// (a revolute joint's anchor must stay on its axis).
    pub fn anchor_prismatic_at_com(&self, w: &mut PhysicsWorld, h: &RobotHandles) {
        for (j, handle) in self.joints().iter().zip(&h.joints) {
            let RobotJointHandle::Impulse(handle) = *handle else {
                continue;
            };
            if j.kind != JointKind::Prismatic {
                continue;
            }
            let Some(child) = h.links.get(j.child).and_then(|&c| w.bodies.get_mut(c)) else {
                continue;
            };
            child.recompute_mass_properties_from_colliders(&w.colliders);
            if child.mass() <= 0.0 {
                continue;
            }
            let com = child.local_center_of_mass();
            let Some(ij) = w.impulse_joints.get_mut(handle, false) else {
                continue;
            };
            let d = ij.data.local_frame2.inverse_transform_point(com);
            if !d.is_finite() {
                continue;
            }
            let shift = Pose::from_translation(d);
            ij.data.local_frame1 *= shift;
            ij.data.local_frame2 *= shift;
        }
    }

    /// Gives the links of an impulse-jointed robot the Gauss-Seidel sweeps per solver pass at
    /// which the soft solve sees its padded links (`pads`, link indices) through their joints:
    /// every link's `additional_pgs_iterations` becomes the most any padded link's assembly
    /// needs ([`SoftWorld::jointed_sweeps_needed`], the largest over the step `dt` and the
    /// substeps `dt / 2^k` down to `dt / 64`) times [`JOINTED_SWEEPS_MARGIN`], less rapier's
    /// own `num_internal_pgs_iterations` (rapier takes the largest of an island's bodies). A
    /// hinged finger needs hundreds (rapier solves a motor row against the link's free inertia
    /// about its centre of mass, off the hinge, and does not orthogonalise it against the
    /// locked rows): the shipped three-finger hand's fingers 518 at the step, 520 at its
    /// substeps, so 649 more with the margin; a prismatic jaw anchored at its centre of mass
    /// ([`Robot::anchor_prismatic_at_com`]) needs 1 and gets none. A multibody robot's links get
    /// what rapier's sweeps over its motor and coupling rows need for a padded link
    /// ([`SoftWorld::multibody_sweeps_needed`], with the same substeps and margin, at most
    /// [`MAX_JOINTED_SWEEPS`]; the soft solve always sees a multibody, so this never fails):
    /// the shipped parallel gripper's links need 16 (get 19 more than rapier's 1), the
    /// three-finger hand's 348 (434 more), and the world's `num_internal_stabilization_iterations`
    /// is raised to the same total (rapier's unbiased pass over the same rows). Robots without
    /// a pad are left as they are. Call it
    /// after the fingertips are attached and the anchors moved.
    ///
    /// # Errors
    /// [`JointedUnseen`] names the first padded link the solve cannot see through its impulse
    /// joints: its assembly needs more than [`MAX_JOINTED_SWEEPS`] with the margin, or is not
    /// one the solve reads (more than 8 bodies, or rapier's sweeps over it never converge).
    /// Nothing is set then, and a run would take the links as free bodies
    /// (`SoftCounters::jointed_free`): [`Scene::parse`](crate::Scene::parse) refuses such a
    /// scene ([`SceneError::JointedUnseen`](crate::SceneError::JointedUnseen)).
    pub fn set_jointed_sweeps(
        &self,
        world: &mut SoftWorld,
        h: &RobotHandles,
        pads: &[usize],
    ) -> Result<(), JointedUnseen> {
        if self.joint_model() == JointModel::Multibody {
            self.set_multibody_sweeps(world, h, pads);
            return Ok(());
        }
        // rapier computes a body's world (effective) mass properties at its first step; the
        // rate needs them now. Setting the locked axes updates them (only on a change, hence
        // there and back).
        let w = &mut world.physics;
        for &l in &h.links {
            if let Some(rb) = w.bodies.get_mut(l) {
                rb.recompute_mass_properties_from_colliders(&w.colliders);
                let axes = rb.locked_axes();
                rb.set_locked_axes(axes ^ LockedAxes::TRANSLATION_LOCKED_X, false);
                rb.set_locked_axes(axes, false);
            }
        }
        let dt = world.physics.integration_parameters.dt as f64;
        // The most sweeps any padded link held by impulse joints needs, at the step and its
        // substeps, and the link that needs them.
        let mut most: Option<(usize, usize)> = None;
        for &l in pads {
            let Some(&body) = h.links.get(l) else {
                continue;
            };
            let w = &world.physics;
            let jointed = w.bodies.get(body).is_some_and(|rb| rb.is_dynamic())
                && w.impulse_joints.attached_joints(body).next().is_some();
            if !jointed {
                continue;
            }
            let need = (0..=6)
                .filter_map(|k| world.jointed_sweeps_needed(body, dt / f64::from(1u32 << k)))
                .max()
                .ok_or(JointedUnseen {
                    link: l,
                    needed: None,
                })?;
            if most.is_none_or(|(n, _)| need > n) {
                most = Some((need, l));
            }
        }
        let own = world
            .physics
            .integration_parameters
            .num_internal_pgs_iterations;
        let Some((need, link)) = most.filter(|&(n, _)| n > own) else {
            return Ok(());
        };
        let need = (need as f64 * JOINTED_SWEEPS_MARGIN).ceil() as usize;
        if need > MAX_JOINTED_SWEEPS {
            return Err(JointedUnseen {
                link,
                needed: Some(need),
            });
        }
        for &l in &h.links {
            if let Some(rb) = world.physics.bodies.get_mut(l) {
                let extra = rb.additional_pgs_iterations().max(need - own);
                rb.set_additional_pgs_iterations(extra);
            }
        }
        Ok(())
    }

    /// `Robot::set_jointed_sweeps` for a multibody robot: every link's
    /// `additional_pgs_iterations` becomes the most rapier's sweeps over the multibody's motor
    /// and coupling rows need for a padded link ([`SoftWorld::multibody_sweeps_needed`], the
    /// largest over the step `dt` and the substeps `dt / 2^k` down to `dt / 64`) times
    /// [`JOINTED_SWEEPS_MARGIN`], at most [`MAX_JOINTED_SWEEPS`], less rapier's own
    /// `num_internal_pgs_iterations`. The soft solve folds the motors and couplings in as
    /// rapier's converged solve does; with fewer sweeps rapier's joints do not do what it
    /// predicts (mimic-coupled jaws at 2 sweeps were thrown 36 mm open). The shipped parallel
    /// gripper needs 16 (20 with the margin), the three-finger hand 348 (435). The world's
    /// `num_internal_stabilization_iterations` (rapier's unbiased pass, one count for every
    /// body) is raised to the same count: with rapier's 1 the coupled joints leave each
    /// substep with velocities the couplings do not allow (the xArm gripper's drive joint,
    /// mimicked by five joints, read its effort 14 % off `J^T F`; `tests/xarm.rs`).
    fn set_multibody_sweeps(&self, world: &mut SoftWorld, h: &RobotHandles, pads: &[usize]) {
        if !self.joints().iter().any(|j| j.mimic.is_some()) {
            return;
        }
        let dt = world.physics.integration_parameters.dt as f64;
        let mut most = 0;
        for &l in pads {
            let Some(&body) = h.links.get(l) else {
                continue;
            };
            for k in 0..=6 {
                if let Some(n) = world.multibody_sweeps_needed(body, dt / f64::from(1u32 << k)) {
                    most = most.max(n);
                }
            }
        }
        let own = world
            .physics
            .integration_parameters
            .num_internal_pgs_iterations;
        let need = ((most as f64 * JOINTED_SWEEPS_MARGIN).ceil() as usize).min(MAX_JOINTED_SWEEPS);
        if need <= own {
            return;
        }
        // rapier's unbiased (stabilization) pass after each substep's position update runs
        // `num_internal_stabilization_iterations` sweeps on the whole world, whatever the
        // bodies ask. At rapier's 1 it leaves the coupled joints' velocities unconverged: the
        // xArm gripper's drive joint, still in its hold, read 6.7e-4 rad/s and its mimics up
        // to 1.1e-3 rad/s (its motor's damping took 14 % off its effort), and the next substep
        // starts from them. A third or a tenth of the sweeps is worse, not between (measured:
        // 0.95 % and 28 % off); the same count as the biased pass converges both.
        let ip = &mut world.physics.integration_parameters;
        ip.num_internal_stabilization_iterations =
            ip.num_internal_stabilization_iterations.max(need);
        for &l in &h.links {
            if let Some(rb) = world.physics.bodies.get_mut(l) {
                let extra = rb.additional_pgs_iterations().max(need - own);
                rb.set_additional_pgs_iterations(extra);
            }
        }
    }

    /// Start positions and mimic couplings of a multibody robot.
    fn start_multibody(&self, w: &mut PhysicsWorld, h: &RobotHandles) {
        for (j, handle) in self.joints().iter().zip(&h.joints) {
            let RobotJointHandle::Multibody(handle) = *handle else {
                continue;
            };
            if j.kind.moves()
                && j.initial != 0.0
                && let Some((mb, link)) = w.multibody_joints.get_mut(handle)
                && let Some(l) = mb.link_mut(link)
            {
                l.joint.apply_displacement(&[j.initial as f32]);
            }
            let Some(m) = j.mimic else { continue };
            let RobotJointHandle::Multibody(other) = h.joints[m.joint] else {
                continue;
            };
            let Some(link1) = w.multibody_joints.get(other).map(|(_, l)| l) else {
                continue;
            };
            if let Some((mb, link2)) = w.multibody_joints.get_mut(handle) {
                mb.add_dof_coupling(MultibodyDofCoupling {
                    link1,
                    dof1: 0,
                    axis1: motor_axis(self.joints()[m.joint].kind) as usize,
                    link2,
                    dof2: 0,
                    axis2: motor_axis(j.kind) as usize,
                    coeff: m.multiplier as f32,
                    offset: m.offset as f32,
                });
            }
        }
        if let Some(&root) = h.links.get(self.root())
            && let Some(id) = w.multibody_joints.rigid_body_link(root).copied()
            && let Some(mb) = w.multibody_joints.get_multibody_mut(id.multibody)
        {
            mb.forward_kinematics(&w.bodies, true);
            mb.update_rigid_bodies(&mut w.bodies, true);
        }
    }
}

/// Links' bodies and colliders apart.
fn split(
    links: Vec<rapier3d_urdf::UrdfLinkHandle>,
    joints: Vec<RobotJointHandle>,
) -> (
    Vec<RigidBodyHandle>,
    Vec<Vec<ColliderHandle>>,
    Vec<RobotJointHandle>,
) {
    let bodies = links.iter().map(|l| l.body).collect();
    let colliders = (links.into_iter())
        .map(|l| l.colliders.into_iter().map(|c| c.handle).collect())
        .collect();
    (bodies, colliders, joints)
}

/// `j`'s position motor on `g` (force-based, its gains, its effort as the largest force) with
/// target `position` \[m or rad\] and `velocity`, and its limits.
pub(crate) fn set_motor(
    g: &mut softgrip_rapier::rapier3d::prelude::GenericJoint,
    j: &RobotJoint,
    position: f64,
    velocity: f64,
) {
    let axis = motor_axis(j.kind);
    g.set_motor_model(axis, MotorModel::ForceBased);
    g.set_motor(
        axis,
        position as f32,
        velocity as f32,
        j.stiffness as f32,
        j.damping as f32,
    );
    if let Some(effort) = j.effort {
        g.set_motor_max_force(axis, effort as f32);
    }
    if j.kind != JointKind::Continuous {
        g.set_limits(axis, [j.limits[0] as f32, j.limits[1] as f32]);
    }
}
