//! [`SoftContacts`]: the plugin's state: registered fingertips, per-contact memory, readout.

use std::sync::Arc;

use nalgebra::Vector3;
use rapier3d::prelude::{
    ActiveCollisionTypes, ActiveHooks, ColliderHandle, ColliderSet, InteractionGroups,
    PhysicsWorld, RigidBodyHandle,
};

use crate::bodies::{BodyTable, UnsplitCarry};
use crate::boundary::raw;
use crate::counters::SoftCounters;
use crate::curved_models::CurvedModels;
use crate::detect::Geom;
use crate::error::{Error, Result};
use crate::fast_hash::{FastMap, FastSet};
use crate::fingertip::SoftFingertip;
use crate::model::Model;
use crate::problem::{RigidRow, Row};
use crate::readout::Accums;
use crate::solve::SolveScratch;
use crate::substep::SoftAccuracy;
use crate::taxels::{TactileImage, TactileSlot};
use crate::tip_contact::TipContact;
use crate::tip_record::TipRecord;

/// Memory of one contact between steps.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PairState {
    /// Friction anchor on the other body, in its collider's frame \[m\]: the static
    /// friction spring's stretch is the contact's tangential offset from it (`problem::spring`).
    pub anchor_local: Vector3<f64>,
    /// The friction spring's stretch (`SoftContacts::set_friction_spring`) at the last
    /// (sub)step's start, in the other collider's frame \[m\]: the relative tangential slip of
    /// the two bodies' material at the contact, summed over the steps in contact (zero when the
    /// contact starts). Each step adds the slip between the material points that touched at the
    /// last step's start (`anchor_local` on the other body, `tip_local` on the fingertip),
    /// measured on the poses; both are then re-set to the contact. Not the offset from a fixed
    /// anchor: a fingertip rolling over the other body moves the contact point over it without
    /// any slip, and that offset, taken as the stretch, tethered a rolling ball to where it
    /// first touched.
    pub stretch_local: Vector3<f64>,
    /// With the friction spring: the material point of the fingertip at the contact at the
    /// last (sub)step's start, in the fingertip collider's frame \[m\].
    pub tip_local: Vector3<f64>,
    /// The last substep in contact (`Scratch::stamp`).
    pub stamp: u64,
    /// The contact's impulses of its last (sub)step: the coupled solve's warm start.
    pub warm: Option<crate::problem::Warm>,
}

/// Buffers of one step, kept between steps so that a warm step allocates nothing (apart from
/// the dense LU of coupled contact groups).
#[derive(Debug, Clone, Default)]
pub(crate) struct Scratch {
    /// The solver's body table.
    pub body_table: BodyTable,
    /// The body table before the solve, restored for each further onset solve
    /// (`step::onset`).
    pub onset_base: Vec<crate::mobility::BodyState>,
    /// The contacts prepared for the solve.
    pub rows: Vec<Row>,
    /// rapier's touching rigid contacts of the bodies the soft contacts move (`rigid`).
    pub rigid: Vec<RigidRow>,
    /// The warm start of each rigid row the last coupled solve answered (`RigidRow::solved`),
    /// by [`RigidKey`](crate::problem::RigidKey): looked up, never iterated.
    pub rigid_warm: FastMap<crate::problem::RigidKey, [crate::problem::Warm; 2]>,
    /// The rigid rows of the last coupled solve that were rapier's soft rows
    /// (`RigidRow::softness`), by key: the switch's hysteresis (`Step::prepare_rigid`).
    pub rigid_soft: crate::fast_hash::FastSet<crate::problem::RigidKey>,
    /// The bodies to visit while gathering `rigid` (in order), the set of them, and the
    /// collider pairs already taken.
    pub rigid_visit: (
        Vec<RigidBodyHandle>,
        FastSet<RigidBodyHandle>,
        FastSet<(ColliderHandle, ColliderHandle)>,
    ),
    /// The law and coefficients of each row.
    pub models: Vec<Arc<Model>>,
    /// Index into `SoftContacts::geoms` of each row.
    pub geom: Vec<usize>,
    /// The solver's buffers.
    pub solve: SolveScratch,
    /// Normal mobility of each row [1/kg].
    pub mobility: Vec<f64>,
    /// Pairs in contact without a row this substep (no model, or non-finite).
    pub skipped: Vec<(ColliderHandle, ColliderHandle)>,
    /// Substep counter stamped on the pairs in contact (the others are forgotten).
    pub stamp: u64,
    /// Net impulse per body (linear, angular) of a substep.
    pub net: Vec<(Vector3<f64>, Vector3<f64>)>,
    /// Detection candidates of one fingertip, each with its AABB gap to it \[m\].
    pub candidates: Vec<(ColliderHandle, f32)>,
    /// Which fingertips the last detection looked at (the others' contacts are held).
    pub detected: crate::detect::Detected,
    /// The sleeping bodies a wake pass woke (`Step::wake_touched`).
    pub woken: Vec<RigidBodyHandle>,
    /// Per-contact sums over the substeps of a step.
    pub accums: Accums,
    /// What the soft impulses did to each dynamic body in the last step when it was not split
    /// (`step::split`); empty after a split step.
    pub unsplit_carry: Vec<UnsplitCarry>,
    /// `bodies::unsplit_carry`'s per-body sums (kept so that a step allocates nothing).
    pub carry_sums: crate::bodies::CarrySums,
    /// The multibody links' user forces while the plugin's force is on them for one pipeline
    /// step (`multibody::apply_to_rapier`).
    pub link_forces: Vec<crate::multibody::SavedForce>,
    /// The gravity lag of split steps: the lead-in's and give-back's share per body.
    pub split_lag: crate::bodies::SplitLag,
    /// The rigid supports' gathering read a pair of rapier's narrow phase this step (such a
    /// step is not replayed: `step::memo`).
    pub rigid_read: bool,
    /// The speed the joint motors add to each multibody link over the step, found at the
    /// step's first detection.
    pub motor_push: MotorPush,
}

/// The speed the joint motors add to each multibody link over a step
/// (`multibody::motor_push`), for the step's detections.
#[derive(Debug, Clone, Default)]
pub(crate) struct MotorPush {
    /// (linear [m/s], angular [rad/s]) by the link's rigid body.
    pub by_link: FastMap<RigidBodyHandle, (f32, f32)>,
    /// The largest of them (linear, angular).
    pub max: (f32, f32),
    /// The step they were found for \[s\] (a substep's detection scales them by its share).
    pub dt: f64,
}

/// The plugin's state: which colliders are soft, their contacts' memory and the readout.
#[derive(Debug, Clone)]
pub struct SoftContacts {
    // A fingertip's state is one `TipRecord` (`tips`); `tip_order` and `hook_view` are indexes
    // derived from the records at registration, for the two readers that cannot use the map:
    // the detection walks the fingertips in handle order, and rapier's hooks read which
    // colliders are soft while the rest of the state is written (`step`). A contact's memory
    // between steps is its `PairState` (`pairs`): the slot where a law with memory keeps its
    // variables.
    /// The registered fingertips.
    pub(crate) tips: FastMap<ColliderHandle, TipRecord>,
    /// The fingertips and their collision groups, in handle order (the detection's order).
    pub(crate) tip_order: Vec<(ColliderHandle, InteractionGroups)>,
    /// The fingertips' colliders, each with its facing in its collider's frame if it is backed
    /// (for the hooks and events passed to rapier: rapier's rigid contacts behind the flat
    /// face).
    pub(crate) hook_view: HookView,
    /// The multibody links' jacobians, for dropping rapier's contacts along directions they
    /// cannot move (`link_contacts`; refreshed each step).
    pub(crate) link_contacts: crate::link_contacts::LinkContacts,
    /// Pairs of bodies that never touch (`exclude_pair`).
    pub(crate) excluded: crate::excluded::ExcludedPairs,
    /// The first step has primed rapier's broad and narrow phases (`step`).
    pub(crate) started: bool,
    /// The step's parts are timed (`SoftCounters::step_time` ..; `set_profiling`).
    pub(crate) profiling: bool,
    /// Static friction as Mindlin's tangential spring (`set_friction_spring`).
    pub(crate) friction_spring: bool,
    pub(crate) pairs: FastMap<(ColliderHandle, ColliderHandle), PairState>,
    pub(crate) soft_pairs: FastMap<(ColliderHandle, ColliderHandle), Option<Arc<Model>>>,
    /// The models of contacts on curved counterparts and edges (`curved_models`).
    pub(crate) curved_models: CurvedModels,
    pub(crate) contacts: Vec<TipContact>,
    pub(crate) counters: SoftCounters,
    pub(crate) accuracy: SoftAccuracy,
    pub(crate) geoms: Vec<Geom>,
    /// Each contact's gap and normal velocity at the start of the last step
    /// (`step::split`'s approach check for links of jointed bodies).
    pub(crate) gaps: FastMap<(ColliderHandle, ColliderHandle), crate::step::GapMemory>,
    /// The step's buffers, boxed: a step takes them out and puts them back, which moved the
    /// whole struct twice and built and dropped a default one every step unboxed (`None` only
    /// while a step holds them, or after a step that panicked).
    pub(crate) scratch: Option<Box<Scratch>>,
    /// The error that faulted the plugin (`step`): a faulted plugin steps no more.
    pub(crate) fault: Option<crate::step_error::StepError>,
    /// Simulated time of the steps taken \[s\].
    pub(crate) time: f64,
    /// The largest registered fingertip radius \[m\] (the reach of an awake body towards a
    /// sleeping fingertip, `detect`).
    pub(crate) max_radius: f32,
    /// Whether any fingertip was registered with a tactile pad (`update_tactile` walks the
    /// fingertips only then).
    pub(crate) any_tactile: bool,
    /// The resting fast path's memo of the last step (`step::memo`).
    pub(crate) rest: crate::step::memo::RestMemo,
    /// The clearing of the empty awake island rapier 0.36.1 can leave behind
    /// (`step::stale_island`).
    pub(crate) stale_island: crate::step::stale_island::StaleIsland,
}

/// The fingertips' colliders as rapier's hooks see them: each with its facing in its
/// collider's frame if it is backed, `None` if it is soft all round.
pub(crate) type HookView = FastMap<ColliderHandle, Option<Vector3<f64>>>;

impl Default for SoftContacts {
    /// An empty plugin state with the default accuracy and the friction spring on
    /// (`set_friction_spring`, the default since session 19, issue 23).
    fn default() -> Self {
        Self {
            tips: Default::default(),
            tip_order: Default::default(),
            hook_view: Default::default(),
            link_contacts: Default::default(),
            excluded: Default::default(),
            started: false,
            profiling: false,
            friction_spring: true,
            pairs: Default::default(),
            soft_pairs: Default::default(),
            curved_models: Default::default(),
            contacts: Default::default(),
            counters: Default::default(),
            accuracy: Default::default(),
            geoms: Default::default(),
            gaps: Default::default(),
            scratch: Some(Box::default()),
            fault: None,
            time: 0.0,
            max_radius: 0.0,
            any_tactile: false,
            rest: Default::default(),
            stale_island: Default::default(),
        }
    }
}

impl SoftContacts {
    /// An empty plugin state with the default accuracy.
    pub fn new() -> Self {
        Self::default()
    }

    /// Keeps bodies `a` and `b` of `world` from touching each other: rapier computes no
    /// contact between their colliders (the plugin's hooks filter the pair) and the plugin no
    /// soft contact between a fingertip on one and the other. As MoveIt's allowed collision
    /// matrix does for a robot's links in collision at its default pose: a closed chain
    /// modelled as a tree, or links welded through a chain of fixed joints, whose shapes
    /// overlap at every pose and which rapier would push apart against their own joints.
    /// Turns rapier's `FILTER_CONTACT_PAIRS` hook on for the colliders attached to `a` and `b`
    /// now (attach their colliders first); the user's own `filter_contact_pair` is still asked
    /// about every other pair of a collider the user turned that hook on for, and about no
    /// pair of the others (rapier's default answer). Contacts the two bodies already have are
    /// cleared at the next step. rapier never recycles the contacts of a pair with an active
    /// hook, so every other pair of those colliders gets rapier's full contact update each step
    /// (crate README, Limits: on a gripper's finger that moved its grasp's hold force).
    ///
    /// # Errors
    /// [`Error::UnknownBody`] if `a` or `b` is not in `world`, [`Error::SamePair`] if they are
    /// the same body.
    pub fn exclude_pair(
        &mut self,
        world: &mut PhysicsWorld,
        a: RigidBodyHandle,
        b: RigidBodyHandle,
    ) -> Result<()> {
        self.excluded.insert(world, a, b)
    }

    /// Whether bodies `a` and `b` are kept from touching ([`exclude_pair`](Self::exclude_pair)).
    pub fn is_excluded(&self, a: RigidBodyHandle, b: RigidBodyHandle) -> bool {
        self.excluded.contains(a, b)
    }

    /// The pairs of bodies kept from touching ([`exclude_pair`](Self::exclude_pair)), each
    /// once, in no particular order.
    pub fn excluded_pairs(&self) -> Vec<(RigidBodyHandle, RigidBodyHandle)> {
        self.excluded.pairs().collect()
    }

    /// Marks `collider` of `world` as the soft fingertip `fingertip`.
    ///
    /// The collider must be a ball of the fingertip's radius (to 1e-5 relative).
    ///
    /// **rapier's narrow phase never sees a fingertip.** Its collision groups are moved into
    /// the plugin (the plugin's detection tests them, rapier's groups of the collider become
    /// `InteractionGroups::none()`), so rapier filters every pair of a fingertip before
    /// computing any contact: the plugin recomputes the geometry fresh every step and never
    /// reads rapier's manifolds. What a fingertip's collider loses in rapier: contact
    /// manifolds (`NarrowPhase::contact_pair`), collision and contact-force events, sensor
    /// intersections, and island links through its contacts (a body resting only on
    /// fingertips forms its own island for sleeping; the plugin wakes a sleeping side of a
    /// soft contact whose other side moves, crate README, Sleeping). Use [`contacts`](Self::contacts) for the
    /// soft contacts. Set the fingertip's collision groups *before* registering it; changing
    /// them on the collider afterwards has no effect on the soft contacts, and setting them
    /// back to anything but `none()` makes rapier compute (and ignore, the solver groups being
    /// `none()` too) the manifolds again. Also adds `KINEMATIC_FIXED | KINEMATIC_KINEMATIC`
    /// to its active collision types (a fingertip on a kinematic finger must still see fixed
    /// and kinematic objects). The user's hooks and events passed to [`step`](Self::step)
    /// never see a fingertip's pairs either.
    ///
    /// **A backed fingertip** ([`SoftFingertipBuilder::backing`](crate::SoftFingertipBuilder::backing))
    /// keeps its collision and solver groups, and gets the active hooks
    /// `FILTER_CONTACT_PAIRS | MODIFY_SOLVER_CONTACTS`: rapier's narrow phase computes its
    /// pairs, and the plugin's hooks keep only the solver contacts behind its flat face (the
    /// rigid finger's side), which rapier's solver then handles as any rigid contact; every
    /// solver contact on the pole side is dropped (the plugin's law handles that side). Its
    /// manifolds are therefore visible in `NarrowPhase::contact_pair`, but still no event of
    /// its pairs reaches the user's handler.
    pub fn register(
        &mut self,
        world: &mut PhysicsWorld,
        collider: ColliderHandle,
        fingertip: SoftFingertip,
    ) -> Result<()> {
        self.materialize_rest();
        self.rest.invalidate();
        let co = world
            .colliders
            .get_mut(collider)
            .ok_or(Error::UnknownCollider(collider))?;
        let Some(ball) = co.shape().as_ball() else {
            return Err(Error::NotABall {
                handle: collider,
                shape: format!("{:?}", co.shape().shape_type()),
            });
        };
        let r = ball.radius as f64;
        if !((r - fingertip.radius()).abs() <= 1e-5 * fingertip.radius()) {
            return Err(Error::RadiusMismatch {
                handle: collider,
                collider_radius: r,
                fingertip_radius: fingertip.radius(),
            });
        }
        let (groups, solver_groups) = match self.tips.get(&collider) {
            Some(old) => (old.groups, old.solver_groups),
            None => (co.collision_groups(), co.solver_groups()),
        };
        let facing = match fingertip.facing() {
            // A backed fingertip: rapier's narrow phase computes its pairs (its own groups),
            // and the hooks keep only the solver contacts behind its flat face (`hooks`).
            Some([x, y, z]) if !fingertip.backing().is_free() => {
                co.set_collision_groups(groups);
                co.set_solver_groups(solver_groups);
                co.set_active_hooks(
                    co.active_hooks()
                        | ActiveHooks::FILTER_CONTACT_PAIRS
                        | ActiveHooks::MODIFY_SOLVER_CONTACTS,
                );
                Some(Vector3::new(x, y, z))
            }
            _ => {
                co.set_collision_groups(InteractionGroups::none());
                co.set_solver_groups(InteractionGroups::none());
                None
            }
        };
        co.set_active_collision_types(
            co.active_collision_types()
                | ActiveCollisionTypes::KINEMATIC_FIXED
                | ActiveCollisionTypes::KINEMATIC_KINEMATIC,
        );
        // A pair's model holds the fingertips' own: rebuilt with the new one on first use.
        self.soft_pairs
            .retain(|(a, b), _| *a != collider && *b != collider);
        self.hook_view.insert(collider, facing);
        let record = TipRecord {
            model: fingertip.model().clone(),
            tactile: fingertip.tactile().map(|grid| TactileSlot::new(*grid)),
            fingertip,
            groups,
            solver_groups,
        };
        self.max_radius = self.max_radius.max(record.fingertip.radius() as f32);
        self.any_tactile |= record.tactile.is_some();
        self.tips.insert(collider, record);
        // In handle order, kept sorted by insertion (not rebuilt: N registrations were
        // quadratic).
        match self
            .tip_order
            .binary_search_by_key(&raw(collider), |(h, _)| raw(*h))
        {
            Ok(i) => self.tip_order[i] = (collider, groups),
            Err(i) => self.tip_order.insert(i, (collider, groups)),
        }
        Ok(())
    }

    /// Whether `collider` is a registered fingertip.
    pub fn is_soft(&self, collider: ColliderHandle) -> bool {
        self.tips.contains_key(&collider)
    }

    /// The fingertip registered on `collider`.
    pub fn fingertip(&self, collider: ColliderHandle) -> Option<&SoftFingertip> {
        self.tips.get(&collider).map(|t| &t.fingertip)
    }

    /// The soft contacts of the last step.
    pub fn contacts(&self) -> &[TipContact] {
        self.live_contacts()
    }

    /// The readout of the last step: its own, or that of the step it replayed
    /// (`step::memo`, kept there until the next full step).
    fn live_contacts(&self) -> &[TipContact] {
        self.rest.live_contacts().unwrap_or(&self.contacts)
    }

    /// Moves the plugin's state a replayed step ended with (`step::memo`) into its own fields:
    /// before anything reads or changes them but the readout's accessors.
    pub(crate) fn materialize_rest(&mut self) {
        if let Some(end) = self.rest.take_live() {
            self.pairs.clone_from(&end.pairs);
            self.contacts.clone_from(&end.contacts);
            self.geoms.clone_from(&end.geoms);
            let scratch = self.scratch.get_or_insert_with(Box::default);
            scratch.unsplit_carry.clone_from(&end.unsplit_carry);
            scratch.stamp = end.stamp;
        }
    }

    /// The contacts of one fingertip in the last step.
    pub fn contacts_of(&self, fingertip: ColliderHandle) -> impl Iterator<Item = &TipContact> {
        self.live_contacts()
            .iter()
            .filter(move |c| c.fingertip == fingertip)
    }

    /// Diagnostics counters.
    pub fn counters(&self) -> &SoftCounters {
        &self.counters
    }

    /// The accuracy setting (phase per substep).
    pub fn accuracy(&self) -> SoftAccuracy {
        self.accuracy
    }

    /// Sets the accuracy (phase per substep).
    pub fn set_accuracy(&mut self, accuracy: SoftAccuracy) {
        self.accuracy = accuracy;
        self.materialize_rest();
        self.rest.invalidate();
    }

    /// Turns the resting fast path on or off (default on; crate README, "Resting steps
    /// replayed"): a step whose inputs (rapier's bodies and colliders, the integration
    /// parameters, gravity, the plugin's fingertips, settings and contact memory) are
    /// bit-identical to the last step's, when that step was unsplit and had no kinematic body,
    /// joint or rigid support, applies that step's velocity changes again instead of
    /// recomputing them, then runs rapier's pipeline. The physics is bit for bit the same
    /// either way (`tests/rest_replay.rs`); counted in
    /// [`SoftCounters::replayed_steps`](crate::SoftCounters::replayed_steps).
    pub fn set_rest_replay(&mut self, on: bool) {
        self.materialize_rest();
        self.rest.enabled = on;
        self.rest.invalidate();
    }

    /// Whether the resting fast path is on ([`set_rest_replay`](Self::set_rest_replay)).
    pub fn rest_replay(&self) -> bool {
        self.rest.enabled
    }

    /// Turns the timing of a step's parts on or off (default off): with it on, each step adds
    /// its parts' wall time to [`SoftCounters`]' `step_time`, `rows_time`, `supports_time`,
    /// `law_time`, `soft_solve_time`, `apply_time` and `readout_time` (a dozen clock reads per
    /// substep, 1.7 % of a sweep trial's CPU; crate README, "Session 15, where a grasp step's
    /// time goes"). The physics is the same either way. `detect_time`, `solve_time` and
    /// `pipeline_time` are always timed.
    pub fn set_profiling(&mut self, on: bool) {
        self.profiling = on;
    }

    /// Static friction as Mindlin's tangential spring (on by default; crate README, "Session
    /// 16, friction as a tangential spring"): each contact's tangential slip, summed over its
    /// steps in contact (the separation of the two bodies' material points that touched at
    /// the last step's start, measured on the poses), is the stretch of a spring of stiffness
    /// `k_t = 8 G* a` \[N/m\] (`G*` the pair's effective shear modulus, `a` the law's contact
    /// radius), solved implicitly like the normal and capped by the Coulomb disk, instead of a
    /// hard stick with a positional correction of 0.3 of the offset per step. It cuts the
    /// coupled solve's passes (the default grasp, with the warm start it allows: 31.6 to 4.9
    /// a solve) and gives the fingertip's elastic shear (a held box sags by its share of the
    /// weight over `k_t`). With it, rapier's part of the rigid supports' normal impulses is
    /// split per pair of bodies instead of per point (the box pressed against a wall by a free
    /// tip settles with it since session 18), and the coupled solve starts warm where no body
    /// of the group is a jointed link. `false`: the rigid stick, cold-started (the default
    /// before session 20; since session 19's tighter `solve_group` stop not bit-identical to
    /// before).
    pub fn set_friction_spring(&mut self, on: bool) {
        self.friction_spring = on;
        self.materialize_rest();
        self.rest.invalidate();
    }

    /// Whether static friction is a tangential spring
    /// ([`set_friction_spring`](Self::set_friction_spring)).
    pub fn friction_spring(&self) -> bool {
        self.friction_spring
    }

    /// Whether the step's parts are timed ([`set_profiling`](Self::set_profiling)).
    pub fn profiling(&self) -> bool {
        self.profiling
    }

    /// The tactile image of the fingertip `collider` after the last step (`None` unless the
    /// fingertip was built with a pad, [`SoftFingertipBuilder::tactile`]). Computed on the
    /// first read after a step.
    ///
    /// [`SoftFingertipBuilder::tactile`]: crate::SoftFingertipBuilder::tactile
    pub fn tactile_image(&self, collider: ColliderHandle) -> Option<&TactileImage> {
        let slot = self.tips.get(&collider)?.tactile.as_ref()?;
        Some(slot.image(collider, self.live_contacts()))
    }

    /// Every tactile image, in the fingertips' handle order (each computed on its first read
    /// after a step).
    pub fn tactile_images(&self) -> impl Iterator<Item = (ColliderHandle, &TactileImage)> {
        self.tip_order.iter().filter_map(|(h, _)| {
            let slot = self.tips.get(h)?.tactile.as_ref()?;
            Some((*h, slot.image(*h, self.live_contacts())))
        })
    }

    /// Marks the images stale after a step (from the readout; read-only for the physics):
    /// keeps each fingertip's orientation for the deferred image.
    pub(crate) fn update_tactile(&mut self, colliders: &ColliderSet) {
        if !self.any_tactile {
            return;
        }
        for (handle, tip) in &mut self.tips {
            if let Some(slot) = &mut tip.tactile {
                slot.refresh(colliders.get(*handle).map(|c| {
                    let q = c.position().rotation;
                    [q.x as f64, q.y as f64, q.z as f64, q.w as f64]
                }));
            }
        }
    }

    /// The contact model of a geometry (the fingertip's, or the combined one of two).
    pub(crate) fn model(&mut self, g: &Geom) -> Option<Arc<Model>> {
        if g.soft_pair {
            let (a, b) = (self.tips.get(&g.tip)?, self.tips.get(&g.other)?);
            self.soft_pairs
                .entry((g.tip, g.other))
                .or_insert_with(|| {
                    let (ma, mb) = (a.model.clone(), b.model.clone());
                    Model::of_pair(&a.fingertip, &b.fingertip, ma, mb).map(Arc::new)
                })
                .clone()
        } else {
            let base = &self.tips.get(&g.tip)?.model;
            if g.touch.counterpart.is_plane() {
                return Some(base.clone());
            }
            let pairs = &self.pairs;
            Some(self.curved_models.model(
                (g.tip, g.other),
                base,
                &g.touch,
                &mut self.counters,
                |k| pairs.contains_key(k),
            ))
        }
    }
}
