//! Reciprocals without a division, for cores that have none (Cortex-M0/M0+, where a 32-bit
//! division is a library call of about 130 instructions and a 64-bit one several times that):
//! a first guess from a small table and Newton steps in integer products. Perspective
//! correction divides by `1 / w` with them at every sub-span's end, plane set-up by small
//! areas and anti-aliasing by an edge's width.

use super::lane::{mul_i32_u32, mul_u32, widening_mul};

/// `d << shift` in `[2^31, 2^32)` and `shift`, for `d > 0`: counting leading zeros is an
/// instruction from Cortex-M3 up and a library call on Cortex-M0, where five steps do.
#[inline(always)]
pub(crate) fn normalise(d: u32) -> (u32, u32) {
    if crate::arch::DIVIDES {
        let shift = d.leading_zeros();
        return (d << shift, shift);
    }
    let (mut normal, mut shift) = (d, 0);
    for step in [16, 8, 4, 2, 1] {
        if normal < 1 << (32 - step) {
            normal <<= step;
            shift += step;
        }
    }
    (normal, shift)
}

/// First guesses of `2^31 / d` for `d` in `[2^15, 2^16)`: entry `i` serves
/// `d` in `[(64 + i) * 512, (65 + i) * 512)` and is taken at the middle, within 0.78%.
const FIRST_GUESS: [u16; 64] = {
    let mut table = [0u16; 64];
    let mut i = 0;
    while i < 64 {
        // 2^31 / ((64.5 + i) * 512) = 2^23 / (129 + 2i), rounded.
        let middle = 129 + 2 * i as u32;
        table[i] = ((2 * (1u32 << 23) + middle) / (2 * middle)) as u16;
        i += 1;
    }
    table
};

/// `2^63 / d` for `d` in `[2^31, 2^32)`, within `2^-26` of it relatively, saturated to
/// `u32::MAX` (which `d = 2^31` would exceed).
///
/// A first guess from [`FIRST_GUESS`] (7 bits), one Newton step `x + x (1 - d x)` in 32-bit
/// products on the top 16 bits of `d` (14 bits) and one in 64-bit products on all of it (27
/// bits). Each 64-bit product is four 16-bit multiplies on Cortex-M0 and one instruction on
/// Cortex-M3 and up, so this costs about what one division does on Cortex-M4 and a tenth of
/// the library's division on Cortex-M0.
#[inline(never)]
pub(crate) fn reciprocal(d: u32) -> u32 {
    reciprocal_inline(d)
}

/// [`reciprocal`], inline: in `PerspectivePlanes::attributes` from Cortex-M3 up, where the
/// call cost 2% of a perspective-correct triangle (on Cortex-M0 inline cost 0.5 to 1.3% more).
#[inline(always)]
pub(crate) fn reciprocal_inline(d: u32) -> u32 {
    debug_assert!(d >= 1 << 31);
    let top = d >> 16;
    let guess = u32::from(FIRST_GUESS[((top >> 9) & 63) as usize]);
    // 1 - top * guess / 2^31, below 2^24 in magnitude (the guess is within 0.78%).
    let error = (1u32 << 31).wrapping_sub(top * guess) as i32;
    // guess + guess * error / 2^31; both products below 2^30.
    let better = guess as i32 + (((guess as i32) * (error >> 11)) >> 20);
    // About 2^47 / top, so about 2^63 / d; at most 2^16 - 1 so that it fits after the shift.
    let x = (better.clamp(1, 0xFFFF) as u32) << 16;
    // 1 - d * x / 2^63, below 2^50 in magnitude (x is within 2^-13 of the reciprocal).
    let error = ((1u64 << 63).wrapping_sub(mul_u32(d, x)) as i64) >> 20;
    let correction = mul_i32_u32(error as i32, x) >> 43;
    (i64::from(x) + correction).clamp(0, i64::from(u32::MAX)) as u32
}

/// `digits / d`, for the base-2^16 `digits` of a dividend (most significant first, each below
/// 2^16) and `d` in `2..=2^16`, without a division: long division, each quotient digit estimated by a product with about
/// `2^32 / d` (from [`reciprocal`], within 2^-26 relatively) and corrected by comparing with
/// `d`. Exact: the corrections leave each digit's remainder in `0..d`. The plane set-up's
/// small areas (`2^62 / d`) and anti-aliasing's edge ratios (`rows 2^32 / d`) divide so on
/// Cortex-M0, where a 32-bit division is a library call of about 130 instructions.
#[inline(always)]
pub(crate) fn divide_by_inverse<const K: usize>(digits: [u32; K], d: u32) -> u64 {
    let (normal, shift) = normalise(d);
    // 2^63 / (d * 2^shift) down to about 2^32 / d.
    let inverse = reciprocal(normal) >> (31 - shift);
    let mut quotient = 0u64;
    let mut remainder = 0u32;
    for digit in digits {
        // remainder < d <= 2^16: the dividend fits 32 bits and its digit 16.
        let dividend = (remainder << 16) | digit;
        let mut q = (widening_mul(dividend, inverse) >> 32) as u32;
        // q is a few units off the digit at most, so its remainder, taken wrapping, is
        // within `i32` (the callers' unit tests try every d, with the largest dividends).
        let mut r = dividend.wrapping_sub(q.wrapping_mul(d)) as i32;
        while r < 0 {
            q -= 1;
            r += d as i32;
        }
        while r >= d as i32 {
            q += 1;
            r -= d as i32;
        }
        quotient = (quotient << 16) | u64::from(q);
        remainder = r as u32;
    }
    quotient
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reciprocals_are_within_2_to_the_minus_26() {
        let check = |d: u32| {
            let exact = (1u128 << 63) / u128::from(d);
            let got = u128::from(reciprocal(d));
            let want = exact.min(u128::from(u32::MAX));
            let error = got.abs_diff(want);
            assert!(error <= (want >> 26) + 1, "{d:#x}: {got} vs {exact}");
        };
        for d in (1u32 << 31..=u32::MAX).step_by(4099) {
            check(d);
        }
        for i in 0..64u32 {
            let edge = (64 + i) << 25;
            for d in [
                edge,
                edge + 1,
                edge.wrapping_sub(1) | 1 << 31,
                edge | 0x01FF_FFFF,
            ] {
                check(d);
            }
        }
        check(u32::MAX);
    }
}
