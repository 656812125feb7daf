//! Where a grasp step's time goes (issue 23 item 3): the default grasp through the path users
//! take (the scene parsed and built, the bevy_ecs schedule of `softgrip run`), split into the
//! plugin's parts (`SoftCounters`' timers) and the schedule's sets (a marker system between
//! each), per step in microseconds and as a share of the whole step.
//!
//! ```sh
//! cargo run --release -p softgrip-ecs --example profile_grasp [-- [SCENE.toml] [--runs N]]
//! ```
//!
//! Two columns: **trial**, the run of a `softgrip sweep` trial (`sweeps/throughput.toml`'s is
//! the default scene with another squeeze depth and box density: the summary, no recording)
//! and **run --out**, the README's main command (the summary and the MCAP recorder every
//! `record.every_n_steps`-th step, to a temporary file). Each figure is the least over
//! `--runs` runs (default 7) of the run's time per step (on a shared machine a run preempted
//! inside one part charges that part a whole time slice; the least is the undisturbed cost);
//! "whole step" is the least of the runs' `Simulation::step` wall time. Wall time of this
//! thread: the recorder compresses and writes on its own thread, which is not counted (see
//! the crate README of softgrip-record). The plugin's parts are timed with
//! `SoftContacts::set_profiling(true)`.
//!
//! The tactile images are laid on their first read (the recorder's, on the steps it takes): a
//! marker system reads them first on those steps, so their cost is its own line and the
//! recorder's read finds them laid. The plugin's parts are the `SoftCounters` timers
//! (`detect_time`, `rows_time`, ...); "plugin, the rest" is `step_time` minus those parts (the
//! kinematic paths, the gravity bookkeeping of split steps, the state checks).

#![allow(missing_docs)]

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use softgrip_ecs::bevy_ecs::prelude::{IntoScheduleConfigs, Res, ResMut, Resource};
use softgrip_ecs::softgrip_rapier::SoftCounters;
use softgrip_ecs::systems::{assemble_frame, physics_step, readout, record, sync_to_rapier};
use softgrip_ecs::{
    McapSink, Physics, Recorder, Scene, SimClock, Simulation, SoftgripSystems, accumulate_summary,
};
use softgrip_scene::DEFAULT_SCENE;

/// The ECS parts, in schedule order: each ends at a marker system.
const ECS_PARTS: [&str; 6] = [
    "ECS: sync and controllers",
    "ECS: physics system (the plugin's step below)",
    "ECS: readout and summary",
    "tactile images (laid on the recorder's steps)",
    "ECS: frame assembled",
    "ECS: recorder (MCAP messages; compression on its thread)",
];

/// Marker times of the step in progress and the sums per part.
#[derive(Resource, Default)]
struct Marks {
    last: Option<Instant>,
    sums: [Duration; ECS_PARTS.len()],
}

impl Marks {
    fn mark(&mut self, part: usize) {
        let now = Instant::now();
        if let Some(last) = self.last {
            self.sums[part] += now - last;
        }
        self.last = Some(now);
    }
}

fn start(mut m: ResMut<Marks>) {
    m.last = Some(Instant::now());
}
fn after_control(mut m: ResMut<Marks>) {
    m.mark(0);
}
fn after_physics(mut m: ResMut<Marks>) {
    m.mark(1);
}
fn after_readout(mut m: ResMut<Marks>) {
    m.mark(2);
}
/// Lays the tactile images on the steps the recorder takes (its read then finds them laid).
fn tactile(
    mut m: ResMut<Marks>,
    physics: Res<Physics>,
    clock: Res<SimClock>,
    recorder: Option<Res<Recorder>>,
) {
    if recorder.is_some_and(|r| r.0.wants(clock.step)) {
        for (_, image) in physics.world.soft.tactile_images() {
            std::hint::black_box(image);
        }
    }
    m.mark(3);
}
fn after_frame(mut m: ResMut<Marks>) {
    m.mark(4);
}
fn after_record(mut m: ResMut<Marks>) {
    m.mark(5);
}

/// One run's figures per step [us]: the whole step, the ECS parts, the plugin's parts; and
/// per run [us]: the scene parsed from its text, the simulation built and initialised.
struct RunTimes {
    parse: f64,
    build: f64,
    whole: f64,
    ecs: [f64; ECS_PARTS.len()],
    plugin: Vec<(&'static str, f64)>,
}

/// The plugin's parts per step [us] from its counters.
fn plugin_parts(c: &SoftCounters, steps: f64) -> Vec<(&'static str, f64)> {
    let us = |d: Duration| d.as_secs_f64() * 1e6 / steps;
    let parts = [
        ("detection (`detect_time`)", c.detect_time),
        (
            "rows and bodies: joints, multibodies (`rows_time`)",
            c.rows_time,
        ),
        ("rigid supports gathered (`supports_time`)", c.supports_time),
        ("law response, contact memory (`law_time`)", c.law_time),
        (
            "soft solve, coupled with supports and joints (`soft_solve_time`)",
            c.soft_solve_time,
        ),
        ("impulses applied and checked (`apply_time`)", c.apply_time),
        (
            "readout: sums and contacts (`readout_time`)",
            c.readout_time,
        ),
        ("rapier's pipeline (`pipeline_time`)", c.pipeline_time),
    ];
    let named: Duration = parts.iter().map(|p| p.1).sum();
    let mut v: Vec<_> = parts.iter().map(|&(n, d)| (n, us(d))).collect();
    v.push(("plugin, the rest", us(c.step_time.saturating_sub(named))));
    v.push(("plugin step (`step_time`)", us(c.step_time)));
    v
}

/// One run of `text` (its relative paths from `base`), recorded or not.
fn run_once(text: &str, base: &Path, recorded: bool) -> RunTimes {
    let t = Instant::now();
    let scene = Scene::parse(text, "<profile>", base).expect("the scene parsed in `main`");
    let parse = t.elapsed().as_secs_f64() * 1e6;
    let scene = &scene;
    let t = Instant::now();
    let mut sim = Simulation::new(scene).with_summary();
    let mut dir_made = None;
    if recorded {
        let dir = std::env::temp_dir().join(format!("profile_grasp_{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temporary directory");
        let path: PathBuf = dir.join("run.mcap");
        let _ = std::fs::remove_file(&path);
        let every = scene.file().record.every_n_steps.max(1);
        let sink = McapSink::with_options(&path, scene, text, every, &Default::default())
            .expect("recorder");
        sim = sim.with_recorder(sink);
        dir_made = Some(dir);
    }
    sim.world.insert_resource(Marks::default());
    {
        use SoftgripSystems as S;
        let s = sim.schedule_mut();
        s.add_systems(start.before(sync_to_rapier).in_set(S::Sync));
        s.add_systems(after_control.before(physics_step).in_set(S::Physics));
        s.add_systems(after_physics.before(readout).in_set(S::Readout));
        s.add_systems(
            after_readout
                .after(readout)
                .after(accumulate_summary)
                .in_set(S::Readout),
        );
        s.add_systems(tactile.before(assemble_frame).in_set(S::Record));
        s.add_systems(
            after_frame
                .after(tactile)
                .after(assemble_frame)
                .before(record)
                .in_set(S::Record),
        );
        s.add_systems(
            after_record
                .after(after_frame)
                .after(record)
                .in_set(S::Record),
        );
    }
    sim.initialize();
    let build = t.elapsed().as_secs_f64() * 1e6;
    sim.world
        .resource_mut::<Physics>()
        .world
        .soft
        .set_profiling(true);
    let steps = sim.total_steps();
    let mut whole = Duration::ZERO;
    for _ in 0..steps {
        let t = Instant::now();
        sim.step();
        whole += t.elapsed();
    }
    sim.finish().expect("recording finished");
    if let Some(dir) = &dir_made {
        let _ = std::fs::remove_dir_all(dir);
    }
    let n = steps as f64;
    let marks = sim.world.resource::<Marks>();
    let counters = *sim.world.resource::<Physics>().world.soft.counters();
    RunTimes {
        parse,
        build,
        whole: whole.as_secs_f64() * 1e6 / n,
        ecs: marks.sums.map(|d| d.as_secs_f64() * 1e6 / n),
        plugin: plugin_parts(&counters, n),
    }
}

/// The least of each line over the runs (on a shared machine each part's least disturbed
/// figure; a run preempted inside one part charges that part a whole time slice), in the
/// table's order; the schedule's overhead is the least whole step minus the least parts.
fn lines(runs: &[RunTimes]) -> Vec<(String, f64)> {
    let least = |f: &dyn Fn(&RunTimes) -> f64| runs.iter().map(f).fold(f64::INFINITY, f64::min);
    let mut out = vec![(
        "whole step (`Simulation::step`)".to_string(),
        least(&|r| r.whole),
    )];
    for (i, name) in ECS_PARTS.iter().enumerate() {
        out.push((name.to_string(), least(&|r| r.ecs[i])));
        if i == 1 {
            for (j, (name, _)) in runs[0].plugin.iter().enumerate() {
                out.push((format!("- {name}"), least(&|r| r.plugin[j].1)));
            }
        }
    }
    let parts: f64 = out[1..]
        .iter()
        .filter(|(n, _)| !n.starts_with("- "))
        .map(|p| p.1)
        .sum();
    out.push((
        "schedule overhead (whole step minus the parts)".to_string(),
        out[0].1 - parts,
    ));
    out
}

/// The median of `v`.
fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut runs = 7;
    let mut path = None;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        if a == "--runs" {
            runs = args.next().ok_or("--runs needs a number")?.parse()?;
        } else {
            path = Some(PathBuf::from(a));
        }
    }
    let (scene, text) = match &path {
        Some(p) => Scene::from_file_with_text(p)?,
        None => (Scene::default_scene(), DEFAULT_SCENE.to_string()),
    };
    let base = path
        .as_deref()
        .and_then(Path::parent)
        .unwrap_or(Path::new("."))
        .to_path_buf();
    let runs = runs.max(1);
    let trial: Vec<_> = (0..runs).map(|_| run_once(&text, &base, false)).collect();
    let out: Vec<_> = (0..runs).map(|_| run_once(&text, &base, true)).collect();
    let (a, b) = (lines(&trial), lines(&out));
    let dt = scene.file().dt;
    println!(
        "{} steps of dt = {dt} s, the least of {runs} runs each; us per step (share of the whole step)",
        scene.steps()
    );
    println!("| part | trial (summary) | run --out (summary, MCAP) |");
    println!("|---|---:|---:|");
    for ((name, x), (_, y)) in a.iter().zip(&b) {
        println!(
            "| {name} | {x:.1} ({:.1} %) | {y:.1} ({:.1} %) |",
            100.0 * x / a[0].1,
            100.0 * y / b[0].1
        );
    }
    let per_run = |f: fn(&RunTimes) -> f64, r: &[RunTimes]| median(r.iter().map(f).collect());
    println!(
        "per run (median), us: scene parsed {:.0} / {:.0}, simulation built {:.0} / {:.0} (trial / run --out)",
        per_run(|r| r.parse, &trial),
        per_run(|r| r.parse, &out),
        per_run(|r| r.build, &trial),
        per_run(|r| r.build, &out)
    );
    println!(
        "real time: trial {:.0}x, run --out {:.0}x",
        dt * 1e6 / a[0].1,
        dt * 1e6 / b[0].1
    );
    Ok(())
}
