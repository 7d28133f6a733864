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

/// Addressing of coordinates that may leave the texture, by the style's [`Wrap`]: chosen per
/// triangle, at run time, so that one span loop serves every wrap mode. Only spans that leave
/// the texture take it (see [`Direct`]), so its per-pixel `match` is off the common path.
///
/// [`Wrap`]: super::Wrap
#[derive(Copy, Clone, Debug)]
pub(crate) enum Wrapped {
    /// Clamp to edge: texel indices are clamped to `0..=last`.
    Clamp { last: i64 },
    /// Repeat of a power-of-two side (2 to 2^15): the low bits of the integer part.
    Pow2 { mask: u32 },
    /// Repeat of any side: the coordinate is kept reduced modulo the side, and the step too,
    /// so moving on needs at most one subtraction. Reducing costs a division, once per span.
    Repeat {
        size: u32,
        /// The side in 2^-46 texels.
        period: i64,
    },
}

impl Wrapped {
    /// Clamp-to-edge addressing for a side of `size` texels (at least 1).
    #[inline]
    pub(crate) fn clamp(size: u32) -> Self {
        Self::Clamp {
            last: i64::from(size.max(1) - 1),
        }
    }

    /// Repeat addressing for a side of `size` texels (1 to 2^15): masking for powers of two.
    #[inline]
    pub(crate) fn repeat(size: u32) -> Self {
        let size = size.clamp(1, 1 << 15);
        if size.is_power_of_two() && size >= 2 {
            Self::Pow2 { mask: size - 1 }
        } else {
            Self::Repeat {
                size,
                period: i64::from(size) << COORDINATE_BITS,
            }
        }
    }
}

impl Axis for Wrapped {
    type Coord = i64;

    #[inline(always)]
    fn coord(self, value: i64) -> i64 {
        match self {
            // The period is below 2^62, so the reduced value is a positive i64.
            Self::Repeat { period, .. } => value.rem_euclid(period),
            Self::Clamp { .. } | Self::Pow2 { .. } => value,
        }
    }

    #[inline(always)]
    fn step(self, gradient: i64) -> i64 {
        self.coord(gradient)
    }

    #[inline(always)]
    fn advance(self, coord: i64, step: i64) -> i64 {
        match self {
            Self::Repeat { period, .. } => {
                // Both below the period, which is below 2^62: no overflow.
                let moved = coord + step;
                if moved >= period {
                    moved - period
                } else {
                    moved
                }
            }
            // The integer bits a power-of-two side reads (up to 2^15) survive wrapping.
            Self::Clamp { .. } | Self::Pow2 { .. } => coord.wrapping_add(step),
        }
    }

    #[inline(always)]
    fn nearest(self, coord: i64) -> u32 {
        let texel = coord >> COORDINATE_BITS;
        match self {
            Self::Clamp { last } => texel.clamp(0, last) as u32,
            // Two's complement: the low bits of the floor are the floor modulo the side.
            Self::Pow2 { mask } => texel as u32 & mask,
            Self::Repeat { .. } => texel as u32,
        }
    }

    #[inline(always)]
    fn linear(self, coord: i64) -> (u32, u32, u32) {
        let texel = coord >> COORDINATE_BITS;
        let fraction = (coord >> (COORDINATE_BITS - 16)) as u32 & 0xFFFF;
        let (left, right) = match self {
            Self::Clamp { last } => (
                texel.clamp(0, last) as u32,
                (texel + 1).clamp(0, last) as u32,
            ),
            Self::Pow2 { mask } => (texel as u32 & mask, (texel as u32).wrapping_add(1) & mask),
            Self::Repeat { size, .. } => {
                let left = texel as u32;
                (left, if left + 1 == size { 0 } else { left + 1 })
            }
        };
        (left, right, fraction)
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
                let repeated = Wrapped::repeat(size);
                let mut coord = repeated.coord(start);
                for k in 1..200 {
                    coord = repeated.advance(coord, repeated.step(step));
                    let value = start + k * step;
                    let want = (value >> COORDINATE_BITS).rem_euclid(i64::from(size)) as u32;
                    assert_eq!(repeated.nearest(coord), want);
                }
            }
        }
    }
}
