//! `softgrip export FILE.mcap --csv DIR`: one CSV file per topic family, with units in the
//! headers: `contacts.csv` (every `SoftContact` field), `wrenches.csv`, `poses.csv`,
//! `clock.csv`. (`/softgrip/markers` is for 3D views and is not exported.)

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use softgrip_ecs::softgrip_record::{Message, Recording, topics};

use super::{csv_field, fingertips, open, seconds};

/// Arguments of `softgrip export`.
#[derive(Debug, Clone, clap::Args)]
pub struct ExportArgs {
    /// The recording (MCAP).
    pub file: PathBuf,
    /// Directory for the CSV files (created if needed).
    #[arg(long, value_name = "DIR")]
    pub csv: PathBuf,
}

/// Header of `contacts.csv`.
pub const CONTACTS_HEADER: &str = "time_s,fingertip,other,point_x_m,point_y_m,point_z_m,normal_x,normal_y,normal_z,compression_m,ratio_x,normal_force_N,friction_force_x_N,friction_force_y_N,friction_force_z_N,torsional_moment_Nm,contact_radius_m,mean_pressure_Pa,peak_pressure_Pa,stiffness_N_per_m,level,level_name,validity_exceeded,sliding,peak_normal_force_N,max_compression_m,contact_duration_s";

fn create(dir: &Path, name: &str, header: &str) -> Result<BufWriter<File>> {
    let path = dir.join(name);
    let mut w = BufWriter::new(
        File::create(&path).with_context(|| format!("creating {}", path.display()))?,
    );
    writeln!(w, "{header}")?;
    Ok(w)
}

/// Runs the command; prints the files written and their rows.
pub fn export(args: &ExportArgs) -> Result<()> {
    let rec = open(&args.file)?;
    std::fs::create_dir_all(&args.csv)
        .with_context(|| format!("creating {}", args.csv.display()))?;
    if rec.recovered() {
        eprintln!(
            "note: {} was not finished; exporting what was recovered",
            args.file.display()
        );
    }
    for (name, rows) in write_all(&rec, &args.csv)? {
        println!("{}: {rows} rows", args.csv.join(name).display());
    }
    Ok(())
}

fn write_all(rec: &Recording, dir: &Path) -> Result<Vec<(&'static str, usize)>> {
    let mut contacts = create(dir, "contacts.csv", CONTACTS_HEADER)?;
    let mut wrenches = create(
        dir,
        "wrenches.csv",
        "time_s,fingertip,topic,force_x_N,force_y_N,force_z_N,torque_x_Nm,torque_y_Nm,torque_z_Nm",
    )?;
    let mut poses = create(
        dir,
        "poses.csv",
        "time_s,parent_frame,frame,x_m,y_m,z_m,qx,qy,qz,qw",
    )?;
    let mut clock = create(dir, "clock.csv", "log_time_s,clock_s")?;
    let names = fingertips(rec);
    let tip_of_topic = |topic: &str| {
        names
            .iter()
            .find(|n| topics::wrench(n) == topic)
            .cloned()
            .unwrap_or_default()
    };
    let mut n = [0usize; 4];
    for m in &rec.messages {
        let t = seconds(m.log_time_ns);
        match &m.message {
            Message::Contacts(a) => {
                for c in &a.contacts {
                    writeln!(
                        contacts,
                        "{t},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}",
                        csv_field(&c.fingertip),
                        csv_field(&c.other),
                        c.point.x,
                        c.point.y,
                        c.point.z,
                        c.normal.x,
                        c.normal.y,
                        c.normal.z,
                        c.compression,
                        c.ratio_x,
                        c.normal_force,
                        c.friction_force.x,
                        c.friction_force.y,
                        c.friction_force.z,
                        c.torsional_moment,
                        c.contact_radius,
                        c.mean_pressure,
                        c.peak_pressure,
                        c.stiffness,
                        c.level,
                        csv_field(&c.level_name),
                        u8::from(c.validity_exceeded),
                        u8::from(c.sliding),
                        c.peak_normal_force,
                        c.max_compression,
                        c.contact_duration
                    )?;
                    n[0] += 1;
                }
            }
            Message::Wrench(w) => {
                let (f, q) = (&w.wrench.force, &w.wrench.torque);
                writeln!(
                    wrenches,
                    "{t},{},{},{},{},{},{},{},{}",
                    csv_field(&tip_of_topic(&m.topic)),
                    csv_field(&m.topic),
                    f.x,
                    f.y,
                    f.z,
                    q.x,
                    q.y,
                    q.z
                )?;
                n[1] += 1;
            }
            Message::Tf(tf) => {
                for p in &tf.transforms {
                    let (v, q) = (&p.transform.translation, &p.transform.rotation);
                    writeln!(
                        poses,
                        "{t},{},{},{},{},{},{},{},{},{}",
                        csv_field(&p.header.frame_id),
                        csv_field(&p.child_frame_id),
                        v.x,
                        v.y,
                        v.z,
                        q.x,
                        q.y,
                        q.z,
                        q.w
                    )?;
                    n[2] += 1;
                }
            }
            Message::Clock(c) => {
                writeln!(clock, "{t},{}", seconds(c.clock.as_nanos()))?;
                n[3] += 1;
            }
            _ => {}
        }
    }
    for w in [&mut contacts, &mut wrenches, &mut poses, &mut clock] {
        w.flush()?;
    }
    Ok(vec![
        ("contacts.csv", n[0]),
        ("wrenches.csv", n[1]),
        ("poses.csv", n[2]),
        ("clock.csv", n[3]),
    ])
}
