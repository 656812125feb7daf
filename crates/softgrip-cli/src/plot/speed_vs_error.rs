//! `law_speed_vs_error.png`: cost per evaluation against the largest force error vs FE, one
//! point per level and Poisson ratio, labelled with the level's name.

use std::path::Path;

use anyhow::{Result, anyhow};
use plotters::coord::Shift;
use plotters::prelude::*;

use super::labels::{PixelBox, place};
use super::style::{CAPTION_SIZE, FONT, LABEL_SIZE, TICK_SIZE, ensure_font, series_colour};

/// One level at one Poisson ratio.
#[derive(Debug, Clone)]
pub struct SpeedPoint {
    /// Level name, drawn beside the point.
    pub label: String,
    /// The construction and Poisson ratio, e.g. `flat, ν = 0.48`: one colour and marker per
    /// value.
    pub series: String,
    /// Time per evaluation of force and stiffness \[ns\], > 0.
    pub ns_per_eval: f64,
    /// Largest relative force error against FE [%], > 0.
    pub force_error_pct: f64,
}

/// Draws the figure into `path` (PNG). Both axes are logarithmic.
pub fn draw_speed_vs_error(path: &Path, points: &[SpeedPoint], x_desc: &str) -> Result<()> {
    ensure_font()?;
    let failed = |e: &dyn std::fmt::Display| anyhow!("drawing {}: {e}", path.display());
    let root = BitMapBackend::new(path, (1200, 850)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| failed(&e))?;
    let positive = |v: f64| v.is_finite() && v > 0.0;
    let shown: Vec<&SpeedPoint> = points
        .iter()
        .filter(|p| positive(p.ns_per_eval) && positive(p.force_error_pct))
        .collect();
    let bounds = |f: fn(&SpeedPoint) -> f64| {
        let lo = shown.iter().map(|p| f(p)).fold(f64::INFINITY, f64::min);
        let hi = shown.iter().map(|p| f(p)).fold(0.0, f64::max);
        if lo <= hi {
            (lo / 2.0, hi * 4.0)
        } else {
            (1.0, 10.0)
        }
    };
    let (x_lo, x_hi) = bounds(|p| p.ns_per_eval);
    let (y_lo, y_hi) = bounds(|p| p.force_error_pct);
    let mut nus: Vec<&str> = Vec::new();
    for p in &shown {
        if !nus.contains(&p.series.as_str()) {
            nus.push(&p.series);
        }
    }

    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Contact law levels: cost vs accuracy against finite elements",
            (FONT, CAPTION_SIZE + 4),
        )
        .margin(20)
        .x_label_area_size(60)
        .y_label_area_size(80)
        .build_cartesian_2d((x_lo..x_hi).log_scale(), (y_lo..y_hi).log_scale())
        .map_err(|e| failed(&e))?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc("max |F − F_FE| / F_FE on 0.01 ≤ x ≤ 0.5  [%]")
        .axis_desc_style((FONT, LABEL_SIZE))
        .label_style((FONT, TICK_SIZE))
        .y_label_formatter(&|v| format!("{v}"))
        .x_label_formatter(&|v| format!("{v}"))
        .light_line_style(BLACK.mix(0.04))
        .bold_line_style(BLACK.mix(0.12))
        .draw()
        .map_err(|e| failed(&e))?;

    for (i, &nu) in nus.iter().enumerate() {
        let colour = series_colour(i);
        let of_nu: Vec<&SpeedPoint> = shown.iter().copied().filter(|p| p.series == nu).collect();
        let at = of_nu.iter().map(|p| (p.ns_per_eval, p.force_error_pct));
        let label = nu.to_owned();
        // Circles and triangles alternate: readable without colour too.
        if i % 2 == 0 {
            chart
                .draw_series(at.map(|c| Circle::new(c, 6, colour.filled())))
                .map_err(|e| failed(&e))?
                .label(label)
                .legend(move |c| Circle::new(c, 6, colour.filled()));
        } else {
            chart
                .draw_series(at.map(|c| TriangleMarker::new(c, 8, colour.filled())))
                .map_err(|e| failed(&e))?
                .label(label)
                .legend(move |c| TriangleMarker::new(c, 8, colour.filled()));
        }
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .label_font((FONT, LABEL_SIZE))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.3))
        .draw()
        .map_err(|e| failed(&e))?;
    draw_labels(&root, &chart, &shown, &nus).map_err(|e| failed(&e))?;
    root.present().map_err(|e| failed(&e))?;
    Ok(())
}

type LogLog = Cartesian2d<LogCoord<f64>, LogCoord<f64>>;

/// Level names beside their points, in the colour of their series, placed so that none overlap;
/// a thin leader line joins a label that had to move away from its point.
fn draw_labels<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    chart: &ChartContext<'_, DB, LogLog>,
    shown: &[&SpeedPoint],
    nus: &[&str],
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let colour_of = |nu: &str| series_colour(nus.iter().position(|&n| n == nu).unwrap_or(0));
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    let area = PixelBox {
        x: xs.start,
        y: ys.start,
        w: xs.end - xs.start,
        h: ys.end - ys.start,
    };
    let font = (FONT, TICK_SIZE).into_font();
    let pixels: Vec<(i32, i32)> = shown
        .iter()
        .map(|p| chart.backend_coord(&(p.ns_per_eval, p.force_error_pct)))
        .collect();
    let sizes = shown
        .iter()
        .map(|p| {
            let (w, h) = root.estimate_text_size(&p.label, &TextStyle::from(font.clone()))?;
            Ok((w as i32, h as i32))
        })
        .collect::<Result<Vec<_>, _>>()?;
    for ((p, &(px, py)), ((corner, far), (w, h))) in shown
        .iter()
        .zip(&pixels)
        .zip(place(&pixels, &sizes, area).into_iter().zip(sizes))
    {
        let colour = colour_of(&p.series);
        if far {
            let end = (corner.0 + w / 2, corner.1 + h / 2);
            root.draw(&PathElement::new([(px, py), end], colour.mix(0.5)))?;
        }
        root.draw(&Text::new(p.label.clone(), corner, font.color(&colour)))?;
    }
    Ok(())
}
