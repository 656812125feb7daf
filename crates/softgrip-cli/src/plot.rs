//! Figures drawn with plotters into PNG files (bitmap backend, text from the shipped font).

mod force_vs_x;
mod labels;
mod speed_vs_error;
pub(crate) mod style;

pub use force_vs_x::{ForcePanel, draw_force_vs_x};
pub use speed_vs_error::{SpeedPoint, draw_speed_vs_error};
