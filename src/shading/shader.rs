//! Per-pixel shading by a user function of interpolated attributes.

use embedded_graphics::{geometry::Point, pixelcolor::PixelColor, primitives::Rectangle};
use fixed::types::I16F16;

use super::{
    paint::{drawable_style, PaintVisitor, ShaderPainter},
    spans::PlanesShader,
    TriangleStyle,
};
use crate::{coverage::FillRule, geometry::Shape};

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
}

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
        let values = self.attributes.map(|a| a.map(|v| i64::from(v.to_bits())));
        let shade = |position, raw: [u32; N]| {
            (self.shader)(Fragment {
                position,
                values: raw.map(|v| I16F16::from_bits(v as i32)),
            })
        };
        let shader = PlanesShader::new(triangle, values, 0, window.top_left, shade)?;
        Some(visitor.visit(ShaderPainter(shader)))
    }
}

drawable_style!([C, const N: usize, F] ShaderStyle<N, F> where C: PixelColor, F: Fn(Fragment<N>) -> C);
