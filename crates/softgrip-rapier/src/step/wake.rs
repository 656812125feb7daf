//! The wake before the solve: the soft contacts' sides that rapier cannot wake (crate README,
//! Sleeping), and the held fingertips of the bodies woken (`detect`).

use rapier3d::prelude::RigidBodyHandle;

use super::Step;
use crate::bodies;
use crate::boundary::{raw, to_f64};
use crate::contacts::Scratch;
use crate::detect::{self, Scene};

impl Step<'_> {
    /// Wakes (or keeps awake) the dynamic bodies of the found contacts whose other side is not
    /// fixed or asleep (`bodies::wake_touched`), before any of them enters the body table (a
    /// sleeping body is immobile there). Repeated until nothing more wakes: a woken body wakes
    /// what sleeps on it in turn, as rapier wakes a whole island. A woken body's fingertips
    /// that the detection held (`detect`) are detected now, so that they enter the solve with
    /// every contact they have (a woken ball without its ground contact fell through it).
    pub(super) fn wake_touched(&mut self, s: &mut Scratch) {
        let dt = self.physics.integration_parameters.dt as f64;
        let gravity = to_f64(self.physics.gravity);
        let mut redetected = false;
        loop {
            let mut woken = std::mem::take(&mut s.woken);
            woken.clear();
            for g in &self.soft.geoms {
                let Some(tip) = self.soft.tips.get(&g.tip) else {
                    continue;
                };
                let r = tip.fingertip.radius();
                let log = self.soft.rest.log().map(|w| &mut w.wakes);
                bodies::wake_touched(&mut self.physics.bodies, g, r, gravity, dt, &mut woken, log);
            }
            self.soft.counters.woken += woken.len() as u64;
            // The woken bodies' held fingertips: their contacts join the list, and the next
            // pass wakes through them.
            redetected |= self.detect_woken(&woken, s);
            let done = woken.is_empty();
            s.woken = woken;
            if done {
                break;
            }
        }
        if redetected {
            self.soft.geoms.sort_by_key(|g| (raw(g.tip), raw(g.other)));
        }
    }

    /// Detects the held fingertips of the `woken` bodies (`detect::detect_woken`); returns
    /// whether there was any.
    fn detect_woken(&mut self, woken: &[RigidBodyHandle], s: &mut Scratch) -> bool {
        if s.detected.all {
            return false;
        }
        let dt = self.physics.integration_parameters.dt as f64;
        let soft = &mut *self.soft;
        let scene = Scene {
            bodies: &self.physics.bodies,
            colliders: &self.physics.colliders,
            narrow_phase: &self.physics.narrow_phase,
            broad_phase: &self.physics.broad_phase,
            islands: &self.physics.islands,
            tip_order: &soft.tip_order,
            gravity: self.physics.gravity.length(),
            max_radius: soft.max_radius,
            impulse_joints: &self.physics.impulse_joints,
            multibody_joints: &self.physics.multibody_joints,
            motor_push: (&s.motor_push.by_link, 1.0),
            excluded: self.excluded,
        };
        let mut any = false;
        for &body in woken {
            let Some(rb) = scene.bodies.get(body) else {
                continue;
            };
            for &ch in rb.colliders() {
                any |= detect::detect_woken(
                    &scene,
                    &soft.tips,
                    ch,
                    dt,
                    &mut soft.geoms,
                    &mut s.candidates,
                    &mut s.detected,
                    &mut soft.counters,
                );
            }
        }
        any
    }
}
