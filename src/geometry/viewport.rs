//! Viewport mapping: normalised device coordinates to pixel vertices and depths.

use embedded_graphics::{
    geometry::{Point, Size},
    primitives::Rectangle,
};
use fixed::types::{I16F16, I24F8};

use super::SubPoint;

/// Maps normalised device coordinates (NDC: x and y from -1 to 1, y up; depth z from -1 near
/// to 1 far) onto an area of pixels, as OpenGL's viewport and depth range do.
///
/// For an area at `(left, top)` of `width` x `height` pixels:
///
/// - `x = left + (x_ndc + 1) * width / 2`
/// - `y = top + (1 - y_ndc) * height / 2` (screens count rows downwards)
/// - `depth = (z_ndc + 1) * 65535 / 2`
///
/// each computed exactly from the `I16F16` input and rounded to the nearest integer, halves
/// up. So NDC -1 and 1 land on the area's edges (x = `left` and `left + width`; a triangle
/// spanning them covers columns `left .. left + width` under the top-left rule), and 0 on its
/// centre. Depths outside -1..=1 are clamped to `0..=65535`; pixel coordinates saturate at the
/// `i32` range. There is no clipping: triangles reaching outside the area are cut to it when
/// drawn.
///
/// [`Viewport::to_ndc`] goes back, rounding to the nearest `I16F16`; for areas up to 32,768
/// pixels across, mapping the result again gives back the same pixel.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{prelude::*, primitives::Rectangle};
/// use fixed::types::I16F16;
/// use trirast::geometry::Viewport;
///
/// let viewport = Viewport::new(Rectangle::new(Point::zero(), Size::new(320, 240)));
/// let one = I16F16::ONE;
/// assert_eq!(viewport.to_pixel([-one, one]), Point::new(0, 0)); // top left
/// assert_eq!(viewport.to_pixel([one, -one]), Point::new(320, 240)); // bottom right
/// assert_eq!(viewport.to_pixel([I16F16::ZERO; 2]), Point::new(160, 120)); // centre
/// assert_eq!(Viewport::to_depth(-one), 0);
/// assert_eq!(Viewport::to_depth(one), 65535);
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Viewport {
    /// The area NDC maps onto.
    pub area: Rectangle,
}

impl Viewport {
    /// A viewport onto `area`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives::Rectangle};
    /// use trirast::geometry::Viewport;
    ///
    /// const SCREEN: Viewport = Viewport::new(Rectangle::new(Point::new(0, 0), Size::new(240, 240)));
    /// assert_eq!(SCREEN.area.size, Size::new(240, 240));
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(area: Rectangle) -> Self {
        Self { area }
    }

    /// The pixel for NDC `[x, y]`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives::Rectangle};
    /// use fixed::types::I16F16;
    /// use trirast::geometry::Viewport;
    ///
    /// let viewport = Viewport::new(Rectangle::new(Point::new(10, 20), Size::new(100, 50)));
    /// let half = I16F16::from_num(0.5);
    /// // x: 10 + 1.5 * 50 = 85; y: 20 + 0.5 * 25 = 32.5, rounded up to 33.
    /// assert_eq!(viewport.to_pixel([half, half]), Point::new(85, 33));
    /// ```
    #[must_use]
    pub fn to_pixel(&self, [x, y]: [I16F16; 2]) -> Point {
        let Size { width, height } = self.area.size;
        let one = i128::from(I16F16::ONE.to_bits());
        // (ndc + 1) * side / 2 in 2^-16 units is (raw + one) * side / 2; rounded half up.
        let map = |raw: i128, side: u32, origin: i32| {
            let twice = (raw + one) * i128::from(side);
            let offset = (twice + one).div_euclid(2 * one);
            saturate(i128::from(origin) + offset)
        };
        Point::new(
            map(i128::from(x.to_bits()), width, self.area.top_left.x),
            map(-i128::from(y.to_bits()), height, self.area.top_left.y),
        )
    }

    /// The sub-pixel point for NDC `[x, y]`: as [`Viewport::to_pixel`], to the nearest 1/256
    /// pixel (halves up) instead of the nearest pixel, saturated to [`SubPoint`]'s range.
    /// Vertices that move by less than a pixel then move the triangle by as much, instead of
    /// jumping a pixel at a time.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives::Rectangle};
    /// use fixed::types::{I16F16, I24F8};
    /// use trirast::geometry::Viewport;
    ///
    /// let viewport = Viewport::new(Rectangle::new(Point::new(10, 20), Size::new(100, 50)));
    /// let half = I16F16::from_num(0.5);
    /// // x: 10 + 1.5 * 50 = 85; y: 20 + 0.5 * 25 = 32.5, kept.
    /// let p = viewport.to_subpixel([half, half]);
    /// assert_eq!((p.x, p.y), (I24F8::from_num(85), I24F8::from_num(32.5)));
    /// ```
    #[must_use]
    pub fn to_subpixel(&self, [x, y]: [I16F16; 2]) -> SubPoint {
        let Size { width, height } = self.area.size;
        let one = i128::from(I16F16::ONE.to_bits());
        // (ndc + 1) * side / 2 pixels, in 1/256: (raw + one) * side * 256 / (2 * one).
        let map = |raw: i128, side: u32, origin: i32| {
            let twice = (raw + one) * i128::from(side) * 256;
            let offset = (twice + one).div_euclid(2 * one);
            let units = (i128::from(origin) * 256 + offset)
                .clamp(i128::from(i32::MIN), i128::from(i32::MAX));
            I24F8::from_bits(units as i32)
        };
        SubPoint::new(
            map(i128::from(x.to_bits()), width, self.area.top_left.x),
            map(-i128::from(y.to_bits()), height, self.area.top_left.y),
        )
    }

    /// [`Viewport::project`] to a sub-pixel point ([`Viewport::to_subpixel`]) and a depth.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives::Rectangle};
    /// use fixed::types::{I16F16, I24F8};
    /// use trirast::geometry::Viewport;
    ///
    /// let viewport = Viewport::new(Rectangle::new(Point::zero(), Size::new(320, 240)));
    /// let (p, depth) = viewport.project_subpixel([I16F16::from_num(0.001), I16F16::ZERO, I16F16::ZERO]);
    /// assert_eq!(p.x.to_bits(), 160 * 256 + 41); // 0.16 pixel right of the centre
    /// assert_eq!(depth, 32768);
    /// ```
    #[must_use]
    pub fn project_subpixel(&self, [x, y, z]: [I16F16; 3]) -> (SubPoint, u16) {
        (self.to_subpixel([x, y]), Self::to_depth(z))
    }

    /// Projects a point in clip coordinates `[x, y, z, w]` (what a projection matrix gives):
    /// NDC `[x, y, z] / w` mapped as [`Viewport::project_subpixel`] maps it, computed exactly
    /// from the clip coordinates and rounded once (halves up), with `w` kept for
    /// perspective-correct texturing ([`Perspective`](crate::texture::Perspective)).
    ///
    /// Points at or behind the viewer (`w` not positive) must be clipped away beforehand:
    /// they are projected as if `w` were the smallest positive `I16F16`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives::Rectangle};
    /// use fixed::types::{I16F16, I24F8};
    /// use trirast::geometry::Viewport;
    ///
    /// let viewport = Viewport::new(Rectangle::new(Point::zero(), Size::new(320, 240)));
    /// let clip = [0.5, 0.25, 0.0, 2.0].map(I16F16::from_num);
    /// let v = viewport.project_clip(clip);
    /// // NDC (0.25, 0.125, 0): x = 1.25 * 160 = 200, y = 0.875 * 120 = 105.
    /// assert_eq!((v.position.x, v.position.y), (I24F8::from_num(200), I24F8::from_num(105)));
    /// assert_eq!((v.depth, v.w), (32768, I16F16::from_num(2)));
    /// ```
    #[must_use]
    pub fn project_clip(&self, [x, y, z, w]: [I16F16; 4]) -> Projected {
        let Size { width, height } = self.area.size;
        let w = w.max(I16F16::DELTA);
        let wide = |v: I16F16| i128::from(v.to_bits());
        let (x, y, z, raw_w) = (wide(x), wide(y), wide(z), wide(w));
        // origin + (v / w + 1) * side / 2 pixels, in 1/256: (v + w) * side * 128 / w.
        let map = |v: i128, side: u32, origin: i32| {
            let twice = (v + raw_w) * i128::from(side) * 256;
            let offset = (twice + raw_w).div_euclid(2 * raw_w);
            let units = (i128::from(origin) * 256 + offset)
                .clamp(i128::from(i32::MIN), i128::from(i32::MAX));
            I24F8::from_bits(units as i32)
        };
        // (z / w + 1) * 65535 / 2.
        let twice = (z + raw_w) * i128::from(u16::MAX);
        let depth = (twice + raw_w)
            .div_euclid(2 * raw_w)
            .clamp(0, i128::from(u16::MAX)) as u16;
        Projected {
            position: SubPoint::new(
                map(x, width, self.area.top_left.x),
                map(-y, height, self.area.top_left.y),
            ),
            depth,
            w,
        }
    }

    /// The depth for NDC `z`: -1 (near) is 0, 1 (far) is 65535, clamped between.
    ///
    /// # Examples
    ///
    /// ```
    /// use fixed::types::I16F16;
    /// use trirast::geometry::Viewport;
    ///
    /// assert_eq!(Viewport::to_depth(I16F16::ZERO), 32768); // 32767.5 rounds up
    /// assert_eq!(Viewport::to_depth(I16F16::from_num(-3)), 0);
    /// ```
    #[must_use]
    pub fn to_depth(z: I16F16) -> u16 {
        let one = i64::from(I16F16::ONE.to_bits());
        let twice = (i64::from(z.to_bits()) + one) * i64::from(u16::MAX);
        (twice + one)
            .div_euclid(2 * one)
            .clamp(0, i64::from(u16::MAX)) as u16
    }

    /// The pixel and depth for NDC `[x, y, z]`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives::Rectangle};
    /// use fixed::types::I16F16;
    /// use trirast::geometry::Viewport;
    ///
    /// let viewport = Viewport::new(Rectangle::new(Point::zero(), Size::new(64, 64)));
    /// let (pixel, depth) = viewport.project([I16F16::ZERO, I16F16::ZERO, -I16F16::ONE]);
    /// assert_eq!((pixel, depth), (Point::new(32, 32), 0));
    /// ```
    #[must_use]
    pub fn project(&self, [x, y, z]: [I16F16; 3]) -> (Point, u16) {
        (self.to_pixel([x, y]), Self::to_depth(z))
    }

    /// NDC `[x, y]` of `pixel`, rounded to the nearest `I16F16` (halves up), saturated to its
    /// range.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{prelude::*, primitives::Rectangle};
    /// use fixed::types::I16F16;
    /// use trirast::geometry::Viewport;
    ///
    /// let viewport = Viewport::new(Rectangle::new(Point::zero(), Size::new(320, 240)));
    /// assert_eq!(viewport.to_ndc(Point::new(160, 0)), [I16F16::ZERO, I16F16::ONE]);
    /// let p = Point::new(17, 203);
    /// assert_eq!(viewport.to_pixel(viewport.to_ndc(p)), p);
    /// ```
    #[must_use]
    pub fn to_ndc(&self, pixel: Point) -> [I16F16; 2] {
        let Size { width, height } = self.area.size;
        let one = i128::from(I16F16::ONE.to_bits());
        // ndc = 2 * (p - origin) / side - 1, in 2^-16 units, rounded half up.
        let unmap = |p: i32, origin: i32, side: u32| {
            let side = i128::from(side.max(1));
            let twice = 2 * (i128::from(p) - i128::from(origin)) * one;
            let raw = (2 * twice + side).div_euclid(2 * side) - one;
            I16F16::from_bits(raw.clamp(i128::from(i32::MIN), i128::from(i32::MAX)) as i32)
        };
        let x = unmap(pixel.x, self.area.top_left.x, width);
        let y = unmap(pixel.y, self.area.top_left.y, height);
        [x, I16F16::from_bits(y.to_bits().saturating_neg())]
    }
}

/// A vertex projected by [`Viewport::project_clip`]: where it lands (to 1/256 pixel), its
/// depth, and its `w` for perspective-correct texturing. A [`MeshVertex`](crate::mesh::MeshVertex).
///
/// # Examples
///
/// ```
/// use embedded_graphics::{prelude::*, primitives::Rectangle};
/// use fixed::types::I16F16;
/// use trirast::{geometry::Viewport, mesh::MeshVertex};
///
/// let viewport = Viewport::new(Rectangle::new(Point::zero(), Size::new(64, 64)));
/// let v = viewport.project_clip([0, 0, 0, 3].map(I16F16::from_num));
/// assert_eq!((v.position(), v.depth(), v.w()), (Point::new(32, 32), 32768, I16F16::from_num(3)));
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct Projected {
    /// Where the vertex lands.
    pub position: SubPoint,
    /// Its depth (0 = near plane, 65535 = far plane).
    pub depth: u16,
    /// Its `w`: distance along the view direction, as the projection gave it.
    pub w: I16F16,
}

/// `value` clamped to the `i32` range.
fn saturate(value: i128) -> i32 {
    value.clamp(i128::from(i32::MIN), i128::from(i32::MAX)) as i32
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ndc(v: f64) -> I16F16 {
        I16F16::from_num(v)
    }

    #[test]
    fn corners_centre_and_extremes() {
        for (w, h) in [(320u32, 240u32), (1, 1), (7, 3), (128, 160)] {
            let vp = Viewport::new(Rectangle::new(Point::new(-5, 9), Size::new(w, h)));
            let (w, h) = (w as i32, h as i32);
            assert_eq!(vp.to_pixel([ndc(-1.0), ndc(1.0)]), Point::new(-5, 9));
            assert_eq!(
                vp.to_pixel([ndc(1.0), ndc(-1.0)]),
                Point::new(-5 + w, 9 + h)
            );
            // The centre, rounded half up for odd sides.
            let centre = vp.to_pixel([I16F16::ZERO; 2]);
            assert_eq!(centre, Point::new(-5 + (w + 1) / 2, 9 + (h + 1) / 2));
            for extreme in [I16F16::MIN, I16F16::MAX] {
                let p = vp.to_pixel([extreme, extreme]);
                assert!(p.x.abs() < 1 << 30 && p.y.abs() < 1 << 30);
            }
        }
        let huge = Viewport::new(Rectangle::new(
            Point::new(i32::MAX - 5, i32::MIN),
            Size::new(u32::MAX, u32::MAX),
        ));
        assert_eq!(huge.to_pixel([I16F16::MAX, I16F16::MAX]).x, i32::MAX);
        assert_eq!(huge.to_pixel([I16F16::MAX, I16F16::MAX]).y, i32::MIN);
    }

    #[test]
    fn round_trip_through_ndc() {
        for (w, h) in [(320u32, 240u32), (1, 1), (7, 3), (32_768, 100)] {
            let vp = Viewport::new(Rectangle::new(Point::new(3, -4), Size::new(w, h)));
            for (x, y) in [
                (3, -4),
                (3 + w as i32, -4 + h as i32),
                (10, 0),
                (3 + w as i32 / 2, 50),
            ] {
                let p = Point::new(x, y);
                assert_eq!(vp.to_pixel(vp.to_ndc(p)), p, "{w}x{h} {p:?}");
            }
        }
    }

    #[test]
    fn depth_mapping() {
        assert_eq!(Viewport::to_depth(ndc(-1.0)), 0);
        assert_eq!(Viewport::to_depth(ndc(1.0)), 65535);
        assert_eq!(Viewport::to_depth(ndc(0.0)), 32768);
        assert_eq!(Viewport::to_depth(I16F16::MIN), 0);
        assert_eq!(Viewport::to_depth(I16F16::MAX), 65535);
        // Monotone over the whole range.
        let mut last = 0;
        for raw in (-70_000..70_000).step_by(7) {
            let d = Viewport::to_depth(I16F16::from_bits(raw));
            assert!(d >= last);
            last = d;
        }
    }

    #[test]
    #[allow(clippy::many_single_char_names)]
    fn clip_coordinates_divide_exactly() {
        let vp = Viewport::new(Rectangle::new(Point::new(-7, 3), Size::new(320, 240)));
        let mut rng = crate::test_rng::XorShift(0x1234_5678_9ABC_DEF0);
        let mut next = |range: i32| (rng.next_u64() % (2 * range as u64 + 1)) as i32 - range;
        for _ in 0..10_000 {
            let [x, y, z] = [(); 3].map(|()| I16F16::from_bits(next(1 << 17)));
            // w = 1: exactly the NDC mapping.
            let one = vp.project_clip([x, y, z, I16F16::ONE]);
            let (position, depth) = vp.project_subpixel([x, y, z]);
            assert_eq!((one.position, one.depth), (position, depth));
            // Scaling all four by k changes nothing.
            let k = next(40).unsigned_abs().max(1) as i32;
            let w = I16F16::from_bits(next(1 << 18).abs().max(1));
            let base = vp.project_clip([x, y, z, w]);
            let scaled = vp.project_clip([x, y, z, w].map(|v| I16F16::from_bits(v.to_bits() * k)));
            assert_eq!((base.position, base.depth), (scaled.position, scaled.depth));
        }
        // Behind the viewer: no panic, saturated.
        let behind = vp.project_clip([I16F16::ONE, -I16F16::ONE, I16F16::ZERO, -I16F16::ONE]);
        assert_eq!(behind.w, I16F16::DELTA);
        assert_eq!(behind.position.x.to_bits(), i32::MAX);
    }
}
