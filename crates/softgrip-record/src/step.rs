//! [`StepRecord`]: what the simulation hands the recorder after a step, and the standard
//! messages built from it (`/tf`, `/tf_static`, the fingertip wrenches, `/clock`).

use std::sync::Arc;

use crate::msgs::builtin_interfaces::Time;
use crate::msgs::geometry_msgs::{Quaternion, Transform, TransformStamped, Vector3, Wrench};
use crate::msgs::rosgraph_msgs::Clock;
use crate::msgs::sensor_msgs::{Image, JointState};
use crate::msgs::softgrip_msgs::{SoftContactArrayMsg, SoftContactMsg};
use crate::msgs::std_msgs::Header;
use crate::msgs::std_msgs::StringMsg;
use crate::msgs::tf2_msgs::TFMessage;
use crate::msgs::visualization_msgs::Marker;

/// A body's pose for `/tf` (its frame is its name, a child of the world frame, or of its parent
/// link for a robot's link; world axes are z-up).
#[derive(Debug, Clone, PartialEq)]
pub struct BodyPose {
    /// Name of the body (its tf frame).
    pub name: String,
    /// Its parent frame (a robot link's parent link); empty: the world frame. `position` and
    /// `orientation` are relative to it.
    pub parent: String,
    /// Position of the body frame's origin, world \[m\].
    pub position: [f64; 3],
    /// Orientation, unit quaternion `[x, y, z, w]`.
    pub orientation: [f64; 4],
}

/// A fingertip after a step: its pose, radius and the net contact wrench on it.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct FingertipState {
    /// Name of the fingertip (`/softgrip/<name>/wrench`, the contacts' `fingertip`).
    pub name: String,
    /// Centre of the fingertip sphere, world \[m\].
    pub position: [f64; 3],
    /// Orientation, unit quaternion `[x, y, z, w]`.
    pub orientation: [f64; 4],
    /// Radius R \[m\], > 0.
    pub radius: f64,
    /// Net contact wrench on the fingertip, torque about its centre, in the axes of `frame`
    /// (as ROS means a `WrenchStamped`; [`contact_wrench`] computes it in world axes from the
    /// contacts).
    pub wrench: Wrench,
    /// Its tf frame ([`fingertip_frame`](crate::frames::fingertip_frame)): the wrench's and
    /// its marker's `frame_id`. Empty: the world frame (then `wrench` is in world axes).
    pub frame: String,
    /// Length of its contacts' force arrows per newton \[m/N\] up to the reference force
    /// `radius / arrow_scale`, logarithmic and capped above it
    /// ([`visuals::arrow_length`](crate::visuals::arrow_length)); 0: no arrows.
    pub arrow_scale: f64,
    /// A backed fingertip's facing (flat face to pole, unit), in its body's axes (the axes of
    /// `frame`, or of `orientation` when `frame` is empty); `None`: a free fingertip.
    pub facing: Option<[f64; 3]>,
}

/// One step's worth of recordable state.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StepRecord {
    /// Simulation time at the end of the step \[ns\].
    pub time_ns: u64,
    /// Name of the world frame (the `/tf` root), e.g. `world`.
    pub world_frame: String,
    /// The soft contacts of the step (their headers are overwritten with the step's).
    pub contacts: Vec<SoftContactMsg>,
    /// The fingertips.
    pub fingertips: Vec<FingertipState>,
    /// Other bodies to publish on `/tf`.
    pub bodies: Vec<BodyPose>,
    /// `/tf_static` (each fingertip's frame on its body), on the first step a converter fills
    /// only; `None` on the others.
    pub tf_static: Option<TFMessage>,
    /// The rigid bodies' shape markers, in their body frames (stamped with the step's time by
    /// [`visuals::markers`](crate::visuals::markers)); shared by every step of a run.
    pub shapes: Arc<[Marker]>,
    /// The tactile image of each fingertip with a pad: (fingertip name, its `32FC1` image,
    /// stamped with the step's time, `frame_id` the fingertip's frame).
    pub tactile: Vec<(String, Image)>,
    /// Each robot's URDF on the first step a converter fills: (robot name, or `""` for a scene's
    /// only robot; the URDF); empty on the others.
    pub robot_descriptions: Vec<(String, StringMsg)>,
    /// `/joint_states` (scenes with robots).
    pub joint_states: Option<JointState>,
    /// `/joint_commands`: the joints' targets for the step (scenes with robots).
    pub joint_commands: Option<JointState>,
}

impl StepRecord {
    /// The step's header: its time in the world frame.
    pub fn header(&self) -> Header {
        Header::new(self.time_ns, &self.world_frame)
    }

    /// The step's contacts as one `SoftContactArrayMsg`, each stamped with the step's header;
    /// moves them out of the step (no copy: put `array.contacts` back to reuse them).
    pub fn take_contact_array(&mut self) -> SoftContactArrayMsg {
        let header = self.header();
        for c in &mut self.contacts {
            c.header.stamp = header.stamp;
            c.header.frame_id.clone_from(&header.frame_id);
        }
        SoftContactArrayMsg {
            header,
            contacts: std::mem::take(&mut self.contacts),
        }
    }

    /// `/clock`.
    pub fn clock(&self) -> Clock {
        Clock {
            clock: Time::from_nanos(self.time_ns),
        }
    }

    /// A fingertip's wrench frame: its tf frame, or the world frame if it has none.
    pub fn frame_of<'a>(&'a self, tip: &'a FingertipState) -> &'a str {
        if tip.frame.is_empty() {
            &self.world_frame
        } else {
            &tip.frame
        }
    }

    /// `/tf`: every body as a child of the world frame (a robot link: of its parent link),
    /// then every fingertip that has no frame of its own on `/tf_static` (`frame` empty) as a
    /// child of the world frame.
    pub fn tf(&self) -> TFMessage {
        let header = self.header();
        let pose_in = |parent: &str, name: &str, position: [f64; 3], orientation: [f64; 4]| {
            TransformStamped {
                header: if parent.is_empty() {
                    header.clone()
                } else {
                    Header {
                        frame_id: parent.to_owned(),
                        ..header.clone()
                    }
                },
                child_frame_id: name.to_owned(),
                transform: Transform {
                    translation: Vector3::from_array(position),
                    rotation: Quaternion::from_xyzw(orientation),
                },
            }
        };
        let tips = self
            .fingertips
            .iter()
            .filter(|t| t.frame.is_empty())
            .map(|t| pose_in("", &t.name, t.position, t.orientation));
        let bodies = self
            .bodies
            .iter()
            .map(|b| pose_in(&b.parent, &b.name, b.position, b.orientation));
        TFMessage {
            transforms: bodies.chain(tips).collect(),
        }
    }
}

/// Net wrench of `contacts` on a fingertip centred at `center` \[m\]: force
/// `Σ (F_n n + f_t)` \[N\] and torque `Σ (p − c) × (F_n n + f_t) + τ n` [N m], world axes.
///
/// ```
/// use softgrip_record::contact_wrench;
/// use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
/// use softgrip_record::msgs::geometry_msgs::{Point, Vector3};
/// let c = SoftContactMsg {
///     point: Point { x: 0.0, y: 0.0, z: -0.01 },
///     normal: Vector3 { x: 0.0, y: 0.0, z: 1.0 },
///     normal_force: 2.0,
///     friction_force: Vector3 { x: 0.5, y: 0.0, z: 0.0 },
///     ..Default::default()
/// };
/// let w = contact_wrench([0.0; 3], [&c]);
/// assert_eq!((w.force.x, w.force.z), (0.5, 2.0));
/// assert!((w.torque.y - (-0.01 * 0.5)).abs() < 1e-15); // r x f = (0,0,-0.01) x (0.5,0,2)
/// ```
pub fn contact_wrench<'a>(
    center: [f64; 3],
    contacts: impl IntoIterator<Item = &'a SoftContactMsg>,
) -> Wrench {
    let mut force = [0.0; 3];
    let mut torque = [0.0; 3];
    for c in contacts {
        let n = c.normal.to_array();
        let ft = c.friction_force.to_array();
        let f: [f64; 3] = std::array::from_fn(|i| c.normal_force * n[i] + ft[i]);
        let p = c.point.to_array();
        let r: [f64; 3] = std::array::from_fn(|i| p[i] - center[i]);
        let rxf = [
            r[1] * f[2] - r[2] * f[1],
            r[2] * f[0] - r[0] * f[2],
            r[0] * f[1] - r[1] * f[0],
        ];
        for i in 0..3 {
            force[i] += f[i];
            torque[i] += rxf[i] + c.torsional_moment * n[i];
        }
    }
    Wrench {
        force: Vector3::from_array(force),
        torque: Vector3::from_array(torque),
    }
}
