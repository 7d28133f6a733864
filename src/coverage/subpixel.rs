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
use crate::{
    geometry::SubPixelTriangle,
    setup::{lane::floor_div_rem_i128, Lane},
};

/// One sub-pixel unit per pixel.
const UNIT: i64 = 256;

/// An edge walked one row at a time: pixel bound, error term and increments, in lane `T`
/// (32-bit for triangles under 2^23 units (32,768 pixels) across, which every value of the
/// walk then fits; 64-bit beyond).
#[derive(Copy, Clone, Debug)]
struct SubEdge<T> {
    /// The pixel bound on the current row.
    x: T,
    /// `K mod D - D`, in `-D..0`.
    error: T,
    /// `floor(dx / dy)`: whole pixels per row.
    step: T,
    /// `256 dx - step D`, in `0..D`.
    remainder: T,
    /// `D = 256 dy`.
    divisor: T,
}

impl<T: Lane> SubEdge<T> {
    /// The edge from `upper` to `lower` (1/256 units, `upper.1 < lower.1`) at pixel row `row`,
    /// whose samples lie at or below `upper`. Out of line: one copy per lane serves every
    /// style and target.
    #[inline(never)]
    fn start(upper: (i64, i64), lower: (i64, i64), rounding: Rounding, row: i64) -> Self {
        let (dx, dy) = (lower.0 - upper.0, lower.1 - upper.1);
        let divisor = UNIT * dy;
        let bias = match rounding {
            Rounding::Ceil => divisor - 1,
            Rounding::FloorPlusOne => divisor,
        };
        let (x, error) = start_bound(upper, (dx, dy), bias, row);
        // Steep edges (-dy <= dx < dy) move at most a pixel a row: no division.
        let (step, rest) = if dx < 0 && dx >= -dy {
            (-1, dx + dy)
        } else if dx >= 0 && dx < dy {
            (0, dx)
        } else {
            let (step, rest) = T::from_i64(dx).div_rem_floor(T::from_i64(dy));
            (step.to_i64(), rest.to_i64())
        };
        Self {
            x: T::from_i64(x),
            error: T::from_i64(error),
            step: T::from_i64(step),
            remainder: T::from_i64(UNIT * rest),
            divisor: T::from_i64(divisor),
        }
    }

    /// Moves to the next row.
    #[inline(always)]
    fn advance(&mut self) {
        self.x += self.step;
        self.error += self.remainder;
        if self.error >= T::ZERO {
            self.x += T::ONE;
            self.error -= self.divisor;
        }
    }
}

/// The pixel bound `floor(K / D)` and error `K mod D - D` of an edge from `upper` with deltas
/// `(dx, dy)` on pixel row `row`, where `K = X dy + bias` and `D = 256 dy` (`X` the crossing in
/// 1/256 pixel). Written from the upper vertex's whole pixel, so that the usual case (a row
/// less than a pixel below it, deltas under 2^21 units) takes one 32-bit division.
#[inline(always)]
fn start_bound(upper: (i64, i64), (dx, dy): (i64, i64), bias: i64, row: i64) -> (i64, i64) {
    let divisor = UNIT * dy;
    // Shifts and masks, not `div_euclid` (whose remainder is a 64-bit multiply on M0).
    let (whole, fraction) = (upper.0 >> 8, upper.0 & (UNIT - 1));
    let down = UNIT * row - upper.1;

    if down < UNIT && dy < SMALL && dx > -SMALL && dx < SMALL {
        // |fraction dy|, |down dx| and bias each below 2^29: the sum fits i32.
        // In 32 bits: 64-bit products are library calls on Cortex-M0.
        let narrow = |v: i64| v as i32;
        let k = narrow(fraction) * narrow(dy) + narrow(down) * narrow(dx) + narrow(bias);
        let d = narrow(divisor);
        // Cores without a divider (Cortex-M0/M0+: no compare-and-swap either, which is what
        // `target_has_atomic` can tell) count steep edges' quotients out; the others divide
        // (counting measured +4% per small flat triangle on Cortex-M4F).
        let count = cfg!(not(target_has_atomic = "32"));
        let (q, r) = if count && dx > -dy && dx < dy {
            // Steep: each term is under D in magnitude, so K / D is -1 to 3; count it out
            // rather than divide (a library call on Cortex-M0).
            let (mut q, mut r) = (0, k);
            while r < 0 {
                r += d;
                q -= 1;
            }
            while r >= d {
                r -= d;
                q += 1;
            }
            (q, r)
        } else {
            k.div_rem_floor(d)
        };
        return (whole + i64::from(q), i64::from(r) - divisor);
    }
    start_bound_wide((whole, fraction), (dx, dy), bias, down)
}

/// [`start_bound`] for rows far below the vertex or long edges: out of line, once.
#[inline(never)]
fn start_bound_wide(
    (whole, fraction): (i64, i64),
    (dx, dy): (i64, i64),
    bias: i64,
    down: i64,
) -> (i64, i64) {
    let divisor = UNIT * dy;
    let narrow = fraction
        .checked_mul(dy)
        .zip(down.checked_mul(dx))
        .and_then(|(a, b)| a.checked_add(b))
        .and_then(|k| k.checked_add(bias));
    if let Some(k) = narrow {
        let (q, r) = k.div_rem_floor(divisor);
        return (whole + q, r - divisor);
    }
    // Far rows make it wide: once per edge.
    let k = i128::from(fraction) * i128::from(dy)
        + i128::from(down) * i128::from(dx)
        + i128::from(bias);
    let d = i128::from(divisor);
    // A pixel bound within the 24-bit range, a remainder below D: both fit.
    let (quotient, remainder) = floor_div_rem_i128(k, d);
    (whole + quotient as i64, (remainder - d) as i64)
}

/// Deltas below which an edge's start fits 32 bits.
const SMALL: i64 = 1 << 21;

/// `ceil(v / 256)`.
fn ceil_row(v: i64) -> i64 {
    (v + UNIT - 1) >> 8
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
    // Triangles under 2^23 units (32,768 pixels) across walk in 32-bit arithmetic.
    let span = |a: i64, b: i64, c: i64| a.max(b).max(c) - a.min(b).min(c);
    if span(top.0, middle.0, bottom.0) < 1 << 23 && bottom.1 - top.1 < 1 << 23 {
        walk_in::<i32, K>([top, middle, bottom], rule, clip, sink)
    } else {
        // Rare: out of line and type-erased, one copy per error type.
        walk_wide([top, middle, bottom], rule, clip, &mut |span| {
            sink.span(span)
        })
    }
}

/// [`walk_in`] in 64-bit arithmetic, for triangles 2^23 units across or more.
#[inline(never)]
fn walk_wide<E>(
    vertices: [(i64, i64); 3],
    rule: FillRule,
    clip: &Rectangle,
    sink: &mut dyn SpanSink<Error = E>,
) -> Result<(), E> {
    walk_in::<i64, _>(vertices, rule, clip, sink)
}

/// The walk of vertices sorted by row, in lane `T`.
#[inline(always)]
fn walk_in<T: Lane, K: SpanSink + ?Sized>(
    [top, middle, bottom]: [(i64, i64); 3],
    rule: FillRule,
    clip: &Rectangle,
    sink: &mut K,
) -> Result<(), K::Error> {
    // The middle vertex right of the long edge (top to bottom): the long edge bounds the left.
    let delta = |v: i64| T::from_i64(v);
    let Some(long_edge_left) = T::cross_positive(
        delta(middle.0 - top.0),
        delta(bottom.1 - top.1),
        delta(middle.1 - top.1),
        delta(bottom.0 - top.0),
    ) else {
        return Ok(());
    };
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
        FillRule::Inclusive => (Rounding::FloorPlusOne, (bottom.1 >> 8) + 1),
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
    let long = SubEdge::<T>::start(top, bottom, long_rounding, first);
    let upper_half = first < switch;
    let mut short = if upper_half {
        SubEdge::start(top, middle, short_rounding, first)
    } else {
        SubEdge::start(middle, bottom, short_rounding, first)
    };
    let mut long = long;
    // The clip's columns in the lane (clamping changes no comparison: bounds stay inside).
    let lane = |v: i64| T::from_i64(v.clamp(T::CLIP_MIN, T::CLIP_MAX));
    let (left_clip, right_clip) = (lane(x0), lane(x1));
    let mut row = first;
    let mut stop = if upper_half { switch.min(end) } else { end };
    loop {
        while row < stop {
            let (l, r) = if long_edge_left {
                (long.x, short.x)
            } else {
                (short.x, long.x)
            };
            let (l, r) = (l.max(left_clip), r.min(right_clip));
            if l < r {
                // Inside the clip, whose coordinates fit i32.
                let span = Span {
                    x: l.to_i64() as i32,
                    y: row as i32,
                    len: T::len_u32(r, l),
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
