//! `softgrip inspect FILE.mcap`: topics, duration, per-fingertip peaks, slip events and
//! validity excursions of a recording, its laws and controllers; says so when an unfinished
//! file was recovered.

use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::PathBuf;

use anyhow::Result;
use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
use softgrip_record::units::{si, sig};
use softgrip_record::{Recording, RecordingInfo, TipRunSummary};

use super::{contact_radius, contacts, fingertips, info, laws, open, seconds};

/// Arguments of `softgrip inspect`.
#[derive(Debug, Clone, clap::Args)]
pub struct InspectArgs {
    /// The recording (MCAP, written by `softgrip run --out`).
    pub file: PathBuf,
}

/// One fingertip's findings.
#[derive(Debug, Clone, Default)]
struct TipFindings {
    peak_force: f64,
    peak_force_t: f64,
    peak_x: f64,
    peak_x_t: f64,
    peak_radius: f64,
    slips: Vec<f64>,
    excursions: Vec<f64>,
}

/// Runs the command.
pub fn inspect(args: &InspectArgs) -> Result<()> {
    let rec = open(&args.file)?;
    crate::out::text(&report(&args.file.display().to_string(), &rec));
    Ok(())
}

fn times(ts: &[f64]) -> String {
    const SHOWN: usize = 8;
    let mut s: Vec<String> = ts.iter().take(SHOWN).map(|t| format!("{t:.4}")).collect();
    if ts.len() > SHOWN {
        s.push(format!("... ({} more)", ts.len() - SHOWN));
    }
    if s.is_empty() {
        String::new()
    } else {
        format!(" at t = {} s", s.join(", "))
    }
}

/// The report, as printed.
fn report(name: &str, rec: &Recording) -> String {
    let mut out = String::new();
    let info = info(rec);
    write_header(&mut out, name, rec, &info);
    let run_summary = rec.run_summary().ok().flatten();
    let mut found = findings(rec);
    for tip in fingertips(rec) {
        let f = found.remove(&tip).unwrap_or_default();
        let counted = run_summary.as_ref().and_then(|s| s.tip(&tip));
        write_tip(&mut out, &tip, &f, counted);
    }
    if !info.law.is_empty() {
        let _ = writeln!(out, "law:");
        for law in &info.law {
            let _ = writeln!(out, "  {law}");
        }
    }
    // `name: kind (code N)`, in the order they ran (none in recordings made before session 10).
    if !info.controllers.is_empty() {
        let _ = writeln!(out, "controllers:");
        for c in &info.controllers {
            let _ = writeln!(out, "  {c}");
        }
    }
    out
}

/// The first lines: what the file is, whether it was recovered, its messages and topics.
fn write_header(out: &mut String, name: &str, rec: &Recording, info: &RecordingInfo) {
    let or_unknown = |s: &str| {
        if s.is_empty() {
            "?".to_owned()
        } else {
            s.to_owned()
        }
    };
    let every = match info.every_n_steps {
        0 => "?".to_owned(),
        n => n.to_string(),
    };
    let _ = writeln!(
        out,
        "{name}: softgrip {} recording of {} (every {every} step(s))",
        or_unknown(&info.softgrip_version),
        or_unknown(&info.origin)
    );
    if let Some(r) = &rec.recovery {
        let _ = writeln!(
            out,
            "recovered: {} chunks, {} bytes of {} (the file was not finished: {})",
            r.chunks, r.bytes_kept, r.file_len, r.stopped_because
        );
    }
    let (t0, t1) = match (rec.messages.first(), rec.messages.last()) {
        (Some(a), Some(b)) => (seconds(a.log_time_ns), seconds(b.log_time_ns)),
        _ => (0.0, 0.0),
    };
    let _ = writeln!(
        out,
        "messages: {}, chunks: {}, time {t0:.4} .. {t1:.4} s (duration {:.4} s)",
        rec.messages.len(),
        rec.chunk_count,
        t1 - t0
    );
    let _ = writeln!(out, "topics:");
    for c in &rec.channels {
        let _ = writeln!(
            out,
            "  {:<28} {:<40} {:>7} messages",
            c.topic, c.schema_name, c.message_count
        );
    }
}

/// Per fingertip: peaks, and the slip and excursion events of the recorded steps.
fn findings(rec: &Recording) -> HashMap<String, TipFindings> {
    let laws = laws(rec);
    let law_cache: HashMap<String, _> = fingertips(rec)
        .into_iter()
        .map(|t| {
            let l = laws.iter().find(|l| l.name == t).and_then(|l| l.law().ok());
            (t, l)
        })
        .collect();
    let mut found: HashMap<String, TipFindings> = HashMap::new();
    // Slip and excursion events: a contact (fingertip, other) that starts sliding (or past the
    // validity range) in a recorded step where it did not in the previous recorded step.
    let mut state: HashMap<(String, String), (bool, bool, f64)> = HashMap::new();
    let mut last_t = f64::NAN;
    for (t, c) in contacts(rec) {
        if t != last_t {
            // A contact missing from a recorded step has ended: forget it.
            state.retain(|_, s| s.2 == last_t);
            last_t = t;
        }
        let f = found.entry(c.fingertip.clone()).or_default();
        if c.peak_normal_force > f.peak_force {
            f.peak_force = c.peak_normal_force;
            f.peak_force_t = t;
        }
        // Peak x: the step's largest compression (`max_compression`, every substep and the
        // end of the step) over R, as the run summary counts it.
        let law = law_cache.get(&c.fingertip).and_then(Option::as_ref);
        let x = max_x(c, law);
        if x > f.peak_x {
            f.peak_x = x;
            f.peak_x_t = t;
            f.peak_radius = match law {
                Some(l) => l.patch(c.max_compression.max(c.compression)).radius,
                None => contact_radius(c, None),
            };
        }
        let key = (c.fingertip.clone(), c.other.clone());
        let (was_sliding, was_past, _) = state.get(&key).copied().unwrap_or((false, false, t));
        if c.sliding && !was_sliding {
            f.slips.push(t);
        }
        if c.validity_exceeded && !was_past {
            f.excursions.push(t);
        }
        state.insert(key, (c.sliding, c.validity_exceeded, t));
    }
    found
}

/// A recorded contact's largest compression ratio of its step: `max_compression / R` (R from
/// `compression / ratio_x`, else the law's in the metadata), never below `ratio_x`.
fn max_x(c: &SoftContactMsg, law: Option<&softgrip_law::ContactLaw>) -> f64 {
    let radius = (c.ratio_x > 0.0)
        .then(|| c.compression / c.ratio_x)
        .or_else(|| law.map(|l| l.delta_max() / l.x_max()))
        .filter(|r| r.is_finite() && *r > 0.0);
    match radius {
        Some(r) => (c.max_compression / r).max(c.ratio_x),
        None => c.ratio_x,
    }
}

/// A fingertip's two lines; `counted` is the run's own summary of it, if the file has one.
fn write_tip(out: &mut String, tip: &str, f: &TipFindings, counted: Option<&TipRunSummary>) {
    let _ = writeln!(
        out,
        "fingertip {tip}: peak force {} (t = {:.4} s), peak x {} (t = {:.4} s), contact radius at peak x {}",
        si(f.peak_force, "N"),
        f.peak_force_t,
        sig(f.peak_x),
        f.peak_x_t,
        si(f.peak_radius, "m")
    );
    // The run's own counts cover every step; the recording may hold every n-th only, and
    // a slip or excursion shorter than n steps falls between recorded steps.
    let events = |all: Option<u32>, seen: &[f64]| match all {
        Some(all) => format!(
            "{all} (every step; {} in the recorded steps{})",
            seen.len(),
            times(seen)
        ),
        None => format!("{} (in the recorded steps){}", seen.len(), times(seen)),
    };
    let _ = writeln!(
        out,
        "  slip events: {}; validity excursions: {}",
        events(counted.map(|c| c.slips), &f.slips),
        events(counted.map(|c| c.validity_excursions), &f.excursions)
    );
}
