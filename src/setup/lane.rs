//! The integer type the per-row edge stepping runs in.
//!
//! Setup picks [`i32`] when every vertex coordinate lies within [`FAST_LIMIT`] (the fast path: all
//! per-row arithmetic in single 32-bit registers, which is what a Cortex-M0 wants) and [`i64`]
//! otherwise (the wide path: any `i32` vertex, exact). Both run the same generic code.

use core::cmp::Ordering;
use core::ops::{Add, AddAssign, BitAnd, Shl, Shr, Sub, SubAssign};

/// Vertex coordinates within ±`FAST_LIMIT` (2^30 - 1) take the 32-bit fast path.
///
/// The fast path runs for every coordinate in `-2^30..2^30`: edge deltas then stay below
/// `2^31`, edge positions within `-2^30..=2^30`, stepping error terms within `-2^31..2^31` and
/// doubled areas within `i64`. Beyond, the same walk runs in 64-bit arithmetic.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
/// use trirast::{FlatStyle, Triangle, FAST_LIMIT};
///
/// // Far beyond the fast range, still exact: this one covers the whole 64x64 display.
/// let (min, max) = (i32::MIN, i32::MAX);
/// assert!(max > FAST_LIMIT);
/// let t = Triangle::new(Point::new(min, min), Point::new(max, 0), Point::new(0, max));
/// let mut display = MockDisplay::new();
/// t.into_styled(FlatStyle::new(BinaryColor::On)).draw(&mut display).unwrap();
/// assert_eq!(display.get_pixel(Point::new(0, 0)), Some(BinaryColor::On));
/// assert_eq!(display.get_pixel(Point::new(63, 63)), Some(BinaryColor::On));
/// ```
pub const FAST_LIMIT: i32 = (1 << 30) - 1;

/// The fast range is `-FAST_BIAS..FAST_BIAS`: biased by `FAST_BIAS`, a coordinate in it has
/// bit 31 clear, so six coordinates are checked with one OR.
const FAST_BIAS: i32 = 1 << 30;

/// Integer operations the stepping code needs, for `i32` (fast) and `i64` (wide).
pub(crate) trait Lane:
    Copy
    + Ord
    + Add<Output = Self>
    + Sub<Output = Self>
    + AddAssign
    + SubAssign
    + Shl<u32, Output = Self>
    + Shr<u32, Output = Self>
    + BitAnd<Output = Self>
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
    /// `Some(a * b - c * d > 0)`, or `None` when it is zero (a cheaper form of
    /// [`Self::cross_sign`] for setup).
    fn cross_positive(a: Self, b: Self, c: Self, d: Self) -> Option<bool>;
    /// `(a - b)` as a `u32` length, for `b <= a` with `a - b < 2^32` (may wrap the lane).
    fn len_u32(a: Self, b: Self) -> u32;
    /// `-limit <= value < limit`, for `0 < limit`, in one unsigned comparison.
    fn in_half_open(value: Self, limit: Self) -> bool;
}

/// Whether `a`, `b`, `c` and `d` all lie in `-2^15..2^15` (the deltas of every screen-sized
/// triangle), so that `a * b - c * d` fits 32 bits: products up to 2^30, their difference
/// below 2^31. On Cortex-M0 a 64-bit multiply is a library call of about forty instructions;
/// this test is a few.
#[inline(always)]
fn within_15_bits(a: i32, b: i32, c: i32, d: i32) -> bool {
    const HALF: i32 = 1 << 15;
    let biased =
        a.wrapping_add(HALF) | b.wrapping_add(HALF) | c.wrapping_add(HALF) | d.wrapping_add(HALF);
    (biased as u32) < 1 << 16
}

/// Floor division by a positive divisor: one truncating division and a fix-up (what
/// `div_euclid` and `rem_euclid` compile to, minus their handling of negative divisors).
macro_rules! floor_div_rem {
    ($value:expr, $divisor:expr) => {{
        debug_assert!($divisor > 0);
        // A no-op that tells the optimiser the divisor is positive, which removes the
        // division-by-zero and overflow checks.
        let (value, divisor) = ($value, $divisor.max(1));
        let (q, r) = (value / divisor, value % divisor);
        if r < 0 { (q - 1, r + divisor) } else { (q, r) }
    }};
}

impl Lane for i32 {
    const ZERO: Self = 0;
    const ONE: Self = 1;
    const CLIP_MIN: i64 = -(FAST_BIAS as i64);
    const CLIP_MAX: i64 = FAST_BIAS as i64;

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
        div_rem_floor_compact(self, divisor)
    }

    #[inline]
    fn cross_sign(a: Self, b: Self, c: Self, d: Self) -> Ordering {
        if within_15_bits(a, b, c, d) {
            return (a * b - c * d).cmp(&0);
        }
        // Fast-path deltas are below 2^31 in magnitude: each product below 2^62 and their
        // difference below 2^63.
        (i64::from(a) * i64::from(b) - i64::from(c) * i64::from(d)).cmp(&0)
    }

    #[inline(always)]
    fn cross_positive(a: Self, b: Self, c: Self, d: Self) -> Option<bool> {
        if within_15_bits(a, b, c, d) {
            let cross = a * b - c * d;
            return (cross != 0).then_some(cross > 0);
        }
        let cross = i64::from(a) * i64::from(b) - i64::from(c) * i64::from(d);
        (cross != 0).then_some(cross > 0)
    }

    #[inline(always)]
    fn len_u32(a: Self, b: Self) -> u32 {
        // Up to 2^31 in the fast range: wraps i32, not u32.
        a.wrapping_sub(b) as u32
    }

    #[inline(always)]
    fn in_half_open(value: Self, limit: Self) -> bool {
        // Fast-path deltas are below 2^31: the shifted value and 2 * limit fit u32.
        (value.wrapping_add(limit) as u32) < (limit as u32).wrapping_mul(2)
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
        // Wide path only (vertices beyond the fast range): the compact division, on magnitudes.
        let divisor = divisor.max(1).unsigned_abs();
        let (q, r) = div_rem_u64(self.unsigned_abs(), divisor);
        if self >= 0 {
            (q as i64, r as i64)
        } else if r == 0 {
            (-(q as i64), 0)
        } else {
            (-(q as i64) - 1, (divisor - r) as i64)
        }
    }

    #[inline]
    fn cross_sign(a: Self, b: Self, c: Self, d: Self) -> Ordering {
        // Deltas of i32 coordinates reach 2^32: products reach 2^64, beyond i64.
        (i128::from(a) * i128::from(b)).cmp(&(i128::from(c) * i128::from(d)))
    }

    #[inline]
    fn cross_positive(a: Self, b: Self, c: Self, d: Self) -> Option<bool> {
        match Self::cross_sign(a, b, c, d) {
            Ordering::Equal => None,
            sign => Some(sign == Ordering::Greater),
        }
    }

    #[inline(always)]
    fn len_u32(a: Self, b: Self) -> u32 {
        (a - b) as u32
    }

    #[inline(always)]
    fn in_half_open(value: Self, limit: Self) -> bool {
        // Deltas of i32 coordinates are below 2^33: the shifted value and 2 * limit fit u64.
        (value.wrapping_add(limit) as u64) < (limit as u64).wrapping_mul(2)
    }
}

/// `(floor(value / divisor), value mod divisor)` for a positive divisor, for quotients expected
/// small (an edge's pixels per row): by [`div_rem_floor_counted`] on cores without a divider
/// (Cortex-M0/M0+, see [`crate::arch::DIVIDES`]), by
/// the divide instruction elsewhere. The 32-bit lane's division (every edge of a whole-pixel
/// triangle steeper than one pixel a row) and the sub-pixel edges' start take it.
#[inline(always)]
pub(crate) fn div_rem_floor_compact(value: i32, divisor: i32) -> (i32, i32) {
    if crate::arch::DIVIDES {
        floor_div_rem!(value, divisor)
    } else {
        div_rem_floor_counted(value, divisor)
    }
}

/// [`div_rem_floor_compact`] answering quotients 1 and -2 inline on Cortex-M0 (edges of one
/// to two pixels a row, half of the sub-pixel edges that divide): for the sub-pixel edge
/// start, where it saves a call of about 34 instructions (in the whole-pixel walk the extra
/// tests cost its registers: flat `small` +18%).
#[inline(always)]
pub(crate) fn div_rem_floor_short(value: i32, divisor: i32) -> (i32, i32) {
    if !crate::arch::DIVIDES {
        if let Some(result) = one_or_minus_two(value, divisor) {
            return result;
        }
    }
    div_rem_floor_compact(value, divisor)
}

/// `(floor(value / divisor), value mod divisor)` when the quotient is 1 or -2, for a positive
/// divisor; `None` for any other quotient.
#[inline(always)]
fn one_or_minus_two(value: i32, divisor: i32) -> Option<(i32, i32)> {
    if value >= divisor && value - divisor < divisor {
        Some((1, value - divisor))
    } else if value < -divisor && value + divisor >= -divisor {
        Some((-2, value + divisor + divisor))
    } else {
        None
    }
}

/// [`div_rem_floor_compact`] on Cortex-M0: quotients below 32 counted out, two units a loop
/// trip (about two instructions a unit), where the library's division takes some 100 to 130
/// whatever the quotient (4% less per small flat triangle, 1.3% per small Gouraud one with
/// quotients below 8; below 32, flat `mesh` -0.45% more and the bands' edge jumps -0.2%; below
/// 64 measured worse); larger ones by that division, which is linked anyway (a
/// shift-and-subtract loop for them cost the flat share 180 bytes for no measurable gain). Out
/// of line: one copy.
#[inline(never)]
pub(crate) fn div_rem_floor_counted(value: i32, divisor: i32) -> (i32, i32) {
    let d = divisor.max(1) as u32;
    let n = value.unsigned_abs();
    let (mut quotient, mut rest) = (0u32, n);
    if n >> 5 < d {
        // Two units a trip (d below 2^31: doubled, it fits).
        let twice = d << 1;
        while rest >= twice {
            rest -= twice;
            quotient += 2;
        }
        if rest >= d {
            rest -= d;
            quotient += 1;
        }
    } else {
        (quotient, rest) = (n / d, n % d);
    }
    if value >= 0 {
        (quotient as i32, rest as i32)
    } else if rest == 0 {
        ((quotient as i32).wrapping_neg(), 0)
    } else {
        // floor(-m / d) = -(m / d) - 1, with the remainder d - m % d.
        ((quotient as i32).wrapping_neg() - 1, (d - rest) as i32)
    }
}

/// `value * small` (wrapping) for `small` below 2^16, in 32-bit multiplies where a 64-bit one
/// is a call (Cortex-M0: three calls of about forty instructions for an `i64` product).
#[inline(always)]
pub(crate) fn mul_small(value: i64, small: u32) -> i64 {
    if crate::arch::DIVIDES {
        value.wrapping_mul(i64::from(small))
    } else {
        mul_small_split(value, small)
    }
}

/// [`mul_small`] on Cortex-M0; tested on every host.
#[inline(always)]
fn mul_small_split(value: i64, small: u32) -> i64 {
    let (high, low) = ((value >> 32) as u32, value as u32);
    // `small` below 2^16: the low word's product from two 16-bit multiplies, not four.
    let low = mul_16_by_32(small, low);
    (u64::from(high.wrapping_mul(small)) << 32).wrapping_add(low) as i64
}

/// `a * b` in full: one multiply on cores that have it, four 16-bit ones on Cortex-M0 (where
/// a 64-bit multiply is a call of about forty instructions). The same bits either way.
#[inline(always)]
pub(crate) fn mul_u32(a: u32, b: u32) -> u64 {
    if crate::arch::DIVIDES {
        u64::from(a) * u64::from(b)
    } else {
        widening_mul(a, b)
    }
}

/// `a * b` in full, for a signed `a`: one multiply on cores that have it, [`mul_i32_u32_split`]
/// on Cortex-M0.
#[inline(always)]
pub(crate) fn mul_i32_u32(a: i32, b: u32) -> i64 {
    if crate::arch::DIVIDES {
        i64::from(a) * i64::from(b)
    } else {
        mul_i32_u32_split(a, b)
    }
}

/// [`mul_i32_u32`] in four 16-bit multiplies: `a`'s bits read unsigned are `a + 2^32` when
/// `a` is negative, so the unsigned product is `b * 2^32` too large then (one subtraction,
/// where taking the magnitude and negating the product measured more). Tested on every host.
#[inline(always)]
fn mul_i32_u32_split(a: i32, b: u32) -> i64 {
    let product = widening_mul(a as u32, b);
    let excess = if a < 0 { u64::from(b) << 32 } else { 0 };
    product.wrapping_sub(excess) as i64
}

/// `a * b` in full, from four 16 x 16-bit products: inline, where a 64-bit multiply is a call
/// of about forty instructions on Cortex-M0.
#[inline(always)]
pub(crate) fn widening_mul(a: u32, b: u32) -> u64 {
    let (a_high, a_low) = (a >> 16, a & 0xFFFF);
    let (b_high, b_low) = (b >> 16, b & 0xFFFF);
    let middle = u64::from(a_high * b_low) + u64::from(a_low * b_high);
    (u64::from(a_high * b_high) << 32) + (middle << 16) + u64::from(a_low * b_low)
}

/// `a * b` in full for `a` below 2^16: two 16-bit multiplies (Cortex-M0 has no wider one).
/// Tested on every host.
#[inline(always)]
pub(crate) fn mul_16_by_32(a: u32, b: u32) -> u64 {
    debug_assert!(a < 1 << 16);
    (u64::from(a * (b >> 16)) << 16) + u64::from(a * (b & 0xFFFF))
}

/// `value << n` for `n` below 32, from 32-bit shifts and without a branch. Where the optimiser
/// cannot see `n` (`opt-level = "s"` keeps some set-up shifts variable) a 64-bit shift is a
/// library call on Cortex-M0 (`__aeabi_llsl`).
#[inline(always)]
pub(crate) fn shl64(value: u64, n: u32) -> u64 {
    debug_assert!(n < 32);
    let (high, low) = ((value >> 32) as u32, value as u32);
    // `low >> 1 >> (31 - n)` is `low >> (32 - n)`, defined for a zero `n` too.
    (u64::from((high << n) | (low >> 1 >> (31 - n))) << 32) | u64::from(low << n)
}

/// `value >> n` for `n` from 1 to 32, as [`shl64`].
#[inline(always)]
pub(crate) fn shr64(value: u64, n: u32) -> u64 {
    debug_assert!((1..=32).contains(&n));
    let (high, low) = ((value >> 32) as u32, value as u32);
    // `x >> 1 >> (n - 1)` is `x >> n`, defined for `n = 32` too.
    (u64::from(high >> 1 >> (n - 1)) << 32) | u64::from((low >> 1 >> (n - 1)) | (high << (32 - n)))
}

/// `value * count` (wrapping) for a count of rows or columns within `i16`, as counts across
/// a screen are: three 32-bit multiplies where a 64-bit one is a library call of about forty
/// instructions (Cortex-M0), one multiply elsewhere. The same bits either way.
#[inline(always)]
pub(crate) fn mul_count(value: i64, count: i16) -> i64 {
    if crate::arch::DIVIDES {
        value.wrapping_mul(i64::from(count))
    } else {
        mul_count_split(value, count)
    }
}

/// [`mul_count`] on Cortex-M0; tested on every host.
#[inline(always)]
fn mul_count_split(value: i64, count: i16) -> i64 {
    let count = i32::from(count);
    let (high, low) = ((value >> 32) as i32, value as u32);
    // Each 16-bit half of the low word times the count is below 2^31 in magnitude.
    let upper = i64::from((low >> 16) as i32 * count) << 16;
    let lower = i64::from((low & 0xFFFF) as i32 * count);
    (i64::from(high.wrapping_mul(count)) << 32)
        .wrapping_add(upper)
        .wrapping_add(lower)
}

/// `(n / d, n % d)` for `d > 0`, in 32 bits when both fit (on Cortex-M0 a short library call),
/// else by shift and subtract: slow, but a few dozen instructions of flash instead of the ~1 KB
/// 64-bit division routine. Only rare paths divide in 64 bits: edges starting far above the
/// window and vertices beyond the fast range.
#[inline]
pub(crate) fn div_rem_u64(n: u64, d: u64) -> (u64, u64) {
    if let (Ok(n), Ok(d)) = (u32::try_from(n), u32::try_from(d)) {
        let d = d.max(1);
        return (u64::from(n / d), u64::from(n % d));
    }
    div_rem_u64_bitwise(n, d.max(1))
}

/// [`div_rem_u64`]'s shift and subtract, out of line: one copy for every caller. The dividend
/// is shifted out at the top while the quotient's bits come in at the bottom of the same
/// word: only shifts by one in the loop (shifts by a variable amount take several
/// instructions each on 32-bit cores, and the compiler unrolls the loop four times: 928 bytes
/// on Cortex-M4F with them).
#[inline(never)]
fn div_rem_u64_bitwise(n: u64, d: u64) -> (u64, u64) {
    let zeros = n.leading_zeros();
    if zeros == u64::BITS {
        return (0, 0);
    }
    let (mut bits, mut r) = (n << zeros, 0u64);
    for _ in zeros..u64::BITS {
        // r < d <= 2^63 before the shift: no bit is lost.
        r = (r << 1) | (bits >> 63);
        bits <<= 1;
        if r >= d {
            r -= d;
            bits |= 1;
        }
    }
    // Every bit of the dividend is out; the quotient's are in.
    (bits, r)
}

/// `(floor(n / d), n - d * floor(n / d))` for `d > 0`: the Euclidean quotient and remainder of
/// 128-bit values, for the exact paths (plane setup, far edge starts). One out-of-line copy.
/// On 32-bit cores by shift and subtract over the quotient's bits (about 50 in a plane setup):
/// the library's 128-bit division inlines 1.2 to 1.3 KB per use there, with its panics, and
/// measured slower on Cortex-M0 (about 4,000 instructions, twice this) and even on Cortex-M4F,
/// which divides 32 bits in hardware. 64-bit hosts keep the library's.
#[inline(never)]
pub(crate) fn floor_div_rem_i128(n: i128, d: i128) -> (i128, i128) {
    if crate::arch::WORD_64 {
        let d = d.max(1);
        (n.div_euclid(d), n.rem_euclid(d))
    } else {
        floor_div_rem_bitwise(n, d)
    }
}

/// [`floor_div_rem_i128`] on 32-bit cores.
#[inline(always)]
fn floor_div_rem_bitwise(n: i128, d: i128) -> (i128, i128) {
    let d = d.max(1).unsigned_abs();
    let (q, r) = div_rem_u128_bitwise(n.unsigned_abs(), d);
    if n >= 0 {
        (q as i128, r as i128)
    } else if r == 0 {
        ((q as i128).wrapping_neg(), 0)
    } else {
        // floor(-m / d) = -(m / d) - 1, with the remainder d - m % d.
        ((q as i128).wrapping_neg() - 1, (d - r) as i128)
    }
}

/// `(n / d, n % d)` for `d > 0`, by shift and subtract, one step per quotient bit.
#[inline(always)]
fn div_rem_u128_bitwise(n: u128, d: u128) -> (u128, u128) {
    if n < d {
        return (0, n);
    }
    let shift = d.leading_zeros() - n.leading_zeros();
    let (mut divisor, mut quotient, mut rest) = (d << shift, 0u128, n);
    for _ in 0..=shift {
        quotient <<= 1;
        if rest >= divisor {
            rest -= divisor;
            quotient |= 1;
        }
        divisor >>= 1;
    }
    (quotient, rest)
}

/// True when all `values` can take the 32-bit fast path (lie in `-2^30..2^30`).
#[inline(always)]
pub(crate) fn all_in_fast_range(values: [i32; 6]) -> bool {
    values
        .iter()
        .fold(0, |acc, &v| acc | v.wrapping_add(FAST_BIAS))
        >= 0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sixteen_bit_products_are_the_full_product() {
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        for _ in 0..100_000 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            let (a, b) = (u32::from(seed as u16), (seed >> 32) as u32);
            assert_eq!(mul_16_by_32(a, b), u64::from(a) * u64::from(b), "{a} {b}");
        }
        assert_eq!(mul_16_by_32(0xFFFF, u32::MAX), 0xFFFF * 0xFFFF_FFFF);
    }

    #[test]
    fn split_shifts_are_the_64_bit_ones() {
        let mut rng = crate::test_rng::XorShift(0x0123_4567_89AB_CDEF);
        for round in 0..20_000 {
            let value = match round % 4 {
                0 => rng.next_u64(),
                1 => rng.next_u64() >> (round % 64),
                2 => 1,
                _ => u64::MAX,
            };
            for n in 0..32 {
                assert_eq!(shl64(value, n), value << n, "{value:#x} << {n}");
            }
            for n in 1..=32 {
                assert_eq!(shr64(value, n), value >> n, "{value:#x} >> {n}");
            }
        }
    }

    #[test]
    fn small_products_wrap_as_64_bit_ones() {
        for value in [
            0i64,
            1,
            -1,
            i64::MAX,
            i64::MIN,
            0x1234_5678_9ABC,
            -0xFFFF_FFFF,
        ] {
            for small in [0u32, 1, 7, 16, 31, 0xFFFF] {
                let product = value.wrapping_mul(i64::from(small));
                assert_eq!(mul_small(value, small), product);
                assert_eq!(mul_small_split(value, small), product);
            }
        }
    }

    /// The split products (Cortex-M0's) against the 64-bit one, on fixed and pseudo-random
    /// values and every count's edge cases.
    #[test]
    fn count_products_wrap_as_64_bit_ones() {
        let fixed = [
            0i64,
            1,
            -1,
            i64::MAX,
            i64::MIN,
            0x1234_5678_9ABC,
            -0xFFFF_FFFF,
        ];
        let mut state = 0x9E37_79B9_7F4A_7C15u64;
        let random = (0..2000).map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state as i64
        });
        for value in fixed.into_iter().chain(random) {
            for count in [0i16, 1, -1, 7, -16, 0x7FFF, -0x7FFF, i16::MIN, value as i16] {
                let product = value.wrapping_mul(i64::from(count));
                assert_eq!(mul_count(value, count), product);
                assert_eq!(mul_count_split(value, count), product);
            }
            let small = (value as u32) & 0xFFFF;
            assert_eq!(
                mul_small_split(value, small),
                value.wrapping_mul(i64::from(small))
            );
        }
    }

    /// The 32-bit cores' division, checked on the host as well: the unsigned shift and
    /// subtract against the library's division, and the floor division built on it against
    /// `div_euclid` and `rem_euclid`, for both signs of every numerator.
    #[test]
    fn bitwise_division_is_the_128_bit_one() {
        let check = |n: i128, d: i128| {
            let (m, e) = (n.unsigned_abs(), d.unsigned_abs());
            assert_eq!(div_rem_u128_bitwise(m, e), (m / e, m % e), "{m} / {e}");
            for n in [n, n.wrapping_neg()] {
                let want = (n.div_euclid(d), n.rem_euclid(d));
                assert_eq!(floor_div_rem_bitwise(n, d), want, "{n} / {d}");
            }
        };
        let mut rng = crate::test_rng::XorShift(0x9E37_79B9_7F4A_7C15);
        for _ in 0..100_000 {
            let mut wide = || {
                let (high, low) = (rng.next_u64(), rng.next_u64());
                (i128::from(high) << 64 | i128::from(low)) >> (rng.next_u64() % 127)
            };
            let (n, d) = (wide(), (wide() & i128::MAX).max(1));
            check(n, d);
        }
        for (n, d) in [
            (0, 1),
            (-1, 1),
            (-1, 2),
            (7, 2),
            (-8, 2),
            (7, 7),
            (-1, 1 << 100),
            (i128::MAX, 1),
            (i128::MIN, 3),
        ] {
            check(n, d);
        }
    }

    #[test]
    fn cross_sign_is_exact_at_the_32_bit_limit() {
        let h = 1 << 15;
        let cases = [
            (-h, -h, -h, h - 1),
            (h - 1, h - 1, -h, h - 1),
            (-h, h - 1, h - 1, -h),
            (h, 1, 1, h),
            (h, h, 0, 0),
            (3, 5, 15, 1),
            (-7, 9, 2, -31),
            (i32::MAX / 2, 3, 1, 1),
            // Just past the 32-bit products' range.
            (h, h + 1, -h - 1, h),
            (3 * h - 1, 3 * h - 1, 1, 1),
            (-2 * h, 2 * h, 2 * h, 2 * h - 1),
        ];
        for (a, b, c, d) in cases {
            let exact = i64::from(a) * i64::from(b) - i64::from(c) * i64::from(d);
            assert_eq!(
                <i32 as Lane>::cross_positive(a, b, c, d),
                (exact != 0).then_some(exact > 0),
                "{a} {b} {c} {d}"
            );
            assert_eq!(
                <i32 as Lane>::cross_sign(a, b, c, d),
                exact.cmp(&0),
                "{a} {b} {c} {d}"
            );
        }
    }

    #[test]
    fn counted_division_is_the_floor_division() {
        let check = |n: i32, d: i32| {
            let want = (n.div_euclid(d), n.rem_euclid(d));
            assert_eq!(div_rem_floor_counted(n, d), want, "{n} / {d}");
            if let Some(got) = one_or_minus_two(n, d) {
                assert_eq!(got, want, "{n} / {d}");
            } else {
                assert!(!matches!(want.0, 1 | -2), "{n} / {d}");
            }
        };
        let edges = [
            0,
            1,
            -1,
            2,
            -2,
            255,
            256,
            -256,
            1 << 30,
            -(1 << 30),
            i32::MAX,
            i32::MIN + 1,
        ];
        for &n in &edges {
            for &d in &edges {
                if d > 0 {
                    check(n, d);
                }
            }
        }
        for n in -600..600 {
            for d in 1..300 {
                check(n, d);
            }
        }
        let mut rng = crate::test_rng::XorShift(0xD1D1_D1D1_0000_0042);
        for _ in 0..100_000 {
            let n = (rng.next_u64() as i32) >> (rng.next_u64() % 32);
            let d = ((rng.next_u64() as u32) >> (1 + rng.next_u64() % 31)).max(1) as i32;
            check(n, d);
        }
    }

    #[test]
    fn compact_division_agrees_with_the_builtin() {
        let values = [
            0u64,
            1,
            2,
            7,
            1 << 31,
            u64::from(u32::MAX),
            1 << 32,
            (1 << 62) + 12_345,
            u64::MAX - 1,
            u64::MAX,
        ];
        for &n in &values {
            for &d in &values[1..] {
                assert_eq!(div_rem_u64(n, d), (n / d, n % d), "{n} / {d}");
            }
        }
        // Random dividends and divisors of every width (the shift and subtract's loop runs
        // once per dividend bit).
        let mut rng = crate::test_rng::XorShift(0x5DEE_CE66_D1CE_4E5B);
        for _ in 0..20_000 {
            let n = rng.next_u64() >> (rng.next_u64() % 64);
            let d = (rng.next_u64() >> (rng.next_u64() % 64)).max(1);
            assert_eq!(div_rem_u64(n, d), (n / d, n % d), "{n} / {d}");
        }
        for v in [
            -7i64,
            -6,
            -1,
            0,
            5,
            i64::from(i32::MIN) * 4 - 3,
            i64::from(i32::MAX) * 4 + 1,
        ] {
            for d in [1i64, 2, 3, 7, 1 << 32, (1 << 33) - 1] {
                assert_eq!(
                    v.div_rem_floor(d),
                    (v.div_euclid(d), v.rem_euclid(d)),
                    "{v} / {d}"
                );
            }
        }
    }

    #[test]
    fn the_split_signed_product_is_the_product() {
        let mut rng = crate::test_rng::XorShift(0x5851_F42D_4C95_7F2D);
        let edges = [
            0,
            1,
            -1,
            i32::MAX,
            i32::MIN,
            1 << 16,
            -(1 << 16),
            0x7FFF,
            -0x8000,
        ];
        let bs = [0, 1, u32::MAX, 1 << 31, 0xFFFF, 0x1_0000, 12_345_678];
        for &a in &edges {
            for &b in &bs {
                assert_eq!(
                    mul_i32_u32_split(a, b),
                    i64::from(a) * i64::from(b),
                    "{a} {b}"
                );
            }
        }
        for _ in 0..100_000 {
            let (a, b) = (rng.next_u64() as i32, rng.next_u64() as u32);
            assert_eq!(
                mul_i32_u32_split(a, b),
                i64::from(a) * i64::from(b),
                "{a} {b}"
            );
        }
    }
}
