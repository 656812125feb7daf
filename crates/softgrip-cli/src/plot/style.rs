//! What the figures share: the font (DejaVu Sans, shipped in `assets/`), colours, sizes.

use std::sync::OnceLock;

use anyhow::{Result, ensure};
use plotters::style::{FontStyle, RGBColor};

/// Family name under which the shipped font is registered.
pub const FONT: &str = "sans-serif";
/// Text sizes \[px\].
pub const TITLE_SIZE: u32 = 30;
/// Panel captions \[px\].
pub const CAPTION_SIZE: u32 = 24;
/// Axis descriptions \[px\].
pub const LABEL_SIZE: u32 = 20;
/// Tick labels and legends \[px\].
pub const TICK_SIZE: u32 = 16;

static DEJAVU_SANS: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");

/// Registers the shipped font with plotters' ab_glyph text backend (once per process).
pub fn ensure_font() -> Result<()> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        plotters::style::register_font(FONT, FontStyle::Normal, DEJAVU_SANS).is_ok()
    });
    ensure!(
        ok,
        "the shipped font assets/DejaVuSans.ttf could not be read"
    );
    Ok(())
}

/// A categorical palette (matplotlib's tab10): colour `i` of a series.
pub fn series_colour(i: usize) -> RGBColor {
    const TAB10: [(u8, u8, u8); 10] = [
        (31, 119, 180),
        (255, 127, 14),
        (44, 160, 44),
        (214, 39, 40),
        (148, 103, 189),
        (140, 86, 75),
        (227, 119, 194),
        (127, 127, 127),
        (188, 189, 34),
        (23, 190, 207),
    ];
    let (r, g, b) = TAB10[i % TAB10.len()];
    RGBColor(r, g, b)
}

/// A chart with `f64` axes, as every figure here draws.
pub type Chart<'a, DB> = plotters::chart::ChartContext<
    'a,
    DB,
    plotters::coord::cartesian::Cartesian2d<
        plotters::coord::types::RangedCoordf64,
        plotters::coord::types::RangedCoordf64,
    >,
>;

/// Draws one curve, solid or dashed, with a legend entry `label` (a line swatch).
pub fn draw_curve<'a, DB: plotters::prelude::DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
    points: Vec<(f64, f64)>,
    label: &str,
    colour: RGBColor,
    width: u32,
    dashed: bool,
) -> Result<(), plotters::drawing::DrawingAreaErrorKind<DB::ErrorType>> {
    use plotters::prelude::{Color, DashedLineSeries, LineSeries, PathElement};
    let style = colour.stroke_width(width);
    let anno = if dashed {
        chart.draw_series(DashedLineSeries::new(points, 10, 6, style))?
    } else {
        chart.draw_series(LineSeries::new(points, style))?
    };
    if !label.is_empty() {
        anno.label(label)
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 24, y)], colour.stroke_width(3)));
    }
    Ok(())
}

/// The legend box of the upper-left corner, in the style of every figure here.
pub fn draw_legend<'a, DB: plotters::prelude::DrawingBackend + 'a>(
    chart: &mut Chart<'a, DB>,
) -> Result<(), plotters::drawing::DrawingAreaErrorKind<DB::ErrorType>> {
    use plotters::prelude::{BLACK, Color, SeriesLabelPosition, WHITE};
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .label_font((FONT, TICK_SIZE))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK.mix(0.3))
        .draw()
}
