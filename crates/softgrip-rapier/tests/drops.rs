//! Nothing explodes, nothing sinks through (issue 23, item 5). A fingertip dropped on a rigid
//! plane never rises above its start, whatever its size, material, restitution, step and drop
//! height.
//!
//! The named cases are the ones that broke: the default fingertip (Dragon Skin 30, R = 10 mm,
//! e = 0.5) dropped 0.5 mm at dt = 1/60 s sank 1.2 mm into the floor within one step (no
//! force until the step ended) and rebounded to 13 times its drop height; a stiff 1 mm tip
//! dropped 10 cm at dt = 1/30 s rebounded to 317 m with a 1.9 MN peak. The remedy is the
//! implicit contact's onset (`step::onset`): a contact that would touch by the end of a step
//! it does not resolve is linearised at its predicted end and solved implicitly there, Newton
//! on the law within the step.
//!
//! `cargo test -p softgrip-rapier --test drops -- --nocapture` prints the numbers.

#![allow(clippy::unwrap_used)] // tests: a failed unwrap is a failed test

use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use rapier3d::prelude::*;
use softgrip_law::Material;
use softgrip_rapier::{MAX_SUBSTEPS, Preset, SoftAccuracy, SoftFingertip, SoftWorld};

/// What one drop did.
#[derive(Debug, Clone, Copy)]
struct Drop {
    /// Highest point of the ball's lowest point after its first contact, over the drop
    /// height [-] (1 = back to the start).
    rise: f64,
    /// Deepest compression over the radius [-].
    max_x: f64,
    /// Largest force of any substep \[N\].
    peak: f64,
    /// Whether the ball touched at all.
    touched: bool,
}

/// Drops `tip` (density `rho`) from `h0` \[m\] (its lowest point above a plane normal to y)
/// at a step of `dt` \[s\] for `steps` steps.
///
/// The ball's centre reaches the origin as it touches (the plane lies at `-R`, the ball starts
/// `h0` above the origin): rapier's positions are f32, and a contact is resolved in steps of
/// the f32 spacing of the centre's coordinate there. A stiff tip's compression is a few
/// hundred f32 steps of a coordinate a few millimetres from the origin (a 4 mm tip of E =
/// 3.6 GPa dropped 1.4 um compresses 0.2 um), where the force's quantisation moved a bounce by
/// 1.6 % of such a drop; a 10 um ball touching 1 m from the origin (spacing 60-120 nm)
/// compresses less than one step there: it stuck to the plane at its first impact, even at
/// e = 1, and every step after ran at the substep cap; touching at the origin it bounces back
/// to 0.99993 of its drop. The start is resolved to 1e-7 of the drop height. (The crate
/// README's Limits: keep micro scenes near the origin.)
fn drop(tip: SoftFingertip, rho: f32, h0: f64, dt: f64, steps: usize) -> Drop {
    let r = tip.radius();
    let mut world = SoftWorld::new();
    world.physics.integration_parameters.dt = dt as f32;
    let floor = -r as f32;
    world.physics.colliders.insert(
        ColliderBuilder::new(SharedShape::halfspace(Vector::Y))
            .translation(Vector::new(0.0, floor, 0.0)),
    );
    let floor = floor as f64;
    // At rest in rapier's integration: its step of dt is N passes of "kick, then drift", so a
    // body whose stored velocity is 0 moves in its first step as if it fell at g dt / (2N)
    // (0.041 m/s at dt = 1/30 s, N = 4: the kinetic energy of an 85 um drop, which an elastic
    // bounce gives back). The stored velocity g dt / (2N) upward is a true start at rest.
    let passes = world.physics.integration_parameters.num_solver_iterations as f64;
    let v0 = 9.81 * dt / (2.0 * passes);
    let body = world.physics.bodies.insert(
        RigidBodyBuilder::dynamic()
            .translation(Vector::new(0.0, h0 as f32, 0.0))
            .linvel(Vector::new(0.0, v0 as f32, 0.0))
            .can_sleep(false),
    );
    let ball = world.physics.colliders.insert_with_parent(
        ColliderBuilder::ball(r as f32).density(rho).friction(0.0),
        body,
        &mut world.physics.bodies,
    );
    world.register(ball, tip).unwrap();
    // The start as rapier holds it (f32).
    let start = world.physics.bodies[body].translation().y as f64 - floor - r;
    let mut d = Drop {
        rise: 0.0,
        max_x: 0.0,
        peak: 0.0,
        touched: false,
    };
    let mut apex: f64 = f64::NEG_INFINITY;
    for _ in 0..steps {
        world.step();
        let y = world.physics.bodies[body].translation().y as f64 - floor - r;
        assert!(y.is_finite(), "the ball's position is not finite");
        for c in world.soft.contacts() {
            d.touched = true;
            d.max_x = d.max_x.max(c.max_x);
            d.peak = d.peak.max(c.peak_normal_force);
        }
        if d.touched {
            apex = apex.max(y);
        }
    }
    d.rise = apex / start;
    d
}

/// How far above its start \[fraction of the drop\] a ball may rise: f32's resolution of its
/// position, and the explicit update's energy error of one impact, O(theta^2) at the default
/// accuracy theta = 0.05 rad (`SoftAccuracy`), taken as `2 theta^2` = 0.5 %: with a
/// velocity-independent Hunt-Crossley coefficient the restitution tends to 1 at low impact
/// speeds (`e(v) ~ 1 - (2/3) alpha v`), where drops with e = 0.96 and 0.998 rose 0.15 % and
/// 0.31 % above their start (seeds 3 and 4 of `DROPS_SEED`, 300 cases each).
fn rise_tolerance(h0: f64, r: f64) -> f64 {
    let theta = SoftAccuracy::DEFAULT.theta();
    4.0 * f32::EPSILON as f64 * (r + h0) / h0 + 2.0 * theta * theta
}

/// The ball did not rise above its start (see [`rise_tolerance`]) and its centre did not reach
/// the plane.
fn assert_no_rise(d: &Drop, h0: f64, r: f64, what: &str) {
    assert!(d.touched, "{what}: {d:?}");
    assert!(
        d.rise <= 1.0 + rise_tolerance(h0, r),
        "{what}: rose above its start: {d:?}"
    );
    assert!(
        d.max_x < 1.0,
        "{what}: the centre went through the plane: {d:?}"
    );
}

#[test]
fn default_fingertip_dropped_half_a_millimetre_does_not_gain_energy() {
    let tip = SoftFingertip::builder(0.01)
        .preset(Preset::DragonSkin30)
        .restitution(0.5)
        .friction(0.0)
        .build()
        .unwrap();
    let d = drop(tip, 1070.0, 0.0005, 1.0 / 60.0, 120);
    println!("Dragon Skin 30, R = 10 mm, e = 0.5, 0.5 mm at 1/60 s: {d:?}");
    assert_no_rise(&d, 0.0005, 0.01, "default tip, 0.5 mm");
    // It rose to 13x its drop height before the implicit onset; e = 0.5 at 1 m/s and a
    // slower impact rebounds higher (e(v) ~ 1 - (2/3) alpha v), so below the start.
    assert!(d.rise < 1.0, "{d:?}");
}

#[test]
fn stiff_millimetre_tip_dropped_ten_centimetres_at_thirty_hertz_stays_down() {
    let tip = SoftFingertip::builder(0.001)
        .material(Material::try_new(1.0e9, 0.3).unwrap())
        .restitution(0.5)
        .friction(0.0)
        .build()
        .unwrap();
    let d = drop(tip, 1070.0, 0.1, 1.0 / 30.0, 60);
    println!("stiff 1 mm tip (E = 1 GPa), 10 cm at 1/30 s: {d:?}");
    assert_no_rise(&d, 0.1, 0.001, "stiff 1 mm tip, 10 cm");
}

fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.ln()..hi.ln()).prop_map(f64::exp)
}

/// One drop of the random set: a fingertip of radius `r` \[m\], Young's modulus `e` \[Pa\],
/// Poisson's ratio `nu`, restitution `restitution`, dropped from `h0` \[m\] at a step of `dt`
/// \[s\], long enough to fall, hit and rise again (the fall time twice, plus 20 steps). Also
/// whether the plugin can resolve the impact: the law stops the ball within its validity
/// range, `m g (h0 + delta_max) < W(delta_max)` (past it the force stops growing), and the
/// impact crosses that range in no less than one substep at the cap, `v dt / MAX_SUBSTEPS <
/// delta_max`. Since session 24 every drop is checked, resolvable or not (before, an
/// unresolvable one only for a touching fall; [`micrometre_drops_do_not_rise_above_their_start`]).
fn random_drop(
    r: f64,
    e: f64,
    nu: f64,
    restitution: f64,
    dt: f64,
    h0: f64,
) -> (Drop, bool, String) {
    let tip = SoftFingertip::builder(r)
        .material(Material::try_new(e, nu).unwrap())
        .restitution(restitution)
        .friction(0.0)
        .build()
        .unwrap();
    let rho = 1070.0;
    let m = rho * 4.0 / 3.0 * std::f64::consts::PI * r.powi(3);
    let delta_max = tip.law().delta_max();
    let v_impact = (2.0 * 9.81 * h0).sqrt();
    let resolvable = m * 9.81 * (h0 + delta_max) < tip.law().energy(delta_max)
        && v_impact * dt / f64::from(MAX_SUBSTEPS) < delta_max;
    let fall = (2.0 * h0 / 9.81).sqrt();
    let steps = ((3.0 * fall / dt).ceil() as usize + 20).min(20_000);
    let d = drop(tip, rho as f32, h0, dt, steps);
    let what = format!("R {r:.3e} E {e:.3e} nu {nu:.3} e {restitution:.3} dt {dt:.3e} h0 {h0:.3e}");
    println!("{what}: {d:?} resolvable {resolvable}");
    (d, resolvable, what)
}

/// The random set's seed and size: `DROPS_SEED` and `DROPS_CASES` (default 40) explore others.
fn random_config() -> ProptestConfig {
    let env = |k: &str| std::env::var(k).ok().and_then(|v| v.parse::<u64>().ok());
    ProptestConfig {
        cases: env("DROPS_CASES").unwrap_or(40) as u32,
        rng_seed: RngSeed::Fixed(env("DROPS_SEED").unwrap_or(0x5eed_d70b)),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

proptest! {
    // Seeded (the same 40 drops every run): R from 1 um to 10 cm, E from 10 kPa to 10 GPa,
    // nu 0 to 0.499, e from 0.05 to 1, dt from 0.1 ms to 1/30 s, drops from 1 um to 1 m.
    #![proptest_config(random_config())]
    #[test]
    fn no_drop_rises_above_its_start(
        r in log_uniform(1e-6, 0.1),
        e in log_uniform(1e4, 1e10),
        nu in 0.0f64..0.499,
        restitution in 0.05f64..=1.0,
        dt in log_uniform(1e-4, 1.0 / 30.0),
        h0 in log_uniform(1e-6, 1.0),
    ) {
        let (d, resolvable, what) = random_drop(r, e, nu, restitution, dt, h0);
        prop_assert!(d.touched, "{}: {:?}", what, d);
        prop_assert!(
            d.rise <= 1.0 + rise_tolerance(h0, r),
            "{}: rose above its start (resolvable {}): {:?}", what, resolvable, d
        );
        prop_assert!(d.max_x < 1.0, "{}: through the plane (resolvable {}): {:?}", what, resolvable, d);
    }
}

#[test]
fn heavy_ball_dropped_a_micrometre_at_thirty_hertz() {
    let (r, h0) = (0.1, 1.17e-6);
    let (d, _, what) = random_drop(r, 1.54e7, 0.0, 0.64, 1.0 / 30.0, h0);
    assert_no_rise(&d, h0, r, &what);
}

#[test]
fn stiff_ball_dropped_24_micrometres() {
    let (r, h0) = (0.060112132861074086, 2.3619364994540738e-5);
    let (d, _, what) = random_drop(
        r,
        678032393.2302994,
        0.0,
        0.3391396486040971,
        0.02535715225123831,
        h0,
    );
    assert_no_rise(&d, h0, r, &what);
}

#[test]
fn stiff_ball_dropped_a_micrometre_at_thirty_hertz() {
    // Bounced from its start-at-rest (see `drop`) at 10-50 um above a 1.5 um drop with a
    // stored start velocity of 0: rapier's first step moved it as if it fell at 0.041 m/s.
    let (r, h0) = (0.00824475694364629, 1.547846813863218e-6);
    let (d, _, what) = random_drop(r, 7.80478442727e8, 0.0, 0.7154949456614239, 1.0 / 30.0, h0);
    assert_no_rise(&d, h0, r, &what);
}

#[test]
fn soft_ball_with_an_unsplit_step_at_the_bottom_of_its_bounce() {
    // At its deepest point (no speed, 11 times its weight) the contact is taken as resting
    // and one step is not split; giving back half of that step's impulse to the next, split,
    // step (the first form of `held_velocity`) made it rise 2-12 % above its start.
    let (r, h0) = (0.0038268680184967664, 0.0007183333149743129);
    for nu in [0.0, 0.33496903025254154] {
        let (d, _, what) = random_drop(
            r,
            104870.29189893932,
            nu,
            0.7783366661807992,
            0.0004644129628640923,
            h0,
        );
        assert_no_rise(&d, h0, r, &what);
    }
}

#[test]
fn soft_ball_through_its_equilibrium_at_a_large_step() {
    // Passing its equilibrium at 0.13 m/s (less than |g| dt) it takes an unsplit step: with
    // the carried velocity of the first form it rose to 41 times its drop.
    let (r, h0) = (0.022588262755163548, 9.894768774864107e-6);
    let (d, _, what) = random_drop(
        r,
        35092.325528118614,
        0.0,
        0.932102259749346,
        0.011903929425379881,
        h0,
    );
    assert_no_rise(&d, h0, r, &what);
}

/// Found by `DROPS_SEED=2 DROPS_CASES=100` (session 8): a 4.6 mm ball of E = 194 kPa dropped
/// 1.7 um at dt = 0.8 ms rose 65 % above its start (1.1 um, about 3 % of its 39 um resting
/// compression). It oscillates about its balance (0 to 70 um of compression, 2.5 times its
/// weight at the bottom) with little damping; at each bottom turning point its velocity was
/// below `|g| dt` and the step was taken unsplit (as resting), nearly explicit at
/// `omega dt = 0.58`, between split ones, and each such step gained energy. An unsplit step's
/// touching contacts are now implicit (`Step::prepare_state`): such a step damps.
#[test]
fn soft_ball_dropped_less_than_its_resting_compression_at_a_fine_step() {
    let (r, h0) = (0.004587784200690864, 1.6663639745840468e-6);
    let (d, _, what) = random_drop(
        r,
        193844.09039897323,
        0.0,
        0.7164047288826273,
        0.0008003256727893792,
        h0,
    );
    assert_no_rise(&d, h0, r, &what);
}

/// Micrometre to 10 um balls (nu 0.3) dropped 0.6-1 m: every combination of `dts` \[s\],
/// Young's moduli `es` \[Pa\], restitutions `rests` and `(R, drop)` pairs `sizes` \[m\].
/// Returns the number of drops and those that rose above their start, went through the plane,
/// never touched, or, perfectly elastic (e = 1: the impulsive impact's restitution is 1 at
/// every speed), came back lower than 0.99 of their drop.
fn micrometre_grid(
    dts: &[f64],
    es: &[f64],
    rests: &[f64],
    sizes: &[(f64, f64)],
) -> (usize, Vec<String>) {
    let mut bad = Vec::new();
    let mut cases = 0;
    for &dt in dts {
        for &e in es {
            for &rest in rests {
                for &(r, h0) in sizes {
                    let (d, _, what) = random_drop(r, e, 0.3, rest, dt, h0);
                    cases += 1;
                    let elastic = rest < 1.0 || d.rise >= 0.99;
                    let ok = d.touched
                        && d.rise <= 1.0 + rise_tolerance(h0, r)
                        && d.max_x < 1.0
                        && elastic;
                    if !ok {
                        bad.push(format!("{what}: {d:?}"));
                    }
                }
            }
        }
    }
    (cases, bad)
}

/// Impacts shorter than a capped substep (`random_drop`'s `resolvable` false: a micrometre
/// ball at 4.4 m/s and dt = 1/74 s travels 15 R per substep at the cap), on a grid that spans
/// the range at its hard end: R 1-10 um, drops 0.6-1 m, dt 1/74 and 1/30 s, E 10 kPa
/// to 10 GPa, e 0.9-1 (where session 24's failures were; e = 0.5, whose balls then bounce low
/// at the cap for many steps, costs 19 times as much and is in the full grid). Until session 24 such impacts were checked for a touching fall only;
/// on the full grid ([`micrometre_drops_full_grid`]) 256 of 588 failed, every one with
/// e >= 0.8: a 1 um ball of E 10 kPa, e 0.99, dropped 0.6 m at dt = 1/74 s rose to 99 times
/// its drop, at e = 1 the world faulted (a `StepError`, 2.2e17 m/s after the impact step), and
/// 10 um balls of E 10 kPa ended with their centre past the plane (x 1.3-1.6). The remedies
/// (`step::onset`, `impact` and `wall_stop`): an impact whose predicted end lies past the wall
/// within a capped substep is an impulsive impact with the fingertip's own restitution at that
/// speed; a touching contact that would pass its wall within one is stopped short of it.
/// Since session 25 the balls touch at the origin (`drop`; 1 m from it they stuck to the plane
/// in f32, e = 1 included), and an impact shorter than a capped substep whose end stays short
/// of the wall is impulsive too (`short_impact`; before, a 10 um ball of e = 1 dropped 1 m at
/// dt = 1/60 s stopped dead): every e = 1 drop must come back to at least 0.99 of its drop.
#[test]
fn micrometre_drops_do_not_rise_above_their_start() {
    let (cases, bad) = micrometre_grid(
        &[1.0 / 74.0, 1.0 / 30.0],
        &[1e4, 1e7, 1e10],
        &[0.9, 0.95, 0.99, 1.0],
        &[(1e-6, 1.0), (1e-6, 0.6), (1e-5, 1.0)],
    );
    assert_eq!(cases, 72);
    assert!(
        bad.is_empty(),
        "{} of {cases} failed:\n{}",
        bad.len(),
        bad.join("\n")
    );
}

/// [`micrometre_drops_do_not_rise_above_their_start`] on the full grid of session 24 (588
/// drops: dt 1/74, 1/60, 1/30 s, E every decade from 10 kPa to 10 GPa, e 0.05-1, four sizes):
/// 0 fail since its remedies (256 before). About 4 minutes in release, so run by hand.
#[test]
#[ignore = "588 drops, about 4 minutes in release: cargo test --release -p softgrip-rapier --test drops -- --ignored micrometre"]
fn micrometre_drops_full_grid() {
    let (cases, bad) = micrometre_grid(
        &[1.0 / 74.0, 1.0 / 60.0, 1.0 / 30.0],
        &[1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10],
        &[0.05, 0.5, 0.8, 0.9, 0.95, 0.99, 1.0],
        &[(1e-6, 1.0), (1e-6, 0.6), (3e-6, 1.0), (1e-5, 1.0)],
    );
    assert_eq!(cases, 588);
    assert!(
        bad.is_empty(),
        "{} of {cases} failed:\n{}",
        bad.len(),
        bad.join("\n")
    );
}
