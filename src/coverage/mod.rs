//! Coverage, the second pipeline stage: which pixels of each row a triangle covers.
//!
//! Rows are walked top to bottom. The left and right bounds of each row come from
//! edge steppers (integer quotient and error term, no per-row division), are clipped to
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
    setup::{fits_fast_path, lane::FAST_LIMIT, sort_top_to_bottom, Clip, Lane, Prepared},
};
#[cfg(not(target_pointer_width = "32"))]
use edge::PackedStepper;
use edge::{EdgeStepper, EdgeWalk, Rounding};

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

/// Receives spans from [`walk`].
///
/// Any `FnMut(Span) -> Result<(), E>` closure is a sink. Implement the trait on a type of your
/// own when the per-span work must be inlined into the edge walk whatever the optimiser thinks
/// (closures cannot be marked `#[inline(always)]`); the crate's styles do.
///
/// # Examples
///
/// ```
/// use core::convert::Infallible;
/// use embedded_graphics::{prelude::*, primitives::Rectangle};
/// use trirast::{coverage::{walk, Span, SpanSink}, FillRule, Triangle};
///
/// /// Counts covered pixels.
/// struct Area(u64);
///
/// impl SpanSink for Area {
///     type Error = Infallible;
///
///     #[inline(always)]
///     fn span(&mut self, span: Span) -> Result<(), Infallible> {
///         self.0 += u64::from(span.len);
///         Ok(())
///     }
/// }
///
/// let triangle = Triangle::new(Point::new(0, 0), Point::new(10, 0), Point::new(0, 10));
/// let mut area = Area(0);
/// walk(&triangle, FillRule::TopLeft, &Rectangle::new(Point::zero(), Size::new(64, 64)), &mut area)?;
/// assert_eq!(area.0, 55);
/// # Ok::<(), Infallible>(())
/// ```
pub trait SpanSink {
    /// What the sink can fail with; the first error stops the walk.
    type Error;

    /// Takes one span.
    ///
    /// # Errors
    ///
    /// Whatever the sink reports; [`for_each_span`] stops and returns it.
    fn span(&mut self, span: Span) -> Result<(), Self::Error>;
}

impl<E, F: FnMut(Span) -> Result<(), E>> SpanSink for F {
    type Error = E;

    #[inline(always)]
    fn span(&mut self, span: Span) -> Result<(), E> {
        self(span)
    }
}

/// Calls `emit` with every span of `triangle` inside `clip`, top to bottom, one per row.
///
/// This is the coverage the crate's drawing styles use; call it directly to feed spans to a
/// custom shader or a target of your own. Degenerate triangles produce nothing. The first error
/// returned by `emit` stops the walk and is returned. ([`walk`] does the same for any
/// [`SpanSink`].)
///
/// Vertices may be any `i32`. When all coordinates lie within ±[`FAST_LIMIT`] the walk runs in
/// 32-bit arithmetic; beyond, it runs the same algorithm in 64-bit arithmetic, equally exact.
///
/// # Errors
///
/// The first error `emit` returns.
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
    walk(triangle, rule, clip, &mut emit)
}

/// Feeds every span of `triangle` inside `clip` to `sink`, top to bottom, one per row: the
/// same walk as [`for_each_span`], for sinks that are not closures.
///
/// # Errors
///
/// The first error the sink returns.
///
/// # Examples
///
/// ```
/// use core::convert::Infallible;
/// use embedded_graphics::{prelude::*, primitives::Rectangle};
/// use trirast::{coverage::{walk, Span, SpanSink}, FillRule, Triangle};
///
/// struct Rows(Vec<i32>);
///
/// impl SpanSink for Rows {
///     type Error = Infallible;
///
///     fn span(&mut self, span: Span) -> Result<(), Infallible> {
///         self.0.push(span.y);
///         Ok(())
///     }
/// }
///
/// let triangle = Triangle::new(Point::new(0, 0), Point::new(6, 3), Point::new(0, 6));
/// let mut rows = Rows(Vec::new());
/// walk(&triangle, FillRule::TopLeft, &Rectangle::new(Point::zero(), Size::new(8, 8)), &mut rows)?;
/// assert_eq!(rows.0, [1, 2, 3, 4, 5]);
/// # Ok::<(), Infallible>(())
/// ```
#[inline]
pub fn walk<K: SpanSink + ?Sized>(
    triangle: &Triangle,
    rule: FillRule,
    clip: &Rectangle,
    sink: &mut K,
) -> Result<(), K::Error> {
    walk_inlined(triangle, rule, clip, sink)
}

/// [`walk`] as a function of its own for each sink, as the depth path wants it: inlined there, its
/// row loops leave no room to inline the target's span fill (measured on the band renderer).
/// With `small-code` the walk is small and left to the compiler, as [`walk`] is.
#[cfg_attr(not(feature = "small-code"), inline(never))]
#[cfg_attr(feature = "small-code", inline)]
pub(crate) fn walk_outlined<K: SpanSink + ?Sized>(
    triangle: &Triangle,
    rule: FillRule,
    clip: &Rectangle,
    sink: &mut K,
) -> Result<(), K::Error> {
    walk_inlined(triangle, rule, clip, sink)
}

/// [`walk`], inlined into the caller in optimised builds: the plain styles' draws, where a call
/// costs tiny triangles several percent (`benches/ir.sh flat small`). Not forced into the depth
/// path, whose band renderer grows and slows with it, nor into debug builds, whose test
/// binaries take many times longer to build with it.
#[cfg_attr(
    all(not(feature = "small-code"), not(debug_assertions)),
    inline(always)
)]
#[cfg_attr(any(feature = "small-code", debug_assertions), inline)]
pub(crate) fn walk_inlined<K: SpanSink + ?Sized>(
    triangle: &Triangle,
    rule: FillRule,
    clip: &Rectangle,
    sink: &mut K,
) -> Result<(), K::Error> {
    let sorted = sort_top_to_bottom(triangle.vertices);
    let [a, b, c] = sorted;
    if cfg!(feature = "small-code") {
        // One clipped variant of the row loop instead of three.
        return if fits_fast_path(&sorted) {
            walk_lane::<i32, FastEdge, K, true, true>(sorted, rule, clip, sink)
        } else {
            // Type-erased: one wide walk per error type rather than one per style and target
            // (a call per span is nothing next to 64-bit edge stepping).
            let (tl, size) = (clip.top_left, clip.size);
            let mut erased: &mut dyn FnMut(Span) -> Result<(), K::Error> =
                &mut move |span| sink.span(span);
            walk_wide(
                [a.x, a.y, b.x, b.y, c.x, c.y],
                rule,
                [tl.x, tl.y, size.width as i32, size.height as i32],
                &mut erased,
            )
        };
    }
    // Span bounds lie within x_min..=x_max + 1 and rows within a.y..=c.y: a triangle inside
    // the window needs no clipping at all, and its edges all start at their upper vertex.
    // Inside a window within the fast range, it is within the fast range too.
    let window = Window::new(clip);
    let inside_x = window.holds_x(a.x) && window.holds_x(b.x) && window.holds_x(c.x);
    if inside_x && window.holds_y(a.y) && window.holds_y(c.y) && window.in_fast_range() {
        if cfg!(not(target_pointer_width = "32")) && c.y - a.y <= SHORT_ROWS {
            walk_lane::<i32, EdgeStepper<i32>, K, false, false>(sorted, rule, clip, sink)
        } else {
            walk_lane::<i32, FastEdge, K, false, false>(sorted, rule, clip, sink)
        }
    } else if fits_fast_path(&sorted) {
        if inside_x {
            walk_lane::<i32, FastEdge, K, true, false>(sorted, rule, clip, sink)
        } else {
            walk_lane::<i32, FastEdge, K, true, true>(sorted, rule, clip, sink)
        }
    } else {
        // Scalars, not references: the cold call should not force the triangle and window
        // into memory on the fast path.
        let (tl, size) = (clip.top_left, clip.size);
        walk_wide(
            [a.x, a.y, b.x, b.y, c.x, c.y],
            rule,
            [tl.x, tl.y, size.width as i32, size.height as i32],
            sink,
        )
    }
}

/// The edge stepper of the 32-bit paths. On 64-bit machines the packed stepper (position and
/// error term in one register) steps a row in fewer instructions; 32-bit ones have no such
/// registers.
#[cfg(not(target_pointer_width = "32"))]
type FastEdge = PackedStepper;
#[cfg(target_pointer_width = "32")]
type FastEdge = EdgeStepper<i32>;

/// Triangles at most this many rows high take the plain stepper even on 64-bit machines: it
/// starts in fewer instructions, which matters more than stepping for a few rows (measured with
/// `benches/ir.sh flat small`).
const SHORT_ROWS: i32 = 4;

/// A window's half-open `i32` bounds, with the ends saturated at `i32::MAX` (which only makes
/// the inside test more conservative).
#[derive(Copy, Clone)]
struct Window {
    x0: i32,
    x1: i32,
    y0: i32,
    y1: i32,
}

impl Window {
    #[inline(always)]
    fn new(area: &Rectangle) -> Self {
        let end = |start: i32, len: u32| {
            i32::try_from(i64::from(start) + i64::from(len)).unwrap_or(i32::MAX)
        };
        Self {
            x0: area.top_left.x,
            x1: end(area.top_left.x, area.size.width),
            y0: area.top_left.y,
            y1: end(area.top_left.y, area.size.height),
        }
    }

    /// `x0 <= x < x1`, in one unsigned comparison.
    #[inline(always)]
    fn holds_x(self, x: i32) -> bool {
        (x.wrapping_sub(self.x0) as u32) < self.x1.wrapping_sub(self.x0) as u32
    }

    /// `y0 <= y < y1`, in one unsigned comparison.
    #[inline(always)]
    fn holds_y(self, y: i32) -> bool {
        (y.wrapping_sub(self.y0) as u32) < self.y1.wrapping_sub(self.y0) as u32
    }

    /// True when every pixel of the window lies in the fast range.
    #[inline(always)]
    fn in_fast_range(self) -> bool {
        let limit = FAST_LIMIT + 1;
        self.x0 >= -limit && self.y0 >= -limit && self.x1 <= limit && self.y1 <= limit
    }
}

/// The wide path, kept out of line: rare, and it should not bloat the fast path's caller.
#[inline(never)]
#[cold]
fn walk_wide<K: SpanSink + ?Sized>(
    v: [i32; 6],
    rule: FillRule,
    clip: [i32; 4],
    sink: &mut K,
) -> Result<(), K::Error> {
    let sorted = [
        Point::new(v[0], v[1]),
        Point::new(v[2], v[3]),
        Point::new(v[4], v[5]),
    ];
    let clip = Rectangle::new(
        Point::new(clip[0], clip[1]),
        Size::new(clip[2] as u32, clip[3] as u32),
    );
    walk_lane::<i64, EdgeStepper<i64>, K, true, true>(sorted, rule, &clip, sink)
}

/// Walks a triangle whose vertices are sorted top to bottom. `CLIP` is false only for
/// triangles inside the window; `CLIP_X` is false for triangles inside it horizontally.
#[inline(always)]
fn walk_lane<
    T: Lane,
    E: EdgeWalk<T>,
    K: SpanSink + ?Sized,
    const CLIP: bool,
    const CLIP_X: bool,
>(
    sorted: [Point; 3],
    rule: FillRule,
    clip: &Rectangle,
    sink: &mut K,
) -> Result<(), K::Error> {
    let clip = if CLIP {
        match Clip::<T>::from_rectangle(clip) {
            Some(clip) => clip,
            None => return Ok(()),
        }
    } else {
        // Unused: nothing is clipped.
        Clip {
            x0: T::ZERO,
            x1: T::ZERO,
            y0: T::ZERO,
            y1: T::ZERO,
        }
    };
    let Some(triangle) = Prepared::<T>::from_sorted(sorted) else {
        return Ok(());
    };
    if triangle.long_edge_left {
        walk_rows::<T, E, K, CLIP, CLIP_X, true>(&triangle, rule, &clip, sink)
    } else {
        walk_rows::<T, E, K, CLIP, CLIP_X, false>(&triangle, rule, &clip, sink)
    }
}

/// `CLIP` is false for triangles inside the window, which skip every clipping step.
#[inline(always)]
fn walk_rows<
    T: Lane,
    E: EdgeWalk<T>,
    K: SpanSink + ?Sized,
    const CLIP: bool,
    const CLIP_X: bool,
    const LONG_LEFT: bool,
>(
    triangle: &Prepared<T>,
    rule: FillRule,
    clip: &Clip<T>,
    sink: &mut K,
) -> Result<(), K::Error> {
    let [top, middle, bottom] = triangle.sorted;
    // Top-left: rows top..bottom (the bottom vertex row is an apex or a bottom edge, both out).
    // Inclusive: rows top..=bottom.
    let (right_rounding, rows_end) = match rule {
        FillRule::TopLeft => (Rounding::Ceil, bottom.1),
        FillRule::Inclusive => (Rounding::FloorPlusOne, bottom.1 + T::ONE),
    };
    let (mut first_row, end_row) = if CLIP {
        (top.1.max(clip.y0), rows_end.min(clip.y1))
    } else {
        (top.1, rows_end)
    };
    // Under the top-left rule the row of a lone top vertex is empty (its span is
    // `x0..x0`): start one row lower, stepping the edges once instead of walking a row.
    let skip_apex = rule == FillRule::TopLeft && first_row == top.1 && top.1 < middle.1;
    if skip_apex {
        first_row += T::ONE;
    }
    if first_row >= end_row {
        return Ok(());
    }
    let (long_rounding, short_rounding) = if LONG_LEFT {
        (Rounding::Ceil, right_rounding)
    } else {
        (right_rounding, Rounding::Ceil)
    };

    let mut long = if skip_apex {
        let mut edge = E::start(top, bottom, long_rounding, top.1, true);
        edge.advance();
        edge
    } else {
        E::start(
            top,
            bottom,
            long_rounding,
            first_row,
            // Unclipped, the long edge nearly always advances: skip the test.
            !CLIP || end_row - first_row > T::ONE,
        )
    };
    // The upper short edge serves rows above the middle vertex, the lower one the rest. With a
    // flat bottom (which only the inclusive rule reaches) the upper edge also serves the middle
    // row, where it ends exactly; the lower edge is then never started.
    let switch_row = if middle.1 < bottom.1 {
        middle.1
    } else {
        end_row
    };
    let mut row = first_row;
    if row < switch_row {
        // Unclipped, the middle row never lies past the end.
        let rows = if CLIP {
            switch_row.min(end_row)
        } else {
            switch_row
        } - row;
        let short = if skip_apex {
            let mut edge = E::start(top, middle, short_rounding, top.1, true);
            edge.advance();
            edge
        } else {
            E::start(top, middle, short_rounding, row, rows > T::ONE)
        };
        rows_between::<T, E, K, CLIP_X, LONG_LEFT>(&mut long, short, row, rows, clip, sink)?;
        row += rows;
        if row == end_row {
            return Ok(());
        }
        long.advance();
    }
    // Unclipped, this row is the middle vertex's (after a one-row top half or a flat top).
    let row = if CLIP { row } else { middle.1 };
    let rows = end_row - row;
    let short = E::start(middle, bottom, short_rounding, row, rows > T::ONE);
    rows_between::<T, E, K, CLIP_X, LONG_LEFT>(&mut long, short, row, rows, clip, sink)
}

/// Emits `rows` rows (at least one) from `row` down between the long edge and one short edge,
/// leaving the long edge on the last of them.
///
/// Specialised by which side the long edge is on, so each row costs two edge steps, a
/// comparison and the sink.
#[inline(always)]
fn rows_between<
    T: Lane,
    E: EdgeWalk<T>,
    K: SpanSink + ?Sized,
    const CLIP_X: bool,
    const LONG_LEFT: bool,
>(
    long: &mut E,
    mut short: E,
    mut row: T,
    rows: T,
    clip: &Clip<T>,
    sink: &mut K,
) -> Result<(), K::Error> {
    let mut edge = *long;
    let last = row + rows - T::ONE;
    let result = loop {
        let (mut l, mut r) = if LONG_LEFT {
            (edge.x(), short.x())
        } else {
            (short.x(), edge.x())
        };
        if CLIP_X {
            l = l.max(clip.x0);
            r = r.min(clip.x1);
        }
        if l < r {
            // Values inside the window, whose coordinates and width fit.
            let span = Span {
                x: l.to_i64() as i32,
                y: row.to_i64() as i32,
                len: T::len_u32(r, l),
            };
            if let Err(e) = sink.span(span) {
                break Err(e);
            }
        }
        if row == last {
            break Ok(());
        }
        row += T::ONE;
        edge.advance();
        short.advance();
    };
    *long = edge;
    result
}
