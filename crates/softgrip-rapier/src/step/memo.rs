//! The resting fast path: a step whose inputs are bit-identical to those of a step already
//! computed replays that step's writes instead of recomputing them (crate README, "Resting
//! steps replayed").
//!
//! The plugin's part of a step is a deterministic function of what it reads: rapier's bodies
//! and colliders (poses, velocities, forces, mass properties, types, sleep, shapes, groups),
//! the integration parameters and gravity, and its own state (fingertips, settings, the
//! contacts' memory, the last substep count). Its outputs are writes to rapier's bodies (the
//! impulses as velocity sets, and wakes), its own state and the readout. Resting fingertips
//! never asleep do not stop at one state: in `f32` their bodies settle on a cycle of two
//! (`softgrip-bench`'s `fixed_point` example: from step 8 on, each ball's height alternates
//! between two neighbouring `f32` values, 1 ulp apart, and its stored velocity between two
//! values 1.1e-7 m/s apart, bit for bit), so the memo keeps the last [`SLOTS`] steps:
//!
//! - every step snapshots the inputs read from rapier ([`world_key`]);
//! - a full step whose snapshot equals one of the last [`SLOTS`] steps' is *recorded* in a
//!   slot: its snapshot, its writes to rapier's bodies in order (wakes, velocity sets), its
//!   counters' increments, the plugin's state it ends with (the contacts' memory, readout,
//!   geometry, unsplit carry), and that memory's bits at its start and end. It is
//!   *replayable* if it was unsplit (and the step before it too), held no sleeping fingertip
//!   and had no kinematic body, joint, rigid support or non-finite value;
//! - slot `b` may follow slot `a` when `a`'s memory at its end is bit for bit `b`'s at its
//!   start (a state that returns);
//! - a step that follows a replayable slot `a` (recorded or replayed the step before) and whose
//!   snapshot equals that of a slot `b` that may follow `a` replays `b`: its writes through
//!   the same calls in the same order (`RigidBodySet::get_mut`, `wake_up`, `set_linvel`,
//!   `set_angvel`, so rapier's change tracking sees the same bodies in the same order), its
//!   counts, and its end state; then rapier's pipeline runs as in the full step.
//!
//! Anything that changes an input breaks the equality and the step is a full one: a body or
//! collider inserted or removed, moved, pushed, woken or put to sleep, a force, mass, shape
//! (its local bounding box and its `Arc`), group or friction changed, the parameters or
//! gravity changed, a fingertip registered, the accuracy or friction spring set
//! ([`RestMemo::invalidate`]). Not seen by the snapshot: a shape edited in place
//! (`Collider::shape_mut` on an unshared shape) that keeps its local bounding box; rapier's
//! change flags that would show it are private to rapier.

use rapier3d::prelude::{
    ColliderHandle, IntegrationParameters, PhysicsWorld, RigidBodyHandle, Vector,
};

use crate::bodies::UnsplitCarry;
use crate::contacts::PairState;
use crate::counters::SoftCounters;
use crate::detect::Geom;
use crate::fast_hash::FastMap;
use crate::tip_contact::TipContact;

/// The contacts' memory (`SoftContacts::pairs`).
type Pairs = FastMap<(ColliderHandle, ColliderHandle), PairState>;
/// One pair's memory as bits: its colliders' handles, then `PairState`'s fields.
type PairBits = ((u32, u32, u32, u32), [u64; 16]);

/// Steps remembered: a resting world's cycle may be this long (two measured).
pub(crate) const SLOTS: usize = 4;

/// The writes of one full step to rapier's bodies, in the order it made them.
#[derive(Debug, Clone, Default)]
pub(crate) struct Writes {
    /// Bodies woken (`wake_up(true)`), in order (before the velocity sets).
    pub wakes: Vec<RigidBodyHandle>,
    /// Velocity sets (`set_linvel`, `set_angvel`, no wake), in order.
    pub sets: Vec<(RigidBodyHandle, Vector, Vector)>,
}

/// The plugin's state a step ends with, restored by its replay.
#[derive(Debug, Clone, Default)]
pub(crate) struct EndState {
    pub pairs: Pairs,
    pub contacts: Vec<TipContact>,
    pub geoms: Vec<Geom>,
    pub unsplit_carry: Vec<UnsplitCarry>,
    pub stamp: u64,
}

/// One recorded step.
#[derive(Debug, Clone, Default)]
struct Slot {
    /// Its inputs from rapier at its start ([`world_key`]) and the parameters.
    key: Vec<u32>,
    params: Option<IntegrationParameters>,
    /// It may be replayed (see the module's notes).
    valid: bool,
    /// The contacts' memory's bits at its start and end.
    p_start: Vec<PairBits>,
    p_end: Vec<PairBits>,
    /// The slots that may follow it.
    succ: [bool; SLOTS],
    writes: Writes,
    /// Its counters' increments: the counters before and after it.
    counts_before: SoftCounters,
    counts_after: SoftCounters,
    end: EndState,
}

/// The memo of the last steps (see the module's notes).
#[derive(Debug, Clone)]
pub(crate) struct RestMemo {
    /// The fast path is used (`SoftContacts::set_rest_replay`, default on).
    pub enabled: bool,
    slots: Vec<Slot>,
    /// The snapshots of the last steps' starts (a ring), and how many are filled.
    seen: Vec<(Vec<u32>, Option<IntegrationParameters>)>,
    seen_len: usize,
    seen_next: usize,
    /// The snapshot of the step in progress.
    cur: Vec<u32>,
    /// The slot the last step was (recorded or replayed), if replayable.
    prev: Option<usize>,
    /// The slot the step in progress records into.
    recording: Option<usize>,
    /// The slot whose end state is the plugin's live state (the last step replayed it).
    live: Option<usize>,
    next_slot: usize,
    /// The memory's bits at the recording step's start.
    p_start: Vec<PairBits>,
    /// Scratch for the bits at its end.
    p_end: Vec<PairBits>,
    /// The last full step could not have been replayed for a reason that outlasts a step (a
    /// sleeping fingertip held, a kinematic body, a joint, a rigid support, substeps): the
    /// next step is a full one without a snapshot ([`note_full`](Self::note_full)). A world
    /// of N sleeping fingertips paid the snapshot's O(N) walk every step for nothing
    /// (`peers_softgrip resting-sleep`, N = 1000: 183 µs a step against 22 µs without it).
    skip_next: bool,
}

impl Default for RestMemo {
    fn default() -> Self {
        Self {
            enabled: true,
            slots: vec![Slot::default(); SLOTS],
            seen: vec![Default::default(); SLOTS],
            seen_len: 0,
            seen_next: 0,
            cur: Vec::new(),
            prev: None,
            recording: None,
            live: None,
            next_slot: 0,
            p_start: Vec::new(),
            p_end: Vec::new(),
            skip_next: false,
        }
    }
}

/// What a step does with the memo, decided at its start.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Plan {
    /// Replay the slot.
    Replay(usize),
    /// A full step that records itself (its inputs equal a recent step's).
    Record,
    /// A full step.
    Full,
}

impl RestMemo {
    /// Forgets every step: the next one is a full one (a setting or a fingertip changed).
    pub(crate) fn invalidate(&mut self) {
        debug_assert!(self.live.is_none(), "materialize_rest before invalidate");
        for s in &mut self.slots {
            s.valid = false;
            s.succ = [false; SLOTS];
        }
        self.seen_len = 0;
        self.prev = None;
        self.recording = None;
    }

    /// The recording step's log of writes, if it records.
    pub(crate) fn log(&mut self) -> Option<&mut Writes> {
        self.recording.map(|i| &mut self.slots[i].writes)
    }

    /// At a step's start (before the plugin writes anything): snapshots the inputs and decides.
    pub(crate) fn begin(
        &mut self,
        world: &PhysicsWorld,
        counters: &SoftCounters,
        pairs: &Pairs,
    ) -> Plan {
        self.recording = None;
        if !self.enabled {
            return Plan::Full;
        }
        if self.skip_next {
            // No snapshot: nothing may follow into this step, nor a replay follow it.
            self.prev = None;
            self.seen_len = 0;
            return Plan::Full;
        }
        let params = Some(world.integration_parameters);
        // The parameters by value (`PartialEq`: a NaN field never equals, so never replays).
        if let Some(a) = self.prev.take() {
            let succ = self.slots[a].succ;
            for (b, ok) in succ.into_iter().enumerate() {
                let s = &self.slots[b];
                if ok && s.valid && s.params == params && {
                    // Compared as it is read (no snapshot written).
                    let mut cmp = Compare {
                        key: &s.key,
                        at: 0,
                        diff: 0,
                        short: false,
                    };
                    world_key(world, &mut cmp);
                    cmp.same()
                } {
                    self.prev = Some(b);
                    return Plan::Replay(b);
                }
            }
        }
        self.cur.clear();
        world_key(world, &mut self.cur);
        let same = |key: &[u32], p: &Option<IntegrationParameters>| *p == params && key == self.cur;
        let recent = self.seen[..self.seen_len]
            .iter()
            .any(|(key, p)| same(key, p));
        let seen = &mut self.seen[self.seen_next];
        seen.0.clone_from(&self.cur);
        seen.1 = params;
        self.seen_next = (self.seen_next + 1) % SLOTS;
        self.seen_len = (self.seen_len + 1).min(SLOTS);
        if !recent {
            return Plan::Full;
        }
        let i = self.next_slot;
        self.next_slot = (i + 1) % SLOTS;
        // The slot is rewritten: nothing may follow into it, nor it into anything.
        for s in &mut self.slots {
            s.succ[i] = false;
        }
        let slot = &mut self.slots[i];
        slot.valid = false;
        slot.succ = [false; SLOTS];
        slot.key.clone_from(&self.cur);
        slot.params = params;
        slot.writes.wakes.clear();
        slot.writes.sets.clear();
        slot.counts_before = *counters;
        pairs_bits(pairs, &mut self.p_start);
        slot.p_start.clone_from(&self.p_start);
        self.recording = Some(i);
        Plan::Record
    }

    /// At the end of a recording step: whether it may be replayed (`eligible`: unsplit, no
    /// kinematic body, joint, rigid support; `substeps_before`: the last substep count at its
    /// start), its end state, and which slots may follow it and which it may follow.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn finish(
        &mut self,
        eligible: bool,
        substeps_before: u32,
        counters: &SoftCounters,
        pairs: &Pairs,
        contacts: &[TipContact],
        geoms: &[Geom],
        unsplit_carry: &[UnsplitCarry],
        stamp: u64,
    ) {
        let Some(i) = self.recording.take() else {
            return;
        };
        pairs_bits(pairs, &mut self.p_end);
        let slot = &mut self.slots[i];
        slot.end.pairs.clone_from(pairs);
        slot.end.contacts.clear();
        slot.end.contacts.extend_from_slice(contacts);
        slot.end.geoms.clear();
        slot.end.geoms.extend_from_slice(geoms);
        slot.end.unsplit_carry.clear();
        slot.end.unsplit_carry.extend_from_slice(unsplit_carry);
        slot.end.stamp = stamp;
        slot.valid = eligible
            && substeps_before == 1
            && counters.substeps_last == 1
            && counters.non_finite == slot.counts_before.non_finite
            && counters.held_tips == slot.counts_before.held_tips;
        slot.counts_after = *counters;
        slot.p_end.clone_from(&self.p_end);
        if !slot.valid {
            return;
        }
        for j in 0..SLOTS {
            if self.slots[j].valid && self.slots[j].p_start == self.p_end {
                self.slots[i].succ[j] = true;
            }
            if self.slots[j].valid && self.slots[j].p_end == self.p_start {
                self.slots[j].succ[i] = true;
            }
        }
        self.prev = Some(i);
    }

    /// At the end of every full step (snapshot or not): whether it could have been replayed
    /// (`eligible`, as [`finish`](Self::finish) reads it). When it could not, the next step
    /// skips the snapshot; once a full step is eligible the snapshots start again, so a world
    /// coming to rest is replayed a step later than it would be with a snapshot every step.
    pub(crate) fn note_full(&mut self, eligible: bool) {
        self.skip_next = self.enabled && !eligible;
    }

    /// The replayed slot's writes and counts (`add_increments`); its end state becomes the
    /// live one ([`live_contacts`](Self::live_contacts), [`take_live`](Self::take_live)).
    pub(crate) fn replay(&mut self, i: usize) -> (&Writes, &SoftCounters, &SoftCounters) {
        self.live = Some(i);
        let s = &self.slots[i];
        (&s.writes, &s.counts_before, &s.counts_after)
    }

    /// The readout of the replayed step, while its end state is the live one.
    pub(crate) fn live_contacts(&self) -> Option<&[TipContact]> {
        self.live.map(|i| self.slots[i].end.contacts.as_slice())
    }

    /// The replayed step's end state, to be moved into the plugin's fields (then no longer
    /// live here).
    pub(crate) fn take_live(&mut self) -> Option<&EndState> {
        self.live.take().map(|i| &self.slots[i].end)
    }
}

/// The contacts' memory as bits, sorted by pair (the stamp left out: it counts steps and is
/// only compared with the current one).
fn pairs_bits(pairs: &Pairs, out: &mut Vec<PairBits>) {
    out.clear();
    for ((a, b), s) in pairs {
        let (ai, ag) = a.into_raw_parts();
        let (bi, bg) = b.into_raw_parts();
        out.push(((ai, ag, bi, bg), pair_bits(s)));
    }
    out.sort_unstable_by_key(|e| e.0);
}

/// One pair's memory as bits.
fn pair_bits(s: &PairState) -> [u64; 16] {
    let (has, jn, jt, jtw, h) = match &s.warm {
        Some(w) => (1, w.jn, w.jt, w.jtw, w.h),
        None => (0, 0.0, nalgebra::Vector3::zeros(), 0.0, 0.0),
    };
    let (a, st, t) = (&s.anchor_local, &s.stretch_local, &s.tip_local);
    let b = f64::to_bits;
    [
        b(a[0]),
        b(a[1]),
        b(a[2]),
        b(st[0]),
        b(st[1]),
        b(st[2]),
        b(t[0]),
        b(t[1]),
        b(t[2]),
        b(jn),
        b(jt[0]),
        b(jt[1]),
        b(jt[2]),
        b(jtw),
        b(h),
        has,
    ]
}

/// Where [`world_key`] puts its bits: a snapshot, or a comparison with one.
pub(crate) trait Sink {
    /// Takes the next bits.
    fn extend<const K: usize>(&mut self, bits: [u32; K]);
    /// Takes one more.
    fn push(&mut self, bits: u32) {
        self.extend([bits]);
    }
}

impl Sink for Vec<u32> {
    #[inline(always)]
    fn extend<const K: usize>(&mut self, bits: [u32; K]) {
        self.extend_from_slice(&bits);
    }
}

/// A comparison of the bits with `key`, as they come: `diff` ORs every difference (no branch
/// per value); `short` is set if the bits outrun the key.
struct Compare<'a> {
    key: &'a [u32],
    at: usize,
    diff: u32,
    short: bool,
}

impl Compare<'_> {
    /// Whether the bits were exactly `key`.
    fn same(&self) -> bool {
        self.diff == 0 && !self.short && self.at == self.key.len()
    }
}

impl Sink for Compare<'_> {
    #[inline(always)]
    fn extend<const K: usize>(&mut self, bits: [u32; K]) {
        match self.key.get(self.at..self.at + K) {
            Some(k) => {
                for (a, b) in k.iter().zip(bits) {
                    self.diff |= a ^ b;
                }
            }
            None => self.short = true,
        }
        self.at += K;
    }
}

/// Puts a pose's bits.
#[inline(always)]
fn pose_bits(p: &rapier3d::prelude::Pose, out: &mut impl Sink) {
    let (t, q) = (p.translation, p.rotation);
    out.extend([t.x, t.y, t.z, q.x, q.y, q.z, q.w].map(f32::to_bits));
}

/// Puts a vector's bits.
#[inline(always)]
fn vec_bits(v: Vector, out: &mut impl Sink) {
    out.extend([v.x, v.y, v.z].map(f32::to_bits));
}

/// The bits of everything the plugin's step reads from `world`, in the sets' order.
pub(crate) fn world_key(world: &PhysicsWorld, out: &mut impl Sink) {
    vec_bits(world.gravity, out);
    out.push(world.bodies.len() as u32);
    out.push(world.colliders.len() as u32);
    out.push(world.impulse_joints.len() as u32);
    out.push(world.multibody_joints.iter().count() as u32);
    for (h, rb) in world.bodies.iter() {
        let (i, g) = h.into_raw_parts();
        out.extend([i, g]);
        out.push(
            rb.body_type() as u32
                | (rb.is_sleeping() as u32) << 8
                | (rb.is_enabled() as u32) << 9
                | (rb.is_ccd_enabled() as u32) << 10
                | (rb.dominance_group() as u8 as u32) << 16
                | (rb.locked_axes().bits() as u32) << 24,
        );
        out.push(rb.colliders().len() as u32);
        pose_bits(rb.position(), out);
        pose_bits(rb.next_position(), out);
        vec_bits(rb.linvel(), out);
        vec_bits(rb.angvel(), out);
        vec_bits(rb.user_force(), out);
        vec_bits(rb.user_torque(), out);
        out.extend(
            [
                rb.gravity_scale(),
                rb.linear_damping(),
                rb.angular_damping(),
            ]
            .map(f32::to_bits),
        );
        let m = rb.mass_properties();
        vec_bits(m.world_com, out);
        vec_bits(m.effective_inv_mass, out);
        let ii = &m.effective_world_inv_inertia;
        out.extend([ii.m11, ii.m12, ii.m13, ii.m22, ii.m23, ii.m33].map(f32::to_bits));
        let l = &m.local_mprops;
        vec_bits(l.local_com, out);
        out.push(l.inv_mass.to_bits());
        vec_bits(l.inv_principal_inertia, out);
        let q = l.principal_inertia_local_frame;
        out.extend([q.x, q.y, q.z, q.w].map(f32::to_bits));
    }
    for (h, co) in world.colliders.iter() {
        let (i, g) = h.into_raw_parts();
        let (pi, pg) = co
            .parent()
            .map_or((u32::MAX, u32::MAX), |b| b.into_raw_parts());
        out.extend([i, g, pi, pg]);
        out.extend([
            co.is_enabled() as u32 | (co.is_sensor() as u32) << 1,
            co.active_hooks().bits(),
            co.active_collision_types().bits() as u32,
        ]);
        pose_bits(co.position(), out);
        if let Some(rel) = co.position_wrt_parent() {
            pose_bits(rel, out);
        }
        for groups in [co.collision_groups(), co.solver_groups()] {
            out.extend([
                groups.memberships.bits(),
                groups.filter.bits(),
                groups.test_mode as u32,
            ]);
        }
        out.extend([co.friction(), co.restitution(), co.contact_skin()].map(f32::to_bits));
        out.extend([
            co.friction_combine_rule() as u32,
            co.restitution_combine_rule() as u32,
        ]);
        let shape = co.shape();
        let addr = shape as *const dyn rapier3d::prelude::Shape as *const u8 as usize as u64;
        out.extend([addr as u32, (addr >> 32) as u32, shape.shape_type() as u32]);
        let aabb = shape.compute_local_aabb();
        vec_bits(aabb.mins, out);
        vec_bits(aabb.maxs, out);
    }
}
