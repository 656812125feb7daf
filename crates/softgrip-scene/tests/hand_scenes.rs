//! The shipped hands' scenes (issue 25, item 6): each hand (`robots/parallel_gripper`,
//! `robots/three_finger_hand`) grasps a box, a ball and a cylinder
//! (`scenes/robots/<hand>_<object>.toml`). Each run reaches its grasp force on every pad,
//! lifts the object with the hand and holds it: the object's motion relative to the hand's
//! base over the hold (slip) is below issue 25's 100 um, and after the hold's first step
//! (creep) below 1 um. `cargo test -p softgrip-scene --test hand_scenes -- --nocapture`
//! prints each run's numbers (the table in SCENES.md).

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use common::{hold_efforts, to_the_end_of_the_hold};

use std::path::{Path, PathBuf};

use softgrip_scene::control::Phase;
use softgrip_scene::{PlainRun, Scene};

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// What a grasp run gives.
#[derive(Debug)]
struct Grasped {
    /// The grasp reached its force (its `GripReached` event).
    reached: bool,
    /// Each pad's normal force at the end of the hold \[N\].
    pads: Vec<f64>,
    /// How far the object rose from its start \[m\].
    rise: f64,
    /// How far the hand's base rose \[m\].
    base_rise: f64,
    /// The object's largest motion relative to the base over the hold, from its first step
    /// \[m\].
    slip: f64,
    /// The same from the hold's second step \[m\].
    creep: f64,
    /// The same over the hold's second half (from its middle step) \[m\].
    late: f64,
    /// The largest compression ratio of any pad.
    peak_x: f64,
    /// The object's mass \[kg\].
    mass: f64,
    /// The pads' friction springs' stiffness along the vertical, summed, at the lift's last
    /// step: `sum 8 G* a (1 - n_y^2)`, `G* = G / (2 - nu)` of the pad against the rigid
    /// object, `a` the law's patch at the pad's compression (Mindlin; as the plugin) \[N/m\].
    k_up: f64,
    /// The pads' vertical friction on the object, summed, at the lift's last step \[N\].
    lift_shear: f64,
    /// The same at the hold's last step \[N\].
    hold_shear: f64,
    /// The object's vertical position relative to the base at each hold step \[m\].
    hold_y: Vec<f64>,
}

/// Runs `scenes/robots/{name}.toml`, whose object is the body `object`.
fn grasp(name: &str, object: &str) -> Grasped {
    grasp_with(name, object, true)
}

/// The same, with the pads' friction spring on (the default) or off (the rigid stick).
fn grasp_with(name: &str, object: &str, spring: bool) -> Grasped {
    let path = repo().join(format!("scenes/robots/{name}.toml"));
    let scene = Scene::from_file(&path).unwrap();
    let mut run = PlainRun::new(&scene);
    run.world.soft.set_friction_spring(spring);
    let obj = run.handles.body(object).unwrap();
    let base = run.handles.robots[0].1.links[0];
    let pads: Vec<_> = (scene.file().fingertips.iter())
        .map(|t| run.handles.fingertip(&t.name).unwrap())
        .collect();
    let at = |run: &PlainRun,
              b: softgrip_scene::softgrip_rapier::rapier3d::prelude::RigidBodyHandle| {
        let t = run.world.physics.bodies[b].translation();
        [t.x as f64, t.y as f64, t.z as f64]
    };
    let (start, base_start) = (at(&run, obj), at(&run, base));
    let mut hold: Vec<[f64; 3]> = Vec::new();
    let (mut reached, mut peak_x) = (false, 0.0f64);
    let (mut pads_held, mut rise, mut base_rise) = (Vec::new(), 0.0, 0.0);
    let (mut k_up, mut lift_shear, mut hold_shear) = (0.0, 0.0, 0.0);
    let mut trace: Vec<(f64, f64, f64)> = Vec::new();
    // The pads' summed vertical spring stiffness and vertical friction on the object now.
    let springs = |run: &PlainRun| {
        let (mut k, mut f) = (0.0, 0.0);
        for c in run.world.soft.contacts() {
            if !pads.contains(&c.fingertip)
                || run.world.physics.colliders[c.other].parent() != Some(obj)
            {
                continue;
            }
            let m = run.world.soft.fingertip(c.fingertip).unwrap().material();
            let g_star = m.shear_modulus() / (2.0 - m.poisson_ratio());
            let n = c.reading.normal;
            let kt = 8.0 * g_star * c.patch().equivalent_radius();
            k += kt * (1.0 - n[1] * n[1]);

            // The reading's friction is the force on the pad: negative (down) while the pad
            // carries the object.
            f += c.reading.friction_force[1];
        }
        (k, f)
    };
    for _ in 0..scene.steps() {
        run.step();
        if run.control.controllers()[0].phase() == Some(Phase::Lift) {
            (k_up, lift_shear) = springs(&run);
        }
        if matches!(
            run.control.controllers()[0].phase(),
            Some(Phase::Lift | Phase::Hold)
        ) {
            let (o, b) = (at(&run, obj), at(&run, base));
            trace.push((o[1] - b[1], b[1], springs(&run).1));
        }
        reached |= !run.events().is_empty();
        for c in run.world.soft.contacts() {
            peak_x = peak_x.max(c.max_x);
        }
        if run.control.controllers()[0].phase() == Some(Phase::Hold) {
            let (o, b) = (at(&run, obj), at(&run, base));
            hold.push([0, 1, 2].map(|i| o[i] - b[i]));
            hold_shear = springs(&run).1;
            rise = o[1] - start[1];
            base_rise = b[1] - base_start[1];
            pads_held = (pads.iter())
                .map(|&p| run.world.soft.contacts_of(p).map(|c| c.normal_force).sum())
                .collect();
        }
    }
    assert!(hold.len() > 2, "{name}: the grasp never held");
    let g = Grasped {
        reached,
        pads: pads_held,
        rise,
        base_rise,
        slip: common::excursion(&hold, 0),
        creep: common::excursion(&hold, 1),
        late: common::excursion(&hold, hold.len() / 2),
        peak_x,
        mass: run.world.physics.bodies[obj].mass() as f64,
        k_up,
        lift_shear,
        hold_shear,
        hold_y: hold.iter().map(|p| p[1]).collect(),
    };
    let half = &g.hold_y[g.hold_y.len() / 2..];
    let nl = trace.len() - g.hold_y.len();
    // The lift's last steps and the hold's first: the object's height relative to the base
    // (from the hold's first step), the base's speed, the pads' vertical friction.
    for (i, t) in trace.iter().enumerate().skip(nl.saturating_sub(5)).take(12) {
        let v = (t.1 - trace[i - 1].1) / scene.file().dt;
        eprintln!(
            "{name} (spring {spring}) step {} from the hold: rel_y {:.4} um, base speed {:.5} \
             m/s, pads' vertical friction {:.5} N",
            i as i64 - nl as i64,
            (t.0 - g.hold_y[0]) * 1e6,
            v,
            t.2
        );
    }
    // The base's speed at the hold's first step, stopped over the next: the lift's last
    // deceleration [m/s^2].
    let dt = scene.file().dt;
    let a_last = (trace[nl].1 - trace[nl - 1].1) / dt / dt;
    eprintln!(
        "{name} (spring {spring}): mass {:.4} kg, k_up {:.1} N/m; pads' vertical friction {:.5} N \
         at the lift's last step, {:.5} N at the hold's end; the lift's last deceleration \
         {a_last:.3} m/s^2, m a / k_up {:.3} um; hold slip {:.3} um, creep {:.3} um, the hold's \
         end {:+.4} um from its first step, second half spread {:.4} um",
        g.mass,
        g.k_up,
        g.lift_shear,
        g.hold_shear,
        g.mass * a_last / g.k_up * 1e6,
        g.slip * 1e6,
        g.creep * 1e6,
        (g.hold_y[g.hold_y.len() - 1] - g.hold_y[0]) * 1e6,
        half.iter().fold(0.0f64, |m, r| m.max((r - half[0]).abs())) * 1e6,
    );
    eprintln!(
        "{name}: reached {}, pads at the end of the hold {:.4?} N, object rose {:.3} mm \
         (base {:.3} mm), hold slip {:.2} um, creep after the first hold step {:.3} um, \
         peak x {:.4}",
        g.reached,
        g.pads,
        g.rise * 1e3,
        g.base_rise * 1e3,
        g.slip * 1e6,
        g.creep * 1e6,
        g.peak_x
    );
    g
}

/// The checks every hand scene passes: the grasp reached its force; at the end of the hold each
/// pad presses at least `least[k]` \[N\] and less than `most` \[N\]; object and hand lifted
/// by `lift` \[m\] (the object within 1 mm); hold slip < 100 um (issue 25); no creep late in
/// the hold, the object's motion relative to the base over the hold's second half < 0.1 um
/// (`Grasped::late`); pads within their law's range (x < 0.3).
///
/// With the friction spring (the default) the hold's first steps are not a creep: the lift's
/// last step stops the base at about twice the ramp's deceleration (the trapezoid's `sqrt(2 a
/// d)` cap), and the object, hung on the pads' springs (`omega h = h sqrt(k_up / m)` 3.3-4.4,
/// not resolved by the step), rings that out over 2-6 steps back to its steady lift's height
/// (session 19: 0.02-0.24 um from it). The old bound on the motion from the hold's second step
/// (0.1 um gripper, 1-2 um three-finger hand) was set for the rigid stick, which has no such
/// spring: it is kept for the rigid stick's run (`check_rigid_stick`); the spring's run is
/// bounded by Mindlin's static sag (`assert_mindlin_sag`, where the fingers are rigid
/// vertically) and by the late hold, where a creep (a slipping pad, or a stretch that
/// drifts: session 20's `f32` pose round-off, 0.104 um over the gripper cylinder's second
/// half) would show.
fn check(g: &Grasped, least: &[f64], most: f64, lift: f64) {
    assert!(g.reached, "{g:?}: the grasp never reached its force");
    assert_eq!(g.pads.len(), least.len(), "{g:?}");
    for (f, l) in g.pads.iter().zip(least) {
        assert!(f >= l && *f < most, "{g:?}: pad holds {f} N");
    }
    assert!((g.base_rise - lift).abs() < 1e-6, "{g:?}: hand lifted");
    assert!((g.rise - lift).abs() < 1e-3, "{g:?}: object lifted");
    assert!(g.slip < 100e-6, "{g:?}: hold slip");
    assert!(g.late < 1e-7, "{g:?}: creep over the hold's second half");
    assert!(g.peak_x < 0.3, "{g:?}: peak x");
}

/// The rigid stick's run (`set_friction_spring(false)`) of the same scene: the checks of
/// [`check`] and its creep after the hold's first step below `creep` \[m\] (the bound the
/// hand scenes had before the spring was the default).
fn check_rigid_stick(g: &Grasped, least: &[f64], most: f64, lift: f64, creep: f64) {
    check(g, least, most, lift);
    assert!(g.creep < creep, "{g:?}: creep (rigid stick)");
}

/// Mindlin's static sag, measured: the parallel gripper's fingers slide on prismatic joints
/// (rigid vertically), so at the end of the hold the object hangs below where the rigid stick
/// (`set_friction_spring(false)`) holds it by the springs' stretch, the pads' vertical
/// friction over their summed vertical stiffness `sum 8 G* a` (`Grasped::k_up`). Measured
/// (session 19): box 257 um against 256.9 um, ball 154 against 153.5, cylinder 224 against
/// 224.7 (the vertical friction, not `m g`: on the curved objects the normals carry part of
/// the weight). Within 1 %.
fn assert_mindlin_sag(name: &str, object: &str) -> (Grasped, Grasped) {
    let spring = grasp_with(name, object, true);
    let rigid = grasp_with(name, object, false);
    let sag = (rigid.rise - spring.rise) - (rigid.base_rise - spring.base_rise);
    let mindlin = spring.hold_shear.abs() / spring.k_up;
    eprintln!(
        "{name}: sag below the rigid stick {:.2} um, Mindlin's (vertical friction {:.5} N over \
         k_up {:.1} N/m) {:.2} um, {:+.2} %",
        sag * 1e6,
        spring.hold_shear,
        spring.k_up,
        mindlin * 1e6,
        (sag / mindlin - 1.0) * 100.0
    );
    assert!(
        (sag / mindlin - 1.0).abs() < 0.01,
        "{name}: sag {sag} vs {mindlin}"
    );
    (spring, rigid)
}

// The parallel gripper: 5 N per pad (the motors hold 4.97-5.05 N once settled: the target froze
// the step the force passed 5 N), lift 10 cm at 0.1 m/s ramped at 1 m/s^2: slip <= 0.01 um.
// (Before session 13, when the hold's steps took 75-89 substeps: 4.93-4.99 N, slip 2.9-6.9 um.)

#[test]
fn parallel_gripper_grasps_a_box() {
    let (spring, rigid) = assert_mindlin_sag("parallel_gripper_box", "box");
    check(&spring, &[4.9; 2], 5.5, 0.1);
    check_rigid_stick(&rigid, &[4.9; 2], 5.5, 0.1, 1e-7);
}

#[test]
fn parallel_gripper_grasps_a_ball() {
    let (spring, rigid) = assert_mindlin_sag("parallel_gripper_ball", "ball");
    check(&spring, &[4.9; 2], 5.5, 0.1);
    check_rigid_stick(&rigid, &[4.9; 2], 5.5, 0.1, 1e-7);
}

#[test]
fn parallel_gripper_grasps_a_cylinder() {
    let (spring, rigid) = assert_mindlin_sag("parallel_gripper_cylinder", "cylinder");
    check(&spring, &[4.9; 2], 5.5, 0.1);
    check_rigid_stick(&rigid, &[4.9; 2], 5.5, 0.1, 1e-7);
}

// The three-finger hand: 1 N per pad (2 N on the box), lift 5 cm at 0.05 m/s ramped at
// 0.5 m/s^2.

/// Three fingers on a box's four faces: finger 0 pushes the +x face, fingers 1 and 2 hold
/// the +-z faces 30 degrees off their normals, so the box is held in x by their friction.
/// Pads 2.26 / 2.11 / 2.14 N at the end of the hold, slip 0.30 um, creep 0.35 um; with every
/// step resolved far finer (the motors' free run within 0.2 % of the compression per substep)
/// 2.10 / 2.27 / 2.28 N, creep 0.42 um. Before session 13 (78 substeps per step, the motors'
/// push read as an approach velocity) the box crept 67 um through the hold with 1.79 N on the
/// thumb; with every hold step unsplit the thumb kept 0.37 N.
/// Session 19, the friction spring the default: the thumb (pad 0) ends at 1.8426 N (least
/// 2.0; the rigid stick 2.2657 N). Measured step by step: fingers 1 and 2 drag the box 0.436
/// mm towards +x before the thumb touches (rigid 0.313); the thumb's force rises 0.52 / 1.30 /
/// 2.14 N over its last three closing steps (rigid 0.48 / 1.56 / 2.78) and its target freezes
/// at 2.14 N, having pushed the box back to x = -0.034 mm against pads 1 and 2's springs (their
/// tangential force 0.23 -> 1.07 N); in the settle those springs push the box back to +0.079
/// mm and the thumb's frozen motor gives way to 1.82-1.84 N. The grip's force is then the
/// frozen target against the springs' recoil, not 2 N: a controller matter (no force servo
/// after the freeze). Session 20: the grasp primitive now closes a force-stopped finger again
/// through the settle, lift and hold while it presses less than its force (`control/grasp.rs`,
/// `keep_force`): the thumb ends at 2.0144 N (pads 2.0144 / 2.1592 / 2.1619 N); the rigid
/// stick's run (2.2717 / 2.1101 / 2.1246 N) never falls below 2 N and is not moved by it.
#[test]
fn three_finger_hand_grasps_a_box() {
    let name = "three_finger_hand_box";
    check(&grasp(name, "box"), &[2.0, 2.0, 2.0], 2.6, 0.05);
    check_rigid_stick(
        &grasp_with(name, "box", false),
        &[2.0, 2.0, 2.0],
        2.6,
        0.05,
        2e-6,
    );
}

#[test]
fn three_finger_hand_grasps_a_ball() {
    let name = "three_finger_hand_ball";
    check(&grasp(name, "ball"), &[1.0; 3], 1.5, 0.05);
    check_rigid_stick(&grasp_with(name, "ball", false), &[1.0; 3], 1.5, 0.05, 1e-6);
}

/// The lying cylinder: fingers 1 and 2 on its round side carry it; finger 0 on its flat end
/// presses 1 N at the grip and 0.85 N at the end of the hold (the cylinder tilts a little as
/// it is lifted; 0.76 N with every step resolved far finer; 0.19 N before session 13, when
/// the motors' push split each step into ~78 substeps read as an approach), creep 0.04 um.
#[test]
fn three_finger_hand_grasps_a_cylinder() {
    let name = "three_finger_hand_cylinder";
    check(&grasp(name, "cylinder"), &[0.5, 1.0, 1.0], 1.5, 0.05);
    check_rigid_stick(
        &grasp_with(name, "cylinder", false),
        &[0.5, 1.0, 1.0],
        1.5,
        0.05,
        1e-6,
    );
}

/// Issue 25, item 8: the URDF gripper's 5 N grasp of its 200 g box; at the end of the hold each
/// finger joint's effort equals `J^T F`, the joint-space projection of the pads' forces, within
/// 1 %. The driven `finger_joint`'s motor holds both pads (the right finger is its mimic); the
/// mimic joint has no motor: its effort is the load its coupling carries
/// (`robot::joint_state_loaded`), which must also be the share of the driven joint's motor
/// effort left after its own finger's load, `(tau_motor + J^T F_own) / multiplier`, within 1 %:
/// the force the coupling really transmitted. Prints the root README's table (`cargo test -p
/// softgrip-scene --test hand_scenes -- efforts --nocapture`). Asserted within 1e-5 since
/// session 29, when the gripper's links got the sweeps rapier needs over its motor and mimic
/// coupling (`Robot::set_jointed_sweeps`): measured 2.8e-7 (`finger_joint`) and 5.6e-7 (the
/// coupling's share); at rapier's 1 sweep they were 2.8e-3 and 5.5e-3.
#[test]
fn gripper_joint_efforts_equal_jt_f() {
    let path = repo().join("scenes/robots/parallel_gripper_box.toml");
    let scene = Scene::from_file(&path).unwrap();
    let robot = scene.robots()[0].clone();
    let (rows, pads) = to_the_end_of_the_hold(&scene);
    println!("pads' normal forces at the end of the hold: {pads:.4?} N");
    println!("| joint | position [mm] | effort [N] | J^T F [N] | |effort + J^T F| / |J^T F| |");
    println!("|---|---:|---:|---:|---:|");
    for (j, s, load, _) in &rows {
        let joint = &robot.joints()[*j];
        let rel = (s.effort + load).abs() / load.abs();
        let kind = if joint.mimic.is_some() {
            " (mimic: its coupling's load)"
        } else {
            ""
        };
        println!(
            "| `{}`{kind} | {:.3} | {:.4} | {load:.4} | {:.2e} |",
            joint.name,
            s.position * 1e3,
            s.effort,
            rel
        );
        assert!(
            rel < 1e-5,
            "{}: effort {} vs J^T F {load}",
            joint.name,
            s.effort
        );
        assert!(
            load.abs() > 4.5,
            "{}: J^T F {load} N for 5 N pads",
            joint.name
        );
    }
    // The coupling's share of the motor: the driven joint's motor effort minus its own finger's
    // load, over the multiplier, is what the mimic joint reports.
    for (j, s, _, _) in &rows {
        let Some(mimic) = robot.joints()[*j].mimic else {
            continue;
        };
        let (_, leader, _, own) = rows.iter().find(|r| r.0 == mimic.joint).unwrap();
        let share = (leader.effort + own) / mimic.multiplier;
        let rel = (s.effort - share).abs() / share.abs();
        println!(
            "`{}`: effort {:.4} N, the coupling's share of `{}`'s motor {share:.4} N ({rel:.2e})",
            robot.joints()[*j].name,
            s.effort,
            robot.joints()[mimic.joint].name
        );
        assert!(
            rel < 1e-5,
            "mimic effort {} vs the motor's share {share}",
            s.effort
        );
    }
}

/// A lift's `acceleration` is checked like every other value: not positive, not finite or past
/// the engine's range is an error naming the field and the value.
#[test]
fn a_bad_lift_acceleration_is_an_error_naming_it() {
    for bad in ["0.0", "-1.0", "nan", "1e9"] {
        let to = format!("acceleration = {bad}");
        let edits = [("acceleration = 1.0", to.as_str())];
        let e = common::shipped_robot_scene("parallel_gripper_box", &edits)
            .unwrap_err()
            .to_string();
        assert!(e.contains("controller[0].lift.acceleration"), "{bad}: {e}");
    }
}

/// A body that starts inside a robot's link is refused, naming both and the depth: the
/// gripper's cylinder stood up (its top at 80 mm) starts 15 mm inside the palm (`base_link`
/// from 65 mm at this pose); run, rapier pushed it 14.5 mm into the table in the first step
/// and it toppled. Lying (the shipped scene) it clears the palm by 25 mm and loads.
#[test]
fn a_body_starting_inside_a_link_is_an_error_naming_both_and_the_depth() {
    common::shipped_robot_scene("parallel_gripper_cylinder", &[])
        .expect("the lying cylinder loads");
    let standing = [
        (
            "rotation = [1.5707963267948966, 0.0, 0.0] # lying",
            "# standing",
        ),
        ("position = [0.0, 0.02, 0.0]", "position = [0.0, 0.04, 0.0]"),
    ];
    let e = common::shipped_robot_scene("parallel_gripper_cylinder", &standing).unwrap_err();
    let softgrip_scene::SceneError::StartOverlap {
        link,
        other,
        depth,
        allowed,
        ..
    } = &e
    else {
        panic!("{e}");
    };
    assert!(link.contains("`base_link`"), "{e}");
    assert!(other.contains("`cylinder`"), "{e}");
    assert!((depth - 0.015).abs() < 1e-5, "depth {depth} m: {e}");
    assert!(*allowed < 0.015, "{e}");
    let message = e.to_string();
    assert!(
        message.contains("0.015") && message.contains("cylinder"),
        "{message}"
    );
}

/// Issue 25 ("other hands' URDFs"): an underactuated hand, the shipped three-finger hand with
/// each distal joint a `<mimic>` of its proximal one (multiplier 0.5, the common tendon-like
/// design), written to a temporary folder, grasps the ball, the box and the cylinder of the
/// shipped scenes. Its links get the Gauss-Seidel sweeps rapier needs over the motors and the
/// three couplings (`Robot::set_jointed_sweeps`); at the end of each hold every proximal
/// joint's motor effort equals `J^T F` of its finger (its own links and, through the coupling,
/// its distal joint's load) and each distal joint's effort its share of the motor. Measured
/// (session 29, release): within 3.9e-6 and 2.4e-5. With rapier's own sweep (the scene not
/// raising them, as before session 29) they were 2.8-3.3 % and 15-17 % off.
#[test]
fn an_underactuated_hand_holds_with_efforts_equal_to_jt_f() {
    let dir = std::env::temp_dir().join(format!("softgrip-underactuated-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let urdf =
        std::fs::read_to_string(repo().join("robots/three_finger_hand/three_finger_hand.urdf"))
            .unwrap();
    let mut out = String::new();
    let mut finger = None;
    for line in urdf.lines() {
        if let Some(i) = line.find("joint name=\"f") {
            let f = &line[i + 12..i + 14];
            finger = line.contains("_distal_joint").then(|| f.to_string());
        }
        if line.trim() == "</joint>"
            && let Some(f) = finger.take()
        {
            out.push_str(&format!(
                "    <mimic joint=\"{f}_proximal_joint\" multiplier=\"0.5\" offset=\"0\"/>\n"
            ));
        }
        out.push_str(line);
        out.push('\n');
    }
    assert_eq!(out.matches("<mimic").count(), 3, "a mimic per distal joint");
    std::fs::write(dir.join("hand.urdf"), out).unwrap();
    for object in ["ball", "box", "cylinder"] {
        let path = repo().join(format!("scenes/robots/three_finger_hand_{object}.toml"));
        let text = std::fs::read_to_string(path).unwrap().replace(
            "../../robots/three_finger_hand/three_finger_hand.urdf",
            "hand.urdf",
        );
        let scene = Scene::parse(&text, "underactuated.toml", &dir).unwrap();
        let (loads, shares) = hold_efforts(&scene);
        for &(ref joint, effort, load, rel) in &loads {
            println!("{object}: `{joint}` effort {effort:.6} vs J^T F {load:.6} ({rel:.2e})");
            assert!(load.abs() > 0.01, "{object}: `{joint}` J^T F {load}");
            assert!(
                rel < 1e-4,
                "{object}: `{joint}` effort {effort} vs J^T F {load}"
            );
        }
        assert_eq!(shares.len(), 3, "{object}: a share per mimic joint");
        for &(ref joint, effort, share, rel) in &shares {
            println!("{object}: `{joint}` effort {effort:.6} vs its share {share:.6} ({rel:.2e})");
            assert!(
                rel < 1e-4,
                "{object}: `{joint}` effort {effort} vs share {share}"
            );
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Issue 25 item 8's 1 % on the shipped three-finger hand (no mimic joint, so rapier keeps its
/// one Gauss-Seidel sweep over the six motor rows, which the soft solve folds in as converged;
/// SCENES.md, "Multibody robots with a mimic joint"): at the end of each hold every joint's
/// motor effort against `J^T F`. Measured (session 29): proximal joints 7.9e-3 to 8.5e-3, distal
/// ones 1.5e-3 to 1.6e-3 (the proximal motors read high: rapier's sweep has not passed all of
/// the distal load to them). Bounded at the 1 %; with the sweeps the chains need (348,
/// at 9.3x the step time) they would read about 1e-6.
#[test]
fn three_finger_hand_joint_efforts_equal_jt_f_within_1_percent() {
    for object in ["ball", "box", "cylinder"] {
        let path = repo().join(format!("scenes/robots/three_finger_hand_{object}.toml"));
        let scene = Scene::from_file(&path).unwrap();
        let (loads, shares) = hold_efforts(&scene);
        assert!(shares.is_empty(), "no mimic joint");
        assert_eq!(loads.len(), 6, "six joints");
        for &(ref joint, effort, load, rel) in &loads {
            println!("{object}: `{joint}` effort {effort:.5} vs J^T F {load:.5} ({rel:.2e})");
            assert!(load.abs() > 0.03, "{object}: `{joint}` J^T F {load}");
            assert!(
                rel < 0.01,
                "{object}: `{joint}` effort {effort} vs J^T F {load}"
            );
        }
    }
}
