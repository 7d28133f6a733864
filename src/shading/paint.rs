//! How styles hand their per-triangle painters to the passes that draw them: plain (each span
//! straight to the target) or depth-tested (spans broken where the test fails).
//!
//! A style sets up a [`Painter`] once per triangle (colour planes, texture addressing, ...) and
//! passes it to a [`PaintVisitor`], which walks the triangle's spans and asks the painter to
//! paint runs of them. The visitor pattern keeps every combination monomorphic: the painter's
//! concrete type, which differs per style option (filter, wrap, ...), reaches the span loop.

use embedded_graphics::{
    draw_target::DrawTarget,
    geometry::{Point, Size},
    pixelcolor::PixelColor,
    primitives::Rectangle,
};

use super::spans::{PixelShader, shade_span};
use crate::{
    coverage::{CoverageSink, FillRule, Span, SpanSink},
    geometry::Shape,
    interpolate::{AreaMemo, Planes},
    target::BlendTarget,
};

/// Paints runs of covered pixels, each within one row, for one triangle.
#[doc(hidden)]
pub trait Painter {
    /// The colour painted.
    type Color: PixelColor;

    /// Paints `run` (screen coordinates, inside the target) into `target`, whose pixel
    /// `(x, y)` is the screen's `(x, y) + offset` (see [`stored`]).
    ///
    /// # Errors
    ///
    /// The target's.
    fn paint<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = Self::Color>;

    /// Paints `run`, pixels an edge crosses, for anti-aliasing: their centres may lie just
    /// outside the triangle, where interpolated colours can leave the range the vertices
    /// span, so painters whose colours could wrap there keep them within it.
    ///
    /// # Errors
    ///
    /// The target's.
    #[inline]
    fn paint_edge<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = Self::Color>,
    {
        self.paint(run, offset, target)
    }

    /// Whether the painter can carry a depth pass's plane with its own
    /// ([`Painter::carry_depth`]): a constant, so that the depth pass of painters that cannot
    /// holds no code for it.
    const CARRIES_DEPTH: bool = false;

    /// Takes `depth`, a depth pass's plane set up for the same window as the painter's own
    /// planes, to move with them: one move per span for both. Returns whether it did (never,
    /// by default); if so, the depth pass reads depths through [`Painter::carried_depth_at`],
    /// which moves both, and paints a run only from where that move left the planes: through
    /// [`Painter::paint_carried`], or [`Painter::paint`], whose own move is then none (a move
    /// by `paint` alone would leave the depth behind).
    #[inline(always)]
    fn carry_depth(&mut self, depth: &Planes<1>) -> bool {
        let _ = depth;
        false
    }

    /// The carried depth (raw 16.16) at pixel `(x, y)`, the painter's planes moved there with
    /// it: only after [`Painter::carry_depth`] took the plane.
    #[inline(always)]
    fn carried_depth_at(&self, x: i32, y: i32) -> u32 {
        let _ = (x, y);
        0
    }

    /// [`Painter::paint`] for a painter that carries a depth pass's plane, whose planes the
    /// pass has just moved to `run`'s first pixel ([`Painter::carried_depth_at`]): inline, so
    /// that the pass's own span function holds the span loop (one call and one move per span
    /// instead of two).
    ///
    /// # Errors
    ///
    /// The target's.
    #[inline(always)]
    fn paint_carried<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = Self::Color>,
    {
        self.paint(run, offset, target)
    }
}

/// Where `run` (screen coordinates) lies in a target whose pixel `(x, y)` is the screen's
/// `(x, y) + offset`.
///
/// The offset is zero except in band rendering, whose band framebuffer holds a part of the
/// screen from its own `(0, 0)`. Painting through an offset instead of a translating target
/// type keeps one copy of each painter for frames and bands alike.
#[inline(always)]
pub(crate) fn stored(run: Span, offset: Point) -> Rectangle {
    let top_left = Point::new(run.x.wrapping_sub(offset.x), run.y.wrapping_sub(offset.y));
    Rectangle::new(top_left, Size::new(run.len, 1))
}

/// The screen area a target's `area` shows, when its pixel `(x, y)` is the screen's
/// `(x, y) + offset`.
#[inline(always)]
pub(crate) fn on_screen(area: Rectangle, offset: Point) -> Rectangle {
    let top_left = Point::new(
        area.top_left.x.wrapping_add(offset.x),
        area.top_left.y.wrapping_add(offset.y),
    );
    Rectangle::new(top_left, area.size)
}

/// Receives a triangle's painter and draws with it.
#[doc(hidden)]
pub trait PaintVisitor<C: PixelColor> {
    /// What drawing returns.
    type Output;

    /// Whether the painter will be asked for pixels an edge crosses
    /// ([`Painter::paint_edge`]): anti-aliasing's. Styles whose edge pixels need more than
    /// their plain painter hand over another painter then.
    const EDGE_PIXELS: bool = false;

    /// Draws with `painter`.
    fn visit<P: Painter<Color = C>>(self, painter: P) -> Self::Output;

    /// Where the style's plane set-ups keep the area's reciprocal for the visitor's own
    /// (a depth pass's plane): none by default.
    #[inline(always)]
    fn area_memo(&self) -> Option<&AreaMemo> {
        None
    }
}

mod sealed {
    pub trait Sealed {}
}

/// The crate's triangle styles: [`FlatStyle`](crate::FlatStyle),
/// [`GouraudStyle`](crate::GouraudStyle), [`TextureStyle`](crate::TextureStyle) and
/// [`ShaderStyle`](crate::ShaderStyle). Each draws a [`Triangle`](crate::Triangle) through `into_styled`, and
/// with a depth test through [`DepthTarget::draw`](crate::depth::DepthTarget::draw).
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use embedded_graphics::prelude::*;
/// use trirast::{shading::TriangleStyle, FillRule, FlatStyle};
///
/// fn rule_of<S: TriangleStyle>(style: &S) -> FillRule {
///     style.fill_rule()
/// }
/// assert_eq!(rule_of(&FlatStyle::new(Rgb565::RED)), FillRule::TopLeft);
/// ```
pub trait TriangleStyle: sealed::Sealed {
    /// The colour drawn.
    type Color: PixelColor;

    /// Which boundary pixels belong to the triangle.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use trirast::{shading::TriangleStyle, FillRule, FlatStyle};
    ///
    /// let style = FlatStyle::new(BinaryColor::On).with_fill_rule(FillRule::Inclusive);
    /// assert_eq!(style.fill_rule(), FillRule::Inclusive);
    /// ```
    fn fill_rule(&self) -> FillRule;

    /// Sets up this style's painter for `triangle` drawn into `window` and hands it to
    /// `visitor`; `None` for degenerate triangles.
    #[doc(hidden)]
    fn paint<G: Shape, V: PaintVisitor<Self::Color>>(
        &self,
        triangle: &G,
        window: &Rectangle,
        visitor: V,
    ) -> Option<V::Output>;
}

/// Implements [`TriangleStyle`]'s seal and embedded-graphics' drawing traits for a style.
macro_rules! drawable_style {
    ([$($generics:tt)*] $style:ty $(where $($bounds:tt)*)?) => {
        impl<$($generics)*> $crate::shading::paint::Sealed for $style $(where $($bounds)*)? {}
        $crate::shading::paint::drawable_style!(@shape $crate::geometry::Triangle, [$($generics)*] $style $(where $($bounds)*)?);
        $crate::shading::paint::drawable_style!(@shape $crate::geometry::SubPixelTriangle, [$($generics)*] $style $(where $($bounds)*)?);
    };
    (@shape $shape:ty, [$($generics:tt)*] $style:ty $(where $($bounds:tt)*)?) => {
        impl<$($generics)*> embedded_graphics::primitives::StyledDrawable<$style> for $shape
        $(where $($bounds)*)?
        {
            type Color = <$style as $crate::shading::TriangleStyle>::Color;
            type Output = ();

            #[inline]
            fn draw_styled<D>(&self, style: &$style, target: &mut D) -> Result<(), D::Error>
            where
                D: embedded_graphics::draw_target::DrawTarget<Color = Self::Color>,
            {
                $crate::shading::paint::draw_plain(self, style, target)
            }
        }

        impl<$($generics)*> embedded_graphics::primitives::StyledDimensions<$style> for $shape
        $(where $($bounds)*)?
        {
            fn styled_bounding_box(&self, _style: &$style) -> embedded_graphics::primitives::Rectangle {
                embedded_graphics::geometry::Dimensions::bounding_box(self)
            }
        }
    };
}
pub(crate) use drawable_style;
pub(crate) use sealed::Sealed;

/// Draws `triangle` with `style` straight into `target`: each span painted as it comes.
#[inline(always)]
pub(crate) fn draw_plain<G, S, D>(triangle: &G, style: &S, target: &mut D) -> Result<(), D::Error>
where
    G: Shape,
    S: TriangleStyle,
    D: DrawTarget<Color = S::Color>,
{
    let window = target.bounding_box();
    draw_plain_in(triangle, style, target, &window, NoOffset)
}

/// The offset from screen to target coordinates, as a type: [`NoOffset`] for targets that are
/// the screen, so that the zero is a constant wherever the span sink lives (the wide walk
/// keeps the sink in memory: a stored zero is reloaded for every span), or a [`Point`] for a
/// band's framebuffer.
pub(crate) trait Offset: Copy {
    fn point(self) -> Point;
}

/// Target and screen coordinates are the same.
#[derive(Copy, Clone, Debug)]
pub(crate) struct NoOffset;

impl Offset for NoOffset {
    #[inline(always)]
    fn point(self) -> Point {
        Point::zero()
    }
}

impl Offset for Point {
    #[inline(always)]
    fn point(self) -> Point {
        self
    }
}

/// [`draw_plain`] with interpolation set up for `setup` (the whole screen, when `target` is a
/// band of it), so that colours do not depend on the part of the screen drawn, into a target
/// whose pixel `(x, y)` is the screen's `(x, y) + offset`.
#[inline(always)]
pub(crate) fn draw_plain_in<G, S, D, O>(
    triangle: &G,
    style: &S,
    target: &mut D,
    setup: &Rectangle,
    offset: O,
) -> Result<(), D::Error>
where
    G: Shape,
    S: TriangleStyle,
    D: DrawTarget<Color = S::Color>,
    O: Offset,
{
    let window = on_screen(target.bounding_box(), offset.point());
    let visitor = PlainVisitor {
        target,
        triangle,
        rule: style.fill_rule(),
        window,
        offset,
    };
    style.paint(triangle, setup, visitor).unwrap_or(Ok(()))
}

/// Walks the triangle and paints every span.
struct PlainVisitor<'a, G, D, O> {
    target: &'a mut D,
    triangle: &'a G,
    rule: FillRule,
    /// Where spans are drawn, in screen coordinates.
    window: Rectangle,
    offset: O,
}

impl<G: Shape, D: DrawTarget, O: Offset> PaintVisitor<D::Color> for PlainVisitor<'_, G, D, O> {
    type Output = Result<(), D::Error>;

    #[inline(always)]
    fn visit<P: Painter<Color = D::Color>>(self, painter: P) -> Self::Output {
        let mut sink = PaintSpans {
            target: self.target,
            painter,
            offset: self.offset,
        };
        self.triangle.walk_spans(self.rule, &self.window, &mut sink)
    }
}

/// Paints each span as the walk emits it.
struct PaintSpans<'a, D, P, O> {
    target: &'a mut D,
    painter: P,
    offset: O,
}

impl<D, P, O> SpanSink for PaintSpans<'_, D, P, O>
where
    D: DrawTarget,
    P: Painter<Color = D::Color>,
    O: Offset,
{
    type Error = D::Error;

    // A forwarder: the painter decides what is inlined into the row loop (a flat fill is).
    #[inline(always)]
    fn span(&mut self, span: Span) -> Result<(), D::Error> {
        self.painter.paint(span, self.offset.point(), self.target)
    }
}

/// Draws `triangle` with `style` into `target` with anti-aliased edges: every pixel blended by
/// the area of its square the triangle covers (see
/// [`for_each_coverage_run`](crate::coverage::for_each_coverage_run)).
#[inline]
pub(crate) fn draw_anti_aliased<G, S, D>(
    triangle: &G,
    style: &S,
    target: &mut D,
) -> Result<(), D::Error>
where
    G: Shape,
    S: TriangleStyle,
    D: BlendTarget<Color = S::Color>,
{
    let window = target.bounding_box();
    draw_anti_aliased_in(triangle, style, target, &window, Point::zero())
}

/// [`draw_anti_aliased`] with interpolation set up for `setup` into a target whose pixel
/// `(x, y)` is the screen's `(x, y) + offset`, as [`draw_plain_in`] (band rendering).
pub(crate) fn draw_anti_aliased_in<G, S, D>(
    triangle: &G,
    style: &S,
    target: &mut D,
    setup: &Rectangle,
    offset: Point,
) -> Result<(), D::Error>
where
    G: Shape,
    S: TriangleStyle,
    D: BlendTarget<Color = S::Color>,
{
    let window = on_screen(target.bounding_box(), offset);
    let visitor = AntiAliasVisitor {
        target,
        triangle,
        window,
        offset,
    };
    style.paint(triangle, setup, visitor).unwrap_or(Ok(()))
}

/// Walks the triangle's area coverage and paints every run, blended by its coverage.
struct AntiAliasVisitor<'a, G, D> {
    target: &'a mut D,
    triangle: &'a G,
    /// Where runs are drawn, in screen coordinates.
    window: Rectangle,
    offset: Point,
}

impl<G: Shape, D: BlendTarget> PaintVisitor<D::Color> for AntiAliasVisitor<'_, G, D> {
    type Output = Result<(), D::Error>;
    const EDGE_PIXELS: bool = true;

    fn visit<P: Painter<Color = D::Color>>(self, painter: P) -> Self::Output {
        let mut sink = PaintCoverage {
            target: self.target,
            painter,
            offset: self.offset,
        };
        self.triangle.walk_area(&self.window, &mut sink)
    }
}

/// Paints coverage as it comes: interiors through the painter as usual, edge runs through its
/// edge painting, each pixel blended by its own coverage.
struct PaintCoverage<'a, D, P> {
    target: &'a mut D,
    painter: P,
    offset: Point,
}

impl<D, P> CoverageSink for PaintCoverage<'_, D, P>
where
    D: BlendTarget,
    P: Painter<Color = D::Color>,
{
    type Error = D::Error;

    fn interior(&mut self, span: Span, coverage: u8) -> Result<(), D::Error> {
        let mut blended = Blended {
            target: &mut *self.target,
            opacity: coverage,
        };
        self.painter.paint(span, self.offset, &mut blended)
    }

    fn edge(&mut self, x: i32, y: i32, coverages: &[u8]) -> Result<(), D::Error> {
        let span = Span {
            x,
            y,
            len: coverages.len() as u32,
        };
        let mut blended = BlendedEach {
            target: &mut *self.target,
            coverages,
            first: x.wrapping_sub(self.offset.x),
        };
        self.painter.paint_edge(span, self.offset, &mut blended)
    }
}

/// A [`BlendTarget`] seen as a plain target for one run of pixels, each blended at its own
/// opacity: `coverages[k]` for the run's `k`-th pixel.
struct BlendedEach<'t, 'c, D> {
    target: &'t mut D,
    coverages: &'c [u8],
    /// The target column of the run's first pixel.
    first: i32,
}

impl<D: BlendTarget> embedded_graphics::geometry::Dimensions for BlendedEach<'_, '_, D> {
    fn bounding_box(&self) -> Rectangle {
        self.target.bounding_box()
    }
}

impl<D: BlendTarget> DrawTarget for BlendedEach<'_, '_, D> {
    type Color = D::Color;
    type Error = D::Error;

    /// Painters fill runs; single pixels take the coverage of their place in the run.
    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), D::Error>
    where
        I: IntoIterator<Item = embedded_graphics::Pixel<D::Color>>,
    {
        for embedded_graphics::Pixel(at, color) in pixels {
            let k = at.x.wrapping_sub(self.first) as u32 as usize;
            if let Some(&coverage) = self.coverages.get(k) {
                let area = Rectangle::new(at, Size::new(1, 1));
                self.target
                    .blend_contiguous(&area, core::iter::once(color), coverage)?;
            }
        }
        Ok(())
    }

    #[inline]
    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), D::Error>
    where
        I: IntoIterator<Item = D::Color>,
    {
        let pixels = colors.into_iter().zip(self.coverages.iter().copied());
        self.target.blend_each(area, pixels)
    }

    #[inline]
    fn fill_solid(&mut self, area: &Rectangle, color: D::Color) -> Result<(), D::Error> {
        let pixels = self.coverages.iter().map(|&coverage| (color, coverage));
        self.target.blend_each(area, pixels)
    }
}

/// A [`BlendTarget`] seen as a plain target that blends everything at `opacity` (and writes
/// straight through at 255).
struct Blended<'t, D> {
    target: &'t mut D,
    opacity: u8,
}

impl<D: BlendTarget> embedded_graphics::geometry::Dimensions for Blended<'_, D> {
    fn bounding_box(&self) -> Rectangle {
        self.target.bounding_box()
    }
}

impl<D: BlendTarget> DrawTarget for Blended<'_, D> {
    type Color = D::Color;
    type Error = D::Error;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), D::Error>
    where
        I: IntoIterator<Item = embedded_graphics::Pixel<D::Color>>,
    {
        for embedded_graphics::Pixel(at, color) in pixels {
            let area = Rectangle::new(at, Size::new(1, 1));
            self.target
                .blend_contiguous(&area, core::iter::once(color), self.opacity)?;
        }
        Ok(())
    }

    #[inline]
    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), D::Error>
    where
        I: IntoIterator<Item = D::Color>,
    {
        if self.opacity == u8::MAX {
            self.target.fill_contiguous(area, colors)
        } else {
            self.target.blend_contiguous(area, colors, self.opacity)
        }
    }

    #[inline]
    fn fill_solid(&mut self, area: &Rectangle, color: D::Color) -> Result<(), D::Error> {
        if self.opacity == u8::MAX {
            self.target.fill_solid(area, color)
        } else {
            self.target.blend_solid(area, color, self.opacity)
        }
    }
}

/// Paints runs with one colour, through `fill_solid`.
pub(crate) struct SolidPainter<C>(pub(crate) C);

impl<C: PixelColor> Painter for SolidPainter<C> {
    type Color = C;

    #[inline(always)]
    fn paint<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        target.fill_solid(&stored(run, offset), self.0)
    }
}

/// Paints runs pixel by pixel with a [`PixelShader`], through `fill_contiguous`.
pub(crate) struct ShaderPainter<S>(pub(crate) S);

impl<S: PixelShader> Painter for ShaderPainter<S> {
    type Color = S::Color;

    #[inline(always)]
    fn paint<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = S::Color>,
    {
        shade_span(&self.0, run, offset, target)
    }
}
