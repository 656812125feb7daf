//! `softgrip export FILE.mcap --csv DIR`: one CSV file per topic family, with units in the
//! headers: `contacts.csv` (every `SoftContactMsg` field), `wrenches.csv`, `poses.csv`,
//! `clock.csv`. (`/softgrip/markers` is for 3D views and is not exported.) Each file's row is a
//! serde struct written by the `csv` crate (its field names are the header).
//!
//! The four files are written whole or not at all: into temporary files beside them, put in
//! place together at the end. SIGINT, SIGTERM or SIGHUP during the export removes the
//! temporary files and exits 128 + the signal with nothing written (a CSV cut mid-row was
//! left before).

use std::fs::File;
use std::io::{BufWriter, Write};
use std::marker::PhantomData;
use std::path::{Path, PathBuf};

use anyhow::{Context, Result, anyhow};
use serde::Serialize;
use softgrip_record::msgs::geometry_msgs::TransformStamped;
use softgrip_record::msgs::softgrip_msgs::SoftContactMsg;
use softgrip_record::{Message, Recording, topics};

use super::{fingertips, open, seconds};
use crate::files::{Output, check_output, commit_all};
use crate::signals::Stop;

/// Arguments of `softgrip export`.
#[derive(Debug, Clone, clap::Args)]
pub struct ExportArgs {
    /// The recording (MCAP).
    pub file: PathBuf,
    /// Directory for the CSV files (created if needed).
    #[arg(long, value_name = "DIR")]
    pub csv: PathBuf,
    /// Overwrite CSV files that exist in DIR.
    #[arg(long)]
    pub force: bool,
}

/// The files `export` writes into its directory.
const FILES: [&str; 4] = ["contacts.csv", "wrenches.csv", "poses.csv", "clock.csv"];

/// A row of `contacts.csv`: every field of a `SoftContactMsg`, at its log time.
#[derive(Serialize, Default)]
struct ContactRow<'a> {
    time_s: f64,
    fingertip: &'a str,
    other: &'a str,
    point_x_m: f64,
    point_y_m: f64,
    point_z_m: f64,
    normal_x: f64,
    normal_y: f64,
    normal_z: f64,
    compression_m: f64,
    ratio_x: f64,
    #[serde(rename = "normal_force_N")]
    normal_force: f64,
    #[serde(rename = "friction_force_x_N")]
    friction_force_x: f64,
    #[serde(rename = "friction_force_y_N")]
    friction_force_y: f64,
    #[serde(rename = "friction_force_z_N")]
    friction_force_z: f64,
    #[serde(rename = "torsional_moment_Nm")]
    torsional_moment: f64,
    contact_radius_m: f64,
    #[serde(rename = "mean_pressure_Pa")]
    mean_pressure: f64,
    #[serde(rename = "peak_pressure_Pa")]
    peak_pressure: f64,
    #[serde(rename = "stiffness_N_per_m")]
    stiffness: f64,
    level: u8,
    level_name: &'a str,
    /// 0 or 1.
    validity_exceeded: u8,
    /// 0 or 1.
    sliding: u8,
    #[serde(rename = "peak_normal_force_N")]
    peak_normal_force: f64,
    max_compression_m: f64,
    contact_duration_s: f64,
}

impl<'a> ContactRow<'a> {
    fn new(time_s: f64, c: &'a SoftContactMsg) -> Self {
        Self {
            time_s,
            fingertip: &c.fingertip,
            other: &c.other,
            point_x_m: c.point.x,
            point_y_m: c.point.y,
            point_z_m: c.point.z,
            normal_x: c.normal.x,
            normal_y: c.normal.y,
            normal_z: c.normal.z,
            compression_m: c.compression,
            ratio_x: c.ratio_x,
            normal_force: c.normal_force,
            friction_force_x: c.friction_force.x,
            friction_force_y: c.friction_force.y,
            friction_force_z: c.friction_force.z,
            torsional_moment: c.torsional_moment,
            contact_radius_m: c.contact_radius,
            mean_pressure: c.mean_pressure,
            peak_pressure: c.peak_pressure,
            stiffness: c.stiffness,
            level: c.level,
            level_name: &c.level_name,
            validity_exceeded: u8::from(c.validity_exceeded),
            sliding: u8::from(c.sliding),
            peak_normal_force: c.peak_normal_force,
            max_compression_m: c.max_compression,
            contact_duration_s: c.contact_duration,
        }
    }
}

/// A row of `wrenches.csv`.
#[derive(Serialize, Default)]
#[allow(non_snake_case)] // the unit in the column name: N, N m
struct WrenchRow<'a> {
    time_s: f64,
    fingertip: &'a str,
    topic: &'a str,
    force_x_N: f64,
    force_y_N: f64,
    force_z_N: f64,
    torque_x_Nm: f64,
    torque_y_Nm: f64,
    torque_z_Nm: f64,
}

/// A row of `poses.csv`.
#[derive(Serialize, Default)]
struct PoseRow<'a> {
    time_s: f64,
    parent_frame: &'a str,
    frame: &'a str,
    x_m: f64,
    y_m: f64,
    z_m: f64,
    qx: f64,
    qy: f64,
    qz: f64,
    qw: f64,
}

impl<'a> PoseRow<'a> {
    fn new(time_s: f64, p: &'a TransformStamped) -> Self {
        let (v, q) = (&p.transform.translation, &p.transform.rotation);
        Self {
            time_s,
            parent_frame: &p.header.frame_id,
            frame: &p.child_frame_id,
            x_m: v.x,
            y_m: v.y,
            z_m: v.z,
            qx: q.x,
            qy: q.y,
            qz: q.z,
            qw: q.w,
        }
    }
}

/// A row of `clock.csv`.
#[derive(Serialize, Default)]
struct ClockRow {
    log_time_s: f64,
    clock_s: f64,
}

/// One CSV file of rows `R` being written (into its [`Output`]'s temporary file), and its row
/// count.
struct Table<R> {
    output: Output,
    writer: csv::Writer<BufWriter<File>>,
    rows: usize,
    _row: PhantomData<fn(R)>,
}

/// The CSV writer of softgrip's exports: `\n` line ends, fields quoted only when needed.
fn builder() -> csv::WriterBuilder {
    let mut b = csv::WriterBuilder::new();
    b.terminator(csv::Terminator::Any(b'\n'));
    b
}

/// Messages exported between two looks at the signal flag.
const SIGNAL_CHECK_EVERY: usize = 256;

impl<R: Serialize + Default> Table<R> {
    /// Starts `dir/name` with its header line (the field names of `R`), so that a file with
    /// no rows still says what its columns are.
    fn create(dir: &Path, name: &'static str, inputs: &[PathBuf], force: bool) -> Result<Self> {
        let mut output = Output::create(&dir.join(name), inputs, force)?;
        let path = output.path().to_path_buf();
        let mut header = builder().from_writer(Vec::new());
        header.serialize(R::default())?;
        let header = header.into_inner().context("CSV header")?;
        let end = header
            .iter()
            .position(|&b| b == b'\n')
            .map_or(header.len(), |i| i + 1);
        let file = output
            .file()
            .try_clone()
            .map_err(|e| anyhow!("{}: {e}", path.display()))?;
        let mut file = BufWriter::new(file);
        file.write_all(&header[..end])
            .map_err(|e| anyhow!("{}: {e}", path.display()))?;
        Ok(Self {
            output,
            writer: builder().has_headers(false).from_writer(file),
            rows: 0,
            _row: PhantomData,
        })
    }

    fn row(&mut self, row: R) -> Result<()> {
        let path = self.output.path();
        self.writer
            .serialize(row)
            .map_err(|e| anyhow!("{}: {e}", path.display()))?;
        self.rows += 1;
        Ok(())
    }

    /// Flushes the rows; the output, ready to commit, and its row count.
    fn finish(mut self) -> Result<(Output, usize)> {
        let path = self.output.path().display().to_string();
        self.writer.flush().map_err(|e| anyhow!("{path}: {e}"))?;
        Ok((self.output, self.rows))
    }
}

/// Runs the command; prints the files written and their rows. `Some(signal)` when a signal
/// stopped it (nothing is written then).
pub fn export(args: &ExportArgs) -> Result<Option<i32>> {
    let stop = Stop::install();
    for name in FILES {
        check_output(&args.csv.join(name), &[&args.file], args.force)?;
    }
    let rec = open(&args.file)?;
    std::fs::create_dir_all(&args.csv)
        .with_context(|| format!("creating {}", args.csv.display()))?;
    if rec.recovered() {
        eprintln!(
            "note: {} was not finished; exporting what was recovered",
            args.file.display()
        );
    }
    let inputs = [args.file.clone()];
    let Some(tables) = write_all(&rec, &args.csv, &inputs, args.force, &stop)? else {
        let sig = stop.received().unwrap_or_default();
        eprintln!(
            "export interrupted by {}: nothing written to {}",
            crate::signals::name(sig),
            args.csv.display()
        );
        return Ok(Some(sig));
    };
    let counts: Vec<(PathBuf, usize)> = (tables.iter())
        .map(|(o, rows)| (o.path().to_path_buf(), *rows))
        .collect();
    commit_all(tables.into_iter().map(|(o, _)| o).collect())?;
    for (path, rows) in counts {
        crate::out::outln!("{}: {rows} rows", path.display());
    }
    Ok(None)
}

/// Test-only: `SOFTGRIP_TEST_EXPORT_DELAY_US=N` waits N µs per message (a slow export, to
/// test that a signal during it leaves nothing). Not for users.
fn test_delay() -> Option<std::time::Duration> {
    std::env::var("SOFTGRIP_TEST_EXPORT_DELAY_US")
        .ok()
        .and_then(|v| v.parse().ok())
        .map(std::time::Duration::from_micros)
}

/// Writes the four tables into their temporary files; `None` if a signal came first (the
/// temporary files are then removed as the outputs drop).
fn write_all(
    rec: &Recording,
    dir: &Path,
    inputs: &[PathBuf],
    force: bool,
    stop: &Stop,
) -> Result<Option<Vec<(Output, usize)>>> {
    let mut contacts = Table::<ContactRow>::create(dir, FILES[0], inputs, force)?;
    let mut wrenches = Table::<WrenchRow>::create(dir, FILES[1], inputs, force)?;
    let mut poses = Table::<PoseRow>::create(dir, FILES[2], inputs, force)?;
    let mut clock = Table::<ClockRow>::create(dir, FILES[3], inputs, force)?;
    let names = fingertips(rec);
    let tip_of_topic = |topic: &str| {
        names
            .iter()
            .find(|n| topics::wrench(n) == topic)
            .map_or("", String::as_str)
    };
    let delay = test_delay();
    for (k, m) in rec.messages.iter().enumerate() {
        if k % SIGNAL_CHECK_EVERY == 0 && stop.received().is_some() {
            return Ok(None);
        }
        if let Some(d) = delay {
            std::thread::sleep(d);
        }
        let t = seconds(m.log_time_ns);
        match &m.message {
            Message::Contacts(a) => {
                for c in &a.contacts {
                    contacts.row(ContactRow::new(t, c))?;
                }
            }
            Message::Wrench(w) => {
                let (f, q) = (&w.wrench.force, &w.wrench.torque);
                wrenches.row(WrenchRow {
                    time_s: t,
                    fingertip: tip_of_topic(&m.topic),
                    topic: &m.topic,
                    force_x_N: f.x,
                    force_y_N: f.y,
                    force_z_N: f.z,
                    torque_x_Nm: q.x,
                    torque_y_Nm: q.y,
                    torque_z_Nm: q.z,
                })?;
            }
            Message::Tf(tf) => {
                for p in &tf.transforms {
                    poses.row(PoseRow::new(t, p))?;
                }
            }
            Message::Clock(c) => clock.row(ClockRow {
                log_time_s: t,
                clock_s: seconds(c.clock.as_nanos()),
            })?,
            _ => {}
        }
    }
    let tables = vec![
        contacts.finish()?,
        wrenches.finish()?,
        poses.finish()?,
        clock.finish()?,
    ];
    if stop.received().is_some() {
        return Ok(None);
    }
    Ok(Some(tables))
}
