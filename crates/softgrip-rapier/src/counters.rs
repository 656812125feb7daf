//! [`SoftCounters`]: what the plugin did, to explain a slow or odd step.

use std::time::{Duration, Instant};

/// Diagnostics of the plugin (rapier's own timers need its `profiler` feature; these use
/// `std::time::Instant` and are always on).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct SoftCounters {
    /// Steps taken.
    pub steps: u64,
    /// Soft contacts evaluated (one per contact per substep), total.
    pub contacts_evaluated: u64,
    /// Substeps of the last step (1 = not split).
    pub substeps_last: u32,
    /// Substeps taken, total over all steps.
    pub substeps_total: u64,
    /// Steps whose substep count hit the cap.
    pub substep_cap_hits: u64,
    /// Contact evaluations past the law's validity range (`Regime::Extended`).
    pub validity_excursions: u64,
    /// Contact evaluations past the law's wall (`ContactLaw::x_wall`: the fingertip's rigid
    /// part at the surface it presses), one per contact per substep, total; also counted in
    /// `validity_excursions`. Such a contact is solved as a rigid one, as rapier solves its
    /// own (crate README, Past a law's validity). A free body never gets there (the barrier
    /// stops it); a kinematic jam does (a palm driving a pad into a box the table holds).
    pub past_wall: u64,
    /// Contacts skipped because a pose, velocity, distance or impulse was not finite.
    pub non_finite: u64,
    /// Candidate pairs that parry could not compute (unsupported shape pair).
    pub unsupported_pairs: u64,
    /// Extra solves for contacts that begin within a (sub)step (linearised where they end:
    /// Newton on the implicit law; 0 when every contact is resolved or already touching).
    pub onset_solves: u64,
    /// Contacts on a counterpart the fingertip's law cannot take (a groove or bowl tighter
    /// than the fingertip), computed as on a plane instead (one per contact per substep).
    pub counterpart_fallbacks: u64,
    /// Coupled solves of soft contacts on rigid supports (`rigid::solve_coupled`), total.
    pub coupled_solves: u64,
    /// Outer passes (a dense LU, then friction sweeps) of those solves, total.
    pub coupled_passes: u64,
    /// Coupled solves that used every pass allowed without settling, total.
    pub coupled_unsettled: u64,
    /// Coupled solves whose answer was degenerate, total: rapier's contacts of the group could
    /// not all hold at once (a finger link pressing a box that the table holds, under a
    /// kinematic base), so the hard rows balanced by their compliance at up to 1e9 times the
    /// velocity they missed. Such a group's soft contacts are solved on their bodies alone
    /// for that (sub)step, rapier's contacts left to rapier. Not an error; before session 13
    /// the answer was applied (2e8 N on a 20 g link) and the hand went to 1e24 rad/s.
    pub coupled_degenerate: u64,
    /// Solves of a group of two or more soft contacts on a dynamic body without rigid
    /// supports (a box held by fingertips alone; `solve.rs`'s `solve_group`), total.
    pub group_solves: u64,
    /// Outer passes (the normals by a dense LU, then friction sweeps) of those solves, total;
    /// each stops once its impulses move by less than 1e-6 of its largest normal impulse.
    pub group_passes: u64,
    /// Group solves that used every pass allowed (256) without settling (nor answered as
    /// sticking, `group_stuck`), total.
    pub group_unsettled: u64,
    /// Group solves whose outer passes diverged (their largest normal impulse grew past 1000
    /// times the larger of the first pass's and the group's impulse scale: a wedge of rows past
    /// their law's wall locked by friction, where each pass's normals answer the friction of
    /// the last), total. Such a group is answered by its normals solved exactly without
    /// friction, then friction within those normals' Coulomb disks, not fed back (`solve.rs`,
    /// `solve_group`). Not an error; before session 22 the passes went on and a pad of the
    /// three-finger hand driven into the table read 1.9e38 N (issue 25).
    pub group_diverged: u64,
    /// Group solves answered by their fixed point solved directly, every contact sticking,
    /// where the outer passes had not settled within 16 (`stick.rs`; the three-finger hand's
    /// ball: its passes contract by 0.988 each), total. Not an error.
    pub group_stuck: u64,
    /// Rows of coupled solves (rapier's contacts in them, and soft rows) along which their
    /// bodies cannot move (mobility below `f32::EPSILON` of the bodies' at that point: a
    /// prismatic finger's vertical on a table), solved as immobile (no impulse), total. Not an
    /// error: a gripper whose fingers touch the table counts its table rows here each
    /// (sub)step. Before session 12 such a row took an impulse of its `f32` noise and threw
    /// the link off its joint.
    pub immobile_rows: u64,
    /// rapier's own solver contacts of a multibody link against a fixed or kinematic body (or
    /// another such link) along a direction the link's joints cannot move it (the same
    /// criterion), dropped before rapier's solver (`link_contacts.rs`), total; also counted in
    /// `immobile_rows`. Not an error: the parallel gripper's fingers pushed into the table by
    /// its kinematic base count theirs here each (sub)step. Left to rapier, such a contact
    /// asked an impulse of `1 / (f32 noise)` and threw the link off its joint.
    pub locked_link_contacts: u64,
    /// Colliders whose rapier contact pairs were updated afresh for a step because a recycled
    /// contact of theirs acted across a gap (its points slid over each other and the shapes
    /// stood apart by more than 2 % of the smaller one's bounding radius, at most rapier's
    /// allowed linear error), total (`stale_contacts.rs`; crate README, "rapier's settings").
    /// Not an error. Before session 31 the parallel gripper's finger slid 25 mm up a 2 kg ball
    /// held by such a contact.
    pub stale_contacts: u64,
    /// Bodies held by rapier impulse joints that the soft solve took as free bodies, counted
    /// once per (sub)step each, total: their joints' rows do not converge within rapier's
    /// Gauss-Seidel sweeps of a solver pass (`rate^sweeps > 1e-5`, crate README, What one step
    /// does, 9), their assembly holds more than 8 bodies, or its numbers are not finite. Not an
    /// error, but a pad on such a body reads a small force and sinks into what it presses
    /// (the two-link finger at 2 PGS iterations: 0.004 N where the law asks 6.3 N). Before
    /// session 13 the shipped gripper's impulse fingers counted here (their joint anchors 31
    /// mm from their centres of mass); raise `num_internal_pgs_iterations` or the bodies'
    /// `additional_pgs_iterations`, put a prismatic joint's anchors at its child's centre of
    /// mass, or use a multibody.
    pub jointed_free: u64,
    /// The most soft contacts solved together in one coupled group (contacts sharing a
    /// dynamic body, What one step does, 4), over all solves so far (0 before any contact).
    /// Resting fingertips apart from each other are groups of one: a larger figure says the
    /// solve is coupling contacts it need not (its cost grows with the cube of a group's
    /// size).
    pub largest_group: u64,
    /// Sleeping dynamic bodies the plugin woke because the other side of one of their soft
    /// contacts moved (an awake dynamic body, a kinematic body with a velocity), total. rapier
    /// cannot see a soft contact (a fingertip's collision groups are `none()`), so it never
    /// wakes a body through one (crate README, Sleeping).
    pub woken: u64,
    /// Fingertips whose contacts were held, total over the steps: on a sleeping body that no
    /// awake body could reach, they were not detected, nor their law evaluated or solved;
    /// their readout and contact memory stay those of the step they fell asleep in (crate
    /// README, Sleeping).
    pub held_tips: u64,
    /// Steps replayed by the resting fast path, total: their inputs (rapier's bodies and
    /// colliders, the parameters, the plugin's state) were bit-identical to the last step's,
    /// so its writes were applied again instead of recomputed (crate README, "Resting steps
    /// replayed"). A replayed step adds the counts of the step it replays (`contacts_evaluated`
    /// included: the same contacts, reused bit for bit), not its times.
    pub replayed_steps: u64,
    /// Pipeline steps that carried a collider-less body through rapier's awake island to clear
    /// it, total: after a step that put every awake body to sleep in several chunks, rapier
    /// 0.36.1 leaves its awake island empty but set and enters its solver on no body every
    /// later step (crate README, "Where a resting step's time goes"); one such step after each
    /// time the world falls wholly asleep. Not counted by a step the resting fast path replays
    /// unless it carries the body itself.
    pub awake_islands_cleared: u64,
    /// Time spent in soft contact detection.
    pub detect_time: Duration,
    /// Time spent in the contact stage of the substeps: the rows of every substep after the
    /// first ([`rows_time`](Self::rows_time), [`supports_time`](Self::supports_time)), the
    /// law ([`law_time`](Self::law_time)), the impulse solve
    /// ([`soft_solve_time`](Self::soft_solve_time)), the impulses applied
    /// ([`apply_time`](Self::apply_time)) and the readout's sums (part of
    /// [`readout_time`](Self::readout_time)).
    pub solve_time: Duration,
    /// Time spent in rapier's pipeline.
    pub pipeline_time: Duration,
    /// The step's parts below (`step_time` to `readout_time`) are timed only while profiling
    /// is on ([`SoftContacts::set_profiling`](crate::SoftContacts::set_profiling); off by
    /// default: reading the clock a dozen times a substep was 1.7 % of a sweep trial's CPU);
    /// they stay zero otherwise.
    ///
    /// Time spent in whole steps (`SoftContacts::try_step`, from its state check to its
    /// last): every part below, plus what no part names (the kinematic paths, the gravity
    /// bookkeeping of split steps, the state checks, the link contacts' refresh).
    pub step_time: Duration,
    /// Time spent building the contacts' rows and their bodies' table (free, kinematic,
    /// multibody link and impulse-jointed mobilities: the joints).
    pub rows_time: Duration,
    /// Time spent gathering rapier's touching rigid contacts as supports of the coupled solve.
    pub supports_time: Duration,
    /// Time spent on the law's response and the contacts' memory (friction anchors).
    pub law_time: Duration,
    /// Time spent in the impulse solve proper (soft rows, coupled with the rigid supports and
    /// joints where they are, with its onset passes).
    pub soft_solve_time: Duration,
    /// Time spent applying the impulses to the bodies and checking them.
    pub apply_time: Duration,
    /// Time spent on the readout: the substeps' sums and the step's contacts assembled (not
    /// the tactile images, which are laid on their first read).
    pub readout_time: Duration,
}

impl SoftCounters {
    /// Adds the counts `after - before` (a recorded step's) again: every count but `steps`
    /// (the caller's), `substeps_last` (set to `after`'s), `largest_group` (a maximum, already
    /// reached) and `replayed_steps`; not the times.
    pub(crate) fn add_increments(&mut self, before: &Self, after: &Self) {
        macro_rules! add {
            ($($f:ident),*) => { $( self.$f += after.$f - before.$f; )* };
        }
        add!(
            contacts_evaluated,
            substeps_total,
            substep_cap_hits,
            validity_excursions,
            past_wall,
            non_finite,
            unsupported_pairs,
            onset_solves,
            counterpart_fallbacks,
            coupled_solves,
            coupled_passes,
            coupled_unsettled,
            coupled_degenerate,
            group_solves,
            group_passes,
            group_unsettled,
            group_diverged,
            group_stuck,
            immobile_rows,
            locked_link_contacts,
            stale_contacts,
            jointed_free,
            woken,
            held_tips
        );
        self.substeps_last = after.substeps_last;
    }
}

/// A stopwatch over a step's parts that reads the clock only while profiling is on
/// ([`SoftContacts::set_profiling`](crate::SoftContacts::set_profiling)).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Lap(Option<Instant>);

impl Lap {
    /// Starts now if `on`; a stopwatch that is off never reads the clock.
    pub(crate) fn start(on: bool) -> Self {
        Self(on.then(Instant::now))
    }

    /// Adds the time since the start or the last lap to `total`, and starts the next lap.
    pub(crate) fn lap(&mut self, total: &mut Duration) {
        if let Some(t) = &mut self.0 {
            let now = Instant::now();
            *total += now - *t;
            *t = now;
        }
    }
}
