//! Which pixels on a triangle's boundary belong to it.

/// Decides which pixels lying exactly on a triangle's edges are drawn.
///
/// Pixel `(x, y)` is the sample point `(x, y)`, as in embedded-graphics. Pixels strictly inside a
/// triangle are always drawn and pixels strictly outside never are; the rule settles the rest.
/// Neither rule depends on the order or winding of the vertices.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
/// use trirast::{FillRule, FlatStyle, Triangle};
///
/// let triangle = Triangle::new(Point::new(0, 0), Point::new(4, 0), Point::new(0, 4));
///
/// // Top-left: the top and left edges are in, the sloped right edge is out.
/// let mut display = MockDisplay::new();
/// triangle.into_styled(FlatStyle::new(BinaryColor::On)).draw(&mut display)?;
/// display.assert_pattern(&[
///     "####", //
///     "### ",
///     "##  ",
///     "#   ",
/// ]);
///
/// // Inclusive: every pixel on the closed triangle, vertices included.
/// let mut display = MockDisplay::new();
/// let style = FlatStyle::new(BinaryColor::On).with_fill_rule(FillRule::Inclusive);
/// triangle.into_styled(style).draw(&mut display)?;
/// display.assert_pattern(&[
///     "#####", //
///     "#### ",
///     "###  ",
///     "##   ",
///     "#    ",
/// ]);
/// # Ok::<(), core::convert::Infallible>(())
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, Hash)]
pub enum FillRule {
    /// The top-left rule (as in Direct3D and most GPUs): a pixel on an edge is drawn only when
    /// that edge is a *top* edge (horizontal, with the triangle below it) or a *left* edge (the
    /// triangle lies to its right). Equivalently, each pixel is sampled an infinitesimal step
    /// right and an even smaller step down of its integer position.
    ///
    /// Triangles that share an edge therefore draw every pixel on it exactly once, with no gap
    /// and no overdraw, so meshes can be blended and counted. Each triangle covers the pixels
    /// `x` with `left(y) <= x < right(y)` on rows `top <= y < bottom`.
    #[default]
    TopLeft,
    /// Every pixel on the closed triangle, edges and vertices included: for lone triangles whose
    /// outline should be fully lit. Neighbouring triangles draw their shared edge twice.
    Inclusive,
}
