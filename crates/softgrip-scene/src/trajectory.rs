//! [`Trajectory`]: a kinematic body's scripted path, linear between waypoints.

use crate::format::BodySpec;

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

    /// Position at time `t` \[s\]; `None` for an empty trajectory.
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn holds_before_and_after_and_is_linear_between() {
        let path = Trajectory {
            waypoints: vec![(1.0, [0.0, 0.0, 0.0]), (3.0, [2.0, -4.0, 0.0])],
        };
        assert_eq!(path.position_at(0.0), Some([0.0; 3]));
        assert_eq!(path.position_at(2.0), Some([1.0, -2.0, 0.0]));
        assert_eq!(path.position_at(9.0), Some([2.0, -4.0, 0.0]));
        let empty = Trajectory { waypoints: vec![] };
        assert_eq!(empty.position_at(1.0), None);
    }
}
