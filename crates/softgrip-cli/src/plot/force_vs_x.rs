//! `law_force_vs_x.png`: each level's normalised force against the FE points, one column per
//! construction and Poisson ratio; the lower row shows the same as `chi = f / f_Hertz`, where levels that lie
//! on top of each other in `f` come apart.

use std::path::Path;

use anyhow::{Result, anyhow};
use plotters::coord::Shift;
use plotters::prelude::*;
use softgrip_law::ContactLaw;

use super::style::{
    CAPTION_SIZE, FONT, LABEL_SIZE, TICK_SIZE, TITLE_SIZE, draw_curve, draw_legend, ensure_font,
    series_colour,
};
use crate::fe::FePoint;

/// Largest compression ratio drawn.
const X_PLOT: f64 = 0.86;
/// A panel's x axis ends at this many times its FE's reach (at most [`X_PLOT`], at least
/// [`X_MIN_RIGHT`]): a thin skin's FE stops at x = 0.09, which a fixed axis to 0.86 squeezes
/// into its first tenth.
const X_PAST_REACH: f64 = 1.5;
/// The shortest x axis drawn.
const X_MIN_RIGHT: f64 = 0.2;
/// Spacing of the points of each level's line.
const DX: f64 = 0.0025;

/// One construction at one Poisson ratio: the levels (normalised, E* = 1 and R = 1) and its FE.
#[derive(Debug)]
pub struct ForcePanel<'a> {
    /// What the panel shows, e.g. `flat, ν = 0.48`.
    pub title: String,
    /// Name and law of each level.
    pub laws: Vec<(&'a str, &'a ContactLaw)>,
    /// FE points of the force reference.
    pub fe: &'a [FePoint],
    /// Further FE points past the reference's range (volume collapse), drawn hollow.
    pub fe_beyond: &'a [FePoint],
}

/// Which quantity a chart shows.
#[derive(Debug, Clone, Copy)]
enum Shown {
    Force,
    Chi,
}

impl Shown {
    fn of(self, x: f64, f: f64) -> f64 {
        match self {
            Shown::Force => f,
            Shown::Chi => f / (4.0 / 3.0 * x * x.sqrt()),
        }
    }
}

/// Draws the figure into `path` (PNG).
pub fn draw_force_vs_x(path: &Path, panels: &[ForcePanel<'_>]) -> Result<()> {
    ensure_font()?;
    let width = 800 * panels.len().max(1) as u32;
    let root = BitMapBackend::new(path, (width, 1300)).into_drawing_area();
    let failed = |e: &dyn std::fmt::Display| anyhow!("drawing {}: {e}", path.display());
    root.fill(&WHITE).map_err(|e| failed(&e))?;
    let root = root
        .titled(
            "Contact force of a soft fingertip, by construction: law levels (lines) vs finite elements (points)",
            (FONT, TITLE_SIZE),
        )
        .map_err(|e| failed(&e))?;
    let rows = root.split_evenly((2, panels.len().max(1)));
    for (j, panel) in panels.iter().enumerate() {
        chart(&rows[j], panel, Shown::Force).map_err(|e| failed(&e))?;
        chart(&rows[panels.len() + j], panel, Shown::Chi).map_err(|e| failed(&e))?;
    }
    root.present().map_err(|e| failed(&e))?;
    Ok(())
}

fn chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &ForcePanel<'_>,
    shown: Shown,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let fe_all = || panel.fe.iter().chain(panel.fe_beyond);
    let reach = fe_all().map(|p| p.x).fold(0.0, f64::max);
    let x_right = (X_PAST_REACH * reach).clamp(X_MIN_RIGHT, X_PLOT);
    let y_top = 1.12
        * fe_all()
            .map(|p| shown.of(p.x, p.force_norm))
            .fold(0.0, f64::max);
    let (caption, y_desc) = match shown {
        Shown::Force => (
            format!("{}: normalised force", panel.title),
            "f = F / (E* R²)  [-]",
        ),
        Shown::Chi => (
            format!("{}: correction to Hertz", panel.title),
            "χ = F / F_Hertz  [-]",
        ),
    };
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FONT, CAPTION_SIZE))
        .margin(12)
        .x_label_area_size(50)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..x_right, 0.0..y_top)?;
    chart
        .configure_mesh()
        .x_desc("compression ratio x = δ / R  [-]")
        .y_desc(y_desc)
        .axis_desc_style((FONT, LABEL_SIZE))
        .label_style((FONT, TICK_SIZE))
        .light_line_style(WHITE.mix(0.0))
        .bold_line_style(BLACK.mix(0.08))
        .draw()?;

    // FE first, the lines on top: a level that matches FE stays visible.
    let point = |p: &FePoint| (p.x, shown.of(p.x, p.force_norm));
    chart
        .draw_series(
            panel
                .fe
                .iter()
                .map(|p| Circle::new(point(p), 3, BLACK.filled())),
        )?
        .label("FE (CalculiX)")
        .legend(|(x, y)| Circle::new((x + 12, y), 3, BLACK.filled()));
    if !panel.fe_beyond.is_empty() {
        chart
            .draw_series(
                panel
                    .fe_beyond
                    .iter()
                    .map(|p| Circle::new(point(p), 4, BLACK.stroke_width(1))),
            )?
            .label("FE, volume collapse (J < 0.2)")
            .legend(|(x, y)| Circle::new((x + 12, y), 4, BLACK.stroke_width(1)));
    }
    for (i, (name, law)) in panel.laws.iter().enumerate() {
        let colour = series_colour(i);
        // Levels that by design lie on an earlier one (the exact theory on its table, auto on
        // the full theory) are dashed so that both stay visible.
        let dashed = matches!(*name, "neo-hookean-exact" | "auto");
        // softgrip's own level is drawn thicker.
        let width = if dashed || *name == "calibrated" {
            3
        } else {
            2
        };
        let x_end = law.x_max().min(x_right);
        let n = (x_end / DX).floor() as usize;
        let points = (1..=n)
            .map(|k| k as f64 * DX)
            .chain(std::iter::once(x_end))
            .map(|x| (x, shown.of(x, law.response(x).force)));
        // The line ends at the level's x_max; parts outside the chart (poles, a spring's
        // chi at small x) are left out. Only the first part gets the legend entry.
        for (j, segment) in inside(points, y_top).into_iter().enumerate() {
            let label = if j == 0 { *name } else { "" };
            draw_curve(&mut chart, segment, label, colour, width, dashed)?;
        }
    }
    draw_legend(&mut chart)?;
    Ok(())
}

/// The runs of consecutive points with a finite `y` in `[0, y_top]`.
fn inside(points: impl Iterator<Item = (f64, f64)>, y_top: f64) -> Vec<Vec<(f64, f64)>> {
    let mut runs: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut run = Vec::new();
    for (x, y) in points {
        if (0.0..=y_top).contains(&y) {
            run.push((x, y));
        } else if !run.is_empty() {
            runs.push(std::mem::take(&mut run));
        }
    }
    runs.push(run);
    runs.retain(|r| r.len() > 1);
    runs
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_are_cut_where_they_leave_the_chart() {
        let ys = [5.0, 1.0, 2.0, 9.0, 3.0, 4.0, f64::NAN, 1.0];
        let runs = inside(ys.iter().enumerate().map(|(i, &y)| (i as f64, y)), 4.5);
        assert_eq!(
            runs,
            vec![vec![(1.0, 1.0), (2.0, 2.0)], vec![(4.0, 3.0), (5.0, 4.0)]]
        );
    }
}
