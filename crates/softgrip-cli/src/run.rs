//! `softgrip run [SCENE.toml] [--out FILE.mcap]`: a scene through the bevy_ecs schedule, with
//! progress on long runs, an MCAP recording, Ctrl-C handling and a per-fingertip summary.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use softgrip_ecs::{Controllers, McapReport, McapSink, Physics, Simulation, Summary};
use softgrip_record::RecorderOptions;
use softgrip_record::units::{si, sig};

use crate::gripper_action::GripperActions;
use crate::joint_commands::{CommandBridge, Route, Routes};
use softgrip_ros2::PublisherStats;
use softgrip_scene::{ContactDigest, DEFAULT_SCENE, Scene};

use crate::files::check_output;
use crate::out::outln;
use crate::signals::Stop;

/// Arguments of `softgrip run`.
#[derive(Debug, Clone, clap::Args)]
pub struct RunArgs {
    /// Scene file (TOML, see crates/softgrip-scene/SCENES.md), `-` for standard input (read
    /// once; mesh and curve paths then relative to the current folder); default: the embedded
    /// grasp.
    pub scene: Option<PathBuf>,
    /// Write an MCAP recording (ROS 2 messages, see crates/softgrip-record/README.md).
    #[arg(long, value_name = "FILE.mcap")]
    pub out: Option<PathBuf>,
    /// Overwrite `--out` if it exists (never one of the run's inputs).
    #[arg(long)]
    pub force: bool,
    /// Record every N-th step (overrides the scene's `record.every_n_steps`; 1 = every step).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
    pub every: Option<u64>,
    /// Publish every step live over ROS 2 (the recording's topics; domain from ROS_DOMAIN_ID;
    /// QoS in crates/softgrip-ros2/README.md). Paces the run at real time unless
    /// `--realtime-factor` says otherwise.
    #[arg(long)]
    pub ros2: bool,
    /// Pace the simulation at this multiple of real time (1 = real time, 0 = as fast as
    /// possible; else from 0.001 to 1000). Default: 1 with `--ros2`, else 0.
    #[arg(long, value_name = "F", value_parser = parse_realtime_factor)]
    pub realtime_factor: Option<f64>,
    /// With `--ros2` and robots in the scene: the topic joint commands come in on
    /// (`sensor_msgs/JointState`: position and/or velocity targets by joint name,
    /// `<robot>/<joint>` with several robots).
    #[arg(long, value_name = "TOPIC", default_value = crate::joint_commands::DEFAULT_TOPIC)]
    pub joint_commands: String,
    /// Print the digest of every step's contact values (`digest <hex> steps <n> contacts
    /// <m>`): the golden value crates/softgrip-cli/tests/digest.rs holds. For tests.
    #[arg(long, hide = true)]
    pub digest: bool,
}

/// Test-only: `SOFTGRIP_TEST_PANIC_AT_STEP=N` panics after step N (to test that a panic still
/// finishes the recording). Not for users.
const PANIC_AT_STEP_VAR: &str = "SOFTGRIP_TEST_PANIC_AT_STEP";

/// Smallest and largest `--realtime-factor` other than 0.
pub const REALTIME_FACTOR_RANGE: (f64, f64) = (1e-3, 1e3);

/// `--realtime-factor`: 0, or finite in [`REALTIME_FACTOR_RANGE`].
fn parse_realtime_factor(s: &str) -> Result<f64, String> {
    let (lo, hi) = REALTIME_FACTOR_RANGE;
    let v: f64 = s.parse().map_err(|_| format!("`{s}` is not a number"))?;
    if v == 0.0 || (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(format!(
            "must be 0 (as fast as possible) or from {lo} to {hi} (multiples of real time), got {s}"
        ))
    }
}

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RunEnd {
    /// Every step of the scene's duration.
    Complete,
    /// Stopped by this signal (SIGINT, SIGTERM or SIGHUP; the recording is finished).
    Interrupted(i32),
    /// Stopped by a step that failed (`Simulation::fault`; the recording is finished with
    /// every step before it). `run` returns it as its error.
    Diverged,
}

/// Runs the command.
pub fn run(args: &RunArgs) -> Result<RunEnd> {
    // Before anything is read or written: a signal from now on finishes the recording.
    let stop = Stop::install();
    slow_start_for_tests();
    let (scene, text) = load_scene(args)?;
    if let Some(out) = &args.out {
        let inputs = inputs(args.scene.as_deref(), &scene);
        let inputs: Vec<&Path> = inputs.iter().map(PathBuf::as_path).collect();
        check_output(out, &inputs, args.force)?;
    }
    let panic_at = panic_at_step()?;
    let every = args
        .every
        .unwrap_or(scene.file().record.every_n_steps)
        .max(1);
    let (mut sim, sinks) = attach_sinks(
        Simulation::new(&scene).with_summary(),
        args,
        &scene,
        &text,
        every,
    )?;
    let pace = args
        .realtime_factor
        .unwrap_or(if args.ros2 { 1.0 } else { 0.0 });
    outln!(
        "scene {}: {} steps of {:.6} s",
        scene.origin(),
        scene.steps(),
        scene.file().dt
    );
    sim.initialize();
    let (bridge, actions) = if args.ros2 {
        (
            start_commands(&mut sim, &args.joint_commands)?,
            start_gripper_actions(&mut sim)?,
        )
    } else {
        (None, None)
    };
    let mut digest = args.digest.then(ContactDigest::new);
    let done = step_loop(
        &mut sim,
        &stop,
        scene.file().dt,
        pace,
        panic_at,
        digest.as_mut(),
    );
    sim.finish()
        .map_err(|e| anyhow::anyhow!("{e}"))
        .context("recorder")?;
    print_summary(&sim, &done);
    if let Some(d) = digest {
        outln!("{d}");
    }
    print_ros2(sinks.ros2);
    if let Some(b) = bridge {
        let topic = b.topic().to_owned();
        let c = b.finish()?;
        outln!(
            "ros2: {} joint command messages on {topic}: {} joint targets applied, {} refused",
            c.messages,
            c.routed,
            c.refused
        );
        for (name, why) in &c.refused_names {
            outln!("ros2: joint command `{name}` refused: {why}");
        }
    }
    if let Some(a) = actions {
        let names = a.names().join(", ");
        let c = a.finish()?;
        outln!(
            "ros2: gripper actions {names}: {} goals accepted ({} reached, {} stalled), {} refused",
            c.accepted,
            c.reached,
            c.stalled,
            c.rejected
        );
    }
    if let (Some(out), Some(handle)) = (&args.out, sinks.recording) {
        print_recording(out, &handle, &done, every)?;
    }
    if let Some(e) = sim.fault().filter(|_| done.end == RunEnd::Diverged) {
        // Printed by `main` as `error: ...`, exit code 1, after the summary and recording.
        return Err(anyhow::Error::new(e.clone()));
    }
    Ok(done.end)
}

/// The scene and its text as read (for the recording's metadata): the file is read once, so
/// a pipe (`/dev/stdin`, `-`) gives its text to both (it was read twice, and the recorded
/// text was empty).
fn load_scene(args: &RunArgs) -> Result<(Scene, String)> {
    Ok(match &args.scene {
        Some(path) if path.as_os_str() == "-" => {
            let text = softgrip_scene::read_text_from(std::io::stdin().lock(), "<stdin>")?;
            (Scene::parse(&text, "<stdin>", Path::new("."))?, text)
        }
        Some(path) => Scene::from_file_with_text(path)?,
        None => (Scene::default_scene(), DEFAULT_SCENE.to_string()),
    })
}

/// The step after which to panic ([`PANIC_AT_STEP_VAR`]), if set.
fn panic_at_step() -> Result<Option<u64>> {
    match std::env::var(PANIC_AT_STEP_VAR) {
        Ok(v) => Ok(Some(v.parse().with_context(|| {
            format!("{PANIC_AT_STEP_VAR}={v}: not a step number")
        })?)),
        Err(_) => Ok(None),
    }
}

/// Subscribes to joint commands for the scene's robots (none: nothing to command).
fn start_commands(sim: &mut Simulation, topic: &str) -> Result<Option<CommandBridge>> {
    let Some(mut controllers) = sim.world.get_resource_mut::<Controllers>() else {
        return Ok(None);
    };
    let set = &mut controllers.0;
    let robots: Vec<(String, Vec<String>)> = (set.robots().iter())
        .map(|r| {
            let joints = (r.joints().iter())
                .filter(|j| j.kind.moves() && j.mimic.is_none())
                .map(|j| j.name.clone());
            (r.name().to_owned(), joints.collect())
        })
        .collect();
    let routes: Routes = (robots.into_iter().enumerate())
        .filter_map(|(i, (robot, joints))| {
            let inbox = set.inbox(i)?;
            Some(Route {
                robot,
                joints,
                inbox,
            })
        })
        .collect();
    if routes.is_empty() {
        return Ok(None);
    }
    let bridge = CommandBridge::start(topic, routes)?;
    outln!("ros2: joint commands from {topic} (sensor_msgs/JointState)");
    Ok(Some(bridge))
}

/// Serves `control_msgs/action/ParallelGripperCommand` for each gripper group (none: no robot).
fn start_gripper_actions(sim: &mut Simulation) -> Result<Option<GripperActions>> {
    let Some(mut controllers) = sim.world.get_resource_mut::<Controllers>() else {
        return Ok(None);
    };
    let groups = crate::gripper_action::groups(&mut controllers.0);
    if groups.is_empty() {
        return Ok(None);
    }
    let actions = GripperActions::start(groups)?;
    outln!(
        "ros2: gripper actions {} (control_msgs/action/ParallelGripperCommand)",
        actions.names().join(", ")
    );
    Ok(Some(actions))
}

/// What the sinks report after the run.
struct SinkHandles {
    /// The MCAP recorder's report (`--out`).
    recording: Option<Arc<Mutex<McapReport>>>,
    /// The ROS 2 publisher's counts (`--ros2`).
    ros2: Option<Arc<Mutex<Option<PublisherStats>>>>,
}

/// Adds the MCAP recorder (`--out`, every `every`-th step) and the ROS 2 publisher (`--ros2`).
fn attach_sinks(
    mut sim: Simulation,
    args: &RunArgs,
    scene: &Scene,
    text: &str,
    every: u64,
) -> Result<(Simulation, SinkHandles)> {
    let mut handles = SinkHandles {
        recording: None,
        ros2: None,
    };
    if let Some(out) = &args.out {
        // Without --force, created only if still absent: a file that appeared since the
        // check is an error, never replaced.
        let options = RecorderOptions {
            create_new: !args.force,
            ..Default::default()
        };
        let sink = McapSink::with_options(out, scene, text, every, &options)?;
        handles.recording = Some(sink.report_handle());
        sim = sim.with_recorder(sink);
    }
    if args.ros2 {
        let sink =
            softgrip_ros2::Ros2Sink::new(&softgrip_ecs::scene_info(scene), &Default::default())
                .context("starting the ROS 2 publisher (--ros2)")?;
        outln!(
            "ros2: publishing on domain {} (node /softgrip)",
            sink.domain_id().unwrap_or_default()
        );
        handles.ros2 = Some(sink.stats_handle());
        sim = sim.with_publisher(sink);
    }
    Ok((sim, handles))
}

/// The files a run reads: the scene, its meshes and its measured curves.
fn inputs(scene_path: Option<&Path>, scene: &Scene) -> Vec<PathBuf> {
    (scene_path.filter(|p| p.as_os_str() != "-"))
        .map(Path::to_path_buf)
        .into_iter()
        .chain(scene.input_files())
        .collect()
}

/// Test-only: `SOFTGRIP_TEST_SLOW_START_MS=N` waits N ms before the scene is read (a slow
/// start, to test that a signal then still finishes the run). Not for users.
fn slow_start_for_tests() {
    if let Some(ms) = std::env::var("SOFTGRIP_TEST_SLOW_START_MS")
        .ok()
        .and_then(|v| v.parse().ok())
    {
        std::thread::sleep(Duration::from_millis(ms));
    }
}

/// How the step loop ended.
struct Done {
    /// Steps taken.
    steps: u64,
    /// Steps of the scene's duration.
    total: u64,
    /// Time step \[s\].
    dt: f64,
    /// Wall-clock time of the loop.
    wall: Duration,
    /// Complete or interrupted.
    end: RunEnd,
}

/// Steps the scene's duration (or until a signal in `stop`), paced at `pace` times real time (0 = as fast
/// as possible), with progress on stderr on long runs; adds every step to `digest`.
fn step_loop(
    sim: &mut Simulation,
    stop: &Stop,
    dt: f64,
    pace: f64,
    panic_at: Option<u64>,
    mut digest: Option<&mut ContactDigest>,
) -> Done {
    let total = sim.total_steps();
    let start = Instant::now();
    let mut progress = Progress::new(start);
    let mut steps = 0;
    let mut end = RunEnd::Complete;
    while steps < total {
        if let Some(sig) = stop.received() {
            end = RunEnd::Interrupted(sig);
            break;
        }
        sim.step();
        if sim.fault().is_some() {
            // Not read out, recorded or published (the schedule stops at a fault).
            end = RunEnd::Diverged;
            break;
        }
        steps += 1;
        if let Some(d) = digest.as_deref_mut() {
            d.add_step(sim.world.resource::<Physics>().world.soft.contacts().iter());
        }
        if pace > 0.0 {
            // Real-time pacing (for live publishing): wait until the wall clock reaches the
            // simulated time of this step, divided by the factor.
            // (A wait too long for a `Duration` is no wait at all: the factor's range keeps it
            // far from that.)
            let wait = Duration::try_from_secs_f64(steps as f64 * dt / pace).ok();
            let now = Instant::now();
            if let Some(due) = wait.and_then(|w| start.checked_add(w))
                && due > now
            {
                std::thread::sleep(due - now);
            }
        }
        if panic_at == Some(steps) {
            panic!("{PANIC_AT_STEP_VAR}: test panic after step {steps}");
        }
        progress.show(steps, total);
    }
    let wall = start.elapsed();
    progress.finish();
    Done {
        steps,
        total,
        dt,
        wall,
        end,
    }
}

/// Progress on stderr, only on long runs (after one second), four times a second.
struct Progress {
    start: Instant,
    last: Instant,
    shown: bool,
}

impl Progress {
    fn new(start: Instant) -> Self {
        Self {
            start,
            last: start,
            shown: false,
        }
    }

    fn show(&mut self, steps: u64, total: u64) {
        let now = Instant::now();
        if now - self.start > Duration::from_secs(1) && now - self.last > Duration::from_millis(250)
        {
            self.last = now;
            self.shown = true;
            eprint!(
                "\r{:5.1} % (step {steps}/{total})",
                100.0 * steps as f64 / total as f64
            );
            std::io::stderr().flush().ok();
        }
    }

    /// Ends the progress line, if one was shown.
    fn finish(&self) {
        if self.shown {
            eprintln!();
        }
    }
}

/// The interruption, each fingertip's summary, and the wall time.
fn print_summary(sim: &Simulation, done: &Done) {
    let (steps, total) = (done.steps, done.total);
    if let RunEnd::Interrupted(sig) = done.end {
        outln!(
            "interrupted at t = {:.4} s (step {steps} of {total}) by {}",
            steps as f64 * done.dt,
            crate::signals::name(sig)
        );
    }
    if let (RunEnd::Diverged, Some(e)) = (done.end, sim.fault()) {
        outln!(
            "diverged at t = {:.4} s (step {} of {total}): {e}",
            e.time(),
            steps + 1
        );
    }
    for (_, tip) in &sim.world.resource::<Summary>().tips {
        outln!("fingertip {tip}");
    }
    let sim_time = steps as f64 * done.dt;
    let wall = done.wall.as_secs_f64();
    // `sig` and `si` print "n/a" rather than inf or NaN (a wall time below the clock's
    // resolution, a huge dt).
    outln!(
        "wall time {}, simulated {}, real-time factor {}",
        si(wall, "s"),
        si(sim_time, "s"),
        sig(if wall > 0.0 {
            sim_time / wall
        } else {
            f64::NAN
        })
    );
}

/// The ROS 2 publisher's counts (`--ros2`).
fn print_ros2(stats: Option<Arc<Mutex<Option<PublisherStats>>>>) {
    let published = stats.and_then(|h| *h.lock().unwrap_or_else(|e| e.into_inner()));
    if let Some(s) = published {
        outln!(
            "ros2: {} steps published, {} dropped (queue full), {} publish failures",
            s.published,
            s.dropped,
            s.publish_failures
        );
    }
}

/// What the recorder wrote (`--out`); an error if it did not finish the file.
fn print_recording(
    out: &std::path::Path,
    handle: &Mutex<McapReport>,
    done: &Done,
    every: u64,
) -> Result<()> {
    let r = handle.lock().unwrap_or_else(|e| e.into_inner()).clone();
    let Some(stats) = r.stats else {
        bail!("{}: the recording was not finished", out.display());
    };
    let size = std::fs::metadata(out).map(|m| m.len()).unwrap_or(0);
    let wall = done.wall.as_secs_f64();
    outln!(
        "recorded {} of {} steps (every {every}) to {}: {} messages, {} chunks, {} bytes; writing took {:.1} ms ({:.1} % of the wall time)",
        r.frames_written,
        done.steps,
        out.display(),
        stats.messages,
        stats.chunks,
        size,
        r.write_time.as_secs_f64() * 1e3,
        100.0 * r.write_time.as_secs_f64() / wall.max(1e-12)
    );
    Ok(())
}
