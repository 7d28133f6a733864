//! Reciprocals without a division, for cores that have none (Cortex-M0/M0+, where a 32-bit
//! division is a library call of about 130 instructions and a 64-bit one several times that):
//! a first guess from a small table and Newton steps in integer products. Perspective
//! correction divides by `1 / w` with them at every sub-span's end, plane set-up by small
//! areas and anti-aliasing by an edge's width.

use super::lane::{mul_u32, widening_mul};

/// `d << shift` in `[2^31, 2^32)` and `shift`, for `d > 0`: counting leading zeros is an
/// instruction from Cortex-M3 up and a library call on Cortex-M0, where five steps do.
#[inline(always)]
pub(crate) fn normalise(d: u32) -> (u32, u32) {
    if cfg!(target_has_atomic = "32") {
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

/// `a * b` in full, for a signed `a`: one multiply on cores that have it, [`mul_i32_u32_split`]
/// on Cortex-M0.
#[inline(always)]
pub(crate) fn mul_i32_u32(a: i32, b: u32) -> i64 {
    if cfg!(target_has_atomic = "32") {
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
