//! Texture addressing: texture coordinates stepped along a span and turned into texel indices.
//!
//! Coordinates are interpolated with [`COORDINATE_BITS`] fraction bits in an `i64`, leaving 18
//! integer bits: every `I16F16` coordinate, plus the half-texel rounding bias, fits without
//! wrapping. Each addressing mode keeps the coordinate in the form its per-pixel work is
//! cheapest in, so stepping is one addition: 64-bit, or 32-bit for spans inside the texture
//! ([`Narrow`] for perspective sub-spans, [`Scaled`] for affine ones).

use crate::setup::lane::shr64;

/// Fraction bits of texture coordinates while drawing.
pub(crate) const COORDINATE_BITS: u32 = 46;

/// One axis of a texture, addressed per triangle.
pub(crate) trait Axis: Copy {
    /// A coordinate along this axis, as the span loop carries it.
    type Coord: Copy;

    /// The coordinate for `value` (in 2^-46 texels); once per span.
    fn coord(self, value: i64) -> Self::Coord;

    /// The per-pixel step for `gradient` (in 2^-46 texels per pixel); once per triangle.
    fn step(self, gradient: i64) -> Self::Coord;

    /// `coord` moved on by `step`.
    fn advance(self, coord: Self::Coord, step: Self::Coord) -> Self::Coord;

    /// The texel containing `coord` (whose value carries the half-texel rounding bias).
    fn nearest(self, coord: Self::Coord) -> u32;

    /// The texels left and right of `coord` and its fraction of the way between them, in
    /// 1/65536.
    fn linear(self, coord: Self::Coord) -> (u32, u32, u32);
}

/// Addressing of 64-bit coordinates known to stay inside the texture: texels are the integer
/// parts, with no wrapping or clamping at all. The reference the 32-bit addressings are tested
/// against (spans inside the texture step [`Scaled`] or [`Narrow`] coordinates).
#[cfg(test)]
#[derive(Copy, Clone, Debug)]
pub(crate) struct Direct;

#[cfg(test)]
impl Axis for Direct {
    type Coord = i64;

    #[inline(always)]
    fn coord(self, value: i64) -> i64 {
        value
    }

    #[inline(always)]
    fn step(self, gradient: i64) -> i64 {
        gradient
    }

    #[inline(always)]
    fn advance(self, coord: i64, step: i64) -> i64 {
        coord.wrapping_add(step)
    }

    // Coordinates are not negative here; a logical shift tells the compiler the texel fits
    // 18 bits, which saves widening it again for indexing.
    #[inline(always)]
    fn nearest(self, coord: i64) -> u32 {
        ((coord as u64) >> COORDINATE_BITS) as u32
    }

    #[inline(always)]
    fn linear(self, coord: i64) -> (u32, u32, u32) {
        let texel = ((coord as u64) >> COORDINATE_BITS) as u32;
        let fraction = (coord >> (COORDINATE_BITS - 16)) as u32 & 0xFFFF;
        (texel, texel + 1, fraction)
    }
}

/// Addressing of coordinates known to stay inside the texture, carried in 16.16 (`u32`): for
/// perspective sub-spans, whose coordinates and steps are raw 16.16 already. On 32-bit cores
/// each coordinate is one register instead of two, so the span loop keeps them all in
/// registers; the texels are those 64-bit coordinates give (tested).
#[derive(Copy, Clone, Debug)]
pub(crate) struct Narrow;

/// The shift between raw 16.16 coordinates and the 2^-46 texels the span loops step.
pub(crate) const RAW_SHIFT: u32 = COORDINATE_BITS - 16;

impl Axis for Narrow {
    type Coord = u32;

    // The values come from raw 16.16 ones shifted up, so the shift back is exact.
    #[inline(always)]
    fn coord(self, value: i64) -> u32 {
        (value >> RAW_SHIFT) as u32
    }

    #[inline(always)]
    fn step(self, gradient: i64) -> u32 {
        (gradient >> RAW_SHIFT) as u32
    }

    #[inline(always)]
    fn advance(self, coord: u32, step: u32) -> u32 {
        coord.wrapping_add(step)
    }

    #[inline(always)]
    fn nearest(self, coord: u32) -> u32 {
        coord >> 16
    }

    #[inline(always)]
    fn linear(self, coord: u32) -> (u32, u32, u32) {
        let texel = coord >> 16;
        (texel, texel + 1, coord & 0xFFFF)
    }
}

/// Addressing of coordinates known to stay inside a texture of at most [`Scaled::SIDE`]
/// texels a side, in a `u32` with [`Scaled::BITS`] fraction bits: affine runs, whose 64-bit
/// coordinates cost Cortex-M0 two words, their steps' loads and a carry each a pixel (measured
/// on the firmware's `big` scene, nearest: 35.1 -> 27.7 instructions a pixel on Cortex-M0,
/// 21.4 -> 15.6 on M4F; bilinear 174 -> 162 and 99.6 -> 98.3). A constant shift: a variable one
/// (as many fraction bits as each texture leaves) kept a register and a copy a pixel on
/// Cortex-M0, whose shifts overwrite their operand. The caller starts each run from the 64-bit
/// coordinates rounded down and lifted so that it never falls below them (see
/// `TexturedPainter::paint_linear`).
#[derive(Copy, Clone, Debug)]
pub(crate) struct Scaled;

impl Scaled {
    /// Fraction bits.
    pub(crate) const BITS: u32 = 22;

    /// The longest side these coordinates address: every coordinate inside stays below 2^31.
    pub(crate) const SIDE: u32 = 1 << (31 - Self::BITS);

    /// The shift from [`COORDINATE_BITS`] fraction bits down to [`Scaled::BITS`].
    const SHIFT: u32 = COORDINATE_BITS - Self::BITS;
}

impl Axis for Scaled {
    type Coord = u32;

    /// Rounded down: with [`Axis::step`] rounded down too, the caller's lift covers both.
    /// The low word of the shift, the same for negative values as an arithmetic shift's.
    #[inline(always)]
    fn coord(self, value: i64) -> u32 {
        shr64(value as u64, Self::SHIFT) as u32
    }

    #[inline(always)]
    fn step(self, gradient: i64) -> u32 {
        shr64(gradient as u64, Self::SHIFT) as u32
    }

    #[inline(always)]
    fn advance(self, coord: u32, step: u32) -> u32 {
        coord.wrapping_add(step)
    }

    #[inline(always)]
    fn nearest(self, coord: u32) -> u32 {
        coord >> Self::BITS
    }

    #[inline(always)]
    fn linear(self, coord: u32) -> (u32, u32, u32) {
        let texel = coord >> Self::BITS;
        let fraction = (coord >> (Self::BITS - 16)) & 0xFFFF;
        (texel, texel + 1, fraction)
    }
}

/// Addressing of coordinates that may leave the texture, clamped to its edge or repeated,
/// chosen per triangle. One type for both modes, so that each filter has one span loop for
/// runs that leave the texture: they are the rarer runs, and a loop per mode multiplied the
/// flash of every texture style (six loops, about 8.7 KB on Cortex-M0, against two).
///
/// Repeated coordinates are kept reduced modulo the side, and their steps too, so moving on
/// needs at most one subtraction; reducing is a mask for power-of-two sides and a division
/// for others, once per span. Clamped coordinates are kept as they are, and clamped per
/// texel.
#[derive(Copy, Clone, Debug)]
pub(crate) struct Wrapped {
    /// The last texel.
    last: i32,
    /// The texel right of the last one: the first when repeating, the last when clamping.
    after_last: u32,
    /// The side in 2^-46 texels when repeating; `i64::MAX` when clamping, which no coordinate
    /// reaches, so that moving on never subtracts.
    period: i64,
}

impl Wrapped {
    /// Clamp-to-edge addressing for a side of `size` texels (at least 1).
    #[inline]
    pub(crate) fn clamp(size: u32) -> Self {
        let last = size.clamp(1, 1 << 15) - 1;
        Self {
            last: last as i32,
            after_last: last,
            period: i64::MAX,
        }
    }

    /// Repeat addressing for a side of `size` texels, 1 to 2^15.
    #[inline]
    pub(crate) fn repeat(size: u32) -> Self {
        let size = size.clamp(1, 1 << 15);
        Self {
            last: size as i32 - 1,
            after_last: 0,
            period: i64::from(size) << COORDINATE_BITS,
        }
    }
}

impl Axis for Wrapped {
    type Coord = i64;

    #[inline(always)]
    fn coord(self, value: i64) -> i64 {
        let period = self.period;
        if period == i64::MAX {
            value
        } else if period & (period - 1) == 0 {
            // Power-of-two side: the remainder is the low bits, negative values included.
            value & (period - 1)
        } else {
            // `value = whole 2^46 + fraction`, fraction in `0..2^46`, so the remainder modulo
            // `side 2^46` is `(whole mod side) 2^46 + fraction`: the whole texels (18 bits
            // with the sign) reduced by a 32-bit division, not a 64-bit one (a long library
            // call on Cortex-M). Euclidean, in unsigned arithmetic: `rem_euclid` would check
            // for `i32::MIN % -1` and bring in a panic.
            let side = ((self.last as u32) + 1).max(1);
            let whole = (value >> COORDINATE_BITS) as i32;
            let wrapped = if whole >= 0 {
                whole as u32 % side
            } else {
                side - 1 - (!whole) as u32 % side
            };
            (i64::from(wrapped) << COORDINATE_BITS) | (value & ((1 << COORDINATE_BITS) - 1))
        }
    }

    #[inline(always)]
    fn step(self, gradient: i64) -> i64 {
        self.coord(gradient)
    }

    #[inline(always)]
    fn advance(self, coord: i64, step: i64) -> i64 {
        // Repeating, both are below the period, which is below 2^62: no overflow.
        let moved = coord.wrapping_add(step);
        if moved >= self.period {
            moved - self.period
        } else {
            moved
        }
    }

    // The texel of any i64 coordinate fits an i32 (18 bits): clamping in 32 bits is cheaper.
    // (`max` then `min`, not `clamp`, which would check `0 <= last` and bring in a panic.)
    #[inline(always)]
    fn nearest(self, coord: i64) -> u32 {
        ((coord >> COORDINATE_BITS) as i32).max(0).min(self.last) as u32
    }

    #[inline(always)]
    fn linear(self, coord: i64) -> (u32, u32, u32) {
        let texel = (coord >> COORDINATE_BITS) as i32;
        let fraction = (coord >> (COORDINATE_BITS - 16)) as u32 & 0xFFFF;
        let right = if texel >= self.last {
            self.after_last
        } else {
            (texel + 1).max(0) as u32
        };
        (texel.max(0).min(self.last) as u32, right, fraction)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ONE: i64 = 1 << COORDINATE_BITS;

    /// Texel `floor(value)` under each addressing mode, against plain integer arithmetic.
    #[test]
    fn modes_agree_with_integer_arithmetic() {
        for size in [1u32, 2, 3, 5, 8, 64, 100, 1 << 15] {
            let repeated = Wrapped::repeat(size);
            let clamped = Wrapped::clamp(size);
            for texel in [
                -70_000i64, -65_537, -3, -1, 0, 1, 2, 7, 63, 99, 40_000, 131_071,
            ] {
                for fraction in [0, 1, ONE / 2, ONE - 1] {
                    let value = texel * ONE + fraction;
                    let wrapped = texel.rem_euclid(i64::from(size)) as u32;
                    let want_fraction = (fraction >> (COORDINATE_BITS - 16)) as u32;
                    assert_eq!(
                        repeated.nearest(repeated.coord(value)),
                        wrapped,
                        "{size} {value}"
                    );
                    let (l, r, f) = repeated.linear(repeated.coord(value));
                    assert_eq!((l, r, f), (wrapped, (wrapped + 1) % size, want_fraction));
                    let last = i64::from(size) - 1;
                    let value = clamped.coord(value);
                    assert_eq!(i64::from(clamped.nearest(value)), texel.clamp(0, last));
                    let (l, r, f) = clamped.linear(value);
                    assert_eq!(i64::from(l), texel.clamp(0, last));
                    assert_eq!(i64::from(r), (texel + 1).clamp(0, last));
                    assert_eq!(f, want_fraction);
                }
            }
        }
    }

    /// 32-bit coordinates pick the texels and fractions the 64-bit ones do, stepped alike, for
    /// raw 16.16 values inside a texture of up to 2^15 texels.
    #[test]
    fn narrow_coordinates_agree_with_direct_ones() {
        let mut rng = crate::test_rng::XorShift(0x1234_5678_9ABC_DEF1);
        for _ in 0..20_000 {
            let start = (rng.next_u64() % (1 << 31)) as u32;
            let step = (rng.next_u64() % (1 << 18)) as u32;
            let (mut narrow, mut direct) = (
                Narrow.coord(i64::from(start) << RAW_SHIFT),
                Direct.coord(i64::from(start) << RAW_SHIFT),
            );
            let (narrow_step, direct_step) = (
                Narrow.step(i64::from(step) << RAW_SHIFT),
                Direct.step(i64::from(step) << RAW_SHIFT),
            );
            for _ in 0..16 {
                if i64::from(narrow) >= 1 << 31 {
                    break;
                }
                assert_eq!(Narrow.nearest(narrow), Direct.nearest(direct));
                assert_eq!(Narrow.linear(narrow), Direct.linear(direct));
                narrow = Narrow.advance(narrow, narrow_step);
                direct = Direct.advance(direct, direct_step);
            }
        }
    }

    /// Scaled coordinates, started from 64-bit ones rounded down and lifted by the run's
    /// length, stay at or above the 64-bit ones stepped alike and at most the length (in
    /// units of 2^-22 texel) over them, for any start inside a 512-texel side and any step
    /// that keeps the run inside: the bound `TexturedPainter::paint_linear` documents.
    #[test]
    fn scaled_coordinates_stay_within_their_lift() {
        let mut rng = crate::test_rng::XorShift(0x5CA1_ED00_D1CE_0001);
        let side = i64::from(Scaled::SIDE) << COORDINATE_BITS;
        let unit = 1i128 << (COORDINATE_BITS - Scaled::BITS);
        for _ in 0..20_000 {
            let len = (rng.next_u64() % 1023) as u32 + 1;
            let start = (rng.next_u64() % side as u64) as i64;
            // Steps of either sign up to a texel and a half a pixel, kept inside the side.
            let step = (rng.next_u64() % (3 << (COORDINATE_BITS - 1))) as i64
                - (3 << (COORDINATE_BITS - 2));
            let end = i128::from(start) + i128::from(step) * i128::from(len - 1);
            if !(0..i128::from(side)).contains(&end) {
                continue;
            }
            let mut scaled = Scaled.coord(start).wrapping_add(len);
            let scaled_step = Scaled.step(step);
            for k in 0..i128::from(len) {
                let direct = i128::from(start) + k * i128::from(step);
                let over = i128::from(scaled) * unit - direct;
                assert!(
                    (0..=i128::from(len) * unit).contains(&over),
                    "{start} {step} {len} {k}"
                );
                scaled = Scaled.advance(scaled, scaled_step);
            }
        }
    }

    /// Stepping wraps exactly like the sum of the values, and clamps like it.
    #[test]
    fn stepping_wraps_like_the_sum() {
        let steps = [ONE / 3, -ONE * 5 / 2, ONE * 37 + 5, -1];
        for size in [1u32, 2, 3, 16, 100, 1 << 15] {
            for step in steps {
                let start = -ONE * 7 + 12_345;
                for (axis, repeat) in [(Wrapped::repeat(size), true), (Wrapped::clamp(size), false)]
                {
                    let mut coord = axis.coord(start);
                    for k in 1..200 {
                        coord = axis.advance(coord, axis.step(step));
                        let texel = (start + k * step) >> COORDINATE_BITS;
                        let want = if repeat {
                            texel.rem_euclid(i64::from(size))
                        } else {
                            texel.clamp(0, i64::from(size) - 1)
                        };
                        assert_eq!(i64::from(axis.nearest(coord)), want);
                    }
                }
            }
        }
    }
}
