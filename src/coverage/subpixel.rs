//! Coverage of sub-pixel triangles: the same exact walk as for whole-pixel vertices, with
//! vertices in 1/256 pixel.
//!
//! An edge from `a` to `b` (1/256 units, `a.y < b.y`) crosses pixel row `y` at
//! `X = a.x + (256 y - a.y) (b.x - a.x) / (b.y - a.y)`; its pixel bound there is `ceil(X / 256)`
//! (a left bound, or the exclusive end of a right one that leaves out samples on the edge) or
//! `floor(X / 256) + 1` (an end that keeps them). With `D = 256 (b.y - a.y)` that is
//! `floor(K / D)` for a numerator `K` that grows by `256 (b.x - a.x)` per row: the bound steps
//! by quotient and remainder, one division per edge, as Bresenham's does.

use embedded_graphics::{
    geometry::{Point, Size},
    primitives::Rectangle,
};

use super::{
    FillRule, Span, SpanSink,
    edge::{EdgeStepper, Rounding, increments},
};
use crate::{
    geometry::SubPixelTriangle,
    setup::{
        Lane,
        lane::{div_rem_floor_short, floor_div_rem_i128},
    },
};

/// One sub-pixel unit per pixel.
const UNIT: i64 = 256;

/// Sub-pixel edge starts: an edge from `a` to `b` steps from row to row as a whole-pixel
/// edge does ([`EdgeStepper`]), by `floor(dx / dy)` pixels and a remainder `rest` per row. In
/// terms of `D = 256 dy` its error term `E` (in `-D..0`) grows by `256 rest` a row, so it
/// moves in whole multiples of 256 and `E >= 0` exactly when `floor(E / 256) >= 0`: the
/// stepper keeps `floor(E / 256)`, in `-dy..0`, and steps it by `rest` against `dy`, bit
/// for bit the same bounds. Only the start differs (in lane `T`: 32-bit for triangles whose
/// every value of the walk fits it, see [`walk_subpixel`]; 64-bit beyond).
struct SubEdge<T>(core::marker::PhantomData<T>);

impl<T: Lane> SubEdge<T> {
    /// [`SubEdge::start_inline`] out of line, one copy per lane: the lower short edge, started
    /// between the row loop's two stretches (inline there, it made the loop spill: +6% per
    /// pixel on Cortex-M0).
    #[inline(never)]
    fn start(upper: (T, T), lower: (T, T), rounding: Rounding, row: T) -> EdgeStepper<T> {
        Self::start_inline(upper, lower, rounding, row)
    }

    /// The two edges a walk starts with, on the same row, inline: the long edge (`top` to
    /// `bottom`) and the short edge from `top` to `middle` (`upper_half`) or from `middle` to
    /// `bottom` (when the walk starts below the middle vertex). Inline, they cost 3.5% less per
    /// small sub-pixel triangle on Cortex-M0 than two calls of [`SubEdge::start`] (one call
    /// for both cost 4% more: its results went through memory twice).
    #[inline(always)]
    fn start_pair(
        [top, middle, bottom]: [(T, T); 3],
        (long_rounding, short_rounding): (Rounding, Rounding),
        row: T,
        upper_half: bool,
    ) -> (EdgeStepper<T>, EdgeStepper<T>) {
        let long = Self::start_inline(top, bottom, long_rounding, row);
        let (upper, lower) = if upper_half {
            (top, middle)
        } else {
            (middle, bottom)
        };
        (long, Self::start_inline(upper, lower, short_rounding, row))
    }

    /// The edge from `upper` to `lower` (1/256 units, `upper.1 < lower.1`) at pixel row `row`,
    /// whose samples lie at or below `upper`.
    ///
    /// The bound is `floor(K / D)` and the error `K mod D - D`, where `K = X dy + bias`,
    /// `D = 256 dy` and `X` is the crossing in 1/256 pixel. Written from the upper vertex's
    /// whole pixel `w` and fraction `f`, a row `down` units below it, with
    /// `dx = step dy + rest`: `K = 256 w dy + dy (f + down step) + down rest + bias`. Split
    /// `f + down step = 256 a + b` (`b` in `0..256`); the rest, `dy b + down rest + bias`, is
    /// non-negative and under `3 D` when the row lies less than a pixel below the vertex, so
    /// the bound is `w + a` plus at most 2: no division beyond the edge's own step. The
    /// stepper's error is `floor((K mod D - D) / 256)` (see [`SubEdge`]), counted in those
    /// units from the start: the bias is `D - 1` or `D`, so `floor((dy b + down rest + bias -
    /// D) / 256)` is `(dy b + down rest - 1) >> 8` or `(dy b + down rest) >> 8`.
    #[inline(always)]
    fn start_inline(upper: (T, T), lower: (T, T), rounding: Rounding, row: T) -> EdgeStepper<T> {
        let (dx, dy) = (lower.0 - upper.0, lower.1 - upper.1);
        let down = (row << 8) - upper.1;
        let small = T::from_i32(SMALL);
        if !(down < T::from_i32(256) && dy < small && T::in_half_open(dx, small)) {
            return Self::start_far(upper, (dx, dy), rounding, down);
        }
        // Deltas below 2^21 and a row within a pixel of the vertex: |down step|, dy b and
        // down rest each below 2^29, so every sum fits i32 (and 64-bit products are
        // library calls on Cortex-M0).
        let narrow = |v: T| v.to_i64() as i32;
        let (dx, dy, down) = (narrow(dx), narrow(dy), narrow(down));
        let (step, rest) = increments(dx, dy, div_rem_floor_short);
        let upper_x = narrow(upper.0);
        let moved = (upper_x & 0xFF) + down * step;
        let mut x = (upper_x >> 8) + (moved >> 8);
        // The error term in 1/256 of `D`: `floor((dy b + down rest + bias - D) / 256)`, where
        // the bias is `D - 1` or `D` (a multiple of 256 less one, or none).
        let ceil = match rounding {
            Rounding::Ceil => 1,
            Rounding::FloorPlusOne => 0,
        };
        let mut error = (dy * (moved & 0xFF) + down * rest - ceil) >> 8;
        // Below `2 dy`: at most two units, counted (a division measured 1.2% more per small
        // sub-pixel triangle on Cortex-M4F, a loop 4% more on Cortex-M0).
        if error >= 0 {
            error -= dy;
            x += 1;
            if error >= 0 {
                error -= dy;
                x += 1;
            }
        }
        EdgeStepper::from_parts(
            T::from_i32(x),
            T::from_i32(error),
            (T::from_i32(step), T::from_i32(rest)),
            T::from_i32(dy),
        )
    }

    /// [`SubEdge::start_inline`] for rows a pixel or more below the vertex (clipped tops, the lower
    /// short edge of a triangle clipped below its middle vertex) or deltas of 2^21 units and
    /// more: in 64 or 128 bits, out of line.
    #[cold]
    #[inline(never)]
    fn start_far(upper: (T, T), (dx, dy): (T, T), rounding: Rounding, down: T) -> EdgeStepper<T> {
        let divisor = dy << 8;
        let bias = match rounding {
            Rounding::Ceil => divisor - T::ONE,
            Rounding::FloorPlusOne => divisor,
        };
        let (step, rest) = increments(dx, dy, T::div_rem_floor);
        let wide = |v: T| v.to_i64();
        let (x, error) = start_bound_wide(
            (wide(upper.0 >> 8), wide(upper.0 & T::from_i32(0xFF))),
            (wide(dx), wide(dy)),
            wide(bias),
            wide(down),
        );
        EdgeStepper::from_parts(T::from_i64(x), T::from_i64(error >> 8), (step, rest), dy)
    }
}

/// The bound and error of [`SubEdge::start_inline`] for rows far below the vertex or long edges, in
/// 64 bits or, for far rows, 128: out of line, once.
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
const SMALL: i32 = 1 << 21;

/// `ceil(v / 256)`.
#[inline(always)]
fn ceil_row<T: Lane>(v: T) -> T {
    (v + T::from_i32(0xFF)) >> 8
}

/// Feeds every span of `triangle` inside `clip` to `sink`, top to bottom, one per row: pixel
/// `(x, y)` is covered when the point `(x, y)` lies inside the triangle under `rule`, exactly.
pub(crate) fn walk_subpixel<K: SpanSink + ?Sized>(
    triangle: &SubPixelTriangle,
    rule: FillRule,
    clip: &Rectangle,
    sink: &mut K,
) -> Result<(), K::Error> {
    let [mut top, mut middle, mut bottom] =
        triangle.vertices.map(|p| (p.x.to_bits(), p.y.to_bits()));
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
    // Triangles within ±2^30 units (4 million pixels) of the origin and under 2^23 units
    // (32,768 pixels) high walk in 32-bit arithmetic: `256 * row`, every bound, `256 * dy`
    // and the error terms then fit (widths do not matter: an x delta only divides).
    let biased = |v: i32| v.wrapping_add(NARROW_LIMIT) as u32;
    let inside =
        biased(top.0) | biased(middle.0) | biased(bottom.0) | biased(top.1) | biased(bottom.1);
    if inside < 1 << 31 && bottom.1 - top.1 < 1 << 23 {
        walk_in::<i32, K>([top, middle, bottom], rule, clip, sink)
    } else {
        // Rare: out of line and type-erased, one copy for every sink (its error is kept
        // here; the walk only stops). Scalars, not references: the cold call should not
        // force the window into memory on the fast path.
        let (tl, size) = (clip.top_left, clip.size);
        let mut error = None;
        let _ = walk_wide(
            [top.0, top.1, middle.0, middle.1, bottom.0, bottom.1],
            rule,
            [tl.x, tl.y, size.width as i32, size.height as i32],
            &mut |span| sink.span(span).map_err(|e| error = Some(e)),
        );
        error.map_or(Ok(()), Err)
    }
}

/// The span of `triangle` on `row` under `rule`, over every column but `i32::MAX`: one row of
/// the walk, for [`SubPixelTriangle`]'s points, through a sink behind `dyn` (one copy).
pub(crate) fn subpixel_row_span(
    triangle: &SubPixelTriangle,
    rule: FillRule,
    row: i32,
) -> Option<Span> {
    let mut found = None;
    let window = Rectangle::new(Point::new(i32::MIN, row), Size::new(u32::MAX, 1));
    let sink: &mut dyn SpanSink<Error = ()> = &mut |span| {
        found = Some(span);
        Ok(())
    };
    let _ = walk_subpixel(triangle, rule, &window, sink);
    found
}

/// Coordinates in `-NARROW_LIMIT..NARROW_LIMIT` (and heights under 2^23) walk in 32 bits.
const NARROW_LIMIT: i32 = 1 << 30;

/// [`walk_in`] in 64-bit arithmetic, for triangles beyond the 32-bit range.
#[inline(never)]
fn walk_wide(
    v: [i32; 6],
    rule: FillRule,
    clip: [i32; 4],
    sink: &mut dyn SpanSink<Error = ()>,
) -> Result<(), ()> {
    let wide = |x: i32, y: i32| (i64::from(x), i64::from(y));
    let vertices = [wide(v[0], v[1]), wide(v[2], v[3]), wide(v[4], v[5])];
    let clip = Rectangle::new(
        Point::new(clip[0], clip[1]),
        Size::new(clip[2] as u32, clip[3] as u32),
    );
    walk_in::<i64, _>(vertices, rule, &clip, sink)
}

/// The walk of vertices sorted by row, in lane `T`.
#[inline(always)]
fn walk_in<T: Lane, K: SpanSink + ?Sized>(
    [top, middle, bottom]: [(T, T); 3],
    rule: FillRule,
    clip: &Rectangle,
    sink: &mut K,
) -> Result<(), K::Error> {
    // The middle vertex right of the long edge (top to bottom): the long edge bounds the left.
    let Some(long_edge_left) = T::cross_positive(
        middle.0 - top.0,
        bottom.1 - top.1,
        middle.1 - top.1,
        bottom.0 - top.0,
    ) else {
        return Ok(());
    };
    let (x0, y0) = (i64::from(clip.top_left.x), i64::from(clip.top_left.y));
    // Pixel coordinates end at i32::MAX: clips reaching past it stop there.
    let (x1, y1) = (
        (x0 + i64::from(clip.size.width)).min(1 << 31),
        (y0 + i64::from(clip.size.height)).min(1 << 31),
    );
    // The clip in the lane (clamping changes no comparison: bounds and rows stay inside).
    let lane = |v: i64| T::from_i64(v.clamp(T::CLIP_MIN, T::CLIP_MAX));
    // Rows whose samples lie between the top and the bottom vertex: under the top-left rule a
    // sample on a bottom edge (or at a bottom apex) is out; under the inclusive rule, in.
    let (right_rounding, end) = match rule {
        FillRule::TopLeft => (Rounding::Ceil, ceil_row(bottom.1)),
        FillRule::Inclusive => (Rounding::FloorPlusOne, (bottom.1 >> 8) + T::ONE),
    };
    let first = ceil_row(top.1).max(lane(y0));
    let end = end.min(lane(y1));
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
    let upper_half = first < switch;
    let (long, short) = SubEdge::<T>::start_pair(
        [top, middle, bottom],
        (long_rounding, short_rounding),
        first,
        upper_half,
    );
    // Left and right chosen once: the rows then step two bounds, whichever edge each is.
    let (mut left, mut right) = if long_edge_left {
        (long, short)
    } else {
        (short, long)
    };
    let (left_clip, right_clip) = (lane(x0), lane(x1));
    let mut row = first;
    let mut stop = if upper_half { switch.min(end) } else { end };
    // Rows run in at most two stretches, above and below the middle vertex; the edges step
    // between rows, not after the last one of a stretch.
    loop {
        loop {
            let (l, r) = (left.x().max(left_clip), right.x().min(right_clip));
            if l < r {
                // Inside the clip, whose coordinates fit i32.
                let span = Span {
                    x: l.to_i64() as i32,
                    y: row.to_i64() as i32,
                    len: T::len_u32(r, l),
                };
                sink.span(span)?;
            }
            row += T::ONE;
            if row >= stop {
                break;
            }
            left.advance();
            right.advance();
        }
        if stop >= end {
            return Ok(());
        }
        // The lower half: the lower short edge from the first row below the middle vertex.
        let lower = SubEdge::start(middle, bottom, short_rounding, row);
        if long_edge_left {
            left.advance();
            right = lower;
        } else {
            right.advance();
            left = lower;
        }
        stop = end;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Bound and error from their definition: `K = X dy + bias` for the crossing `X` (1/256
    /// pixel) on `row`, `D = 256 dy`; the bound is `floor(K / D)`, the error `K mod D - D`,
    /// kept by the stepper as `floor((K mod D - D) / 256)`.
    fn exact(upper: (i64, i64), lower: (i64, i64), rounding: Rounding, row: i64) -> (i64, i64) {
        let (dx, dy) = (lower.0 - upper.0, lower.1 - upper.1);
        let d = 256 * dy;
        let bias = match rounding {
            Rounding::Ceil => d - 1,
            Rounding::FloorPlusOne => d,
        };
        let k = upper.0 * dy + (256 * row - upper.1) * dx + bias;
        (k.div_euclid(d), (k.rem_euclid(d) - d).div_euclid(256))
    }

    /// Every fraction of the upper vertex's row, edges from under a pixel to several pixels
    /// high of every slope up to three pixels a row both ways, both roundings, from the first
    /// row below the vertex (the inline start) and two rows further down (the far one), then
    /// stepped: bound and error exact on each row. The starts' remainders reach `2 D`
    /// exactly (e.g. `dy = 2`, `dx = 1`, fractions `255` and `254`, rounding `FloorPlusOne`),
    /// where counting must take both units.
    #[test]
    fn starts_and_steps_are_exact() {
        for dy in (1..=48i64).chain([255, 256, 257, 1000, 3000]) {
            for dx in (-3 * dy..=3 * dy).step_by((dy / 12).max(1) as usize) {
                for fy in 0..256 {
                    for fx in [0, 1, 127, 128, 254, 255] {
                        for rounding in [Rounding::Ceil, Rounding::FloorPlusOne] {
                            check(((-5 << 8) + fx, (7 << 8) + fy), (dx, dy), rounding);
                        }
                    }
                }
            }
        }
    }

    fn check(upper: (i64, i64), (dx, dy): (i64, i64), rounding: Rounding) {
        let lower = (upper.0 + dx, upper.1 + dy);
        let (first, last) = ((upper.1 + 255) >> 8, lower.1 >> 8);
        let narrow = |(x, y): (i64, i64)| (x as i32, y as i32);
        for start in [first, first + 2] {
            let mut edge =
                SubEdge::<i32>::start_inline(narrow(upper), narrow(lower), rounding, start as i32);
            for row in start..=last.min(start + 3) {
                let want = exact(upper, lower, rounding, row);
                let got = (i64::from(edge.x()), i64::from(edge.error()));
                assert_eq!(got, want, "{upper:?} {lower:?} {rounding:?} row {row}");
                edge.advance();
            }
        }
    }
}
