//! [`TactilePad`]: a tactile sensor pad on a fingertip (rows x columns of taxels over a patch
//! of its surface), validated into a [`TactileGrid`] when the fingertip is built.
//!
//! **Pad coordinates.** The pad is centred on the unit direction `d` of the fingertip's frame
//! (the frame of its ball collider, origin at the sphere's centre). A point of the undeformed
//! sphere in the direction `s` has pad coordinates
//! `(u, v) = R θ (s_t·e_u, s_t·e_v) / |s_t|`, `θ = angle(s, d)`, `s_t = s - (s·d) d`: its
//! distance from the pad's centre *along the surface* (a great circle), in the direction it
//! lies (the azimuthal equidistant map about `d`). `e_v` is `up` made tangent at `d`,
//! `e_u = e_v x d`: seen from outside the fingertip, `u` points right and `v` up. The grid
//! covers `|u| <= width/2` (columns, left to right) and `|v| <= height/2` (rows, top to
//! bottom: row 0 is `v = +height/2`, as in an image).
//!
//! **Taxel values** ([`crate::TactileImage`]): each contact of the fingertip is the law's
//! Hertz-shaped pressure `p(ρ) = (3/2) p_mean sqrt(1 - ρ²/a²)` over its flat contact disc of
//! radius `a` (the law's contact radius at the contact's compression), `p_mean = F / (π a²)`
//! with `F` the contact's step-average normal force (the readout's `normal_force`), laid on
//! the pad centred at the pad coordinates of the contact's direction (`-normal` from the
//! centre). Under the patch the skin is pressed flat, so the disc lies on the pad undistorted.
//! A taxel holds the mean of the summed pressures over its area \[Pa\], integrated exactly in
//! one direction and by Gauss-Legendre quadrature (split at the disc's kinks) in the other:
//! `Σ taxel pressure x taxel area = Σ F` for discs inside the grid.

use softgrip_law::Shortest;

use crate::error::{Error, Result};

/// Largest number of rows or of columns of a pad.
pub const MAX_TAXELS_PER_SIDE: u32 = 1024;

/// Smallest taxel side over the fingertip's radius R [-]: a taxel narrower than 1e-6 R is
/// integrated from differences of values of order R² (the disc's cap), which loses
/// `1e-16 R / side` of its value (1e-10 here, all of it at 1e-16 R); its area, side² (1e-30
/// m² at the smallest R, 1 nm), stays far above f64's range. A 1e-300 m pad had a taxel area
/// of 0 and recorded NaN pressures.
pub const MIN_TAXEL_SIDE_OVER_RADIUS: f64 = 1e-6;

/// A tactile sensor pad (the builder's input, [`SoftFingertipBuilder::tactile`]); checked by
/// [`SoftFingertipBuilder::build`] into a [`TactileGrid`].
///
/// [`SoftFingertipBuilder::tactile`]: crate::SoftFingertipBuilder::tactile
/// [`SoftFingertipBuilder::build`]: crate::SoftFingertipBuilder::build
///
/// ```
/// use softgrip_rapier::{Preset, SoftFingertip, TactilePad};
/// let pad = TactilePad::new(16, 16, [1.0, 0.0, 0.0], 0.016, 0.016);
/// let tip = SoftFingertip::builder(0.01).preset(Preset::DragonSkin30).tactile(pad).build().unwrap();
/// let grid = tip.tactile().unwrap();
/// assert_eq!((grid.rows(), grid.columns()), (16, 16));
/// assert!((grid.taxel_area() - 1e-6).abs() < 1e-18); // 1 mm x 1 mm taxels
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TactilePad {
    /// Rows of taxels (the image's height), in `1..=1024`.
    pub rows: u32,
    /// Columns of taxels (the image's width), in `1..=1024`.
    pub columns: u32,
    /// Direction of the pad's centre in the fingertip's frame [-], finite and non-zero (any
    /// length: it is normalised).
    pub direction: [f64; 3],
    /// Direction of the image's top (`+v`) in the fingertip's frame [-]: made tangent to the
    /// sphere at `direction`; finite, not parallel to `direction`.
    pub up: [f64; 3],
    /// Width covered by the columns, along the surface \[m\], finite, each taxel at least
    /// [`MIN_TAXEL_SIDE_OVER_RADIUS`] R wide.
    pub width: f64,
    /// Height covered by the rows, along the surface \[m\], finite, each taxel at least
    /// [`MIN_TAXEL_SIDE_OVER_RADIUS`] R high. The pad's corners
    /// lie within a quarter great circle of its centre: `sqrt(width² + height²) <= π R`.
    pub height: f64,
}

impl TactilePad {
    /// A pad of `rows` x `columns` taxels, `width` x `height` \[m\] along the surface, centred
    /// on `direction`, with the default `up`: the frame's `+z`, or `+x` when `direction` lies
    /// within 25° of the z axis.
    pub fn new(rows: u32, columns: u32, direction: [f64; 3], width: f64, height: f64) -> Self {
        let n = norm(direction);
        let up = if n > 0.0 && (direction[2] / n).abs() > 25f64.to_radians().cos() {
            [1.0, 0.0, 0.0]
        } else {
            [0.0, 0.0, 1.0]
        };
        Self {
            rows,
            columns,
            direction,
            up,
            width,
            height,
        }
    }

    /// The same pad with `up` (see [`up`](Self::up)).
    pub fn with_up(mut self, up: [f64; 3]) -> Self {
        self.up = up;
        self
    }

    /// Checks the pad for a fingertip of radius `radius` \[m\] (finite, > 0).
    pub(crate) fn validate(&self, radius: f64) -> Result<TactileGrid> {
        let side = |field: &'static str, n: u32| {
            if (1..=MAX_TAXELS_PER_SIDE).contains(&n) {
                Ok(())
            } else {
                Err(invalid(
                    field,
                    n as f64,
                    format!("an integer in 1..={MAX_TAXELS_PER_SIDE}"),
                ))
            }
        };
        side("tactile.rows", self.rows)?;
        side("tactile.columns", self.columns)?;
        let d = unit(self.direction).ok_or_else(|| {
            invalid(
                "tactile.direction",
                norm(self.direction),
                "finite and non-zero".into(),
            )
        })?;
        let n_up = norm(self.up);
        let cos = dot(self.up, d) / n_up; // NaN for a zero or non-finite `up`
        let e_v = (cos.abs() < 1.0 - 1e-9)
            .then(|| unit(std::array::from_fn(|i| self.up[i] - cos * n_up * d[i])))
            .flatten()
            .ok_or_else(|| {
                let range = "finite, non-zero and not parallel to `direction` (the cosine of their angle, given here, in (-1, 1))";
                invalid("tactile.up", cos, range.into())
            })?;
        let limit = std::f64::consts::PI * radius;
        if !(self.height.is_finite() && self.height > 0.0 && self.height < limit) {
            let range = format!(
                "finite, > 0 m and < π R = {} m (along the surface)",
                Shortest(limit)
            );
            return Err(invalid("tactile.height", self.height, range));
        }
        let w_max = (limit * limit - self.height * self.height).sqrt();
        if !(self.width.is_finite() && self.width > 0.0 && self.width <= w_max) {
            let range = format!(
                "finite, > 0 m and <= sqrt((π R)² - height²) = {} m (the corners within a quarter great circle of the centre)",
                Shortest(w_max)
            );
            return Err(invalid("tactile.width", self.width, range));
        }
        let min_side = MIN_TAXEL_SIDE_OVER_RADIUS * radius;
        for (field, size, n) in [
            ("tactile.width", self.width, self.columns),
            ("tactile.height", self.height, self.rows),
        ] {
            if size / f64::from(n) < min_side {
                let side = Shortest(min_side);
                let range = format!(
                    "at least {n} x {side} m ({n} taxels, each at least 1e-6 R = {side} m wide: f64 integrates smaller ones inexactly)"
                );
                return Err(invalid(field, size, range));
            }
        }
        Ok(TactileGrid {
            pad: TactilePad {
                direction: d,
                up: e_v,
                ..*self
            },
            e_u: cross(e_v, d),
            radius,
        })
    }
}

fn invalid(field: &'static str, value: f64, range: String) -> Error {
    Error::InvalidTactilePad {
        field,
        value,
        range,
    }
}

/// A validated tactile pad on a fingertip of radius R: the grid and its pad coordinates (see
/// the module's documentation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TactileGrid {
    /// The pad, `direction` normalised and `up` the unit tangent `e_v`.
    pad: TactilePad,
    /// Unit tangent of `+u`, `e_v x d`.
    e_u: [f64; 3],
    /// Fingertip radius R \[m\].
    radius: f64,
}

impl TactileGrid {
    /// Rows (the image's height).
    pub fn rows(&self) -> u32 {
        self.pad.rows
    }

    /// Columns (the image's width).
    pub fn columns(&self) -> u32 {
        self.pad.columns
    }

    /// The pad as given, `direction` normalised and `up` the unit tangent of `+v` [-].
    pub fn pad(&self) -> &TactilePad {
        &self.pad
    }

    /// Unit tangent of `+u` (the columns' direction) at the pad's centre, fingertip frame [-].
    pub fn right(&self) -> [f64; 3] {
        self.e_u
    }

    /// Width of a taxel along `u` \[m\].
    pub fn taxel_width(&self) -> f64 {
        self.pad.width / self.pad.columns as f64
    }

    /// Height of a taxel along `v` \[m\].
    pub fn taxel_height(&self) -> f64 {
        self.pad.height / self.pad.rows as f64
    }

    /// Area of a taxel in pad coordinates \[m²\].
    pub fn taxel_area(&self) -> f64 {
        self.taxel_width() * self.taxel_height()
    }

    /// Pad coordinates `(u, v)` \[m\] of the taxel centre at `row`, `column`.
    pub fn taxel_center(&self, row: u32, column: u32) -> [f64; 2] {
        [
            -0.5 * self.pad.width + (column as f64 + 0.5) * self.taxel_width(),
            0.5 * self.pad.height - (row as f64 + 0.5) * self.taxel_height(),
        ]
    }

    /// Pad coordinates `(u, v)` \[m\] of the surface point in the direction `s` of the
    /// fingertip's frame (any length): distance along the surface from the pad's centre, in
    /// the direction the point lies. `None` for a zero or non-finite `s` and for the antipode
    /// of the pad's centre.
    pub fn coordinates(&self, s: [f64; 3]) -> Option<[f64; 2]> {
        let s = unit(s)?;
        let d = self.pad.direction;
        let e_v = self.pad.up;
        let (x, y) = (dot(s, self.e_u), dot(s, e_v));
        let tangential = (x * x + y * y).sqrt();
        // atan2 keeps the angle accurate near 0 and π (acos of the cosine does not).
        let theta = tangential.atan2(dot(s, d));
        if tangential == 0.0 {
            return (theta == 0.0).then_some([0.0, 0.0]);
        }
        let k = self.radius * theta / tangential;
        Some([k * x, k * y])
    }
}

pub(crate) fn norm(v: [f64; 3]) -> f64 {
    dot(v, v).sqrt()
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `v` normalised, if finite and non-zero.
fn unit(v: [f64; 3]) -> Option<[f64; 3]> {
    let n = norm(v);
    (n.is_finite() && n > 0.0).then(|| v.map(|c| c / n))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(pad: TactilePad) -> TactileGrid {
        pad.validate(0.01).expect("a valid pad")
    }

    #[test]
    fn coordinates_are_arc_lengths_along_the_axes() {
        let g = grid(TactilePad::new(8, 8, [1.0, 0.0, 0.0], 0.01, 0.01).with_up([0.0, 1.0, 0.0]));
        // e_v = +y, e_u = e_v x d = y x x = -z.
        assert_eq!(g.right(), [0.0, 0.0, -1.0]);
        let t = 0.3f64;
        let up = g.coordinates([t.cos(), t.sin(), 0.0]).unwrap();
        assert!((up[0]).abs() < 1e-15 && (up[1] - 0.01 * t).abs() < 1e-15);
        let right = g.coordinates([t.cos(), 0.0, -t.sin()]).unwrap();
        assert!((right[0] - 0.01 * t).abs() < 1e-15 && right[1].abs() < 1e-15);
        assert_eq!(g.coordinates([-1.0, 0.0, 0.0]), None);
        assert_eq!(g.coordinates([2.0, 0.0, 0.0]), Some([0.0, 0.0]));
    }

    #[test]
    fn taxel_centres_run_left_to_right_and_top_to_bottom() {
        let g = grid(TactilePad::new(2, 4, [0.0, -1.0, 0.0], 0.008, 0.004));
        assert_eq!(g.taxel_center(0, 0), [-0.003, 0.001]);
        assert_eq!(g.taxel_center(1, 3), [0.003, -0.001]);
    }
}
