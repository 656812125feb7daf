//! The frames of a recording (REP 103): a fixed root [`WORLD_FRAME`] that is z-up whatever axis
//! the scene uses internally ([`UpAxis`]), a frame per body (child of the world, on `/tf`) and a
//! frame per fingertip (child of the body that carries it, its constant offset on
//! `/tf_static`), each name unique ([`fingertip_frame`]).

use std::collections::HashSet;

use crate::sink::SceneInfo;

/// Name of the world frame (the `/tf` root, z-up) in softgrip's recordings.
pub const WORLD_FRAME: &str = "world";

/// Suffix that [`fingertip_frame`] appends to a fingertip's name that is already a body's.
pub const FINGERTIP_FRAME_SUFFIX: &str = "_tip";

/// The scene's up axis (the direction opposite to gravity on a table). Scene files are y-up
/// (`gravity = [0, -9.81, 0]`, a table's normal `[0, 1, 0]`); what is recorded and published is
/// z-up, as ROS (REP 103) and Foxglove expect, by one fixed rotation at the recording
/// boundary ([`UpAxis::to_world`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum UpAxis {
    /// The scene is y-up: recorded as world `(x, y, z) = (x_s, -z_s, y_s)`, a quarter turn about
    /// +x (scene +y becomes world +z, scene +z becomes world -y; x stays).
    #[default]
    Y,
    /// The scene is already z-up: recorded as it is.
    Z,
}

impl UpAxis {
    /// The rotation from the scene's axes to the world's, unit quaternion `[x, y, z, w]`.
    ///
    /// ```
    /// use softgrip_record::frames::{UpAxis, rotate};
    /// let up = rotate(UpAxis::Y.to_world(), [0.0, 1.0, 0.0]);
    /// assert!((up[2] - 1.0).abs() < 1e-15 && up[0].abs() < 1e-15 && up[1].abs() < 1e-15);
    /// ```
    pub fn to_world(self) -> [f64; 4] {
        match self {
            UpAxis::Y => {
                let h = std::f64::consts::FRAC_1_SQRT_2;
                [h, 0.0, 0.0, h]
            }
            UpAxis::Z => [0.0, 0.0, 0.0, 1.0],
        }
    }

    /// `v` (scene axes) in world axes. Exact for [`UpAxis::Y`]: a permutation with a sign.
    pub fn vector(self, v: [f64; 3]) -> [f64; 3] {
        match self {
            UpAxis::Y => [v[0], -v[2], v[1]],
            UpAxis::Z => v,
        }
    }

    /// An orientation `q` (scene axes) in world axes: `r q` with `r` = [`to_world`](Self::to_world).
    pub fn rotation(self, q: [f64; 4]) -> [f64; 4] {
        match self {
            UpAxis::Y => mul(self.to_world(), q),
            UpAxis::Z => q,
        }
    }
}

/// The tf frame of the fingertip `fingertip` of `scene`: its name, unless that is already a
/// body's name (or the world's), then the name with [`FINGERTIP_FRAME_SUFFIX`] appended until
/// it is no body's and no other fingertip's. Every frame of a recording is unique. The
/// tactile image's `frame_id` and the wrench's use it too.
///
/// ```
/// use softgrip_law::Level;
/// use softgrip_record::{FingertipInfo, FingertipLaw, SceneInfo, frames::fingertip_frame};
/// let tip = |name: &str, body: &str| FingertipInfo {
///     name: name.into(), body: body.into(), offset: [0.0; 3], radius: 0.01,
///     law: FingertipLaw {
///         name: name.into(), level: Level::auto(), youngs_modulus: 5.9e5,
///         poisson_ratio: 0.49, radius: 0.01, friction: 0.8, restitution: 0.5,
///         backing: Default::default(),
///         curve: None,
///         custom_name: None,
///     },
///     facing: None,
/// };
/// let scene = SceneInfo {
///     bodies: vec!["sphere".into(), "jaw".into()],
///     fingertips: vec![tip("sphere", "sphere"), tip("thumb", "jaw")],
///     ..Default::default()
/// };
/// assert_eq!(fingertip_frame(&scene, "sphere"), "sphere_tip");
/// assert_eq!(fingertip_frame(&scene, "thumb"), "thumb");
/// ```
pub fn fingertip_frame(scene: &SceneInfo, fingertip: &str) -> String {
    FrameNames::new(scene).fingertip_frame(fingertip)
}

/// The names a scene's frames are made from, indexed once: [`fingertip_frame`] of every
/// fingertip of a scene in time linear in its size (each call of [`fingertip_frame`] reads
/// the whole scene).
pub(crate) struct FrameNames<'a> {
    bodies: HashSet<&'a str>,
    fingertips: HashSet<&'a str>,
}

impl<'a> FrameNames<'a> {
    /// The names of `scene`.
    pub(crate) fn new(scene: &'a SceneInfo) -> Self {
        Self {
            bodies: scene.bodies.iter().map(String::as_str).collect(),
            fingertips: scene.fingertips.iter().map(|t| t.name.as_str()).collect(),
        }
    }

    /// [`fingertip_frame`] of the fingertip named `fingertip`.
    pub(crate) fn fingertip_frame(&self, fingertip: &str) -> String {
        // `name` is another fingertip's (this one's own name is not taken by itself).
        let taken = |name: &str| {
            name == WORLD_FRAME
                || self.bodies.contains(name)
                || (name != fingertip && self.fingertips.contains(name))
        };
        let mut frame = fingertip.to_owned();
        while taken(&frame) {
            frame.push_str(FINGERTIP_FRAME_SUFFIX);
        }
        frame
    }
}

/// `q v q*` for a unit quaternion `q = [x, y, z, w]`.
pub fn rotate(q: [f64; 4], v: [f64; 3]) -> [f64; 3] {
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

/// `q* v q`: `v` (world axes) in the axes of a frame of orientation `q = [x, y, z, w]`.
pub fn rotate_inverse(q: [f64; 4], v: [f64; 3]) -> [f64; 3] {
    rotate([-q[0], -q[1], -q[2], q[3]], v)
}

/// The Hamilton product `a b` of quaternions `[x, y, z, w]` (`b` first, then `a`).
pub fn mul(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    let [ax, ay, az, aw] = a;
    let [bx, by, bz, bw] = b;
    [
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
        aw * bw - ax * bx - ay * by - az * bz,
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

    #[test]
    fn y_up_vector_is_the_quaternion_rotation() {
        for v in [
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [0.3, -2.0, 5.0],
        ] {
            let a = UpAxis::Y.vector(v);
            let b = rotate(UpAxis::Y.to_world(), v);
            for i in 0..3 {
                assert!((a[i] - b[i]).abs() < 1e-14, "{v:?}: {a:?} vs {b:?}");
            }
        }
        // Gravity of a y-up scene points down in the world.
        assert_eq!(UpAxis::Y.vector([0.0, -9.81, 0.0]), [0.0, -0.0, -9.81]);
    }

    #[test]
    fn rotation_composes_with_the_body_orientation() {
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let q = [0.0, h, 0.0, h]; // a body turned 90 deg about scene +y
        let v = [1.0, 0.0, 0.0];
        let direct = UpAxis::Y.vector(rotate(q, v));
        let composed = rotate(UpAxis::Y.rotation(q), v);
        for i in 0..3 {
            assert!((direct[i] - composed[i]).abs() < 1e-15);
        }
        let back = rotate_inverse(q, rotate(q, [0.2, 0.4, -0.7]));
        assert!((back[0] - 0.2).abs() < 1e-15 && (back[2] + 0.7).abs() < 1e-15);
    }
}
