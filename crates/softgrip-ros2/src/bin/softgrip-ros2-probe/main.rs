//! `softgrip-ros2-probe`: publishes a scripted squeeze on softgrip's ROS 2 topics, in a loop,
//! and prints (as JSON lines on stdout) what arrives on `/softgrip/command`. For checking a
//! ROS 2 setup by hand (`ros2 topic echo /softgrip/contacts`) and for the DDS round-trip test.
//!
//! `softgrip-ros2-probe [--timeout-s 60] [--period-ms 10] [--linger-ms 1000]`: stops
//! `linger-ms` after the first command arrived (exit 0), or at the timeout (exit 3). The
//! domain is `ROS_DOMAIN_ID`'s.

mod script;

use std::process::ExitCode;
use std::time::{Duration, Instant};

use serde_json::json;
use softgrip_record::msgs::geometry_msgs::WrenchStamped;
use softgrip_ros2::{
    COMMAND_TOPIC, NodeOptions, Ros2Publisher, Ros2PublisherOptions, Ros2Subscriber, qos,
};

fn arg(args: &[String], name: &str, default: f64) -> Result<f64, String> {
    match args.iter().position(|a| a == name) {
        None => Ok(default),
        Some(i) => args
            .get(i + 1)
            .and_then(|v| v.parse().ok())
            .filter(|v: &f64| v.is_finite() && *v >= 0.0)
            .ok_or_else(|| format!("{name} needs a number >= 0")),
    }
}

fn run() -> Result<bool, Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let timeout = Duration::from_secs_f64(arg(&args, "--timeout-s", 60.0)?);
    let period = Duration::from_secs_f64(arg(&args, "--period-ms", 10.0)? * 1e-3);
    let linger = Duration::from_secs_f64(arg(&args, "--linger-ms", 1000.0)? * 1e-3);

    let publisher = Ros2Publisher::new(&Ros2PublisherOptions::default())?;
    let commands = Ros2Subscriber::<WrenchStamped>::new(
        &NodeOptions {
            name: "softgrip_probe".into(),
            ..Default::default()
        },
        COMMAND_TOPIC,
        qos::data(),
    )?;
    println!(
        "{}",
        json!({"event": "ready", "domain_id": publisher.domain_id()})
    );

    let start = Instant::now();
    let mut received: Option<Instant> = None;
    let mut k = 0;
    loop {
        let now = Instant::now();
        match received {
            Some(t) if now - t >= linger => break,
            None if now - start >= timeout => break,
            _ => {}
        }
        publisher.publish_step_owned(script::step(k % script::STEPS))?;
        k += 1;
        let next = now + period;
        while let Some(cmd) =
            commands.recv_timeout(next.saturating_duration_since(Instant::now()))?
        {
            if received.is_none() {
                received = Some(Instant::now());
                println!("{}", json!({"event": "command", "message": cmd}));
            }
        }
    }
    let stats = publisher.close(Duration::from_secs(2))?;
    println!(
        "{}",
        json!({
            "event": "done",
            "steps_submitted": stats.submitted,
            "steps_published": stats.published,
            "steps_dropped": stats.dropped,
            "publish_failures": stats.publish_failures,
            "seconds": start.elapsed().as_secs_f64(),
        })
    );
    Ok(received.is_some())
}

fn main() -> ExitCode {
    match run() {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => {
            eprintln!("softgrip-ros2-probe: no message on {COMMAND_TOPIC} before the timeout");
            ExitCode::from(3)
        }
        Err(e) => {
            eprintln!("softgrip-ros2-probe: {e}");
            ExitCode::FAILURE
        }
    }
}
