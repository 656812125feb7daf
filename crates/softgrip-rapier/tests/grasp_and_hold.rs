//! Hard case 8, grasp and hold: two soft fingertips on kinematic jaws squeeze a 200 g box
//! (5 cm cube) with a 5 N grip (squeeze depth from the law's inverse), lift it 0.1 m and hold
//! it 10 s at dt = 1/60 s. mu = 0.3, so the friction limit 2 mu F = 3 N holds the 1.96 N
//! weight, and half the grip (1.5 N) does not.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

mod common;

use common::{Grasp, GraspSpec};

struct Outcome {
    /// Box height relative to the jaws at the end of settle minus at the end, [m].
    slip: f64,
    /// Largest |slip| during the hold [m].
    slip_hold_max: f64,
    /// Creep over the hold's second half (`common::late_spread`) [m].
    late_spread: f64,
    /// Mindlin's slide `m g / (2 k_t)` with the friction spring (`common::mindlin_sag`) [m].
    mindlin: f64,
    turn_deg: f64,
    grip_force: f64,
    lifted: f64,
}

fn run(spec: &GraspSpec) -> Outcome {
    run_with(spec, true)
}

/// [`run`] with the friction spring on or off (`SoftContacts::set_friction_spring`).
fn run_with(spec: &GraspSpec, spring: bool) -> Outcome {
    let mut g = common::grasp(spec);
    g.world.soft.set_friction_spring(spring);
    let mut rel0 = None;
    let mut rel_hold0 = None;
    let mut slip_hold_max = 0.0f64;
    let mut hold = Vec::new();
    let mut grip_force = 0.0;
    g.run(0.1, 10.0, |g: &Grasp, phase| {
        assert!(common::all_finite(&g.world), "non-finite in {phase}");
        let rel = g.object_y() - g.jaw_y();
        if phase == "settle" {
            rel0 = Some(rel);
        }
        if phase == "hold" {
            let r0 = *rel_hold0.get_or_insert(rel);
            slip_hold_max = slip_hold_max.max((rel - r0).abs());
            hold.push(rel);
            grip_force = g
                .world
                .soft
                .contacts_of(g.tips[0])
                .map(|c| c.normal_force)
                .sum::<f64>();
        }
    });
    let rel = g.object_y() - g.jaw_y();
    Outcome {
        slip: rel0.unwrap() - rel,
        slip_hold_max,
        late_spread: common::late_spread(&hold),
        mindlin: common::mindlin_sag(spec, g.squeeze).0,
        turn_deg: g.object_turn_deg(),
        grip_force,
        lifted: g.object_y() - g.half,
    }
}

#[test]
fn box_held_10_s_slips_less_than_1_mm() {
    let o = run(&GraspSpec::default());
    println!(
        "grasp 5 N: slip {:.3e} m (Mindlin {:.3e} m; hold only {:.3e} m, late hold {:.2e} m), lifted {:.4} m, grip {:.4} N, turn {:.3} deg",
        o.slip, o.mindlin, o.slip_hold_max, o.late_spread, o.lifted, o.grip_force, o.turn_deg
    );
    // Session 19: the friction spring is the default. The box slides by Mindlin's elastic
    // shear of the two pads, m g / (2 k_t) (258.0 um; measured 258.7 um), within 2 %, and then
    // holds: < 1 um over the hold's second half (the hold's first part still carries the
    // lift's deceleration). The hard stick's figures below (0.5 um, 0 in the hold) stand with
    // `set_friction_spring(false)` (`rigid_stick_box_held_10_s_slips_less_than_5_um`).
    assert!(
        (o.slip / o.mindlin - 1.0).abs() < 0.02,
        "slip {} m, Mindlin {} m",
        o.slip,
        o.mindlin
    );
    assert!(o.late_spread < 1e-6, "late hold spread {} m", o.late_spread);
    assert!((o.lifted - 0.1).abs() < 2e-3);
    assert!((o.grip_force / 5.0 - 1.0).abs() < 0.005);
}

/// The rigid stick (`set_friction_spring(false)`, the default before session 19).
#[test]
fn rigid_stick_box_held_10_s_slips_less_than_5_um() {
    let o = run_with(&GraspSpec::default(), false);
    println!(
        "rigid stick, grasp 5 N: slip {:.3e} m (hold only {:.3e} m), lifted {:.4} m, grip {:.4} N, turn {:.3} deg",
        o.slip, o.slip_hold_max, o.lifted, o.grip_force, o.turn_deg
    );
    // The READMEs state "slip 0.5 um, 0 m during the hold; grip 5.000 N". The friction limit
    // (3 N) is well above the lift's need (m (g + a) = 2.08 N): static friction holds. The
    // 62 um the plugin used to read came from the first steps of the lift, the box still on
    // the ground, which the plugin's solve did not see (it predicted a free box falling under
    // gravity; `src/rigid.rs`). Below 5 um (a return of the 62 um fails it), 1 um on the hold
    // (f32 poses near 0.1 m are ~1e-8 m apart), 0.5 % on the grip.
    assert!(o.slip.abs() < 5e-6, "slip {} m, README: 0.5 um", o.slip);
    assert!(
        o.slip_hold_max < 1e-6,
        "hold slip {} m, README: 0",
        o.slip_hold_max
    );
    assert!((o.lifted - 0.1).abs() < 2e-3);
    assert!((o.grip_force / 5.0 - 1.0).abs() < 0.005);
}

#[test]
fn off_centre_load_turns_less_than_2_degrees_thanks_to_torsion() {
    // Centre of mass 2 mm off the grip axis: 1.96 N x 2 mm = 3.9 mN m, below the torsion limit
    // 2 (3 pi/16) mu F a = 2 x 0.589 x 0.3 x 5 N x ~3.7 mm = 6.5 mN m.
    let with = run(&GraspSpec {
        com_offset_z: 0.002,
        ..GraspSpec::default()
    });
    // Without torsion, the figure below is the rigid stick's (`set_friction_spring(false)`).
    // With the friction spring (the default since session 19) the same box turns 42.2 deg
    // without torsion: no derived bound yet (`SPRING_DEFAULT_STATUS.md`).
    let without = run_with(
        &GraspSpec {
            com_offset_z: 0.002,
            torsion: false,
            ..GraspSpec::default()
        },
        false,
    );
    println!(
        "off-centre load: turn {:.3} deg with torsion, {:.2} deg without; slip {:.3e} m",
        with.turn_deg, without.turn_deg, with.slip
    );
    // The READMEs state 0.042 deg with torsion and 149 deg without (0.095 and 136 before the
    // ground was in the solve, `src/rigid.rs`): < 0.19 deg on the first (was < 2 deg), 100-170
    // deg on the second (was > 10 deg).
    assert!(
        with.turn_deg < 0.19,
        "turn {} deg, README: 0.042",
        with.turn_deg
    );
    assert!(
        (100.0..=170.0).contains(&without.turn_deg),
        "turn {} deg without torsion, README: 149",
        without.turn_deg
    );
    assert!(with.slip.abs() < 1e-3);
}

#[test]
fn half_grip_below_friction_limit_slips() {
    let o = run(&GraspSpec {
        grip_force: 2.5,
        ..GraspSpec::default()
    });
    println!(
        "grasp 2.5 N (limit 1.5 N < 1.96 N weight): slip {:.4} m, lifted {:.4} m",
        o.slip, o.lifted
    );
    // The READMEs state 0.100 m (the whole lift: the box stays on the ground); was > 5 cm.
    assert!(o.slip > 0.09, "slip {} m, README: 0.100", o.slip);
}

/// Issue 10: the same grasp with `flat` pads (hemispheres bonded to the jaws, facing the box):
/// the squeeze depth is the flat law's inverse at 5 N, the box is held (slip during the lift
/// only, none in the hold), the grip reads 5 N, and the torsion of the flat law's patch keeps
/// the off-centre load from turning.
#[test]
fn flat_pads_hold_the_box_and_resist_twist() {
    let flat = softgrip_law::Backing::Flat;
    let o = run(&GraspSpec {
        backing: flat,
        ..GraspSpec::default()
    });
    let twist = run(&GraspSpec {
        backing: flat,
        com_offset_z: 0.002,
        ..GraspSpec::default()
    });
    println!(
        "flat pads, grasp 5 N: slip {:.3e} m (hold only {:.3e} m), lifted {:.4} m, grip {:.4} N; off-centre load: turn {:.3} deg",
        o.slip, o.slip_hold_max, o.lifted, o.grip_force, twist.turn_deg
    );
    // Session 19 (the friction spring the default): Mindlin's slide m g / (2 k_t) with the
    // flat law's patch within 2 % and < 1 um over the hold's second half, as the free pads.
    // (Rigid stick: slip 0.5 um, 0 in the hold, grip 5.000 N, 0.04 deg.)
    println!(
        "flat pads: Mindlin {:.3e} m, late hold {:.2e} m",
        o.mindlin, o.late_spread
    );
    assert!(
        (o.slip / o.mindlin - 1.0).abs() < 0.02,
        "slip {} m, Mindlin {} m",
        o.slip,
        o.mindlin
    );
    assert!(o.late_spread < 1e-6, "late hold spread {} m", o.late_spread);
    assert!((o.lifted - 0.1).abs() < 2e-3);
    assert!((o.grip_force / 5.0 - 1.0).abs() < 0.005);
    assert!(twist.turn_deg < 0.19, "turn {} deg", twist.turn_deg);
}

/// Session 16: static friction as Mindlin's tangential spring
/// (`SoftContacts::set_friction_spring`, the default since session 19). Each pad's contact shears like a
/// spring of stiffness `k_t = 8 G* a` (`G* = G / (2 - nu)` against the rigid box, `a` the law's
/// contact radius at the grip): the held box sags in the grip by its weight shared over the
/// two pads, `m g / (2 k_t)`, and then holds (the Coulomb disk `mu F` is not reached).
#[test]
fn friction_spring_sags_by_the_weight_over_mindlins_stiffness() {
    let spec = GraspSpec::default();
    let mut g = common::grasp(&spec);
    g.world.soft.set_friction_spring(true);
    let (mut rel0, mut hold) = (None, Vec::new());
    g.run(0.1, 10.0, |g: &Grasp, phase| {
        let rel = g.object_y() - g.jaw_y();
        if phase == "settle" {
            rel0 = Some(rel);
        }
        if phase == "hold" {
            hold.push(rel);
        }
    });
    let sag = rel0.unwrap() - hold.last().unwrap();
    // The prediction from the law at the grip's compression.
    let nu = 0.49;
    let g_star = spec.youngs_modulus / (2.0 * (1.0 + nu)) / (2.0 - nu);
    let tip = softgrip_rapier::SoftFingertip::builder(common::GRASP_R)
        .material(softgrip_law::Material::try_new(spec.youngs_modulus, nu).unwrap())
        .build()
        .unwrap();
    let a = tip.law().patch(g.squeeze).radius;
    let k_t = 8.0 * g_star * a;
    let want = f64::from(spec.mass) * 9.81 / (2.0 * k_t);
    // The second half of the hold: still (the f32 poses near 0.1 m are ~1e-8 m apart).
    let late = &hold[hold.len() / 2..];
    let spread = late.iter().fold(0.0f64, |m, r| m.max((r - late[0]).abs()));
    println!(
        "friction spring: sag {sag:.4e} m, Mindlin m g / (2 k_t) {want:.4e} m (k_t {k_t:.1} N/m, a {a:.4e} m), late hold spread {spread:.2e} m, lifted {:.4} m",
        g.object_y() - g.half
    );
    assert!(
        (sag / want - 1.0).abs() < 0.02,
        "sag {sag} m, Mindlin {want} m"
    );
    assert!(spread < 1e-6, "late hold spread {spread} m");
    assert!((g.object_y() - g.half - 0.1).abs() < 2e-3);
}
