//! A controller's robot and joints, by name, checked against the scene's robots.

use crate::error::SceneError;
use crate::robot::Robot;
use crate::validate::Checker;

/// The robot named `robot` (index) and the joints named `joints` (indices): each a moving
/// joint of the robot that is not a mimic joint (a mimic joint follows its joint), named once.
pub(crate) fn resolve(
    c: &Checker,
    field: &str,
    robots: &[Robot],
    robot: &str,
    joints: &[String],
) -> Result<(usize, Vec<usize>), SceneError> {
    let r = robots
        .iter()
        .position(|r| r.name() == robot)
        .ok_or_else(|| {
            c.name(
                format!("{field}.robot"),
                format!(
                    "no robot is named `{robot}` (robots: {})",
                    robot_names(robots)
                ),
            )
        })?;
    if joints.is_empty() {
        return Err(c.name(format!("{field}.joints"), "give at least one joint"));
    }
    let mut out = Vec::with_capacity(joints.len());
    for (k, name) in joints.iter().enumerate() {
        let f = format!("{field}.joints[{k}]");
        let j = robots[r].joint_index(name).ok_or_else(|| {
            c.name(
                &f,
                format!(
                    "robot `{robot}` has no joint `{name}` (its moving joints: {})",
                    crate::robot::moving_names(robots[r].joints())
                ),
            )
        })?;
        let joint = &robots[r].joints()[j];
        if !joint.kind.moves() {
            return Err(c.name(&f, format!("joint `{name}` is fixed")));
        }
        if joint.mimic.is_some() {
            return Err(c.name(
                &f,
                format!("joint `{name}` is a mimic joint: command the joint it follows"),
            ));
        }
        if out.contains(&j) {
            return Err(c.name(&f, format!("joint `{name}` is named twice")));
        }
        out.push(j);
    }
    Ok((r, out))
}

/// `v` \[m or rad\] within joint `j`'s limits.
pub(crate) fn check_position(
    c: &Checker,
    field: &str,
    robot: &Robot,
    j: usize,
    v: f64,
) -> Result<(), SceneError> {
    let [lo, hi] = robot.joints()[j].limits;
    if v.is_finite() && v >= lo && v <= hi && v.abs() <= crate::limits::MAX_COORDINATE {
        Ok(())
    } else {
        Err(c.invalid(
            field,
            v,
            &format!(
                "finite and within joint `{}`'s limits [{lo}, {hi}]",
                robot.joints()[j].name
            ),
        ))
    }
}

/// The robots' names, `a, b` (`none` without robots), for errors naming what is valid.
pub(crate) fn robot_names(robots: &[Robot]) -> String {
    let names: Vec<&str> = robots.iter().map(|r| r.name()).collect();
    if names.is_empty() {
        "none".to_owned()
    } else {
        names.join(", ")
    }
}
