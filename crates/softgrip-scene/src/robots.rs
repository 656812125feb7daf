//! `[[robot]]` checks: unique names (among robots and bodies, no `/`), each URDF read and
//! checked into a [`Robot`].

use std::collections::HashSet;
use std::path::Path;

use crate::error::SceneError;
use crate::format::SceneFile;
use crate::robot::Robot;
use crate::validate::Checker;

/// Every robot of the file, in order.
pub(crate) fn check_robots(
    c: &Checker,
    file: &SceneFile,
    base: &Path,
) -> Result<Vec<Robot>, SceneError> {
    let bodies: HashSet<&str> = file.bodies.iter().map(|b| b.name.as_str()).collect();
    let mut names = HashSet::new();
    let mut robots = Vec::new();
    for (i, spec) in file.robots.iter().enumerate() {
        let field = format!("robot[{i}]");
        let n = spec.name.as_str();
        if n.is_empty() || n.contains('/') || bodies.contains(n) || !names.insert(n) {
            return Err(c.name(
                format!("{field}.name"),
                format!(
                    "`{n}` is empty, holds a `/`, or is used twice (bodies and robots share names)"
                ),
            ));
        }
        robots.push(Robot::from_spec(c, &field, spec, base)?);
    }
    Ok(robots)
}
