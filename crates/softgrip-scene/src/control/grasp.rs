//! `type = "grasp"`: the grasp primitive for a group of a robot's joints ([`Grasp`]): close at
//! a speed until each finger presses a force (or until a closed position), settle, lift the
//! robot's base, hold, open; through the settle, lift and hold a finger that presses less than
//! the force closes again.

use std::any::Any;

use crate::control::controller::{ControlEvent, Controller, GraspView, Phase};
use crate::control::group::{check_position, resolve};
use crate::control::io::{Carrier, ControlIo};
use crate::control::kinds::ControllerKind;
use crate::control::spec::{GraspSpec, LiftSpec};
use crate::error::SceneError;
use crate::limits::{MAX_ACCELERATION, MAX_COORDINATE, MAX_SPEED, MAX_TIME};
use crate::robot::{BaseKind, Robot};
use crate::validate::Checker;

/// A checked grasp primitive and its state.
#[derive(Debug, Clone, PartialEq)]
pub struct Grasp {
    /// Name.
    pub name: String,
    /// The robot's index.
    pub robot: usize,
    /// The group's joints (indices into the robot's joints).
    pub joints: Vec<usize>,
    /// Each joint's closed position \[m or rad\].
    pub closed: Vec<f64>,
    /// Each joint's position after the release \[m or rad\].
    pub open: Vec<f64>,
    /// Target speed \[m/s or rad/s\].
    pub speed: f64,
    /// Force each finger stops at \[N\], if force-controlled; after the squeeze a finger
    /// pressing less closes again (see `keep_force`).
    pub force: Option<f64>,
    /// Time before closing starts \[s\].
    pub start: f64,
    /// Wait after the grip \[s\].
    pub settle: f64,
    /// Lift of the base.
    pub lift: LiftSpec,
    /// Lift direction (unit).
    pub up: [f64; 3],
    /// Hold \[s\].
    pub hold: f64,
    /// The fingertips (scene indices) moved by each joint: on the links it moves, and on those
    /// its mimic joints move.
    pub fingers: Vec<Vec<usize>>,
    /// The robot's root link (what the lift moves).
    pub base_link: usize,
    /// The state.
    pub state: GraspState,
}

/// A grasp's state.
#[derive(Debug, Clone, PartialEq)]
pub struct GraspState {
    /// Phase.
    pub phase: Phase,
    /// Each joint's target \[m or rad\] (its start position at first).
    pub targets: Vec<f64>,
    /// Each joint has stopped closing.
    pub stopped: Vec<bool>,
    /// Time in the phase \[s\] (settle, hold) or distance moved \[m\] (lift).
    pub progress: f64,
    /// The base's position \[m\] (the lift's), once the lift has started.
    pub base: Option<[f64; 3]>,
    /// The lift's speed over the last step \[m/s\].
    pub lift_speed: f64,
}

impl Grasp {
    /// Checks `spec` (`field` = `controller[i]`); `carriers` are the fingertips' carriers and
    /// `gravity` the scene's.
    pub(crate) fn from_spec(
        c: &Checker,
        field: &str,
        robots: &[Robot],
        carriers: &[Carrier],
        gravity: [f64; 3],
        spec: &GraspSpec,
    ) -> Result<Self, SceneError> {
        let f = |s: &str| format!("{field}.{s}");
        let (r, joints) = resolve(c, field, robots, &spec.robot, &spec.joints)?;
        let robot = &robots[r];
        let per_joint = |name: &str, v: &[f64]| -> Result<(), SceneError> {
            if v.len() == joints.len() {
                return Ok(());
            }
            Err(c.name(
                f(name),
                format!(
                    "give one value per joint: {} joints, {} values",
                    joints.len(),
                    v.len()
                ),
            ))
        };
        per_joint("closed", &spec.closed)?;
        let open = spec
            .open
            .clone()
            .unwrap_or_else(|| joints.iter().map(|&j| robot.joints()[j].initial).collect());
        per_joint("open", &open)?;
        for (k, &j) in joints.iter().enumerate() {
            check_position(c, &f(&format!("closed[{k}]")), robot, j, spec.closed[k])?;
            check_position(c, &f(&format!("open[{k}]")), robot, j, open[k])?;
        }
        c.positive(f("speed"), spec.speed, "m/s or rad/s")?;
        c.range(f("speed"), spec.speed, (0.0, MAX_SPEED), "m/s or rad/s")?;
        for &j in &joints {
            if let Some(vmax) = robot.joints()[j].velocity
                && spec.speed > vmax
            {
                let expected = format!(
                    "within joint `{}`'s URDF velocity limit {vmax}",
                    robot.joints()[j].name
                );
                return Err(c.invalid(f("speed"), spec.speed, &expected));
            }
        }
        if let Some(force) = spec.force {
            c.positive(f("force"), force, "N")?;
        }
        c.range(f("start"), spec.start, (0.0, MAX_TIME), "s")?;
        c.range(f("settle"), spec.settle, (0.0, MAX_TIME), "s")?;
        c.range(f("hold"), spec.hold, (0.0, MAX_TIME), "s")?;
        c.range(
            f("lift.distance"),
            spec.lift.distance,
            (0.0, MAX_COORDINATE),
            "m",
        )?;
        c.positive(f("lift.speed"), spec.lift.speed, "m/s")?;
        c.range(f("lift.speed"), spec.lift.speed, (0.0, MAX_SPEED), "m/s")?;
        if let Some(a) = spec.lift.acceleration {
            c.positive(f("lift.acceleration"), a, "m/s^2")?;
            c.range(f("lift.acceleration"), a, (0.0, MAX_ACCELERATION), "m/s^2")?;
        }
        if spec.lift.distance > 0.0 && robot.base() != BaseKind::Kinematic {
            return Err(c.name(
                f("lift"),
                format!(
                    "lifting moves the base of robot `{}`: give it `base = \"kinematic\"`",
                    spec.robot
                ),
            ));
        }
        let up = match spec.up {
            Some(u) => c.direction(f("up"), u)?,
            None => c.direction(f("up"), gravity.map(|x| -x))?,
        };
        let fingers = joints
            .iter()
            .map(|&j| finger(robot, r, j, carriers))
            .collect();
        let targets = joints.iter().map(|&j| robot.joints()[j].initial).collect();
        Ok(Self {
            name: spec.name.clone(),
            robot: r,
            closed: spec.closed.clone(),
            open,
            speed: spec.speed,
            force: spec.force,
            start: spec.start,
            settle: spec.settle,
            lift: spec.lift,
            up,
            hold: spec.hold,
            fingers,
            base_link: robot.root(),
            state: GraspState {
                phase: Phase::Squeeze,
                stopped: vec![false; joints.len()],
                targets,
                progress: 0.0,
                base: None,
                lift_speed: 0.0,
            },
            joints,
        })
    }

    /// Moves each unstopped target toward `goal` by `speed dt`; true when every target is
    /// there.
    fn move_targets(&mut self, goal: &[f64], dt: f64) -> bool {
        let step = self.speed * dt;
        let mut all = true;
        for (k, t) in self.state.targets.iter_mut().enumerate() {
            if self.state.stopped[k] && self.state.phase == Phase::Squeeze {
                continue;
            }
            let d = goal[k] - *t;
            if d.abs() <= step {
                *t = goal[k];
            } else {
                *t += step * d.signum();
                all = false;
            }
        }
        all
    }

    /// The velocity target of joint `k` while moving toward `goal`.
    fn velocity(&self, k: usize, goal: &[f64]) -> f64 {
        let d = goal[k] - self.state.targets[k];
        if d == 0.0 || (self.state.phase == Phase::Squeeze && self.state.stopped[k]) {
            0.0
        } else {
            self.speed * d.signum()
        }
    }

    /// The squeeze: each joint closes until its finger presses `force` or it reaches
    /// `closed`.
    fn squeeze(&mut self, io: &ControlIo<'_>) -> Option<ControlEvent> {
        for k in 0..self.joints.len() {
            if self.state.stopped[k] {
                continue;
            }
            let tips = &self.fingers[k];
            let pressed = self
                .force
                .is_some_and(|f| !tips.is_empty() && tips.iter().all(|&t| io.normal_force(t) >= f));
            if pressed || self.state.targets[k] == self.closed[k] {
                self.state.stopped[k] = true;
            }
        }
        if self.state.stopped.iter().all(|&s| s) {
            self.state.phase = Phase::Settle;
            self.state.progress = 0.0;
            let forces = (self.fingers.iter())
                .map(|tips| {
                    tips.iter()
                        .map(|&t| io.normal_force(t))
                        .fold(f64::INFINITY, f64::min)
                })
                .map(|f| if f.is_finite() { f } else { 0.0 })
                .collect();
            return Some(ControlEvent::GripReached { depth: forces });
        }
        let closed = self.closed.clone();
        self.move_targets(&closed, io.dt);
        None
    }

    /// After the squeeze (settle, lift, hold): each joint that stopped at `force` and whose
    /// finger now presses less (the least of its pads' normal forces `f`, e.g. when the
    /// object, pushed while the finger closed, springs back and unloads it) closes again,
    /// its target moved toward `closed` by `speed dt (force - f) / force` (at most `speed dt`,
    /// never past `closed`). It never opens: a finger pressing `force` or more keeps its
    /// target, so the grasp holds at least `force` where the joint can reach it.
    fn keep_force(&mut self, io: &ControlIo<'_>) {
        let Some(force) = self.force else { return };
        for k in 0..self.joints.len() {
            let tips = &self.fingers[k];
            if !self.state.stopped[k] || tips.is_empty() {
                continue;
            }
            let f = tips
                .iter()
                .map(|&t| io.normal_force(t))
                .fold(f64::INFINITY, f64::min);
            if f >= force || f.is_nan() {
                continue;
            }
            let step = self.speed * io.dt * ((force - f) / force).min(1.0);
            let t = &mut self.state.targets[k];
            let d = self.closed[k] - *t;
            *t = if d.abs() <= step {
                self.closed[k]
            } else {
                *t + step * d.signum()
            };
        }
    }

    /// The lift's advance over the coming step \[m\]: at `lift.speed`, or with
    /// `lift.acceleration` a trapezoid: the speed grows by `a dt` a step up to `lift.speed` and
    /// never exceeds `sqrt(2 a d)`, `d` the distance left, so it reaches 0 at the top.
    fn lift_step(&mut self, dt: f64) -> f64 {
        let left = (self.lift.distance - self.state.progress).max(0.0);
        let v = match self.lift.acceleration {
            None => self.lift.speed,
            Some(a) => (self.state.lift_speed + a * dt)
                .min(self.lift.speed)
                .min((2.0 * a * left).sqrt()),
        };
        let s = (v * dt).min(left);
        self.state.lift_speed = if dt > 0.0 { s / dt } else { 0.0 };
        s
    }

    /// The latest time its hold ends \[s\]: closing starts after `start`; each joint closes
    /// its whole stroke at `speed` (a force never reached), then the settle, the lift (at
    /// `lift.speed`, plus `lift.speed / lift.acceleration` for its two ramps), the hold.
    fn hold_ends_by(&self) -> f64 {
        let stroke = (self.closed.iter().zip(&self.state.targets))
            .map(|(c, t)| (c - t).abs())
            .fold(0.0, f64::max);
        let lift = self.lift.distance / self.lift.speed
            + self.lift.acceleration.map_or(0.0, |a| self.lift.speed / a);
        self.start + stroke / self.speed + self.settle + lift + self.hold
    }

    /// The robot's root link (the base the lift moves).
    fn root(&self) -> Carrier {
        Carrier::Link {
            robot: self.robot,
            link: self.base_link,
        }
    }
}

/// The fingertips moved by joint `j` of robot `r`: on its child's subtree and on the subtrees
/// of the joints that mimic it.
fn finger(robot: &Robot, r: usize, j: usize, carriers: &[Carrier]) -> Vec<usize> {
    let joints = robot.joints();
    let mut links = vec![false; robot.links().len()];
    let mut starts = vec![joints[j].child];
    starts.extend(
        (joints.iter())
            .filter(|o| o.mimic.is_some_and(|m| m.joint == j))
            .map(|o| o.child),
    );
    for s in starts {
        links[s] = true;
    }
    // Joints in any order: repeat until no link is added.
    let mut grew = true;
    while grew {
        grew = false;
        for o in joints {
            if links[o.parent] && !links[o.child] {
                links[o.child] = true;
                grew = true;
            }
        }
    }
    (carriers.iter().enumerate())
        .filter(|(_, c)| matches!(c, Carrier::Link { robot, link } if *robot == r && links[*link]))
        .map(|(i, _)| i)
        .collect()
}

impl Controller for Grasp {
    fn name(&self) -> &str {
        &self.name
    }

    fn kind(&self) -> ControllerKind {
        ControllerKind::Grasp
    }

    fn update(&mut self, io: &mut ControlIo<'_>) -> Option<ControlEvent> {
        let mut event = None;
        let root = self.root();
        match self.state.phase {
            Phase::Squeeze if io.time > self.start => event = self.squeeze(io),
            Phase::Squeeze => {}
            Phase::Settle | Phase::Hold => {
                self.keep_force(io);
                self.state.progress += io.dt;
                let (wait, next) = if self.state.phase == Phase::Settle {
                    (self.settle, Phase::Lift)
                } else {
                    (self.hold, Phase::Release)
                };
                if self.state.progress >= wait - 1e-9 * io.dt {
                    self.state.phase = next;
                    self.state.progress = 0.0;
                }
            }
            Phase::Lift => {
                self.keep_force(io);
                let base = *self
                    .state
                    .base
                    .get_or_insert_with(|| io.position(root).unwrap_or_default());
                let s = self.lift_step(io.dt);
                self.state.progress += s;
                let p = [0, 1, 2].map(|i| base[i] + self.state.progress * self.up[i]);
                io.set_translation(root, p);
                if self.state.progress >= self.lift.distance {
                    self.state.phase = Phase::Hold;
                    self.state.progress = 0.0;
                }
            }
            Phase::Release => {
                let open = self.open.clone();
                if self.move_targets(&open, io.dt) {
                    self.state.phase = Phase::Done;
                }
            }
            Phase::Done => {}
        }
        let goal = if matches!(self.state.phase, Phase::Release | Phase::Done) {
            &self.open
        } else {
            &self.closed
        };
        for k in 0..self.joints.len() {
            let v = if matches!(self.state.phase, Phase::Squeeze | Phase::Release) {
                self.velocity(k, goal)
            } else {
                0.0
            };
            io.set_joint(self.robot, self.joints[k], self.state.targets[k], v);
        }
        event
    }

    fn phase(&self) -> Option<Phase> {
        Some(self.state.phase)
    }

    fn grasp(&self) -> Option<GraspView> {
        let hand = vec![self.root()];
        Some(GraspView {
            up: self.up,
            lift_distance: self.lift.distance,
            fingers: self.fingers.clone(),
            hand,
            depth: vec![None; self.fingers.len()],
            hold_ends_by: Some(self.hold_ends_by()),
        })
    }

    fn as_any_mut(&mut self) -> &mut dyn Any {
        self
    }

    fn boxed_clone(&self) -> Box<dyn Controller> {
        Box::new(self.clone())
    }
}
