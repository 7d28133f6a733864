//! Coverage of sub-pixel triangles: the same exact walk as for whole-pixel vertices, with
//! vertices in 1/256 pixel.
//!
//! An edge from `a` to `b` (1/256 units, `a.y < b.y`) crosses pixel row `y` at
//! `X = a.x + (256 y - a.y) (b.x - a.x) / (b.y - a.y)`; its pixel bound there is `ceil(X / 256)`
//! (a left bound, or the exclusive end of a right one that leaves out samples on the edge) or
//! `floor(X / 256) + 1` (an end that keeps them). With `D = 256 (b.y - a.y)` that is
//! `floor(K / D)` for a numerator `K` that grows by `256 (b.x - a.x)` per row: the bound steps
//! by quotient and remainder, one division per edge, as Bresenham's does.

use embedded_graphics::primitives::Rectangle;

use super::{edge::Rounding, FillRule, Span, SpanSink};
use crate::geometry::SubPixelTriangle;

/// One sub-pixel unit per pixel.
const UNIT: i64 = 256;

/// An edge walked one row at a time: pixel bound, error term and increments.
#[derive(Copy, Clone, Debug)]
struct SubEdge {
    /// The pixel bound on the current row.
    x: i64,
    /// `K mod D - D`, in `-D..0`.
    error: i64,
    /// `floor(dx / dy)`: whole pixels per row.
    step: i64,
    /// `256 dx - step D`, in `0..D`.
    remainder: i64,
    /// `D = 256 dy`.
    divisor: i64,
}

impl SubEdge {
    /// The edge from `upper` to `lower` (1/256 units, `upper.1 < lower.1`) at pixel row `row`,
    /// whose samples lie at or below `upper`.
    fn start(upper: (i64, i64), lower: (i64, i64), rounding: Rounding, row: i64) -> Self {
        let (dx, dy) = (lower.0 - upper.0, lower.1 - upper.1);
        let divisor = UNIT * dy;
        let bias = match rounding {
            Rounding::Ceil => divisor - 1,
            Rounding::FloorPlusOne => divisor,
        };
        // K = X dy + bias with X in 1/256 (the bound is floor(K / D)): a.x dy + (256 row -
        // a.y) dx + bias. Far vertices make it wide: once per edge.
        let down = UNIT * row - upper.1;
        let narrow = upper
            .0
            .checked_mul(dy)
            .zip(down.checked_mul(dx))
            .and_then(|(a, b)| a.checked_add(b))
            .and_then(|k| k.checked_add(bias));
        let (x, error) = if let Some(k) = narrow {
            (k.div_euclid(divisor), k.rem_euclid(divisor) - divisor)
        } else {
            let k = i128::from(upper.0) * i128::from(dy)
                + i128::from(down) * i128::from(dx)
                + i128::from(bias);
            let d = i128::from(divisor);
            // A pixel bound within the 24-bit range, a remainder below D: both fit.
            (k.div_euclid(d) as i64, (k.rem_euclid(d) - d) as i64)
        };
        let step = dx.div_euclid(dy);
        Self {
            x,
            error,
            step,
            remainder: UNIT * (dx - step * dy),
            divisor,
        }
    }

    /// Moves to the next row.
    #[inline(always)]
    fn advance(&mut self) {
        self.x += self.step;
        self.error += self.remainder;
        if self.error >= 0 {
            self.x += 1;
            self.error -= self.divisor;
        }
    }
}

/// `ceil(v / 256)`.
fn ceil_row(v: i64) -> i64 {
    (v + UNIT - 1).div_euclid(UNIT)
}

/// Feeds every span of `triangle` inside `clip` to `sink`, top to bottom, one per row: pixel
/// `(x, y)` is covered when the point `(x, y)` lies inside the triangle under `rule`, exactly.
pub(crate) fn walk_subpixel<K: SpanSink + ?Sized>(
    triangle: &SubPixelTriangle,
    rule: FillRule,
    clip: &Rectangle,
    sink: &mut K,
) -> Result<(), K::Error> {
    let [mut top, mut middle, mut bottom] = triangle
        .vertices
        .map(|p| (i64::from(p.x.to_bits()), i64::from(p.y.to_bits())));
    // Sorted by row (ties in any order: coverage does not depend on it).
    if middle.1 < top.1 {
        core::mem::swap(&mut top, &mut middle);
    }
    if bottom.1 < middle.1 {
        core::mem::swap(&mut middle, &mut bottom);
        if middle.1 < top.1 {
            core::mem::swap(&mut top, &mut middle);
        }
    }
    // The middle vertex right of the long edge (top to bottom): the long edge bounds the left.
    let cross = i128::from(middle.0 - top.0) * i128::from(bottom.1 - top.1)
        - i128::from(middle.1 - top.1) * i128::from(bottom.0 - top.0);
    if cross == 0 {
        return Ok(());
    }
    let long_edge_left = cross > 0;
    let (x0, y0) = (i64::from(clip.top_left.x), i64::from(clip.top_left.y));
    // Pixel coordinates end at i32::MAX: clips reaching past it stop there.
    let (x1, y1) = (
        (x0 + i64::from(clip.size.width)).min(1 << 31),
        (y0 + i64::from(clip.size.height)).min(1 << 31),
    );
    // Rows whose samples lie between the top and the bottom vertex: under the top-left rule a
    // sample on a bottom edge (or at a bottom apex) is out; under the inclusive rule, in.
    let (right_rounding, end) = match rule {
        FillRule::TopLeft => (Rounding::Ceil, ceil_row(bottom.1)),
        FillRule::Inclusive => (Rounding::FloorPlusOne, bottom.1.div_euclid(UNIT) + 1),
    };
    let first = ceil_row(top.1).max(y0);
    let end = end.min(y1);
    if first >= end {
        return Ok(());
    }
    let (long_rounding, short_rounding) = if long_edge_left {
        (Rounding::Ceil, right_rounding)
    } else {
        (right_rounding, Rounding::Ceil)
    };
    // Rows above the middle vertex take the upper short edge, the others the lower one; with
    // a flat bottom (reached by the inclusive rule only) the upper one serves to the end.
    let switch = if middle.1 < bottom.1 {
        ceil_row(middle.1)
    } else {
        end
    };
    let long = SubEdge::start(top, bottom, long_rounding, first);
    let upper_half = first < switch;
    let mut short = if upper_half {
        SubEdge::start(top, middle, short_rounding, first)
    } else {
        SubEdge::start(middle, bottom, short_rounding, first)
    };
    let mut long = long;
    let mut row = first;
    let mut stop = if upper_half { switch.min(end) } else { end };
    loop {
        while row < stop {
            let (l, r) = if long_edge_left {
                (long.x, short.x)
            } else {
                (short.x, long.x)
            };
            let (l, r) = (l.max(x0), r.min(x1));
            if l < r {
                // Inside the clip, whose coordinates fit i32.
                let span = Span {
                    x: l as i32,
                    y: row as i32,
                    len: (r - l) as u32,
                };
                sink.span(span)?;
            }
            long.advance();
            short.advance();
            row += 1;
        }
        if stop >= end {
            return Ok(());
        }
        // The lower half: the lower short edge from the first row below the middle vertex.
        short = SubEdge::start(middle, bottom, short_rounding, row);
        stop = end;
    }
}
