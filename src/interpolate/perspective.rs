//! Perspective-correct interpolation without a divider: attributes divided by `w` are linear
//! on screen, so they are interpolated with the ordinary plane machinery, and the true values
//! come back by one reciprocal at each end of a sub-span, with affine steps between.
//!
//! Per triangle, `1 / w` is normalised to `q = w_min / w` (at most 1, with [`Q_BITS`]
//! fraction bits) and each attribute taken relative to the first vertex's, so that the
//! precision of the division depends on how far the attribute changes across the triangle,
//! not on how large it is. The reciprocal is a table of 64 first guesses and two Newton steps
//! in integer products: no division and no float, on any core.

use embedded_graphics::primitives::Rectangle;
use fixed::types::I16F16;

use super::{AreaMemo, TrackedPlanes};
use crate::geometry::Shape;
use crate::setup::{
    lane::{mul_i32_u32, mul_small, mul_u32, shl64, shr64},
    reciprocal::{reciprocal, reciprocal_inline},
};

/// How many pixels apart perspective-correct interpolation divides: the true texture coordinates
/// are computed at both ends of each sub-span of a row, and stepped linearly between.
///
/// Shorter sub-spans follow the true curve more closely and divide more often. Within a
/// sub-span the error is what linear steps between two exact points give: at most
/// `L^2 * |d²u/dx²| / 8` texels for a sub-span of `L` pixels, small unless the texture is
/// magnified steeply along the row.
///
/// # Examples
///
/// ```
/// use trirast::interpolate::SubSpan;
///
/// assert_eq!(SubSpan::default(), SubSpan::Pixels16);
/// assert_eq!(SubSpan::Pixels8.pixels(), 8);
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, Hash)]
pub enum SubSpan {
    /// 8 pixels.
    Pixels8,
    /// 16 pixels, as Quake divided.
    #[default]
    Pixels16,
    /// 32 pixels.
    Pixels32,
}

impl SubSpan {
    /// The pixels per sub-span.
    ///
    /// # Examples
    ///
    /// ```
    /// use trirast::interpolate::SubSpan;
    ///
    /// assert_eq!(SubSpan::Pixels32.pixels(), 32);
    /// ```
    #[inline]
    #[must_use]
    pub const fn pixels(self) -> u32 {
        match self {
            Self::Pixels8 => 8,
            Self::Pixels16 => 16,
            Self::Pixels32 => 32,
        }
    }
}

/// Perspective-correct interpolation, for textures ([`TextureStyle::with_perspective`]) and
/// shader attributes ([`ShaderStyle::with_perspective`]): each vertex's `w` (its distance
/// along the view direction, as the projection's fourth coordinate gives it), and the
/// sub-span length.
///
/// Attributes divided by `w` and `1 / w` itself are linear on screen; the true attributes are
/// recovered from them at both ends of every [`SubSpan`] of a row, by a reciprocal from a
/// table and two Newton steps in integer arithmetic (no division, no float), and stepped
/// linearly between.
///
/// - At the ends of sub-spans the attributes are within 1/256 (a texel, for texture
///   coordinates) of the exact rational perspective ones, for `w` ratios up to 1:256 within a
///   triangle and attributes changing by less than 4096 across it.
/// - Between, they follow the straight line between the two ends (see [`SubSpan`]), stepped
///   in 2^-16 (each pixel adds less than 1.5 x 2^-16 of rounding).
/// - Equal `w` at the three vertices (a face parallel to the screen) draws exactly what the
///   affine interpolation draws.
///
/// Sub-spans are counted from the first pixel of each run painted: where a depth test or
/// anti-aliasing splits a row into several runs, each is divided on its own, so a pixel's
/// value can differ between such drawings by what the sub-span approximation allows.
///
/// `w` must be positive; values that are not count as the smallest positive `I16F16`. Only the
/// ratios between the three matter. Texture modulation colours stay affine on screen. An
/// attribute more than 32,767 from the first vertex's (which 16.16 arithmetic cannot step
/// across) counts as 32,767 from it.
///
/// [`TextureStyle::with_perspective`]: crate::TextureStyle::with_perspective
/// [`ShaderStyle::with_perspective`]: crate::ShaderStyle::with_perspective
///
/// # Examples
///
/// ```
/// use fixed::types::I16F16;
/// use trirast::interpolate::{Perspective, SubSpan};
///
/// let w = [1, 4, 4].map(I16F16::from_num);
/// let perspective = Perspective::new(w).with_sub_span(SubSpan::Pixels8);
/// assert_eq!(perspective.sub_span.pixels(), 8);
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Perspective {
    /// Each vertex's `w`, in the triangle's vertex order.
    pub w: [I16F16; 3],
    /// Pixels between divisions; [`SubSpan::Pixels16`] by default.
    pub sub_span: SubSpan,
}

impl Perspective {
    /// Perspective with weights `w`, one per vertex, and 16-pixel sub-spans.
    ///
    /// # Examples
    ///
    /// ```
    /// use fixed::types::I16F16;
    /// use trirast::interpolate::{Perspective, SubSpan};
    ///
    /// let perspective = Perspective::new([I16F16::ONE; 3]);
    /// assert_eq!(perspective.sub_span, SubSpan::Pixels16);
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(w: [I16F16; 3]) -> Self {
        Self {
            w,
            sub_span: SubSpan::Pixels16,
        }
    }

    /// The same with another sub-span length.
    ///
    /// # Examples
    ///
    /// ```
    /// use fixed::types::I16F16;
    /// use trirast::interpolate::{Perspective, SubSpan};
    ///
    /// let perspective = Perspective::new([I16F16::ONE; 3]).with_sub_span(SubSpan::Pixels32);
    /// assert_eq!(perspective.sub_span, SubSpan::Pixels32);
    /// ```
    #[inline]
    #[must_use]
    pub const fn with_sub_span(mut self, sub_span: SubSpan) -> Self {
        self.sub_span = sub_span;
        self
    }

    /// Whether the three weights are equal: the mapping is then affine.
    #[inline]
    pub(crate) fn is_affine(&self) -> bool {
        let [a, b, c] = self.w.map(|w| w.to_bits().max(1));
        a == b && b == c
    }
}

/// Fraction bits of the normalised reciprocal `q = w_min / w`.
const Q_BITS: u32 = 30;

/// The low 32 bits of `value >> shift`, for `shift` from 1 to 32: [`shr64`]'s low word (a
/// variable 64-bit shift is a library call on Cortex-M0, and its two cases, shifts below 32
/// and from 32, cost twice the five instructions of the low word there).
#[inline(always)]
fn low_word_shifted(value: i64, shift: u32) -> i32 {
    shr64(value as u64, shift) as i32
}

/// `q` shifted left until its top bit is set, and by how much: one instruction on
/// Cortex-M3 and up; on Cortex-M0 (no such instruction) a loop, short for the values drawing
/// meets (q near 1, so a few shifts).
#[inline(always)]
fn normalise(q: u32) -> (u32, u32) {
    if crate::arch::DIVIDES {
        let zeros = q.leading_zeros();
        return (q << zeros, zeros);
    }
    let (mut q, mut zeros) = (q, 0);
    while q < 1 << 31 {
        q <<= 1;
        zeros += 1;
    }
    (q, zeros)
}

/// `w_min / w` for each vertex, with [`Q_BITS`] fraction bits (at least 1: ratios beyond 2^30
/// lose precision, never the sign). Weights that are not positive count as the smallest
/// positive `I16F16`.
#[inline(always)]
fn normalised(w: [I16F16; 3]) -> [u32; 3] {
    let mut q = [0; 3];
    for i in 0..3 {
        q[i] = w[i].to_bits().max(1) as u32;
    }
    let nearest = q[0].min(q[1]).min(q[2]);
    for q in &mut q {
        if *q == nearest {
            *q = 1 << Q_BITS;
        } else {
            // nearest * 2^30 / w, through 2^63 / (w * 2^zeros).
            let (normal, zeros) = normalise(*q);
            let scaled = mul_u32(nearest, reciprocal(normal));
            // `zeros` is at least 1 (weights are below 2^31): a shift of 2 to 32, without the
            // variable 64-bit shift's library call on Cortex-M0.
            *q = (shr64(scaled, 33 - zeros) as u32).max(1);
        }
    }
    q
}

/// Planes of `q`, `(a - a_0) q` for each of `N` attributes, and what turns them back into the
/// attributes: everything a perspective-correct span needs, set up once per triangle.
#[derive(Clone, Debug)]
pub(crate) struct PerspectivePlanes<const P: usize, const N: usize> {
    /// `q` first, then the attributes times `q`; `P = N + 1`.
    planes: TrackedPlanes<P>,
    /// The first vertex's attributes, raw 16.16, bias included (wrapping).
    base: [i32; N],
    /// The planes' change over a whole sub-span.
    across: [i64; P],
    /// Pixels per sub-span, a power of two, and its logarithm.
    sub_span: u32,
    shift: u32,
}

impl<const P: usize, const N: usize> PerspectivePlanes<P, N> {
    /// Planes of `N` attributes (raw 16.16, one array per vertex, `bias` added to all) with
    /// weights `w`, for sub-spans of `sub_span` pixels (8, 16 or 32), drawn into `window`, the
    /// area's reciprocal through `memo`; `None` for degenerate triangles. Out of line: rarer
    /// than affine texturing, and once per triangle.
    #[inline(never)]
    pub(crate) fn new<G: Shape>(
        triangle: &G,
        values: [[i64; N]; 3],
        bias: i64,
        w: [I16F16; 3],
        sub_span: u32,
        window: &Rectangle,
        memo: Option<&AreaMemo>,
    ) -> Option<Self> {
        debug_assert_eq!(P, N + 1);
        let q = normalised(w);
        let base = values[0];
        // Attributes within 2^14 of the first vertex's (every texture coordinate on a texture
        // up to 16,384 texels a side) need no clamp: one test of all of them costs Cortex-M4F
        // less than a clamp of each (on Cortex-M0 more).
        let mut spread = 0;
        for i in 1..3 {
            for k in 0..N {
                spread |= (values[i][k] - base[k] + (1 << 30)) as u64;
            }
        }
        let near = crate::arch::DIVIDES && spread >> 31 == 0;
        // Every element made in place (zeroed first, the array took a `memclr` call).
        let weighted: [[i64; P]; 3] = core::array::from_fn(|i| {
            core::array::from_fn(|j| {
                if j == 0 {
                    return i64::from(q[i]);
                }
                let k = j - 1;
                // (a - a_0) * q rounded, with a - a_0 bounded (q is at most 1), so that every
                // value the planes take inside the triangle (a mean of the vertices', give or
                // take rounding) fits raw 16.16: the walk converts them without saturating.
                // Only attributes 32,767 or more from the first vertex's meet the bound.
                let delta = values[i][k] - base[k];
                let delta = if near {
                    delta
                } else {
                    delta.clamp(-WEIGHTED_LIMIT, WEIGHTED_LIMIT)
                };
                let product = mul_i32_u32(delta as i32, q[i]);
                (product + (1 << (Q_BITS - 1))) >> Q_BITS
            })
        });
        let planes = triangle.planes_in(weighted, 0, window, memo)?;
        let shift = sub_span.trailing_zeros();
        let mut this = Self {
            planes: TrackedPlanes::new(planes),
            base: [0; N],
            across: [0; P],
            sub_span,
            shift,
        };
        for k in 0..P {
            // 3 to 5 bits: without the variable 64-bit shift's library call on Cortex-M0.
            this.across[k] = shl64(this.planes.dx[k] as u64, shift) as i64;
        }
        for k in 0..N {
            this.base[k] = base[k].wrapping_add(bias) as i32;
        }
        Some(this)
    }

    /// The sub-spans of the run of `len` pixels from `(x, y)`, walked by
    /// [`PerspectivePlanes::next_sub_span`].
    #[inline(always)]
    pub(crate) fn sub_spans(&self, x: i32, y: i32, len: u32, inline: bool) -> SubSpans<P, N> {
        let values = self.planes.at_exact(x, y);
        let start = self.attributes_where(&values, inline);
        SubSpans {
            values,
            start,
            x,
            left: len,
        }
    }

    /// The next sub-span of `walk`: up to a whole sub-span's pixels, whose last step ends on
    /// the next one's first pixel, or on the run's last. Inlined into the painters' sub-span
    /// loops: returned through memory, the stretch cost about 45 more instructions per
    /// sub-span on Cortex-M0, and flash is no larger.
    #[inline(always)]
    pub(crate) fn next_sub_span(&self, walk: &mut SubSpans<P, N>, inline: bool) -> Stretch<N> {
        let (x, start) = (walk.x, walk.start);
        let whole = walk.left > self.sub_span;
        let len = if whole { self.sub_span } else { walk.left };
        let mut end = start;
        let mut steps = [0; N];
        if whole {
            for k in 0..P {
                walk.values[k] = walk.values[k].wrapping_add(self.across[k]);
            }
            end = self.attributes_where(&walk.values, inline);
            for k in 0..N {
                // Towards zero, by a shift: sub-spans are powers of two.
                let delta = end[k].wrapping_sub(start[k]);
                let magnitude = (delta.unsigned_abs() >> self.shift) as i32;
                steps[k] = if delta < 0 { -magnitude } else { magnitude };
            }
        } else if len > 1 {
            for k in 0..P {
                let dx = self.planes.dx[k];
                walk.values[k] = walk.values[k].wrapping_add(mul_small(dx, len - 1));
            }
            end = self.attributes_where(&walk.values, inline);
            for k in 0..N {
                steps[k] = sub_span_step(start[k], end[k], len - 1);
            }
        }
        walk.start = end;
        walk.x = x.wrapping_add(len as i32);
        walk.left -= len;
        Stretch {
            x,
            len,
            start,
            steps,
            end,
        }
    }

    /// [`PerspectivePlanes::attributes`], inline where `inline` holds (a constant for each
    /// walk): the call and its trip through memory cost a perspective-correct nearest pixel
    /// about 4% on Cortex-M4F and 6% on Cortex-M0, whose bilinear pixels cost ten times more.
    #[inline(always)]
    fn attributes_where(&self, values: &[i64; P], inline: bool) -> [i32; N] {
        if inline {
            self.attributes_inline(values)
        } else {
            self.attributes(values)
        }
    }

    /// The attributes (raw 16.16, bias included, wrapping) where the planes are `values`:
    /// one reciprocal of `q` and one product per attribute.
    #[inline(never)]
    fn attributes(&self, values: &[i64; P]) -> [i32; N] {
        self.attributes_inline(values)
    }

    /// [`PerspectivePlanes::attributes`], inline.
    #[inline(always)]
    fn attributes_inline(&self, values: &[i64; P]) -> [i32; N] {
        // Inside the triangle q is at least the smallest vertex's; rounding may take it a
        // unit lower, never to zero but for the most extreme ratios, which are clamped.
        let q = high_bits(values[0]).max(1) as u32;
        let (normal, zeros) = normalise(q);
        let inverse = if crate::arch::DIVIDES {
            reciprocal_inline(normal)
        } else {
            reciprocal(normal)
        };
        // a - a_0 = (a - a_0) q / q = weighted * inverse * 2^zeros * 2^30 / 2^63; q is below
        // 2^31, so the shift is 2 to 32.
        let shift = 63 - Q_BITS - zeros;
        let mut out = [0; N];
        for k in 0..N {
            let product = mul_i32_u32(high_bits(values[k + 1]), inverse);
            out[k] = self.base[k].wrapping_add(low_word_shifted(product, shift));
        }
        out
    }
}

/// `value >> 16`: a plane value in 2^-32 units back to raw 16.16. Values inside a triangle
/// fit `i32` ([`PerspectivePlanes::new`] bounds the vertices' to [`WEIGHTED_LIMIT`]), so
/// nothing saturates (which cost Cortex-M4F four instructions a value, three values at every
/// sub-span's end).
#[inline(always)]
fn high_bits(value: i64) -> i32 {
    (value >> 16) as i32
}

/// The largest attribute change `a - a_0` from the first vertex, raw 16.16, and so the
/// largest weighted one `(a - a_0) q`: one unit inside `i32`'s range, which leaves room for
/// the planes' rounding inside the triangle (below half a unit, however large the triangle).
const WEIGHTED_LIMIT: i64 = (1 << 31) - (1 << 16);

/// Where a run's walk over its sub-spans is.
#[derive(Copy, Clone, Debug)]
pub(crate) struct SubSpans<const P: usize, const N: usize> {
    /// The planes at the next sub-span's first pixel.
    values: [i64; P],
    /// The attributes there.
    start: [i32; N],
    /// Its column.
    x: i32,
    /// The run's pixels from there on.
    pub(crate) left: u32,
}

/// A stretch of a run along which attributes step linearly: raw 16.16, bias included.
#[derive(Copy, Clone, Debug)]
pub(crate) struct Stretch<const N: usize> {
    /// The first pixel's column.
    pub(crate) x: i32,
    /// Pixels.
    pub(crate) len: u32,
    /// The attributes at the first pixel.
    pub(crate) start: [i32; N],
    /// Their steps per pixel, rounded towards zero.
    pub(crate) steps: [i32; N],
    /// Where the steps lead (the next sub-span's first pixel, or this one's last): the steps
    /// taken within the sub-span stay between `start` and `end`.
    pub(crate) end: [i32; N],
}

/// The per-pixel step from `start` to `end` over `pixels` (1 to 32) pixels, rounded towards
/// zero, so that every value stepped to lies between the two: a multiply by a 32-bit
/// reciprocal from a table, not a division. Within 1.5 units of the exact quotient.
#[inline(always)]
fn sub_span_step(start: i32, end: i32, pixels: u32) -> i32 {
    /// floor(2^32 / n) for n from 2 to 32.
    const RECIPROCALS: [u32; 33] = {
        let mut table = [0u32; 33];
        let mut n = 2;
        while n < 33 {
            table[n] = ((1u64 << 32) / n as u64) as u32;
            n += 1;
        }
        table
    };
    let delta = end.wrapping_sub(start);
    let magnitude = delta.unsigned_abs();
    let step = if pixels <= 1 {
        magnitude
    } else {
        (mul_u32(magnitude, RECIPROCALS[pixels.min(32) as usize]) >> 32) as u32
    };
    // Below 2^31 unless pixels is 1 and the difference is -2^31: wraps alike either way.
    if delta < 0 {
        (step as i32).wrapping_neg()
    } else {
        step as i32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalising_and_shifting_are_the_plain_operations() {
        for shift in 0..32 {
            for value in [1u32 << shift, (1u32 << shift) | 1, u32::MAX >> (31 - shift)] {
                let zeros = value.leading_zeros();
                assert_eq!(normalise(value), (value << zeros, zeros), "{value:#x}");
            }
        }
        for value in [
            0i64,
            1,
            -1,
            i64::MAX,
            i64::MIN,
            0x1234_5678_9ABC_DEF0,
            -0x7654_3210_0123,
        ] {
            for shift in 1..=32 {
                assert_eq!(
                    low_word_shifted(value, shift),
                    (value >> shift) as i32,
                    "{value} >> {shift}"
                );
            }
        }
        let mut rng = crate::test_rng::XorShift(0x2F69_3D1B_0C8A_77E5);
        for _ in 0..20_000 {
            let (value, shift) = (rng.next_u64() as i64, 1 + (rng.next_u64() % 32) as u32);
            assert_eq!(low_word_shifted(value, shift), (value >> shift) as i32);
        }
    }

    #[test]
    fn steps_stay_between_the_ends() {
        for (start, end) in [
            (0i32, 100),
            (100, 0),
            (-5, 5),
            (7, 7),
            (0, 1 << 30),
            (3, -(1 << 30)),
            (45, -1_502_861),
            (0, 0x7FFF_FFFF),
            (0x7FFF_FFFF, 0),
        ] {
            for pixels in 1..=32u32 {
                let step = i64::from(sub_span_step(start, end, pixels));
                let (start, end) = (i64::from(start), i64::from(end));
                let reached = start + step * i64::from(pixels);
                let (low, high) = (start.min(end), start.max(end));
                assert!((low..=high).contains(&reached), "{start} {end} {pixels}");
                // Within a unit and a half of the exact quotient (a unit of rounding, and
                // |delta| / 2^32 from the reciprocal).
                let delta = i128::from(end - start);
                let off = (i128::from(step) * i128::from(pixels) - delta).abs();
                assert!(2 * off <= 3 * i128::from(pixels), "{start} {end} {pixels}");
            }
        }
    }

    #[test]
    fn equal_weights_normalise_to_one() {
        let w = I16F16::from_num(3.25);
        assert_eq!(normalised([w; 3]), [1 << Q_BITS; 3]);
        let q = normalised([w, w * 2, w * 16]);
        assert_eq!(q[0], 1 << Q_BITS);
        assert!(q[1].abs_diff(1 << (Q_BITS - 1)) <= 16, "{q:?}");
        assert!(q[2].abs_diff(1 << (Q_BITS - 4)) <= 1, "{q:?}");
        // Not positive: the smallest positive weight.
        assert_eq!(
            normalised([I16F16::ZERO, -w, I16F16::DELTA]),
            [1 << Q_BITS; 3]
        );
    }

    /// What the walk relies on to convert without saturating: inside any triangle, whatever
    /// its attributes and weights, every plane value fits raw 16.16 (`i32` after `>> 16`).
    #[test]
    #[allow(clippy::many_single_char_names)]
    fn values_inside_any_triangle_fit_raw_16_16() {
        use crate::Triangle;
        use embedded_graphics::geometry::{Point, Size};
        let mut rng = crate::test_rng::XorShift(0x9E37_79B9_7F4A_7C15);
        let mut next = |range: u64| rng.next_u64() % range;
        let window = Rectangle::new(Point::new(-1000, -1000), Size::new(2000, 2000));
        let mut checked = 0;
        while checked < 20_000 {
            // Small to screen-sized to far beyond the window.
            let reach = [40, 400, 1 << 20][next(3) as usize];
            let mut corner = || {
                Point::new(
                    (next(2 * reach) as i64 - reach as i64) as i32,
                    (next(2 * reach) as i64 - reach as i64) as i32,
                )
            };
            let v = [corner(), corner(), corner()];
            let triangle = Triangle { vertices: v };
            // Any positive weights, any 16.16 attributes.
            let w =
                [(); 3].map(|()| I16F16::from_bits(1 + (next(i32::MAX as u64) as i32 >> next(31))));
            let uv: [[i64; 2]; 3] =
                [(); 3].map(|()| [(); 2].map(|()| i64::from(next(1 << 32) as u32 as i32)));
            let Some(planes) =
                PerspectivePlanes::<3, 2>::new(&triangle, uv, 0, w, 16, &window, None)
            else {
                continue;
            };
            let p = v.map(|p| (i128::from(p.x), i128::from(p.y)));
            for _ in 0..8 {
                let x = (next(2000) as i32) - 1000;
                let y = (next(2000) as i32) - 1000;
                let (px, py) = (i128::from(x), i128::from(y));
                let edge = |s: (i128, i128), t: (i128, i128)| {
                    (t.0 - s.0) * (py - s.1) - (t.1 - s.1) * (px - s.0)
                };
                let e = [edge(p[1], p[2]), edge(p[2], p[0]), edge(p[0], p[1])];
                if !(e.iter().all(|&e| e >= 0) || e.iter().all(|&e| e <= 0)) {
                    continue; // outside
                }
                for value in planes.planes.at_exact(x, y) {
                    assert!(
                        i32::try_from(value >> 16).is_ok(),
                        "{v:?} {w:?} {uv:?} at ({x}, {y}): {value}"
                    );
                }
                checked += 1;
            }
        }
    }

    /// The documented bound: within 1/256 texel of the exact perspective coordinate, for `w`
    /// ratios up to 1:256 and coordinates changing by less than 4096 texels (measured: at
    /// most 85/65536 texel over these cases).
    #[test]
    #[allow(clippy::many_single_char_names)]
    fn attributes_are_within_1_256_texel() {
        use crate::Triangle;
        use embedded_graphics::geometry::{Point, Size};
        let mut rng = crate::test_rng::XorShift(0x2545_F491_4F6C_DD1D);
        let mut next = |range: i64| (rng.next_u64() % range as u64) as i64;
        let window = Rectangle::new(Point::new(0, 0), Size::new(320, 240));
        let mut checked = 0;
        while checked < 20_000 {
            let v = [(); 3].map(|()| Point::new(next(400) as i32 - 40, next(320) as i32 - 40));
            let triangle = Triangle { vertices: v };
            // w from 1/16 to 16, so ratios up to 1:256.
            let w = [(); 3].map(|()| I16F16::from_bits((1 << 12) + next(1 << 20) as i32));
            let origin = next(1 << 28) - (1 << 27);
            let uv: [[i64; 2]; 3] = [(); 3].map(|()| [(); 2].map(|()| origin + next(4095 << 16)));
            let Some(planes) =
                PerspectivePlanes::<3, 2>::new(&triangle, uv, 0, w, 16, &window, None)
            else {
                continue;
            };
            for _ in 0..8 {
                let (x, y) = (next(320) as i32, next(240) as i32);
                // Exact: barycentric weights over w, normalised (edge functions as weights).
                let p = v.map(|p| (i128::from(p.x), i128::from(p.y)));
                let (px, py) = (i128::from(x), i128::from(y));
                let edge = |s: (i128, i128), t: (i128, i128)| {
                    (t.0 - s.0) * (py - s.1) - (t.1 - s.1) * (px - s.0)
                };
                let mut e = [edge(p[1], p[2]), edge(p[2], p[0]), edge(p[0], p[1])];
                let area: i128 = e.iter().sum();
                if area < 0 {
                    e = e.map(|e| -e);
                }
                if e.iter().any(|&e| e < 0) {
                    continue; // outside
                }
                let wr = w.map(|w| i128::from(w.to_bits()));
                let others = [wr[1] * wr[2], wr[0] * wr[2], wr[0] * wr[1]];
                let den: i128 = (0..3).map(|i| e[i] * others[i]).sum();
                let got = planes
                    .attributes(&planes.planes.at_exact(x, y))
                    .map(i64::from);
                for k in 0..2 {
                    let num: i128 = (0..3)
                        .map(|i| e[i] * others[i] * i128::from(uv[i][k]))
                        .sum();
                    // |got - num / den| <= 256 raw units (1/256 texel).
                    let off = (i128::from(got[k]) * den - num).abs();
                    assert!(
                        off <= 256 * den,
                        "{v:?} {w:?} {uv:?} at ({x}, {y}): {got:?}"
                    );
                }
                checked += 1;
            }
        }
    }
}
