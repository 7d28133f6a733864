//! The triangle primitive: three integer vertices, no style.

use core::cmp::Ordering;

use embedded_graphics::{
    geometry::{Dimensions, Point, Size},
    primitives::{self, ContainsPoint, PointsIter, Primitive, Rectangle},
    transform::Transform,
};

use super::SubPixelTriangle;
use crate::{
    coverage::{FillRule, row_span, subpixel_row_span},
    setup::{Lane, fits_fast_path, sort_top_to_bottom},
};

/// A triangle with integer vertices, in pixel coordinates (`y` grows downwards).
///
/// A plain `Copy` value, styled and drawn the embedded-graphics way: `into_styled` (from
/// [`Primitive`]) with a style such as [`FlatStyle`](crate::FlatStyle), then
/// [`Drawable::draw`](embedded_graphics::Drawable::draw). Vertices may be any `i32`, in any
/// order and winding; see [`FillRule`] for which pixels are drawn.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
/// use trirast::{Framebuffer, FlatStyle, Triangle};
///
/// const TRIANGLE: Triangle = Triangle::new(Point::new(2, 1), Point::new(30, 8), Point::new(9, 20));
///
/// let mut pixels = [Rgb565::BLACK; 32 * 24];
/// let mut framebuffer = Framebuffer::new(&mut pixels, 32, 24)?;
/// TRIANGLE.into_styled(FlatStyle::new(Rgb565::RED)).draw(&mut framebuffer).unwrap();
/// assert_eq!(framebuffer.pixel(Point::new(10, 10)), Some(Rgb565::RED));
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Triangle {
    /// The three vertices, in the order given.
    pub vertices: [Point; 3],
}

/// The winding of a triangle's vertices as seen on screen (`y` down).
///
/// # Examples
///
/// ```
/// use embedded_graphics::prelude::*;
/// use trirast::{Orientation, Triangle};
///
/// let t = Triangle::new(Point::new(0, 0), Point::new(10, 0), Point::new(0, 10));
/// assert_eq!(t.orientation(), Orientation::Clockwise);
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// Clockwise on screen (positive doubled signed area).
    Clockwise,
    /// Counter-clockwise on screen (negative doubled signed area).
    CounterClockwise,
    /// Zero area: collinear or coincident vertices. Such triangles draw nothing.
    Degenerate,
}

impl Orientation {
    /// The orientation whose doubled signed area has `sign`.
    #[inline(always)]
    pub(crate) fn of_area_sign(sign: Ordering) -> Self {
        match sign {
            Ordering::Greater => Orientation::Clockwise,
            Ordering::Less => Orientation::CounterClockwise,
            Ordering::Equal => Orientation::Degenerate,
        }
    }
}

impl Triangle {
    /// Creates a triangle from three vertices.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::Triangle;
    ///
    /// let t = Triangle::new(Point::new(0, 0), Point::new(8, 2), Point::new(3, 9));
    /// assert_eq!(t.vertices[1], Point::new(8, 2));
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(a: Point, b: Point, c: Point) -> Self {
        Self {
            vertices: [a, b, c],
        }
    }

    /// Twice the signed area, exact for any `i32` vertices: positive for
    /// [clockwise](Orientation::Clockwise) triangles on screen, zero for degenerate ones.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::Triangle;
    ///
    /// let t = Triangle::new(Point::new(0, 0), Point::new(4, 0), Point::new(0, 3));
    /// assert_eq!(t.doubled_signed_area(), 12);
    /// let huge = Triangle::new(Point::new(i32::MIN, i32::MIN), Point::new(i32::MAX, i32::MIN), Point::new(i32::MIN, i32::MAX));
    /// assert_eq!(huge.doubled_signed_area(), (1i128 << 64) - 2 * (1 << 32) + 1);
    /// ```
    #[must_use]
    pub fn doubled_signed_area(&self) -> i128 {
        let [a, b, c] = self.vertices.map(|p| (i128::from(p.x), i128::from(p.y)));
        (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
    }

    /// The winding of the vertices, computed exactly.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::{Orientation, Triangle};
    ///
    /// let t = Triangle::new(Point::new(0, 0), Point::new(0, 10), Point::new(10, 0));
    /// assert_eq!(t.orientation(), Orientation::CounterClockwise);
    /// let line = Triangle::new(Point::new(0, 0), Point::new(5, 5), Point::new(10, 10));
    /// assert_eq!(line.orientation(), Orientation::Degenerate);
    /// ```
    #[must_use]
    pub fn orientation(&self) -> Orientation {
        let sign = if fits_fast_path(&self.vertices) {
            cross_sign::<i32>(&self.vertices)
        } else {
            cross_sign::<i64>(&self.vertices)
        };
        Orientation::of_area_sign(sign)
    }

    /// True when the vertices are collinear or coincident; such triangles draw nothing.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::Triangle;
    ///
    /// assert!(Triangle::new(Point::new(1, 1), Point::new(1, 1), Point::new(5, 2)).is_degenerate());
    /// ```
    #[must_use]
    pub fn is_degenerate(&self) -> bool {
        self.orientation() == Orientation::Degenerate
    }

    /// True when `rule` draws `point` as part of this triangle: the exact half-space test that
    /// the drawing code reproduces row by row.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::{FillRule, Triangle};
    ///
    /// let t = Triangle::new(Point::new(0, 0), Point::new(4, 0), Point::new(0, 4));
    /// assert!(t.covers(Point::new(0, 0), FillRule::TopLeft)); // top-left corner
    /// assert!(!t.covers(Point::new(4, 0), FillRule::TopLeft)); // on the right edge
    /// assert!(t.covers(Point::new(4, 0), FillRule::Inclusive));
    /// ```
    #[must_use]
    pub fn covers(&self, point: Point, rule: FillRule) -> bool {
        let wide = |p: Point| (i128::from(p.x), i128::from(p.y));
        half_space_covers(self.vertices.map(wide), wide(point), rule)
    }
}

/// The exact half-space test of the sample `p` against the triangle `vertices` (any order and
/// winding, any common unit): what [`Triangle::covers`] and
/// [`SubPixelTriangle::covers`](super::SubPixelTriangle::covers) compute.
pub(crate) fn half_space_covers(
    [mut a, b, mut c]: [(i128, i128); 3],
    p: (i128, i128),
    rule: FillRule,
) -> bool {
    // Orient edges so the interior is positive, then test each edge function exactly.
    let area = (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0);
    if area == 0 {
        return false;
    }
    if area < 0 {
        core::mem::swap(&mut a, &mut c);
    }
    [(a, b), (b, c), (c, a)].iter().all(|&(from, to)| {
        // E(p) = (to - from) x (p - from): positive inside for clockwise-on-screen order.
        let (ex, ey) = (to.0 - from.0, to.1 - from.1);
        let value = ex * (p.1 - from.1) - ey * (p.0 - from.0);
        match rule {
            FillRule::Inclusive => value >= 0,
            // dE/dx = -ey, dE/dy = ex: an edge is top-left when the interior lies right of
            // it (dE/dx > 0) or, if horizontal, below it (dE/dy > 0).
            FillRule::TopLeft => value > 0 || (value == 0 && (ey < 0 || (ey == 0 && ex > 0))),
        }
    })
}

impl From<primitives::Triangle> for Triangle {
    /// The same vertices in the same order: an embedded-graphics triangle drawn by this crate's
    /// styles, under its exact fill rules (embedded-graphics' own fill can differ on edges).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives};
    /// use trirast::Triangle;
    ///
    /// let eg = primitives::Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
    /// assert_eq!(Triangle::from(eg).vertices, eg.vertices);
    /// ```
    #[inline]
    fn from(triangle: primitives::Triangle) -> Self {
        Self {
            vertices: triangle.vertices,
        }
    }
}

impl From<Triangle> for primitives::Triangle {
    /// The same vertices in the same order, as embedded-graphics' triangle (for its stroke
    /// styles, say).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives};
    /// use trirast::Triangle;
    ///
    /// let t = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
    /// assert_eq!(primitives::Triangle::from(t).vertices, t.vertices);
    /// ```
    #[inline]
    fn from(triangle: Triangle) -> Self {
        let [a, b, c] = triangle.vertices;
        primitives::Triangle::new(a, b, c)
    }
}

impl PointsIter for Triangle {
    type Iter = Points;

    /// The pixels the default top-left rule draws, row by row from the top, left to right in
    /// each: what [`ContainsPoint::contains`] accepts, one at a time, for any `i32` vertices.
    /// For drawing, styles and [`for_each_span`](crate::coverage::for_each_span) hand out
    /// whole rows and step their edges instead, which is much faster; this iterator sets up
    /// each row's ends exactly from the vertices in 64-bit arithmetic (a few divisions a row),
    /// visiting every row from the top vertex to the bottom one, empty ones too (a sliver
    /// billions of rows tall takes that long to iterate).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives::PointsIter};
    /// use trirast::Triangle;
    ///
    /// let t = Triangle::new(Point::new(0, 0), Point::new(3, 0), Point::new(0, 3));
    /// let points: Vec<Point> = t.points().collect();
    /// assert_eq!(points, [(0, 0), (1, 0), (2, 0), (0, 1), (1, 1), (0, 2)].map(Point::from));
    /// ```
    fn points(&self) -> Points {
        let sorted = sort_top_to_bottom(self.vertices);
        // Rows from the top vertex's to the bottom one's (whose own row the top-left rule
        // leaves out); none for a degenerate triangle.
        let rows = if self.is_degenerate() {
            0..0
        } else {
            i64::from(sorted[0].y)..i64::from(sorted[2].y)
        };
        Points::new(PointsOf::Whole(sorted), rows)
    }
}

/// The pixels of a [`Triangle`] or a [`SubPixelTriangle`](super::SubPixelTriangle) under the
/// top-left rule, from [`PointsIter::points`].
///
/// # Examples
///
/// ```
/// use embedded_graphics::{prelude::*, primitives::PointsIter};
/// use trirast::{geometry::Points, Triangle};
///
/// let mut points: Points = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8)).points();
/// assert_eq!(points.next(), Some(Point::new(0, 0)));
/// assert_eq!(points.count(), 35); // 36 pixels in all
/// ```
#[derive(Clone, Debug)]
pub struct Points {
    triangle: PointsOf,
    /// The rows not yet visited.
    rows: core::ops::Range<i64>,
    /// The rest of the current row: its next pixel and how many are left (at least one).
    span: Option<(Point, u32)>,
}

impl Points {
    /// The points of `triangle` on `rows`.
    pub(super) fn new(triangle: PointsOf, rows: core::ops::Range<i64>) -> Self {
        Self {
            triangle,
            rows,
            span: None,
        }
    }
}

/// Whose points [`Points`] lists.
#[derive(Clone, Debug)]
pub(super) enum PointsOf {
    /// A [`Triangle`]'s vertices, top to bottom.
    Whole([Point; 3]),
    SubPixel(SubPixelTriangle),
}

impl Iterator for Points {
    type Item = Point;

    fn next(&mut self) -> Option<Point> {
        let (point, left) = if let Some(rest) = self.span {
            rest
        } else {
            loop {
                // Rows lie between two vertices' rows, so within i32.
                let row = self.rows.next()? as i32;
                let span = match &self.triangle {
                    PointsOf::Whole(sorted) => row_span(*sorted, FillRule::TopLeft, row),
                    PointsOf::SubPixel(triangle) => {
                        subpixel_row_span(triangle, FillRule::TopLeft, row)
                    }
                };
                if let Some(span) = span {
                    break (Point::new(span.x, span.y), span.len);
                }
            }
        };
        // The pixel after the row's last may lie past i32::MAX: it is never read.
        self.span = (left > 1).then(|| (Point::new(point.x.wrapping_add(1), point.y), left - 1));
        Some(point)
    }
}

impl ContainsPoint for Triangle {
    /// True when `point` is one of the pixels the default top-left rule draws (see
    /// [`Triangle::covers`] for either rule).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives::ContainsPoint};
    /// use trirast::Triangle;
    ///
    /// let t = Triangle::new(Point::new(0, 0), Point::new(4, 0), Point::new(0, 4));
    /// assert!(t.contains(Point::new(1, 1)));
    /// assert!(!t.contains(Point::new(4, 0))); // on the right edge: the neighbour's pixel
    /// ```
    #[inline]
    fn contains(&self, point: Point) -> bool {
        self.covers(point, FillRule::TopLeft)
    }
}

fn cross_sign<T: Lane>(vertices: &[Point; 3]) -> Ordering {
    let [a, b, c] = vertices.map(|p| (T::from_i32(p.x), T::from_i32(p.y)));
    T::cross_sign(b.0 - a.0, c.1 - a.1, b.1 - a.1, c.0 - a.0)
}

impl Primitive for Triangle {}

impl Dimensions for Triangle {
    /// The smallest rectangle holding all three vertices (saturated at the largest `Size`).
    fn bounding_box(&self) -> Rectangle {
        let [a, b, c] = self.vertices;
        let min = a.component_min(b).component_min(c);
        let max = a.component_max(b).component_max(c);
        let side =
            |lo: i32, hi: i32| u32::try_from(i64::from(hi) - i64::from(lo) + 1).unwrap_or(u32::MAX);
        Rectangle::new(min, Size::new(side(min.x, max.x), side(min.y, max.y)))
    }
}

impl Transform for Triangle {
    /// Moves every vertex by `by`, saturating at the `i32` range.
    fn translate(&self, by: Point) -> Self {
        let mut moved = *self;
        moved.translate_mut(by);
        moved
    }

    fn translate_mut(&mut self, by: Point) -> &mut Self {
        for v in &mut self.vertices {
            *v = Point::new(v.x.saturating_add(by.x), v.y.saturating_add(by.y));
        }
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounding_box_saturates() {
        let t = Triangle::new(
            Point::new(i32::MIN, 0),
            Point::new(i32::MAX, 5),
            Point::new(0, -5),
        );
        let bb = t.bounding_box();
        assert_eq!(bb.top_left, Point::new(i32::MIN, -5));
        assert_eq!(bb.size, Size::new(u32::MAX, 11));
    }

    #[test]
    fn translate_saturates() {
        let t = Triangle::new(
            Point::new(i32::MAX, 0),
            Point::new(0, i32::MIN),
            Point::new(1, 1),
        );
        let moved = t.translate(Point::new(5, -5));
        assert_eq!(
            moved.vertices,
            [
                Point::new(i32::MAX, -5),
                Point::new(5, i32::MIN),
                Point::new(6, -4)
            ]
        );
    }

    #[test]
    fn orientation_on_both_paths() {
        let big = Triangle::new(
            Point::new(i32::MIN, i32::MIN),
            Point::new(i32::MAX, i32::MIN),
            Point::new(i32::MIN, i32::MAX),
        );
        assert_eq!(big.orientation(), Orientation::Clockwise);
        let flipped = Triangle::new(big.vertices[0], big.vertices[2], big.vertices[1]);
        assert_eq!(flipped.orientation(), Orientation::CounterClockwise);
        assert_eq!(flipped.doubled_signed_area(), -big.doubled_signed_area());
    }
}
