//! The first impact of a [`BallDrop`]: the plugin's, measured step by step
//! ([`FirstImpact`]), and a 1-DOF RK4 reference of `m delta'' = m g - F(delta)` at a step of
//! 1e-7 s ([`reference()`]). Shared by `softgrip-rapier`'s bounce test and `softgrip-bench`'s
//! speed-vs-error table.

use softgrip_law::ContactLaw;

use crate::scenes::{BallDrop, G};

/// A first impact: the plugin's, or the 1-DOF reference's.
#[derive(Debug, Clone, Copy, Default)]
pub struct Impact {
    /// Peak normal force \[N\].
    pub peak_force: f64,
    /// Peak compression delta \[m\].
    pub peak_delta: f64,
    /// Contact duration \[s\].
    pub duration: f64,
}

/// 1-DOF reference from first touch at `v0` [m/s] to separation: RK4 on
/// `delta'' = g - F(delta) / m` at h = 1e-7 s.
pub fn reference(law: &ContactLaw, mass: f64, v0: f64) -> Impact {
    let h = 1e-7;
    let acc = |d: f64| G - law.response(d).force / mass;
    let (mut d, mut v, mut t, mut peak, mut peak_delta) = (0.0f64, v0, 0.0, 0.0f64, 0.0f64);
    loop {
        let (k1d, k1v) = (v, acc(d));
        let (k2d, k2v) = (v + 0.5 * h * k1v, acc(d + 0.5 * h * k1d));
        let (k3d, k3v) = (v + 0.5 * h * k2v, acc(d + 0.5 * h * k2d));
        let (k4d, k4v) = (v + h * k3v, acc(d + h * k3d));
        let d_next = d + h / 6.0 * (k1d + 2.0 * k2d + 2.0 * k3d + k4d);
        v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        if d_next <= 0.0 {
            // Separation inside the step: linear interpolation of the crossing.
            t += h * d / (d - d_next);
            return Impact {
                peak_force: peak,
                peak_delta,
                duration: t,
            };
        }
        d = d_next;
        t += h;
        peak = peak.max(law.response(d).force);
        peak_delta = peak_delta.max(d);
    }
}

/// The plugin's first impact in a [`BallDrop`], measured step by step: call
/// [`before_step`](Self::before_step), step the world, then [`after_step`](Self::after_step).
#[derive(Debug, Clone, Copy, Default)]
pub struct FirstImpact {
    /// Peak force and compression of the contact's readouts, and the sum of their
    /// durations, from the first touch to the first step without contact.
    pub impact: Impact,
    /// Speed at first touch [m/s], from the free fall over the gap before the touching step
    /// (with the ball's true velocity, [`BallDrop::true_velocity_y`]).
    pub speed: f64,
    touched: bool,
    v_before: f64,
    gap_before: f64,
}

impl FirstImpact {
    /// Notes the ball's downward true velocity and gap before a step.
    pub fn before_step(&mut self, s: &BallDrop) {
        self.v_before = -s.true_velocity_y();
        self.gap_before = s.gap();
    }

    /// Adds the step's contact readout; true once the ball has touched and left the ground.
    pub fn after_step(&mut self, s: &BallDrop) -> bool {
        match s.world.soft.contacts().first() {
            Some(c) => {
                if !self.touched {
                    // Speed at first touch, from the free fall over the gap before the step.
                    self.speed = (self.v_before * self.v_before + 2.0 * G * self.gap_before).sqrt();
                }
                self.touched = true;
                self.impact.peak_force = self.impact.peak_force.max(c.peak_normal_force);
                self.impact.peak_delta = self.impact.peak_delta.max(c.max_delta);
                self.impact.duration += c.contact_duration;
                false
            }
            None => self.touched,
        }
    }
}
