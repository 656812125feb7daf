//! What the figures share: the font (DejaVu Sans, shipped in `assets/`), colours, sizes.

use std::sync::OnceLock;

use anyhow::{Result, ensure};
use plotters::style::{FontStyle, RGBColor};

/// Family name under which the shipped font is registered.
pub const FONT: &str = "sans-serif";
/// Text sizes [px].
pub const TITLE_SIZE: u32 = 30;
/// Panel captions [px].
pub const CAPTION_SIZE: u32 = 24;
/// Axis descriptions [px].
pub const LABEL_SIZE: u32 = 20;
/// Tick labels and legends [px].
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
