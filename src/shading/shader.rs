//! Per-pixel shading by a user function of interpolated attributes.

use embedded_graphics::{
    draw_target::DrawTarget, geometry::Point, pixelcolor::PixelColor, primitives::Rectangle,
};
use fixed::types::I16F16;

use super::{
    TriangleStyle,
    paint::{PaintVisitor, Painter, ShaderPainter, drawable_style},
    spans::{PlanesShader, SteppedShader, shade_span},
};
use crate::{
    coverage::{FillRule, Span},
    geometry::Shape,
    interpolate::{Perspective, PerspectivePlanes},
};

/// What a shader sees at one pixel: its position and the `N` attributes interpolated there.
///
/// # Examples
///
/// ```
/// use embedded_graphics::prelude::*;
/// use fixed::types::I16F16;
/// use trirast::shading::Fragment;
///
/// let f = Fragment { position: Point::new(3, 4), values: [I16F16::from_num(0.5)] };
/// assert_eq!(f.values[0] * 2, I16F16::ONE);
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Fragment<const N: usize> {
    /// The pixel.
    pub position: Point,
    /// The attributes, interpolated at the pixel.
    pub values: [I16F16; N],
}

/// Shades each pixel with a function of `N` attributes interpolated from the vertices: normals,
/// light intensity, texture or depth values of your own, anything that varies linearly.
///
/// The attributes are `I16F16` per vertex; each is interpolated from its plane and handed to
/// `shader` with the pixel's position. The value at the start of each span is the exact one
/// rounded to 2^-16 (within one least significant bit); along the span it steps by the gradient
/// rounded to 2^-16, so a pixel `k` pixels into its span is within `1 + k / 2` LSB of exact
/// (0.0025 for `k` = 320). Nothing is allocated; the closure is inlined into the span loop.
/// Values wrap if a plane leaves the `I16F16` range inside the triangle.
///
/// # Examples
///
/// Light intensity per vertex, applied to one base colour:
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb888, prelude::*};
/// use fixed::types::I16F16;
/// use trirast::{shading::Fragment, Framebuffer, ShaderStyle, Triangle};
///
/// let light = [I16F16::from_num(0.25), I16F16::from_num(1), I16F16::from_num(0.5)];
/// let style = ShaderStyle::new([[light[0]], [light[1]], [light[2]]], |f: Fragment<1>| {
///     let level = (f.values[0] * 200).to_num::<u8>();
///     Rgb888::new(level, level / 2, 40)
/// });
/// let mut pixels = [Rgb888::BLACK; 32 * 32];
/// let mut display = Framebuffer::new(&mut pixels, 32, 32)?;
/// Triangle::new(Point::new(0, 0), Point::new(31, 0), Point::new(0, 31)).into_styled(style).draw(&mut display).unwrap();
/// assert_eq!(display.pixel(Point::new(0, 0)), Some(Rgb888::new(50, 25, 40)));
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Copy, Clone, Debug)]
pub struct ShaderStyle<const N: usize, F> {
    /// The attributes at each vertex, in the triangle's vertex order.
    pub attributes: [[I16F16; N]; 3],
    /// Computes a pixel's colour.
    pub shader: F,
    /// Which boundary pixels belong to the triangle; [`FillRule::TopLeft`] by default.
    pub fill_rule: FillRule,
}

impl<const N: usize, F> ShaderStyle<N, F> {
    /// A style calling `shader` for each pixel with `attributes` interpolated there.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use fixed::types::I16F16;
    /// use trirast::{shading::Fragment, ShaderStyle};
    ///
    /// let zero = [I16F16::ZERO; 2];
    /// let style = ShaderStyle::new([zero; 3], |f: Fragment<2>| Gray8::new(f.values[1].to_num()));
    /// assert_eq!(style.attributes.len(), 3);
    /// ```
    #[inline]
    #[must_use]
    pub const fn new<C>(attributes: [[I16F16; N]; 3], shader: F) -> Self
    where
        F: Fn(Fragment<N>) -> C,
    {
        Self {
            attributes,
            shader,
            fill_rule: FillRule::TopLeft,
        }
    }

    /// The same style with another fill rule.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use fixed::types::I16F16;
    /// use trirast::{shading::Fragment, FillRule, ShaderStyle};
    ///
    /// let style = ShaderStyle::new([[I16F16::ZERO]; 3], |_: Fragment<1>| Gray8::new(0))
    ///     .with_fill_rule(FillRule::Inclusive);
    /// assert_eq!(style.fill_rule, FillRule::Inclusive);
    /// ```
    #[inline]
    #[must_use]
    pub fn with_fill_rule(mut self, fill_rule: FillRule) -> Self {
        self.fill_rule = fill_rule;
        self
    }

    /// The same style with its attributes interpolated perspective-correct, with each vertex's
    /// `w` in `perspective` (see [`Perspective`] for the accuracy): for attributes of a surface
    /// seen at an angle, such as texture coordinates of a procedural texture. Drawn for 1 to 8
    /// attributes.
    ///
    /// # Examples
    ///
    /// A checker computed from perspective-correct coordinates, on a floor whose far edge
    /// (`w` = 4) is four times as far as its near one: the checks' boundary halfway up the
    /// texture lands a fifth of the way down from the far edge.
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
    /// use fixed::types::I16F16;
    /// use trirast::{interpolate::Perspective, shading::Fragment, Framebuffer, ShaderStyle, Triangle};
    ///
    /// let (near, far) = (I16F16::ONE, I16F16::from_num(4));
    /// let v = [[I16F16::ZERO], [I16F16::ZERO], [I16F16::ONE]];
    /// let style = ShaderStyle::new(v, |f: Fragment<1>| (f.values[0] >= 0.5).into())
    ///     .with_perspective(Perspective::new([far, far, near]));
    /// let mut pixels = [BinaryColor::Off; 40 * 40];
    /// let mut display = Framebuffer::new(&mut pixels, 40, 40)?;
    /// let triangle = Triangle::new(Point::new(0, 0), Point::new(40, 0), Point::new(0, 40));
    /// triangle.into_styled(style).draw(&mut display).unwrap();
    /// assert_eq!(display.pixel(Point::new(1, 7)), Some(BinaryColor::Off));
    /// assert_eq!(display.pixel(Point::new(1, 9)), Some(BinaryColor::On));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[inline]
    #[must_use]
    pub fn with_perspective(self, perspective: Perspective) -> PerspectiveShaderStyle<N, F> {
        PerspectiveShaderStyle {
            style: self,
            perspective,
        }
    }
}

impl<const N: usize, F> ShaderStyle<N, F> {
    /// The attributes as raw 16.16, for the planes.
    #[inline(always)]
    fn raw_attributes(&self) -> [[i64; N]; 3] {
        self.attributes.map(|a| a.map(|v| i64::from(v.to_bits())))
    }
}

/// `shader`'s colour for the pixel at `position` with raw 16.16 values `raw`.
#[inline(always)]
fn fragment_shade<C, const N: usize, F>(shader: &F, position: Point, raw: [u32; N]) -> C
where
    F: Fn(Fragment<N>) -> C,
{
    shader(Fragment {
        position,
        values: raw.map(|v| I16F16::from_bits(v as i32)),
    })
}

/// A [`ShaderStyle`] whose attributes are interpolated perspective-correct: made by
/// [`ShaderStyle::with_perspective`], drawn for 1 to 8 attributes.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use fixed::types::I16F16;
/// use trirast::{interpolate::Perspective, shading::Fragment, ShaderStyle};
///
/// let w = [1, 2, 3].map(I16F16::from_num);
/// let style = ShaderStyle::new([[I16F16::ZERO]; 3], |f: Fragment<1>| Gray8::new(f.values[0].to_num()))
///     .with_perspective(Perspective::new(w));
/// assert_eq!(style.perspective.w, w);
/// ```
#[derive(Copy, Clone, Debug)]
pub struct PerspectiveShaderStyle<const N: usize, F> {
    /// The style: attributes, shader and fill rule.
    pub style: ShaderStyle<N, F>,
    /// Each vertex's `w` and the sub-span length.
    pub perspective: Perspective,
}

/// The painter of a perspective-correct shader: each run cut into sub-spans, whose ends get
/// their exact attributes and whose pixels step linearly between them.
struct PerspectiveShaderPainter<'a, const P: usize, const N: usize, F> {
    planes: &'a PerspectivePlanes<P, N>,
    shader: &'a F,
}

impl<C, const P: usize, const N: usize, F> Painter for PerspectiveShaderPainter<'_, P, N, F>
where
    C: PixelColor,
    F: Fn(Fragment<N>) -> C,
{
    type Color = C;

    #[inline]
    fn paint<D>(&self, run: Span, offset: Point, target: &mut D) -> Result<(), D::Error>
    where
        D: DrawTarget<Color = C>,
    {
        let mut sub_spans = self.planes.sub_spans(run.x, run.y, run.len, false);
        while sub_spans.left > 0 {
            let stretch = self.planes.next_sub_span(&mut sub_spans, false);
            let shader = SteppedShader {
                start: stretch.start,
                steps: stretch.steps,
                shade: |position, raw| fragment_shade(self.shader, position, raw),
            };
            let piece = Span {
                x: stretch.x,
                y: run.y,
                len: stretch.len,
            };
            shade_span(&shader, piece, offset, target)?;
        }
        Ok(())
    }
}

/// The perspective shader style for each attribute count: its planes hold one more plane
/// (`1 / w`) than it has attributes, which a generic `N` cannot name.
macro_rules! perspective_shader_style {
    ($($n:literal => $p:literal),*) => {$(
        impl<C, F> TriangleStyle for PerspectiveShaderStyle<$n, F>
        where
            C: PixelColor,
            F: Fn(Fragment<$n>) -> C,
        {
            type Color = C;

            #[inline]
            fn fill_rule(&self) -> FillRule {
                self.style.fill_rule
            }

            #[inline(always)]
            fn paint<G: Shape, V: PaintVisitor<C>>(
                &self,
                triangle: &G,
                window: &Rectangle,
                visitor: V,
            ) -> Option<V::Output> {
                if self.perspective.is_affine() {
                    return self.style.paint(triangle, window, visitor);
                }
                let (values, memo) = (self.style.raw_attributes(), visitor.area_memo());
                let (w, sub_span) = (self.perspective.w, self.perspective.sub_span.pixels());
                let planes = PerspectivePlanes::<$p, $n>::new(
                    triangle, values, 0, w, sub_span, window, memo,
                );
                let painter = PerspectiveShaderPainter {
                    planes: planes.as_ref()?,
                    shader: &self.style.shader,
                };
                Some(visitor.visit(painter))
            }
        }

        drawable_style!([C, F] PerspectiveShaderStyle<$n, F> where C: PixelColor, F: Fn(Fragment<$n>) -> C);
    )*};
}

perspective_shader_style!(1 => 2, 2 => 3, 3 => 4, 4 => 5, 5 => 6, 6 => 7, 7 => 8, 8 => 9);

impl<C, const N: usize, F> TriangleStyle for ShaderStyle<N, F>
where
    C: PixelColor,
    F: Fn(Fragment<N>) -> C,
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
        let shade = |position, raw| fragment_shade(&self.shader, position, raw);
        let (values, memo) = (self.raw_attributes(), visitor.area_memo());
        let shader = PlanesShader::new(triangle, values, 0, window.top_left, memo, shade)?;
        Some(visitor.visit(ShaderPainter(shader)))
    }
}

drawable_style!([C, const N: usize, F] ShaderStyle<N, F> where C: PixelColor, F: Fn(Fragment<N>) -> C);
