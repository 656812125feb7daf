//! When a step is split into substeps (`substep_count`), and what a split step takes over from
//! an unsplit one (`carry_unsplit`).

use nalgebra::Vector3;

use super::Step;
use crate::boundary::{to_f32, to_f64};
use crate::contacts::Scratch;
use crate::detect::compression_from_signed_distance;
use crate::solve;
use crate::substep;

impl Step<'_> {
    /// Before a step of `dt` \[s\] split into `n > 1` substeps that follows a step that was
    /// not: gives back to each dynamic body the velocity its soft contacts held against its
    /// external acceleration `a` in that step, `dt/2` of it (see [`held_velocity`]), then
    /// forgets it.
    ///
    /// Why: an unsplit step applies the contact's impulse before rapier's `N` passes of
    /// "kick, then drift" and gravity's within them, so a body resting on a soft contact ends
    /// the step with the stored velocity `g dt (N-1)/(2N)` downward, which the next step's
    /// impulse cancels again. A split step reads the stored velocity in free-flight's
    /// convention (it lags the true velocity by `g dt/(2N)`, step 1 of `step`'s notes) and
    /// its fine substeps cancel gravity only as it acts: the resting body started the split
    /// step falling at `g dt / 2` (0.16 m/s at dt = 1/30 s) and bounced off its own support
    /// (a 1.2 um drop rose to 677 times its height). The substep count is the world's, so
    /// every resting contact got that kick whenever another contact of the world needed
    /// substeps.
    pub(super) fn carry_unsplit(&mut self, n: u32, dt: f64, scratch: &mut Scratch) {
        if n > 1 {
            for c in &scratch.unsplit_carry {
                let Some(rb) = self.physics.bodies.get_mut(c.body) else {
                    continue;
                };
                if !rb.is_dynamic() {
                    continue;
                }
                let v = to_f64(rb.linvel()) + held_velocity(&c.dv, &c.a_ext, dt);
                if v.iter().all(|x| x.is_finite()) {
                    rb.set_linvel(to_f32(&v), true);
                }
            }
        }
        scratch.unsplit_carry.clear();
    }

    /// The substep count of a step of `dt` \[s\] from its prepared rows (the largest any contact
    /// needs), counted in the diagnostics.
    ///
    /// A touching contact is judged on two things, apart:
    /// - the motion it carries (its bodies' passive velocity, `BodyState::passive`: the
    ///   velocity now and the external accelerations', without the joint motors' push), known
    ///   up to one step's increment of the external accelerations and one substep's of the
    ///   motors' push (rapier's stored velocity lags or leads the true one by that): its
    ///   excess is resolved as an impact (`substep::substeps_for`);
    /// - the motors' push, a force, which a substep's update balances against the law
    ///   linearised at the substep's start: enough substeps that the push's free run over one
    ///   stays within [`DRIVE_RUN_FRACTION`] of the compression ([`drive_substeps`]).
    ///
    /// Read as an approach velocity, the push was the motor's free run over a whole step
    /// (0.21 m/s for a gripper pad holding 5 N, against 5 um/s of real motion), and a held
    /// grasp took 75 to 89 substeps per step. An approaching contact keeps the full free
    /// velocity (a motor closing a finger does carry it into the contact).
    pub(super) fn substep_count(&mut self, dt: f64, scratch: &Scratch) -> u32 {
        let theta = self.soft.accuracy.theta();
        let mut n = 1u32;
        let table = &scratch.body_table.table;
        for ((row, model), gi) in scratch.rows.iter().zip(&scratch.models).zip(&scratch.geom) {
            let delta = compression_from_signed_distance(self.soft.geoms[*gi].dist);
            let mut vn = solve::normal_velocity(table, row);
            let mut k_drive = 1;
            let w = solve::normal_mobility(table, row);
            // The external load pressing the contact (acceleration into it over the mobility).
            let push = (-solve::normal_external_acceleration(table, row)).max(0.0) / w;
            if delta > 0.0 {
                let passive = solve::passive_normal_velocity(table, row);
                let drive = vn - passive;
                k_drive = drive_substeps(drive, delta, model.radius, dt);
                // A touching contact's velocity is known only up to the velocity increment of
                // one step of its external accelerations and of one substep of its motors'
                // push (rapier's stored velocity lags or leads the true one by up to that):
                // only the excess counts as dynamic.
                let a = solve::normal_external_acceleration(table, row).abs();
                let known = a * dt + drive.abs() / k_drive as f64;
                vn = passive.signum() * (passive.abs() - known).max(0.0);
            }
            let k = substep::substeps_for(&model.law, model.radius, delta, vn, w, push, dt, theta)
                .max(k_drive);
            n = n.max(k);
        }
        if n >= substep::MAX_SUBSTEPS {
            self.soft.counters.substep_cap_hits += 1;
        }
        self.soft.counters.substeps_last = n;
        self.soft.counters.substeps_total += n as u64;
        n
    }
}

/// The largest fraction of a touching contact's compression (`max(delta, 1e-3 R)`) that its
/// joint motors' free run may cover in one substep ([`drive_substeps`]). Measured on the
/// shipped gripper's box hold (free run 3.5 times the compression per step): 0.5 leaves the
/// finger motor's effort 1.05 % off `J^T F` (its end-of-step velocity lags; the damping reads
/// it), 0.25 (about 14 substeps) 0.28 %; the three-finger hand's box hold reads pads 2.26 /
/// 2.11 / 2.14 N at 0.25 against 2.10 / 2.27 / 2.28 N fully resolved.
pub(crate) const DRIVE_RUN_FRACTION: f64 = 0.25;

/// Substeps a touching contact of compression `delta` \[m\] (fingertip radius `radius`)
/// needs for its joint motors' push over a step of `dt` \[s\], `drive` \[m/s\] the normal
/// velocity the motors would add in the step if the contact were not there: enough that the
/// motors' free run over a substep, `|drive| h`, stays within [`DRIVE_RUN_FRACTION`] of
/// `max(delta, 1e-3 R)`. Each substep's update takes the law linearised at its start
/// (stiffness at `delta`) and the motors' response as the folded mobility predicts it; a push
/// that runs past the compression within one update leaves the range where both hold: the
/// shipped gripper's pad held at 1.1 mm by its 2000 N/m motor (free run 3.8 mm per 1/60 s)
/// let go of its box in one unsplit step, and the three-finger hand's thumb held its box at
/// 0.38 N unsplit where the resolved hold reads 2.1 N.
fn drive_substeps(drive: f64, delta: f64, radius: f64, dt: f64) -> u32 {
    let run = drive.abs() * dt / (DRIVE_RUN_FRACTION * delta.max(1e-3 * radius));
    if !run.is_finite() {
        return 1;
    }
    (run.ceil() as u32).clamp(1, substep::MAX_SUBSTEPS)
}

/// The velocity a body's soft contacts held against its external acceleration `a`
/// \[m/s^2\] in an unsplit step of `dt` \[s\] where they changed its velocity by `dv` \[m/s\]:
/// along `dv`, the part of `-a dt / 2` that `dv` opposes, at most `|dv|` (a contact that
/// only grazed the body held little). At rest on a support it is `-g dt / 2`, the velocity
/// the unsplit step's convention leaves owing (see `Step::carry_unsplit`); a body pressed
/// sideways or held by rapier's contacts (the plugin's impulses cancel) gets nothing.
fn held_velocity(dv: &Vector3<f64>, a: &Vector3<f64>, dt: f64) -> Vector3<f64> {
    let size = dv.norm();
    if !(size > 0.0) {
        return Vector3::zeros();
    }
    let u = dv / size;
    let along = -a.dot(&u) * 0.5 * dt;
    if along > 0.0 {
        u * along.min(size)
    } else {
        Vector3::zeros()
    }
}
