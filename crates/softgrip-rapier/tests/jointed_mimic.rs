//! A fingertip on each of two multibody jaws coupled by a mimic, squeezing a box on a table
//! (issue 23, item 4), and a multibody's kinematic root moved to its target with a fingertip
//! on its link: the multibody cases of the `jointed` scenes (`jointed_scene`).
//!
//! `cargo test -p softgrip-rapier --test jointed_mimic -- --nocapture` prints the numbers.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod jointed_scene;

use jointed_scene::*;
use rapier3d::prelude::*;
use softgrip_rapier::SoftWorld;

/// A parallel jaw as one multibody: two prismatic fingers along x on a fixed base, the right one
/// coupled to the left by a mimic (`q_right = -q_left`, a dof coupling), only the left motored
/// (2e4 N/m); a fingertip on each finger squeezes the box on the table from its sides. The two
/// pads are rows on two links of one multibody (coupled through its mobility and the coupling).
/// At rest each pad reads the law at its geometric compression, both the same force, and the
/// left motor holds `J^T F` of both pads through the coupling (`2 F`).
///
/// At the suite's 2 PGS iterations with the jaws' links given the sweeps the plugin says rapier
/// needs over their motor and coupling rows (`SoftWorld::multibody_sweeps_needed`: 17, the
/// largest over the step and its substeps; the links get 15 more with
/// `RigidBody::set_additional_pgs_iterations`, the rest of the world keeps its 2, as the scene
/// layer does for a robot with a mimic joint): the hold settles as at 64 sweeps
/// ([`multibody_mimic_jaws_settle_with_converged_pgs`]). Measured (session 29, `--nocapture`):
/// 5.4839 / 5.4831 N, pads differ 1.37e-4, motor vs `J^T F` 2.15e-4, at most 4 substeps in the
/// hold, the coupling 5.8e-11 m off, the box at 1.24e-7 m/s and 0.064 um of drift, 1.27e-2 off
/// the law at the geometry's compression (the converged hold's 1.18e-2: see there).
///
/// Why the sweeps (session 10): rapier solves the motor (a compliant row on the left dof) and
/// the coupling (a hard row) by Gauss-Seidel in its sweeps, from a zero impulse, while the
/// plugin's mobility folds both in exactly (`multibody::couple`, a Schur complement: the
/// converged answer). At 2 sweeps (the links not raised) the right pad's force reaches the
/// left motor only partly, so an unsplit step with 5.6 N on the pads throws both fingers 36 mm
/// open where the plugin predicts 0.3 mm; the motor brings them back, the next contact is split
/// (~460 substeps, 2.1 / 2.4 N), and the cycle repeats every 4 steps; the box creeps along z.
/// At 8 sweeps the cycle is 2 steps (5.48 N unsplit, 3.8 N split, motor 19.4 N against `J^T F`
/// 11.0 N). `multibody_sweeps_needed` reads the rate of those sweeps (`joint_sweeps`, as for
/// impulse joints) and asks for `rate^sweeps <= 1e-5`.
#[test]
fn multibody_mimic_jaws_squeeze_a_box_with_the_sweeps_they_need() {
    let m = mimic_jaws_with(PGS, false, false, None, true);
    assert_eq!(m.needed, Some(17), "the sweeps the jaws need");
    assert_mimic_hold(&m, 1e-3);
}

/// The mimic-coupled jaws of [`multibody_mimic_jaws_squeeze_a_box_with_the_sweeps_they_need`] with rapier's PGS run to
/// convergence (64 sweeps), where the plugin's exact fold of the motor and the coupling is
/// what rapier does: the hold's steps split only for the motor's push (5 substeps), the two
/// pads equal (1.30e-4 since rapier's soft table rows, session 21; 6.8e-5 before them, 4.5e-4
/// before session 20's split-step gravity share), the motor's effort `J^T F` of both pads
/// through the coupling (4.8e-6), both fingers where the coupling puts them (1.2e-10 m), the
/// box still.
#[test]
fn multibody_mimic_jaws_settle_with_converged_pgs() {
    let m = mimic_jaws(64);
    assert!(m.forces[0] > 5.0 && m.forces[0] < 6.0, "{:?}", m.forces);
    // The motor's push on the held pads (2e4 N/m at 5.6 N: a free run of 1.3 compressions per
    // step) splits the hold into the substeps that keep it within a quarter of the compression
    // (`step::split::DRIVE_RUN_FRACTION`), not into an impact's hundreds.
    assert!(
        (2..=8).contains(&m.max_substeps_hold),
        "the hold's steps: {} substeps",
        m.max_substeps_hold
    );
    // The pads 1.30e-4 apart (6.8e-5 before rapier's soft table rows, session 21; 4.5e-4
    // before session 20; 3.1e-5 when every hold step was one unsplit step). NOT the 1e-4 the
    // stiff table's test holds.
    assert!(m.balance < 1e-3, "pads differ {}", m.balance);
    assert!(m.effort_error < 1e-4, "motor vs J^T F {}", m.effort_error);
    assert!(
        m.mimic_error < 1e-8,
        "the coupling is {} m off",
        m.mimic_error
    );
    // Issue 23 item 4's bound: still, < 1 um/s, no drift (< 1 um) over the last 40 steps.
    // Measured (session 21): 8.99e-8 m/s from the poses, 0.048 um from the pose at step 200,
    // since the coupled solve takes rapier's table as rapier's soft contact and gives the box
    // the plugin's impulses over rapier's passes (`rigid`, rapier's soft rows); 1.37e-3 m/s,
    // 19.2 um with the table as hard rows.
    assert!(m.speed_hold < 1e-6, "speed {} m/s", m.speed_hold);
    assert!(m.drift_hold < 1e-6, "drift {} m", m.drift_hold);
    // Bounded at what it does: 1.8e-3 off the law at the geometry's compression (2.96e-2,
    // then 2.2e-2, before session 20), not yet understood (the single prismatic jaw is 1.5e-5 off; the contact's own compression is
    // the law's, the box's pose against the pads' centres is not).
    assert!(m.worst < 0.04, "{}", m.worst);
}

/// Issue 23 item 4 ("nothing rattles, nothing drifts"): why the box squeezed by the mimic jaws
/// of [`multibody_mimic_jaws_settle_with_converged_pgs`] moved 13-16 um from step to step
/// before rapier's soft table rows (session 21; the rest of this comment is that finding). Not the plugin's rows alone, not the split step's gravity (session 20), not a
/// period-2 ringing (the heights wander: -11.5..-22.7 um below the box's rest): rapier's own
/// table contact is a spring (`static_contact_softness`, 60 Hz with damping ratio 10: the box
/// alone rests 69 um deep in it) that rapier solves pass by pass, while the plugin's coupled
/// solve takes the table as hard rows and applies the pads' share of the box's weight (70-90 %)
/// as one impulse before rapier's passes: in the first passes the box rises before the table
/// lets go of it, the stick's (or the spring's) next correction pulls it back, and the two
/// position references (the pads' anchors, the table's soft contact) hand the box between them
/// (per-substep trace, session 21: rapier's table impulse 8.6e-5..1.6e-4 N s a substep against
/// the weight's 1.3e-4, the pads' vertical impulse -6e-5..+4.4e-5 N s). With the table's
/// contact stiff (1000 Hz) the same jaws, box and plugin hold the box still with either
/// friction: this test. With rapier's default table the box moved up to 14.8 um a step with
/// the rigid stick (`SPRING_DEFAULT_STATUS.md`, 20), and is still since the table's rows are
/// rapier's soft contact (21).
// Measured (`-- --nocapture`, session 21, with rapier's soft rows; spring / rigid stick): speed
// from the poses 4.1e-8 / 5.4e-8 m/s, drift over the last 40 steps 0.024 / 0.033 um, height
// step to step < 1 nm, pads differ 8.0e-6 / 5.8e-6 (the default table, rigid stick: 1.30e-4).
#[test]
fn mimic_jaws_hold_the_box_still_on_a_stiff_table() {
    for spring in [true, false] {
        let m = mimic_jaws_with(64, spring, false, Some(1000.0), false);
        let name = if spring {
            "friction spring"
        } else {
            "rigid stick"
        };
        assert!(
            m.forces[0] > 5.0 && m.forces[0] < 6.0,
            "{name}: {:?}",
            m.forces
        );
        // Issue 23 item 4's bound: still, < 1 um/s, and no drift (< 1 um) over the last 40
        // steps.
        assert!(m.speed_hold < 1e-6, "{name}: speed {} m/s", m.speed_hold);
        assert!(m.drift_hold < 1e-6, "{name}: drift {} m", m.drift_hold);
        assert!(m.balance < 1e-4, "{name}: pads differ {}", m.balance);
        assert!(
            m.effort_error < 1e-4,
            "{name}: motor vs J^T F {}",
            m.effort_error
        );
        assert!(m.mimic_error < 1e-8, "{name}: coupling {} m", m.mimic_error);
    }
}

/// Issue 23 ("nothing rattles, nothing drifts"): a box resting on rapier's table, pressed 1 mm
/// from above by a fingertip, in a world whose every step is split (the mimic jaws' motor, 4
/// or 5 substeps) leaves each step at rest. A split step kicks every body by gravity's lead-in
/// `g (dt - h) / (2N)` before its substeps and takes it back after them (`step.rs`, note 1);
/// the table takes the lead-in from a resting box, so taking it back left the box moving up
/// at 0.01635 / 0.01533 m/s (5 / 4 substeps at 60 Hz, N = 4) at every step's end, and the
/// give-back of 5 substeps against the next lead-in of 4 moved it 0.1 um. The lead-in and
/// the give-back are now gravity's times the share of gravity the body still feels in rapier's
/// passes (`bodies::SplitLag`): 0 for this box.
// Measured (`-- --nocapture`): stored |v_y| <= 1.1e-8 m/s, the height bit-equal step to step
// over the last 40 steps (before: 0.01635 m/s, 0.105 um).
#[test]
fn a_pressed_box_on_the_table_leaves_split_steps_at_rest() {
    let m = mimic_jaws_with(64, false, true, None, false);
    let (vy, rattle, lead_in) = m.pressed.unwrap();
    println!(
        "pressed box: stored |v_y| <= {vy:.2e} m/s (lead-in {lead_in:.5} m/s), height step to \
         step <= {:.2e} um",
        rattle * 1e6
    );
    assert!(m.max_substeps_hold > 1, "the hold is split");
    assert!(
        vy < 1e-3 * lead_in,
        "stored v_y {vy} m/s, lead-in {lead_in} m/s"
    );
    assert!(rattle < 1e-8, "the box's height moved {rattle} m in a step");
}

/// What [`mimic_jaws`] measured after its 240 steps.
struct Mimic {
    forces: Vec<f64>,
    /// The worst `|F / F_law(delta_geometry) - 1|` of the two pads.
    worst: f64,
    /// `|F_left / F_right - 1|`.
    balance: f64,
    /// The left motor's effort against `J^T F` of both pads.
    effort_error: f64,
    /// The largest substep count over the last 60 steps.
    max_substeps_hold: u32,
    /// `|q_right + q_left|` \[m\].
    mimic_error: f64,
    /// The squeezed box's largest speed over the last 40 steps, from its poses (translation
    /// plus rotation at its corners, per step) \[m/s\].
    speed_hold: f64,
    /// The squeezed box's largest displacement over the last 40 steps from its pose at their
    /// start (translation plus rotation at its corners) \[m\].
    drift_hold: f64,
    /// With a pressed box ([`mimic_jaws_with`]): its largest `|v_y|` at a step's end over the
    /// last 40 steps \[m/s\], its largest change of height from one step to the next over them
    /// \[m\], and the least split step's gravity lead-in `g (dt - h) / (2N)` \[m/s\].
    pressed: Option<(f64, f64, f64)>,
    /// With `raise` ([`mimic_jaws_with`]): the sweeps per solver pass the jaws' links were
    /// given (`SoftWorld::multibody_sweeps_needed`).
    needed: Option<usize>,
}

/// The mimic-coupled jaws squeezing the box for 240 steps at `pgs` PGS iterations.
fn mimic_jaws(pgs: usize) -> Mimic {
    mimic_jaws_with(pgs, false, false, None, false)
}

/// [`mimic_jaws`] with the friction as Mindlin's tangential spring (`spring`) or the rigid
/// stick; with `press`, a second box on the table 10 cm away, pressed 1 mm from above by a
/// fingertip on a kinematic body (lowered over the first 60 steps, then held): the jaws' motor
/// splits every step of the world, the pressed box's too. `table_hz`: rapier's contacts with
/// a fixed body (the table) at that natural frequency \[Hz\]
/// (`IntegrationParameters::static_contact_softness`; rapier's default 60 Hz, damping ratio
/// 10). With `raise`, the jaws' links get the sweeps `SoftWorld::multibody_sweeps_needed` asks
/// for (the largest over the step and its substeps `dt / 2^k`, k <= 6).
fn mimic_jaws_with(
    pgs: usize,
    spring: bool,
    press: bool,
    table_hz: Option<f32>,
    raise: bool,
) -> Mimic {
    let (mut world, box_body, box_col) = table_and_box(pgs, 0.0);
    world.soft.set_friction_spring(spring);
    if let Some(hz) = table_hz {
        world
            .physics
            .integration_parameters
            .static_contact_softness
            .natural_frequency = hz;
    }
    let pressed = press.then(|| {
        let b = world.physics.bodies.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.1, HALF, 0.0))
                .can_sleep(false),
        );
        world.physics.colliders.insert_with_parent(
            ColliderBuilder::cuboid(HALF, HALF, HALF).density(500.0),
            b,
            &mut world.physics.bodies,
        );
        let top = 2.0 * HALF + R as f32;
        let tip_body = world.physics.bodies.insert(
            RigidBodyBuilder::kinematic_position_based().translation(Vector::new(
                0.1,
                top + 0.0005,
                0.0,
            )),
        );
        soft_tip(&mut world, tip_body, Vector::ZERO);
        (b, tip_body, top)
    });
    let (mut pressed_vy, mut pressed_rattle, mut lead_in) = (0.0f64, 0.0f64, f64::INFINITY);
    let mut pressed_prev = 0.0f64;
    let dt = world.physics.integration_parameters.dt as f64;
    let passes = world.physics.integration_parameters.num_solver_iterations as f64;
    let y = HALF;
    let base = world
        .physics
        .bodies
        .insert(RigidBodyBuilder::fixed().translation(Vector::new(0.0, y + 0.05, 0.0)));
    let open = HALF + R as f32 + GAP;
    let mut fingers = Vec::new();
    let mut tips = Vec::new();
    let mut laws = Vec::new();
    for side in [-1.0f32, 1.0] {
        let body = light_link(
            &mut world,
            Vector::new(side * open, y, 0.0),
            (0.0, DENSITY),
            Vector::new(0.003, 0.02, 0.004),
            Vector::new(side * 0.012, 0.02, 0.0),
        );
        let anchor = Vector::new(side * open, -0.05, 0.0);
        let data: GenericJoint = if side < 0.0 {
            motored_joint(JointKind::Prismatic, Vector::X, anchor, 0.0015)
        } else {
            PrismaticJointBuilder::new(Vector::X)
                .local_anchor1(anchor)
                .local_anchor2(Vector::ZERO)
                .build()
                .into()
        };
        world
            .physics
            .multibody_joints
            .insert(base, body, data, true)
            .unwrap();
        let (tip, law) = soft_tip(&mut world, body, Vector::ZERO);
        laws.push(law);
        fingers.push(body);
        tips.push(tip);
    }
    let links = fingers.map_links(&world);
    {
        let mb = world
            .physics
            .multibody_joints
            .get_multibody_mut(links[0].multibody)
            .unwrap();
        mb.add_dof_coupling(MultibodyDofCoupling {
            link1: links[0].id,
            dof1: 0,
            axis1: 0,
            link2: links[1].id,
            dof2: 0,
            axis2: 0,
            coeff: -1.0,
            offset: 0.0,
        });
    }
    // The sweeps rapier needs over the jaws' motor and coupling rows, at the step and its
    // substeps (as the scene layer asks them for a robot), given to the jaws' links only.
    let needed = raise.then(|| {
        let need = (0..=6)
            .filter_map(|k| world.multibody_sweeps_needed(fingers[0], dt / f64::from(1u32 << k)))
            .max()
            .expect("the jaws' sweeps converge");
        for &b in &fingers {
            world.physics.bodies[b].set_additional_pgs_iterations(need.saturating_sub(pgs));
        }
        need
    });
    let law = &laws[0];
    let mut max_substeps_hold = 0;
    // The squeezed box's largest stored |v_y| at a step's end [m/s] and change of height from
    // one step to the next [m] over the last 40 steps (printed).
    let (mut box_vy, mut box_rattle) = (0.0f64, 0.0f64);
    let mut y_prev = 0.0f64;
    // The squeezed box's largest speed from its poses (translation plus rotation at its
    // corners, per step) and its largest displacement from its pose at step 200, over the
    // last 40 steps [m/s, m].
    let (mut speed_hold, mut drift_hold) = (0.0f64, 0.0f64);
    let mut pose_prev = *world.physics.bodies[box_body].position();
    let mut pose_200 = pose_prev;
    for i in 0..240 {
        if let Some((_, tip_body, top)) = pressed {
            let y = top + 0.0005 - 0.0015 * ((i + 1) as f32 / 60.0).min(1.0);
            world.physics.bodies[tip_body].set_next_kinematic_translation(Vector::new(0.1, y, 0.0));
        }
        world.step();
        let n = world.soft.counters().substeps_last;
        if let Some((b, _, _)) = pressed {
            let rb = &world.physics.bodies[b];
            let y = rb.translation().y as f64;
            if i >= 200 {
                pressed_vy = pressed_vy.max((rb.linvel().y as f64).abs());
                pressed_rattle = pressed_rattle.max((y - pressed_prev).abs());
                if n > 1 {
                    lead_in = lead_in.min(9.81 * (dt - dt / n as f64) / (2.0 * passes));
                }
            }
            pressed_prev = y;
        }
        if i >= 180 {
            max_substeps_hold = max_substeps_hold.max(world.soft.counters().substeps_last);
        }
        let rb = &world.physics.bodies[box_body];
        let y = rb.translation().y as f64;
        if i >= 200 {
            box_vy = box_vy.max((rb.linvel().y as f64).abs());
            box_rattle = box_rattle.max((y - y_prev).abs());
        }
        y_prev = y;
        let pose = *rb.position();
        let moved = |from: &Pose| {
            (pose.translation - from.translation).length() as f64
                + HALF as f64
                    * (pose.rotation * from.rotation.inverse())
                        .to_axis_angle()
                        .1
                        .abs() as f64
        };
        if i == 200 {
            pose_200 = pose;
        }
        if i > 200 {
            speed_hold = speed_hold.max(moved(&pose_prev) / dt);
            drift_hold = drift_hold.max(moved(&pose_200));
        }
        pose_prev = pose;
    }
    let p = &world.physics;
    let rb = &p.bodies[box_body];
    let mut forces = Vec::new();
    let mut worst = 0.0f64;
    let mut generalised = 0.0;
    for (k, tip) in tips.iter().enumerate() {
        let c = world
            .soft
            .contacts()
            .iter()
            .find(|c| c.fingertip == *tip && c.other == box_col)
            .expect("each pad touches the box");
        let centre = p.colliders[*tip].translation();
        let side = if k == 0 { -1.0 } else { 1.0 };
        let face = rb
            .position()
            .transform_point(Vector::new(side * HALF, 0.0, 0.0))
            .x;
        let delta = R - (side * (centre.x - face)) as f64;
        worst = worst.max((c.normal_force / law.response(delta).force - 1.0).abs());
        forces.push(c.normal_force);
        let (f, _) = c.wrench_about([0.0; 3]);
        // d q_k / d q_left: 1 for the left finger, the coupling's -1 for the right.
        generalised += f[0] * if k == 0 { 1.0 } else { -1.0 };
    }
    let mb = p
        .multibody_joints
        .get_multibody(links[0].multibody)
        .unwrap();
    let left = mb.link(links[0].id).unwrap();
    let (q, v) = (
        left.joint().coords()[0] as f64,
        mb.joint_velocity(left)[0] as f64,
    );
    let effort = K_PRI as f64 * (0.0015 - q) - C_PRI as f64 * v;
    let effort_error = (effort / -generalised - 1.0).abs();
    let balance = (forces[0] / forces[1] - 1.0).abs();
    let right = mb.link(links[1].id).unwrap();
    let mimic_error = (right.joint().coords()[0] as f64 + q).abs();
    println!(
        "mimic jaws at {pgs} PGS iterations (links raised to {needed:?}): forces {forces:?} N, worst |F/F_law - 1| \
         {worst:.2e}, pads differ {balance:.2e}, motor {effort:.4} N vs J^T F {:.4} N \
         ({effort_error:.2e}), substeps in the hold <= {max_substeps_hold}, coupling off by \
         {mimic_error:.2e} m; box's stored |v_y| <= {box_vy:.2e} m/s, height step to step \
         <= {:.3} um, speed from the poses <= {speed_hold:.3e} m/s, drift from step 200 <= \
         {:.3} um",
        -generalised,
        box_rattle * 1e6,
        drift_hold * 1e6
    );
    Mimic {
        forces,
        worst,
        balance,
        effort_error,
        max_substeps_hold,
        mimic_error,
        speed_hold,
        drift_hold,
        pressed: pressed.map(|_| (pressed_vy, pressed_rattle, lead_in)),
        needed,
    }
}

/// The multibody link ids of bodies.
trait MapLinks {
    fn map_links(&self, world: &SoftWorld) -> Vec<MultibodyLinkId>;
}

impl MapLinks for Vec<RigidBodyHandle> {
    fn map_links(&self, world: &SoftWorld) -> Vec<MultibodyLinkId> {
        self.iter()
            .map(|b| *world.physics.multibody_joints.rigid_body_link(*b).unwrap())
            .collect()
    }
}

/// A multibody's kinematic root moved with `set_next_kinematic_translation` (a robot's base
/// lifted) carries its links: rapier 0.36.1 alone overwrites the target at the start of its
/// step and the base stays put; through the plugin the base ends each step at its target and
/// its motored prismatic link rides along at its joint position (a fingertip on the link,
/// in the air). Then rotated with `set_next_kinematic_position`: the link turns with it.
#[test]
fn kinematic_multibody_root_moves_to_its_target() {
    let mut world = SoftWorld::new();
    let base = world.physics.bodies.insert(
        RigidBodyBuilder::kinematic_position_based().translation(Vector::new(0.0, 0.1, 0.0)),
    );
    let link = light_link(
        &mut world,
        Vector::new(0.03, 0.1, 0.0),
        (0.0, DENSITY),
        Vector::new(0.003, 0.02, 0.004),
        Vector::ZERO,
    );
    let data = motored_joint(
        JointKind::Prismatic,
        Vector::X,
        Vector::new(0.03, 0.0, 0.0),
        0.0,
    );
    world
        .physics
        .multibody_joints
        .insert(base, link, data, true)
        .unwrap();
    soft_tip(&mut world, link, Vector::ZERO);
    let dt = world.physics.integration_parameters.dt;
    let mut worst = 0.0f32;
    for k in 1..=30 {
        let y = 0.1 + 0.1 * dt * k as f32;
        world.physics.bodies[base].set_next_kinematic_translation(Vector::new(0.0, y, 0.0));
        world.step();
        let (b, l) = (
            world.physics.bodies[base].translation(),
            world.physics.bodies[link].translation(),
        );
        worst = worst
            .max((b.y - y).abs())
            .max((l.y - y).abs())
            .max((l.x - 0.03).abs());
    }
    println!("kinematic root lifted 5 cm: base and link off their targets by at most {worst:e} m");
    assert!(worst < 1e-6, "{worst}");
    // A quarter turn about y over 30 steps: the link (3 cm along x) ends at -z.
    let top = *world.physics.bodies[base].position();
    for k in 1..=30 {
        let angle = std::f32::consts::FRAC_PI_2 * k as f32 / 30.0;
        let pose = Pose::from_parts(top.translation, Rotation::from_rotation_y(angle));
        world.physics.bodies[base].set_next_kinematic_position(pose);
        world.step();
    }
    let l = world.physics.bodies[link].translation();
    println!("after a quarter turn the link is at {l:?}");
    assert!(
        (l.x).abs() < 1e-5 && (l.z + 0.03).abs() < 1e-5 && (l.y - top.translation.y).abs() < 1e-6,
        "{l:?}"
    );
}

/// [`multibody_mimic_jaws_settle_with_converged_pgs`] with the friction spring (the default
/// since session 19) on rapier's default table: issue 23 item 4's bounds hold with it too
/// since rapier's soft rows (`rigid`; before them the pads differed 5.6e-3 and the box moved
/// 16.4 um a step, `SPRING_DEFAULT_STATUS.md`, 20).
// Measured (`-- --nocapture`, session 22): forces 5.4851 / 5.4836 N, pads 2.84e-4 apart, motor
// vs `J^T F` 1.1e-6, substeps in the hold <= 5, coupling 1.8e-10 m, speed from the poses
// 1.59e-7 m/s, drift over the last 40 steps 0.091 um, worst 1.69e-2 off the law.
#[test]
fn friction_spring_mimic_jaws_hold_the_box_still_on_the_default_table() {
    let m = mimic_jaws_with(64, true, false, None, false);
    println!(
        "friction spring, default table: forces {:?} N, worst {:.2e}, pads differ {:.2e}, \
         motor vs J^T F {:.2e}, substeps <= {}, coupling {:.2e} m, speed {:.3e} m/s, drift \
         {:.3e} m",
        m.forces,
        m.worst,
        m.balance,
        m.effort_error,
        m.max_substeps_hold,
        m.mimic_error,
        m.speed_hold,
        m.drift_hold
    );
    assert_mimic_hold(&m, 1e-4);
}

/// What both mimic-jaw holds assert: the pads' force, the hold's substeps, the two pads alike,
/// the motor against `J^T F` within `effort` (relative), the coupling kept, the box still (issue
/// 23 item 4: < 1 um/s, no drift over 1 um in the last 40 steps) and the worst step as the
/// converged hold's (1.18e-2; bounded at 0.04, not yet understood).
fn assert_mimic_hold(m: &Mimic, effort: f64) {
    assert!(m.forces[0] > 5.0 && m.forces[0] < 6.0, "{:?}", m.forces);
    assert!(
        (2..=8).contains(&m.max_substeps_hold),
        "the hold's steps: {} substeps",
        m.max_substeps_hold
    );
    assert!(m.balance < 1e-3, "pads differ {}", m.balance);
    assert!(m.effort_error < effort, "motor vs J^T F {}", m.effort_error);
    assert!(m.mimic_error < 1e-8, "coupling {} m", m.mimic_error);
    assert!(m.speed_hold < 1e-6, "speed {} m/s", m.speed_hold);
    assert!(m.drift_hold < 1e-6, "drift {} m", m.drift_hold);
    assert!(m.worst < 0.04, "{}", m.worst);
}
