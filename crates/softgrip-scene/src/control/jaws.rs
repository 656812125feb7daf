//! The parallel-jaw gripper (`[gripper]`, the controller `parallel_jaws`): kinematic jaws,
//! any number of them, each closing along its own direction: approach -> squeeze -> settle ->
//! lift -> hold -> release, as plain logic ([`GripperState::advance`]) behind the
//! [`Controller`] interface, so the ECS and the plain runner command the jaws identically.

use std::any::Any;

use softgrip_rapier::SoftFingertip;

use crate::control::controller::{ControlEvent, Controller, GraspView, Phase};
use crate::control::io::{Carrier, ControlIo};
use crate::control::kinds::ControllerKind;
use crate::error::SceneError;
use crate::format::{BodyKind, GripperSpec, MoveSpec, SceneFile};
use crate::limits::{MAX_COORDINATE, MAX_SPEED, MAX_TIME};
use crate::validate::Checker;

/// The commanded grip.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Squeeze {
    /// Compression of each fingertip past first touch \[m\].
    Depth(f64),
    /// Grip force per fingertip \[N\], reached through the law's inverse.
    Force(f64),
}

/// A checked gripper program (from a scene's `[gripper]`).
#[derive(Debug, Clone, PartialEq)]
pub struct GripperProgram {
    /// Name.
    pub name: String,
    /// Body index of each jaw in the scene, at least one.
    pub jaws: Vec<usize>,
    /// Closing direction of each jaw (unit).
    pub axes: Vec<[f64; 3]>,
    /// Lift direction (unit).
    pub up: [f64; 3],
    /// Closing speed before touch [m/s].
    pub approach_speed: f64,
    /// The commanded grip.
    pub squeeze: Squeeze,
    /// Closing speed while squeezing [m/s].
    pub squeeze_speed: f64,
    /// Wait at the commanded depth \[s\].
    pub settle: f64,
    /// Lift move.
    pub lift: MoveSpec,
    /// Hold time \[s\].
    pub hold: f64,
    /// Opening move of each jaw.
    pub release: MoveSpec,
    /// Target compression of each jaw's fingertip \[m\] (the depth, or the law's
    /// `compression_for_force(force)` of the jaw's first fingertip).
    pub depth: Vec<f64>,
    /// The fingertips (indices into the scene's fingertips, in file order) carried by each
    /// jaw, at least one each.
    pub tips: Vec<Vec<usize>>,
}

impl GripperProgram {
    pub(crate) fn from_spec(
        c: &Checker,
        file: &SceneFile,
        tips: &[SoftFingertip],
        g: &GripperSpec,
    ) -> Result<Self, SceneError> {
        let squeeze = squeeze(c, g)?;
        if g.jaws.is_empty() {
            return Err(c.name("gripper.jaws", "give at least one jaw"));
        }
        let mut jaws: Vec<Jaw> = Vec::with_capacity(g.jaws.len());
        for (k, name) in g.jaws.iter().enumerate() {
            let j = jaw(c, file, tips, squeeze, k, name)?;
            if jaws.iter().any(|o| o.body == j.body) {
                return Err(c.name(
                    format!("gripper.jaws[{k}]"),
                    "the jaws must be different bodies",
                ));
            }
            jaws.push(j);
        }
        let axes = match (&g.axis, &g.axes) {
            (Some(a), None) if jaws.len() == 2 => {
                let a = c.direction("gripper.axis", *a)?;
                vec![a, a.map(|x| -x)]
            }
            (Some(_), None) => {
                return Err(c.name(
                    "gripper.axis",
                    format!("applies to two jaws (the second closes opposite); with {} jaws give `axes`, one per jaw", jaws.len()),
                ));
            }
            (None, Some(list)) if list.len() == jaws.len() => (list.iter().enumerate())
                .map(|(k, a)| c.direction(format!("gripper.axes[{k}]"), *a))
                .collect::<Result<_, _>>()?,
            (None, Some(list)) => {
                return Err(c.name(
                    "gripper.axes",
                    format!(
                        "give one direction per jaw: {} jaws, {} axes",
                        jaws.len(),
                        list.len()
                    ),
                ));
            }
            _ => return Err(c.name("gripper.axis", "give exactly one of `axis` and `axes`")),
        };
        let up = match g.up {
            Some(u) => c.direction("gripper.up", u)?,
            None => c.direction("gripper.up", file.gravity.map(|x| -x))?,
        };
        let speed = |field: &str, v: f64| {
            c.positive(field, v, "m/s")?;
            c.range(field, v, (0.0, MAX_SPEED), "m/s")
        };
        speed("gripper.approach_speed", g.approach_speed)?;
        speed("gripper.squeeze.speed", g.squeeze.speed)?;
        speed("gripper.lift.speed", g.lift.speed)?;
        speed("gripper.release.speed", g.release.speed)?;
        c.range(
            "gripper.squeeze.settle",
            g.squeeze.settle,
            (0.0, MAX_TIME),
            "s",
        )?;
        c.range("gripper.hold", g.hold, (0.0, MAX_TIME), "s")?;
        let distance = (0.0, MAX_COORDINATE);
        c.range("gripper.lift.distance", g.lift.distance, distance, "m")?;
        c.range(
            "gripper.release.distance",
            g.release.distance,
            distance,
            "m",
        )?;
        Ok(Self {
            name: g.name.clone(),
            jaws: jaws.iter().map(|j| j.body).collect(),
            axes,
            up,
            approach_speed: g.approach_speed,
            squeeze,
            squeeze_speed: g.squeeze.speed,
            settle: g.squeeze.settle,
            lift: g.lift,
            hold: g.hold,
            release: g.release,
            depth: jaws.iter().map(|j| j.depth).collect(),
            tips: jaws.into_iter().map(|j| j.tips).collect(),
        })
    }
}

/// The commanded grip: exactly one of `depth` and `force`.
fn squeeze(c: &Checker, g: &GripperSpec) -> Result<Squeeze, SceneError> {
    match (g.squeeze.depth, g.squeeze.force) {
        (Some(d), None) => {
            c.positive("gripper.squeeze.depth", d, "m")?;
            Ok(Squeeze::Depth(d))
        }
        (None, Some(f)) => {
            c.positive("gripper.squeeze.force", f, "N")?;
            Ok(Squeeze::Force(f))
        }
        _ => Err(c.name("gripper.squeeze", "give exactly one of `depth` and `force`")),
    }
}

/// One checked jaw of the program.
struct Jaw {
    /// Body index.
    body: usize,
    /// Target compression of its fingertip [m].
    depth: f64,
    /// Its fingertips' indices.
    tips: Vec<usize>,
}

/// Jaw `k`, the body named `name`: kinematic, without a trajectory, carrying a fingertip
/// (whose law gives the depth of a force-controlled squeeze).
fn jaw(
    c: &Checker,
    file: &SceneFile,
    tips: &[SoftFingertip],
    squeeze: Squeeze,
    k: usize,
    name: &str,
) -> Result<Jaw, SceneError> {
    let field = format!("gripper.jaws[{k}]");
    let body = (file.bodies.iter())
        .position(|b| b.name == name)
        .ok_or_else(|| c.name(&field, format!("no body is named `{name}`")))?;
    let b = &file.bodies[body];
    if b.kind != BodyKind::Kinematic || !b.trajectory.is_empty() {
        return Err(c.name(
            &field,
            format!("`{name}` must be kinematic, without a trajectory"),
        ));
    }
    let jaw_tips: Vec<usize> = (file.fingertips.iter().enumerate())
        .filter(|(_, t)| t.body.as_deref() == Some(name))
        .map(|(j, _)| j)
        .collect();
    let &tip = jaw_tips
        .first()
        .ok_or_else(|| c.name(&field, format!("`{name}` carries no fingertip")))?;
    let depth = match squeeze {
        // Like the force's reachability: a depth past the law's validity is an error (a
        // 1.1 R squeeze gave 16 kN on a 32 g box).
        Squeeze::Depth(d) => {
            tips[tip].law().try_response(d).map_err(|e| {
                c.invalid(
                    "gripper.squeeze.depth",
                    d,
                    &format!("within the law's validity for `{}`: {e}", tips[tip].name()),
                )
            })?;
            d
        }
        Squeeze::Force(f) => tips[tip].law().compression_for_force(f).map_err(|e| {
            c.invalid(
                "gripper.squeeze.force",
                f,
                &format!("reachable by `{}`: {e}", tips[tip].name()),
            )
        })?,
    };
    Ok(Jaw {
        body,
        depth,
        tips: jaw_tips,
    })
}

/// One jaw's commanded motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JawState {
    /// Commanded position \[m\] at the end of the coming step.
    pub position: [f64; 3],
    /// Position where the fingertip's compression is zero (found at first touch) \[m\].
    pub touch: Option<[f64; 3]>,
    /// The commanded depth was reached.
    pub reached: bool,
}

/// What the controller did in one step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GripperEvent {
    /// Every jaw reached the commanded depth.
    GripReached,
}

/// The controller's state.
#[derive(Debug, Clone, PartialEq)]
pub struct GripperState {
    /// Current phase.
    pub phase: Phase,
    /// The jaws.
    pub jaws: Vec<JawState>,
    /// Time spent in the current phase (settle, hold) \[s\] or distance moved (lift, release) \[m\].
    pub progress: f64,
}

/// Largest compression \[m\] of each jaw's fingertips among `contacts`, given as (fingertip
/// key, compression `delta` \[m\]) in readout order; `tips[k]` are jaw k's fingertip keys (rapier
/// handles, entities, scene indices). `None` for a jaw without contact.
pub fn jaw_compressions<K: PartialEq>(
    tips: &[Vec<K>],
    contacts: impl IntoIterator<Item = (K, f64)>,
) -> Vec<Option<f64>> {
    let mut delta = vec![None; tips.len()];
    for (tip, d) in contacts {
        for k in 0..tips.len() {
            if tips[k].contains(&tip) {
                delta[k] = Some(delta[k].map_or(d, |m: f64| m.max(d)));
            }
        }
    }
    delta
}

fn axpy(a: f64, x: [f64; 3], y: [f64; 3]) -> [f64; 3] {
    [y[0] + a * x[0], y[1] + a * x[1], y[2] + a * x[2]]
}

impl GripperState {
    /// The state at the start: jaws at their initial positions.
    pub fn new(jaw_positions: impl IntoIterator<Item = [f64; 3]>) -> Self {
        Self {
            phase: Phase::Squeeze,
            jaws: (jaw_positions.into_iter())
                .map(|position| JawState {
                    position,
                    touch: None,
                    reached: false,
                })
                .collect(),
            progress: 0.0,
        }
    }

    /// Advances the command by one step `dt`, given each jaw's largest fingertip compression
    /// after the last step (`None` without contact). Updates the jaws' commanded positions.
    pub fn advance(
        &mut self,
        p: &GripperProgram,
        dt: f64,
        delta: &[Option<f64>],
    ) -> Option<GripperEvent> {
        let dirs = &p.axes;
        match self.phase {
            Phase::Squeeze => {
                for (k, jaw) in self.jaws.iter_mut().enumerate() {
                    let dir = dirs[k];
                    if jaw.touch.is_none() {
                        match delta.get(k).copied().flatten() {
                            // Back off by the compression already there: the touch point.
                            Some(d) if d > 0.0 => jaw.touch = Some(axpy(-d, dir, jaw.position)),
                            _ => jaw.position = axpy(p.approach_speed * dt, dir, jaw.position),
                        }
                    }
                    if let Some(touch) = jaw.touch {
                        let target = axpy(p.depth[k], dir, touch);
                        let left: f64 =
                            (0..3).map(|i| (target[i] - jaw.position[i]) * dir[i]).sum();
                        if left <= p.squeeze_speed * dt {
                            jaw.position = target;
                            jaw.reached = true;
                        } else {
                            jaw.position = axpy(p.squeeze_speed * dt, dir, jaw.position);
                        }
                    }
                }
                if self.jaws.iter().all(|j| j.reached) {
                    self.phase = Phase::Settle;
                    self.progress = 0.0;
                    return Some(GripperEvent::GripReached);
                }
            }
            Phase::Settle | Phase::Hold => {
                self.progress += dt;
                let wait = if self.phase == Phase::Settle {
                    p.settle
                } else {
                    p.hold
                };
                if self.progress >= wait - 1e-9 * dt {
                    self.phase = if self.phase == Phase::Settle {
                        Phase::Lift
                    } else {
                        Phase::Release
                    };
                    self.progress = 0.0;
                }
            }
            Phase::Lift | Phase::Release => {
                let lift = self.phase == Phase::Lift;
                let mv = if lift { p.lift } else { p.release };
                let s = (mv.speed * dt).min(mv.distance - self.progress).max(0.0);
                for (k, jaw) in self.jaws.iter_mut().enumerate() {
                    let dir = if lift { p.up } else { dirs[k].map(|x| -x) };
                    jaw.position = axpy(s, dir, jaw.position);
                }
                self.progress += s;
                if self.progress >= mv.distance {
                    self.phase = if lift { Phase::Hold } else { Phase::Done };
                    self.progress = 0.0;
                }
            }
            Phase::Done => {}
        }
        None
    }
}

/// The parallel-jaw gripper as a [`Controller`]: its program and state.
#[derive(Debug, Clone)]
pub struct ParallelJaws {
    /// The program.
    pub program: GripperProgram,
    /// The state.
    pub state: GripperState,
}

impl ParallelJaws {
    /// The controller of `program`, jaws at `positions` \[m\] (one per jaw).
    pub fn new(program: GripperProgram, positions: Vec<[f64; 3]>) -> Self {
        Self {
            program,
            state: GripperState::new(positions),
        }
    }
}

impl Controller for ParallelJaws {
    fn name(&self) -> &str {
        &self.program.name
    }

    fn kind(&self) -> ControllerKind {
        ControllerKind::ParallelJaws
    }

    fn update(&mut self, io: &mut ControlIo<'_>) -> Option<ControlEvent> {
        let delta: Vec<Option<f64>> = self
            .program
            .tips
            .iter()
            .map(|t| io.compression(t))
            .collect();
        let event = self.state.advance(&self.program, io.dt, &delta);
        for (jaw, state) in self.program.jaws.iter().zip(&self.state.jaws) {
            io.set_translation(Carrier::Body(*jaw), state.position);
        }
        event.map(|GripperEvent::GripReached| ControlEvent::GripReached {
            depth: self.program.depth.clone(),
        })
    }

    fn phase(&self) -> Option<Phase> {
        Some(self.state.phase)
    }

    fn grasp(&self) -> Option<GraspView> {
        Some(GraspView {
            up: self.program.up,
            lift_distance: self.program.lift.distance,
            fingers: self.program.tips.clone(),
            hand: self
                .program
                .jaws
                .iter()
                .map(|&j| Carrier::Body(j))
                .collect(),
            depth: self.program.depth.iter().map(|&d| Some(d)).collect(),
            hold_ends_by: None,
        })
    }

    fn as_any_mut(&mut self) -> &mut dyn Any {
        self
    }

    fn boxed_clone(&self) -> Box<dyn Controller> {
        Box::new(self.clone())
    }
}
