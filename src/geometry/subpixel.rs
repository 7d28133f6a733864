//! Sub-pixel geometry: vertices with a fraction of a pixel, for smooth motion.

use embedded_graphics::{
    geometry::{Dimensions, Point, Size},
    primitives::{ContainsPoint, PointsIter, Primitive, Rectangle},
    transform::Transform,
};
use fixed::types::{I16F16, I24F8};

use super::{
    Orientation, Points, Triangle,
    triangle::{PointsOf, half_space_covers},
};
use crate::coverage::FillRule;

/// A point with 8 fraction bits: 1/256 of a pixel, as Direct3D's 16.8 vertices, over
/// ±2^23 pixels. Pixel `(x, y)` is the point `(x, y)`, as for [`Point`].
///
/// # Examples
///
/// ```
/// use embedded_graphics::prelude::*;
/// use fixed::types::{I16F16, I24F8};
/// use trirast::geometry::SubPoint;
///
/// let p = SubPoint::new(I24F8::from_num(2.5), I24F8::from_num(-1.25));
/// assert_eq!(p.x.to_bits(), 640); // in 1/256 pixel
/// assert_eq!(SubPoint::from(Point::new(3, 4)), SubPoint::new(I24F8::from_num(3), I24F8::from_num(4)));
/// // From 16.16 (what `Viewport` works in), to the nearest 1/256.
/// let q = SubPoint::from([I16F16::from_num(0.3), I16F16::from_num(7)]);
/// assert_eq!(q.x.to_bits(), 77); // 0.3 * 256 = 76.8
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct SubPoint {
    /// Column, in pixels.
    pub x: I24F8,
    /// Row, in pixels (down).
    pub y: I24F8,
}

impl SubPoint {
    /// The point `(x, y)`.
    ///
    /// # Examples
    ///
    /// ```
    /// use fixed::types::I24F8;
    /// use trirast::geometry::SubPoint;
    ///
    /// const P: SubPoint = SubPoint::new(I24F8::from_bits(384), I24F8::ZERO);
    /// assert_eq!(P.x, I24F8::from_num(1.5));
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(x: I24F8, y: I24F8) -> Self {
        Self { x, y }
    }

    /// The point at pixel `p`, saturating at the type's range (±2^23 pixels).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use fixed::types::I24F8;
    /// use trirast::geometry::SubPoint;
    ///
    /// const P: SubPoint = SubPoint::from_point(Point::new(-2, 5));
    /// assert_eq!((P.x, P.y), (I24F8::from_num(-2), I24F8::from_num(5)));
    /// assert_eq!(SubPoint::from_point(Point::new(i32::MAX, 0)).x, I24F8::MAX);
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_point(p: Point) -> Self {
        Self {
            x: I24F8::from_bits(p.x.saturating_mul(256)),
            y: I24F8::from_bits(p.y.saturating_mul(256)),
        }
    }

    /// The point nearest `[x, y]` (16.16, as [`Viewport`](super::Viewport) and
    /// [`Fragment`](crate::shading::Fragment) use), halves rounded up.
    ///
    /// # Examples
    ///
    /// ```
    /// use fixed::types::I16F16;
    /// use trirast::geometry::SubPoint;
    ///
    /// let p = SubPoint::from_fixed([I16F16::from_bits(0x0001_0080), I16F16::from_bits(-0x80)]);
    /// assert_eq!((p.x.to_bits(), p.y.to_bits()), (257, 0)); // 1 + 1/512 rounds up; so does -1/512
    /// ```
    #[inline]
    #[must_use]
    pub const fn from_fixed([x, y]: [I16F16; 2]) -> Self {
        Self {
            x: nearest_256th(x),
            y: nearest_256th(y),
        }
    }
}

/// `v` to the nearest 1/256, halves up: 16 fraction bits to 8, the dropped bits' top one
/// rounding (the shift floors, so negative halves go up too).
const fn nearest_256th(v: I16F16) -> I24F8 {
    I24F8::from_bits((v.to_bits() >> 8) + ((v.to_bits() >> 7) & 1))
}

impl From<Point> for SubPoint {
    #[inline]
    fn from(p: Point) -> Self {
        Self::from_point(p)
    }
}

impl From<[I16F16; 2]> for SubPoint {
    #[inline]
    fn from(p: [I16F16; 2]) -> Self {
        Self::from_fixed(p)
    }
}

impl From<[I24F8; 2]> for SubPoint {
    #[inline]
    fn from([x, y]: [I24F8; 2]) -> Self {
        Self::new(x, y)
    }
}

/// A triangle whose vertices have a fraction of a pixel (1/256): what moves slowly moves
/// smoothly, instead of a pixel at a time. Pixel `(x, y)` is covered when the point `(x, y)`
/// lies inside the exact triangle, under the fill rule (top-left unless chosen), as for
/// [`Triangle`], which is the special case of whole-pixel vertices: a `SubPixelTriangle` with
/// integer vertices draws exactly what that `Triangle` draws.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*};
/// use fixed::types::I24F8;
/// use trirast::{geometry::{SubPixelTriangle, SubPoint}, FlatStyle};
///
/// let at = |x: f32, y: f32| SubPoint::new(I24F8::from_num(x), I24F8::from_num(y));
/// // A quarter pixel right of whole coordinates: column 0's centres are outside, and the
/// // hypotenuse reaches one column further on each row.
/// let t = SubPixelTriangle::new(at(0.25, 0.0), at(4.25, 0.0), at(0.25, 4.0));
/// let mut display = MockDisplay::new();
/// t.into_styled(FlatStyle::new(BinaryColor::On)).draw(&mut display).unwrap();
/// display.assert_pattern(&[" ####", " ### ", " ##  ", " #   "]);
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct SubPixelTriangle {
    /// The three vertices, in any order.
    pub vertices: [SubPoint; 3],
}

impl SubPixelTriangle {
    /// The triangle through `a`, `b` and `c`.
    ///
    /// # Examples
    ///
    /// ```
    /// use fixed::types::I24F8;
    /// use trirast::geometry::{SubPixelTriangle, SubPoint};
    ///
    /// const ZERO: SubPoint = SubPoint::new(I24F8::ZERO, I24F8::ZERO);
    /// const T: SubPixelTriangle = SubPixelTriangle::new(ZERO, ZERO, ZERO);
    /// assert!(T.is_degenerate());
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(a: SubPoint, b: SubPoint, c: SubPoint) -> Self {
        Self {
            vertices: [a, b, c],
        }
    }

    /// Twice the signed area in 1/65,536 pixel², exact: positive for clockwise triangles on
    /// screen.
    ///
    /// # Examples
    ///
    /// ```
    /// use fixed::types::I24F8;
    /// use trirast::geometry::{SubPixelTriangle, SubPoint};
    ///
    /// let p = |x: i32, y: i32| SubPoint::new(I24F8::from_bits(x), I24F8::from_bits(y));
    /// // Half a pixel by half a pixel, a right angle: area 1/8 pixel², doubled 1/4.
    /// let t = SubPixelTriangle::new(p(0, 0), p(128, 0), p(0, 128));
    /// assert_eq!(t.doubled_signed_area(), 128 * 128);
    /// ```
    #[must_use]
    pub fn doubled_signed_area(&self) -> i128 {
        let [a, b, c] = self
            .vertices
            .map(|p| (i128::from(p.x.to_bits()), i128::from(p.y.to_bits())));
        (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
    }

    /// The winding of the vertices on screen, exactly.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::{geometry::SubPixelTriangle, Orientation, Triangle};
    ///
    /// let t = SubPixelTriangle::from(Triangle::new(Point::new(0, 0), Point::new(10, 0), Point::new(0, 10)));
    /// assert_eq!(t.orientation(), Orientation::Clockwise);
    /// ```
    #[must_use]
    pub fn orientation(&self) -> Orientation {
        use crate::setup::Lane;
        // The sign of the doubled area, in 32-bit products for deltas within 2^15 units (128
        // pixels), 64-bit ones within 2^31, 128-bit beyond: on Cortex-M0 each 64-bit
        // product is a library call, and the 128-bit area took twelve.
        let [first, second, third] = self
            .vertices
            .map(|p| (i64::from(p.x.to_bits()), i64::from(p.y.to_bits())));
        let deltas = [
            second.0 - first.0,
            third.1 - first.1,
            second.1 - first.1,
            third.0 - first.0,
        ];
        let sign = match deltas.map(i32::try_from) {
            [Ok(a), Ok(b), Ok(c), Ok(d)] => i32::cross_sign(a, b, c, d),
            _ => i64::cross_sign(deltas[0], deltas[1], deltas[2], deltas[3]),
        };
        Orientation::of_area_sign(sign)
    }

    /// True when the vertices are collinear or coincident; such triangles draw nothing.
    ///
    /// # Examples
    ///
    /// ```
    /// use fixed::types::I24F8;
    /// use trirast::geometry::{SubPixelTriangle, SubPoint};
    ///
    /// let p = |x: i32, y: i32| SubPoint::new(I24F8::from_bits(x), I24F8::from_bits(y));
    /// assert!(SubPixelTriangle::new(p(0, 0), p(1, 1), p(2, 2)).is_degenerate());
    /// assert!(!SubPixelTriangle::new(p(0, 0), p(1, 0), p(0, 1)).is_degenerate());
    /// ```
    #[must_use]
    pub fn is_degenerate(&self) -> bool {
        self.doubled_signed_area() == 0
    }

    /// True when `rule` draws pixel `point` as part of this triangle: the exact half-space test
    /// of the sample point `(x, y)` against the sub-pixel vertices, which the drawing code
    /// reproduces row by row. For hit tests (a touch on a needle, a pointer over a shape).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use fixed::types::I24F8;
    /// use trirast::{geometry::{SubPixelTriangle, SubPoint}, FillRule};
    ///
    /// let at = |x: f32, y: f32| SubPoint::new(I24F8::from_num(x), I24F8::from_num(y));
    /// let t = SubPixelTriangle::new(at(0.5, 0.0), at(4.0, 0.0), at(0.5, 3.5));
    /// assert!(!t.covers(Point::new(0, 1), FillRule::TopLeft)); // left of the left edge
    /// assert!(t.covers(Point::new(1, 1), FillRule::TopLeft));
    /// assert!(!t.covers(Point::new(3, 1), FillRule::TopLeft)); // on the hypotenuse, right
    /// assert!(t.covers(Point::new(3, 1), FillRule::Inclusive));
    /// ```
    #[must_use]
    pub fn covers(&self, point: Point, rule: FillRule) -> bool {
        let vertices = self
            .vertices
            .map(|p| (i128::from(p.x.to_bits()), i128::from(p.y.to_bits())));
        let sample = (i128::from(point.x) << 8, i128::from(point.y) << 8);
        half_space_covers(vertices, sample, rule)
    }
}

impl PointsIter for SubPixelTriangle {
    type Iter = Points;

    /// The pixels the default top-left rule draws, row by row from the top, left to right in
    /// each, for any vertices: as [`Triangle`]'s points (each row set up again: for
    /// convenience, drawing takes spans).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives::PointsIter};
    /// use fixed::types::I24F8;
    /// use trirast::geometry::{SubPixelTriangle, SubPoint};
    ///
    /// let at = |x: f32, y: f32| SubPoint::new(I24F8::from_num(x), I24F8::from_num(y));
    /// let t = SubPixelTriangle::new(at(0.5, 0.0), at(4.0, 0.0), at(0.5, 3.5));
    /// let points: Vec<Point> = t.points().collect();
    /// assert_eq!(points, [(1, 0), (2, 0), (3, 0), (1, 1), (2, 1), (1, 2)].map(Point::from));
    /// ```
    fn points(&self) -> Points {
        let ys = self.vertices.map(|p| i64::from(p.y.to_bits()));
        let (top, bottom) = (ys[0].min(ys[1]).min(ys[2]), ys[0].max(ys[1]).max(ys[2]));
        // Rows whose samples lie from the top vertex down to the bottom one; none for a
        // degenerate triangle.
        let rows = if self.is_degenerate() {
            0..0
        } else {
            (top + 255) >> 8..(bottom >> 8) + 1
        };
        Points::new(PointsOf::SubPixel(*self), rows)
    }
}

impl ContainsPoint for SubPixelTriangle {
    /// True when `point` is one of the pixels the default top-left rule draws (see
    /// [`SubPixelTriangle::covers`] for either rule).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives::ContainsPoint};
    /// use fixed::types::I24F8;
    /// use trirast::geometry::{SubPixelTriangle, SubPoint};
    ///
    /// let at = |x: f32, y: f32| SubPoint::new(I24F8::from_num(x), I24F8::from_num(y));
    /// let t = SubPixelTriangle::new(at(0.5, 0.0), at(4.0, 0.0), at(0.5, 3.5));
    /// assert!(t.contains(Point::new(1, 1)));
    /// assert!(!t.contains(Point::new(0, 1)));
    /// ```
    #[inline]
    fn contains(&self, point: Point) -> bool {
        self.covers(point, FillRule::TopLeft)
    }
}

impl From<Triangle> for SubPixelTriangle {
    /// The same triangle (vertices saturate at ±2^23 pixels).
    #[inline]
    fn from(t: Triangle) -> Self {
        Self {
            vertices: t.vertices.map(SubPoint::from_point),
        }
    }
}

impl Primitive for SubPixelTriangle {}

impl Dimensions for SubPixelTriangle {
    /// The pixels whose centres the vertices' box spans: every pixel the triangle can cover
    /// (a zero-sized rectangle when it spans no pixel centre).
    fn bounding_box(&self) -> Rectangle {
        let xs = self.vertices.map(|p| i64::from(p.x.to_bits()));
        let ys = self.vertices.map(|p| i64::from(p.y.to_bits()));
        // Whole pixels from the first sample at or after the least coordinate to the last at
        // or before the greatest (shifts floor; within ±2^23 pixels everything fits i32).
        let first = |v: [i64; 3]| ((v[0].min(v[1]).min(v[2]) + 255) >> 8) as i32;
        let last = |v: [i64; 3]| (v[0].max(v[1]).max(v[2]) >> 8) as i32;
        let (x0, y0, x1, y1) = (first(xs), first(ys), last(xs), last(ys));
        let size = if x1 < x0 || y1 < y0 {
            Size::zero()
        } else {
            Size::new((x1 - x0 + 1) as u32, (y1 - y0 + 1) as u32)
        };
        Rectangle::new(Point::new(x0, y0), size)
    }
}

impl Transform for SubPixelTriangle {
    /// Moves every vertex by `by` whole pixels, saturating at the type's range.
    fn translate(&self, by: Point) -> Self {
        let mut moved = *self;
        moved.translate_mut(by);
        moved
    }

    fn translate_mut(&mut self, by: Point) -> &mut Self {
        let by = SubPoint::from_point(by);
        for v in &mut self.vertices {
            v.x = v.x.saturating_add(by.x);
            v.y = v.y.saturating_add(by.y);
        }
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounding_box_spans_the_samples_between_the_vertices() {
        use embedded_graphics::geometry::Dimensions;
        let p = |x: i32, y: i32| SubPoint::new(I24F8::from_bits(x), I24F8::from_bits(y));
        // x from -1.5 to 3.25, y from 0.5 to 2: samples at x -1..=3, y 1..=2.
        let t = SubPixelTriangle::new(p(-384, 128), p(832, 512), p(0, 512));
        assert_eq!(
            t.bounding_box(),
            Rectangle::new(Point::new(-1, 1), Size::new(5, 2))
        );
        // Between two sample rows: no pixel, a zero size.
        let thin = SubPixelTriangle::new(p(0, 300), p(900, 310), p(20, 400));
        assert_eq!(thin.bounding_box().size, Size::zero());
        let far = SubPixelTriangle::new(p(i32::MIN, i32::MIN), p(i32::MAX, 0), p(0, i32::MAX));
        let b = far.bounding_box();
        assert_eq!(
            (b.top_left, b.size),
            (
                Point::new(-(1 << 23), -(1 << 23)),
                Size::new(1 << 24, 1 << 24)
            )
        );
    }

    #[test]
    fn fixed_conversion_rounds_to_nearest() {
        for bits in [
            -1000,
            -129,
            -128,
            -127,
            -1,
            0,
            1,
            127,
            128,
            129,
            1000,
            65_536 * 300 + 77,
        ] {
            let got = SubPoint::from_fixed([I16F16::from_bits(bits), I16F16::ZERO]).x;
            // Nearest multiple of 256 (in 2^-16), halves up.
            let want = (2 * i64::from(bits) + 256).div_euclid(512);
            assert_eq!(i64::from(got.to_bits()), want, "{bits}");
        }
    }
}
