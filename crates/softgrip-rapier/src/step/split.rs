//! When a step is split into substeps (`substep_count`), and what a split step takes over from
//! an unsplit one (`carry_unsplit`).

use nalgebra::Vector3;

use super::Step;
use crate::contacts::Scratch;
use crate::detect::{compression_from_signed_distance, to_f32, to_f64};
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
    pub(super) fn substep_count(&mut self, dt: f64, scratch: &Scratch) -> u32 {
        let theta = self.soft.accuracy.theta();
        let mut n = 1u32;
        let table = &scratch.body_table.table;
        for ((row, model), gi) in scratch.rows.iter().zip(&scratch.models).zip(&scratch.geom) {
            let delta = compression_from_signed_distance(self.soft.geoms[*gi].dist);
            let mut vn = solve::normal_velocity(table, row);
            if delta > 0.0 {
                // A touching contact's velocity is known only up to the external velocity
                // increment of one step (rapier's stored velocity lags or leads the true one
                // by up to |a| dt): only the excess counts as dynamic.
                let a = solve::normal_external_acceleration(table, row).abs();
                vn = vn.signum() * (vn.abs() - a * dt).max(0.0);
            }
            let w = solve::normal_mobility(table, row);
            n = n.max(substep::substeps_for(
                &model.law,
                model.radius,
                delta,
                vn,
                w,
                dt,
                theta,
            ));
        }
        if n >= substep::MAX_SUBSTEPS {
            self.soft.counters.substep_cap_hits += 1;
        }
        self.soft.counters.substeps_last = n;
        self.soft.counters.substeps_total += n as u64;
        n
    }
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
