//! `softgrip plot FILE.mcap -o FIG.png`: per fingertip, the recorded force against x with the
//! recorded law's curve and, for comparison, Hertz, Tatara and softgrip's other levels (as
//! the paper's Figs. 9-10); below, force and contact radius against time.

use std::path::{Path, PathBuf};

use anyhow::{Result, anyhow, bail};
use plotters::coord::Shift;
use plotters::prelude::*;
use softgrip_ecs::FingertipLaw;
use softgrip_law::{Backing, ContactLaw, Level};

use super::{contact_radius, contacts, fingertips, laws, open};
use crate::files::{Output, check_output};
use crate::plot::style::{
    CAPTION_SIZE, FONT, LABEL_SIZE, TICK_SIZE, TITLE_SIZE, draw_curve, draw_legend, ensure_font,
    series_colour,
};

/// Arguments of `softgrip plot`.
#[derive(Debug, Clone, clap::Args)]
pub struct PlotArgs {
    /// The recording (MCAP).
    pub file: PathBuf,
    /// The figure (PNG).
    #[arg(short = 'o', long = "out", value_name = "FIG.png")]
    pub out: PathBuf,
    /// Overwrite the figure if it exists.
    #[arg(long)]
    pub force: bool,
}

/// One recorded sample of a fingertip's contact.
#[derive(Debug, Clone, Copy)]
struct Sample {
    t: f64,
    x: f64,
    force: f64,
    radius: f64,
}

/// A fingertip's column of the figure.
struct Column {
    name: String,
    law: Option<FingertipLaw>,
    samples: Vec<Sample>,
}

/// Runs the command.
pub fn plot(args: &PlotArgs) -> Result<()> {
    check_output(&args.out, &[&args.file], args.force)?;
    let png = args
        .out
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("png"));
    if !png {
        bail!(
            "{}: the figure is a PNG image: give a file name ending in .png",
            args.out.display()
        );
    }
    let rec = open(&args.file)?;
    if rec.recovered() {
        eprintln!(
            "note: {} was not finished; plotting what was recovered",
            args.file.display()
        );
    }
    let laws = laws(&rec);
    let mut columns = Vec::new();
    for name in fingertips(&rec) {
        let law = laws.iter().find(|l| l.name == name).cloned();
        let bound = law.as_ref().and_then(|l| l.law().ok());
        let samples: Vec<Sample> = contacts(&rec)
            .filter(|(_, c)| c.fingertip == name)
            .map(|(t, c)| Sample {
                t,
                x: c.ratio_x,
                force: c.normal_force,
                radius: contact_radius(c, bound.as_ref()),
            })
            .collect();
        if !samples.is_empty() {
            columns.push(Column { name, law, samples });
        }
    }
    if columns.is_empty() {
        bail!(
            "{}: no soft contacts recorded: nothing to plot",
            args.file.display()
        );
    }
    let title = format!(
        "{}: {}",
        args.file
            .file_name()
            .map_or_else(String::new, |f| f.to_string_lossy().into_owned()),
        rec.softgrip_metadata("origin").unwrap_or("recording")
    );
    // Drawn into a temporary file beside the target, put in place when complete.
    let out = Output::create(&args.out, std::slice::from_ref(&args.file), args.force)?;
    draw(out.temp_path(), &args.out, &title, &columns)?;
    out.commit()?;
    crate::out::outln!("{}", args.out.display());
    Ok(())
}

/// A unit prefix for values up to `max`: (factor to multiply by, prefix).
fn prefix(max: f64) -> (f64, &'static str) {
    for (f, p) in [(1.0, ""), (1e3, "m"), (1e6, "µ"), (1e9, "n"), (1e12, "p")] {
        if max * f >= 1.0 {
            return (f, p);
        }
    }
    (1e12, "p")
}

/// Draws the figure into `path` (a temporary file); errors name `target`.
fn draw(path: &Path, target: &Path, title: &str, columns: &[Column]) -> Result<()> {
    ensure_font()?;
    let width = 900 * columns.len() as u32;
    let root = BitMapBackend::new(path, (width, 1500)).into_drawing_area();
    let failed = |e: &dyn std::fmt::Display| anyhow!("drawing {}: {e}", target.display());
    root.fill(&WHITE).map_err(|e| failed(&e))?;
    let root = root
        .titled(title, (FONT, TITLE_SIZE))
        .map_err(|e| failed(&e))?;
    let (top, bottom) = root.split_vertically(700);
    let tops = top.split_evenly((1, columns.len()));
    let bottoms = bottom.split_evenly((2, columns.len()));
    for (j, col) in columns.iter().enumerate() {
        force_vs_x(&tops[j], col).map_err(|e| failed(&e))?;
        vs_time(&bottoms[j], col, true).map_err(|e| failed(&e))?;
        vs_time(&bottoms[columns.len() + j], col, false).map_err(|e| failed(&e))?;
    }
    root.present().map_err(|e| failed(&e))?;
    Ok(())
}

/// The comparison curves: the recorded level first, then Hertz, Tatara and softgrip's levels.
fn comparison(law: &FingertipLaw) -> Vec<(String, ContactLaw)> {
    let mut out = Vec::new();
    if let Ok(l) = law.law() {
        out.push((format!("recorded level: {}", law.level.name()), l));
    }
    let full = if law.poisson_ratio >= 0.5 {
        Level::Incompressible
    } else {
        Level::NeoHookean
    };
    for (name, level) in [
        ("Hertz", Level::Hertz),
        ("Tatara", Level::Tatara),
        ("fit (χ_L, Eq. 38)", Level::fit()),
        (full.name(), full),
        ("calibrated", Level::Calibrated),
    ] {
        if level.name() == law.level.name() {
            continue;
        }
        if let Ok(l) = law.law_at(level) {
            // With a backing, only `calibrated` is the construction's own law; the others
            // compute the free sphere's (softgrip_law::Level's docs).
            if law.backing.is_free() {
                out.push((name.to_string(), l));
            } else if level == Level::Calibrated {
                out.push((format!("{name} ({})", construction(law.backing)), l));
            } else {
                out.push((format!("{name} (free sphere)"), l));
            }
        }
    }
    out
}

fn force_vs_x<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    col: &Column,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let x_top = (col.samples.iter().map(|s| s.x).fold(0.0, f64::max) * 1.08).max(0.02);
    let f_max = col.samples.iter().map(|s| s.force).fold(0.0, f64::max);
    let y_top = 1.25 * f_max.max(1e-15);
    let (k, p) = prefix(y_top);
    let caption = match &col.law {
        Some(l) => format!(
            "{}, {}: force vs x (R = {}, E* = {}, ν = {})",
            col.name,
            construction(l.backing),
            si(l.radius, "m"),
            si(
                l.youngs_modulus / (1.0 - l.poisson_ratio * l.poisson_ratio),
                "Pa"
            ),
            l.poisson_ratio
        ),
        None => format!("{}: force vs x", col.name),
    };
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FONT, CAPTION_SIZE))
        .margin(14)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(0.0..x_top, 0.0..y_top * k)?;
    chart
        .configure_mesh()
        .x_desc("compression ratio x = δ / R  [-]")
        .y_desc(format!("normal force [{p}N]"))
        .axis_desc_style((FONT, LABEL_SIZE))
        .label_style((FONT, TICK_SIZE))
        .light_line_style(WHITE.mix(0.0))
        .bold_line_style(BLACK.mix(0.08))
        .draw()?;
    chart
        .draw_series(
            col.samples
                .iter()
                .map(|s| Circle::new((s.x, s.force * k), 3, BLACK.filled())),
        )?
        .label("simulated (recorded)")
        .legend(|(x, y)| Circle::new((x + 12, y), 3, BLACK.filled()));
    if let Some(law) = &col.law {
        for (i, (name, l)) in comparison(law).iter().enumerate() {
            let colour = series_colour(i);
            let width = if i == 0 { 3 } else { 2 };
            let x_end = l.x_max().min(x_top);
            let n = 200;
            let pts: Vec<(f64, f64)> = (0..=n)
                .map(|j| x_end * j as f64 / n as f64)
                .map(|x| (x, l.response(x * law.radius).force * k))
                .filter(|&(_, f)| f.is_finite() && f <= y_top * k)
                .collect();
            draw_curve(&mut chart, pts, name, colour, width, i == 0)?;
        }
    }
    draw_legend(&mut chart)?;
    Ok(())
}

fn vs_time<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    col: &Column,
    force: bool,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let value = |s: &Sample| if force { s.force } else { s.radius };
    let t0 = col
        .samples
        .iter()
        .map(|s| s.t)
        .fold(f64::INFINITY, f64::min);
    let t1 = col.samples.iter().map(|s| s.t).fold(0.0, f64::max);
    let t1 = if t1 > t0 { t1 } else { t0 + 1e-3 };
    let y_top = 1.1 * col.samples.iter().map(value).fold(0.0, f64::max).max(1e-15);
    let (k, p) = prefix(y_top);
    let name = match &col.law {
        Some(l) => format!("{}, {}", col.name, construction(l.backing)),
        None => col.name.clone(),
    };
    let (caption, desc) = if force {
        (
            format!("{name}: normal force vs time"),
            format!("normal force [{p}N]"),
        )
    } else {
        (
            format!("{name}: contact radius vs time"),
            format!("contact radius a [{p}m]"),
        )
    };
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FONT, CAPTION_SIZE))
        .margin(14)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(t0..t1, 0.0..y_top * k)?;
    chart
        .configure_mesh()
        .x_desc("time [s]")
        .y_desc(desc)
        .axis_desc_style((FONT, LABEL_SIZE))
        .label_style((FONT, TICK_SIZE))
        .light_line_style(WHITE.mix(0.0))
        .bold_line_style(BLACK.mix(0.08))
        .draw()?;
    let colour = series_colour(if force { 0 } else { 2 });
    chart.draw_series(
        col.samples
            .iter()
            .map(|s| Circle::new((s.t, value(s) * k), 2, colour.filled())),
    )?;
    Ok(())
}

/// How the fingertip is built, for a caption: "free sphere", "flat-backed" or "skin t = 2 mm on
/// a core".
fn construction(backing: Backing) -> String {
    match backing {
        Backing::Free => "free sphere".into(),
        Backing::Flat => "flat-backed".into(),
        Backing::Core { thickness } => format!("skin t = {} on a core", si(thickness, "m")),
    }
}

/// `value unit` with an SI prefix.
fn si(value: f64, unit: &str) -> String {
    for (f, p) in [
        (1e-9, "G"),
        (1e-6, "M"),
        (1e-3, "k"),
        (1.0, ""),
        (1e3, "m"),
        (1e6, "µ"),
    ] {
        if value * f >= 1.0 {
            let v = format!("{:.3}", value * f);
            return format!(
                "{} {p}{unit}",
                v.trim_end_matches('0').trim_end_matches('.')
            );
        }
    }
    format!("{value:e} {unit}")
}
