//! Texture addressing: texture coordinates stepped along a span and turned into texel indices.
//!
//! Coordinates are interpolated with [`COORDINATE_BITS`] fraction bits in an `i64`, leaving 18
//! integer bits: every `I16F16` coordinate, plus the half-texel rounding bias, fits without
//! wrapping. Each addressing mode keeps the coordinate in the form its per-pixel work is
//! cheapest in, so stepping is one (64-bit) addition.

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

/// Addressing of coordinates known to stay inside the texture (the caller checks each span's
/// ends): texels are the integer parts, with no wrapping or clamping at all.
#[derive(Copy, Clone, Debug)]
pub(crate) struct Direct;

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

/// Repeat addressing of a power-of-two side: the coordinate is kept as a `u64` with its
/// integer part (modulo 2^16) in the top 16 bits, so wrapping is free and extracting the texel
/// is a constant shift and a mask.
#[derive(Copy, Clone, Debug)]
pub(crate) struct Pow2Repeated {
    mask: u32,
}

impl Pow2Repeated {
    /// Addressing for a side of `size` texels, if it is a power of two from 2 to 2^15.
    #[inline]
    pub(crate) fn new(size: u32) -> Option<Self> {
        (size.is_power_of_two() && (2..=1 << 15).contains(&size)).then_some(Self { mask: size - 1 })
    }
}

impl Axis for Pow2Repeated {
    type Coord = u64;

    #[inline(always)]
    fn coord(self, value: i64) -> u64 {
        // Shifting out the integer bits above 16 is a modulo by a multiple of the side.
        (value as u64) << (64 - 16 - COORDINATE_BITS)
    }

    #[inline(always)]
    fn step(self, gradient: i64) -> u64 {
        self.coord(gradient)
    }

    #[inline(always)]
    fn advance(self, coord: u64, step: u64) -> u64 {
        coord.wrapping_add(step)
    }

    #[inline(always)]
    fn nearest(self, coord: u64) -> u32 {
        (coord >> 48) as u32 & self.mask
    }

    #[inline(always)]
    fn linear(self, coord: u64) -> (u32, u32, u32) {
        let texel = (coord >> 48) as u32;
        let fraction = (coord >> 32) as u32 & 0xFFFF;
        (texel & self.mask, (texel + 1) & self.mask, fraction)
    }
}

/// Repeat addressing of any side: the coordinate is kept reduced modulo the side, and the
/// step too, so moving on needs at most one subtraction. Reducing costs a division, once per
/// span.
#[derive(Copy, Clone, Debug)]
pub(crate) struct Repeated {
    size: u32,
    /// The side in 2^-46 texels.
    period: i64,
}

impl Repeated {
    /// Addressing for a side of `size` texels, 1 to 2^15.
    #[inline]
    pub(crate) fn new(size: u32) -> Self {
        let size = size.clamp(1, 1 << 15);
        Self {
            size,
            period: i64::from(size) << COORDINATE_BITS,
        }
    }
}

impl Axis for Repeated {
    type Coord = i64;

    #[inline(always)]
    fn coord(self, value: i64) -> i64 {
        // The period is below 2^62, so the reduced value is a positive i64.
        value.rem_euclid(self.period)
    }

    #[inline(always)]
    fn step(self, gradient: i64) -> i64 {
        self.coord(gradient)
    }

    #[inline(always)]
    fn advance(self, coord: i64, step: i64) -> i64 {
        // Both below the period, which is below 2^62: no overflow.
        let moved = coord + step;
        if moved >= self.period {
            moved - self.period
        } else {
            moved
        }
    }

    #[inline(always)]
    fn nearest(self, coord: i64) -> u32 {
        (coord >> COORDINATE_BITS) as u32
    }

    #[inline(always)]
    fn linear(self, coord: i64) -> (u32, u32, u32) {
        let left = (coord >> COORDINATE_BITS) as u32;
        let right = if left + 1 == self.size { 0 } else { left + 1 };
        let fraction = (coord >> (COORDINATE_BITS - 16)) as u32 & 0xFFFF;
        (left, right, fraction)
    }
}

/// Clamp-to-edge addressing: texel indices are clamped to the side.
#[derive(Copy, Clone, Debug)]
pub(crate) struct Clamped {
    last: i64,
}

impl Clamped {
    /// Addressing for a side of `size` texels (at least 1).
    #[inline]
    pub(crate) fn new(size: u32) -> Self {
        Self {
            last: i64::from(size.max(1) - 1),
        }
    }
}

impl Axis for Clamped {
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

    #[inline(always)]
    fn nearest(self, coord: i64) -> u32 {
        (coord >> COORDINATE_BITS).clamp(0, self.last) as u32
    }

    #[inline(always)]
    fn linear(self, coord: i64) -> (u32, u32, u32) {
        let texel = coord >> COORDINATE_BITS;
        let fraction = (coord >> (COORDINATE_BITS - 16)) as u32 & 0xFFFF;
        (
            texel.clamp(0, self.last) as u32,
            (texel + 1).clamp(0, self.last) as u32,
            fraction,
        )
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
            let pow2 = Pow2Repeated::new(size);
            let repeated = Repeated::new(size);
            let clamped = Clamped::new(size);
            assert_eq!(pow2.is_some(), size.is_power_of_two() && size > 1);
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
                    assert_eq!(i64::from(clamped.nearest(value)), texel.clamp(0, last));
                    let (l, r, f) = clamped.linear(value);
                    assert_eq!(i64::from(l), texel.clamp(0, last));
                    assert_eq!(i64::from(r), (texel + 1).clamp(0, last));
                    assert_eq!(f, want_fraction);
                }
            }
        }
    }

    /// Stepping wraps exactly like the sum of the values.
    #[test]
    fn stepping_wraps_like_the_sum() {
        let steps = [ONE / 3, -ONE * 5 / 2, ONE * 37 + 5, -1];
        for size in [1u32, 2, 3, 16, 100, 1 << 15] {
            for step in steps {
                let start = -ONE * 7 + 12_345;
                let repeated = Repeated::new(size);
                let mut coord = repeated.coord(start);
                let mut coord2 = Pow2Repeated::new(size).map(|p| (p, p.coord(start)));
                for k in 1..200 {
                    coord = repeated.advance(coord, repeated.step(step));
                    let value = start + k * step;
                    let want = (value >> COORDINATE_BITS).rem_euclid(i64::from(size)) as u32;
                    assert_eq!(repeated.nearest(coord), want);
                    if let Some((p, c)) = coord2.as_mut() {
                        *c = p.advance(*c, p.step(step));
                        assert_eq!(p.nearest(*c), want);
                    }
                }
            }
        }
    }
}
