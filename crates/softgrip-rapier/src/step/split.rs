//! When a step is split into substeps (`substep_count`), and what a split step takes over from
//! an unsplit one (`carry_unsplit`).

use nalgebra::Vector3;
use softgrip_law::ContactLaw;

use super::Step;
use crate::boundary::{to_f32, to_f64};
use crate::contacts::Scratch;
use crate::detect::compression_from_signed_distance;
use crate::mobility::BodyState;
use crate::problem::{self, RigidRow, Row};
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
    ///   stays within [`DRIVE_RUN_FRACTION`] of the compression ([`drive_substeps`]); or, for
    ///   a contact whose force is far below the push (not held by its motors, but driven into
    ///   or pulled off: [`far_below_push`]), enough that its oscillation at the stiffness it
    ///   reaches in the step is resolved as an impact's, if that is fewer. Either keeps the
    ///   substep's update in the range where it holds.
    ///
    /// Read as an approach velocity, the push was the motor's free run over a whole step
    /// (0.21 m/s for a gripper pad holding 5 N, against 5 um/s of real motion), and a held
    /// grasp took 75 to 89 substeps per step. An approaching contact keeps the full free
    /// velocity (a motor closing a finger does carry it into the contact).
    pub(super) fn substep_count(&mut self, dt: f64, scratch: &Scratch) -> u32 {
        let theta = self.soft.accuracy.theta();
        let mut n = 1u32;
        let table = &scratch.body_table.table;
        let step = self.soft.counters.steps;
        for ((row, model), gi) in scratch.rows.iter().zip(&scratch.models).zip(&scratch.geom) {
            let geom = &self.soft.geoms[*gi];
            let key = (geom.tip, geom.other);
            let now = GapMemory {
                gap: geom.dist,
                vn: problem::normal_velocity(table, row),
                dt,
                step,
                supported: None,
            };
            let last = self.soft.gaps.insert(key, now);
            let delta = compression_from_signed_distance(geom.dist);
            if super::past_wall(&model.law, delta) > 0.0 {
                // A rigid contact (`rigid_past_wall`), as rapier's own: no oscillation to
                // resolve. The barrier's tangent there (6.7e16 N/m on the three-finger hand's
                // pad) asked the cap.
                continue;
            }
            let mut vn = problem::normal_velocity(table, row);
            let w = problem::normal_mobility(table, row);
            let mut k_drive = 1;
            let mut k_jam = 1;
            // The external load pressing the contact (acceleration into it over the mobility).
            let push = (-problem::normal_external_acceleration(table, row)).max(0.0) / w;
            if delta > 0.0 {
                let passive = problem::passive_normal_velocity(table, row);
                let drive = vn - passive;
                k_drive = drive_substeps(drive, delta, model.radius, dt);
                if k_drive > 1 {
                    let far = far_below_push(&model.law, delta, passive, drive, w, dt, theta);
                    if let Some(k) = far {
                        k_drive = k_drive.min(k);
                    }
                }
                // A touching contact's velocity is known only up to the velocity increment of
                // one step of its external accelerations and of one substep of its motors'
                // push (rapier's stored velocity lags or leads the true one by up to that):
                // only the excess counts as dynamic.
                let a = problem::normal_external_acceleration(table, row).abs();
                let known = a * dt + drive.abs() / k_drive as f64;
                vn = passive.signum() * (passive.abs() - known).max(0.0);
                let jam = jam_velocity(table, row, &scratch.rigid);
                k_jam = drive_substeps(jam, delta, model.radius, dt);
                if k_jam > 1 {
                    // As a far push's count (`far_below_push`): no more than the contact's
                    // phase at the stiffness an impact of that speed reaches needs.
                    let law = &model.law;
                    let impact =
                        substep::substeps_for(law, model.radius, delta, -jam, w, 0.0, dt, theta);
                    k_jam = k_jam.min(impact);
                }
            } else if on_jointed_link(table, row) {
                let capped = realised_approach(vn, &now, last.as_ref(), table, row);
                // Only where the capped approach leaves the gap open over the step (else the
                // impact count below takes the contact as closing).
                let open_after = geom.dist > -capped.min(0.0) * dt + 0.01 * model.radius;
                if capped > vn && open_after {
                    // The approach was capped at the realised closing (a jammed link): its
                    // motors' push still closes the gap within the step if the jam lets go.
                    let drive = vn - problem::passive_normal_velocity(table, row);
                    k_drive = gap_drive_substeps(drive, geom.dist, model.radius, dt);
                }
                vn = capped;
            }
            // The impact's mobility: where the contact's last step was solved coupled with
            // rapier's contacts and some held (`Row::supported_mobility`), the body's mobility
            // given them, if less (a box the table's sticking friction holds against a closing
            // jaw is no free body: session 27, 20 219 of the throughput sweep's 22 749 coupled
            // solves were that split). A new contact, a link's, or one whose last step's rigid
            // rows slid keeps the free mobility.
            let w_impact = match last {
                Some(m)
                    if m.step + 1 == step
                        && compression_from_signed_distance(m.gap) > 0.0
                        && !on_jointed_link(table, row) =>
                {
                    m.supported.map_or(w, |s| w.min(s))
                }
                _ => w,
            };
            let k = substep::substeps_for(
                &model.law,
                model.radius,
                delta,
                vn,
                w_impact,
                push,
                dt,
                theta,
            )
            .max(k_drive)
            .max(k_jam);
            n = n.max(k);
        }
        // Forget the contacts not seen in this step.
        self.soft.gaps.retain(|_, m| m.step == step);
        if n >= substep::MAX_SUBSTEPS {
            self.soft.counters.substep_cap_hits += 1;
        }
        self.soft.counters.substeps_last = n;
        self.soft.counters.substeps_total += n as u64;
        n
    }
}

/// A contact's gap and normal velocity at the start of a step, kept for the next step's
/// approach check ([`realised_approach`]).
#[derive(Debug, Clone, Copy)]
pub(crate) struct GapMemory {
    /// Signed distance \[m\] (negative: compressed).
    pub gap: f64,
    /// Normal separation velocity of the contact's bodies (stored velocities, with the step's
    /// external accelerations and motors; `problem::normal_velocity`) \[m/s\].
    pub vn: f64,
    /// The step's length \[s\].
    pub dt: f64,
    /// The step's number (`SoftCounters::steps`).
    pub step: u64,
    /// The contact's normal mobility given the rigid rows that held in the step's last
    /// substep (`Row::supported_mobility`, written after each substep's solve) \[1/kg\].
    pub supported: Option<f64>,
}

/// Whether either body of `row` is a link of a jointed body (a multibody's link or a member
/// of an impulse-jointed assembly: `BodyState::link`).
fn on_jointed_link(table: &[BodyState], row: &Row) -> bool {
    [row.a, row.b]
        .into_iter()
        .flatten()
        .any(|i| table[i].link.is_some())
}

/// The normal velocity \[m/s\] (> 0 separating) an open contact on a link of a jointed body
/// is counted with for its approach estimate (`substep::substeps_for`): its bodies' stored
/// velocity `now.vn`, its approach no faster than the gap's realised closing over the last
/// step plus that velocity's change since the last step's start and one step of the
/// external accelerations.
///
/// Over a step the pose moves by the mean of the velocities within it; when the velocity
/// changes monotonically from the last step's start to this one's (a finger accelerating into
/// a contact), that mean lies between the two stored velocities, so the end velocity is at
/// most the realised closing plus their difference. A stored velocity past that did not
/// produce the motion it implies: a jammed link (the three-finger hand's pads pressing each
/// other under its kinematic palm, driven into the table) whose stored velocity reads
/// 1.8-2.3 m/s towards the other pad step after step while the 7 mm gap does not close is held
/// by rapier's contacts of its links, which undo that velocity within each step; read as an
/// impact, it ran into the barrier and asked the substep cap. A free body's stored velocity
/// is its motion (its impacts stay as they are): only links are checked. Without the last
/// step's memory (a contact first seen) `now.vn` is kept.
fn realised_approach(
    vn: f64,
    now: &GapMemory,
    last: Option<&GapMemory>,
    table: &[BodyState],
    row: &Row,
) -> f64 {
    let Some(last) = last.filter(|m| m.step + 1 == now.step && m.dt > 0.0) else {
        return vn;
    };
    let approach = -vn;
    if !(approach > 0.0) {
        return vn;
    }
    let closing = ((last.gap - now.gap) / last.dt).max(0.0);
    let a = problem::normal_external_acceleration(table, row).abs();
    let bound = closing + (now.vn - last.vn).abs() + a * now.dt;
    if bound.is_finite() && bound < approach {
        -bound
    } else {
        vn
    }
}

/// The normal velocity change \[m/s\] that rapier's rows on a soft contact's own assembly
/// (`rigid`, `Step::prepare_rigid`) impose on the contact (`row`, its fingertip on a link of a
/// jointed body) within the coming step: a link of the fingertip's multibody or
/// impulse-jointed assembly closing on a body outside it (the table, the box) is stopped there
/// by rapier's contact, and that stop reaches the fingertip through the joints. Its size is
/// the stopping impulse's effect, `|W_pr / W_rr| |v_r|` (`v_r` the rigid row's closing normal
/// velocity, `W_rr` its mobility, `W_pr` the cross mobility between the two rows), the
/// largest over the assembly's closing rows; 0 for a fingertip not on a link.
///
/// The step counts it as it counts the motors' push ([`drive_substeps`]: its run over a
/// substep within [`DRIVE_RUN_FRACTION`] of the compression), and no more than an impact of
/// that speed needs (`substep::substeps_for`, as [`far_below_push`] bounds a far push): by
/// its run alone, the multibody hand's pads barely touching (x = 0.015) asked 500-1183
/// substeps a step.
///
/// Why: unsplit, the step in which the impulse-jointed three-finger hand's distal links first
/// met the table under its kinematic palm took the pads from x = 0.10 to 0.64-0.72 and off
/// the box (softgrip-rapier README, Limits (a')); no soft contact of that step asked a split,
/// since the jam is rapier's row, not theirs. A link at rest on a fixed body (not closing)
/// asks nothing; nor does a contact between two links of one assembly (pads pressing each
/// other), which the jam moves on both sides.
fn jam_velocity(table: &[BodyState], row: &Row, rigid: &[RigidRow]) -> f64 {
    let Some(host) = row.a.and_then(|i| table[i].link.as_deref()).map(|l| l.host) else {
        return 0.0;
    };
    let mine = |i: usize| table[i].link.as_deref().is_some_and(|l| l.host == host);
    if row.b.is_some_and(mine) {
        // Two fingertips of one hand pressing each other: the jam moves both sides.
        return 0.0;
    }
    let mut dv = 0.0f64;
    for r in rigid {
        // A row of the assembly's link on something outside it (rows between its own links
        // are its joints' business).
        if mine(r.a) == r.b.is_some_and(mine) {
            continue;
        }
        let ends = (Some(r.a), r.b, &r.p);
        let vr = problem::rel_vel_between(table, ends).dot(&r.n);
        if !(vr < 0.0) {
            continue;
        }
        let w_rr = problem::mobility_between(table, ends, &r.n, ends, &r.n);
        if !(w_rr > 0.0) {
            continue;
        }
        let w_pr = problem::mobility_between(table, (row.a, row.b, &row.p), &row.n, ends, &r.n);
        let change = (w_pr / w_rr * vr).abs();
        if change.is_finite() {
            dv = dv.max(change);
        }
    }
    dv
}

/// The largest fraction of an open contact's gap that its joint motors' push may close in
/// one substep where the contact's approach was capped at its realised closing (a link
/// jammed by rapier's contacts, `realised_approach`): [`gap_drive_substeps`].
pub(crate) const GAP_RUN_FRACTION: f64 = 1.0;

/// Substeps an open contact of gap `gap` \[m\] (fingertip radius `radius`) on a jammed link
/// needs for its motors' push over a step of `dt` \[s\], `drive` \[m/s\] the normal velocity
/// the motors would add in the step (< 0 closing): 1 if the push does not close the gap within
/// the step, else enough that it closes at most [`GAP_RUN_FRACTION`] of `max(gap, 0.01 R)`
/// per substep. Counted only where the capped approach leaves the gap open over the step (a
/// closing one is the impact count's); the jammed three-finger hand's pads under its palm
/// (gaps of 0.1-8 mm, push 0.6-1.2 m/s, capped to 0.14-0.4 m/s) asked 2-18 substeps a step
/// without that condition, and its descent 14 319 substeps against 6077.
///
/// Why: the jam holds the link only while rapier's contacts of its links hold, and those can
/// let go within the step. The shipped gripper's fingers, pressed by a 20 N motor onto the top
/// of a 2 kg box they failed to lift, stood still with their pads 18 mm apart (the push read
/// 1.1 m/s, capped to 0.03 m/s), then cleared the box and shut in one unsplit step (the joint
/// 13 mm to -1.2 mm, past its limit): the pads met only in the next step, 8 mm deep, at
/// 87.9 N where the motor pushes 10 N per pad. Split (2 substeps; the pair now detected,
/// `multibody::motor_push`), the pads meet within the step they shut in, where the onset
/// (`step::onset`) takes the contact from where it starts: at most 4.44 N in that step.
fn gap_drive_substeps(drive: f64, gap: f64, radius: f64, dt: f64) -> u32 {
    let run = -drive * dt;
    if !(run > gap) {
        return 1;
    }
    let n = run / (GAP_RUN_FRACTION * gap.max(0.01 * radius));
    if !n.is_finite() {
        return 1;
    }
    (n.ceil() as u32).clamp(1, substep::MAX_SUBSTEPS)
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

/// The fraction of its motors' push below which a touching contact's force is "far below" it
/// ([`far_below_push`]): the push then drives the contact to at least twice its force (into
/// it) or off it (away), so the law linearised at the current compression describes neither
/// the substep nor the step, and the contact is not held by its motors.
pub(crate) const FAR_BELOW_PUSH: f64 = 0.5;

/// Substeps for a touching contact (compression `delta` \[m\], normal separation velocity
/// without the motors `passive` \[m/s\], normal mobility `w` \[1/kg\]) whose motors' push
/// over a step of `dt` \[s\] (`drive` \[m/s\], the normal velocity they would add if the
/// contact were not there; > 0 pulls the contact apart) is a force `F_push = |drive| / (w dt)`
/// far above its own, `F(delta) < FAR_BELOW_PUSH F_push`; `None` when it is not (a held
/// contact: [`drive_substeps`] counts it).
///
/// Such a contact is not held by its motors; it is an impact or a release, and needs what an
/// impact needs (`substep::substeps_for`): `omega h <= theta` at the largest stiffness it can
/// reach in the step, `omega = sqrt(K w)`. The step takes the fewer of this count and
/// [`drive_substeps`]'s (each keeps a substep's update where it holds: the latter the push's
/// run within the law's linearisation, this one the contact's phase).
/// - Pushed into the contact: an approach under a constant force. Its deepest point `d` is
///   where the law's energy has taken the push's work and the passive motion's kinetic energy,
///   `W(d) - W(delta) = F_push (d - delta) + v_in^2 / (2 w)` (`v_in` the passive approach
///   speed); `K` is the law's stiffness there (past the stall compression, where the law
///   balances the motors' force). `None` if the law has no stiffness there (frozen past its
///   validity): [`drive_substeps`] counts it.
/// - Pulled off the contact: its compression only falls until it lets go (or until the bodies
///   holding the link stop the pull), so its stiffness stays at most `K(delta)`.
///
/// Counted as a held contact instead, the free run of the push over a substep against a
/// barely touching pad (0.1 mm, 0.04 N, a distal link of the three-finger hand whose motor
/// pushed 65 N jammed far from its target) asked 1000-2000 substeps a step.
fn far_below_push(
    law: &ContactLaw,
    delta: f64,
    passive: f64,
    drive: f64,
    w: f64,
    dt: f64,
    theta: f64,
) -> Option<u32> {
    let push = drive.abs() / (w * dt);
    let here = law.response(delta);
    if !(push.is_finite() && here.force < FAR_BELOW_PUSH * push) {
        return None;
    }
    let stiffness = if drive > 0.0 {
        here.stiffness
    } else {
        let kinetic = 0.5 * passive.min(0.0).powi(2) / w;
        let deepest = deepest_under_push(law, delta, push, kinetic)?;
        law.response(deepest).stiffness
    };
    let omega = (stiffness * w).sqrt();
    if !(omega > 0.0 && omega.is_finite()) {
        return None;
    }
    let n = (omega * dt / theta).ceil();
    Some(if n >= substep::MAX_SUBSTEPS as f64 {
        substep::MAX_SUBSTEPS
    } else {
        (n as u32).max(1)
    })
}

/// The compression `d > delta` \[m\] where `W(d) - W(delta) = push (d - delta) + kinetic`
/// (`push` \[N\], `kinetic` \[J\]): the deepest point of a contact driven by a constant
/// force `push` from `delta` with `kinetic` energy of approach. `None` if the law never
/// takes that energy (its force frozen below `push`, past its validity).
fn deepest_under_push(law: &ContactLaw, delta: f64, push: f64, kinetic: f64) -> Option<f64> {
    let w0 = law.energy(delta);
    let excess = |d: f64| law.energy(d) - w0 - push * (d - delta) - kinetic;
    // Bracket: `excess` is negative just past `delta` (the law's force is below the push) and
    // grows once the force passes it; double the step until it is positive.
    let mut lo = delta;
    let mut hi = delta + delta.max(1e-9);
    let mut found = false;
    for _ in 0..80 {
        if excess(hi) > 0.0 {
            found = true;
            break;
        }
        lo = hi;
        hi = delta + 2.0 * (hi - delta);
    }
    if !found {
        return None;
    }
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if excess(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
        if hi - lo <= 1e-9 * hi {
            break;
        }
    }
    Some(hi)
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
