//! Bresenham-style edge stepping: at most one division per edge, then additions only.
//!
//! An edge from `(xa, ya)` to `(xb, yb)` (`ya < yb`) crosses row `ya + n` at
//! `X = xa + dx * n / dy`. A stepper holds the pixel bound `x = xa + floor((dx * n + k) / dy)`
//! (`k = dy - 1` for [`Rounding::Ceil`], `k = dy` for [`Rounding::FloorPlusOne`]) and the
//! remainder of that division as an error term; each row adds the quotient and remainder of
//! `dx / dy`, computed once.

use crate::setup::{
    Lane,
    lane::{div_rem_floor_compact, div_rem_u64},
};

/// How an edge's exact crossing `X` on a row becomes a pixel bound.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(crate) enum Rounding {
    /// `ceil(X)`: the first pixel at or right of the edge (a left bound), or the exclusive end
    /// of a right bound that leaves out pixels exactly on the edge.
    Ceil,
    /// `floor(X) + 1`: the exclusive end of a right bound that keeps pixels on the edge.
    FloorPlusOne,
}

/// Quotient and remainder of `dx / dy`, the per-row increments.
///
/// Steep edges (`-dy <= dx < dy`, about half of all edges and most edges of small triangles)
/// move at most one pixel per row: their quotient is `0` or `-1`, found without dividing.
/// That matters most on cores without a divide instruction. Shallow edges divide by `divide`
/// (the lane's floor division, or a compact one where quotients are expected small).
#[inline(always)]
pub(crate) fn increments<T: Lane>(dx: T, dy: T, divide: impl FnOnce(T, T) -> (T, T)) -> (T, T) {
    if T::in_half_open(dx, dy) {
        // -dy <= dx < dy: quotient -1 below zero, 0 above.
        if dx < T::ZERO {
            (T::ZERO - T::ONE, dx + dy)
        } else {
            (T::ZERO, dx)
        }
    } else {
        divide(dx, dy)
    }
}

/// The bound and error term (`remainder - dy`, in `-dy..0`) at row `ya + rows_in`, for
/// `0 <= rows_in <= dy`.
#[inline(always)]
fn bound_at<T: Lane>(
    xa: T,
    dy: T,
    (step, remainder): (T, T),
    rounding: Rounding,
    rows_in: T,
) -> (T, T) {
    if rows_in == T::ZERO {
        // At the upper vertex the crossing is the integer `xa`: no division needed.
        match rounding {
            Rounding::Ceil => (xa, T::ZERO - T::ONE),
            Rounding::FloorPlusOne => (xa + T::ONE, T::ZERO - dy),
        }
    } else {
        jump(xa, dy, step, remainder, rounding, rows_in)
    }
}

/// The bound and error term `rows_in` rows below the upper vertex (`0 < rows_in <= dy`), for
/// edges that start above the clip window.
///
/// `dx * n + k = step * dy * n + (remainder * n + k)`, and `remainder * n + k <= dy^2` fits
/// `u64` for any `i32` vertices, so no 128-bit arithmetic is needed.
///
/// The 32-bit lane works in 32 bits for edges under 2^15 rows stepping under 2^15 pixels a
/// row (every edge on a screen; bands jump every edge to each band's first row): Cortex-M0
/// makes each 64-bit product a library call of about forty instructions. `remainder` and `n`
/// are at most `dy`, so the numerator stays under 2^31, and `|step n|` under 2^30. Its other
/// edges go to the 64-bit lane's copy, so the 64-bit arithmetic is built once.
#[inline(never)]
fn jump<T: Lane>(xa: T, dy: T, step: T, remainder: T, rounding: Rounding, rows_in: T) -> (T, T) {
    let (dy, n, step) = (dy.to_i64(), rows_in.to_i64(), step.to_i64());
    let k = match rounding {
        Rounding::Ceil => dy - 1,
        Rounding::FloorPlusOne => dy,
    };
    let (x, error) = if T::CLIP_MAX > i64::from(i32::MAX) {
        let numerator = remainder.to_i64() as u64 * n as u64 + k as u64;
        // `dy` is positive; `max` says so, which drops the division-by-zero panic.
        let (quotient, rem) = div_rem_u64(numerator, dy.max(1) as u64);
        // |step * n| <= |dx| + dy < 2^34: no overflow; the sum is a bound, which fits the lane.
        (step * n + quotient as i64, rem as i64 - dy)
    } else if dy < 1 << 15 && step.unsigned_abs() < 1 << 15 {
        let (d, n) = (dy.max(1) as u32, n as u32);
        let numerator = remainder.to_i64() as u32 * n + k as u32;
        // Below 2^31 (see above): the edges' set-up division, which counts small quotients out
        // on Cortex-M0 (bands jump every edge of a triangle to each band's first row).
        let (quotient, rem) = div_rem_floor_compact(numerator as i32, d as i32);
        let (quotient, rem) = (quotient as u32, rem as u32);
        let moved = step as i32 * n as i32 + quotient as i32;
        (i64::from(moved), i64::from(rem) - dy)
    } else {
        jump::<i64>(0, dy, step, remainder.to_i64(), rounding, n)
    };
    (T::from_i64(xa.to_i64() + x), T::from_i64(error))
}

/// An edge being walked one row at a time: bound, error term and increments.
#[derive(Copy, Clone, Debug)]
pub(crate) struct EdgeStepper<T> {
    x: T,
    /// Remainder minus `dy`, in `-dy..0`.
    error: T,
    /// `floor(dx / dy)`.
    step: T,
    /// `dx mod dy`, in `0..dy`.
    remainder: T,
    dy: T,
}

impl<T: Lane> EdgeStepper<T> {
    /// Starts the edge from `upper` to `lower` (`upper.1 < lower.1`) at `row`, which must lie
    /// in `upper.1..=lower.1`.
    #[inline(always)]
    pub(crate) fn start(upper: (T, T), lower: (T, T), rounding: Rounding, row: T) -> Self {
        let (xa, ya) = upper;
        let dy = lower.1 - ya;
        debug_assert!(dy > T::ZERO && row >= ya && row <= lower.1);
        let (step, remainder) = increments(lower.0 - xa, dy, T::div_rem_floor);
        let (x, error) = bound_at(xa, dy, (step, remainder), rounding, row - ya);
        Self {
            x,
            error,
            step,
            remainder,
            dy,
        }
    }

    /// The stepper whose bound on the current row is `x`, with error term `error` (in
    /// `-dy..0`) and increments `step` and `remainder` (`dx = step dy + remainder`,
    /// `remainder` in `0..dy`): for edges started otherwise (sub-pixel vertices).
    #[inline(always)]
    pub(crate) const fn from_parts(x: T, error: T, (step, remainder): (T, T), dy: T) -> Self {
        Self {
            x,
            error,
            step,
            remainder,
            dy,
        }
    }

    /// The error term, in `-dy..0`.
    #[cfg(test)]
    pub(crate) fn error(&self) -> T {
        self.error
    }

    /// The bound on the current row.
    #[inline(always)]
    pub(crate) fn x(&self) -> T {
        self.x
    }

    /// Moves to the next row.
    #[inline(always)]
    pub(crate) fn advance(&mut self) {
        self.x += self.step;
        self.error += self.remainder;
        if self.error >= T::ZERO {
            self.x += T::ONE;
            self.error -= self.dy;
        }
    }
}

/// An edge evaluated at any row directly, without stepping state: the wide walk's, whose rows
/// are few next to the code a 64-bit stepper would take on a 32-bit core.
#[derive(Copy, Clone, Debug)]
pub(crate) struct ExactEdge<T> {
    xa: T,
    ya: T,
    dy: T,
    increments: (T, T),
    rounding: Rounding,
}

impl<T: Lane> ExactEdge<T> {
    /// The edge from `upper` to `lower` (`upper.1 < lower.1`).
    #[inline(never)]
    pub(crate) fn new(upper: (T, T), lower: (T, T), rounding: Rounding) -> Self {
        let dy = lower.1 - upper.1;
        Self {
            xa: upper.0,
            ya: upper.1,
            dy,
            increments: increments(lower.0 - upper.0, dy, T::div_rem_floor),
            rounding,
        }
    }

    /// The bound on `row`, in `upper.1..=lower.1`.
    #[inline(never)]
    pub(crate) fn at(&self, row: T) -> T {
        bound_at(
            self.xa,
            self.dy,
            self.increments,
            self.rounding,
            row - self.ya,
        )
        .0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Exact bound by direct division, for comparison.
    fn exact(xa: i64, ya: i64, xb: i64, yb: i64, rounding: Rounding, row: i64) -> i64 {
        let (dx, dy) = (i128::from(xb - xa), i128::from(yb - ya));
        let num = dx * i128::from(row - ya);
        let bound = match rounding {
            Rounding::Ceil => num.div_euclid(dy) + i128::from(num.rem_euclid(dy) != 0),
            Rounding::FloorPlusOne => num.div_euclid(dy) + 1,
        };
        i64::try_from(bound).unwrap() + xa
    }

    fn check<T: Lane>(a: (i32, i32), b: (i32, i32)) {
        let lane = |p: (i32, i32)| (T::from_i32(p.0), T::from_i32(p.1));
        let rows = i64::from(b.1) - i64::from(a.1);
        for rounding in [Rounding::Ceil, Rounding::FloorPlusOne] {
            // Start at the first rows, in the middle and at the end of the edge.
            let starts: [i64; 4] = [0, 1.min(rows), rows / 2, rows];
            for start in starts {
                let row = T::from_i64(i64::from(a.1) + start);
                let mut edge = EdgeStepper::start(lane(a), lane(b), rounding, row);
                let mut n = start;
                loop {
                    let want = exact(
                        a.0.into(),
                        a.1.into(),
                        b.0.into(),
                        b.1.into(),
                        rounding,
                        i64::from(a.1) + n,
                    );
                    assert_eq!(edge.x().to_i64(), want, "{a:?}->{b:?} {rounding:?} row {n}");
                    let exact = ExactEdge::new(lane(a), lane(b), rounding);
                    assert_eq!(exact.at(T::from_i64(i64::from(a.1) + n)).to_i64(), want);
                    if n == rows || n > start + 50 {
                        break;
                    }
                    edge.advance();
                    n += 1;
                }
            }
        }
    }

    #[test]
    fn steps_match_exact_division() {
        let edges = [
            ((0, 0), (7, 3)),
            ((0, 0), (-7, 3)),
            ((5, -2), (5, 9)),
            ((3, 0), (-40, 1)),
            ((-100, -50), (31, 77)),
            ((0, 0), (1, 1000)),
            ((0, 0), (-1, 1000)),
            // Either side of the 32-bit jump's limits: 2^15 rows, 2^15 pixels a row.
            ((0, 0), (-(1 << 20), (1 << 15) - 1)),
            ((0, 0), ((1 << 20) + 5, 1 << 15)),
            ((7, 0), (32_767 * 40 + 39, 40)),
            ((7, 0), (32_768 * 40, 40)),
            ((7, 0), (-32_767 * 40 + 1, 40)),
            ((7, 0), (-32_768 * 40 - 1, 40)),
        ];
        for (a, b) in edges {
            check::<i32>(a, b);
            check::<i64>(a, b);
        }
        let limit = crate::setup::lane::FAST_LIMIT;
        for (a, b) in [
            ((-limit, -limit), (limit, limit)),
            ((limit, -limit), (-limit, limit - 1)),
            ((limit, -limit), (-limit, -limit + 1)),
        ] {
            check::<i32>(a, b);
        }
        check::<i64>((i32::MIN, i32::MIN), (i32::MAX, i32::MAX));
        check::<i64>((i32::MAX, i32::MIN), (i32::MIN, i32::MAX));
        check::<i64>((i32::MAX, i32::MIN), (i32::MIN, i32::MIN + 1));
    }
}
