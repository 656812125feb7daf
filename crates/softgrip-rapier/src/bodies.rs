//! The solver's view of rapier's bodies: the body table (velocity, inverse mass and inertia in
//! `f64`; the mobility of each kind of body is `mobility`'s, the paths of position-based
//! kinematic bodies `kinematic`'s), waking, the gravity bookkeeping of a split step and the
//! application of the solve's impulses to rapier.

use nalgebra::Vector3;
use rapier3d::prelude::{RigidBody, RigidBodyHandle, RigidBodySet, Vector};

use crate::boundary::{to_f32, to_f64};
use crate::counters::SoftCounters;
use crate::detect::Geom;
use crate::fast_hash::FastMap;
use crate::jointed;
use crate::kinematic::KinematicVelocity;
use crate::mobility::{BodyState, free_mobility};
use crate::multibody::{self, Hosts, LinkCtx, SavedForce};
use crate::problem::{RigidRow, Row};

/// The solver's body table under construction.
#[derive(Debug, Clone, Default)]
pub(crate) struct BodyTable {
    index: FastMap<RigidBodyHandle, usize>,
    pub table: Vec<BodyState>,
    pub handles: Vec<RigidBodyHandle>,
    /// The multibodies in the table: the index of their host link (`multibody`).
    hosts: Hosts,
    /// Bodies held by impulse joints that entered as free bodies (`jointed::is_jointed`).
    pub jointed_free: u64,
}

impl BodyTable {
    /// Empties the table, keeping its buffers.
    pub(crate) fn clear(&mut self) {
        self.index.clear();
        self.table.clear();
        self.handles.clear();
        self.hosts.clear();
        self.jointed_free = 0;
    }
}

/// Wakes the dynamic sides of the soft contact `g` that rapier cannot wake: rapier links only
/// the pairs its narrow phase sees into islands, and a fingertip's pairs are the plugin's
/// (collision groups `none()`), so it never wakes a body through a soft contact. A dynamic
/// side is woken, or kept awake (its sleep timer restarted, a strong wake as rapier wakes an
/// island), unless the other side is fixed or a sleeping dynamic body: so a body may sleep
/// only when each of its soft contacts is with something that cannot move it. That keeps
/// every grasp as before (a box held by kinematic jaws never sleeps: woken from sleep with
/// rapier's zeroed velocity, a box squeezed at 30 Hz read 22.4 N for its 20 N grip), and a
/// body on a moving support awake (rapier's drift criterion alone let a ball riding a
/// platform at 0.05 m/s sleep, miss a step and fall 0.8 mm behind).
///
/// A contact between two dynamic bodies that does not touch wakes only if its gap can close
/// within the step (`can_close`): the detection finds pairs within a generous prediction
/// distance, and two resting fingertips 10 mm apart (a grid at 30 mm) were found as a pair at
/// 60 Hz (the distance counts each side's stored speed, rapier's velocity lag of 0.061 m/s,
/// and `2 |g| dt` of fall) and kept each other awake for ever (session 14: N >= 10 never
/// slept). `r` is the fingertip's radius \[m\], `gravity` the world's \[m/s^2\], `dt` the
/// step \[s\]. The sleeping bodies it wakes are pushed to `woken`.
pub(crate) fn wake_touched(
    bodies: &mut RigidBodySet,
    g: &Geom,
    r: f64,
    gravity: Vector3<f64>,
    dt: f64,
    woken: &mut Vec<RigidBodyHandle>,
    mut log: Option<&mut Vec<RigidBodyHandle>>,
) {
    let (a, b) = (g.body_tip, g.body_other);
    let both_dynamic = [a, b].iter().all(|h| {
        h.and_then(|h| bodies.get(h))
            .is_some_and(|rb| rb.is_dynamic())
    });
    if both_dynamic && g.dist > 0.0 && !can_close(bodies, g, r, gravity, dt) {
        return;
    }
    for (this, other) in [(a, b), (b, a)] {
        let Some(this) = this else { continue };
        let Some(rb) = bodies.get(this) else { continue };
        if !rb.is_dynamic() {
            continue;
        }
        let asleep = rb.is_sleeping();
        let holds = other
            .and_then(|o| bodies.get(o))
            .is_none_or(|o| o.is_fixed() || (o.is_dynamic() && o.is_sleeping()));
        if !holds && let Some(rb) = bodies.get_mut(this) {
            rb.wake_up(true);
            if let Some(log) = log.as_deref_mut() {
                log.push(this);
            }
            if asleep {
                woken.push(this);
            }
        }
    }
}

/// Whether the open gap `g.dist` \[m\] of a contact between two dynamic bodies can close
/// within a step of `dt` \[s\]: the distance their motion along the normal can cover,
/// `0.05 R + 1.5 dt (approach + (|w_tip| + |w_other|) R + 2 |g . n| dt)` (the detection's
/// prediction with the approach speed along the normal instead of each side's whole speed, and
/// gravity's part along the normal: two bodies side by side under gravity do not approach).
fn can_close(bodies: &RigidBodySet, g: &Geom, r: f64, gravity: Vector3<f64>, dt: f64) -> bool {
    let motion = |h: Option<RigidBodyHandle>| {
        h.and_then(|h| bodies.get(h))
            .map(|rb| (to_f64(rb.linvel()), to_f64(rb.angvel()).norm()))
            .unwrap_or((Vector3::zeros(), 0.0))
    };
    let ((v_tip, w_tip), (v_other, w_other)) = (motion(g.body_tip), motion(g.body_other));
    // The normal points from the other body to the fingertip: approaching is `u < 0`.
    let approach = (-(v_tip - v_other).dot(&g.normal)).max(0.0);
    let fall = 2.0 * gravity.dot(&g.normal).abs() * dt;
    let reach = 0.05 * r + 1.5 * dt * (approach + (w_tip + w_other) * r + fall);
    g.dist <= reach
}

/// How close to 0 or 1 a body's share of gravity ([`SplitLag`]) is taken as exactly 0 or 1:
/// rapier's f32 velocities resolve `dv` over a split step's `span` (about `g (dt - h)`, 0.13
/// m/s at 1/60 s) to about 1e-6 of it at 1 m/s, so a body in free flight reads `f` 1e-6 off 1.
const SHARE_SNAP: f64 = 1e-4;

/// The gravity lag of a split step (`step`, note 1), per dynamic body: the share of gravity
/// each body felt in rapier's passes at the end of the last split step, and the bodies the
/// current split step's lead-in kicked.
///
/// rapier's stored velocity lags the true one by `a h / (2N)`, `a` the acceleration the body
/// has *within* rapier's passes. In free flight, or held by the plugin's impulses (applied
/// before rapier's pipeline, outside its passes), that is gravity. A body resting on rapier's
/// own contact (a table) has `a = 0` in the passes: its stored velocity is its true velocity,
/// 0, and there is no lag to convert. The lead-in and the give-back are therefore gravity's
/// times the share `f` in \[0, 1\] of gravity the body still feels in rapier's passes: `f =
/// (dv / span) . g / |g|^2` over the substeps after the first (`dv` rapier's change of the
/// body's velocity in them, the plugin's impulses excluded, `span` their duration; the first
/// is where a support absorbs the lead-in), clamped to \[0, 1\] so an impact on rapier's
/// contact gives back nothing and a pull past gravity no more than free flight, and snapped
/// to 0 or 1 within [`SHARE_SNAP`] of them (the f32 velocities' resolution), so a body in free
/// flight gets exactly main's kick and give-back.
#[derive(Debug, Clone, Default)]
pub(crate) struct SplitLag {
    /// `f` of each body awake at the end of the last split step (absent: 1, free flight).
    shares: FastMap<RigidBodyHandle, f64>,
    /// The bodies the lead-in kicked, each with its velocity before the current substep's
    /// pipeline step (after the plugin's impulses) \[m/s\] and the sum of rapier's changes of
    /// it over the substeps after the first \[m/s\].
    kicked: Vec<(RigidBodyHandle, Vector, Vector3<f64>)>,
}

impl SplitLag {
    /// Forgets the shares: after a step that was not split, they are not known any more.
    pub(crate) fn forget(&mut self) {
        self.shares.clear();
        self.kicked.clear();
    }
}

/// The lead-in of a split step: the impulse `m g f tau` on every awake dynamic body, `f` its
/// share of gravity at the end of the last split step ([`SplitLag`]; 1 when not known), `tau
/// = (dt - h) / (2N)` \[s\].
pub(crate) fn lag_lead_in(
    bodies: &mut RigidBodySet,
    gravity: Vector,
    lag: &mut SplitLag,
    tau: f64,
) {
    lag.kicked.clear();
    for (handle, rb) in bodies.iter_mut() {
        if rb.is_dynamic() && !rb.is_sleeping() && rb.is_enabled() {
            let f = lag.shares.get(&handle).copied().unwrap_or(1.0);
            let imp = gravity * (rb.gravity_scale() * rb.mass() * (f * tau) as f32);
            rb.apply_impulse(imp, false);
            lag.kicked.push((handle, rb.linvel(), Vector3::zeros()));
        }
    }
}

/// Before a substep's pipeline step (`before`) or after it: the velocity of each body the
/// lead-in kicked (the plugin's impulses applied), and rapier's change of it summed.
pub(crate) fn lag_pass(bodies: &RigidBodySet, lag: &mut SplitLag, before: bool) {
    for (handle, v, sum) in &mut lag.kicked {
        if let Some(rb) = bodies.get(*handle) {
            if before {
                *v = rb.linvel();
            } else {
                *sum += to_f64(rb.linvel()) - to_f64(*v);
            }
        }
    }
}

/// The give-back of a split step: the impulse `-m g f tau` on every body the lead-in kicked
/// that is still awake, `f` its share of gravity in rapier's passes over the substeps after
/// the first, `span` \[s\] of them ([`SplitLag`]), remembered for the next split step's
/// lead-in. `tau` as in [`lag_lead_in`].
pub(crate) fn lag_give_back(
    bodies: &mut RigidBodySet,
    gravity: Vector,
    lag: &mut SplitLag,
    span: f64,
    tau: f64,
) {
    lag.shares.clear();
    for &(handle, _, dv) in &lag.kicked {
        let Some(rb) = bodies.get_mut(handle) else {
            continue;
        };
        if !(rb.is_dynamic() && !rb.is_sleeping() && rb.is_enabled()) {
            continue;
        }
        let g = to_f64(gravity) * rb.gravity_scale() as f64;
        let gg = g.norm_squared();
        let a = dv / span;
        let f = if gg > 0.0 { a.dot(&g) / gg } else { 1.0 };
        let f = if !f.is_finite() || f > 1.0 - SHARE_SNAP {
            1.0
        } else if f < SHARE_SNAP {
            0.0
        } else {
            f
        };
        let imp = gravity * (rb.gravity_scale() * rb.mass() * (-f * tau) as f32);
        rb.apply_impulse(imp, false);
        lag.shares.insert(handle, f);
    }
    lag.kicked.clear();
}

/// The body's row in the solver's table: for a dynamic body, its velocity with the external
/// accelerations (gravity, user force and torque) integrated over `ctx.h_drift` \[s\] (see
/// `SoftWorld::prepare`), its inverse mass and inertia; for an awake link of a multibody, its
/// multibody's mobility (`multibody`); for a body held by impulse joints, its assembly's
/// (`jointed`: every member enters the table at once).
pub(crate) fn body_index(
    bodies: &RigidBodySet,
    handle: RigidBodyHandle,
    ctx: &LinkCtx<'_>,
    gravity: Vector,
    kin_vel: &KinematicVelocity,
    tb: &mut BodyTable,
) -> Option<usize> {
    if let Some(i) = tb.index.get(&handle) {
        return Some(*i);
    }
    let h_drift = ctx.h_drift;
    let next = tb.table.len();
    if let Some(state) =
        multibody::link_state(bodies, ctx, handle, &mut tb.table, &mut tb.hosts, next)
    {
        tb.table.push(state);
        tb.handles.push(handle);
        tb.index.insert(handle, next);
        return Some(next);
    }
    if let Some(state) = welded_link_state(bodies, ctx, kin_vel, handle) {
        tb.table.push(state);
        tb.handles.push(handle);
        tb.index.insert(handle, next);
        return Some(next);
    }
    // A body held by impulse joints: its whole assembly enters, the first its host (`jointed`).
    if let Some(states) = jointed::assembly_states(bodies, ctx, kin_vel, handle, next) {
        for (h, state) in states {
            tb.index.insert(h, tb.table.len());
            tb.table.push(state);
            tb.handles.push(h);
        }
        return Some(next);
    }
    if jointed::is_jointed(bodies, ctx, handle) {
        tb.jointed_free += 1;
    }
    let rb = bodies.get(handle)?;
    let com = to_f64(rb.mass_properties().world_com);
    let state = if rb.is_dynamic() && !rb.is_sleeping() {
        free_state(rb, com, to_f64(gravity), h_drift)
    } else if rb.is_kinematic() {
        kinematic_state(rb, handle, com, kin_vel)
    } else {
        fixed_state(com)
    };
    if !(state.v.iter().chain(state.w.iter()).all(|x| x.is_finite())) {
        return None;
    }
    tb.table.push(state);
    tb.handles.push(handle);
    tb.index.insert(handle, tb.table.len() - 1);
    Some(tb.table.len() - 1)
}

/// A free dynamic body's row: its velocity with gravity (`gravity` \[m/s^2\], times its
/// gravity scale), the user force and torque integrated over `h_drift` \[s\], its mobility
/// ([`free_mobility`]) and centre of mass `com` \[m\].
fn free_state(rb: &RigidBody, com: Vector3<f64>, gravity: Vector3<f64>, h_drift: f64) -> BodyState {
    let (inv_m, inv_i) = free_mobility(rb);
    // rapier adds gravity, the user force and torque during its step: predict them.
    let gravity = gravity * rb.gravity_scale() as f64;
    let v =
        to_f64(rb.linvel()) + (inv_m.component_mul(&to_f64(rb.user_force())) + gravity) * h_drift;
    let w = to_f64(rb.angvel()) + inv_i * to_f64(rb.user_torque()) * h_drift;
    let a_ext = inv_m.component_mul(&to_f64(rb.user_force())) + gravity;
    BodyState {
        v,
        w,
        inv_m,
        inv_i,
        com,
        a_ext,
        passive: (v, w),
        link: None,
    }
}

/// A kinematic body's row: its velocity over the (sub)step (`kin_vel` for a position-based
/// one on its path, else rapier's), no mobility.
fn kinematic_state(
    rb: &RigidBody,
    handle: RigidBodyHandle,
    com: Vector3<f64>,
    kin_vel: &KinematicVelocity,
) -> BodyState {
    let (v, w) = kin_vel
        .get(&handle)
        .copied()
        .unwrap_or((to_f64(rb.linvel()), to_f64(rb.angvel())));
    BodyState::immobile(v, w, com)
}

/// A fixed (or sleeping) body's row: at rest, no mobility.
fn fixed_state(com: Vector3<f64>) -> BodyState {
    BodyState::immobile(Vector3::zeros(), Vector3::zeros(), com)
}

/// A dynamic link of a multibody with no free dof (a fixed or kinematic root and only fixed
/// joints: a URDF robot with no moving joint, e.g. a fixture with a pad): nothing moves it but
/// its root, so it is immobile to the solve and moves with the root's velocity (at its centre
/// of mass). `None` for anything else. Before session 15 such a link (whose multibody has no
/// mobility for [`multibody::link_state`]) was taken as a free body of its own mass: its pad's
/// impulses went to a velocity rapier overwrites from the multibody, and a 20 g ball resting on
/// the pad chattered (0 / 0.4 N from step to step, peaks to 1 N after 3 s) where on a fixed
/// body it rests at its weight.
fn welded_link_state(
    bodies: &RigidBodySet,
    ctx: &LinkCtx<'_>,
    kin_vel: &KinematicVelocity,
    handle: RigidBodyHandle,
) -> Option<BodyState> {
    let id = *ctx.multibodies.rigid_body_link(handle)?;
    let mb = ctx.multibodies.get_multibody(id.multibody)?;
    let rb = bodies.get(handle)?;
    if mb.ndofs() != 0 || !rb.is_dynamic() {
        return None;
    }
    let root = bodies.get(mb.root().rigid_body_handle())?;
    let (v_root, w) = (kin_vel.get(&mb.root().rigid_body_handle()).copied())
        .unwrap_or((to_f64(root.linvel()), to_f64(root.angvel())));
    let com = to_f64(rb.mass_properties().world_com);
    let v = v_root + w.cross(&(com - to_f64(root.mass_properties().world_com)));
    (v.iter().chain(w.iter()).all(|x| x.is_finite())).then_some(BodyState::immobile(v, w, com))
}

/// Applies the rows' impulses to rapier's bodies. They are summed per body in `f64` and
/// applied as one velocity change (the only `f64 -> f32` conversion). Applied one by one,
/// rapier's `f32` velocity would have to hold each contact's velocity change before they
/// cancel: a cell (m = 1.2e-11 kg) held between two plates gets +-3e3 m/s per contact and
/// per step, whose `f32` sum leaves up to 2.4e-4 m/s of rounding, an 8 um jump per step
/// (half the cell's radius), measured in `tests/micro_cells_squeeze.rs`.
///
/// The velocity is set without waking the body (`wake_up = false`): the body is awake (a
/// sleeping one is immobile in the table and gets nothing), and a strong wake would restart
/// rapier's sleep timer every step, so a fingertip resting on soft contacts never fell asleep
/// (measured: 4 balls resting on the ground, 600 steps, none asleep). rapier's own criterion
/// (its pose drifting less than its threshold for `time_until_sleep`) decides instead.
#[allow(clippy::too_many_arguments)]
pub(crate) fn apply_impulses(
    bodies: &mut RigidBodySet,
    h: f64,
    saved: &mut Vec<SavedForce>,
    table: &[BodyState],
    handles: &[RigidBodyHandle],
    rows: &[Row],
    rigid: &[RigidRow],
    counters: &mut SoftCounters,
    net: &mut Vec<(Vector3<f64>, Vector3<f64>)>,
    mut log: Option<&mut Vec<(RigidBodyHandle, Vector, Vector)>>,
) {
    net.clear();
    net.resize(table.len(), (Vector3::zeros(), Vector3::zeros()));
    // The bodies on rapier's soft rows (`RigidRow::softness`): their impulses are given as a
    // force over rapier's passes (see below).
    let on_soft_rows: Vec<usize> = rigid
        .iter()
        .filter(|r| r.softness.is_some())
        .flat_map(|r| std::iter::once(r.a).chain(r.b))
        .collect();
    let soft = rows
        .iter()
        .map(|r| (r.a, r.b, r.p, r.n * r.jn + r.jt, r.n * r.jtw));
    // rapier's rigid contacts: the soft contacts' part of their impulses (`rigid`).
    let rigid = rigid
        .iter()
        .map(|r| (Some(r.a), r.b, r.p, r.n * r.jn + r.jt, Vector3::zeros()));
    for (a, b, p, imp, torque) in soft.chain(rigid) {
        if !(imp.iter().chain(torque.iter()).all(|v| v.is_finite())) {
            counters.non_finite += 1;
            continue;
        }
        for (body, sign) in [(a, 1.0), (b, -1.0)] {
            let Some(bi) = body else { continue };
            let arm = p - table[bi].com;
            net[bi].0 += imp * sign;
            net[bi].1 += (arm.cross(&imp) + torque) * sign;
        }
    }
    let mut forced = Vec::new();
    for (i, ((b, (lin, ang)), handle)) in table.iter().zip(net.iter()).zip(handles).enumerate() {
        if b.inv_m == Vector3::zeros() {
            continue;
        }
        // A body on rapier's soft rows: the plugin's impulse as a force over rapier's passes
        // (restored after them, as for the multibody links), so that rapier's soft contact
        // meets it pass by pass as the coupled solve predicted (`problem::ContactSoftness`).
        // Given as one impulse before the passes, the pads' share of a squeezed box's weight
        // (70-90 %, more than the first pass's gravity) lifted the box before the table let
        // go of it: 14.8 um a step (`SPRING_DEFAULT_STATUS.md`, 20-21).
        if b.link.is_none() && on_soft_rows.contains(&i) {
            if *lin == Vector3::zeros() && *ang == Vector3::zeros() {
                continue;
            }
            let (f, t) = (to_f32(&(lin / h)), to_f32(&(ang / h)));
            if !(f.is_finite() && t.is_finite()) {
                counters.non_finite += 1;
                continue;
            }
            if let Some(rb) = bodies.get_mut(*handle) {
                saved.push((*handle, rb.user_force(), rb.user_torque()));
                rb.add_force(f, true);
                rb.add_torque(t, true);
                forced.push(i);
            }
            continue;
        }
        let (dv, dw) = (b.inv_m.component_mul(lin), b.inv_i * ang);
        if !(dv.iter().chain(dw.iter()).all(|v| v.is_finite())) {
            counters.non_finite += 1;
            continue;
        }
        if let Some(rb) = bodies.get_mut(*handle) {
            let (v, w) = (to_f64(rb.linvel()) + dv, to_f64(rb.angvel()) + dw);
            rb.set_linvel(to_f32(&v), false);
            rb.set_angvel(to_f32(&w), false);
            if let Some(log) = log.as_deref_mut() {
                log.push((*handle, rb.linvel(), rb.angvel()));
            }
        }
    }
    // Given as forces: not the links' (`multibody::project_net` reads `net`).
    for i in forced {
        net[i] = (Vector3::zeros(), Vector3::zeros());
    }
    // The multibody links: a force over the coming pipeline step (`multibody`).
    if table.iter().any(|b| b.link.is_some()) {
        multibody::project_net(table, net);
        counters.non_finite += multibody::apply_to_rapier(bodies, table, handles, net, h, saved);
    }
}

/// What the soft impulses of an unsplit step did to a dynamic body, for the next step if it is
/// split (`step::split`, `carry_unsplit`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct UnsplitCarry {
    /// The body.
    pub body: RigidBodyHandle,
    /// Its velocity change from the soft impulses \[m/s\].
    pub dv: Vector3<f64>,
    /// Its external acceleration \[m/s^2\].
    pub a_ext: Vector3<f64>,
}

/// [`unsplit_carry`]'s per-body sums, kept between steps so that a step allocates nothing:
/// the soft rows' linear impulse on each body \[N s\] and whether it is on a rigid row.
#[derive(Debug, Clone, Default)]
pub(crate) struct CarrySums {
    lin: Vec<Vector3<f64>>,
    on_rigid: Vec<bool>,
}

/// The velocity changes of the dynamic bodies of `table` from the soft rows' impulses `rows`
/// (as [`apply_impulses`] applied them), written to `carry`.
///
/// The soft rows only, not the soft contacts' part of rapier's rigid rows that the plugin
/// applies with them: what the carry gives back is the lag of the external acceleration behind
/// an impulse applied before rapier's passes, and a rigid support (the table under a box) holds
/// the box's weight inside those passes, as rapier's own contact. Counted with the net, a box a
/// rigid-stick tip pressed against a wall (the stick pushing it down with 8 N, the table's part
/// pushing it up with as much) read as resting on the plugin's impulses: the carry gave it 0.08
/// m/s when a step was split after an unsplit one and the wedge lifted it 1 mm
/// (`tests/press_on_table.rs`, session 28).
pub(crate) fn unsplit_carry(
    table: &BodyTable,
    rows: &[Row],
    rigid: &[RigidRow],
    carry: &mut Vec<UnsplitCarry>,
    sums: &mut CarrySums,
) {
    carry.clear();
    let (lin, on_rigid) = (&mut sums.lin, &mut sums.on_rigid);
    lin.clear();
    lin.resize(table.table.len(), Vector3::zeros());
    on_rigid.clear();
    on_rigid.resize(table.table.len(), false);
    for r in rigid {
        for bi in std::iter::once(r.a).chain(r.b) {
            on_rigid[bi] = true;
        }
    }
    for r in rows {
        let imp = r.n * r.jn + r.jt;
        for (body, sign) in [(r.a, 1.0), (r.b, -1.0)] {
            if let Some(bi) = body {
                lin[bi] += imp * sign;
            }
        }
    }
    for (((b, lin), body), &rigid) in table
        .table
        .iter()
        .zip(lin.iter())
        .zip(&table.handles)
        .zip(on_rigid.iter())
    {
        let dv = b.inv_m.component_mul(lin);
        if !rigid && b.inv_m != Vector3::zeros() && dv.iter().all(|v| v.is_finite()) {
            carry.push(UnsplitCarry {
                body: *body,
                dv,
                a_ext: b.a_ext,
            });
        }
    }
}
