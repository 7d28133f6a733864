//! Area coverage for anti-aliased edges: for each pixel, the part of its square (side 1,
//! centred on the pixel) that lies inside the triangle.
//!
//! Rows are walked top to bottom; in each, the triangle's left and right boundaries are the
//! pieces of its edges inside the row's strip. The area of a pixel's square left of a boundary
//! piece has a closed form (a rectangle, a trapezoid and nothing, cut where the piece enters and
//! leaves the column), so a pixel's coverage is what lies left of the right boundary minus what
//! lies left of the left one: exact for any shape of the triangle within the pixel, corners and
//! slivers included. Columns between the boundaries are covered by the whole strip and go out
//! as one run; only the columns a boundary crosses are computed pixel by pixel.
//!
//! Arithmetic is fixed point with 12 fraction bits (1/4096 pixel), in coordinates shifted by half
//! a pixel so that pixel `(x, y)`'s square is `[x, x + 1] x [y, y + 1]`. Triangles within 65,536
//! pixels of the clip's corner (every one a screen shows whole) are walked in `i32` from that
//! corner, the rest in `i64` (see [`Coord`]). Boundaries are stepped
//! from row to row by quotient and remainder (one division per edge, none per row); where a
//! boundary crosses a column is found with a per-edge reciprocal. Positions and crossings are
//! kept to within 1/4096 pixel, each costing a pixel at most 3/4096 of its area per boundary
//! piece, of which at most four cross a pixel: each coverage is within 1/256 of the exact
//! area before rounding to 1/255 (`tests/suite/antialias.rs` checks it against exact rational
//! clipping).

use core::{
    fmt::Debug,
    iter::Sum,
    ops::{Add, AddAssign, Shl, Shr, Sub, SubAssign},
};

use embedded_graphics::primitives::Rectangle;

use super::Span;
use crate::bounds::{at, at_mut, first, within_mut};
use crate::geometry::Triangle;
use crate::setup::{
    Lane,
    lane::{floor_div_rem_i128, mul_u32},
    reciprocal::divide_by_inverse,
};

/// Fraction bits of positions.
const FRAC: u32 = 12;
/// One pixel.
const ONE: i64 = 1 << FRAC;
/// Full coverage of a pixel, in units of `1 / (ONE * ONE)` of its square.
const FULL: i64 = ONE * ONE;
/// Pixels processed lie within this many pixels of the origin, so that the rows and columns
/// walked stay far inside `i64` (a target wider than 2^22 pixels is not drawn past it).
const REACH: i64 = 1 << 22;
/// Most vertices of a chain (from the top vertex to the bottom one).
const MAX_VERTICES: usize = 3;
/// Most edges of a chain, and so most pieces of a chain in a row.
const MAX_EDGES: usize = MAX_VERTICES - 1;
/// Vertices within this many units (1/4096 pixel) of the clip's corner, 65,536 pixels, are
/// walked in `i32`: edges then span under 2^29 units, so positions, remainders and their sums
/// stay within 2^31.
const NARROW_REACH: i64 = 1 << 28;
/// Columns and rows of the clip walked in `i32` (from its corner): their positions, under
/// 2^29 units, fit too.
const NARROW_CLIP: i64 = 1 << 17;

/// The integer type of positions and of the per-row state: `i32` for triangles near the clip,
/// where each addition and comparison is one instruction on 32-bit cores (two or more in
/// `i64`; in `i32` anti-aliased triangles take a third fewer instructions on Cortex-M0 and
/// M4F), `i64` for any other. Set-ups (one per edge) compute in `i64` either way and narrow
/// what they keep.
trait Coord:
    Copy
    + Ord
    + Default
    + Debug
    + Add<Output = Self>
    + Sub<Output = Self>
    + AddAssign
    + SubAssign
    + Shl<u32, Output = Self>
    + Shr<u32, Output = Self>
    + Sum
{
    const ZERO: Self;
    /// A pixel, `1 << FRAC`.
    const PIXEL: Self;
    /// A pixel less one unit: added before a shift, rounds up to whole pixels.
    const PIXEL_LESS_ONE: Self;
    /// Half a pixel.
    const HALF: Self;
    /// [`FULL`].
    const FULL: Self;
    /// `value`, which the caller has kept within range (or never reads when it is not).
    fn narrow(value: i64) -> Self;
    fn widen(self) -> i64;
    /// The low 32 bits.
    fn low(self) -> i32;
    /// Whether this is `i64`, whose differences may exceed 32 bits.
    const WIDE: bool;
}

macro_rules! coord {
    ($($t:ty),+) => {$(
        impl Coord for $t {
            const ZERO: Self = 0;
            const PIXEL: Self = 1 << FRAC;
            const PIXEL_LESS_ONE: Self = (1 << FRAC) - 1;
            const HALF: Self = 1 << (FRAC - 1);
            const FULL: Self = 1 << (2 * FRAC);
            const WIDE: bool = <$t>::BITS > 32;
            #[inline(always)]
            fn narrow(value: i64) -> Self {
                value as $t
            }
            #[inline(always)]
            fn widen(self) -> i64 {
                self.into()
            }
            #[inline(always)]
            fn low(self) -> i32 {
                self as i32
            }
        }
    )+};
}

coord!(i32, i64);

/// A position, in units of 1/4096 pixel, shifted by half a pixel.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
struct Position<P> {
    x: P,
    y: P,
}

/// One edge of a boundary, from its upper end `a` to its lower end `b`, with where it crosses
/// the current row boundary.
#[derive(Copy, Clone, Debug)]
struct Edge<P> {
    a: Position<P>,
    b: Position<P>,
    /// `b.y - a.y`, positive.
    dy: P,
    /// Rows the crossing state has reached: the boundary `y` (a multiple of `ONE`) where the
    /// edge is at `x + remainder / dy`.
    y: P,
    x: P,
    remainder: P,
    /// Per row: `ONE * dx = step * dy + step_remainder`. Stepped only across boundaries inside
    /// the edge, so at least a row apart: then `|step| <= |dx| + 1`, which fits `P`; an edge
    /// within one row may keep a wrapped step it never adds.
    step: P,
    step_remainder: P,
    /// Rows (1/4096 units) the edge takes per 1/4096 pixel across, times 2^32 (`u64::MAX` for
    /// vertical edges, which never cross a column inside a row).
    rows_per_column: u64,
}

impl<P: Coord> Edge<P> {
    /// A placeholder for chains of fewer edges than [`MAX_EDGES`]: never read (a chain reads
    /// its first `count` edges only). All zeros, so that an empty chain is cleared, not copied.
    const UNUSED: Self = Edge {
        a: Position {
            x: P::ZERO,
            y: P::ZERO,
        },
        b: Position {
            x: P::ZERO,
            y: P::ZERO,
        },
        dy: P::ZERO,
        y: P::ZERO,
        x: P::ZERO,
        remainder: P::ZERO,
        step: P::ZERO,
        step_remainder: P::ZERO,
        rows_per_column: 0,
    };

    /// Makes this the edge from `a` to `b`, from the first row boundary at or below `a` and at
    /// or below row `first_row`.
    #[inline(always)]
    fn start(&mut self, a: Position<P>, b: Position<P>, first_row: i64) {
        // Set up in i64, whatever `P` keeps: products of deltas and a pixel overflow i32.
        let widen = |p: Position<P>| Position {
            x: p.x.widen(),
            y: p.y.widen(),
        };
        let (a, b) = (widen(a), widen(b));
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        // The first row boundary at or below `a` and at or below the first row drawn.
        let y = ((a.y + ONE - 1) >> FRAC) << FRAC;
        let y = y.max(first_row * ONE);
        let ((x, remainder), (step, step_remainder)) = if y - a.y == ONE / 2 {
            // The usual start, half a row below a vertex at a pixel centre: the row step is
            // twice the half-row one, so one division serves both.
            let (half, rest) = floor_div(ONE / 2 * dx, dy);
            let carry = i64::from(2 * rest >= dy);
            ((half, rest), (2 * half + carry, 2 * rest - carry * dy))
        } else {
            let (step, step_remainder) = floor_div(ONE * dx, dy);
            (
                start_from_step(y - a.y, dx, dy, step, step_remainder),
                (step, step_remainder),
            )
        };
        let x = a.x + x;
        let (across, down) = (dx.unsigned_abs() >> FRAC, (dy as u64) >> FRAC);
        let whole_pixels = (dx | dy) & (ONE - 1) == 0;
        let magnitude = dx.unsigned_abs();
        let rows_per_column = if (magnitude.wrapping_sub(1) | dy as u64) < 1 << 16 {
            // At most 16 pixels across (not vertical) and under 16 down: the ratio in 1/4096
            // units (whole pixels give the same quotient: scaling both does not change it).
            ratio_by_digits(dy as u32, magnitude as u32)
        } else if dx == 0 {
            u64::MAX
        } else if whole_pixels && across < 1 << 16 && down < 1 << 16 {
            // Vertices at pixel centres, under 2^16 pixels apart: the ratio in whole pixels.
            ratio_by_digits(down as u32, across as u32)
        } else if (dx | dy).trailing_zeros() >= 4 && dx.unsigned_abs() < 1 << 20 && dy < 1 << 20 {
            // Vertices in 1/256 pixel (16 units), under 256 pixels each way: in 1/256 pixel.
            ratio_by_digits((dy >> 4) as u32, (dx.unsigned_abs() >> 4) as u32)
        } else if dy < 1 << 32 {
            ((dy as u64) << 32) / dx.unsigned_abs()
        } else {
            let rows = (u128::from(dy as u64) << 32) / u128::from(dx.unsigned_abs());
            u64::try_from(rows).unwrap_or(u64::MAX)
        };
        let narrow = |p: Position<i64>| Position {
            x: P::narrow(p.x),
            y: P::narrow(p.y),
        };
        self.a = narrow(a);
        self.b = narrow(b);
        self.dy = P::narrow(dy);
        self.y = P::narrow(y);
        self.x = P::narrow(x);
        self.remainder = P::narrow(remainder);
        self.step = P::narrow(step);
        self.step_remainder = P::narrow(step_remainder);
        self.rows_per_column = rows_per_column;
    }

    /// Where the edge crosses row boundary `y` (to 1/4096 pixel, rounded down), for `y` at or
    /// after the last boundary asked for.
    fn x_at(&mut self, y: P) -> P {
        while self.y < y {
            self.y += P::PIXEL;
            self.x += self.step;
            self.remainder += self.step_remainder;
            if self.remainder >= self.dy {
                self.remainder -= self.dy;
                self.x += P::narrow(1);
            }
        }
        self.x
    }

    /// The piece of this edge `rows` high, from where it crosses at `start_x` to `end_x`.
    #[inline(always)]
    fn piece(&self, rows: P, start_x: P, end_x: P) -> Piece<P> {
        Piece {
            rows,
            left: start_x.min(end_x),
            right: start_x.max(end_x),
            rows_per_column: self.rows_per_column,
        }
    }
}

/// `(rows << 32) / across` for `rows` under 2^16 and `across` in `1..=2^16`, by two 16-bit
/// digits of 32-bit division (each dividend below 2^32): a 64-bit division is a library call
/// on every Cortex-M.
#[inline(always)]
fn ratio_by_digits(rows: u32, across: u32) -> u64 {
    if !crate::arch::DIVIDES {
        return ratio_by_inverse(rows, across);
    }
    let high = (rows << 16) / across;
    let low = (((rows << 16) % across) << 16) / across;
    (u64::from(high) << 16) | u64::from(low)
}

/// [`ratio_by_digits`] without a division, for Cortex-M0 (where each is a library call of
/// about 130 instructions): `rows 2^32` is the base-2^16 digits `rows, 0, 0`, divided by
/// [`divide_by_inverse`]. Exact. Out of line: one copy.
#[inline(never)]
fn ratio_by_inverse(rows: u32, across: u32) -> u64 {
    if across <= 1 {
        return u64::from(rows) << 32;
    }
    divide_by_inverse([rows, 0, 0], across)
}

/// `n / d` rounded down, and the remainder (`0..d`), for `d > 0`: one division, in 32 bits
/// when both fit (on Cortex-M0 every division is a library call, a 64-bit one several).
#[inline]
fn floor_div(n: i64, d: i64) -> (i64, i64) {
    match (i32::try_from(n), i32::try_from(d)) {
        (Ok(n), Ok(d)) => {
            let (q, r) = n.div_rem_floor(d);
            (i64::from(q), i64::from(r))
        }
        _ => n.div_rem_floor(d),
    }
}

/// [`start_crossing`] from the row step `ONE dx = step dy + step_remainder`, without a
/// second division where every product fits 32 bits (within a row of the vertex, for edges
/// under 128 pixels high moving under 128 pixels a row): with `down step = q 2^12 + r`,
/// `down dx = q dy + t` for `t = (r dy + down step_remainder) / 2^12`, which is exact and in
/// `0..2 dy`.
#[inline(always)]
fn start_from_step(down: i64, dx: i64, dy: i64, step: i64, step_remainder: i64) -> (i64, i64) {
    // One comparison per bound (`dy` is positive, `down` not negative).
    if (down as u64) < ONE as u64 && (step.unsigned_abs() | dy as u64) < 1 << 19 {
        let moved = down as i32 * step as i32;
        let (whole, part) = (moved >> FRAC, (moved & (ONE as i32 - 1)) as u32);
        let (dy, down) = (dy as u32, down as u32);
        let t = (part * dy + down * step_remainder as u32) >> FRAC;
        return if t >= dy {
            (i64::from(whole) + 1, i64::from(t - dy))
        } else {
            (i64::from(whole), i64::from(t))
        };
    }
    start_crossing(down, dx, dy)
}

/// `down * dx / dy` as quotient (rounded down) and remainder, for `down >= 0`, `dy > 0`: in
/// 64 bits when the product fits, as it does for vertices within 2^19 pixels of each other.
fn start_crossing(down: i64, dx: i64, dy: i64) -> (i64, i64) {
    if down < ONE && dx.unsigned_abs() < 1 << 19 {
        // The usual start, within a row of the vertex, of an edge under 128 pixels across:
        // the product below 2^31, a 32-bit multiply (a 64-bit one is a library call on
        // Cortex-M0).
        return floor_div(i64::from(down as i32 * dx as i32), dy);
    }
    if let Some(numerator) = down.checked_mul(dx) {
        floor_div(numerator, dy)
    } else {
        let numerator = i128::from(down) * i128::from(dx);
        let dy = i128::from(dy);
        // The quotient is at most |dx| and the remainder below dy: both fit.
        let (quotient, remainder) = floor_div_rem_i128(numerator, dy);
        (quotient as i64, remainder as i64)
    }
}

/// The part of a boundary edge inside one row: rows `top..bottom` (1/4096 units), crossing
/// columns `left..=right` (1/4096 units).
#[derive(Copy, Clone, Debug, Default)]
struct Piece<P> {
    rows: P,
    left: P,
    right: P,
    rows_per_column: u64,
}

impl<P: Coord> Piece<P> {
    /// Rows (1/4096 units) where the piece lies left of `x`, for `x` in `left..=right`:
    /// 32-bit arithmetic within a column's width of either end (the columns anti-aliasing
    /// solves, on Cortex-M0 a 64-bit multiply is a library call), 64-bit beyond.
    #[inline(always)]
    fn rows_left_of(&self, x: P) -> P {
        let (from_left, from_right) = (x - self.left, self.right - x);
        let rows = self.rows.low() as u32; // At most ONE.
        if from_left <= P::PIXEL || from_right <= P::PIXEL {
            // Integer and 16 fraction bits of rows per 1/4096 pixel; more than a row per
            // unit saturates, as the result does.
            let per_x = (self.rows_per_column >> 32).min(u64::from(rows)) as u32;
            let fraction = (self.rows_per_column as u32) >> 16;
            let rows_over = |across: P| {
                let across = across.low() as u32;
                (across * per_x + ((across * fraction) >> 16)).min(rows)
            };
            let left_of = if from_left <= from_right {
                rows_over(from_left)
            } else {
                rows - rows_over(from_right)
            };
            return P::narrow(i64::from(left_of));
        }
        let across = from_left.widen() as u64;
        let rows = if P::WIDE {
            (across.saturating_mul(self.rows_per_column) >> 32) as i64
        } else if self.rows_per_column >> 32 > 0 {
            // More than a column in at a whole row per unit or more: every row.
            return self.rows;
        } else {
            // Under 2^31 units across: the product's upper word, where a 64-bit multiply is a
            // library call on Cortex-M0.
            (mul_u32(across as u32, self.rows_per_column as u32) >> 32) as i64
        };
        P::narrow(rows.min(self.rows.widen()))
    }

    /// The area of column `column`'s square (in 1/4096 pixels from 0) left of this piece, in
    /// units of [`FULL`] per pixel: the integral over the piece's rows of how far the piece
    /// lies into the column, between 0 and 1. Out of line: one copy serves every caller.
    #[inline(never)]
    fn area_left_of(&self, column: P) -> P {
        let (x0, x1) = (column, column + P::PIXEL);
        if self.right <= x0 {
            return P::ZERO;
        }
        if self.left >= x1 {
            return self.rows << FRAC;
        }
        // Everything below is within the column: 32-bit products.
        let rows = self.rows.low();
        if self.left == self.right {
            // Vertical, inside the column.
            return P::narrow(i64::from(rows * (self.left - x0).low()));
        }
        let (enter, leave) = (x0.max(self.left), x1.min(self.right));
        // Where the piece ends inside the column, all its rows are left of its end: the
        // reciprocal, applied to rounded positions, would leave a few rows over.
        let before = if enter == self.left {
            0
        } else {
            self.rows_left_of(enter).low()
        };
        let inside = if leave == self.right {
            rows
        } else {
            self.rows_left_of(leave).low().max(before)
        };
        // Past the column: the whole width; inside it: the mean depth into it (both factors
        // non-negative: halved by a shift, where `/ 2` rounds a sign it cannot have).
        let depth = (enter - x0).low() + (leave - x0).low();
        P::narrow(i64::from(
            (rows - inside) * ONE as i32 + (((inside - before) * depth) >> 1),
        ))
    }
}

/// The boundaries of one row: pieces of the left and the right chain.
#[derive(Copy, Clone, Debug, Default)]
struct RowBoundaries<P> {
    left: [Piece<P>; MAX_EDGES],
    right: [Piece<P>; MAX_EDGES],
    lefts: usize,
    rights: usize,
    /// Rows of the strip inside the triangle (1/4096 units).
    rows: P,
}

impl<P: Coord> RowBoundaries<P> {
    /// Coverage of column `column` (in 1/4096 pixels), in units of [`FULL`].
    #[inline]
    fn coverage(&self, column: P) -> P {
        let right: P = first(&self.right, self.rights)
            .iter()
            .map(|p| p.area_left_of(column))
            .sum();
        let left: P = first(&self.left, self.lefts)
            .iter()
            .map(|p| p.area_left_of(column))
            .sum();
        (right - left).clamp(P::ZERO, P::FULL)
    }

    /// Columns (in pixels) the pieces of `pieces` touch: `first..end`.
    fn columns(pieces: &[Piece<P>]) -> (P, P) {
        let left = pieces.iter().map(|p| p.left).min().unwrap_or(P::ZERO);
        let right = pieces.iter().map(|p| p.right).max().unwrap_or(P::ZERO);
        (left >> FRAC, (right + P::PIXEL_LESS_ONE) >> FRAC)
    }
}

/// A chain of edges from the top vertex to the bottom one, on one side.
#[derive(Copy, Clone, Debug)]
struct Chain<P> {
    edges: [Edge<P>; MAX_EDGES],
    count: usize,
    /// First edge not yet finished above the current row.
    next: usize,
}

impl<P: Coord> Chain<P> {
    /// No edges.
    const EMPTY: Self = Self {
        edges: [Edge::UNUSED; MAX_EDGES],
        count: 0,
        next: 0,
    };

    /// Makes this the chain through `vertices` (from the top vertex down to the bottom one).
    /// In place, each edge written where it is kept: built and returned, the chain and its
    /// edges (88 bytes each in `i64`) went through three `memcpy` calls, about 700 instructions
    /// per small triangle on Cortex-M0 (measured again by value in `i32`: +1.9%).
    fn start(&mut self, vertices: &[Position<P>], first_row: i64) {
        self.count = 0;
        self.next = 0;
        for pair in vertices.windows(2) {
            // Horizontal edges bound no row.
            if pair[1].y > pair[0].y {
                if let Some(edge) = self.edges.get_mut(self.count) {
                    edge.start(pair[0], pair[1], first_row);
                    self.count += 1;
                }
            }
        }
    }

    /// Whether one edge crosses the strip `top..top + ONE` whole (no vertex inside): the
    /// common row.
    #[inline(always)]
    fn crosses(&self, top: P) -> bool {
        first(&self.edges, self.count)
            .get(self.next)
            .is_some_and(|edge| edge.a.y < top && edge.b.y > top + P::PIXEL)
    }

    /// The piece of the strip `top..top + ONE` that [`Chain::crosses`] found.
    #[inline(always)]
    fn across(&mut self, top: P) -> Piece<P> {
        let edge = at_mut(&mut self.edges, self.next);
        let (start_x, end_x) = (edge.x_at(top), edge.x_at(top + P::PIXEL));
        edge.piece(P::PIXEL, start_x, end_x)
    }

    /// The pieces of this chain inside the strip `top..top + ONE`.
    #[inline]
    fn pieces(&mut self, top: P, out: &mut [Piece<P>; MAX_EDGES]) -> usize {
        // One edge across the whole strip on this side only (the common row, both sides so,
        // does not come here): what the general case below makes of it too.
        if self.crosses(top) {
            out[0] = self.across(top);
            return 1;
        }
        let bottom = top + P::PIXEL;
        while self.next < self.count && at(&self.edges, self.next).b.y <= top {
            self.next += 1;
        }
        let mut count = 0;
        for edge in within_mut(&mut self.edges, self.next, self.count) {
            if edge.a.y >= bottom {
                break;
            }
            let (start, start_x) = if edge.a.y >= top {
                (edge.a.y, edge.a.x)
            } else {
                (top, edge.x_at(top))
            };
            let (end, end_x) = if edge.b.y <= bottom {
                (edge.b.y, edge.b.x)
            } else {
                (bottom, edge.x_at(bottom))
            };
            if end > start {
                *at_mut(out, count) = edge.piece(end - start, start_x, end_x);
                count += 1;
            }
        }
        count
    }
}

/// Coverage (units of [`FULL`], 0 to `FULL`) as an opacity, 0 to 255, rounded.
#[inline(always)]
fn opacity<P: Coord>(coverage: P) -> u8 {
    opacity32(coverage.low())
}

/// [`opacity`] of a coverage already in `i32` (0 to `FULL`, which fits).
#[inline(always)]
fn opacity32(coverage: i32) -> u8 {
    // 16 bits of coverage are plenty; the product then fits 32 bits.
    let coverage = (coverage >> (2 * FRAC - 16)) as u32;
    ((coverage * 255 + (1 << 15)) >> 16) as u8
}

/// Emits the columns of row `y` that one boundary piece crosses, alone: the row's only piece
/// on its side, with the other side's columns apart. Coverage is what lies right of the piece
/// (`left_side`) or left of it, of a strip `rows` high. Columns the piece crosses whole, all
/// but its first and last, take equal steps of rows: their coverage is stepped, not solved.
#[inline]
fn lone_piece_columns<P: Coord, K: CoverageSink>(
    piece: &Piece<P>,
    left_side: bool,
    rows: P,
    clip: (P, P),
    run: &mut EdgeRun,
    sink: &mut K,
) -> Result<(), K::Error> {
    // Shifts, not `div_euclid` (whose remainder costs a 64-bit multiply on Cortex-M0).
    let first = piece.left >> FRAC;
    let end = (piece.right + P::PIXEL_LESS_ONE) >> FRAC;
    // Everything below is within a column or two of the piece: 32-bit arithmetic.
    let strip = (rows << FRAC).low();
    let put = |run: &mut EdgeRun, sink: &mut K, column: P, area_left: i32| {
        let coverage = if left_side {
            strip - area_left
        } else {
            area_left
        };
        if column >= clip.0 && column < clip.1 {
            // Inside the clip, whose columns are i32.
            run.push(
                column.low(),
                opacity32(coverage.clamp(0, FULL as i32)),
                sink,
            )
        } else {
            Ok(())
        }
    };
    // The first and the last column: within a column of the piece's ends
    // (`Piece::area_left_of` without its general cases).
    let rows32 = piece.rows.low();
    let first_x = first << FRAC;
    if end <= first {
        // Vertical, on a column boundary: it crosses no column.
        return Ok(());
    }
    let one = P::narrow(1);
    if end - first == one {
        // Inside one column: a trapezoid the piece's height, its mean depth into the column.
        let depth = (piece.left - first_x).low() + (piece.right - first_x).low();
        return put(run, sink, first, rows32 * depth / 2);
    }
    let leave = first_x + P::PIXEL;
    let inside = piece.rows_left_of(leave).low();
    let depth = (piece.left - first_x).low() + ONE as i32;
    put(
        run,
        sink,
        first,
        (rows32 - inside) * ONE as i32 + inside * depth / 2,
    )?;
    let last_x = (end - one) << FRAC;
    let last = || {
        let before = piece.rows_left_of(last_x).low();
        (rows32 - before) * (piece.right - last_x).low() / 2
    };
    if end - first == P::narrow(2) {
        return put(run, sink, end - one, last());
    }
    // Middle columns: rows left of the column's left side, in 2^-32 units, step by a column's
    // worth each time.
    let (from, to) = ((first + one).max(clip.0), (end - one).min(clip.1));
    if from < to {
        let per_x = piece.rows_per_column;
        // A shift, not a multiply (a library call on Cortex-M0).
        let per_column = if per_x >> (64 - FRAC) == 0 {
            per_x << FRAC
        } else {
            u64::MAX
        };
        let across = ((from << FRAC) - piece.left).widen() as u64;
        let mut rows_before = if across < 1 << 16 && per_x < 1 << 32 {
            // 16 by 32 bits: two 32-bit products of 16-bit halves.
            let (a, high, low) = (across as u32, (per_x >> 16) as u32, (per_x & 0xFFFF) as u32);
            (u64::from(a * high) << 16) + u64::from(a * low)
        } else {
            across.saturating_mul(per_x)
        };
        // In 32 bits (64-bit arithmetic is two instructions a step on 32-bit cores): rows are
        // at most ONE, areas at most FULL, and the columns lie inside the clip.
        let piece_rows = piece.rows.low() as u32;
        let whole = piece_rows as i32 * ONE as i32;
        for column in from.low()..to.low() {
            let rows_after = rows_before.saturating_add(per_column);
            let before = ((rows_before >> 32) as u32).min(piece_rows);
            let inside = ((rows_after >> 32) as u32).min(piece_rows);
            let area_left = whole - (inside + before) as i32 * (ONE as i32 / 2);
            let coverage = if left_side {
                strip - area_left
            } else {
                area_left
            };
            run.push(column, opacity32(coverage.clamp(0, FULL as i32)), sink)?;
            rows_before = rows_after;
        }
    }
    put(run, sink, end - one, last())
}

/// Emits the columns `from..to` of the row within `clip` (columns `clip.0..clip.1`), each
/// solved from every piece.
fn boundary_columns<P: Coord, K: CoverageSink>(
    bounds: &RowBoundaries<P>,
    (from, to): (P, P),
    clip: (P, P),
    run: &mut EdgeRun,
    sink: &mut K,
) -> Result<(), K::Error> {
    // Inside the clip, whose columns are i32.
    for column in from.max(clip.0).low()..to.min(clip.1).low() {
        let x = P::narrow(i64::from(column)) << FRAC;
        run.push(column, opacity(bounds.coverage(x)), sink)?;
    }
    Ok(())
}

/// Receives a triangle's coverage, row by row from the top.
pub trait CoverageSink {
    /// What the sink can fail with; the first error stops the walk.
    type Error;

    /// A row's pixels between its edges, all covered `coverage` (1 to 255).
    fn interior(&mut self, span: Span, coverage: u8) -> Result<(), Self::Error>;

    /// Pixels edges cross, from `(x, y)` rightwards, one coverage each (1 to 255).
    fn edge(&mut self, x: i32, y: i32, coverages: &[u8]) -> Result<(), Self::Error>;
}

/// Most pixels of one edge run.
const RUN: usize = 32;

/// Gathers a row's consecutive edge pixels, so that each run reaches the sink in one call.
struct EdgeRun {
    /// The first pixel's column, from the walk's origin (inside the clip, whose columns are
    /// i32).
    x: i32,
    /// The origin's column: added when the run goes out.
    origin: i32,
    /// The row, on the target.
    y: i32,
    len: usize,
    coverages: [u8; RUN],
}

impl EdgeRun {
    fn new(origin: i32) -> Self {
        Self {
            x: 0,
            origin,
            y: 0,
            len: 0,
            coverages: [0; RUN],
        }
    }

    /// Adds column `column` (to the right of those before) with its coverage.
    #[inline(always)]
    fn push<K: CoverageSink>(
        &mut self,
        column: i32,
        coverage: u8,
        sink: &mut K,
    ) -> Result<(), K::Error> {
        if coverage == 0 {
            // Uncovered pixels are not drawn: a display may not be read, only written.
            return self.flush(sink);
        }
        if self.len == RUN || (self.len > 0 && column != self.x.wrapping_add(self.len as i32)) {
            self.flush(sink)?;
        }
        if self.len == 0 {
            self.x = column;
        }
        *at_mut(&mut self.coverages, self.len) = coverage;
        self.len += 1;
        Ok(())
    }

    /// Hands the gathered pixels to `sink`.
    #[inline]
    fn flush<K: CoverageSink>(&mut self, sink: &mut K) -> Result<(), K::Error> {
        if self.len > 0 {
            let len = core::mem::replace(&mut self.len, 0);
            sink.edge(
                self.x.wrapping_add(self.origin),
                self.y,
                first(&self.coverages, len),
            )?;
        }
        Ok(())
    }
}

/// Hands `sink` every pixel of `triangle` inside `clip` that its area covers, top to bottom
/// and left to right: runs of edge pixels with a coverage each, and each row's interior.
///
/// Coverage is the area of the pixel's square (side 1, centred on the pixel) inside the
/// triangle, within 1/256 of exact before rounding; pixels fully inside get 255. Degenerate triangles cover
/// nothing.
pub(crate) fn walk_coverage<K: CoverageSink>(
    triangle: &Triangle,
    clip: &Rectangle,
    sink: &mut K,
) -> Result<(), K::Error> {
    let vertices = triangle
        .vertices
        .map(|p| (i64::from(p.x) * ONE, i64::from(p.y) * ONE));
    walk_coverage_of(vertices, triangle.orientation(), clip, sink)
}

/// [`walk_coverage`] for a sub-pixel triangle.
pub(crate) fn walk_subpixel_coverage<K: CoverageSink>(
    triangle: &crate::geometry::SubPixelTriangle,
    clip: &Rectangle,
    sink: &mut K,
) -> Result<(), K::Error> {
    // 1/256 pixel is 16 units of 1/4096.
    let vertices = triangle.vertices.map(|p| {
        (
            i64::from(p.x.to_bits()) * (ONE / 256),
            i64::from(p.y.to_bits()) * (ONE / 256),
        )
    });
    walk_coverage_of(vertices, triangle.orientation(), clip, sink)
}

/// [`walk_coverage`] for vertices in 1/4096 pixel (pixel centres at whole pixels): in `i32`
/// from the clip's corner when the vertices lie within [`NARROW_REACH`] of it, else in `i64`.
#[inline(always)]
fn walk_coverage_of<K: CoverageSink>(
    vertices: [(i64, i64); 3],
    orientation: crate::Orientation,
    clip: &Rectangle,
    sink: &mut K,
) -> Result<(), K::Error> {
    if orientation == crate::Orientation::Degenerate || clip.is_zero_sized() {
        return Ok(());
    }
    // Pixels to process: the clip, within reach of the origin.
    let column_start = i64::from(clip.top_left.x).max(-REACH);
    let row_start = i64::from(clip.top_left.y).max(-REACH);
    let column_end = (i64::from(clip.top_left.x) + i64::from(clip.size.width)).min(REACH);
    let row_end = (i64::from(clip.top_left.y) + i64::from(clip.size.height)).min(REACH);
    if column_start >= column_end || row_start >= row_end {
        return Ok(());
    }
    let clockwise = orientation == crate::Orientation::Clockwise;
    let near = vertices.map(|(x, y)| (x - column_start * ONE, y - row_start * ONE));
    if near.iter().all(|&(x, y)| {
        x.unsigned_abs() < NARROW_REACH as u64 && y.unsigned_abs() < NARROW_REACH as u64
    }) {
        // Columns and rows from the corner; beyond NARROW_CLIP none is covered.
        let columns = (column_end - column_start).min(NARROW_CLIP);
        let rows = (row_end - row_start).min(NARROW_CLIP);
        let vertices = near.map(|(x, y)| (x as i32, y as i32));
        // Within the clip: i32.
        let origin = (column_start as i32, row_start as i32);
        walk_chains(
            vertices,
            clockwise,
            (0, columns as i32),
            (0, rows as i32),
            origin,
            sink,
        )
    } else {
        let columns = (column_start, column_end);
        walk_chains(
            vertices,
            clockwise,
            columns,
            (row_start, row_end),
            (0, 0),
            sink,
        )
    }
}

/// Walks the rows of the triangle with `vertices` (1/4096 pixel, from `origin`), within the
/// clip's `columns` and `rows` (pixels from `origin`), handing `sink` each row's coverage at
/// `origin` plus the column and row.
fn walk_chains<P: Coord, K: CoverageSink>(
    vertices: [(P, P); 3],
    clockwise: bool,
    (column_start, column_end): (P, P),
    (row_start, row_end): (P, P),
    origin: (i32, i32),
    sink: &mut K,
) -> Result<(), K::Error> {
    // Positions are shifted by half a pixel (pixel squares from whole units): up to 2^39 in
    // magnitude in `i64`, which each edge's set-up handles.
    let polygon = vertices.map(|(x, y)| Position {
        x: x + P::HALF,
        y: y + P::HALF,
    });
    let len = polygon.len();
    // Chains from the top vertex to the bottom one, each way round.
    let top = (0..len)
        .min_by_key(|&i| (polygon[i].y, polygon[i].x))
        .unwrap_or(0);
    let bottom = (0..len)
        .max_by_key(|&i| (polygon[i].y, polygon[i].x))
        .unwrap_or(0);
    let (next, previous) = ((top + 1) % len, (top + len - 1) % len);
    let forward = [polygon[top], polygon[next], polygon[previous]];
    let backward = [polygon[top], polygon[previous], polygon[next]];
    // Going forward, the bottom vertex is one step away (then two going back) or two.
    let (forwards, backwards) = if next == bottom { (2, 3) } else { (3, 2) };
    // Going forward from the top vertex leads down the right side when the triangle is
    // clockwise on screen (y down).
    let (right, left) = if clockwise {
        (&forward[..forwards], &backward[..backwards])
    } else {
        (&backward[..backwards], &forward[..forwards])
    };
    let first_row = (polygon[top].y >> FRAC).max(row_start);
    let last_row = ((polygon[bottom].y + P::PIXEL_LESS_ONE) >> FRAC).min(row_end);
    if first_row >= last_row {
        return Ok(());
    }
    let (mut left_chain, mut right_chain) = (Chain::EMPTY, Chain::EMPTY);
    left_chain.start(left, first_row.widen());
    right_chain.start(right, first_row.widen());
    let (left, right) = (&mut left_chain, &mut right_chain);
    // Reused from row to row: each row overwrites what it reads.
    let mut bounds = RowBoundaries::default();
    let mut run = EdgeRun::new(origin.0);
    // Rows within the clip: i32.
    for row in first_row.low()..last_row.low() {
        let strip = P::narrow(i64::from(row)) << FRAC;
        run.y = row.wrapping_add(origin.1);
        // The common row, in the `i32` walk only (triangles far from the clip are rare, and
        // its copy in the `i64` walk cost 1.4 KB of flash). Each edge's crossings are stepped
        // once: its piece is the row's.
        if !P::WIDE && left.crosses(strip) && right.crosses(strip) {
            let (l, r) = (left.across(strip), right.across(strip));
            if let Some(done) = common_row(&l, &r, (column_start, column_end), &mut run, sink) {
                done?;
                continue;
            }
            (bounds.left[0], bounds.right[0]) = (l, r);
            (bounds.lefts, bounds.rights, bounds.rows) = (1, 1, P::PIXEL);
        } else {
            bounds.lefts = left.pieces(strip, &mut bounds.left);
            bounds.rights = right.pieces(strip, &mut bounds.right);
            bounds.rows = first(&bounds.left, bounds.lefts)
                .iter()
                .map(|p| p.rows)
                .sum();
        }
        if bounds.lefts == 0 || bounds.rights == 0 || bounds.rows == P::ZERO {
            continue;
        }
        row_coverage(&bounds, (column_start, column_end), &mut run, sink)?;
    }
    Ok(())
}

/// The common row, most rows of a large triangle: on each side one edge crosses the whole
/// strip (`left` and `right`, from [`Chain::across`]), and the two sides' columns lie apart.
/// Hands `sink` what [`row_coverage`] would from the same pieces, without gathering them into
/// a [`RowBoundaries`]; `None` when the sides share a column.
#[inline(always)]
fn common_row<P: Coord, K: CoverageSink>(
    left: &Piece<P>,
    right: &Piece<P>,
    clip: (P, P),
    run: &mut EdgeRun,
    sink: &mut K,
) -> Option<Result<(), K::Error>> {
    let left_end = (left.right + P::PIXEL_LESS_ONE) >> FRAC;
    let right_start = right.left >> FRAC;
    if left_end >= right_start {
        return None;
    }
    let emit = |run: &mut EdgeRun, sink: &mut K| {
        lone_piece_columns(left, true, P::PIXEL, clip, run, sink)?;
        run.flush(sink)?;
        interior((left_end, right_start), P::PIXEL, clip, run, sink)?;
        lone_piece_columns(right, false, P::PIXEL, clip, run, sink)?;
        run.flush(sink)
    };
    Some(emit(run, sink))
}

/// Hands `sink` the interior of the run's row, columns `from..to` within `clip`, covered by a
/// strip `rows` high (1/4096 units), if any of it is inside and covered.
#[inline(always)]
fn interior<P: Coord, K: CoverageSink>(
    (from, to): (P, P),
    rows: P,
    clip: (P, P),
    run: &EdgeRun,
    sink: &mut K,
) -> Result<(), K::Error> {
    let (from, to) = (from.max(clip.0), to.min(clip.1));
    if from < to {
        let alpha = opacity(rows << FRAC);
        if alpha > 0 {
            let span = Span {
                x: from.low().wrapping_add(run.origin),
                y: run.y,
                len: (to - from).low() as u32,
            };
            sink.interior(span, alpha)?;
        }
    }
    Ok(())
}

/// Hands `sink` one row's coverage within columns `clip.0..clip.1`: the left edge's columns,
/// the interior, the right edge's columns.
#[inline]
fn row_coverage<P: Coord, K: CoverageSink>(
    bounds: &RowBoundaries<P>,
    clip: (P, P),
    run: &mut EdgeRun,
    sink: &mut K,
) -> Result<(), K::Error> {
    let (left_start, left_end) = RowBoundaries::columns(first(&bounds.left, bounds.lefts));
    let (right_start, right_end) = RowBoundaries::columns(first(&bounds.right, bounds.rights));
    if left_end >= right_start {
        // The boundaries share columns: every column is a boundary column.
        boundary_columns(bounds, (left_start, right_end), clip, run, sink)?;
        return run.flush(sink);
    }
    // The common row: one piece each side, apart.
    let lone = bounds.lefts == 1 && bounds.rights == 1;
    if lone {
        lone_piece_columns(&bounds.left[0], true, bounds.rows, clip, run, sink)?;
    } else {
        boundary_columns(bounds, (left_start, left_end), clip, run, sink)?;
    }
    run.flush(sink)?;
    interior((left_end, right_start), bounds.rows, clip, run, sink)?;
    if lone {
        lone_piece_columns(&bounds.right[0], false, bounds.rows, clip, run, sink)?;
    } else {
        boundary_columns(bounds, (right_start, right_end), clip, run, sink)?;
    }
    run.flush(sink)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An edge's set-up without its general divisions: the start from the row step, and the
    /// rows-per-column ratio by digits, each against the division, at the ends of their ranges.
    #[test]
    fn edge_set_up_is_the_division() {
        let check = |down: i64, dx: i64, dy: i64| {
            let (step, rest) = floor_div(ONE * dx, dy);
            let want = start_crossing(down, dx, dy);
            assert_eq!(
                start_from_step(down, dx, dy, step, rest),
                want,
                "{down} {dx} {dy}"
            );
            let (q, r) = want;
            assert_eq!(q * dy + r, down * dx, "{down} {dx} {dy}");
            assert!((0..dy).contains(&r), "{down} {dx} {dy}");
        };
        let mut rng = crate::test_rng::XorShift(0x2545_F491_4F6C_DD1D);
        for _ in 0..200_000 {
            let r = rng.next_u64();
            let down = (r & (ONE as u64 - 1)) as i64;
            let dx = ((r >> 12) % (1 << 21)) as i64 - (1 << 20);
            let dy = 1 + ((r >> 40) % (1 << 20)) as i64;
            check(down, dx, dy);
            // Steep and shallow edges within a few pixels, as small triangles have.
            check(down, dx >> 8, (dy >> 8).max(1));
        }
        let limit = (1 << 19) - 1;
        // The ratio by digits, up to an `across` of 2^16 itself.
        for (rows, across) in [
            (0, 1),
            (1, 1),
            (0xFFFF, 1),
            (0xFFFF, 0x1_0000),
            (1, 0x1_0000),
        ] {
            let want = (u64::from(rows) << 32) / u64::from(across);
            assert_eq!(ratio_by_digits(rows, across), want, "{rows} {across}");
            assert_eq!(ratio_by_inverse(rows, across), want, "{rows} {across}");
        }
        // Every width, with the largest dividends and one just under it.
        for across in 1..=0x1_0000u32 {
            for rows in [0xFFFF, across - 1, across.min(0xFFFF)] {
                let want = (u64::from(rows) << 32) / u64::from(across);
                assert_eq!(ratio_by_inverse(rows, across), want, "{rows} {across}");
            }
        }
        for _ in 0..100_000 {
            let r = rng.next_u64();
            let (rows, across) = ((r & 0xFFFF) as u32, 1 + ((r >> 16) % 0x1_0000) as u32);
            let want = (u64::from(rows) << 32) / u64::from(across);
            assert_eq!(ratio_by_digits(rows, across), want, "{rows} {across}");
            assert_eq!(ratio_by_inverse(rows, across), want, "{rows} {across}");
        }
        for down in [0, 1, ONE / 2, ONE - 1, ONE] {
            for dx in [-limit - 1, -limit, -4097, -1, 0, 1, 4095, limit] {
                for dy in [1, 2, 4095, 4096, limit, limit + 1] {
                    check(down, dx, dy);
                }
            }
        }
    }
}
