//! A contact that begins within a (sub)step: solved implicitly where it ends (`onset`).

use super::Step;
use crate::contacts::Scratch;
use crate::detect::compression_from_signed_distance;
use crate::model::Model;
use crate::problem::{self, Row};
use crate::solve;
use crate::substep::{self, theta_blend};

impl Step<'_> {
    /// The solve of a (sub)step, and again while a contact that does not touch at the start
    /// but would by the end is not yet linearised where it ends (see [`onset`]): Newton on the
    /// implicit law from the predicted compression, at most [`MAX_ONSET_PASSES`] solves. The
    /// body table is restored before each solve again.
    pub(super) fn solve_with_onsets(&mut self, h: f64, s: &mut Scratch) {
        let capped = self.soft.counters.substeps_last >= substep::MAX_SUBSTEPS;
        // Only a row open at the start can begin within the (sub)step (`onset`): without one
        // the solve runs once and the table need not be kept (a held grasp's every substep).
        let geoms = &self.soft.geoms;
        let may_begin =
            (s.geom.iter()).any(|&gi| !(compression_from_signed_distance(geoms[gi].dist) > 0.0));
        if may_begin {
            s.onset_base.clone_from(&s.body_table.table);
        }
        for pass in 0..MAX_ONSET_PASSES {
            if pass > 0 {
                s.body_table.table.clone_from_slice(&s.onset_base);
                self.soft.counters.onset_solves += 1;
            }
            let failed = solve::solve(
                &mut s.body_table.table,
                &mut s.rows,
                &mut s.rigid,
                h,
                &mut s.solve,
            );
            let largest = s.solve.largest_group() as u64;
            let counters = &mut self.soft.counters;
            counters.largest_group = counters.largest_group.max(largest);
            let mut again = false;
            for ((row, model), (&gi, &w)) in s
                .rows
                .iter_mut()
                .zip(&s.models)
                .zip(s.geom.iter().zip(&s.mobility))
            {
                let delta0 = compression_from_signed_distance(self.soft.geoms[gi].dist);
                again |= if row.past_wall {
                    false
                } else if delta0 > 0.0 {
                    capped && wall_stop(row, model, delta0, h)
                } else {
                    let push = -problem::normal_external_acceleration(&s.body_table.table, row);
                    onset(row, model, delta0, w, push, h, capped)
                };
            }
            if !again || pass + 1 == MAX_ONSET_PASSES {
                self.soft.counters.non_finite += failed;
                let [solves, passes, unsettled, immobile, degenerate] = s.solve.coupled_stats();
                self.soft.counters.immobile_rows =
                    immobile + self.soft.counters.locked_link_contacts;
                self.soft.counters.coupled_solves = solves;
                self.soft.counters.coupled_passes = passes;
                self.soft.counters.coupled_unsettled = unsettled;
                self.soft.counters.coupled_degenerate = degenerate;
                let [solves, passes, unsettled, diverged, stuck] = s.solve.group_stats();
                self.soft.counters.group_solves = solves;
                self.soft.counters.group_passes = passes;
                self.soft.counters.group_unsettled = unsettled;
                self.soft.counters.group_diverged = diverged;
                self.soft.counters.group_stuck = stuck;
                break;
            }
        }
    }
}

/// The update's blend `theta` (0 explicit, 1 implicit; [`theta_blend`]) of a contact of
/// stiffness `k` \[N/m\] and normal mobility `w` \[1/kg\] over a (sub)step of `h` \[s\]; 1 in
/// a step whose substep count hit [`substep::MAX_SUBSTEPS`] (`capped`). Capped, a contact's
/// phase per substep is larger than the accuracy asks for and the explicit update's energy
/// error grows with it (a 0.56 mm tip of E = 9.6 GPa bouncing from 1.3 um rose 7 % in 13
/// bounces, each impact capped at 2000 substeps); the implicit update never gains energy,
/// and damps such a contact a little more than its restitution says.
pub(super) fn update_blend(k: f64, w: f64, h: f64, capped: bool) -> f64 {
    if w > 0.0 && !capped {
        theta_blend((k * w).sqrt() * h)
    } else {
        1.0
    }
}

/// The most solves of one (sub)step while contacts begin within it.
const MAX_ONSET_PASSES: usize = 12;

/// A contact that begins within the (sub)step: it does not touch at the start (`delta0 <= 0`,
/// \[m\]) but its solved end velocity brings it to `delta_end = delta0 - h v_n(end) > 0`. Its
/// row is linearised at the predicted compression instead of the start (where the law is
/// zero): `F(δ) ≈ F(δ_L) + K(δ_L)(δ - δ_L)`, evaluated at `δ0 - θ h v(end)` with `θ` blended by
/// the stiffness there. Unresolved (`θ = 1`), the contact is backward Euler on the law from
/// the moment it would touch, and never gains energy; before, it penetrated a whole step's
/// travel with no force and released the elastic energy of that penetration on the way out
/// (the default fingertip dropped 0.5 mm at dt = 1/60 s rebounded to 13 times its height, a
/// stiff 1 mm tip dropped 10 cm at dt = 1/30 s to 317 m). Resolved (`θ = 0`, a fine substep)
/// it changes nothing. Returns whether the row was linearised anew (the solve must run again).
/// Called for a row not yet made hard (`past_wall` false) that does not touch at the start;
/// a touching one goes to [`wall_stop`] instead. In a capped substep, an impact shorter than
/// the substep is impulsive ([`impact`] past the wall, [`short_impact`] short of it); `push`
/// \[m/s^2\] is the external acceleration pressing the pair together (gravity on a ball
/// above a plane: g).
fn onset(
    row: &mut Row,
    model: &Model,
    delta0: f64,
    w: f64,
    push: f64,
    h: f64,
    capped: bool,
) -> bool {
    let d = if row.lin > 0.0 {
        delta0 - row.theta * h * row.vn_end
    } else {
        delta0 - h * row.vn_end
    };
    if !(d > 0.0 && d.is_finite()) {
        return false;
    }
    if capped && super::past_wall(&model.law, d) > 0.0 {
        return impact(row, model, d, h);
    }
    if capped && row.lin == 0.0 && short_impact(row, model, delta0, d, w, push, h) {
        return true;
    }
    let resp = model.law.response(d);
    if row.lin > 0.0 {
        // Converged: the law at the prediction is the linear model's.
        let linear = row.force + row.stiffness * (d - delta0);
        if (resp.force - linear).abs() <= 1e-6 * resp.force.abs().max(linear.abs())
            || (d - row.lin).abs() <= 1e-12 * model.radius
        {
            return false;
        }
    }
    row.lin = d;
    row.theta = update_blend(resp.stiffness, w, h, capped);
    if row.theta == 0.0 {
        // Resolved: the law at the start (zero) is the explicit update's.
        row.force = 0.0;
        row.stiffness = 0.0;
        row.damping = 0.0;
        return row.lin != d;
    }
    // The linear model at the start: F(δ_L) + K(δ_L)(δ0 - δ_L).
    row.force = resp.force + resp.stiffness * (delta0 - d);
    row.stiffness = resp.stiffness;
    row.damping = model.alpha * resp.force;
    true
}

/// A contact beginning within a capped substep whose predicted end lies past its law's wall
/// (`delta_end` \[m\]): the approach crosses the law's whole range within one substep, so
/// the impact is over in less than a substep the step cannot shorten (a 1 um ball at 4 m/s:
/// Hertz's contact time about 0.2 us, a capped substep 17 us at dt = 1/30 s). Linearised in
/// the barrier past the wall it answered nonsense (a 1 um ball dropped 0.6 m rebounded to 99
/// times its drop, or the step diverged). It is taken as an impulsive impact instead: a hard
/// row (`theta = 1`, no damping, the law's stiffness at the wall) whose end separation
/// velocity is `e(v) v`, `v` the approach speed the first solve predicted (no force on the
/// row) and `e(v) = max(0, 1 - (2/3) alpha v)` the fingertip's own Hunt-Crossley restitution
/// at that speed (`alpha` from its restitution, `Model::alpha`): the body leaves no faster
/// than it came, and the contact ends within the substep. Returns whether the row changed.
fn impact(row: &mut Row, model: &Model, delta_end: f64, h: f64) -> bool {
    let v_in = if row.lin > 0.0 {
        -row.vn_end
    } else {
        -row.vn_end.min(0.0)
    };
    let v_in = v_in.max(0.0);
    let e = model.restitution(v_in);
    // `delta_end` lies past the wall here (`onset` checked), so the stiffness is the wall's.
    hard_row(row, model, delta_end, |k| k * h * e * v_in)
}

/// A contact beginning within a capped substep, its unforced end `delta_end` \[m\] short of
/// its wall, whose whole impact is shorter than the substep (`h` \[s\]): an impulsive impact
/// too, energy-consistent. Before (session 24), the onset was backward Euler from the touch
/// and the touching substep after it backward Euler at `omega h >> 1`, which took nearly all
/// the energy: a 10 um ball of e = 1 dropped 1 m at dt = 1/60 s stopped dead (its first
/// capped substep's end 0.57 R deep; at 1/74 and 1/30 s the end passes the wall and
/// [`impact`] returned 0.9999-1.0004 of the drop).
///
/// At the approach speed `v` of the first (unforced) solve and the normal mobility `w`
/// \[1/kg\], the impact turns at `delta_m`, `W(delta_m) = v^2 / (2 w)` (the law's energy,
/// bisected), and lasts about `pi delta_m / v` (a linear spring's half period; Hertz's
/// 2.94 `delta_m / v`): when that is at most `h`, the bounce is over within the substep.
/// The body then leaves with the fingertip's own restitution `e(v)` ([`impact`]), lowered
/// where the external push `push` \[m/s^2\] would make it gain: the velocity update moves
/// the body by `h v_end` from its start, `s0 = -delta0` apart, while the true bounce leaves
/// from contact, so `v_end` solves `v_end^2 / 2 + push (s0 + h v_end) = (e v)^2 / 2`, the
/// energy just after the true bounce (at least `-s0 / h`: never past the contact). Returns
/// whether the row was made hard. Not where the rebound's flight `2 e(v) v / push` is at most
/// `h` (no bounce the substep could show: a ball settling, or `e(v) = 0`), which stays the
/// implicit onset: impulsive there, a settling micrometre ball hopped at the cap forever.
fn short_impact(
    row: &mut Row,
    model: &Model,
    delta0: f64,
    delta_end: f64,
    w: f64,
    push: f64,
    h: f64,
) -> bool {
    let v = -row.vn_end;
    if !(v > 0.0 && w > 0.0 && h > 0.0 && v.is_finite()) {
        return false;
    }
    let wall = model.law.x_wall() * model.law.params().radius();
    let kinetic = 0.5 * v * v / w;
    if !(model.law.energy(wall) > kinetic) {
        return false;
    }
    // W is increasing: bisect on [0, wall] to 1e-6 of the wall (60 halvings).
    let (mut lo, mut hi) = (0.0, wall);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if model.law.energy(mid) < kinetic {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    if std::f64::consts::PI * hi / v > h {
        return false;
    }
    let e = model.restitution(v);
    let g = push.max(0.0);
    if g > 0.0 && 2.0 * e * v / g <= h {
        // The rebound would be back within the substep (or there is none, e(v) = 0): the
        // implicit onset settles it (a ball coming to rest, not bouncing).
        return false;
    }
    let s0 = (-delta0).max(0.0);
    let radicand = (g * h).powi(2) + (e * v).powi(2) - 2.0 * g * s0;
    let v_end = if radicand >= 0.0 {
        radicand.sqrt() - g * h
    } else {
        -g * h
    };
    let v_end = v_end.max(-s0 / h);
    hard_row(row, model, delta_end, |k| k * h * v_end)
}

/// Makes `row` hard for the rest of the (sub)step ([`impact`], [`wall_stop`]): implicit
/// (`theta = 1`), undamped, with the law's stiffness `k` at its wall, linearised at
/// `delta_end` \[m\] and with the force `force(k)` \[N\] (`k h v`: the solved end
/// separation velocity is `v`). Returns true (the row changed).
fn hard_row(row: &mut Row, model: &Model, delta_end: f64, force: impl Fn(f64) -> f64) -> bool {
    let wall = model.law.x_wall() * model.law.params().radius();
    let k = model.law.response(wall).stiffness;
    row.lin = delta_end;
    row.past_wall = true;
    row.theta = 1.0;
    row.damping = 0.0;
    row.stiffness = k;
    row.force = force(k);
    true
}

/// A touching contact (`delta0` \[m\] > 0, short of its wall) in a capped substep whose solved
/// end velocity would carry it past its law's wall within the substep: the law cannot stop
/// it there (a 10 um ball of E = 10 kPa dropped 1 m at dt = 1/74 s travels 3 R a capped
/// substep, and its centre ended 0.3-0.6 R past the plane; past the wall the rigid row only
/// pushes out at rapier's bias). The row is made hard (`theta = 1`, no damping, the law's
/// stiffness at the wall) with the end separation velocity that brings the contact to
/// [`WALL_STOP`] of its wall by the substep's end, `-(WALL_STOP wall - delta0) / h` (0 if it is
/// there already): the approach stops short of the wall, dissipating what the law could not
/// store, and the law pushes back from there in the substeps after. Returns whether the row
/// changed.
fn wall_stop(row: &mut Row, model: &Model, delta0: f64, h: f64) -> bool {
    let wall = model.law.x_wall() * model.law.params().radius();
    let delta_end = delta0 - h * row.vn_end;
    if !(delta_end > wall && delta0 < wall) {
        return false;
    }
    let v_end = -((WALL_STOP * wall - delta0) / h).max(0.0);
    hard_row(row, model, delta_end, |k| k * h * v_end)
}

/// The share of its wall a contact is stopped at by [`wall_stop`].
const WALL_STOP: f64 = 0.98;
