//! Gouraud shading: colours interpolated between the vertices.

use core::marker::PhantomData;

use embedded_graphics::{draw_target::DrawTarget, geometry::Point, primitives::Rectangle};

use super::{
    channels::per_channel,
    paint::{drawable_style, stored, PaintVisitor, Painter},
    spans::{shade_span, PixelShader},
    ChannelColor, TriangleStyle,
};
use crate::{
    coverage::{FillRule, Span},
    geometry::Shape,
    interpolate::TrackedPlanes,
};

/// Fills a triangle with colours interpolated between its vertices.
///
/// Each channel is interpolated in its colour type's own range, from the plane through the
/// three vertex colours, and rounded to the nearest value (or dithered, see
/// [`GouraudStyle::with_dither`]): every channel is within one level of the exact value
/// rounded. Along a row the channels step with 16 fraction bits, or, for colour types of two to
/// four channels of at most 6 bits (`Rgb565`, `Rgb555`, `Bgr565`, ...), two to a 32-bit word
/// with at least 10 fraction bits each, from a start exact to 2^-16 of a level. A triangle
/// whose vertices share a colour is filled with exactly that colour, and a vertex pixel gets
/// exactly its vertex's colour. Each covered row goes to the target as one `fill_contiguous`
/// call.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
/// use trirast::{Framebuffer, GouraudStyle, Triangle};
///
/// let mut pixels = [Rgb565::BLACK; 64 * 64];
/// let mut display = Framebuffer::new(&mut pixels, 64, 64)?;
/// Triangle::new(Point::new(0, 0), Point::new(63, 0), Point::new(0, 63))
///     .into_styled(GouraudStyle::new([Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE]))
///     .draw(&mut display)
///     .unwrap();
/// assert_eq!(display.pixel(Point::new(0, 0)), Some(Rgb565::RED));
/// // Halfway along the top edge: 32/63 of red (31), 31/63 of green (63), rounded.
/// assert_eq!(display.pixel(Point::new(31, 0)), Some(Rgb565::new(16, 31, 0)));
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub struct GouraudStyle<C> {
    /// The colour at each vertex, in the triangle's vertex order.
    pub colors: [C; 3],
    /// Which boundary pixels belong to the triangle; [`FillRule::TopLeft`] by default.
    pub fill_rule: FillRule,
    /// Ordered (4x4 Bayer) dithering instead of rounding; off by default.
    pub dither: bool,
}

impl<C> GouraudStyle<C> {
    /// A style interpolating between `colors`, one per vertex in the triangle's vertex order.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use trirast::GouraudStyle;
    ///
    /// const FADE: GouraudStyle<Gray8> = GouraudStyle::new([Gray8::new(0), Gray8::new(128), Gray8::new(255)]);
    /// assert!(!FADE.dither);
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(colors: [C; 3]) -> Self {
        Self {
            colors,
            fill_rule: FillRule::TopLeft,
            dither: false,
        }
    }

    /// The same style with another fill rule.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use trirast::{FillRule, GouraudStyle};
    ///
    /// let s = GouraudStyle::new([BinaryColor::On; 3]).with_fill_rule(FillRule::Inclusive);
    /// assert_eq!(s.fill_rule, FillRule::Inclusive);
    /// ```
    #[inline]
    #[must_use]
    pub const fn with_fill_rule(mut self, fill_rule: FillRule) -> Self {
        self.fill_rule = fill_rule;
        self
    }

    /// The same style with ordered dithering on or off.
    ///
    /// Dithering spreads the fraction of each interpolated channel over a 4x4 Bayer pattern,
    /// so gradients between few levels stay visible: on a monochrome (`BinaryColor`) display
    /// a fade from off to on becomes a graded stipple instead of a hard edge, and `Gray2`,
    /// `Gray4` or `Rgb565` gradients lose their banding. Every channel of every colour type
    /// is dithered: a pixel takes the exact value plus its threshold (1/32, 3/32, ... 31/32),
    /// rounded down, so the mean of each 4x4 block of the pattern is the exact mean within
    /// 1/32 of a level plus 1.5 times the channel's change from one pixel to the next across
    /// and down (`tests/gouraud.rs` checks both).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
    /// use trirast::{GouraudStyle, Triangle};
    ///
    /// let style = GouraudStyle::new([BinaryColor::Off, BinaryColor::On, BinaryColor::Off]).with_dither(true);
    /// let mut display = MockDisplay::new();
    /// Triangle::new(Point::new(0, 0), Point::new(60, 30), Point::new(0, 60))
    ///     .into_styled(style)
    ///     .draw(&mut display)?;
    /// // Some pixels on, some off, more on towards the bright vertex.
    /// let on = |x0: i32| (x0..x0 + 8).filter(|&x| display.get_pixel(Point::new(x, 30)) == Some(BinaryColor::On)).count();
    /// assert!(on(4) < on(40));
    /// # Ok::<(), core::convert::Infallible>(())
    /// ```
    #[inline]
    #[must_use]
    pub const fn with_dither(mut self, dither: bool) -> Self {
        self.dither = dither;
        self
    }
}

/// Thresholds of the 4x4 Bayer matrix, as 16.16 fractions `(2t + 1) / 32`.
const BAYER: [[u32; 4]; 4] = {
    let order = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];
    let mut table = [[0; 4]; 4];
    let mut y = 0;
    while y < 4 {
        let mut x = 0;
        while x < 4 {
            table[y][x] = (2 * order[y][x] + 1) << 11;
            x += 1;
        }
        y += 1;
    }
    table
};

impl<C, const N: usize> TriangleStyle for GouraudStyle<C>
where
    C: ChannelColor<Channels = [u8; N]>,
{
    type Color = C;

    #[inline]
    fn fill_rule(&self) -> FillRule {
        self.fill_rule
    }

    #[inline(always)]
    fn paint<G: Shape, V: PaintVisitor<C>>(
        &self,
        triangle: &G,
        window: &Rectangle,
        visitor: V,
    ) -> Option<V::Output> {
        let values = || {
            self.colors
                .map(|c| c.channels().map(|v| i64::from(v) << 16))
        };
        // Rounded: half a level of bias turns truncation into rounding to nearest. Dithered:
        // the threshold takes its place.
        let bias = if self.dither { 0 } else { 1 << 15 };
        let planes = triangle.planes_with(values, bias, window.top_left, visitor.area_memo())?;
        let painter = GouraudPainter {
            packed_steps: PackedShader::<C, N>::packed_steps(&planes.step),
            planes: TrackedPlanes::new(planes),
            dither: self.dither,
            color: PhantomData,
        };
        // Only anti-aliasing paints pixels outside the triangle: only it carries the range.
        Some(if V::EDGE_PIXELS {
            visitor.visit(EdgeClamped {
                painter,
                corners: self.colors,
            })
        } else {
            visitor.visit(painter)
        })
    }
}

/// The painter of a Gouraud triangle, dithered or not: one type, so the edge walk is built
/// once per target; each run picks its span loop.
struct GouraudPainter<C, const N: usize> {
    planes: TrackedPlanes<N>,
    dither: bool,
    /// The steps packed as [`PackedShader`] steps them, when the colour type packs.
    packed_steps: u64,
    color: PhantomData<C>,
}

/// A Gouraud painter for anti-aliasing, whose edge pixels keep their colours within the
/// vertices' range (see [`GouraudPainter::paint_clamped`]).
struct EdgeClamped<C, const N: usize> {
    painter: GouraudPainter<C, N>,
    /// The vertices' colours.
    corners: [C; 3],
}

impl<C, const N: usize> Painter for EdgeClamped<C, N>
where
    C: ChannelColor<Channels = [u8; N]>,
{
    type Color = C;

    #[inline(always)]
    fn paint<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        self.painter.paint(run, offset, target)
    }

    fn paint_edge<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        self.painter
            .paint_clamped(run, offset, target, &self.corners)
    }
}

impl<C, const N: usize> Painter for GouraudPainter<C, N>
where
    C: ChannelColor<Channels = [u8; N]>,
{
    type Color = C;

    // The packed and dithered loops out of line: one copy per target, not one per walk and
    // target (measured: 4.7 KB less in the every-mode firmware on Cortex-M0, 5.0 KB on M4F),
    // and their own registers. Per pixel on `big` the call costs M4F 2% (11.04 -> 11.29) and
    // saves M0 as much (19.98 -> 19.67); the sub-pixel walk's spans gain on M4F (12.57 ->
    // 11.78), which kept the 64-bit step's upper word in memory inline.
    #[inline(always)]
    fn paint<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        if self.dither {
            self.paint_thresholds(run, &BAYER, offset, target)
        } else if PackedShader::<C, N>::FITS {
            self.paint_packed(run, offset, target)
        } else {
            shade_span(
                &GouraudShader::<C, N, false>(&self.planes, &BAYER, PhantomData),
                run,
                offset,
                target,
            )
        }
    }
}

impl<C, const N: usize> GouraudPainter<C, N>
where
    C: ChannelColor<Channels = [u8; N]>,
{
    /// Colours of `run` with every channel kept within the vertices' range: anti-aliased edge
    /// pixels, whose centres may lie outside the triangle, where the interpolated value could
    /// pass a channel's limits and wrap.
    #[inline(never)]
    fn paint_clamped<D>(
        &self,
        run: Span,
        offset: Point,
        target: &mut D,
        corners: &[C; 3],
    ) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let channels = corners.map(ChannelColor::channels);
        let low: [u8; N] =
            core::array::from_fn(|k| channels.iter().map(|c| c[k]).min().unwrap_or(0));
        let high: [u8; N] =
            core::array::from_fn(|k| channels.iter().map(|c| c[k]).max().unwrap_or(0));
        let mut values = self.planes.at(run.x, run.y);
        let step = self.planes.step;
        let mut x = run.x;
        let colors = (0..run.len).map(|_| {
            let threshold = if self.dither {
                BAYER[(run.y & 3) as usize][(x & 3) as usize]
            } else {
                0
            };
            // Near the triangle the values are far from wrapping as i32.
            let color = C::from_channels(core::array::from_fn(|k| {
                let level = (values[k].wrapping_add(threshold) as i32) >> 16;
                level.clamp(i32::from(low[k]), i32::from(high[k])) as u8
            }));
            x = x.wrapping_add(1);
            for k in 0..N {
                values[k] = values[k].wrapping_add(step[k]);
            }
            color
        });
        target.fill_contiguous(&stored(run, offset), colors)
    }

    /// Paints `run` with the channels packed two to a word ([`PackedShader`]), in stretches of
    /// at most [`PACKED_RUN`] pixels, each started from the planes. Out of line (see
    /// `paint`).
    #[inline(never)]
    fn paint_packed<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        if run.len <= PACKED_RUN {
            let shader = PackedShader::<C, N>(&self.planes, self.packed_steps, PhantomData);
            shade_span(&shader, run, offset, target)
        } else {
            // Rare (wider than most displays): in 16.16, with no thresholds, by the dithered
            // loop, which is out of line anyway.
            self.paint_thresholds(run, &[[0; 4]; 4], offset, target)
        }
    }

    /// Paints `run` channel by channel in 16.16, adding `thresholds` (a 4x4 pattern over
    /// the screen) before truncating: dithered with [`BAYER`], and the same as rounding to
    /// nearest with zeros when the planes carry the half-level bias.
    #[inline(never)]
    fn paint_thresholds<D>(
        &self,
        run: Span,
        thresholds: &[[u32; 4]; 4],
        offset: Point,
        target: &mut D,
    ) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        shade_span(
            GouraudShader::<C, N, true>(&self.planes, thresholds, PhantomData),
            run,
            offset,
            target,
        )
    }
}

/// Colours along a span: channels stepped by additions, rounded to nearest or dithered.
struct GouraudShader<'a, C, const N: usize, const DITHER: bool>(
    &'a TrackedPlanes<N>,
    /// The thresholds added when dithering.
    &'a [[u32; 4]; 4],
    PhantomData<C>,
);

impl<C, const N: usize, const DITHER: bool> PixelShader for GouraudShader<'_, C, N, DITHER>
where
    C: ChannelColor<Channels = [u8; N]>,
{
    type Color = C;
    /// Column, row, channel values and their steps: the steps are copied into the state so the
    /// span loop keeps them in registers.
    type State = (i32, i32, [u32; N], [u32; N]);

    #[inline(always)]
    fn start(&self, x: i32, y: i32) -> Self::State {
        (x, y, self.0.at(x, y), self.0.step)
    }

    #[inline(always)]
    fn next(&self, (x, y, values, step): &mut Self::State) -> C {
        let threshold = if DITHER {
            self.1[(*y & 3) as usize][(*x & 3) as usize]
        } else {
            0
        };
        let color = C::from_channels(per_channel(|k| {
            (values[k].wrapping_add(threshold) >> 16) as u8
        }));
        *x = x.wrapping_add(1);
        *values = per_channel(|k| values[k].wrapping_add(step[k]));
        color
    }
}

/// Longest stretch a [`PackedShader`] steps before starting again from the planes.
const PACKED_RUN: u32 = 256;

/// Up to four 16-bit lanes, two to a 32-bit word: lanes 0 and 1 in the first word (lane 0 in
/// the lower half), 2 and 3 in the second (lane 2 in the upper half). A carry or borrow between
/// the two lanes of a word cancels out as long as each lane's value stays within its 16 bits.
/// [`PackedShader`] steps both words as one 64-bit integer ([`Lanes::wide`]).
///
/// For `Rgb565` that puts red's level bits at bits 11 to 15, where the pixel has them (two
/// shifts clear its fraction, no mask), and blue's at the top of the second word (one shift):
/// with red in the upper half the Cortex-M0 span loop kept a mask in a register and reloaded
/// both of the step's words every pixel (measured on `big`: 14.5 -> 13 instructions a pixel in
/// the loop; Gouraud 19.43 -> 18.19, Gouraud + depth -3.7%, bands -3.3%, M4F translucent -4%).
#[derive(Copy, Clone, Debug, Default)]
struct Lanes(u32, u32);

impl Lanes {
    /// The word holding lane `k`.
    #[inline(always)]
    fn word(&mut self, k: usize) -> &mut u32 {
        if k < 2 {
            &mut self.0
        } else {
            &mut self.1
        }
    }

    /// Where lane `k` starts in its word.
    #[inline(always)]
    fn position(k: usize) -> u32 {
        if k == 1 || k == 2 {
            16
        } else {
            0
        }
    }

    /// Adds `value` (signed) at lane `k`: a negative one in a lower half borrows from the
    /// upper one, which adding the lanes' values gives back.
    #[inline(always)]
    fn add(&mut self, k: usize, value: i32) {
        let at = Self::position(k);
        let word = self.word(k);
        *word = word.wrapping_add((value as u32) << at);
    }

    /// The top `bits` bits of lane `k`.
    #[inline(always)]
    fn top(mut self, k: usize, bits: u32) -> u32 {
        let at = Self::position(k) + 16 - bits;
        (*self.word(k) >> at) & ((1 << bits) - 1)
    }

    /// Both words as one integer, the first word low.
    #[inline(always)]
    fn wide(self) -> u64 {
        (u64::from(self.1) << 32) | u64::from(self.0)
    }

    /// The words of [`Lanes::wide`].
    #[inline(always)]
    fn from_wide(wide: u64) -> Self {
        Self(wide as u32, (wide >> 32) as u32)
    }
}

/// Colours along a span, rounded to nearest, for colour types of two to four channels of at
/// most 6 bits each (`Rgb565`, `Rgb555`, `Bgr565`, ...): the channels stepped together in
/// 16-bit [`Lanes`] (a channel's level bits, then fraction bits), so that a pixel costs one
/// or two additions instead of one per channel and the steps stay in registers (measured on
/// the firmware's `big` scene: Cortex-M0 25.9 -> 21.7 instructions per pixel, Cortex-M4F 16.4
/// -> 13.7).
///
/// A channel of `b` bits keeps `16 - b` fraction bits, at least 10: its start is truncated by
/// less than 2^-10 of a level and its step rounded to 2^-11, so after at most [`PACKED_RUN`]
/// pixels it is within 2^-10 + 256 * 2^-11 < 1/7 of a level of the 16.16 value, and the level
/// within one of the exact one. Inside the triangle a channel plus the half-level rounding
/// bias lies between 1/2 and its maximum plus 1/2, so it never leaves its 16 bits.
struct PackedShader<'a, C, const N: usize>(&'a TrackedPlanes<N>, u64, PhantomData<C>);

impl<C, const N: usize> PackedShader<'_, C, N>
where
    C: ChannelColor<Channels = [u8; N]>,
{
    /// Whether the colour type's channels pack: two to four, none over 6 bits.
    const FITS: bool = {
        let mut fits = N >= 2 && N <= 4;
        let mut k = 0;
        while k < N {
            fits &= C::MAX_CHANNELS[k] < 64;
            k += 1;
        }
        fits
    };

    /// Integer bits of each channel (1 to 6).
    const BITS: [u32; N] = {
        let mut bits = [1; N];
        let mut k = 0;
        while k < N {
            let significant = u8::BITS - C::MAX_CHANNELS[k].leading_zeros();
            if significant > 1 {
                bits[k] = significant;
            }
            k += 1;
        }
        bits
    };

    /// Integer bits of channel `k`: a constant, so that no build counts leading zeros per
    /// pixel (a library routine on Cortex-M0, where `opt-level = "s"` does not unroll the
    /// channel loop that would fold it away).
    #[inline(always)]
    fn bits(k: usize) -> u32 {
        Self::BITS[k]
    }

    /// The lane steps of planes stepping by `steps` (raw 16.16), each rounded, as one step of
    /// [`Lanes::wide`]: the lanes' signed steps summed at their places, so that adding it moves
    /// each word by its lanes' true sum, which keeps the word within its 32 bits (its lanes stay
    /// within theirs) and carries nothing into the other. Once per triangle.
    #[inline(always)]
    fn packed_steps(steps: &[u32; N]) -> u64 {
        let mut packed = 0i64;
        if Self::FITS {
            for k in 0..N {
                let bits = Self::bits(k);
                let step = (steps[k] as i32).wrapping_add(1 << (bits - 1)) >> bits;
                let at = if k < 2 { 0 } else { 32 } + Lanes::position(k);
                packed = packed.wrapping_add(i64::from(step) << at);
            }
        }
        packed as u64
    }
}

impl<C, const N: usize> PixelShader for PackedShader<'_, C, N>
where
    C: ChannelColor<Channels = [u8; N]>,
{
    type Color = C;
    /// The lanes as one 64-bit integer ([`Lanes::wide`]) and its step: one addition (two
    /// instructions with the carry on 32-bit cores) moves every channel. Stepped as two words
    /// instead, the compiler reached the pixels of each 4x unrolled trip by offsets from the
    /// first, loaded from memory on Cortex-M0 (measured on `big`: Cortex-M4F 13.6 -> 11.0
    /// instructions per pixel, Cortex-M0 20.7 -> 20.0; x86-64 8.3 -> 9.6, within its
    /// budget).
    type State = (u64, u64);

    #[inline(always)]
    fn start(&self, x: i32, y: i32) -> Self::State {
        let values = self.0.at(x, y);
        let mut packed = Lanes::default();
        for k in 0..N {
            packed.add(k, ((values[k] >> Self::bits(k)) & 0xFFFF) as i32);
        }
        (packed.wide(), self.1)
    }

    #[inline(always)]
    fn next(&self, (packed, steps): &mut Self::State) -> C {
        let lanes = Lanes::from_wide(*packed);
        let channels = per_channel(|k| lanes.top(k, Self::bits(k)) as u8);
        *packed = packed.wrapping_add(*steps);
        C::from_channels(channels)
    }
}

drawable_style!([C, const N: usize] GouraudStyle<C> where C: ChannelColor<Channels = [u8; N]>);
