//! The softgrip and rapier side of the peers' comparison (`tools/peers/`): prints one JSON
//! object per line, read by `tools/peers/peers.py`, which adds MuJoCo and Drake and prints the
//! table. Single-threaded (rapier is built without `parallel`).
//!
//! ```text
//! cargo run --release -p softgrip-bench --example peers_softgrip [squeeze] [rapier] [fem] [resting] [resting-sleep]
//! ```
//!
//! With no argument every part runs. The parts:
//!
//! - `squeeze`: the quasi-static squeeze of `softgrip_testkit::scenes::PlateSqueeze` (a
//!   dynamic fingertip ball, R = 10 mm, E = 3 MPa, nu = 0.49, e = 1, between a fixed floor and
//!   a kinematic plate moving down at 1 mm/s, dt = 1/60 s) to x = 0.61 per contact, for every
//!   level of `Level::ALL`. Each sample is `(x, F)`: x = half the plate approach over R (the FE
//!   reference's definition: one plate's approach), F = the mean of the plate's and the
//!   floor's normal force (their difference is the ball's weight).
//! - `rapier`: the same scene with the ball *not* registered: rapier's own rigid contact,
//!   whose only compliance is its constraint softness (`IntegrationParameters::contact_softness`
//!   and `static_contact_softness`, a natural frequency and a damping ratio). Its natural
//!   frequency is tuned (bisection, both softnesses equal, damping ratio left at rapier's 10)
//!   so that the held force at x = 0.05 equals Hertz's; then the squeeze runs with it.
//!   `length_unit` = R, as rapier asks for a scene of that size (at 1 m its allowed linear
//!   error alone is 5 mm, x = 0.5).
//! - `fem`: rapier's own FEM soft body (NeoHookean tetrahedral ball,
//!   `softgrip_bench::fem_ball`) in the same squeeze: at real scale and in the rescaled set-up
//!   of `plugin_tables` (R = 1, mass x 1e6).
//! - `resting`: N = 1, 10, 100, 1000 fingertips resting on a fixed ground
//!   (`softgrip_bench::overhead::OverheadScene`, settled 120 steps), softgrip and rapier's own
//!   contacts, µs per step (best of 3 rounds, and the median of a fourth round's single
//!   steps, each timed alone). The balls never sleep (`can_sleep(false)`). `replayed`: the
//!   share of softgrip's timed single steps that the resting fast path replayed
//!   (`SoftContacts::set_rest_replay`; `SOFTGRIP_REST_REPLAY=off` in the environment turns it
//!   off, for its A/B in one binary).
//! - `resting-sleep`: the same with the balls allowed to sleep (rapier's default thresholds),
//!   asleep once settled (kind `resting_sleep`; `peers.py` puts it beside MuJoCo with its
//!   sleeping enabled).
//! - `grasp-law`: the default scene's fingertip law (Dragon Skin 30, E = 0.59 MPa, nu = 0.49,
//!   R = 10 mm, `flat` backing, `auto`) at the squeeze depths of `sweeps/throughput.toml`, the
//!   grip MuJoCo's grasp is matched to.

use std::time::{Duration, Instant};

use rapier3d::prelude::*;
use softgrip_bench::fem_ball::FemSqueeze;
use softgrip_bench::overhead::OverheadScene;
use softgrip_law::{Backing, ContactLaw, ContactParams, Level, Material};
use softgrip_rapier::SoftWorld;
use softgrip_testkit::scenes::{DENSITY, PlateSqueeze, RADIUS, fingertip};

/// Plate speed of the squeeze [m/s].
const SPEED: f64 = 0.001;
/// Compression ratio per contact where the squeeze stops (just past 0.6, the compared range's end).
const X_END: f64 = 0.61;
/// Compression ratio where rapier's softness is matched to Hertz.
const X_MATCH: f64 = 0.05;
/// Young's modulus \[Pa\] and Poisson ratio of the fingertip.
const E: f64 = 3.0e6;
/// Poisson ratio of the fingertip.
const NU: f64 = 0.49;

fn main() -> anyhow::Result<()> {
    let parts: Vec<String> = std::env::args().skip(1).collect();
    let wants = |p: &str| parts.is_empty() || parts.iter().any(|a| a == p);
    if wants("squeeze") {
        for level in Level::ALL {
            softgrip_squeeze(level);
        }
    }
    if wants("rapier") {
        rapier_squeeze()?;
    }
    if wants("fem") {
        fem_squeeze();
    }
    if wants("resting") {
        resting(false);
    }
    if wants("resting-sleep") {
        resting(true);
    }
    if wants("grasp-law") {
        grasp_law()?;
    }
    Ok(())
}

/// A JSON array of numbers (finite ones; others as `null`).
fn json_array(v: &[f64]) -> String {
    let items: Vec<String> = v
        .iter()
        .map(|x| {
            if x.is_finite() {
                format!("{x:.6e}")
            } else {
                "null".to_string()
            }
        })
        .collect();
    format!("[{}]", items.join(","))
}

/// A JSON string (the notes here hold no control characters; quotes and backslashes escaped).
fn json_str(s: &str) -> String {
    format!("\"{}\"", s.replace('\\', "\\\\").replace('"', "\\\""))
}

/// One squeeze's samples and cost, printed as one JSON line.
struct SqueezeRecord<'a> {
    peer: &'a str,
    variant: &'a str,
    /// Step \[s\].
    dt: f64,
    steps: usize,
    /// Wall time of the steps alone.
    wall: Duration,
    /// Compression ratios x of the samples.
    xs: &'a [f64],
    /// Normal force \[N\] at each sample.
    fs: &'a [f64],
    note: &'a str,
}

impl SqueezeRecord<'_> {
    fn print(&self) {
        println!(
            "{{\"kind\":\"squeeze\",\"peer\":{},\"variant\":{},\"dt\":{:.6e},\"steps\":{},\
             \"us_per_step\":{:.4},\"x\":{},\"force\":{},\"note\":{}}}",
            json_str(self.peer),
            json_str(self.variant),
            self.dt,
            self.steps,
            self.wall.as_secs_f64() * 1e6 / self.steps.max(1) as f64,
            json_array(self.xs),
            json_array(self.fs),
            json_str(self.note)
        );
    }
}

/// softgrip's squeeze with `level` to [`X_END`].
fn softgrip_squeeze(level: Level) {
    let tip = fingertip(level, 1.0)
        .build()
        .expect("invariant: valid fingertip");
    let mut s = PlateSqueeze::new(tip);
    let dt = s.world.physics.integration_parameters.dt as f64;
    let (mut xs, mut fs) = (Vec::new(), Vec::new());
    let (mut steps, mut wall) = (0usize, Duration::ZERO);
    while (2.0 * RADIUS - (s.plate_bottom() - SPEED * dt)) / (2.0 * RADIUS) <= X_END {
        s.lower_plate(SPEED * dt);
        let t = Instant::now();
        s.world.step();
        wall += t.elapsed();
        steps += 1;
        let x = (2.0 * RADIUS - s.plate_bottom()) / (2.0 * RADIUS);
        let contacts = s.world.soft.contacts();
        let on = |other| {
            contacts
                .iter()
                .find(|c| c.other == other)
                .map_or(0.0, |c| c.normal_force)
        };
        xs.push(x);
        fs.push(0.5 * (on(s.plate) + on(s.floor)));
    }
    SqueezeRecord {
        peer: "softgrip",
        variant: level.name(),
        dt,
        steps,
        wall,
        xs: &xs,
        fs: &fs,
        note: "rapier 0.36 + softgrip plugin, kinematic plate at 1 mm/s",
    }
    .print();
}

/// The rigid-ball squeeze scene in rapier's own contacts: a fixed floor (top at y = 0), a
/// dynamic ball (R, density [`DENSITY`]) and a kinematic plate, both contacts squeezed to `x0`.
struct RigidSqueeze {
    world: SoftWorld,
    floor: ColliderHandle,
    ball: ColliderHandle,
    plate_body: RigidBodyHandle,
    plate: ColliderHandle,
}

impl RigidSqueeze {
    const HALF: f64 = 0.005;

    /// The scene squeezed to `x0`, the softness's natural frequency `natural_frequency` \[Hz\];
    /// `uncapped` lifts rapier's cap on the penetration-correcting velocity
    /// (`normalized_max_corrective_velocity`, 3 length units per second by default).
    fn new(natural_frequency: f32, x0: f64, uncapped: bool) -> Self {
        let r = RADIUS;
        let mut world = SoftWorld::new();
        let p = &mut world.physics.integration_parameters;
        p.length_unit = r as f32;
        if uncapped {
            p.normalized_max_corrective_velocity = 1.0e6;
        }
        p.contact_softness.natural_frequency = natural_frequency;
        p.static_contact_softness.natural_frequency = natural_frequency;
        let floor = world.physics.colliders.insert(
            ColliderBuilder::cuboid(0.1, 0.01, 0.1).translation(Vector::new(0.0, -0.01, 0.0)),
        );
        let body = world.physics.bodies.insert(
            RigidBodyBuilder::dynamic()
                .translation(Vector::new(0.0, (r - x0 * r) as f32, 0.0))
                .can_sleep(false),
        );
        let ball = world.physics.colliders.insert_with_parent(
            ColliderBuilder::ball(r as f32).density(DENSITY),
            body,
            &mut world.physics.bodies,
        );
        let plate_body =
            world
                .physics
                .bodies
                .insert(
                    RigidBodyBuilder::kinematic_position_based().translation(Vector::new(
                        0.0,
                        (2.0 * r - 2.0 * x0 * r + Self::HALF) as f32,
                        0.0,
                    )),
                );
        let plate = world.physics.colliders.insert_with_parent(
            ColliderBuilder::cuboid(0.05, Self::HALF as f32, 0.05),
            plate_body,
            &mut world.physics.bodies,
        );
        Self {
            world,
            floor,
            ball,
            plate_body,
            plate,
        }
    }

    fn plate_bottom(&self) -> f64 {
        self.world.physics.bodies[self.plate_body].translation().y as f64 - Self::HALF
    }

    /// The mean of the two contacts' normal force over the last step \[N\].
    fn force(&self) -> f64 {
        let dt = self.world.physics.integration_parameters.dt as f64;
        let on = |other| {
            self.world
                .physics
                .narrow_phase
                .contact_pair(other, self.ball)
                .map_or(0.0, |p| p.total_impulse().length() as f64)
                / dt
        };
        0.5 * (on(self.plate) + on(self.floor))
    }
}

/// The held force of rapier's rigid ball squeezed to `x` with `natural_frequency` \[N\]: the
/// mean over the last 60 of 240 steps.
fn rapier_held_force(natural_frequency: f32, x: f64, uncapped: bool) -> f64 {
    let mut s = RigidSqueeze::new(natural_frequency, x, uncapped);
    let mut sum = 0.0;
    for i in 0..240 {
        s.world.physics.step();
        if i >= 180 {
            sum += s.force();
        }
    }
    sum / 60.0
}

/// Both rapier rows: the velocity cap as rapier sets it, and lifted.
fn rapier_squeeze() -> anyhow::Result<()> {
    rapier_squeeze_with(false)?;
    rapier_squeeze_with(true)
}

/// Tunes rapier's contact natural frequency to Hertz at [`X_MATCH`], then squeezes.
fn rapier_squeeze_with(uncapped: bool) -> anyhow::Result<()> {
    let params = ContactParams::try_new(Material::try_new(E, NU)?, RADIUS)?;
    let hertz = ContactLaw::try_new(params, Level::Hertz)?;
    let target = hertz.response(X_MATCH * RADIUS).force;
    // Bisection in log(frequency); the held force grows with the frequency.
    let (mut lo, mut hi) = (1.0f64, 1.0e5f64);
    let (f_lo, f_hi) = (
        rapier_held_force(lo as f32, X_MATCH, uncapped),
        rapier_held_force(hi as f32, X_MATCH, uncapped),
    );
    let matched = f_lo <= target && target <= f_hi;
    if matched {
        for _ in 0..40 {
            let mid = (lo * hi).sqrt();
            if rapier_held_force(mid as f32, X_MATCH, uncapped) < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }
    let freq = if matched { (lo * hi).sqrt() } else { hi };
    let held = rapier_held_force(freq as f32, X_MATCH, uncapped);
    let mut s = RigidSqueeze::new(freq as f32, 0.02, uncapped);
    for _ in 0..120 {
        s.world.physics.step();
    }
    let dt = s.world.physics.integration_parameters.dt as f64;
    let (mut xs, mut fs) = (Vec::new(), Vec::new());
    let (mut steps, mut wall) = (0usize, Duration::ZERO);
    while (2.0 * RADIUS - (s.plate_bottom() - SPEED * dt)) / (2.0 * RADIUS) <= X_END {
        let y = s.world.physics.bodies[s.plate_body].translation().y as f64;
        s.world.physics.bodies[s.plate_body].set_next_kinematic_translation(Vector::new(
            0.0,
            (y - SPEED * dt) as f32,
            0.0,
        ));
        let t = Instant::now();
        s.world.physics.step();
        wall += t.elapsed();
        steps += 1;
        xs.push((2.0 * RADIUS - s.plate_bottom()) / (2.0 * RADIUS));
        fs.push(s.force());
    }
    let cap = if uncapped {
        "normalized_max_corrective_velocity = 1e6 (rapier's cap of 3 length units/s lifted)"
    } else {
        "rapier's cap on the correcting velocity left at 3 length units/s"
    };
    let unmatched = if matched {
        ""
    } else {
        ", NOT matched: out of the frequency range 1..1e5 Hz"
    };
    let note = format!(
        "rigid ball, rapier's contact softness natural_frequency = {freq:.4} Hz (both contact_softness and \
         static_contact_softness; damping_ratio 10, rapier's default), tuned by bisection so that the held \
         force at x = {X_MATCH} is Hertz's {target:.4} N (got {held:.4} N{unmatched}); length_unit = R; {cap}; \
         F = ContactPair::total_impulse / dt"
    );
    SqueezeRecord {
        peer: "rapier",
        variant: if uncapped {
            "rigid ball, contact softness, velocity cap lifted"
        } else {
            "rigid ball, contact softness"
        },
        dt,
        steps,
        wall,
        xs: &xs,
        fs: &fs,
        note: &note,
    }
    .print();
    println!(
        "{{\"kind\":\"rapier_match\",\"uncapped\":{uncapped},\"natural_frequency_hz\":{freq:.6e},\
         \"target_force\":{target:.6e},\"held_force\":{held:.6e},\"matched\":{matched}}}"
    );
    Ok(())
}

/// rapier's FEM ball in the squeeze, at real scale and rescaled as in `plugin_tables`.
fn fem_squeeze() {
    let samples: &'static [f32] = &[0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6];
    let base = FemSqueeze {
        radius: 1.0,
        young_modulus: E as f32,
        poisson_ratio: NU as f32,
        subdivisions: 2,
        cell_size: 0.5,
        mass: 0.0,
        solver: SoftBodySolver::Fem,
        speed: 0.1,
        dt: 1.0 / 60.0,
        samples,
    };
    let real_mass = DENSITY * 4.0 / 3.0 * std::f32::consts::PI * (RADIUS as f32).powi(3);
    let e_star = E / (1.0 - NU * NU);
    let runs = [
        ("SI, R = 10 mm, real mass", RADIUS as f32, real_mass),
        (
            "R = 1 (x100), 1e4 x dynamically real mass",
            1.0,
            real_mass * 100.0 * 1.0e4,
        ),
    ];
    for (name, radius, mass) in runs {
        let cfg = FemSqueeze {
            radius,
            mass,
            ..base
        };
        let variant = format!("FEM ball ({name})");
        match cfg.run() {
            Some(r) => {
                let xs: Vec<f64> = r.force.iter().map(|p| p.0).collect();
                // f = F/(E* R_eff^2) back to newtons at R = 10 mm (f at fixed x is scale-free).
                let fs: Vec<f64> = r
                    .force
                    .iter()
                    .map(|p| 0.5 * (p.1 + p.2) * e_star * RADIUS * RADIUS)
                    .collect();
                let note = format!(
                    "rapier SoftBodyCellModel::NeoHookean, {} particles, {} cells ({} with rest volume <= f32::EPSILON), \
                     dt = 1/60, plate 0.1 R/s; force = mean of plate and ground ContactPair::total_impulse / dt, \
                     scaled to R = 10 mm by E* R^2",
                    r.particles, r.cells, r.degenerate_cells
                );
                SqueezeRecord {
                    peer: "rapier",
                    variant: &variant,
                    dt: cfg.dt as f64,
                    steps: r.steps,
                    wall: r.wall,
                    xs: &xs,
                    fs: &fs,
                    note: &note,
                }
                .print();
            }
            None => SqueezeRecord {
                peer: "rapier",
                variant: &variant,
                dt: cfg.dt as f64,
                steps: 0,
                wall: Duration::ZERO,
                xs: &[],
                fs: &[],
                note: "the tetrahedral fill failed",
            }
            .print(),
        }
    }
}

/// N fingertips resting: softgrip and rapier's own contacts, µs per step (wall, and the
/// thread's CPU time where Linux reports it: on a shared machine the wall time of a round
/// includes the time other processes held the core).
///
/// With `sleep`, the balls may sleep (`OverheadScene::new_sleeping`; asleep once settled),
/// printed as kind `resting_sleep`.
fn resting(sleep: bool) {
    let (kind, new): (_, fn(usize, bool) -> OverheadScene) = if sleep {
        ("resting_sleep", OverheadScene::new_sleeping)
    } else {
        ("resting", OverheadScene::new)
    };
    for n in [1usize, 10, 100, 1000] {
        let steps = (20_000 / n).clamp(60, 2000);
        let mut rigid = new(n, false);
        let mut soft = new(n, true);
        // `SOFTGRIP_REST_REPLAY=off`: the plugin's resting fast path off (the A/B of its cost;
        // the physics is bit for bit the same either way).
        let replay = std::env::var("SOFTGRIP_REST_REPLAY").map_or(true, |v| v != "off");
        soft.world.soft.set_rest_replay(replay);
        let (mut best_rigid, mut best_soft) = ([f64::MAX; 2], [f64::MAX; 2]);
        for _ in 0..3 {
            for (scene, best) in [(&mut rigid, &mut best_rigid), (&mut soft, &mut best_soft)] {
                let cpu = thread_cpu_seconds();
                let (w, _) = scene.measure(steps);
                best[0] = best[0].min(w.as_secs_f64() / steps as f64);
                if let (Some(a), Some(b)) = (cpu, thread_cpu_seconds()) {
                    best[1] = best[1].min((b - a) / steps as f64);
                }
            }
        }
        // Then one more round of single steps, timed one by one: their median (a round's mean
        // on a loaded machine carries every preemption that fell in it).
        let before = *soft.world.soft.counters();
        let medians = [&mut soft, &mut rigid].map(|scene| median_step(scene, steps));
        let after = soft.world.soft.counters();
        // The share of the timed single steps the fast path replayed (softgrip's line).
        let replayed = (after.replayed_steps - before.replayed_steps) as f64
            / (after.steps - before.steps).max(1) as f64;
        for (((peer, [us, cpu]), median), replayed) in
            [("softgrip", best_soft), ("rapier", best_rigid)]
                .into_iter()
                .zip(medians)
                .zip([replayed, 0.0])
        {
            let cpu = if cpu < f64::MAX {
                format!("{:.4}", cpu * 1e6)
            } else {
                "null".to_string()
            };
            println!(
                "{{\"kind\":\"{kind}\",\"peer\":\"{peer}\",\"n\":{n},\"dt\":{:.6e},\"steps\":{steps},\
                 \"us_per_step\":{:.4},\"cpu_us_per_step\":{cpu},\"median_us_per_step\":{:.4},\
                 \"replayed\":{replayed:.3}}}",
                1.0 / 60.0,
                us * 1e6,
                median * 1e6
            );
        }
    }
}

/// The median wall time \[s\] of `steps` single steps of `scene`, each timed alone.
fn median_step(scene: &mut OverheadScene, steps: usize) -> f64 {
    let mut times: Vec<f64> = (0..steps)
        .map(|_| {
            let t = Instant::now();
            scene.step();
            t.elapsed().as_secs_f64()
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// The CPU time this thread has run \[s\] (`/proc/thread-self/schedstat`, in ns), if the
/// system reports it.
fn thread_cpu_seconds() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: u64 = s.split_whitespace().next()?.parse().ok()?;
    Some(ns as f64 * 1e-9)
}

/// The default scene's fingertip law at the throughput sweep's squeeze depths.
fn grasp_law() -> anyhow::Result<()> {
    let params = ContactParams::try_new(Material::try_new(0.59e6, 0.49)?, RADIUS)?
        .with_backing(Backing::Flat)?;
    let law = ContactLaw::try_new(params, Level::auto())?;
    let depths = [
        0.0005, 0.00075, 0.001, 0.00125, 0.0015, 0.00175, 0.002, 0.00225,
    ];
    let forces: Vec<f64> = depths.iter().map(|&d| law.response(d).force).collect();
    println!(
        "{{\"kind\":\"grasp_law\",\"depth\":{},\"force\":{}}}",
        json_array(&depths),
        json_array(&forces)
    );
    Ok(())
}
