//! `type = "trajectory"`: joint position targets over time ([`JointTrajectory`]).

use std::any::Any;

use crate::control::controller::{ControlEvent, Controller};
use crate::control::group::{check_position, resolve};
use crate::control::io::ControlIo;
use crate::control::kinds::ControllerKind;
use crate::control::spec::TrajectorySpec;
use crate::error::SceneError;
use crate::limits::MAX_TIME;
use crate::robot::Robot;
use crate::validate::Checker;

/// Joint position targets at times, linear in between; the velocity target is the segment's
/// slope (0 before the first point and after the last).
#[derive(Debug, Clone, PartialEq)]
pub struct JointTrajectory {
    /// Name.
    pub name: String,
    /// The robot's index.
    pub robot: usize,
    /// The joints' indices.
    pub joints: Vec<usize>,
    /// `(t [s], positions [m or rad])`, `t` increasing.
    pub points: Vec<(f64, Vec<f64>)>,
}

impl JointTrajectory {
    /// Checks `spec` (`field` = `controller[i]`): robot and joints exist, times increase,
    /// positions within limits, no segment faster than a joint's URDF velocity limit.
    pub(crate) fn from_spec(
        c: &Checker,
        field: &str,
        robots: &[Robot],
        spec: &TrajectorySpec,
    ) -> Result<Self, SceneError> {
        let (robot, joints) = resolve(c, field, robots, &spec.robot, &spec.joints)?;
        if spec.points.is_empty() {
            return Err(c.name(format!("{field}.points"), "give at least one point"));
        }
        let mut points: Vec<(f64, Vec<f64>)> = Vec::new();
        for (k, p) in spec.points.iter().enumerate() {
            let f = |s: &str| format!("{field}.points[{k}].{s}");
            let last = points.last().map_or(-1.0, |l| l.0);
            if !(p.t.is_finite() && p.t >= 0.0 && p.t > last && p.t <= MAX_TIME) {
                let expected = format!("finite, in [0, {MAX_TIME:e}] s and increasing");
                return Err(c.invalid(f("t"), p.t, &expected));
            }
            if p.positions.len() != joints.len() {
                return Err(c.name(
                    f("positions"),
                    format!(
                        "give one position per joint: {} joints, {} positions",
                        joints.len(),
                        p.positions.len()
                    ),
                ));
            }
            for (n, (&j, &q)) in joints.iter().zip(&p.positions).enumerate() {
                check_position(c, &f(&format!("positions[{n}]")), &robots[robot], j, q)?;
                if let (Some(prev), Some(vmax)) =
                    (points.last(), robots[robot].joints()[j].velocity)
                {
                    let speed = (q - prev.1[n]).abs() / (p.t - prev.0);
                    if speed > vmax * (1.0 + 1e-9) {
                        return Err(c.invalid(
                            f(&format!("positions[{n}]")),
                            q,
                            &format!(
                                "reachable from the point before within joint `{}`'s velocity limit {vmax} (needs {speed:.6e})",
                                robots[robot].joints()[j].name
                            ),
                        ));
                    }
                }
            }
            points.push((p.t, p.positions.clone()));
        }
        Ok(Self {
            name: spec.name.clone(),
            robot,
            joints,
            points,
        })
    }

    /// Each joint's (position, velocity) target at time `t` \[s\].
    pub fn target_at(&self, t: f64) -> Vec<(f64, f64)> {
        let n = self.joints.len();
        let (first, last) = (&self.points[0], &self.points[self.points.len() - 1]);
        if t <= first.0 {
            return first.1.iter().map(|&q| (q, 0.0)).collect();
        }
        if t >= last.0 {
            return last.1.iter().map(|&q| (q, 0.0)).collect();
        }
        let k = self.points.iter().position(|p| p.0 > t).unwrap_or(1);
        let ((t0, q0), (t1, q1)) = (&self.points[k - 1], &self.points[k]);
        let s = (t - t0) / (t1 - t0);
        (0..n)
            .map(|i| (q0[i] + s * (q1[i] - q0[i]), (q1[i] - q0[i]) / (t1 - t0)))
            .collect()
    }
}

impl Controller for JointTrajectory {
    fn name(&self) -> &str {
        &self.name
    }

    fn kind(&self) -> ControllerKind {
        ControllerKind::Trajectory
    }

    fn update(&mut self, io: &mut ControlIo<'_>) -> Option<ControlEvent> {
        for (&j, (q, v)) in self.joints.iter().zip(self.target_at(io.time)) {
            io.set_joint(self.robot, j, q, v);
        }
        None
    }

    fn as_any_mut(&mut self) -> &mut dyn Any {
        self
    }

    fn boxed_clone(&self) -> Box<dyn Controller> {
        Box::new(self.clone())
    }
}
