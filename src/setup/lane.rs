//! The integer type the per-row edge stepping runs in.
//!
//! Setup picks [`i32`] when every vertex coordinate lies within [`FAST_LIMIT`] (the fast path: all
//! per-row arithmetic in single 32-bit registers, which is what a Cortex-M0 wants) and [`i64`]
//! otherwise (the wide path: any `i32` vertex, exact). Both run the same generic code.

use core::cmp::Ordering;
use core::ops::{Add, AddAssign, Sub, SubAssign};

/// Largest vertex coordinate magnitude for which the 32-bit fast path is exact.
///
/// With every coordinate in `-FAST_LIMIT..=FAST_LIMIT`, edge deltas stay below `2^31`, edge
/// positions stay within `-FAST_LIMIT..=FAST_LIMIT + 1`, stepping error terms stay within
/// `-2^31..2^31` and doubled areas within `i64`.
pub const FAST_LIMIT: i32 = (1 << 30) - 1;

/// Integer operations the stepping code needs, for `i32` (fast) and `i64` (wide).
pub(crate) trait Lane:
    Copy + Ord + Add<Output = Self> + Sub<Output = Self> + AddAssign + SubAssign
{
    const ZERO: Self;
    const ONE: Self;
    /// Clamp range for clip bounds: stepping values never leave it, so clamping a clip bound
    /// into it changes no comparison.
    const CLIP_MIN: i64;
    const CLIP_MAX: i64;

    fn from_i32(value: i32) -> Self;
    /// Narrows a value already proven to lie in the lane's range.
    fn from_i64(value: i64) -> Self;
    fn to_i64(self) -> i64;
    /// `(floor(self / divisor), self mod divisor)` for a positive divisor.
    fn div_rem_floor(self, divisor: Self) -> (Self, Self);
    /// Exact sign of `a * b - c * d`.
    fn cross_sign(a: Self, b: Self, c: Self, d: Self) -> Ordering;
}

impl Lane for i32 {
    const ZERO: Self = 0;
    const ONE: Self = 1;
    const CLIP_MIN: i64 = -(FAST_LIMIT as i64);
    const CLIP_MAX: i64 = FAST_LIMIT as i64 + 1;

    #[inline(always)]
    fn from_i32(value: i32) -> Self {
        value
    }

    #[inline(always)]
    fn from_i64(value: i64) -> Self {
        debug_assert!(i32::try_from(value).is_ok());
        value as i32
    }

    #[inline(always)]
    fn to_i64(self) -> i64 {
        i64::from(self)
    }

    #[inline(always)]
    fn div_rem_floor(self, divisor: Self) -> (Self, Self) {
        debug_assert!(divisor > 0);
        (self.div_euclid(divisor), self.rem_euclid(divisor))
    }

    #[inline]
    fn cross_sign(a: Self, b: Self, c: Self, d: Self) -> Ordering {
        // Fast-path deltas are below 2^31 in magnitude: each product below 2^62.
        (i64::from(a) * i64::from(b)).cmp(&(i64::from(c) * i64::from(d)))
    }
}

impl Lane for i64 {
    const ZERO: Self = 0;
    const ONE: Self = 1;
    const CLIP_MIN: i64 = i64::MIN / 4;
    const CLIP_MAX: i64 = i64::MAX / 4;

    #[inline(always)]
    fn from_i32(value: i32) -> Self {
        i64::from(value)
    }

    #[inline(always)]
    fn from_i64(value: i64) -> Self {
        value
    }

    #[inline(always)]
    fn to_i64(self) -> i64 {
        self
    }

    #[inline(always)]
    fn div_rem_floor(self, divisor: Self) -> (Self, Self) {
        debug_assert!(divisor > 0);
        (self.div_euclid(divisor), self.rem_euclid(divisor))
    }

    #[inline]
    fn cross_sign(a: Self, b: Self, c: Self, d: Self) -> Ordering {
        // Deltas of i32 coordinates reach 2^32: products reach 2^64, beyond i64.
        (i128::from(a) * i128::from(b)).cmp(&(i128::from(c) * i128::from(d)))
    }
}

/// True when a coordinate can take the 32-bit fast path.
#[inline(always)]
pub(crate) const fn in_fast_range(value: i32) -> bool {
    value >= -FAST_LIMIT && value <= FAST_LIMIT
}
