//! [`StepConverter`]: a sink's [`StepFrame`] to the messages of a step ([`StepRecord`]),
//! converted by one function for the MCAP recorder and the ROS 2 publisher alike.

use softgrip_law::ContactPatch;

use crate::msgs::geometry_msgs::{Point, Vector3, Wrench};
use crate::msgs::sensor_msgs::Image;
use crate::msgs::softgrip_msgs::SoftContactMsg;
use crate::msgs::std_msgs::Header;
use crate::sink::{ContactSample, SceneInfo, StepFrame, TactileSample, WrenchSample};
use crate::step::{BodyPose, FingertipState, StepRecord};

/// Name of the world frame (the `/tf` root) in softgrip's recordings.
pub const WORLD_FRAME: &str = "world";

/// Where a fingertip sits on its body, to place its `/tf` frame and marker.
#[derive(Debug, Clone)]
struct TipMount {
    name: String,
    body: String,
    offset: [f64; 3],
    radius: f64,
}

/// Turns [`StepFrame`]s into the messages of a step ([`StepRecord`]): what the MCAP recorder
/// writes and the ROS 2 publisher sends.
#[derive(Debug, Clone, Default)]
pub struct StepConverter {
    tips: Vec<TipMount>,
}

impl StepConverter {
    /// The converter of a scene (it needs where each fingertip is mounted).
    pub fn new(info: &SceneInfo) -> Self {
        let tips = info
            .fingertips
            .iter()
            .map(|t| TipMount {
                name: t.name.clone(),
                body: t.body.clone(),
                offset: t.offset,
                radius: t.radius,
            })
            .collect();
        Self { tips }
    }

    /// Fills `step` from `frame`, reusing its allocations (the world frame is
    /// [`WORLD_FRAME`]).
    pub fn convert(&self, frame: &StepFrame, step: &mut StepRecord) {
        step.time_ns = (frame.time * 1e9).round() as u64;
        if step.world_frame != WORLD_FRAME {
            step.world_frame = WORLD_FRAME.to_owned();
        }
        step.bodies.truncate(frame.bodies.len());
        for (i, b) in frame.bodies.iter().enumerate() {
            match step.bodies.get_mut(i) {
                Some(p) => {
                    p.name.clone_from(&b.name);
                    p.position = b.translation;
                    p.orientation = b.rotation;
                }
                None => step.bodies.push(BodyPose {
                    name: b.name.clone(),
                    position: b.translation,
                    orientation: b.rotation,
                }),
            }
        }
        step.fingertips.truncate(frame.wrenches.len());
        for (i, w) in frame.wrenches.iter().enumerate() {
            let state = self.fingertip_state(i, w, frame);
            match step.fingertips.get_mut(i) {
                Some(t) => {
                    t.name.clone_from(&w.fingertip);
                    t.position = state.position;
                    t.orientation = state.orientation;
                    t.radius = state.radius;
                    t.wrench = state.wrench;
                }
                None => step.fingertips.push(FingertipState {
                    name: w.fingertip.clone(),
                    ..state
                }),
            }
        }
        step.contacts.clear();
        step.contacts
            .extend(frame.contacts.iter().map(soft_contact_msg));
        step.tactile.clear();
        step.tactile.extend(
            frame
                .tactile
                .iter()
                .map(|s| (s.fingertip.clone(), tactile_image(s, step.time_ns))),
        );
    }

    /// The `i`-th fingertip's pose (from its body's and its mount), radius and wrench (its
    /// name is left empty: the caller reuses its own string).
    fn fingertip_state(&self, i: usize, w: &WrenchSample, frame: &StepFrame) -> FingertipState {
        let mount = self
            .tips
            .iter()
            .find(|t| t.name == w.fingertip)
            .or_else(|| self.tips.get(i));
        let (position, orientation, radius) = match mount {
            Some(m) => {
                let body = frame.bodies.iter().find(|b| b.name == m.body);
                let (p, q) = body.map_or(([0.0; 3], [0.0, 0.0, 0.0, 1.0]), |b| {
                    (b.translation, b.rotation)
                });
                let o = rotate(q, m.offset);
                ([p[0] + o[0], p[1] + o[1], p[2] + o[2]], q, m.radius)
            }
            None => ([0.0; 3], [0.0, 0.0, 0.0, 1.0], 0.0),
        };
        FingertipState {
            name: String::new(),
            position,
            orientation,
            radius,
            wrench: Wrench {
                force: Vector3::from_array(w.force),
                torque: Vector3::from_array(w.torque),
            },
        }
    }
}

/// A contact of the frame as a `softgrip_msgs/SoftContact` (its header is set per step, by
/// [`StepRecord::take_contact_array`]).
pub fn soft_contact_msg(c: &ContactSample) -> SoftContactMsg {
    let k = &c.contact;
    let patch = k.patch.unwrap_or(ContactPatch::EMPTY);
    let mut m = SoftContactMsg {
        fingertip: c.fingertip.clone(),
        other: c.other.clone(),
        point: Point::from_array(k.point),
        normal: Vector3::from_array(k.normal),
        compression: k.delta,
        ratio_x: k.x,
        normal_force: k.normal_force,
        friction_force: Vector3::from_array(k.friction_force),
        torsional_moment: k.torsional_moment,
        contact_radius: patch.radius,
        mean_pressure: patch.mean_pressure,
        peak_pressure: patch.peak_pressure,
        stiffness: k.stiffness,
        sliding: k.sliding,
        peak_normal_force: k.peak_normal_force,
        max_compression: k.max_delta,
        contact_duration: k.contact_duration,
        validity_exceeded: k.validity_exceeded,
        ..SoftContactMsg::default()
    };
    m.set_level(k.level);
    m
}

/// A fingertip's tactile image as a `sensor_msgs/Image` (`32FC1`, pressure \[Pa\],
/// little-endian, row-major, `step = 4 columns`) stamped `time_ns` \[ns\], in the
/// fingertip's frame.
pub fn tactile_image(s: &TactileSample, time_ns: u64) -> Image {
    // The fingertip's tf frame. The `frames` work gives it its own name when it collides with
    // its body's (`fingertip_frame`); until then it is the fingertip's name, as on `/tf`.
    let frame = &s.fingertip;
    Image::tactile(Header::new(time_ns, frame), s.rows, s.columns, &s.pressure)
}

/// `q v q*` for a unit quaternion `[x, y, z, w]`.
fn rotate(q: [f64; 4], v: [f64; 3]) -> [f64; 3] {
    let [x, y, z, w] = q;
    // t = 2 (q_v x v); v' = v + w t + q_v x t
    let t = [
        2.0 * (y * v[2] - z * v[1]),
        2.0 * (z * v[0] - x * v[2]),
        2.0 * (x * v[1] - y * v[0]),
    ];
    [
        v[0] + w * t[0] + (y * t[2] - z * t[1]),
        v[1] + w * t[1] + (z * t[0] - x * t[2]),
        v[2] + w * t[2] + (x * t[1] - y * t[0]),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rotate_by_quarter_turn_about_z() {
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let v = rotate([0.0, 0.0, h, h], [1.0, 0.0, 0.0]);
        assert!((v[0]).abs() < 1e-12 && (v[1] - 1.0).abs() < 1e-12);
    }
}
