//! `softgrip bench-law`: the speed-vs-error table of every level of the law for every
//! construction of a fingertip (free sphere, flat-backed hemisphere, skin over a core), against
//! that construction's FE, and its two figures.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Duration;

use anyhow::{Context, Result};
use softgrip_law::{BACKINGS, Backing, ContactLaw, ContactParams, Level};

use crate::accuracy::{MaxError, Quantity, max_error};
use crate::counterpart_arg::CounterpartArg;
use crate::fe::{Dataset, FeCurve};
use crate::plot::{ForcePanel, SpeedPoint, draw_force_vs_x, draw_speed_vs_error};
use crate::timing::{ns_per_eval, sample_points};

/// The constructions, Poisson ratios and counterparts of the table: (backing, t/R for core,
/// nu, counterpart, FE file in `tests/data/fe/`). The free sphere against the reference, the
/// backed ones and the curved counterparts against softgrip's own FE campaigns (`tools/fe/`).
const PANELS: [(&str, f64, f64, &str, &str); 17] = [
    ("free", 0.0, 0.3, "plane", "force_nu0.3.csv"),
    ("free", 0.0, 0.49, "plane", "force_nu0.49.csv"),
    ("flat", 0.0, 0.3, "plane", "flat/force_nu0.3.csv"),
    ("flat", 0.0, 0.48, "plane", "flat/force_nu0.48.csv"),
    ("core", 0.2, 0.499, "plane", "core/force_nu0.499_t0.2.csv"),
    ("core", 0.4, 0.48, "plane", "core/force_nu0.48_t0.4.csv"),
    ("core", 0.8, 0.3, "plane", "core/force_nu0.3_t0.8.csv"),
    // Balls: the fitted ones at nu 0.48, the worst of nu 0.3 (the free sphere on 4R, blind, and
    // the bonded pad on R) and the worst held-out run (0.7 R at nu 0.4).
    ("free", 0.0, 0.48, "ball:1", "ball/free/force_nu0.48_k1.csv"),
    (
        "free",
        0.0,
        0.48,
        "ball:0.5",
        "ball/free/force_nu0.48_k0.5.csv",
    ),
    ("flat", 0.0, 0.48, "ball:2", "ball/flat/force_nu0.48_k2.csv"),
    ("free", 0.0, 0.3, "ball:4", "ball/free/force_nu0.3_k4.csv"),
    ("flat", 0.0, 0.3, "ball:1", "ball/flat/force_nu0.3_k1.csv"),
    (
        "free",
        0.0,
        0.4,
        "ball:0.7",
        "ball/free/force_nu0.4_k0.7.csv",
    ),
    (
        "flat",
        0.0,
        0.48,
        "cylinder:1",
        "cylinder/flat/force_nu0.48_k1.csv",
    ),
    (
        "free",
        0.0,
        0.48,
        "cylinder:3",
        "cylinder/free/force_nu0.48_k3.csv",
    ),
    ("flat", 0.0, 0.48, "edge", "edge/flat/force_nu0.48.csv"),
    ("free", 0.0, 0.48, "edge", "edge/free/force_nu0.48.csv"),
];
/// Range of the first force-error column, where the paper's claims are made.
const FORCE_RANGE: (f64, f64) = (0.01, 0.5);
/// Range of the radius-error column (the FE radius scatters by +-10 % below x = 0.05).
const RADIUS_RANGE: (f64, f64) = (0.1, 0.5);
/// File names of the figures.
const FORCE_FIGURE: &str = "law_force_vs_x.png";
/// The force figures of the counterparts other than a plane, one per kind:
/// `law_force_vs_x_{ball,cylinder,edge}.png`.
const COUNTERPART_KINDS: [&str; 3] = ["ball", "cylinder", "edge"];
const SPEED_FIGURE: &str = "law_speed_vs_error.png";

/// Arguments of `softgrip bench-law`.
#[derive(Debug, clap::Args)]
pub struct BenchLawArgs {
    /// Folder for the figures law_force_vs_x.png, law_force_vs_x_{ball,cylinder,edge}.png and
    /// law_speed_vs_error.png (created if needed).
    #[arg(long, value_name = "DIR", default_value = "docs/figures")]
    out: PathBuf,
    /// Time each level for ~2 ms instead of ~50 ms (for tests; the numbers are noisier).
    #[arg(long)]
    quick: bool,
}

/// One level at one Poisson ratio.
#[derive(Debug)]
struct Row {
    level: Level,
    law: ContactLaw,
    ns_response: f64,
    ns_patch: f64,
    force_paper_range: Option<MaxError>,
    force_fe_range: Option<MaxError>,
    radius: Option<MaxError>,
}

/// Everything measured for one construction at one Poisson ratio.
#[derive(Debug)]
struct Panel {
    /// `free`, `flat` or `core t/R = ...`.
    construction: String,
    nu: f64,
    fe: FeCurve,
    /// FE points past `fe`'s range (nu = 0.3: the volume collapse, x > 0.61).
    fe_beyond: Vec<crate::fe::FePoint>,
    rows: Vec<Row>,
    /// Levels that cannot be built at this nu, with the reason.
    unavailable: Vec<(Level, String)>,
    /// What it is pressed on: `plane` (the figure `law_force_vs_x.png`), `ball`, `cylinder` or
    /// `edge` (`law_force_vs_x_<kind>.png`).
    kind: &'static str,
}

/// Measures, prints the table on stdout and writes the figures.
pub fn run(args: &BenchLawArgs) -> Result<()> {
    let budget = Duration::from_millis(if args.quick { 2 } else { 50 });
    let panels = PANELS
        .iter()
        .map(|&(backing, tau, nu, counterpart, path)| {
            measure(backing, tau, nu, counterpart, path, budget)
        })
        .collect::<Result<Vec<_>>>()?;
    crate::out::text(&table(&panels, budget));

    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("cannot create {}", args.out.display()))?;
    let force_panels = |kind: &str| -> Vec<ForcePanel<'_>> {
        panels
            .iter()
            .filter(|p| p.kind == kind)
            .map(|p| ForcePanel {
                title: format!("{}, ν = {}", p.construction, p.nu),
                laws: p.rows.iter().map(|r| (r.level.name(), &r.law)).collect(),
                fe: &p.fe.points,
                fe_beyond: &p.fe_beyond,
            })
            .collect()
    };
    let force_path = args.out.join(FORCE_FIGURE);
    draw_force_vs_x(&force_path, &force_panels("plane"))?;
    let mut written = vec![force_path];
    for kind in COUNTERPART_KINDS {
        let path = args.out.join(format!("law_force_vs_x_{kind}.png"));
        draw_force_vs_x(&path, &force_panels(kind))?;
        written.push(path);
    }
    let speed: Vec<SpeedPoint> = panels
        .iter()
        .flat_map(|p| {
            p.rows.iter().filter_map(|r| {
                Some(SpeedPoint {
                    label: r.level.name().to_owned(),
                    series: format!("{}, ν = {}", p.construction, p.nu),
                    ns_per_eval: r.ns_response,
                    force_error_pct: 100.0 * r.force_paper_range?.max_abs,
                })
            })
        })
        .collect();
    let speed_path = args.out.join(SPEED_FIGURE);
    draw_speed_vs_error(
        &speed_path,
        &speed,
        "time per evaluation of force and stiffness  [ns]",
    )?;
    written.push(speed_path);
    let names: Vec<String> = written.iter().map(|p| p.display().to_string()).collect();
    eprintln!("wrote {}", names.join(", "));
    Ok(())
}

fn measure(
    backing: &str,
    tau: f64,
    nu: f64,
    counterpart: &str,
    path: &'static str,
    budget: Duration,
) -> Result<Panel> {
    let counterpart: CounterpartArg = counterpart
        .parse()
        .map_err(|e: String| anyhow::anyhow!("{e}"))?;
    let fe = Dataset::File(path).load()?;
    let fe_end = fe.points.last().map_or(0.0, |p| p.x);
    let fe_beyond = if path == "force_nu0.3.csv" {
        let full = Dataset::FullNu03.load()?;
        full.points.into_iter().filter(|p| p.x > fe_end).collect()
    } else {
        Vec::new()
    };
    // The construction through the law's one parser (its row says whether it takes t/R).
    let row = BACKINGS
        .iter()
        .find(|row| row.name == backing)
        .ok_or_else(|| anyhow::anyhow!("no construction `{backing}` in BACKINGS"))?;
    let backing = Backing::try_from_parts(row.name, row.parameter.map(|_| tau))?;
    let mut construction = match backing.thickness() {
        Some(t) => format!("{} t/R = {t}", backing.name()),
        None => backing.name().to_owned(),
    };
    if !counterpart.is_plane() {
        construction.push_str(&format!(" on {counterpart}"));
    }
    let cp = counterpart.counterpart(1.0)?;
    let params = ContactParams::try_from_parts(1.0, 1.0, nu)?.with_backing(backing)?;
    let mut rows = Vec::new();
    let mut unavailable = Vec::new();
    for level in Level::ALL {
        let law = match ContactLaw::try_new(params, level).and_then(|l| l.with_counterpart(cp)) {
            Ok(law) => law,
            Err(e) => {
                unavailable.push((level, e.to_string()));
                continue;
            }
        };
        let xs = sample_points(law.x_max());
        let ns_response = ns_per_eval(&xs, budget, |x| {
            let r = law.response(x);
            r.force + r.stiffness
        });
        let ns_patch = ns_per_eval(&xs, budget, |x| {
            let r = law.response(x);
            let p = law.patch(x);
            r.force + r.stiffness + p.radius + p.mean_pressure
        });
        let (f_lo, f_hi) = FORCE_RANGE;
        let (a_lo, a_hi) = RADIUS_RANGE;
        rows.push(Row {
            level,
            ns_response,
            ns_patch,
            force_paper_range: max_error(&law, &fe.points, Quantity::Force, f_lo, f_hi),
            force_fe_range: max_error(&law, &fe.points, Quantity::Force, 0.0, f64::INFINITY),
            // A ball's radius, or the semi-axis across a cylinder (what its FE file gives);
            // none on an edge (the law's patch there is the plane's at rho x, not validated:
            // the FE's across the ridge is 0.13-0.28 of it).
            radius: if path_kind(path) == "edge" {
                None
            } else {
                max_error(&law, &fe.points, Quantity::Radius, a_lo, a_hi)
            },
            law,
        });
    }
    Ok(Panel {
        construction,
        nu,
        fe,
        fe_beyond,
        rows,
        unavailable,
        kind: path_kind(path),
    })
}

/// The markdown table, one section per Poisson ratio.
fn table(panels: &[Panel], budget: Duration) -> String {
    let mut s = String::new();
    let build = if cfg!(debug_assertions) {
        "a debug build (times are not representative: use `cargo run --release -p softgrip-cli -- bench-law`)"
    } else {
        "an optimised build"
    };
    // Writing to a String cannot fail.
    let _ = writeln!(
        s,
        "Speed vs error of the contact law levels, for each construction of a fingertip. Times: \
         best of 5 runs over {:?} in total per cell, 1024 fixed pseudo-random x in (0, x_max), \
         {build}. Errors: max |law - FE| / FE over that construction's FE points \
         (tests/data/fe/, CalculiX, compressible neo-Hookean), only where x <= x_max of the \
         level. With a backing, `calibrated` is that construction's own law and `auto` is \
         measured against it; every other level is the free sphere's law (a baseline). On a \
         counterpart (ball:K, cylinder:K: K = R2/R) every level is bound to it \
         (`ContactLaw::with_counterpart`: `calibrated` and `auto` with the FE-calibrated map, \
         the others with the patch argument alone) and the radius column is the patch's \
         second semi-axis (a ball's radius, across a cylinder; none on an edge, whose FE patch \
         is not resolved).\n",
        budget
    );
    for p in panels {
        let fe_range = range_of(&p.fe.points);
        let _ = writeln!(
            s,
            "### {} nu = {} (FE: {}, x = {:.2}..{:.2})\n",
            p.construction,
            p.nu,
            p.fe.dataset.file_name(),
            fe_range.0,
            fe_range.1
        );
        let _ = writeln!(
            s,
            "| level | x_max | ns/eval F, K | ns/eval F, K, a, p | F error, 0.01 <= x <= 0.5 \
             | F error, FE range in x_max | that range | a error, 0.1 <= x <= 0.5 |"
        );
        let _ = writeln!(s, "|---|---:|---:|---:|---:|---:|---|---:|");
        for r in &p.rows {
            let range = r.force_fe_range.map_or("-".to_owned(), |m| {
                format!("{:.2}..{:.2}", m.x_range.0, m.x_range.1)
            });
            let _ = writeln!(
                s,
                "| {} | {:.3} | {} | {} | {} | {} | {} | {} |",
                r.level.name(),
                r.law.x_max(),
                ns(r.ns_response),
                ns(r.ns_patch),
                percent_within(r.force_paper_range, FORCE_RANGE.1),
                percent_within(r.force_fe_range, f64::INFINITY),
                range,
                percent_within(r.radius, RADIUS_RANGE.1),
            );
        }
        for (level, why) in &p.unavailable {
            let _ = writeln!(s, "| {} | not available: {why} |||||||", level.name());
        }
        s.push('\n');
    }
    s
}

/// The counterpart kind of an FE file: its first folder if that is a counterpart's, else
/// `plane`.
fn path_kind(path: &str) -> &'static str {
    COUNTERPART_KINDS
        .into_iter()
        .find(|k| path.starts_with(&format!("{k}/")))
        .unwrap_or("plane")
}

fn range_of(points: &[crate::fe::FePoint]) -> (f64, f64) {
    let first = points.first().map_or(0.0, |p| p.x);
    let last = points.last().map_or(0.0, |p| p.x);
    (first, last)
}

fn ns(v: f64) -> String {
    if v < 100.0 {
        format!("{v:.1}")
    } else {
        format!("{v:.0}")
    }
}

/// The error in percent, noting when the level's range stopped short of `x_end`.
fn percent_within(m: Option<MaxError>, x_end: f64) -> String {
    match m {
        None => "-".to_owned(),
        Some(m) => {
            let pct = 100.0 * m.max_abs;
            let value = if pct < 10.0 {
                format!("{pct:.2} %")
            } else {
                format!("{pct:.1} %")
            };
            if x_end.is_finite() && m.x_range.1 < x_end - 1e-9 {
                format!("{value} (x <= {:.2})", m.x_range.1)
            } else {
                value
            }
        }
    }
}
