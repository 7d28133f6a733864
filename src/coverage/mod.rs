//! Coverage, the second pipeline stage: which pixels of each row a triangle covers.
//!
//! Rows are walked top to bottom. The left and right bounds of each row come from
//! [edge steppers](edge) (integer quotient and error term, no per-row division), are clipped to
//! the window and handed on as one [`Span`] per row. The result is bit for bit the exact
//! half-space test under the chosen [`FillRule`].

mod edge;
mod fill_rule;

use embedded_graphics::{
    geometry::{Point, Size},
    primitives::Rectangle,
};

pub use fill_rule::FillRule;

use crate::{
    geometry::Triangle,
    setup::{fits_fast_path, Clip, Lane, Prepared},
};
use edge::{EdgeStepper, Rounding};

/// A run of covered pixels on one row: `len` pixels starting at `(x, y)`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{prelude::*, primitives::Rectangle};
/// use trirast::coverage::Span;
///
/// let span = Span { x: 3, y: 7, len: 4 };
/// assert_eq!(span.rectangle(), Rectangle::new(Point::new(3, 7), Size::new(4, 1)));
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Span {
    /// Column of the first pixel.
    pub x: i32,
    /// Row.
    pub y: i32,
    /// Number of pixels, at least 1.
    pub len: u32,
}

impl Span {
    /// The span as a one-row rectangle, as `DrawTarget::fill_solid` takes it.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::coverage::Span;
    ///
    /// let rect = Span { x: -2, y: 0, len: 5 }.rectangle();
    /// assert_eq!(rect.size, Size::new(5, 1));
    /// ```
    #[inline]
    #[must_use]
    pub const fn rectangle(self) -> Rectangle {
        Rectangle::new(Point::new(self.x, self.y), Size::new(self.len, 1))
    }
}

/// Calls `emit` with every span of `triangle` inside `clip`, top to bottom, one per row.
///
/// This is the coverage the crate's drawing styles use; call it directly to feed spans to a
/// custom shader or a target of your own. Degenerate triangles produce nothing. The first error
/// returned by `emit` stops the walk and is returned.
///
/// Vertices may be any `i32`. When all coordinates lie within ±[`FAST_LIMIT`] the walk runs in
/// 32-bit arithmetic; beyond, it runs the same algorithm in 64-bit arithmetic, equally exact.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{prelude::*, primitives::Rectangle};
/// use trirast::{coverage::{for_each_span, Span}, FillRule, Triangle};
///
/// let triangle = Triangle::new(Point::new(0, 0), Point::new(4, 0), Point::new(0, 4));
/// let clip = Rectangle::new(Point::zero(), Size::new(100, 100));
/// let mut spans = Vec::new();
/// for_each_span(&triangle, FillRule::TopLeft, &clip, |span| {
///     spans.push(span);
///     Ok::<(), ()>(())
/// })?;
/// assert_eq!(spans[0], Span { x: 0, y: 0, len: 4 });
/// assert_eq!(spans.len(), 4);
/// # Ok::<(), ()>(())
/// ```
///
/// [`FAST_LIMIT`]: crate::FAST_LIMIT
#[inline]
pub fn for_each_span<E, F>(
    triangle: &Triangle,
    rule: FillRule,
    clip: &Rectangle,
    mut emit: F,
) -> Result<(), E>
where
    F: FnMut(Span) -> Result<(), E>,
{
    if fits_fast_path(&triangle.vertices) {
        walk::<i32, E, F>(triangle.vertices, rule, clip, &mut emit)
    } else {
        walk_wide(triangle.vertices, rule, clip, &mut emit)
    }
}

/// The wide path, kept out of line: rare, and it should not bloat the fast path's caller.
#[inline(never)]
fn walk_wide<E, F>(
    vertices: [Point; 3],
    rule: FillRule,
    clip: &Rectangle,
    emit: &mut F,
) -> Result<(), E>
where
    F: FnMut(Span) -> Result<(), E>,
{
    walk::<i64, E, F>(vertices, rule, clip, emit)
}

#[inline(always)]
fn walk<T: Lane, E, F>(
    vertices: [Point; 3],
    rule: FillRule,
    clip: &Rectangle,
    emit: &mut F,
) -> Result<(), E>
where
    F: FnMut(Span) -> Result<(), E>,
{
    let Some(clip) = Clip::<T>::from_rectangle(clip) else {
        return Ok(());
    };
    let Some(triangle) = Prepared::<T>::new(vertices) else {
        return Ok(());
    };
    let [top, middle, bottom] = triangle.sorted;
    // Top-left: rows top..bottom (the bottom vertex row is an apex or a bottom edge, both out).
    // Inclusive: rows top..=bottom.
    let (right_rounding, rows_end) = match rule {
        FillRule::TopLeft => (Rounding::Ceil, bottom.1),
        FillRule::Inclusive => (Rounding::FloorPlusOne, bottom.1 + T::ONE),
    };
    let first_row = top.1.max(clip.y0);
    let end_row = rows_end.min(clip.y1);
    if first_row >= end_row {
        return Ok(());
    }
    let left = triangle.long_edge_left;
    let (long_rounding, short_rounding) = if left {
        (Rounding::Ceil, right_rounding)
    } else {
        (right_rounding, Rounding::Ceil)
    };
    let row_span = |row: T, long_x: T, short_x: T, emit: &mut F| {
        let (l, r) = if left {
            (long_x, short_x)
        } else {
            (short_x, long_x)
        };
        let (l, r) = (l.max(clip.x0), r.min(clip.x1));
        if l < r {
            // Clipped values lie in the window, whose coordinates and width fit.
            emit(Span {
                x: l.to_i64() as i32,
                y: row.to_i64() as i32,
                len: (r - l).to_i64() as u32,
            })
        } else {
            Ok(())
        }
    };

    let mut long = EdgeStepper::start(top, bottom, long_rounding, first_row);
    // The upper short edge serves rows above the middle vertex. With a flat bottom (inclusive
    // rule only reaches that row) it also serves the middle row, where it ends exactly.
    let upper_end = if middle.1 < bottom.1 {
        middle.1
    } else {
        end_row
    }
    .min(end_row);
    let mut row = first_row;
    if row < upper_end {
        let mut short = EdgeStepper::start(top, middle, short_rounding, row);
        loop {
            row_span(row, long.x, short.x, emit)?;
            row += T::ONE;
            if row >= end_row {
                return Ok(());
            }
            long.advance();
            if row >= upper_end {
                break;
            }
            short.advance();
        }
    }
    // Rows from the middle vertex down: the lower short edge (row >= middle.1 here).
    let mut short = EdgeStepper::start(middle, bottom, short_rounding, row);
    loop {
        row_span(row, long.x, short.x, emit)?;
        row += T::ONE;
        if row >= end_row {
            return Ok(());
        }
        long.advance();
        short.advance();
    }
}
