//! Coverage, the second pipeline stage: which pixels of each row a triangle covers.
//!
//! Rows are walked top to bottom. The left and right bounds of each row come from
//! edge steppers (integer quotient and error term, no per-row division), are clipped to
//! the window and handed on as one [`Span`] per row. The result is bit for bit the exact
//! half-space test under the chosen [`FillRule`].

mod area;
mod edge;
mod fill_rule;
mod rows;
mod subpixel;

use embedded_graphics::{
    geometry::{Point, Size},
    primitives::Rectangle,
};

pub use fill_rule::FillRule;

pub(crate) use area::{CoverageSink, walk_coverage, walk_subpixel_coverage};
pub(crate) use rows::KeptWalk;
use rows::RowWalk;
pub(crate) use subpixel::{subpixel_row_span, walk_subpixel};

/// Calls `emit` with every span of the sub-pixel `triangle` inside `clip`, top to bottom, one
/// per row: pixel `(x, y)` is covered when the point `(x, y)` lies inside the exact triangle
/// under `rule`, as [`for_each_span`] does for whole-pixel vertices (and, given those, with
/// the same spans). Edges step by quotient and remainder, one division each; vertices may lie
/// anywhere in [`SubPoint`](crate::geometry::SubPoint)'s range.
///
/// # Errors
///
/// The first error `emit` returns.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{prelude::*, primitives::Rectangle};
/// use fixed::types::I24F8;
/// use trirast::{coverage::{for_each_subpixel_span, Span}, geometry::{SubPixelTriangle, SubPoint}, FillRule};
///
/// let at = |x: f32, y: f32| SubPoint::new(I24F8::from_num(x), I24F8::from_num(y));
/// // Rows 1 and 2 only: the top vertex lies between rows 0 and 1.
/// let t = SubPixelTriangle::new(at(0.0, 0.5), at(8.0, 2.5), at(0.0, 2.5));
/// let clip = Rectangle::new(Point::zero(), Size::new(16, 16));
/// let mut spans = Vec::new();
/// for_each_subpixel_span(&t, FillRule::TopLeft, &clip, |span| {
///     spans.push(span);
///     Ok::<(), ()>(())
/// })?;
/// assert_eq!(spans, [Span { x: 0, y: 1, len: 2 }, Span { x: 0, y: 2, len: 6 }]);
/// # Ok::<(), ()>(())
/// ```
#[inline]
pub fn for_each_subpixel_span<E, F>(
    triangle: &crate::geometry::SubPixelTriangle,
    rule: FillRule,
    clip: &Rectangle,
    mut emit: F,
) -> Result<(), E>
where
    F: FnMut(Span) -> Result<(), E>,
{
    walk_subpixel(triangle, rule, clip, &mut emit)
}

/// Calls `emit` with every run of pixels inside `clip` that `triangle` covers in part or in
/// whole, and how much: the area of each pixel's square (side 1, centred on the pixel) inside
/// the triangle, from 1 to 255 (whole). Runs go top to bottom and left to right, one pixel
/// long where an edge crosses the pixels, and one run per row for the pixels between the
/// edges. This is the coverage anti-aliased drawing blends with
/// ([`BlendTarget::draw_anti_aliased`](crate::target::BlendTarget::draw_anti_aliased)).
///
/// Each coverage is within 1/256 of the exact area (plus rounding to 1/255), for any `i32`
/// vertices; triangles sharing an edge have coverages that add up to the pixel (within the
/// same bound). Pixels farther than 2^22 from the origin are not visited.
///
/// # Errors
///
/// The first error `emit` returns.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{prelude::*, primitives::Rectangle};
/// use trirast::{coverage::for_each_coverage_run, Triangle};
///
/// // A right triangle whose hypotenuse runs through pixel centres: half of each square on it.
/// let triangle = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
/// let clip = Rectangle::new(Point::zero(), Size::new(16, 16));
/// let mut runs = Vec::new();
/// for_each_coverage_run(&triangle, &clip, |span, coverage| {
///     runs.push((span.x, span.y, span.len, coverage));
///     Ok::<(), ()>(())
/// })?;
/// // Row 4: the pixel on the left edge is half covered, then three whole ones, then the
/// // diagonal's pixel, half covered again.
/// let row: Vec<_> = runs.iter().filter(|r| r.1 == 4).copied().collect();
/// assert_eq!(row[..3], [(0, 4, 1, 128), (1, 4, 3, 255), (4, 4, 1, 128)]);
/// # Ok::<(), ()>(())
/// ```
#[inline]
pub fn for_each_coverage_run<E, F>(
    triangle: &Triangle,
    clip: &Rectangle,
    mut emit: F,
) -> Result<(), E>
where
    F: FnMut(Span, u8) -> Result<(), E>,
{
    area::walk_coverage(triangle, clip, &mut PixelRuns(&mut emit))
}

/// Hands on coverage as [`for_each_coverage_run`] promises: edge pixels one at a time,
/// uncovered ones left out.
struct PixelRuns<F>(F);

impl<E, F: FnMut(Span, u8) -> Result<(), E>> CoverageSink for PixelRuns<F> {
    type Error = E;

    fn interior(&mut self, span: Span, coverage: u8) -> Result<(), E> {
        (self.0)(span, coverage)
    }

    fn edge(&mut self, x: i32, y: i32, coverages: &[u8]) -> Result<(), E> {
        for (k, &coverage) in coverages.iter().enumerate() {
            if coverage > 0 {
                let span = Span {
                    x: x + k as i32,
                    y,
                    len: 1,
                };
                (self.0)(span, coverage)?;
            }
        }
        Ok(())
    }
}

use crate::{
    geometry::Triangle,
    setup::{Clip, Lane, Prepared, fits_fast_path, sort_top_to_bottom},
};
use edge::{ExactEdge, Rounding};

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

impl<E, F: FnMut(Span) -> Result<(), E> + ?Sized> SpanSink for F {
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
// Always inlined: the row loop belongs in each style's draw, with the painter's span work in
// it. One shared out-of-line copy (the optimiser's choice once bands and frames draw through
// the same painters) costs a flat triangle on Cortex-M0 a third more.
#[inline(always)]
pub fn walk<K: SpanSink + ?Sized>(
    triangle: &Triangle,
    rule: FillRule,
    clip: &Rectangle,
    sink: &mut K,
) -> Result<(), K::Error> {
    let sorted = sort_top_to_bottom(triangle.vertices);
    if fits_fast_path(&sorted) {
        walk_fast(sorted, rule, clip, sink)
    } else {
        // Rare: out of line, and type-erased, so there is one wide walk for every style,
        // target and error type (the sink's error is kept here; the walk only stops). Scalars,
        // not references: the cold call should not force the triangle and window into memory
        // on the fast path.
        let [a, b, c] = sorted;
        let (tl, size) = (clip.top_left, clip.size);
        let mut error = None;
        let _ = walk_wide(
            [a.x, a.y, b.x, b.y, c.x, c.y],
            rule,
            [tl.x, tl.y, size.width as i32, size.height as i32],
            &mut |span| sink.span(span).map_err(|e| error = Some(e)),
        );
        error.map_or(Ok(()), Err)
    }
}

/// [`walk`] for a sink behind `dyn`: one copy of the row loop per error type, shared by every
/// style and target of the depth-tested pass, whose span work is a long call anyway, instead
/// of one copy each.
#[inline(never)]
pub(crate) fn walk_erased<E>(
    triangle: &Triangle,
    rule: FillRule,
    clip: &Rectangle,
    sink: &mut dyn SpanSink<Error = E>,
) -> Result<(), E> {
    walk(triangle, rule, clip, sink)
}

/// [`walk_erased`] for a triangle drawn window after window down the screen (bands): it goes
/// on from the walk `kept` left at this window's first row, if any, rather than starting again
/// (sorting, orienting and jumping its edges down), and when `later` leaves its walk there for
/// the window below (when the triangle goes on below).
#[inline(never)]
pub(crate) fn walk_kept_erased<E>(
    triangle: &Triangle,
    rule: FillRule,
    clip: &Rectangle,
    sink: &mut dyn SpanSink<Error = E>,
    kept: &KeptWalk,
    later: bool,
) -> Result<(), E> {
    let Some(window) = Clip::fast(clip) else {
        return Ok(());
    };
    let rows = if let Some(rows) = kept.resume(&window) {
        rows
    } else {
        let sorted = sort_top_to_bottom(triangle.vertices);
        if !fits_fast_path(&sorted) {
            return walk_erased(triangle, rule, clip, sink);
        }
        let Some(rows) = RowWalk::start(sorted, rule, window) else {
            return Ok(());
        };
        rows
    };
    rows.run(&window, sink, later.then_some(kept))
}

/// The rows a triangle covers inside a window, and how its edges round there: what the fast
/// and the wide walk share.
struct RowPlan<T> {
    triangle: Prepared<T>,
    clip: Clip<T>,
    /// First row to emit and the end of the rows (exclusive), in the window.
    first: T,
    end: T,
    /// The end of the triangle's rows, wherever the window ends.
    rows_end: T,
    /// The first row the lower short edge serves (never reached with a flat bottom).
    switch: T,
    /// Under the top-left rule, the first row is the one below a lone top vertex, whose own row
    /// is empty.
    skip_apex: bool,
    long_rounding: Rounding,
    short_rounding: Rounding,
}

impl<T: Lane> RowPlan<T> {
    /// `None` when nothing of the triangle is inside the window (or it is degenerate).
    #[inline(always)]
    fn new(sorted: [Point; 3], rule: FillRule, clip: Clip<T>) -> Option<Self> {
        let triangle = Prepared::<T>::from_sorted(sorted)?;
        let [top, middle, bottom] = triangle.sorted;
        // Top-left: rows top..bottom (the bottom vertex row is an apex or a bottom edge, both
        // out). Inclusive: rows top..=bottom.
        let (right_rounding, rows_end) = match rule {
            FillRule::TopLeft => (Rounding::Ceil, bottom.1),
            FillRule::Inclusive => (Rounding::FloorPlusOne, bottom.1 + T::ONE),
        };
        let mut first = top.1.max(clip.y0);
        let end = rows_end.min(clip.y1);
        let skip_apex = rule == FillRule::TopLeft && first == top.1 && top.1 < middle.1;
        if skip_apex {
            first += T::ONE;
        }
        if first >= end {
            return None;
        }
        let (long_rounding, short_rounding) = if triangle.long_edge_left {
            (Rounding::Ceil, right_rounding)
        } else {
            (right_rounding, Rounding::Ceil)
        };
        // The upper short edge serves rows above the middle vertex, the lower one the rest.
        // With a flat bottom (which only the inclusive rule reaches) the upper edge also serves
        // the middle row, where it ends exactly.
        let switch = if middle.1 < bottom.1 { middle.1 } else { end };
        Some(Self {
            triangle,
            clip,
            first,
            end,
            rows_end,
            switch,
            skip_apex,
            long_rounding,
            short_rounding,
        })
    }
}

/// Emits the span between bounds `l` and `r` on `row`, clipped to the window `clip`, if any.
#[inline(always)]
fn emit<T: Lane, K: SpanSink + ?Sized>(
    clip: &Clip<T>,
    l: T,
    r: T,
    row: T,
    sink: &mut K,
) -> Result<(), K::Error> {
    let l = l.max(clip.x0);
    let r = r.min(clip.x1);
    if l < r {
        // Values inside the window, whose coordinates and width fit.
        let span = Span {
            x: l.to_i64() as i32,
            y: row.to_i64() as i32,
            len: T::len_u32(r, l),
        };
        sink.span(span)?;
    }
    Ok(())
}

/// The fast walk, in 32-bit arithmetic: the one row loop of the crate ([`RowWalk::run`]).
/// Rows and columns are clipped by bounds computed once, so triangles inside the window and
/// triangles crossing its edges take the same code; each row costs two edge steps, a clip and
/// the sink.
#[inline(always)]
fn walk_fast<K: SpanSink + ?Sized>(
    sorted: [Point; 3],
    rule: FillRule,
    clip: &Rectangle,
    sink: &mut K,
) -> Result<(), K::Error> {
    let Some(clip) = Clip::fast(clip) else {
        return Ok(());
    };
    match RowWalk::start(sorted, rule, clip) {
        Some(rows) => rows.run(&clip, sink, None),
        None => Ok(()),
    }
}

/// The span of the triangle `sorted` (by [`sort_top_to_bottom`]) on `row` under `rule`, over
/// every column but `i32::MAX` (which the top-left rule never covers): one row of the wide
/// walk, for [`Triangle::points`](crate::Triangle), so that drawing links no other code for it.
pub(crate) fn row_span(sorted: [Point; 3], rule: FillRule, row: i32) -> Option<Span> {
    let [a, b, c] = sorted;
    let mut found = None;
    // The window: every column from i32::MIN (a width of u32::MAX, passed as -1), one row.
    let _ = walk_wide(
        [a.x, a.y, b.x, b.y, c.x, c.y],
        rule,
        [i32::MIN, row, -1, 1],
        &mut |span| {
            found = Some(span);
            Ok(())
        },
    );
    found
}

/// The wide walk, for vertices beyond the fast range: 64-bit arithmetic, each row's bounds
/// computed exactly from the edge's start (no stepping state), out of line and type-erased.
#[inline(never)]
#[cold]
fn walk_wide(
    v: [i32; 6],
    rule: FillRule,
    clip: [i32; 4],
    sink: &mut dyn FnMut(Span) -> Result<(), ()>,
) -> Result<(), ()> {
    let sorted = [
        Point::new(v[0], v[1]),
        Point::new(v[2], v[3]),
        Point::new(v[4], v[5]),
    ];
    let clip = Rectangle::new(
        Point::new(clip[0], clip[1]),
        Size::new(clip[2] as u32, clip[3] as u32),
    );
    let Some(plan) =
        Clip::from_rectangle(&clip).and_then(|clip| RowPlan::<i64>::new(sorted, rule, clip))
    else {
        return Ok(());
    };
    let [top, middle, bottom] = plan.triangle.sorted;
    let long = ExactEdge::new(top, bottom, plan.long_rounding);
    // A flat top or bottom leaves its short edge unused: the long edge stands in.
    let short = |upper: (i64, i64), lower: (i64, i64)| {
        if upper.1 < lower.1 {
            ExactEdge::new(upper, lower, plan.short_rounding)
        } else {
            long
        }
    };
    let (upper, lower) = (short(top, middle), short(middle, bottom));
    let mut row = plan.first;
    while row < plan.end {
        let short = if row < plan.switch { &upper } else { &lower };
        let (l, r) = if plan.triangle.long_edge_left {
            (long.at(row), short.at(row))
        } else {
            (short.at(row), long.at(row))
        };
        emit(&plan.clip, l, r, row, sink)?;
        row += 1;
    }
    Ok(())
}
