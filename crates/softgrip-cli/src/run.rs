//! `softgrip run [SCENE.toml] [--out FILE.mcap]`: a scene through the bevy_ecs schedule, with
//! progress on long runs, an MCAP recording, Ctrl-C handling and a per-fingertip summary.

use std::io::Write;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use anyhow::{Context, Result, bail};
use softgrip_ecs::scene::DEFAULT_SCENE;
use softgrip_ecs::{McapSink, Scene, Simulation, Summary};

use crate::ros2_sink::Ros2Sink;

/// Arguments of `softgrip run`.
#[derive(Debug, Clone, clap::Args)]
pub struct RunArgs {
    /// Scene file (TOML, see crates/softgrip-ecs/SCENES.md); default: the embedded grasp.
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
    let (scene, text) = match &args.scene {
        Some(path) => {
            let scene = Scene::from_file(path)?;
            // Read again for the metadata (the scene parsed, so the file is readable).
            let text = std::fs::read_to_string(path)
                .with_context(|| format!("reading {}", path.display()))?;
            (scene, text)
        }
        None => (Scene::default_scene(), DEFAULT_SCENE.to_string()),
    };
    let panic_at: Option<u64> = match std::env::var(PANIC_AT_STEP_VAR) {
        Ok(v) => Some(
            v.parse()
                .with_context(|| format!("{PANIC_AT_STEP_VAR}={v}: not a step number"))?,
        ),
        Err(_) => None,
    };
    let mut sim = Simulation::new(&scene).with_summary();
    let every = args
        .every
        .unwrap_or(scene.file().record.every_n_steps)
        .max(1);
    let mut report_handle = None;
    if let Some(out) = &args.out {
        let sink = McapSink::with_options(out, &scene, &text, every, &Default::default())
            .with_context(|| format!("creating the recording {}", out.display()))?;
        report_handle = Some(sink.report_handle());
        sim = sim.with_recorder(sink);
    }
    let mut ros2_stats = None;
    if args.ros2 {
        let sink = Ros2Sink::new(&scene).context("starting the ROS 2 publisher (--ros2)")?;
        println!(
            "ros2: publishing on domain {} (node /softgrip)",
            sink.domain_id().unwrap_or_default()
        );
        ros2_stats = Some(sink.stats_handle());
        sim = sim.with_publisher(sink);
    }
    let pace = args
        .realtime_factor
        .unwrap_or(if args.ros2 { 1.0 } else { 0.0 });
    if !(pace.is_finite() && pace >= 0.0) {
        bail!("--realtime-factor must be finite and >= 0, got {pace}");
    }
    if let Err(e) = ctrlc::set_handler(|| {
        if STOP.swap(true, Ordering::SeqCst) {
            // Second Ctrl-C: give up at once (closed chunks stay readable: `softgrip inspect`
            // recovers them).
            std::process::exit(i32::from(INTERRUPTED_EXIT_CODE));
        }
    }) {
        eprintln!("warning: no Ctrl-C handler ({e}); Ctrl-C will not finish the recording");
    }
    println!(
        "scene {}: {} steps of {:.6} s",
        scene.origin(),
        scene.steps(),
        scene.file().dt
    );
    sim.initialize();
    let dt = scene.file().dt;
    let total = sim.total_steps();
    let start = Instant::now();
    let mut last = start;
    let mut shown = false;
    let mut steps = 0;
    let mut end = RunEnd::Complete;
    while steps < total {
        sim.step();
        steps += 1;
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
        // Progress only on long runs (after one second), four times a second, on stderr.
        let now = Instant::now();
        if now - start > Duration::from_secs(1) && now - last > Duration::from_millis(250) {
            last = now;
            shown = true;
            eprint!(
                "\r{:5.1} % (step {steps}/{total})",
                100.0 * steps as f64 / total as f64
            );
            std::io::stderr().flush().ok();
        }
        if STOP.load(Ordering::SeqCst) && steps < total {
            end = RunEnd::Interrupted;
            break;
        }
    }
    let wall = start.elapsed();
    if shown {
        eprintln!();
    }
    sim.finish()
        .map_err(|e| anyhow::anyhow!("{e}"))
        .context("recorder")?;
    if end == RunEnd::Interrupted {
        println!(
            "interrupted at t = {:.4} s (step {steps} of {total})",
            steps as f64 * dt
        );
    }
    for (_, tip) in &sim.world.resource::<Summary>().tips {
        println!("fingertip {tip}");
    }
    let sim_time = steps as f64 * dt;
    println!(
        "wall time {:.3} s, simulated {:.3} s, real-time factor {:.1}",
        wall.as_secs_f64(),
        sim_time,
        sim_time / wall.as_secs_f64().max(1e-12)
    );
    let published = ros2_stats.and_then(|h| *h.lock().unwrap_or_else(|e| e.into_inner()));
    if let Some(s) = published {
        println!(
            "ros2: {} steps published, {} dropped (queue full), {} publish failures",
            s.published, s.dropped, s.publish_failures
        );
    }
    if let (Some(out), Some(handle)) = (&args.out, report_handle) {
        let r = handle.lock().unwrap_or_else(|e| e.into_inner()).clone();
        let Some(stats) = r.stats else {
            bail!("{}: the recording was not finished", out.display());
        };
        let size = std::fs::metadata(out).map(|m| m.len()).unwrap_or(0);
        println!(
            "recorded {} of {steps} steps (every {every}) to {}: {} messages, {} chunks, {} bytes; writing took {:.1} ms ({:.1} % of the wall time)",
            r.frames_written,
            out.display(),
            stats.messages,
            stats.chunks,
            size,
            r.write_time.as_secs_f64() * 1e3,
            100.0 * r.write_time.as_secs_f64() / wall.as_secs_f64().max(1e-12)
        );
    }
    Ok(end)
}
