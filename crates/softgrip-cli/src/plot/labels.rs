//! Placing point labels so that they overlap neither each other nor the markers: greedy, in
//! pixels, trying positions around each point from the nearest out.

/// A box in pixels: left, top, width, height.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PixelBox {
    /// Left edge \[px\].
    pub x: i32,
    /// Top edge \[px\].
    pub y: i32,
    /// Width \[px\].
    pub w: i32,
    /// Height \[px\].
    pub h: i32,
}

impl PixelBox {
    fn overlaps(&self, o: &PixelBox) -> bool {
        self.x < o.x + o.w && o.x < self.x + self.w && self.y < o.y + o.h && o.y < self.y + self.h
    }

    fn inside(&self, area: &PixelBox) -> bool {
        self.x >= area.x
            && self.y >= area.y
            && self.x + self.w <= area.x + area.w
            && self.y + self.h <= area.y + area.h
    }
}

/// Half the size of the square kept free around each marker \[px\].
const MARKER_HALF: i32 = 8;

/// Top-left corners for labels of sizes `sizes` (width, height) at `points`, inside `area`.
/// Each label goes to the first free spot of a ring of candidates around its point (right,
/// left, above, below, then further out); if none is free it goes right of the point anyway.
/// Returns the corner and whether the label sits away from its point (draw a leader line).
pub fn place(
    points: &[(i32, i32)],
    sizes: &[(i32, i32)],
    area: PixelBox,
) -> Vec<((i32, i32), bool)> {
    let mut taken: Vec<PixelBox> = points
        .iter()
        .map(|&(x, y)| PixelBox {
            x: x - MARKER_HALF,
            y: y - MARKER_HALF,
            w: 2 * MARKER_HALF,
            h: 2 * MARKER_HALF,
        })
        .collect();
    let mut placed = Vec::with_capacity(points.len());
    for (&(px, py), &(w, h)) in points.iter().zip(sizes) {
        let candidates = (1..=6).flat_map(|ring| {
            let gap = MARKER_HALF + 2 + (ring - 1) * (h + 2);
            [
                (px + gap, py - h / 2),
                (px + gap, py - h - gap / 2),
                (px + gap, py + gap / 2),
                (px - gap - w, py - h / 2),
                (px - gap - w, py - h - gap / 2),
                (px - gap - w, py + gap / 2),
                (px - w / 2, py - gap - h),
                (px - w / 2, py + gap),
            ]
            .map(move |c| (c, ring > 1))
        });
        let mut chosen = ((px + MARKER_HALF + 2, py - h / 2), false);
        for (corner, far) in candidates {
            let b = PixelBox {
                x: corner.0,
                y: corner.1,
                w,
                h,
            };
            if b.inside(&area) && !taken.iter().any(|t| t.overlaps(&b)) {
                chosen = (corner, far);
                break;
            }
        }
        let ((x, y), _) = chosen;
        taken.push(PixelBox { x, y, w, h });
        placed.push(chosen);
    }
    placed
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn close_points_get_labels_that_do_not_overlap() {
        let area = PixelBox {
            x: 0,
            y: 0,
            w: 1000,
            h: 1000,
        };
        let points = [(500, 500), (505, 502), (510, 498)];
        let sizes = [(80, 16); 3];
        let placed = place(&points, &sizes, area);
        let boxes: Vec<PixelBox> = placed
            .iter()
            .zip(&sizes)
            .map(|(&((x, y), _), &(w, h))| PixelBox { x, y, w, h })
            .collect();
        for i in 0..3 {
            for j in 0..i {
                assert!(!boxes[i].overlaps(&boxes[j]), "{boxes:?}");
            }
            assert!(boxes[i].inside(&area));
        }
        // The first label finds a spot on the nearest ring (left: the right is crowded).
        assert_eq!(placed[0], ((500 - MARKER_HALF - 2 - 80, 492), false));
    }
}
