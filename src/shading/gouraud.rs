//! Gouraud shading: colours interpolated between the vertices.

use core::marker::PhantomData;

use embedded_graphics::{draw_target::DrawTarget, geometry::Point, primitives::Rectangle};

use super::{
    ChannelColor, TriangleStyle,
    paint::{PaintVisitor, Painter, drawable_style, stored},
    spans::{PixelShader, shade_span},
};
use crate::{
    coverage::{FillRule, Span},
    geometry::Shape,
    interpolate::{CHANNEL_BITS, Planes, TrackedPlanes},
    unroll::per_channel,
};

/// Fills a triangle with colours interpolated between its vertices.
///
/// Each channel is interpolated in its colour type's own range, from the plane through the
/// three vertex colours, and rounded to the nearest value (or dithered, see
/// [`GouraudStyle::with_dither`]): every channel is within one level of the exact value
/// rounded. Along a row the channels step with 16 fraction bits, or, for colour types of two or
/// three channels of at most 6 bits (`Rgb565`, `Rgb555`, `Rgb666`, their `Bgr` twins), all in
/// one 64-bit integer with at least 15 fraction bits each, which moves from span to span as
/// one value and stays within 1/7 of a level of exact. A triangle whose vertices share a
/// colour is filled with exactly that colour, and a vertex pixel gets exactly its vertex's
/// colour. Each covered row goes to the target as one `fill_contiguous`
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
    /// and down (`tests/suite/gouraud.rs` checks both). Colour types whose channels share one 64-bit
    /// integer (`Rgb565`, `Rgb555`, `Rgb666`, their `Bgr` twins) step all channels with one
    /// addition, as when rounding, within 1/64 + 2^-15 of a level of the exact value: a pixel
    /// within that of a threshold may take the level beside it, and the bound on a block's
    /// mean grows by as much.
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
        let memo = visitor.area_memo();
        let painter = |planes, packed| GouraudPainter {
            planes: TrackedPlanes::new(planes),
            span_loop: match (packed, self.dither) {
                (true, false) => SpanLoop::Lanes,
                (true, true) => SpanLoop::DitheredLanes,
                (false, false) => SpanLoop::Rounded,
                (false, true) => SpanLoop::Dithered,
            },
            color: PhantomData,
        };
        // Whether the triangle paints from lanes, which then replace its planes (see
        // `PackedShader::packs`).
        let to_lanes = |planes: &mut Planes<N>| {
            let packed = PackedShader::<C, N>::packs(planes, window, self.dither);
            if packed {
                PackedShader::<C, N>::to_lanes(planes);
            }
            packed
        };
        // Only anti-aliasing paints pixels outside the triangle: only it carries the range.
        Some(if V::EDGE_PIXELS {
            // Anti-aliased edge pixels keep planes of their own beside the painter's.
            let planes =
                triangle.planes_with::<N, 32, CHANNEL_BITS>(values, bias, window.top_left, memo)?;
            let mut stepped = planes;
            let packed = to_lanes(&mut stepped);
            visitor.visit(EdgeClamped {
                painter: painter(stepped, packed),
                planes: TrackedPlanes::new(planes),
                corners: self.colors,
            })
        } else {
            // Made once per triangle: a band renderer keeps the lanes between bands, not the
            // planes they come from. The lanes keep the planes' origin, which decides: again
            // only for a set-up a band renderer kept (one made here is decided as it is made).
            let mut decided = None;
            let planes = triangle.planes_adjusted::<N, 32, CHANNEL_BITS>(
                values,
                bias,
                window.top_left,
                memo,
                |planes| {
                    decided = Some(to_lanes(planes));
                },
            )?;
            let packed = decided
                .unwrap_or_else(|| PackedShader::<C, N>::packs(&planes, window, self.dither));
            visitor.visit(painter(planes, packed))
        })
    }
}

/// The painter of a Gouraud triangle, dithered or not: one type, so the edge walk is built
/// once per target; each run picks its span loop.
struct GouraudPainter<C, const N: usize> {
    /// The channels' planes or, for the lanes' span loops, the lanes ([`PackedShader`]) as
    /// the first plane (the others unused).
    planes: TrackedPlanes<N>,
    span_loop: SpanLoop,
    color: PhantomData<C>,
}

/// How a Gouraud painter shades its runs, chosen once per triangle.
#[derive(Copy, Clone, PartialEq, Eq)]
enum SpanLoop {
    /// Rounded, from lanes ([`PackedShader`]): colour types that pack, windows within the
    /// lanes' reach.
    Lanes,
    /// Dithered, from lanes ([`DitheredLanes`]): the same, windows within an eighth of it.
    DitheredLanes,
    /// Rounded, channel by channel in 16.16.
    Rounded,
    /// Dithered, channel by channel in 16.16.
    Dithered,
}

/// A Gouraud painter for anti-aliasing, whose edge pixels keep their colours within the
/// vertices' range (see [`GouraudPainter::paint_clamped`]).
struct EdgeClamped<C, const N: usize> {
    painter: GouraudPainter<C, N>,
    /// The planes the edge pixels are painted from.
    planes: TrackedPlanes<N>,
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
            .paint_clamped(&self.planes, run, offset, target, &self.corners)
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
        let planes = &self.planes;
        match self.span_loop {
            SpanLoop::Lanes => Self::paint_lanes(planes, run, offset, target),
            SpanLoop::DitheredLanes => Self::paint_dithered_lanes(planes, run, offset, target),
            SpanLoop::Dithered => Self::paint_thresholds(planes, run, &BAYER, offset, target),
            SpanLoop::Rounded if PackedShader::<C, N>::FITS => {
                // Rare (a window thousands of pixels across): in 16.16, with no thresholds, by
                // the dithered loop, which is out of line anyway.
                Self::paint_thresholds(planes, run, &[[0; 4]; 4], offset, target)
            }
            SpanLoop::Rounded => shade_span(
                &GouraudShader::<C, N, false>(planes, &BAYER, PhantomData),
                run,
                offset,
                target,
            ),
        }
    }

    /// Rounded lanes carry a depth plane in their second plane, which [`PackedShader`]'s
    /// loop leaves unused: a depth-tested Gouraud triangle then moves one set of planes per
    /// span, not two, and its depth pass holds the span loop (see `depth::spans`).
    const CARRIES_DEPTH: bool = PackedShader::<C, N>::FITS;

    #[inline(always)]
    fn carry_depth(&mut self, depth: &Planes<1>) -> bool {
        Self::CARRIES_DEPTH && self.span_loop == SpanLoop::Lanes && self.planes.adopt(1, depth)
    }

    #[inline(always)]
    fn carried_depth_at(&self, x: i32, y: i32) -> u32 {
        TrackedPlanes::<N>::to_step_units(self.planes.first_two_at(x, y).1)
    }

    #[inline(always)]
    fn paint_carried<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let shader = CarriedLanes::<C, N>(&self.planes, self.planes.dx[0] as u64, PhantomData);
        shade_span(shader, run, offset, target)
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
        planes: &TrackedPlanes<N>,
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
        let mut values = planes.at(run.x, run.y);
        let step = planes.step;
        let mut x = run.x;
        let dithered = matches!(self.span_loop, SpanLoop::Dithered | SpanLoop::DitheredLanes);
        let colors = (0..run.len).map(|_| {
            let threshold = if dithered {
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

    /// Paints `run` rounded from the lanes ([`PackedShader`]), the first of `lanes`. Out of
    /// line (see `paint`).
    #[inline(never)]
    fn paint_lanes<D>(
        lanes: &TrackedPlanes<N>,
        run: Span,
        offset: Point,
        target: &mut D,
    ) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let shader = PackedShader::<C, N>(lanes, lanes.dx[0] as u64, PhantomData);
        shade_span(&shader, run, offset, target)
    }

    /// Paints `run` dithered from the lanes ([`DitheredLanes`]), the first of `lanes`.
    #[inline(never)]
    fn paint_dithered_lanes<D>(
        lanes: &TrackedPlanes<N>,
        run: Span,
        offset: Point,
        target: &mut D,
    ) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let step = lanes.dx[0] as u64;
        // From Cortex-M3 up, one span loop per parity of the first column, so that the loop
        // keeps three steps in registers, not four (see `DitheredLanes`); Cortex-M0 keeps one
        // loop (flash).
        if crate::arch::DIVIDES {
            if run.x & 1 == 0 {
                let shader = DitheredLanes::<C, N, EVEN>(lanes, step, PhantomData);
                return shade_span(&shader, run, offset, target);
            }
            let shader = DitheredLanes::<C, N, ODD>(lanes, step, PhantomData);
            return shade_span(&shader, run, offset, target);
        }
        let shader = DitheredLanes::<C, N, ANY>(lanes, step, PhantomData);
        shade_span(&shader, run, offset, target)
    }

    /// Paints `run` channel by channel in 16.16, adding `thresholds` (a 4x4 pattern over
    /// the screen) before truncating: dithered with [`BAYER`], and the same as rounding to
    /// nearest with zeros when the planes carry the half-level bias.
    #[inline(never)]
    fn paint_thresholds<D>(
        planes: &TrackedPlanes<N>,
        run: Span,
        thresholds: &[[u32; 4]; 4],
        offset: Point,
        target: &mut D,
    ) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        shade_span(
            GouraudShader::<C, N, true>(planes, thresholds, PhantomData),
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
        let color = C::from_channels(per_channel!(N, |k| {
            (values[k].wrapping_add(threshold) >> 16) as u8
        }));
        *x = x.wrapping_add(1);
        *values = per_channel!(N, |k| values[k].wrapping_add(step[k]));
        color
    }
}

/// Colours along a span, rounded to nearest, for colour types of two or three channels of at
/// most 6 bits each (`Rgb565`, `Rgb555`, `Rgb666`, their `Bgr` twins): every channel in one
/// lane of a 64-bit integer (its level bits, then at least 15 fraction bits), so that a pixel
/// costs one 64-bit addition (two instructions on 32-bit cores) instead of one per channel,
/// and the step stays in registers (measured on the firmware's `big` scene when the lanes
/// came in: Cortex-M0 25.9 -> 21.7 instructions per pixel, Cortex-M4F 16.4 -> 13.7).
///
/// Three lanes are 21, 22 and 21 bits wide (from bit 0, 21 and 43), two 32 each. A lane's value
/// is its channel in units of 2^-f of a level (f its fraction bits) and the lanes' integer is
/// the sum of each lane's value shifted to its place, wrapping: a sum of such integers is the
/// integer of the lanes' sums, carries and borrows between lanes cancelling out, so wherever
/// the true lane values fit their lanes the level bits read out exactly. In `Rgb565` the level
/// bits fall where the pixel wants them but for a shift: red at bits 16 to 20, green at 37 to
/// 42 (bits 5 to 10 of the upper word: a mask) and blue at 59 to 63 (one shift).
///
/// The lanes are one linear function of the pixel, tracked from span to span as one plane
/// (the first of the painter's [`TrackedPlanes`]): their value at the planes' origin (a small
/// triangle's first vertex, or the window's corner), rounded down to 2^-f, plus the column and
/// row gradients, each rounded down to 2^-f, times the pixel's offset from there. A pixel's
/// lanes therefore depend on where it is only, not on where its span starts (bands, depth runs
/// and anti-aliased rows split spans differently and draw the same colours). Each rounding is
/// less than 2^-f, so within [`reach`] (2^(f - 4)) columns and rows of the origin a lane is
/// within 2^-f (1 + 2^(f - 3)) < 1/7 of a level of the exact value: inside the triangle, with
/// the half-level rounding bias, it lies between 1/2 - 1/7 and its maximum plus 1/2 + 1/7,
/// inside its lane, and the level read out is the exact value rounded to nearest or, within
/// 1/7 of a half level, the level beside it. Where a pixel of the window could lie farther
/// from the origin (rare: a window, or a first vertex off it, thousands of pixels across) the
/// triangle takes the 16.16 path.
///
/// Before the lanes were tracked (2026-11-29, eleventh session) each span packed them from the
/// three planes, moved to its start; one plane moved instead of three: per `mesh` triangle
/// Cortex-M0 Gouraud -8%, Gouraud + depth -6%, Cortex-M4F -8% and -5%, for 0.8 KB more flash
/// in each Gouraud share on Cortex-M0.
struct PackedShader<'a, C, const N: usize>(&'a TrackedPlanes<N>, u64, PhantomData<C>);

impl<C, const N: usize> PackedShader<'_, C, N>
where
    C: ChannelColor<Channels = [u8; N]>,
{
    /// Integer bits of each channel (1 to 8).
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

    /// Where each lane starts, and (the next one's start) ends.
    const STARTS: [u32; N] = {
        let mut starts = [0; N];
        let mut k = 0;
        while k < N {
            starts[k] = match (N, k) {
                (3, 1) => 21,
                (3, 2) => 43,
                _ => 64 / N as u32 * k as u32,
            };
            k += 1;
        }
        starts
    };

    /// The bit after lane `k`.
    const fn end(k: usize) -> u32 {
        if k + 1 < N { Self::STARTS[k + 1] } else { 64 }
    }

    /// Fraction bits of each lane.
    const FRACTION: [u32; N] = {
        let mut fraction = [0; N];
        let mut k = 0;
        while k < N {
            fraction[k] = Self::end(k) - Self::STARTS[k] - Self::BITS[k];
            k += 1;
        }
        fraction
    };

    /// Whether the colour type's channels pack: two or three lanes of at least 15 fraction
    /// bits, each lane's level bits within one 32-bit word.
    const FITS: bool = {
        let mut fits = N == 2 || N == 3;
        let mut k = 0;
        while k < N {
            let (top, low) = (Self::end(k), Self::end(k) - Self::BITS[k]);
            fits &= Self::BITS[k] <= 6 && Self::FRACTION[k] >= 15 && low / 32 == (top - 1) / 32;
            k += 1;
        }
        fits
    };

    /// The fewest fraction bits of any lane.
    const LEAST_FRACTION: u32 = {
        let mut least = 64;
        let mut k = 0;
        while k < N {
            if Self::FRACTION[k] < least {
                least = Self::FRACTION[k];
            }
            k += 1;
        }
        least
    };

    /// Pixels from the planes' origin within which the lanes stay exact enough ([`reach`]): a
    /// constant, not a call at run time (at `opt-level = "s"` it was one).
    const REACH: u32 = reach(Self::LEAST_FRACTION);

    /// Values of the planes (2^-32 units, wrapping) as the lanes' integer, each rounded down
    /// to its lane's units.
    #[inline(always)]
    fn pack(values: &[i64; N]) -> u64 {
        // Each lane's shifts by constants: in a loop (kept at `opt-level = "s"`) they were
        // variable 64-bit shifts, library calls on Cortex-M0.
        let lanes: [u64; N] = per_channel!(N, |k| {
            ((values[k] >> (32 - Self::FRACTION[k])) as u64) << Self::STARTS[k]
        });
        let mut packed = 0u64;
        // Indexed: an array's `into_iter` stayed calls at `opt-level = "s"`.
        for k in 0..N {
            packed = packed.wrapping_add(lanes[k]);
        }
        packed
    }

    /// Whether a triangle of `planes` set up for `window` (which holds every pixel drawn)
    /// paints from lanes: colour types that pack, and every pixel of the window within reach
    /// (dithered: an eighth of it, see [`DitheredLanes`]) of the planes' origin (a small
    /// triangle's first vertex, or the window's corner), which leaves out windows thousands of
    /// pixels across and triangles whose first vertex lies thousands of pixels off the window.
    #[inline(always)]
    fn packs(planes: &Planes<N>, window: &Rectangle, dither: bool) -> bool {
        let origin = planes.origin();
        // Each way: the origin within `reach` of the window's first and last pixel (in i32:
        // windows past 2^24 pixels are beyond reach anyway).
        let within = |reach: u32| {
            let reach = reach as i32;
            let near = |origin: i32, start: i32, size: u32| match origin.checked_sub(start) {
                Some(offset) if size <= 1 << 24 => {
                    offset <= reach && offset >= size as i32 - 1 - reach
                }
                _ => false,
            };
            near(origin.x, window.top_left.x, window.size.width)
                && near(origin.y, window.top_left.y, window.size.height)
        };
        let reach = Self::REACH;
        // Dithered lanes add thresholds up to 31/32 of a level: an eighth of the reach keeps
        // their roundings under 1/64 of a level, so the sums stay inside their lanes.
        Self::FITS && within(reach) && (!dither || within(reach / 8))
    }

    /// Turns `planes` into their lanes, the first of planes otherwise zero, from their origin:
    /// once per triangle.
    #[inline(always)]
    fn to_lanes(planes: &mut Planes<N>) {
        let (base, dx, dy) = (
            Self::pack(&planes.base),
            Self::pack(&planes.dx),
            Self::pack(&planes.dy),
        );
        planes.keep_first(base as i64, dx as i64, dy as i64);
    }

    /// Channel `k`'s level in the lanes' integer `lanes`.
    #[inline(always)]
    fn level(lanes: u64, k: usize) -> u8 {
        let low = Self::end(k) - Self::BITS[k];
        let word = if low >= 32 {
            (lanes >> 32) as u32
        } else {
            lanes as u32
        };
        ((word >> (low % 32)) & ((1 << Self::BITS[k]) - 1)) as u8
    }
}

/// Pixels from the planes' origin, each way, within which lanes of `fraction` bits (15 to 17;
/// any, for colour types that do not pack) keep their roundings under 1/7 of a level (see
/// [`PackedShader`]).
const fn reach(fraction: u32) -> u32 {
    let fraction = if fraction > 24 { 24 } else { fraction };
    1 << fraction.saturating_sub(4)
}

impl<C, const N: usize> PixelShader for PackedShader<'_, C, N>
where
    C: ChannelColor<Channels = [u8; N]>,
{
    type Color = C;
    /// The lanes' integer and its step: one addition (two instructions with the carry on
    /// 32-bit cores) moves every channel. Stepped as two words instead, the compiler reached
    /// the pixels of each 4x unrolled trip by offsets from the first, loaded from memory on
    /// Cortex-M0 (measured on `big`: Cortex-M4F 13.6 -> 11.0 instructions per pixel, Cortex-M0
    /// 20.7 -> 20.0; x86-64 8.3 -> 9.6, within its budget).
    type State = (u64, u64);

    #[inline(always)]
    fn start(&self, x: i32, y: i32) -> Self::State {
        (self.0.first_at(x, y) as u64, self.1)
    }

    #[inline(always)]
    fn next(&self, state: &mut Self::State) -> C {
        Self::next_color(state)
    }
}

impl<C, const N: usize> PackedShader<'_, C, N>
where
    C: ChannelColor<Channels = [u8; N]>,
{
    /// The colour of the lanes `lanes`; then the lanes one pixel right.
    #[inline(always)]
    fn next_color((lanes, step): &mut (u64, u64)) -> C {
        let channels = per_channel!(N, |k| Self::level(*lanes, k));
        *lanes = lanes.wrapping_add(*step);
        C::from_channels(channels)
    }
}

/// [`PackedShader`]'s colours from lanes that carry a depth plane beside them
/// ([`Painter::carry_depth`]), for a span whose caller has moved both planes to its start
/// (reading the depth there): the span loop moves nothing.
struct CarriedLanes<'a, C, const N: usize>(&'a TrackedPlanes<N>, u64, PhantomData<C>);

impl<C, const N: usize> PixelShader for CarriedLanes<'_, C, N>
where
    C: ChannelColor<Channels = [u8; N]>,
{
    type Color = C;
    type State = (u64, u64);

    #[inline(always)]
    fn start(&self, _x: i32, _y: i32) -> Self::State {
        (self.0.first_here() as u64, self.1)
    }

    #[inline(always)]
    fn next(&self, state: &mut Self::State) -> C {
        PackedShader::<C, N>::next_color(state)
    }
}

/// Dithered colours along a span from the lanes of [`PackedShader`] (planes without the
/// half-level bias): each pixel's lanes plus its [`BAYER`] thresholds, packed, then its levels
/// read out as the rounded lanes are. Along a row the thresholds repeat every four pixels, so
/// the state carries the lanes with the current pixel's thresholds added and the four steps
/// from one pixel's sum to the next's (the lanes' step plus the change of thresholds), rotated
/// each pixel: unrolled four times, the rotation costs nothing and a pixel costs what a rounded
/// one does but for its step's load (measured on `big` when the dithered lanes came in:
/// Cortex-M0 28.14 -> 19.28 instructions per pixel, 1.12 times rounded lanes; Cortex-M4F
/// 19.77 -> 12.89, 1.22 times).
///
/// Within an eighth of the lanes' [`reach`] of the planes' origin (512 pixels for `Rgb565`,
/// 256 for `Rgb666`) a lane is within 2^-f (1 + 2^(f - 6)) <= 1/64 + 2^-15 of a level of the
/// exact value, so the sum with a threshold (1/32 to 31/32) stays inside its lane, and each
/// level is the exact value plus its threshold rounded down, or, within that distance of a
/// level, the one beside it. Farther windows dither in 16.16 ([`GouraudShader`]).
///
/// Along a row of the pattern every other step is the same (the Bayer rows go up and down by
/// the same amount, 8 of 16 levels, from each even column to the next odd one), so a span
/// known to start on an even column (`EVEN`) steps by `[p, q, p, r]` and one on an odd column
/// (`ODD`) by `[q, p, r, p]`: the span loop then holds three steps, not four (M4F: six stack
/// loads per four pixels before; 12.31 instructions per pixel on `big` with the two loops,
/// 1.17 times rounded lanes). `ANY` takes the four from the table: Cortex-M0 keeps one loop
/// (flash).
struct DitheredLanes<'a, C, const N: usize, const START: u8>(
    &'a TrackedPlanes<N>,
    u64,
    PhantomData<C>,
);

/// [`DitheredLanes`] spans from any column.
const ANY: u8 = 0;
/// [`DitheredLanes`] spans from an even column.
const EVEN: u8 = 1;
/// [`DitheredLanes`] spans from an odd column.
const ODD: u8 = 2;

impl<C, const N: usize, const START: u8> DitheredLanes<'_, C, N, START>
where
    C: ChannelColor<Channels = [u8; N]>,
{
    /// The thresholds of each pixel of the 4x4 pattern in every lane, as a lanes' integer.
    const THRESHOLDS: [[u64; 4]; 4] = {
        let mut table = [[0u64; 4]; 4];
        let mut y = 0;
        while y < 4 {
            let mut x = 0;
            while x < 4 {
                let mut k = 0;
                while k < N {
                    // BAYER holds (2t + 1) / 32 in 16.16; a lane has FRACTION bits (15 to 17).
                    let fraction = PackedShader::<C, N>::FRACTION[k];
                    let lane = (BAYER[y][x] as u64) << fraction >> 16;
                    table[y][x] = table[y][x].wrapping_add(lane << PackedShader::<C, N>::STARTS[k]);
                    k += 1;
                }
                x += 1;
            }
            y += 1;
        }
        table
    };

    /// The four changes of the thresholds' integer (wrapping) from pixel `x` of row `y` (taken
    /// mod 4) to the next four pixels: a span starts with one line of the table, rotated for
    /// its first column (measured on `big` against indexing a 4x4 table of changes by the
    /// column plus each step: Cortex-M0 -1.9%, Cortex-M4F -1.6% per dithered pixel, for 384
    /// bytes more; a 4x8 table of each row's changes twice over, read from the column on, and
    /// one table with each start's thresholds beside its changes were slower too).
    const CHANGES: [[[u64; 4]; 4]; 4] = {
        let mut table = [[[0u64; 4]; 4]; 4];
        let mut y = 0;
        while y < 4 {
            let row = &Self::THRESHOLDS[y];
            let mut x = 0;
            while x < 4 {
                let mut k = 0;
                while k < 4 {
                    let from = (x + k) % 4;
                    table[y][x][k] = row[(from + 1) % 4].wrapping_sub(row[from]);
                    k += 1;
                }
                x += 1;
            }
            y += 1;
        }
        table
    };

    /// Checks, when the shader is built, that every other change of a row is the same (from
    /// column 0 as from column 2, from 1 as from 3), which the `EVEN` and `ODD` starts rely on.
    const ALTERNATING: () = {
        let mut y = 0;
        while y < 4 {
            let mut x = 0;
            while x < 4 {
                let c = &Self::CHANGES[y][x];
                assert!(if x % 2 == 0 {
                    c[0] == c[2]
                } else {
                    c[1] == c[3]
                });
                x += 1;
            }
            y += 1;
        }
    };
}

impl<C, const N: usize, const START: u8> PixelShader for DitheredLanes<'_, C, N, START>
where
    C: ChannelColor<Channels = [u8; N]>,
{
    type Color = C;
    /// The lanes plus the current pixel's thresholds, and the steps to the next four pixels'.
    type State = (u64, [u64; 4]);

    #[inline(always)]
    fn start(&self, x: i32, y: i32) -> Self::State {
        let row = (y & 3) as usize;
        let column = (x & 3) as usize;
        let lanes = (self.0.first_at(x, y) as u64).wrapping_add(Self::THRESHOLDS[row][column]);
        let [s0, s1, s2, s3] = Self::CHANGES[row][column].map(|change| self.1.wrapping_add(change));
        let () = Self::ALTERNATING;
        let steps = match START {
            EVEN => [s0, s1, s0, s3],
            ODD => [s0, s1, s2, s1],
            _ => [s0, s1, s2, s3],
        };
        (lanes, steps)
    }

    #[inline(always)]
    fn next(&self, (lanes, steps): &mut Self::State) -> C {
        let channels = per_channel!(N, |k| PackedShader::<C, N>::level(*lanes, k));
        *lanes = lanes.wrapping_add(steps[0]);
        // Spelled out: `rotate_left` is a call to the slice rotation.
        *steps = [steps[1], steps[2], steps[3], steps[0]];
        C::from_channels(channels)
    }
}

drawable_style!([C, const N: usize] GouraudStyle<C> where C: ChannelColor<Channels = [u8; N]>);
