//! Flat (single colour) filling.

use embedded_graphics::{pixelcolor::PixelColor, primitives::Rectangle};

use super::{
    TriangleStyle,
    paint::{PaintVisitor, SolidPainter, drawable_style},
};
use crate::{coverage::FillRule, geometry::Shape};

/// Fills a triangle with one colour.
///
/// Each covered row goes to the target as one `fill_solid` call, so targets with a fast
/// rectangle fill (the crate's [`Framebuffer`](crate::Framebuffer), most display drivers) get
/// whole spans, never single pixels.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
/// use trirast::{FlatStyle, Triangle};
///
/// let mut display = MockDisplay::new();
/// Triangle::new(Point::new(0, 0), Point::new(6, 0), Point::new(0, 3))
///     .into_styled(FlatStyle::new(BinaryColor::On))
///     .draw(&mut display)?;
/// display.assert_pattern(&[
///     "######", //
///     "####  ",
///     "##    ",
/// ]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub struct FlatStyle<C> {
    /// The fill colour.
    pub color: C,
    /// Which boundary pixels belong to the triangle; [`FillRule::TopLeft`] by default.
    pub fill_rule: FillRule,
}

impl<C> FlatStyle<C> {
    /// A style filling with `color` under the top-left rule.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Rgb565;
    /// use embedded_graphics::prelude::*;
    /// use trirast::{FillRule, FlatStyle};
    ///
    /// const RED: FlatStyle<Rgb565> = FlatStyle::new(Rgb565::RED);
    /// assert_eq!(RED.fill_rule, FillRule::TopLeft);
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(color: C) -> Self {
        Self {
            color,
            fill_rule: FillRule::TopLeft,
        }
    }

    /// The same style with another fill rule.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use trirast::{FillRule, FlatStyle};
    ///
    /// let style = FlatStyle::new(BinaryColor::On).with_fill_rule(FillRule::Inclusive);
    /// assert_eq!(style.fill_rule, FillRule::Inclusive);
    /// ```
    #[inline]
    #[must_use]
    pub const fn with_fill_rule(mut self, fill_rule: FillRule) -> Self {
        self.fill_rule = fill_rule;
        self
    }
}

impl<C: PixelColor> TriangleStyle for FlatStyle<C> {
    type Color = C;

    #[inline]
    fn fill_rule(&self) -> FillRule {
        self.fill_rule
    }

    #[inline(always)]
    fn paint<G: Shape, V: PaintVisitor<C>>(
        &self,
        _triangle: &G,
        _window: &Rectangle,
        visitor: V,
    ) -> Option<V::Output> {
        // Each span goes to `fill_solid`, inlined into the edge walk.
        Some(visitor.visit(SolidPainter(self.color)))
    }
}

drawable_style!([C: PixelColor] FlatStyle<C>);
