//! Texture mapping: texels sampled at interpolated texture coordinates, optionally tinted by
//! Gouraud-interpolated colours.

use embedded_graphics::{draw_target::DrawTarget, geometry::Point, primitives::Rectangle};
use fixed::types::I16F16;

use super::{
    ChannelColor, TriangleStyle,
    paint::{PaintVisitor, Painter, drawable_style, stored},
    spans::{PixelShader, shade_span},
};
use crate::{
    coverage::{FillRule, Span},
    geometry::Shape,
    interpolate::{AreaMemo, PerspectivePlanes, Planes, TrackedPlanes},
    setup::lane::mul_small,
    texture::{
        Axis, COORDINATE_BITS, Filter, Narrow, Perspective, RAW_SHIFT, Scaled, TexelSource, Wrap,
        Wrapped,
    },
    unroll::per_channel,
};

/// Fills a triangle with a texture: each pixel takes the texel (or bilinear blend of texels)
/// at its texture coordinate, interpolated from the vertices' coordinates.
///
/// Coordinates are in texels, texel `(i, j)` centred on `(i, j)` (see [`crate::texture`]);
/// they are interpolated with 46 fraction bits from plane equations set up once per triangle,
/// and stepped along each span by one addition per coordinate: no division per pixel.
///
/// [`Filter::Nearest`] picks the texel containing a coordinate at or above the exact
/// (rational) interpolated one, rounding half up, and less than 2^-12 texel above it: for
/// textures up to 512 texels a side, spans inside the texture step 32-bit coordinates with 22
/// fraction bits, started up to the span's length in 2^-22 texel above the 64-bit ones (spans
/// under 1,024 pixels; longer ones, and larger textures, are exact as below). So the texel is
/// the exact one unless the exact coordinate lies that close below a texel boundary: ties,
/// integer translations and the identity mapping are exact. The 64-bit coordinates alone pick
/// exactly the texel containing the exact coordinate for every triangle drawn into a window up
/// to 2048 x 2048 whose area is below 2^18 pixels (precisely, while
/// `(2 * width + height + 4) * 2 * area < 2^30`); beyond, within 2^-30 texel of exact.
/// [`Filter::Bilinear`] (whose coordinates are stepped alike) is within one level of the exact
/// blend in every channel. Power-of-two textures repeat by masking; other sizes repeat with one
/// division per span.
///
/// [`TextureStyle::with_modulation`] multiplies the texels by colours interpolated between the
/// vertices, for lit or tinted textures.
///
/// # Examples
///
/// A 2 x 2 checker texture stretched over a 4 x 4 square:
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
/// use trirast::{texture::Texels, TextureStyle, Triangle};
///
/// let texels = [BinaryColor::On, BinaryColor::Off, BinaryColor::Off, BinaryColor::On];
/// let texture = Texels::new(&texels, 2, 2)?;
/// let (a, b, c, d) = (Point::new(0, 0), Point::new(4, 0), Point::new(4, 4), Point::new(0, 4));
/// // Texel coordinates at the corners: half a texel out, so each texel covers 2 x 2 pixels.
/// let at = |p: Point| [p.x, p.y].map(|t| fixed::types::I16F16::from_num(t) / 2 - fixed::types::I16F16::from_num(0.25));
/// let mut display = MockDisplay::new();
/// for (p, q, r) in [(a, b, c), (a, c, d)] {
///     Triangle::new(p, q, r)
///         .into_styled(TextureStyle::new(texture, [at(p), at(q), at(r)]))
///         .draw(&mut display)
///         .unwrap();
/// }
/// display.assert_pattern(&[
///     "##..", //
///     "##..",
///     "..##",
///     "..##",
/// ]);
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Copy, Clone, Debug)]
pub struct TextureStyle<T: TexelSource> {
    /// The texels.
    pub texture: T,
    /// The texture coordinates `[u, v]` of each vertex, in texels, in the triangle's vertex
    /// order.
    pub coordinates: [[I16F16; 2]; 3],
    /// How texels are sampled; [`Filter::Nearest`] by default.
    pub filter: Filter,
    /// What coordinates outside the texture address; [`Wrap::Clamp`] by default.
    pub wrap: Wrap,
    /// Colours per vertex multiplying the texels (white leaves them unchanged); none by
    /// default.
    pub modulation: Option<[T::Color; 3]>,
    /// Which boundary pixels belong to the triangle; [`FillRule::TopLeft`] by default.
    pub fill_rule: FillRule,
    /// Perspective-correct mapping, with each vertex's `w`; none (affine on screen) by
    /// default.
    pub perspective: Option<Perspective>,
}

impl<T: TexelSource> TextureStyle<T> {
    /// A style mapping `texture` with texture coordinates `[u, v]` per vertex, in texels.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Rgb565;
    /// use fixed::types::I16F16;
    /// use trirast::{texture::{Filter, Texels}, TextureStyle};
    ///
    /// let pixels = [Rgb565::default(); 16 * 16];
    /// let texture = Texels::new(&pixels, 16, 16)?;
    /// let zero = I16F16::ZERO;
    /// let side = I16F16::from_num(16);
    /// let style = TextureStyle::new(texture, [[zero, zero], [side, zero], [zero, side]]);
    /// assert_eq!(style.filter, Filter::Nearest);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(texture: T, coordinates: [[I16F16; 2]; 3]) -> Self {
        Self {
            texture,
            coordinates,
            filter: Filter::Nearest,
            wrap: Wrap::Clamp,
            modulation: None,
            fill_rule: FillRule::TopLeft,
            perspective: None,
        }
    }

    /// A style mapping `texture` with whole-texel coordinates per vertex, saturated to the
    /// `I16F16` range.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use fixed::types::I16F16;
    /// use trirast::{texture::Texels, TextureStyle};
    ///
    /// let pixels = [Gray8::new(0); 8 * 8];
    /// let texture = Texels::new(&pixels, 8, 8)?;
    /// let style = TextureStyle::from_points(texture, [Point::new(0, 0), Point::new(8, 0), Point::new(8, 8)]);
    /// assert_eq!(style.coordinates[1], [I16F16::from_num(8), I16F16::ZERO]);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_points(texture: T, points: [Point; 3]) -> Self {
        const fn texels(t: i32) -> I16F16 {
            let t = if t < i16::MIN as i32 {
                i16::MIN as i32
            } else if t > i16::MAX as i32 {
                i16::MAX as i32
            } else {
                t
            };
            I16F16::from_bits(t << 16)
        }
        let [a, b, c] = points;
        Self::new(
            texture,
            [
                [texels(a.x), texels(a.y)],
                [texels(b.x), texels(b.y)],
                [texels(c.x), texels(c.y)],
            ],
        )
    }

    /// The same style with another filter.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use trirast::{texture::{Filter, Texels}, TextureStyle};
    ///
    /// let pixels = [Gray8::new(0); 4];
    /// let style = TextureStyle::from_points(Texels::new(&pixels, 2, 2)?, [Point::zero(); 3])
    ///     .with_filter(Filter::Bilinear);
    /// assert_eq!(style.filter, Filter::Bilinear);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub const fn with_filter(mut self, filter: Filter) -> Self {
        self.filter = filter;
        self
    }

    /// The same style with another wrap mode.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use trirast::{texture::{Texels, Wrap}, TextureStyle};
    ///
    /// let pixels = [Gray8::new(0); 4];
    /// let style = TextureStyle::from_points(Texels::new(&pixels, 2, 2)?, [Point::zero(); 3])
    ///     .with_wrap(Wrap::Repeat);
    /// assert_eq!(style.wrap, Wrap::Repeat);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub const fn with_wrap(mut self, wrap: Wrap) -> Self {
        self.wrap = wrap;
        self
    }

    /// The same style with the texels multiplied by `colors`, one per vertex, interpolated as
    /// in Gouraud shading: each channel becomes `texel * color / max`, rounded. White leaves
    /// the texture unchanged, black makes it black.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
    /// use trirast::{texture::Texels, Framebuffer, TextureStyle, Triangle};
    ///
    /// let texels = [Rgb565::WHITE; 4];
    /// let (a, b, c) = (Point::new(0, 0), Point::new(16, 0), Point::new(0, 16));
    /// let style = TextureStyle::from_points(Texels::new(&texels, 2, 2)?, [a, b, c])
    ///     .with_modulation([Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE]);
    /// let mut pixels = [Rgb565::BLACK; 16 * 16];
    /// let mut display = Framebuffer::new(&mut pixels, 16, 16)?;
    /// Triangle::new(a, b, c).into_styled(style).draw(&mut display).unwrap();
    /// assert_eq!(display.pixel(a), Some(Rgb565::RED));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub const fn with_modulation(mut self, colors: [T::Color; 3]) -> Self {
        self.modulation = Some(colors);
        self
    }

    /// The same style mapped perspective-correct, with each vertex's `w` in `perspective`: a
    /// face seen at an angle then shows its texture as a camera would, instead of bending
    /// it along the triangle's diagonal. See [`Perspective`] for the accuracy.
    ///
    /// # Examples
    ///
    /// A floor receding from the viewer: its far edge (`w` = 4) is four times as far as its
    /// near one. The texture's middle row, `v` = 2, lands a fifth of the way down from the
    /// far edge, where a camera sees it, not halfway as the affine mapping puts it.
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use fixed::types::I16F16;
    /// use trirast::{texture::{Perspective, Texels}, Framebuffer, TextureStyle, Triangle};
    ///
    /// // Four rows of texels: dark, dark, light, light.
    /// let texels = [0, 0, 0, 0, 255, 255, 255, 255].map(Gray8::new);
    /// let texture = Texels::new(&texels, 2, 4)?;
    /// let uv = |u: f32, v: f32| [I16F16::from_num(u), I16F16::from_num(v)];
    /// let (near, far) = (I16F16::ONE, I16F16::from_num(4));
    /// let (mut pixels, width) = ([Gray8::BLACK; 40 * 40], 40);
    /// let mut display = Framebuffer::new(&mut pixels, width, 40)?;
    /// let (a, b, c) = (Point::new(0, 0), Point::new(40, 0), Point::new(0, 40));
    /// let style = TextureStyle::new(texture, [uv(0.0, -0.5), uv(2.0, -0.5), uv(0.0, 3.5)])
    ///     .with_perspective(Perspective::new([far, far, near]));
    /// Triangle::new(a, b, c).into_styled(style).draw(&mut display).unwrap();
    /// // v = 1.5 (the dark-light boundary) at a fifth of the height: rows 0 to 7 dark.
    /// assert_eq!(display.pixel(Point::new(1, 7)), Some(Gray8::new(0)));
    /// assert_eq!(display.pixel(Point::new(1, 9)), Some(Gray8::new(255)));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub const fn with_perspective(mut self, perspective: Perspective) -> Self {
        self.perspective = Some(perspective);
        self
    }

    /// The same style with another fill rule.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use trirast::{texture::Texels, FillRule, TextureStyle};
    ///
    /// let pixels = [Gray8::new(0); 4];
    /// let style = TextureStyle::from_points(Texels::new(&pixels, 2, 2)?, [Point::zero(); 3])
    ///     .with_fill_rule(FillRule::Inclusive);
    /// assert_eq!(style.fill_rule, FillRule::Inclusive);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub const fn with_fill_rule(mut self, fill_rule: FillRule) -> Self {
        self.fill_rule = fill_rule;
        self
    }
}

impl<T, const M: usize> TriangleStyle for TextureStyle<T>
where
    T: TexelSource + Copy,
    T::Color: ChannelColor<Channels = [u8; M]>,
{
    type Color = T::Color;

    #[inline]
    fn fill_rule(&self) -> FillRule {
        self.fill_rule
    }

    #[inline(always)]
    fn paint<G: Shape, V: PaintVisitor<T::Color>>(
        &self,
        triangle: &G,
        window: &Rectangle,
        visitor: V,
    ) -> Option<V::Output> {
        // The texture's size first: for a texture type no value has (`NoTexture`) this point
        // is unreachable, and the compiler drops the set-ups below with it (out-of-line calls
        // that it must otherwise keep: 1.8 KB on Cortex-M0 in a band renderer without
        // textures). For other textures a read whose value goes unused.
        let _ = self.texture.size();
        // Perspective planes stay here, lent to the painter, which is moved around by value;
        // borrowed where they were returned (moving them out of the option is a copy).
        let corrected = self.perspective.filter(|p| !p.is_affine());
        // The coordinates', the tint's and a depth pass's set-ups share the area's reciprocal:
        // through the visitor's memo, or with a tint but no depth pass, a memo of its own.
        let own = AreaMemo::new();
        let memo = visitor
            .area_memo()
            .or_else(|| self.modulation.is_some().then_some(&own));
        let perspective_planes =
            corrected.and_then(|p| new_perspective_planes(triangle, self, p, window, memo));
        let (coordinates, perspective) = match (&perspective_planes, corrected) {
            (Some(planes), _) => (Planes::zero(), Some(planes)),
            // Degenerate.
            (None, Some(_)) => return None,
            (None, None) => (coordinate_planes(triangle, self, window, memo)?, None),
        };
        let tint = match self.modulation {
            Some(colors) => Some(tint_planes(triangle, colors, window, memo)?),
            None => None,
        };
        let mut painter = TexturedPainter::new(self, coordinates, perspective, tint);
        // Runs of a triangle mapped within its texture need no test. Not where anti-aliasing
        // paints edge pixels whose samples lie outside the triangle, nor for perspective
        // runs (tested per sub-span) and bilinear ones: a triangle mapped onto the whole
        // texture reaches past the last texel centre that bilinear reads inside, so the
        // vertices' test would cost its usual triangle and spare it nothing (measured +2.7%
        // per small bilinear triangle on Cortex-M0).
        if !V::EDGE_PIXELS
            && perspective.is_none()
            && painter.runs == Runs::Tested
            && !painter.bilinear
            && painter.vertices_inside(self)
        {
            painter.runs = Runs::Inside;
        }
        // A painter type of its own for styles with a perspective, so that firmware whose
        // styles have none (known where the style is built) links no perspective span code:
        // chosen per span only, it stayed linked (6 KB on Cortex-M0). Styles with one take
        // the same painter when their `w` are equal, so one row walk serves both.
        Some(if self.perspective.is_some() {
            visitor.visit(PerspectivePainter {
                painter,
                perspective,
            })
        } else {
            visitor.visit(painter)
        })
    }
}

drawable_style!([T, const M: usize] TextureStyle<T> where T: TexelSource + Copy, T::Color: ChannelColor<Channels = [u8; M]>);

/// The planes of the texture coordinates, biased so that truncating them rounds as the filter
/// needs, and lifted so that they never fall below the exact coordinate.
#[inline(always)]
fn coordinate_planes<G, T>(
    triangle: &G,
    style: &TextureStyle<T>,
    window: &Rectangle,
    memo: Option<&AreaMemo>,
) -> Option<Planes<2, COORDINATE_BITS>>
where
    G: Shape,
    T: TexelSource,
    T::Color: ChannelColor,
{
    let (values, bias) = (raw_coordinates(style), rounding_bias(style));
    let mut planes = triangle.planes_in(values, bias, window, memo)?;
    // Gradients are rounded to 2^-46, so a value `dx` pixels across and `dy` down from the
    // reference (both within the window), then `k` pixels along a span, is off by at most
    // (|dx| + |dy| + k + 1) / 2 units. Adding that much keeps every value at or above the
    // exact one and less than (2 * width + height + 2) units over, which is below the
    // distance from any exact coordinate to the next texel boundary it does not lie on
    // (1 / (2^16 * 2 * area) texels) under the documented size limit: truncation then picks
    // the exact texel, ties included.
    let lift = i64::from(window.size.width) + i64::from(window.size.height / 2) + 2;
    for base in &mut planes.base {
        *base = base.wrapping_add(lift);
    }
    Some(planes)
}

/// The texture coordinates of `style`'s vertices, raw 16.16.
#[inline(always)]
fn raw_coordinates<T: TexelSource>(style: &TextureStyle<T>) -> [[i64; 2]; 3] {
    style
        .coordinates
        .map(|[u, v]| [i64::from(u.to_bits()), i64::from(v.to_bits())])
}

/// What `style`'s filter adds to coordinates (raw 16.16) so that truncating them rounds as it
/// needs: nearest takes floor(u + 1/2); bilinear splits u into floor and a fraction truncated
/// to the weight bits, so half a weight step rounds it to nearest.
#[inline(always)]
fn rounding_bias<T: TexelSource>(style: &TextureStyle<T>) -> i64
where
    T::Color: ChannelColor,
{
    match style.filter {
        Filter::Nearest => 1 << 15,
        Filter::Bilinear => 1 << (15 - T::Color::WEIGHT_BITS),
    }
}

/// The perspective planes of the texture coordinates, rounding bias included.
#[inline(always)]
fn new_perspective_planes<G, T>(
    triangle: &G,
    style: &TextureStyle<T>,
    perspective: Perspective,
    window: &Rectangle,
    memo: Option<&AreaMemo>,
) -> Option<PerspectivePlanes<3, 2>>
where
    G: Shape,
    T: TexelSource,
    T::Color: ChannelColor,
{
    let (values, bias) = (raw_coordinates(style), rounding_bias(style));
    let sub_span = perspective.sub_span.pixels();
    PerspectivePlanes::new(
        triangle,
        values,
        bias,
        perspective.w,
        sub_span,
        window,
        memo,
    )
}

/// The planes of the modulation factors: each channel as a 16.16 fraction of its maximum.
#[inline(always)]
fn tint_planes<G, C, const M: usize>(
    triangle: &G,
    colors: [C; 3],
    window: &Rectangle,
    memo: Option<&AreaMemo>,
) -> Option<Planes<M>>
where
    G: Shape,
    C: ChannelColor<Channels = [u8; M]>,
{
    let max = C::MAX_CHANNELS;
    let values = colors.map(|c| {
        let channels = c.channels();
        core::array::from_fn(|k| {
            let m = i64::from(max[k].max(1));
            (i64::from(channels[k]) * 65536 + m / 2) / m
        })
    });
    // From the first vertex when the triangle is small, as Gouraud colours.
    triangle.planes(values, 0, window.top_left, memo)
}

/// The painter of a textured triangle, one type for every filter, wrap, modulation and
/// mapping: each run (or, in perspective, each sub-span of a run) picks the span loop for its
/// case. Runs whose coordinates stay inside the texture (checked at both ends; coordinates
/// are monotonic along a row, and stepped linearly between the ends) are sampled with no
/// wrapping or clamping, the others with the style's addressing.
struct TexturedPainter<'a, T, const M: usize> {
    texture: T,
    /// The coordinates' planes, when affine.
    coordinates: TrackedPlanes<2, COORDINATE_BITS>,
    /// The planes of `1 / w` and the coordinates over `w`, when perspective-correct: divided
    /// at the ends of sub-spans. Borrowed, so that the painter stays small to move.
    perspective: Option<&'a PerspectivePlanes<3, 2>>,
    tint: Option<Planes<M>>,
    bilinear: bool,
    /// How runs that leave the texture are addressed.
    addressing: Addressing,
    /// Coordinates (in 2^-46 texels) below these, and not negative, need no addressing.
    limits: [i64; 2],
    /// The same in raw 16.16, for perspective sub-spans.
    sub_span_limits: [u32; 2],
    /// Which runs step [`Scaled`] coordinates (by these steps) rather than go through the
    /// addressing.
    runs: Runs,
    scaled_steps: [u32; 2],
}

/// How a [`TexturedPainter`] chooses between its [`Scaled`] span loops and the addressed ones.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
enum Runs {
    /// Every run addressed: textures over [`Scaled::SIDE`] texels a side.
    Addressed,
    /// Runs inside the texture scaled, the others addressed: each run tested.
    Tested,
    /// Every run inside the texture (see [`TexturedPainter::vertices_inside`]): none tested.
    Inside,
}

impl<'a, T, const M: usize> TexturedPainter<'a, T, M>
where
    T: TexelSource + Copy,
    T::Color: ChannelColor<Channels = [u8; M]>,
{
    #[inline(always)]
    fn new(
        style: &TextureStyle<T>,
        coordinates: Planes<2, COORDINATE_BITS>,
        perspective: Option<&'a PerspectivePlanes<3, 2>>,
        tint: Option<Planes<M>>,
    ) -> Self {
        let texture = style.texture;
        let size = texture.size();
        let bilinear = style.filter == Filter::Bilinear;
        // Bilinear also reads the texel to the right and below.
        let reach = |side: u32| {
            let texels = if bilinear { side - 1 } else { side };
            i64::from(texels) << COORDINATE_BITS
        };
        // Affine steps are the same for every run: addressed once here.
        let [du, dv] = coordinates.dx;
        let (u, v) = match style.wrap {
            Wrap::Clamp => (Wrapped::clamp(size.width), Wrapped::clamp(size.height)),
            Wrap::Repeat => (Wrapped::repeat(size.width), Wrapped::repeat(size.height)),
        };
        let addressing = Addressing {
            u,
            v,
            du: u.step(du),
            dv: v.step(dv),
        };
        let scaled = size.width.max(size.height) <= Scaled::SIDE;
        // Affine runs in `Scaled` coordinates, lifted by less than 2^-12 texel, must end that
        // far inside (others need no addressing just short of the edge). Perspective
        // sub-spans step unlifted 16.16 coordinates: their limits keep the whole reach.
        let margin = if scaled {
            1 << (COORDINATE_BITS - 12)
        } else {
            0
        };
        // Not below zero: bilinear reaches nothing inside a one-texel side.
        let affine_reach = |side: u32| (reach(side) - margin).max(0);
        Self {
            texture,
            coordinates: TrackedPlanes::new(coordinates),
            perspective,
            tint,
            bilinear,
            addressing,
            limits: [affine_reach(size.width), affine_reach(size.height)],
            sub_span_limits: [reach(size.width), reach(size.height)]
                .map(|limit| (limit >> RAW_SHIFT) as u32),
            runs: if scaled {
                Runs::Tested
            } else {
                Runs::Addressed
            },
            scaled_steps: [Scaled.step(du), Scaled.step(dv)],
        }
    }

    /// Whether the coordinates of every pixel the triangle covers lie inside the texture, as
    /// [`TexturedPainter::inside`] tests a run: true when the vertices' do, with a margin. A
    /// covered pixel's exact coordinates are a mean of the vertices' (its sample lies in the
    /// closed triangle), and its planes' values are at or above them by less than
    /// `2 * width + height + 2` units of 2^-46 texel (see `coordinate_planes`), less than 12
    /// raw 16.16 units for any window. So a triangle mapped within its texture, the usual
    /// case, tests nothing per run; one that tiles it tests every run. Not for painters asked
    /// for pixels outside the triangle.
    #[inline(always)]
    fn vertices_inside(&self, style: &TextureStyle<T>) -> bool {
        // Raw values up to `end` lie 29 raw units under the texture's reach: 16 units of the
        // runs' margin (`limits`) and 13, more than the slack.
        let [u_reach, v_reach] = self.sub_span_limits;
        if u_reach < 29 || v_reach < 29 {
            return false;
        }
        let ends = [u_reach - 29, v_reach - 29];
        let bias = rounding_bias(style) as i32;
        // Raw 16.16 plus the bias (half a texel at most): negative ones wrap above every end,
        // as do those that wrap past `i32::MAX`. The three vertices written out: with an
        // iterator's `all` the test cost 7% more per small nearest triangle at `opt-level =
        // "s"` (a loop of calls there).
        let [[u0, v0], [u1, v1], [u2, v2]] = style.coordinates;
        let highest = |a: I16F16, b: I16F16, c: I16F16| {
            let at = |c: I16F16| c.to_bits().wrapping_add(bias) as u32;
            at(a).max(at(b)).max(at(c))
        };
        highest(u0, u1, u2) <= ends[0] && highest(v0, v1, v2) <= ends[1]
    }

    /// Shades `run` with the span loop of this filter and modulation, addressed by `axes`,
    /// from coordinates `start` (in the axes' terms) and modulation factors `tint` (those of the
    /// run's start when `None`).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn shade<A, D, const FILTER: u8, const TINT: u8>(
        &self,
        (u, v): (A, A),
        (du, dv): (A::Coord, A::Coord),
        start: (A::Coord, A::Coord),
        tint: Option<[u32; M]>,
        run: Span,
        offset: Point,
        target: &mut D,
    ) -> Result<(), D::Error>
    where
        A: Axis,
        D: DrawTarget<Color = T::Color>,
    {
        // Everything the loop needs at the run's start, from screen coordinates; then the run
        // where the target stores it, so that the offset is not live in the loop.
        let tint = match (TINT != NO, &self.tint) {
            (true, Some(planes)) => (tint.unwrap_or_else(|| planes.at(run.x, run.y)), planes.step),
            _ => ([0; M], [0; M]),
        };
        let shader = TexturedShader::<_, _, M, FILTER, TINT> {
            sampler: Sampler {
                texture: self.texture,
                u,
                v,
                du,
                dv,
            },
            start,
            tint,
            tinted: self.tint.is_some(),
            bilinear: self.bilinear,
        };
        let area = stored(run, offset);
        let run = Span {
            x: area.top_left.x,
            y: area.top_left.y,
            len: run.len,
        };
        // By value: borrowed, the shader was stored to memory for every run (measured: 4 to
        // 5% of a small or mesh textured triangle on Cortex-M0, 2 to 6% on M4F since
        // 2026-11-29; until then M4F's nearest loop lost 11% a pixel by value).
        shade_span(shader, run, Point::zero(), target)
    }

    /// True when coordinates from `start` to `start + across` (2^-46 texels; `across` is
    /// `None` if out of range) stay inside the texture.
    #[inline(always)]
    fn inside(&self, start: [i64; 2], across: [Option<i64>; 2]) -> bool {
        // Unsigned: negative values wrap above every limit, so one comparison each. A start
        // inside is below 2^61, so the end, wrapped to 64 bits, is below the limit exactly
        // when the sum is: no overflow test.
        /// One axis (a function, not a closure: at `opt-level = "s"` a closure called twice
        /// stayed a call).
        #[inline(always)]
        fn on_axis(limit: i64, start: i64, across: Option<i64>) -> bool {
            let (limit, start) = (limit as u64, start as u64);
            start < limit && across.is_some_and(|d| start.wrapping_add(d as u64) < limit)
        }
        on_axis(self.limits[0], start[0], across[0]) && on_axis(self.limits[1], start[1], across[1])
    }

    /// Shades a run that leaves the texture: a loop per filter, each serving both wrap modes
    /// (`Wrapped`) and both modulations, which it reads per pixel. Out of line: rarer than
    /// runs inside (but most runs of a tiled texture), and flash matters more.
    #[inline(never)]
    fn shade_addressed<D>(
        &self,
        run: Span,
        start: [i64; 2],
        steps: [i64; 2],
        tint: Option<[u32; M]>,
        offset: Point,
        target: &mut D,
    ) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = T::Color>,
    {
        // Affine steps were addressed with the triangle; perspective ones change per
        // sub-span.
        let Addressing { u, v, du, dv } = self.addressing;
        let steps = if self.perspective.is_none() {
            (du, dv)
        } else {
            (u.step(steps[0]), v.step(steps[1]))
        };
        self.shade_filtered((u, v), steps, start, tint, run, offset, target)
    }

    /// Shades an addressed run with this filter's loop, which reads the modulation per pixel.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn shade_filtered<A, D>(
        &self,
        axes: (A, A),
        steps: (A::Coord, A::Coord),
        start: [i64; 2],
        tint: Option<[u32; M]>,
        run: Span,
        offset: Point,
        target: &mut D,
    ) -> Result<(), D::Error>
    where
        A: Axis,
        D: DrawTarget<Color = T::Color>,
    {
        let start = (axes.0.coord(start[0]), axes.1.coord(start[1]));
        if self.bilinear {
            self.shade::<_, _, YES, EITHER>(axes, steps, start, tint, run, offset, target)
        } else {
            self.shade::<_, _, NO, EITHER>(axes, steps, start, tint, run, offset, target)
        }
    }

    /// Paints `run` in perspective: sub-span by sub-span, each stepped linearly between the
    /// exact coordinates at its ends ([`PerspectivePlanes::next_sub_span`]). Sub-spans inside
    /// the texture step their raw 16.16 coordinates in 32 bits ([`Narrow`]), the others go
    /// through the style's addressing. One walk per filter and modulation, chosen per run:
    /// each keeps its one span loop's registers.
    #[inline(never)]
    fn paint_perspective<D>(
        &self,
        planes: &PerspectivePlanes<3, 2>,
        run: Span,
        offset: Point,
        target: &mut D,
    ) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = T::Color>,
    {
        let (p, o) = (planes, offset);
        // Nearest: bilinear runs go to `paint_perspective_bilinear` (see `PerspectivePainter`).
        if self.tint.is_some() {
            self.paint_sub_spans::<_, NO, YES>(p, run, o, target)
        } else {
            self.paint_sub_spans::<_, NO, NO>(p, run, o, target)
        }
    }

    /// [`TexturedPainter::paint_perspective`] bilinear, whose pixels cost ten times more: one
    /// walk, modulation chosen per sub-span. Out of line, so that the nearest walks keep their
    /// registers.
    #[inline(never)]
    fn paint_perspective_bilinear<D>(
        &self,
        planes: &PerspectivePlanes<3, 2>,
        run: Span,
        offset: Point,
        target: &mut D,
    ) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = T::Color>,
    {
        self.paint_sub_spans::<_, YES, EITHER>(planes, run, offset, target)
    }

    /// [`TexturedPainter::paint_perspective`] with one filter and modulation.
    #[inline(always)]
    fn paint_sub_spans<D, const FILTER: u8, const TINT: u8>(
        &self,
        planes: &PerspectivePlanes<3, 2>,
        run: Span,
        offset: Point,
        target: &mut D,
    ) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = T::Color>,
    {
        let tint = self.tint.as_ref().map(|t| (t.at(run.x, run.y), t.step));
        // Nearest pixels are cheap enough for the call per sub-span to show; from Cortex-M3 up
        // bilinear ones gain too.
        let inline = FILTER == NO || crate::arch::DIVIDES;
        let mut sub_spans = planes.sub_spans(run.x, run.y, run.len, inline);
        while sub_spans.left > 0 {
            let sub_span = planes.next_sub_span(&mut sub_spans, inline);
            let tint = tint.map(|(at, step)| {
                let pixels = sub_span.x.wrapping_sub(run.x) as u32;
                per_channel!(M, |k| at[k].wrapping_add(step[k].wrapping_mul(pixels)))
            });
            let stretch = Span {
                x: sub_span.x,
                y: run.y,
                len: sub_span.len,
            };
            // Inside when both ends are: raw 16.16, negative ones wrapping to the top.
            let [u_limit, v_limit] = self.sub_span_limits;
            let inside = (sub_span.start[0] as u32) < u_limit
                && (sub_span.end[0] as u32) < u_limit
                && (sub_span.start[1] as u32) < v_limit
                && (sub_span.end[1] as u32) < v_limit;
            if inside {
                let raw = |a: [i32; 2]| (a[0] as u32, a[1] as u32);
                let (start, steps) = (raw(sub_span.start), raw(sub_span.steps));
                let (pair, o) = ((Narrow, Narrow), offset);
                match (TINT, self.tint.is_some()) {
                    (EITHER, false) => {
                        self.shade::<_, _, FILTER, NO>(pair, steps, start, tint, stretch, o, target)
                    }
                    (EITHER, true) => self
                        .shade::<_, _, FILTER, YES>(pair, steps, start, tint, stretch, o, target),
                    _ => self
                        .shade::<_, _, FILTER, TINT>(pair, steps, start, tint, stretch, o, target),
                }?;
            } else {
                let to_coordinate = |a: [i32; 2]| a.map(|a| i64::from(a) << RAW_SHIFT);
                let (start, steps) = (to_coordinate(sub_span.start), to_coordinate(sub_span.steps));
                self.shade_addressed(stretch, start, steps, tint, offset, target)?;
            }
        }
        Ok(())
    }
}

/// `steps * gradient`, or `None` if it might not fit `i64`. One 64 x 16-bit multiply for runs
/// under 2^16 pixels and gradients under 2^47 (two texels per pixel), whose product fits: a
/// checked 64-bit product is a 128-bit one, several library calls per span on Cortex-M0, and
/// even a plain one is three calls there. On Cortex-M0 also for runs under 256 pixels and
/// gradients under 2^55 (a minified texture on a small triangle: measured -11% per small
/// textured triangle there; from Cortex-M3 up the extra test measured 1 to 3% slower).
#[inline(always)]
fn across(steps: u32, gradient: i64) -> Option<i64> {
    let magnitude = gradient.unsigned_abs();
    let fits = if crate::arch::DIVIDES {
        steps < 1 << 16 && magnitude < 1 << 47
    } else {
        steps < 1 << 16 && magnitude < 1 << 47 || steps < 1 << 8 && magnitude < 1 << 55
    };
    if fits {
        let product = mul_small(magnitude as i64, steps); // below 2^63
        Some(if gradient < 0 { -product } else { product })
    } else {
        i64::from(steps).checked_mul(gradient)
    }
}

/// How a textured triangle addresses runs that leave the texture, with the affine per-pixel
/// steps in the addressing's terms (computed once per triangle).
#[derive(Copy, Clone, Debug)]
struct Addressing {
    u: Wrapped,
    v: Wrapped,
    du: i64,
    dv: i64,
}

impl<T, const M: usize> Painter for TexturedPainter<'_, T, M>
where
    T: TexelSource + Copy,
    T::Color: ChannelColor<Channels = [u8; M]>,
{
    type Color = T::Color;

    #[inline]
    fn paint<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = T::Color>,
    {
        self.paint_linear(run, offset, target)
    }
}

/// A [`TexturedPainter`] for a style with a perspective: runs are painted sub-span by
/// sub-span from the `perspective` planes, or linearly where the `w` are equal (`None`).
struct PerspectivePainter<'a, T, const M: usize> {
    painter: TexturedPainter<'a, T, M>,
    perspective: Option<&'a PerspectivePlanes<3, 2>>,
}

impl<T, const M: usize> Painter for PerspectivePainter<'_, T, M>
where
    T: TexelSource + Copy,
    T::Color: ChannelColor<Channels = [u8; M]>,
{
    type Color = T::Color;

    #[inline]
    fn paint<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = T::Color>,
    {
        // Bilinear runs straight to their walk: through `paint_perspective` they paid a
        // second call per run.
        match self.perspective {
            Some(planes) if self.painter.bilinear => self
                .painter
                .paint_perspective_bilinear(planes, run, offset, target),
            Some(planes) => self.painter.paint_perspective(planes, run, offset, target),
            None => self.painter.paint_linear(run, offset, target),
        }
    }
}

impl<T, const M: usize> TexturedPainter<'_, T, M>
where
    T: TexelSource + Copy,
    T::Color: ChannelColor<Channels = [u8; M]>,
{
    /// Paints `run` with coordinates stepped linearly (affine mapping). One out-of-line copy
    /// per target of the two nearest span loops inside the texture; the bilinear ones are
    /// [`TexturedPainter::paint_bilinear`]'s.
    #[inline(never)]
    fn paint_linear<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = T::Color>,
    {
        let planes = &self.coordinates;
        // The coordinates at the run's start, evaluated once for the test and the loop.
        let start = planes.at_exact(run.x, run.y);
        let steps = planes.dx;
        if self.runs != Runs::Inside {
            // On Cortex-M0 written out: -2.5 to -3% per nearest triangle there (and at
            // `opt-level = "s"` the array's `map` stayed a loop); from M3 up the `map`
            // measured 2 to 4% faster.
            let across = if crate::arch::DIVIDES {
                steps.map(|step| across(run.len - 1, step))
            } else {
                [across(run.len - 1, steps[0]), across(run.len - 1, steps[1])]
            };
            if self.runs == Runs::Addressed || !self.inside(start, across) {
                return self.shade_addressed(run, start, steps, None, offset, target);
            }
        }
        let o = offset;
        // In 32 bits, within 2^-12 texel: each coordinate and step rounded down loses less
        // than a unit of `Scaled` (2^-22 texel) a pixel, so starting `len` units up keeps
        // every pixel's coordinate at or above its 64-bit value (itself at or above the exact
        // one, by the lift of the planes) and at most `len` units over it.
        if run.len < 1 << (Scaled::BITS - 12) {
            let first = (
                Scaled.coord(start[0]).wrapping_add(run.len),
                Scaled.coord(start[1]).wrapping_add(run.len),
            );
            let steps = (self.scaled_steps[0], self.scaled_steps[1]);
            let (start, pair) = (first, (Scaled, Scaled));
            if self.bilinear {
                return self.paint_bilinear(run, start, steps, offset, target);
            }
            return if self.tint.is_some() {
                self.shade::<_, _, NO, YES>(pair, steps, start, None, run, o, target)
            } else {
                self.shade::<_, _, NO, NO>(pair, steps, start, None, run, o, target)
            };
        }
        // Textures over `Scaled::SIDE` texels a side, runs of 1,024 pixels and more.
        self.shade_addressed(run, start, steps, None, offset, target)
    }
}

impl<T, const M: usize> TexturedPainter<'_, T, M>
where
    T: TexelSource + Copy,
    T::Color: ChannelColor<Channels = [u8; M]>,
{
    /// Paints `run`, inside the texture, bilinear from [`Scaled`] coordinates `start` stepping
    /// by `steps`. Out of line: the nearest loops keep their registers.
    #[inline(never)]
    fn paint_bilinear<D>(
        &self,
        run: Span,
        start: (u32, u32),
        steps: (u32, u32),
        offset: Point,
        target: &mut D,
    ) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = T::Color>,
    {
        let (pair, o) = ((Scaled, Scaled), offset);
        if self.tint.is_some() {
            self.shade::<_, _, YES, YES>(pair, steps, start, None, run, o, target)
        } else {
            self.shade::<_, _, YES, NO>(pair, steps, start, None, run, o, target)
        }
    }
}

/// A span loop's filter (bilinear or not) and modulation: fixed for the loop, or read per
/// pixel (`EITHER`, for loops that serve every case).
const NO: u8 = 0;
const YES: u8 = 1;
const EITHER: u8 = 2;

/// Whether `choice` holds, given what the style chose at run time.
#[inline(always)]
const fn holds(choice: u8, chosen: bool) -> bool {
    match choice {
        NO => false,
        YES => true,
        _ => chosen,
    }
}

/// A texture with its addressing and the per-pixel coordinate steps: everything the span loop
/// reads, copied into its state so it stays in registers.
#[derive(Copy, Clone, Debug)]
struct Sampler<T, A: Axis> {
    texture: T,
    u: A,
    v: A,
    du: A::Coord,
    dv: A::Coord,
}

impl<T: TexelSource, A: Axis> Sampler<T, A>
where
    T::Color: ChannelColor,
{
    #[inline(always)]
    fn nearest(&self, u: A::Coord, v: A::Coord) -> T::Color {
        self.texture.texel(self.u.nearest(u), self.v.nearest(v))
    }

    #[inline(always)]
    fn bilinear(&self, u: A::Coord, v: A::Coord) -> T::Color {
        let drop = 16 - T::Color::WEIGHT_BITS;
        let (left, right, across) = self.u.linear(u);
        let (top, bottom, down) = self.v.linear(v);
        let texture = &self.texture;
        let corners = texture.quad(left, right, top, bottom);
        T::Color::bilinear(corners, across >> drop, down >> drop)
    }
}

/// The per-pixel shader of a textured triangle.
struct TexturedShader<T, A: Axis, const M: usize, const FILTER: u8, const TINT: u8> {
    sampler: Sampler<T, A>,
    /// Coordinates at the run's first pixel.
    start: (A::Coord, A::Coord),
    /// Modulation factors at the run's first pixel and their steps (zero without).
    tint: ([u32; M], [u32; M]),
    /// The style's modulation, for loops whose `TINT` is `EITHER`.
    tinted: bool,
    /// The style's filter, for loops whose `FILTER` is `EITHER`.
    bilinear: bool,
}

/// Where a span is: texture coordinates and modulation factors, with their steps.
#[derive(Copy, Clone, Debug)]
struct TexturedState<T, A: Axis, const M: usize> {
    sampler: Sampler<T, A>,
    u: A::Coord,
    v: A::Coord,
    tint: [u32; M],
    tint_step: [u32; M],
}

impl<T, A, const M: usize, const FILTER: u8, const TINT: u8> PixelShader
    for TexturedShader<T, A, M, FILTER, TINT>
where
    T: TexelSource + Copy,
    T::Color: ChannelColor<Channels = [u8; M]>,
    A: Axis,
{
    type Color = T::Color;
    type State = TexturedState<T, A, M>;

    const BUFFERED: bool = FILTER != NO;

    #[inline(always)]
    fn start(&self, _x: i32, _y: i32) -> Self::State {
        let (u, v) = self.start;
        let (tint, tint_step) = self.tint;
        TexturedState {
            sampler: self.sampler,
            u,
            v,
            tint,
            tint_step,
        }
    }

    #[inline(always)]
    fn next(&self, state: &mut Self::State) -> T::Color {
        let sampler = &state.sampler;
        let texel = if holds(FILTER, self.bilinear) {
            sampler.bilinear(state.u, state.v)
        } else {
            sampler.nearest(state.u, state.v)
        };
        state.u = sampler.u.advance(state.u, sampler.du);
        state.v = sampler.v.advance(state.v, sampler.dv);
        if holds(TINT, self.tinted) {
            let factors = state.tint;
            state.tint = per_channel!(M, |k| factors[k].wrapping_add(state.tint_step[k]));
            modulate(texel, factors)
        } else {
            texel
        }
    }
}

/// `texel` with each channel multiplied by a 16.16 factor (clamped to 0..=1), rounded.
#[inline(always)]
fn modulate<C, const M: usize>(texel: C, factors: [u32; M]) -> C
where
    C: ChannelColor<Channels = [u8; M]>,
{
    let channels = texel.channels();
    C::from_channels(per_channel!(M, |k| {
        // Interpolation may overshoot 0 or 1 by a unit; a wrapped negative factor is huge.
        let factor = (factors[k] as i32).clamp(0, 1 << 16) as u32;
        ((u32::from(channels[k]) * factor + (1 << 15)) >> 16) as u8
    }))
}

#[cfg(test)]
mod tests {
    #[test]
    fn products_across_runs_are_exact_or_refused() {
        let gradients = [
            0,
            1,
            -1,
            0xFFFF,
            1 << 46,
            -(1 << 46) + 7,
            (1 << 47) - 1,
            -(1 << 47) + 1,
            1 << 47,
            (1 << 55) - 1,
            -(1 << 55) + 1,
            1 << 55,
            -(1 << 55),
            i64::MAX,
            i64::MIN,
        ];
        for steps in [0, 1, 2, 0xFF, 0x100, 0xFFFF, 1 << 16, u32::MAX] {
            for gradient in gradients {
                let exact = i128::from(steps) * i128::from(gradient);
                match super::across(steps, gradient) {
                    Some(p) => assert_eq!(i128::from(p), exact, "{steps} x {gradient}"),
                    None => assert!(i64::try_from(exact).is_err(), "{steps} x {gradient}"),
                }
            }
        }
    }
}
