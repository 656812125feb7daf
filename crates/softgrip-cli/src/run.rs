//! `softgrip run [SCENE.toml] [--out FILE.mcap]`: a scene through the bevy_ecs schedule, with
//! progress on long runs, an MCAP recording, Ctrl-C handling and a per-fingertip summary.

use std::io::Write;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use softgrip_ecs::{McapReport, McapSink, Physics, Simulation, Summary};
use softgrip_ros2::PublisherStats;
use softgrip_scene::{ContactDigest, DEFAULT_SCENE, Scene};

/// Arguments of `softgrip run`.
#[derive(Debug, Clone, clap::Args)]
pub struct RunArgs {
    /// Scene file (TOML, see crates/softgrip-scene/SCENES.md); default: the embedded grasp.
    pub scene: Option<PathBuf>,
    /// Write an MCAP recording (ROS 2 messages, see crates/softgrip-record/README.md).
    #[arg(long, value_name = "FILE.mcap")]
    pub out: Option<PathBuf>,
    /// Record every N-th step (overrides the scene's `record.every_n_steps`; 1 = every step).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
    pub every: Option<u64>,
    /// Publish every step live over ROS 2 (the recording's topics; domain from ROS_DOMAIN_ID;
    /// QoS in crates/softgrip-ros2/README.md). Paces the run at real time unless
    /// `--realtime-factor` says otherwise.
    #[arg(long)]
    pub ros2: bool,
    /// Pace the simulation at this multiple of real time (1 = real time, 0 = as fast as
    /// possible). Default: 1 with `--ros2`, else 0.
    #[arg(long, value_name = "F")]
    pub realtime_factor: Option<f64>,
    /// Print the digest of every step's contact values (`digest <hex> steps <n> contacts
    /// <m>`): the golden value crates/softgrip-cli/tests/digest.rs holds. For tests.
    #[arg(long, hide = true)]
    pub digest: bool,
}

/// Set by the Ctrl-C handler; the step loop checks it after every step.
static STOP: AtomicBool = AtomicBool::new(false);

/// Test-only: `SOFTGRIP_TEST_PANIC_AT_STEP=N` panics after step N (to test that a panic still
/// finishes the recording). Not for users.
const PANIC_AT_STEP_VAR: &str = "SOFTGRIP_TEST_PANIC_AT_STEP";

/// Exit code of a run interrupted by Ctrl-C (128 + SIGINT, as shells report it).
pub const INTERRUPTED_EXIT_CODE: u8 = 130;

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RunEnd {
    /// Every step of the scene's duration.
    Complete,
    /// Stopped by Ctrl-C (the recording is finished).
    Interrupted,
}

/// Runs the command.
pub fn run(args: &RunArgs) -> Result<RunEnd> {
    let (scene, text) = load_scene(args)?;
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
    if !(pace.is_finite() && pace >= 0.0) {
        bail!("--realtime-factor must be finite and >= 0, got {pace}");
    }
    install_ctrlc();
    println!(
        "scene {}: {} steps of {:.6} s",
        scene.origin(),
        scene.steps(),
        scene.file().dt
    );
    sim.initialize();
    let mut digest = args.digest.then(ContactDigest::new);
    let done = step_loop(&mut sim, scene.file().dt, pace, panic_at, digest.as_mut());
    sim.finish()
        .map_err(|e| anyhow::anyhow!("{e}"))
        .context("recorder")?;
    print_summary(&sim, &done);
    if let Some(d) = digest {
        println!("{d}");
    }
    print_ros2(sinks.ros2);
    if let (Some(out), Some(handle)) = (&args.out, sinks.recording) {
        print_recording(out, &handle, &done, every)?;
    }
    Ok(done.end)
}

/// The scene and its text (for the recording's metadata).
fn load_scene(args: &RunArgs) -> Result<(Scene, String)> {
    Ok(match &args.scene {
        Some(path) => {
            let scene = Scene::from_file(path)?;
            // Read again for the metadata (the scene parsed, so the file is readable).
            let text = std::fs::read_to_string(path)
                .with_context(|| format!("reading {}", path.display()))?;
            (scene, text)
        }
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
        let sink = McapSink::with_options(out, scene, text, every, &Default::default())
            .with_context(|| format!("creating the recording {}", out.display()))?;
        handles.recording = Some(sink.report_handle());
        sim = sim.with_recorder(sink);
    }
    if args.ros2 {
        let sink =
            softgrip_ros2::Ros2Sink::new(&softgrip_ecs::scene_info(scene), &Default::default())
                .context("starting the ROS 2 publisher (--ros2)")?;
        println!(
            "ros2: publishing on domain {} (node /softgrip)",
            sink.domain_id().unwrap_or_default()
        );
        handles.ros2 = Some(sink.stats_handle());
        sim = sim.with_publisher(sink);
    }
    Ok((sim, handles))
}

/// Ctrl-C sets [`STOP`] (the loop ends after the step); a second one exits at once.
fn install_ctrlc() {
    if let Err(e) = ctrlc::set_handler(|| {
        if STOP.swap(true, Ordering::SeqCst) {
            // Second Ctrl-C: give up at once (closed chunks stay readable: `softgrip inspect`
            // recovers them).
            std::process::exit(i32::from(INTERRUPTED_EXIT_CODE));
        }
    }) {
        eprintln!("warning: no Ctrl-C handler ({e}); Ctrl-C will not finish the recording");
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

/// Steps the scene's duration (or until Ctrl-C), paced at `pace` times real time (0 = as fast
/// as possible), with progress on stderr on long runs; adds every step to `digest`.
fn step_loop(
    sim: &mut Simulation,
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
        sim.step();
        steps += 1;
        if let Some(d) = digest.as_deref_mut() {
            d.add_step(sim.world.resource::<Physics>().world.soft.contacts().iter());
        }
        if pace > 0.0 {
            // Real-time pacing (for live publishing): wait until the wall clock reaches the
            // simulated time of this step, divided by the factor.
            let due = start + Duration::from_secs_f64(steps as f64 * dt / pace);
            let now = Instant::now();
            if due > now {
                std::thread::sleep(due - now);
            }
        }
        if panic_at == Some(steps) {
            panic!("{PANIC_AT_STEP_VAR}: test panic after step {steps}");
        }
        progress.show(steps, total);
        if STOP.load(Ordering::SeqCst) && steps < total {
            end = RunEnd::Interrupted;
            break;
        }
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
    if done.end == RunEnd::Interrupted {
        println!(
            "interrupted at t = {:.4} s (step {steps} of {total})",
            steps as f64 * done.dt
        );
    }
    for (_, tip) in &sim.world.resource::<Summary>().tips {
        println!("fingertip {tip}");
    }
    let sim_time = steps as f64 * done.dt;
    println!(
        "wall time {:.3} s, simulated {:.3} s, real-time factor {:.1}",
        done.wall.as_secs_f64(),
        sim_time,
        sim_time / done.wall.as_secs_f64().max(1e-12)
    );
}

/// The ROS 2 publisher's counts (`--ros2`).
fn print_ros2(stats: Option<Arc<Mutex<Option<PublisherStats>>>>) {
    let published = stats.and_then(|h| *h.lock().unwrap_or_else(|e| e.into_inner()));
    if let Some(s) = published {
        println!(
            "ros2: {} steps published, {} dropped (queue full), {} publish failures",
            s.published, s.dropped, s.publish_failures
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
    println!(
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
