//! Translucent drawing: whatever is drawn is blended over what the pixel already shows.
//!
//! Blending needs the colour already there. The crate's [`Framebuffer`] can be read, so
//! [`Framebuffer::translucent`] gives a target that blends over its pixels. A display driver
//! cannot be read (an SPI display's memory is write-only in practice), so [`OverBackground`]
//! blends over a background colour the caller knows, the way smooth-font renderers draw on
//! such displays, and writes the result through.
//!
//! Both are ordinary embedded-graphics `DrawTarget`s: every style of the crate (and any other
//! drawable) becomes translucent through them, with no other change. Triangles sharing an edge
//! write each pixel of it once (the top-left rule), so a translucent mesh is blended exactly
//! once per pixel, without the double-dark seams that overlapping edges leave.

use core::convert::Infallible;

use embedded_graphics::{
    Pixel, draw_target::DrawTarget, geometry::Dimensions, primitives::Rectangle,
};

use super::{Framebuffer, StoredPixel};
use crate::{
    geometry::Shape,
    shading::{ChannelColor, TriangleStyle, paint::draw_anti_aliased},
};

/// A target that can blend what is drawn over what it shows, at any opacity: the crate's
/// [`Framebuffer`] (which reads its pixels), [`Translucent`] and [`OverBackground`] (which
/// blends over a colour the caller knows, for displays that cannot be read). Anti-aliased
/// drawing needs one: each edge pixel is blended by how much of it the triangle covers.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::{Gray8, GrayColor}, prelude::*, primitives::Rectangle};
/// use trirast::{target::BlendTarget, Framebuffer};
///
/// let mut pixels = [Gray8::new(100); 4 * 4];
/// let mut frame = Framebuffer::new(&mut pixels, 4, 4)?;
/// let area = Rectangle::new(Point::zero(), Size::new(2, 1));
/// frame.blend_contiguous(&area, [Gray8::WHITE, Gray8::BLACK], 51).unwrap();
/// assert_eq!(frame.pixel(Point::new(0, 0)), Some(Gray8::new(131)));
/// assert_eq!(frame.pixel(Point::new(1, 0)), Some(Gray8::new(80)));
/// # Ok::<(), trirast::Error>(())
/// ```
pub trait BlendTarget: DrawTarget<Color: ChannelColor> {
    /// Blends `colors` (one per pixel of `area`, row by row) over the pixels of `area` at
    /// `opacity` (255: opaque), by [`blend`]. Pixels outside the target are skipped.
    ///
    /// # Errors
    ///
    /// The target's.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::{Rgb565, RgbColor}, prelude::*, primitives::Rectangle};
    /// use trirast::{target::{blend, BlendTarget}, Framebuffer};
    ///
    /// let mut pixels = [Rgb565::BLUE; 2];
    /// let mut frame = Framebuffer::new(&mut pixels, 2, 1)?;
    /// let area = Rectangle::new(Point::new(1, 0), Size::new(1, 1));
    /// frame.blend_contiguous(&area, [Rgb565::RED], 128).unwrap();
    /// assert_eq!(pixels, [Rgb565::BLUE, blend(Rgb565::RED, Rgb565::BLUE, 128)]);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    fn blend_contiguous<I>(
        &mut self,
        area: &Rectangle,
        colors: I,
        opacity: u8,
    ) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Self::Color>;

    /// Blends `color` over every pixel of `area` at `opacity`.
    ///
    /// # Errors
    ///
    /// The target's.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::{Gray8, GrayColor}, prelude::*, primitives::Rectangle};
    /// use trirast::{target::BlendTarget, Framebuffer};
    ///
    /// let mut pixels = [Gray8::new(0); 3];
    /// let mut frame = Framebuffer::new(&mut pixels, 3, 1)?;
    /// frame.blend_solid(&Rectangle::new(Point::zero(), Size::new(3, 1)), Gray8::WHITE, 255).unwrap();
    /// assert_eq!(pixels, [Gray8::WHITE; 3]);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    fn blend_solid(
        &mut self,
        area: &Rectangle,
        color: Self::Color,
        opacity: u8,
    ) -> Result<(), Self::Error> {
        let pixels = area.size.width as usize * area.size.height as usize;
        self.blend_contiguous(area, core::iter::repeat_n(color, pixels), opacity)
    }

    /// Blends each colour of `pixels` over the pixels of `area` (row by row) at the opacity
    /// paired with it: anti-aliasing's edge pixels, each at its coverage. Pixels outside the
    /// target are skipped.
    ///
    /// # Errors
    ///
    /// The target's.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::{Gray8, GrayColor}, prelude::*, primitives::Rectangle};
    /// use trirast::{target::BlendTarget, Framebuffer};
    ///
    /// let mut pixels = [Gray8::BLACK; 3];
    /// let mut frame = Framebuffer::new(&mut pixels, 3, 1)?;
    /// let area = Rectangle::new(Point::zero(), Size::new(3, 1));
    /// frame.blend_each(&area, [(Gray8::WHITE, 255), (Gray8::WHITE, 51), (Gray8::WHITE, 0)]).unwrap();
    /// assert_eq!(pixels, [Gray8::WHITE, Gray8::new(51), Gray8::BLACK]);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    fn blend_each<I>(&mut self, area: &Rectangle, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = (Self::Color, u8)>,
    {
        let width = area.size.width.max(1);
        for (k, (color, opacity)) in (0u32..).zip(pixels) {
            let at = area.top_left
                + embedded_graphics::geometry::Point::new((k % width) as i32, (k / width) as i32);
            if k / width >= area.size.height {
                break;
            }
            let one = Rectangle::new(at, embedded_graphics::geometry::Size::new(1, 1));
            self.blend_contiguous(&one, core::iter::once(color), opacity)?;
        }
        Ok(())
    }

    /// Draws `triangle` with `style` (any of the crate's styles) with anti-aliased edges:
    /// each pixel is blended by the area of its square (side 1, centred on the pixel) inside
    /// the triangle, within 1/256 (see
    /// [`for_each_coverage_run`](crate::coverage::for_each_coverage_run)). Pixels whose square
    /// lies wholly inside are drawn as without anti-aliasing, in runs; only the pixels an edge
    /// crosses are computed and blended one by one. The style's fill rule plays no part.
    ///
    /// Edge pixels take the style's colour at their centre, which may lie just outside the
    /// triangle: Gouraud colours there are kept within the range of the vertices' colours,
    /// textures are addressed as anywhere else, and a shader's attributes are extrapolated.
    /// Triangles sharing an edge each blend their part of its pixels, so a mesh shows its
    /// background faintly along inner edges (the usual price of coverage as opacity).
    ///
    /// # Errors
    ///
    /// The target's.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::{Gray8, GrayColor}, prelude::*};
    /// use trirast::{target::BlendTarget, FlatStyle, Framebuffer, Triangle};
    ///
    /// let mut pixels = [Gray8::BLACK; 16 * 16];
    /// let mut frame = Framebuffer::new(&mut pixels, 16, 16)?;
    /// let triangle = Triangle::new(Point::new(1, 1), Point::new(14, 4), Point::new(4, 14));
    /// frame.draw_anti_aliased(&triangle, &FlatStyle::new(Gray8::WHITE)).unwrap();
    /// // Inside: white; on the edges: shades of grey; outside: black.
    /// assert_eq!(frame.pixel(Point::new(5, 5)), Some(Gray8::WHITE));
    /// let edge = frame.pixel(Point::new(9, 9)).unwrap().luma();
    /// assert!(edge > 0 && edge < 255);
    /// assert_eq!(frame.pixel(Point::new(13, 13)), Some(Gray8::BLACK));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    fn draw_anti_aliased<G, S>(&mut self, triangle: &G, style: &S) -> Result<(), Self::Error>
    where
        G: Shape,
        S: TriangleStyle<Color = Self::Color>,
        Self: Sized,
    {
        draw_anti_aliased(triangle, style, self)
    }
}

/// `a * b / 255`, rounded to nearest: two opacities applied one after the other.
#[inline]
fn combined(a: u8, b: u8) -> u8 {
    ((u32::from(a) * u32::from(b) + 127) / 255) as u8
}

/// `source` drawn over `destination` at `opacity` (255: `source`, 0: `destination`): each
/// channel within 3/5 of a level of `(source * opacity + destination * (255 - opacity)) /
/// 255`; 8-bit channels rounded to nearest, so within half a level (see
/// [`ChannelColor::over`]).
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::{Gray8, GrayColor, Rgb565, RgbColor};
/// use trirast::target::blend;
///
/// assert_eq!(blend(Gray8::new(200), Gray8::new(100), 128), Gray8::new(150));
/// assert_eq!(blend(Rgb565::RED, Rgb565::BLUE, 255), Rgb565::RED);
/// assert_eq!(blend(Rgb565::RED, Rgb565::BLUE, 0), Rgb565::BLUE);
/// ```
#[must_use]
#[inline]
pub fn blend<C: ChannelColor>(source: C, destination: C, opacity: u8) -> C {
    source.over(destination, opacity)
}

impl<'a, C, S> Framebuffer<'a, C, S>
where
    C: ChannelColor,
    S: StoredPixel<C>,
{
    /// This framebuffer as a target that blends everything drawn into it over its pixels at
    /// `opacity` (255: opaque, 0: invisible), by [`blend`].
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
    /// use trirast::{target::blend, FlatStyle, Framebuffer, Triangle};
    ///
    /// let mut pixels = [Rgb565::BLUE; 16 * 16];
    /// let mut frame = Framebuffer::new(&mut pixels, 16, 16)?;
    /// let t = Triangle::new(Point::new(0, 0), Point::new(16, 0), Point::new(0, 16));
    /// t.into_styled(FlatStyle::new(Rgb565::RED)).draw(&mut frame.translucent(128)).unwrap();
    /// assert_eq!(frame.pixel(Point::new(2, 2)), Some(blend(Rgb565::RED, Rgb565::BLUE, 128)));
    /// assert_eq!(frame.pixel(Point::new(15, 15)), Some(Rgb565::BLUE));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn translucent(&mut self, opacity: u8) -> Translucent<'_, 'a, C, S> {
        Translucent {
            frame: self,
            opacity,
        }
    }
}

/// A [`Framebuffer`] that blends everything drawn into it over its pixels: see
/// [`Framebuffer::translucent`].
///
/// Solid fills over a uniform background blend once per run of equal pixels, not once per
/// pixel.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::{Gray8, GrayColor}, prelude::*, primitives::Rectangle};
/// use trirast::Framebuffer;
///
/// let mut pixels = [Gray8::new(100); 4 * 4];
/// let mut frame = Framebuffer::new(&mut pixels, 4, 4)?;
/// // Any drawable, not only triangles: white at 25% over 100.
/// let mut translucent = frame.translucent(64);
/// translucent.fill_solid(&Rectangle::new(Point::zero(), Size::new(2, 2)), Gray8::WHITE).unwrap();
/// assert_eq!(frame.pixel(Point::new(1, 1)), Some(Gray8::new(139)));
/// assert_eq!(frame.pixel(Point::new(3, 3)), Some(Gray8::new(100)));
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Debug)]
pub struct Translucent<'f, 'a, C, S = C> {
    frame: &'f mut Framebuffer<'a, C, S>,
    opacity: u8,
}

impl<C, S> Translucent<'_, '_, C, S> {
    /// The opacity everything is drawn with.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use trirast::Framebuffer;
    ///
    /// let mut pixels = [Gray8::new(0); 4];
    /// let mut frame = Framebuffer::new(&mut pixels, 2, 2)?;
    /// assert_eq!(frame.translucent(90).opacity(), 90);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn opacity(&self) -> u8 {
        self.opacity
    }
}

impl<C, S> Dimensions for Translucent<'_, '_, C, S> {
    fn bounding_box(&self) -> Rectangle {
        self.frame.bounding_box()
    }
}

impl<C, S> DrawTarget for Translucent<'_, '_, C, S>
where
    C: ChannelColor,
    S: StoredPixel<C>,
{
    type Color = C;
    type Error = Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<C>>,
    {
        for Pixel(point, color) in pixels {
            if let Some(pixel) = self.frame.pixel_mut(point) {
                *pixel = S::store(blend(color, pixel.load(), self.opacity));
            }
        }
        Ok(())
    }

    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = C>,
    {
        let opacity = self.opacity;
        self.frame
            .blend_each(area, colors.into_iter().map(|color| (color, opacity)))
    }

    fn fill_solid(&mut self, area: &Rectangle, color: C) -> Result<(), Self::Error> {
        let opacity = self.opacity;
        if area.size.height == 1 {
            // One row inside (a triangle's span): the first pixel blended, then each pixel
            // that differs from the one before it.
            let (x, y) = (area.top_left.x, area.top_left.y);
            if let Some(row) = self.frame.row_mut(y, x, area.size.width) {
                let Some(first) = row.first().map(|p| p.load()) else {
                    return Ok(());
                };
                let (mut seen, mut result) = (first, S::store(blend(color, first, opacity)));
                for pixel in row {
                    let under = pixel.load();
                    if under != seen {
                        seen = under;
                        result = S::store(blend(color, under, opacity));
                    }
                    *pixel = result;
                }
                return Ok(());
            }
        }
        // Pixels often repeat (a background, an earlier fill): blend each new one once.
        let mut last: Option<(C, S)> = None;
        // One colour for every pixel: skipping those outside the image is free.
        let mut colors = core::iter::repeat(color);
        self.frame.zip_area(area, &mut colors, |pixel, color| {
            let under = pixel.load();
            let blended = match last {
                Some((seen, result)) if seen == under => result,
                _ => {
                    let result = S::store(blend(color, under, opacity));
                    last = Some((under, result));
                    result
                }
            };
            *pixel = blended;
        });
        Ok(())
    }
}

impl<C, S> BlendTarget for Framebuffer<'_, C, S>
where
    C: ChannelColor,
    S: StoredPixel<C>,
{
    fn blend_contiguous<I>(
        &mut self,
        area: &Rectangle,
        colors: I,
        opacity: u8,
    ) -> Result<(), Infallible>
    where
        I: IntoIterator<Item = C>,
    {
        self.translucent(opacity).fill_contiguous(area, colors)
    }

    fn blend_each<I>(&mut self, area: &Rectangle, pixels: I) -> Result<(), Infallible>
    where
        I: IntoIterator<Item = (C, u8)>,
    {
        if area.size.height == 1 {
            // One row inside: anti-aliasing's edge runs.
            let (y, x) = (area.top_left.y, area.top_left.x);
            if let Some(row) = self.row_mut(y, x, area.size.width) {
                for (pixel, (color, opacity)) in row.iter_mut().zip(pixels) {
                    *pixel = S::store(blend(color, pixel.load(), opacity));
                }
                return Ok(());
            }
        }
        // Partly outside, or several rows: the shared clipped walk.
        self.zip_area(area, &mut pixels.into_iter(), |pixel, (color, opacity)| {
            *pixel = S::store(blend(color, pixel.load(), opacity));
        });
        Ok(())
    }

    fn blend_solid(&mut self, area: &Rectangle, color: C, opacity: u8) -> Result<(), Infallible> {
        self.translucent(opacity).fill_solid(area, color)
    }
}

impl<C, S> BlendTarget for Translucent<'_, '_, C, S>
where
    C: ChannelColor,
    S: StoredPixel<C>,
{
    fn blend_each<I>(&mut self, area: &Rectangle, pixels: I) -> Result<(), Infallible>
    where
        I: IntoIterator<Item = (C, u8)>,
    {
        let opacity = self.opacity;
        let pixels = pixels.into_iter().map(|(c, o)| (c, combined(o, opacity)));
        self.frame.blend_each(area, pixels)
    }

    fn blend_contiguous<I>(
        &mut self,
        area: &Rectangle,
        colors: I,
        opacity: u8,
    ) -> Result<(), Infallible>
    where
        I: IntoIterator<Item = C>,
    {
        let opacity = combined(opacity, self.opacity);
        self.frame
            .translucent(opacity)
            .fill_contiguous(area, colors)
    }

    fn blend_solid(&mut self, area: &Rectangle, color: C, opacity: u8) -> Result<(), Infallible> {
        let opacity = combined(opacity, self.opacity);
        self.frame.translucent(opacity).fill_solid(area, color)
    }
}

/// Any target drawn translucently over a background colour the caller knows: each colour is
/// blended over `background` at `opacity` (by [`blend`]) and drawn through. For targets that
/// cannot be read, such as display drivers: anti-aliased or translucent shapes straight to
/// the display, provided they lie over that background.
///
/// Solid fills stay solid fills (one blend per call), so a display driver still gets one
/// window per span.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::Rgb565, prelude::*};
/// use trirast::{target::{blend, OverBackground}, FlatStyle, Triangle};
///
/// let mut display = MockDisplay::<Rgb565>::new();
/// let mut translucent = OverBackground::new(&mut display, Rgb565::BLACK, 64);
/// let t = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
/// t.into_styled(FlatStyle::new(Rgb565::WHITE)).draw(&mut translucent).unwrap();
/// assert_eq!(display.get_pixel(Point::new(1, 1)), Some(blend(Rgb565::WHITE, Rgb565::BLACK, 64)));
/// ```
#[derive(Debug)]
pub struct OverBackground<'d, D: DrawTarget> {
    target: &'d mut D,
    background: D::Color,
    opacity: u8,
}

impl<'d, D> OverBackground<'d, D>
where
    D: DrawTarget,
    D::Color: ChannelColor,
{
    /// Draws into `target` blended over `background` at `opacity` (255: opaque).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::{Gray8, GrayColor}};
    /// use trirast::target::OverBackground;
    ///
    /// let mut display = MockDisplay::<Gray8>::new();
    /// let over = OverBackground::new(&mut display, Gray8::BLACK, 200);
    /// assert_eq!(over.opacity(), 200);
    /// ```
    pub fn new(target: &'d mut D, background: D::Color, opacity: u8) -> Self {
        Self {
            target,
            background,
            opacity,
        }
    }

    /// The opacity everything is drawn with.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor};
    /// use trirast::target::OverBackground;
    ///
    /// let mut display = MockDisplay::<BinaryColor>::new();
    /// assert_eq!(OverBackground::new(&mut display, BinaryColor::Off, 7).opacity(), 7);
    /// ```
    #[must_use]
    pub fn opacity(&self) -> u8 {
        self.opacity
    }

    #[inline(always)]
    fn over(&self, color: D::Color) -> D::Color {
        blend(color, self.background, self.opacity)
    }
}

impl<D: DrawTarget> Dimensions for OverBackground<'_, D> {
    fn bounding_box(&self) -> Rectangle {
        self.target.bounding_box()
    }
}

impl<D> DrawTarget for OverBackground<'_, D>
where
    D: DrawTarget,
    D::Color: ChannelColor,
{
    type Color = D::Color;
    type Error = D::Error;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<D::Color>>,
    {
        let (background, opacity) = (self.background, self.opacity);
        self.target.draw_iter(
            pixels
                .into_iter()
                .map(|Pixel(p, c)| Pixel(p, blend(c, background, opacity))),
        )
    }

    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = D::Color>,
    {
        let (background, opacity) = (self.background, self.opacity);
        self.target.fill_contiguous(
            area,
            colors.into_iter().map(|c| blend(c, background, opacity)),
        )
    }

    fn fill_solid(&mut self, area: &Rectangle, color: D::Color) -> Result<(), Self::Error> {
        let color = self.over(color);
        self.target.fill_solid(area, color)
    }

    fn clear(&mut self, color: D::Color) -> Result<(), Self::Error> {
        let color = self.over(color);
        self.target.clear(color)
    }
}

impl<D> BlendTarget for OverBackground<'_, D>
where
    D: DrawTarget,
    D::Color: ChannelColor,
{
    fn blend_contiguous<I>(
        &mut self,
        area: &Rectangle,
        colors: I,
        opacity: u8,
    ) -> Result<(), D::Error>
    where
        I: IntoIterator<Item = D::Color>,
    {
        let (background, opacity) = (self.background, combined(opacity, self.opacity));
        self.target.fill_contiguous(
            area,
            colors.into_iter().map(|c| blend(c, background, opacity)),
        )
    }

    fn blend_each<I>(&mut self, area: &Rectangle, pixels: I) -> Result<(), D::Error>
    where
        I: IntoIterator<Item = (D::Color, u8)>,
    {
        let (background, over) = (self.background, self.opacity);
        self.target.fill_contiguous(
            area,
            pixels
                .into_iter()
                .map(|(c, o)| blend(c, background, combined(o, over))),
        )
    }

    fn blend_solid(
        &mut self,
        area: &Rectangle,
        color: D::Color,
        opacity: u8,
    ) -> Result<(), D::Error> {
        let opacity = combined(opacity, self.opacity);
        self.target
            .fill_solid(area, blend(color, self.background, opacity))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_graphics::pixelcolor::{Gray4, Gray8, Rgb565, Rgb888};

    /// Every channel within the documented bound of the exact blend (half a level for 8-bit
    /// channels, 3/5 of a level for narrower ones), for every pair of channel values and
    /// every opacity.
    fn check<C: ChannelColor + core::fmt::Debug>(values: &[C]) {
        // |c - n / 255| <= bound  <=>  |1275 c - 5 n| <= 1275 * bound
        let bound = if C::WEIGHT_BITS == 8 { 765 } else { 637 };
        for &s in values {
            for &d in values {
                for opacity in 0..=255u8 {
                    let got = blend(s, d, opacity);
                    let (a, b) = (i64::from(opacity), 255 - i64::from(opacity));
                    let channels = s.channels();
                    for (k, &c) in got.channels().as_ref().iter().enumerate() {
                        let numerator = i64::from(channels.as_ref()[k]) * a
                            + i64::from(d.channels().as_ref()[k]) * b;
                        assert!(
                            (1275 * i64::from(c) - 5 * numerator).abs() <= bound,
                            "{s:?} over {d:?} at {opacity}"
                        );
                    }
                    if opacity == 255 {
                        assert_eq!(got, s);
                    }
                    if opacity == 0 {
                        assert_eq!(got, d);
                    }
                }
            }
        }
    }

    /// Areas partly outside: each pixel inside takes its own colour of the area's row-major
    /// sequence, blended over what it held; the rest stay; solid fills likewise.
    #[test]
    fn clipped_areas_blend_the_right_colours() {
        use embedded_graphics::{geometry::Point, prelude::Size};
        let under = |i: usize| Gray8::new(i as u8 * 10);
        let mut pixels: [Gray8; 12] = core::array::from_fn(under);
        let mut frame = Framebuffer::new(&mut pixels, 4, 3).unwrap();
        // A 3 x 3 area hanging off the top-left corner, colours 20, 40, ... 180 row by row.
        let area = Rectangle::new(Point::new(-1, -1), Size::new(3, 3));
        let colors = (1..=9u8).map(|k| Gray8::new(k * 20));
        frame
            .translucent(100)
            .fill_contiguous(&area, colors)
            .unwrap();
        for (i, &p) in pixels.iter().enumerate() {
            let (x, y) = (i % 4, i / 4);
            let want = if x < 2 && y < 2 {
                let k = (y + 1) * 3 + (x + 1) + 1;
                blend(Gray8::new(k as u8 * 20), under(i), 100)
            } else {
                under(i)
            };
            assert_eq!(p, want, "pixel {i}");
        }
        let mut pixels: [Gray8; 12] = core::array::from_fn(under);
        let mut frame = Framebuffer::new(&mut pixels, 4, 3).unwrap();
        let area = Rectangle::new(Point::new(2, 1), Size::new(9, 9));
        frame
            .translucent(30)
            .fill_solid(&area, Gray8::new(255))
            .unwrap();
        for (i, &p) in pixels.iter().enumerate() {
            let inside = i % 4 >= 2 && i / 4 >= 1;
            let want = if inside {
                blend(Gray8::new(255), under(i), 30)
            } else {
                under(i)
            };
            assert_eq!(p, want, "pixel {i}");
        }
    }

    #[test]
    fn blends_are_within_their_bound() {
        let gray8: [Gray8; 256] = core::array::from_fn(|i| Gray8::new(i as u8));
        let gray4: [Gray4; 16] = core::array::from_fn(|i| Gray4::new(i as u8));
        let rgb565: [Rgb565; 110] = core::array::from_fn(|i| {
            let (r, g) = ((i / 10 * 3) as u8, (i % 10 * 7) as u8);
            Rgb565::new(r, g, 31 - r)
        });
        let rgb888: [Rgb888; 16] = core::array::from_fn(|i| {
            let v = (i * 17) as u8;
            Rgb888::new(v, 255 - v, v / 3)
        });
        check(&gray8);
        check(&gray4);
        check(&rgb565);
        check(&rgb888);
    }
}
