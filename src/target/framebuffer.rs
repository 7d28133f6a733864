//! A `DrawTarget` over caller-provided pixel memory.

use core::{convert::Infallible, fmt, marker::PhantomData};

use embedded_graphics::{
    Pixel,
    draw_target::DrawTarget,
    geometry::{OriginDimensions, Point, Size},
    pixelcolor::PixelColor,
    primitives::Rectangle,
};

use super::StoredPixel;
use crate::Error;

/// A framebuffer over a borrowed slice, one element per pixel, rows top to bottom.
///
/// `fill_solid` and `fill_contiguous` clip the area once and then write whole row slices, so a
/// span costs about what `slice::fill` costs. Nothing is allocated; the slice can live in a
/// `static`, on the stack, or in memory shared with a DMA engine.
///
/// `S` is how each pixel is stored: the colour type itself (the default) or, for the usual
/// colour types, its raw integer (see [`StoredPixel`]).
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
/// use trirast::Framebuffer;
///
/// // Typed pixels.
/// let mut pixels = [Rgb565::BLACK; 320 * 240];
/// let mut fb = Framebuffer::new(&mut pixels, 320, 240)?;
/// fb.fill_solid(&Rectangle::new(Point::new(-5, 10), Size::new(20, 2)), Rgb565::RED).unwrap();
/// assert_eq!(fb.pixel(Point::new(0, 10)), Some(Rgb565::RED));
///
/// // Raw `u16` pixels, as an SPI display driver or DMA transfer wants them.
/// let mut raw = [0u16; 16 * 16];
/// let mut fb: Framebuffer<Rgb565, u16> = Framebuffer::new(&mut raw, 16, 16)?;
/// fb.clear(Rgb565::BLUE).unwrap();
/// assert_eq!(raw[0], 0x001F);
/// # Ok::<(), trirast::Error>(())
/// ```
pub struct Framebuffer<'a, C, S = C> {
    pixels: &'a mut [S],
    width: usize,
    height: usize,
    color: PhantomData<C>,
}

impl<'a, C, S> Framebuffer<'a, C, S>
where
    C: PixelColor,
    S: StoredPixel<C>,
{
    /// Wraps `pixels` as a `width` x `height` image.
    ///
    /// # Errors
    ///
    /// [`Error::BufferLength`] unless `pixels.len() == width * height`;
    /// [`Error::DimensionsTooLarge`] if a side exceeds `i32::MAX` or the product overflows.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use trirast::{Error, Framebuffer};
    ///
    /// let mut pixels = [Gray8::new(0); 64 * 32];
    /// assert!(Framebuffer::new(&mut pixels, 64, 32).is_ok());
    /// assert!(matches!(Framebuffer::new(&mut pixels, 64, 64), Err(Error::BufferLength { .. })));
    /// ```
    pub fn new(pixels: &'a mut [S], width: u32, height: u32) -> Result<Self, Error> {
        let too_large = Error::DimensionsTooLarge { width, height };
        let side = |v: u32| i32::try_from(v).ok().and_then(|v| usize::try_from(v).ok());
        let (Some(w), Some(h)) = (side(width), side(height)) else {
            return Err(too_large);
        };
        let expected = w.checked_mul(h).ok_or(too_large)?;
        if pixels.len() != expected {
            return Err(Error::BufferLength {
                expected,
                actual: pixels.len(),
            });
        }
        Ok(Self {
            pixels,
            width: w,
            height: h,
            color: PhantomData,
        })
    }

    /// The colour at `point`, or `None` outside the image.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
    /// use trirast::Framebuffer;
    ///
    /// let mut pixels = [BinaryColor::Off; 8 * 8];
    /// let fb = Framebuffer::new(&mut pixels, 8, 8)?;
    /// assert_eq!(fb.pixel(Point::new(7, 7)), Some(BinaryColor::Off));
    /// assert_eq!(fb.pixel(Point::new(8, 0)), None);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn pixel(&self, point: Point) -> Option<C> {
        self.index(point).map(|i| self.pixels[i].load())
    }

    /// The stored pixels, row-major.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
    /// use trirast::Framebuffer;
    ///
    /// let mut raw = [0u16; 4 * 2];
    /// let mut fb: Framebuffer<Rgb565, u16> = Framebuffer::new(&mut raw, 4, 2)?;
    /// fb.clear(Rgb565::WHITE).unwrap();
    /// assert!(fb.pixels().iter().all(|&p| p == 0xFFFF));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn pixels(&self) -> &[S] {
        self.pixels
    }

    /// The stored pixels, row-major, writable.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use trirast::Framebuffer;
    ///
    /// let mut pixels = [Gray8::BLACK; 3 * 3];
    /// let mut fb = Framebuffer::new(&mut pixels, 3, 3)?;
    /// fb.pixels_mut()[4] = Gray8::WHITE;
    /// assert_eq!(fb.pixel(Point::new(1, 1)), Some(Gray8::WHITE));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn pixels_mut(&mut self) -> &mut [S] {
        self.pixels
    }

    /// Index of `point` in the slice, if inside.
    #[inline]
    fn index(&self, point: Point) -> Option<usize> {
        let x = usize::try_from(point.x).ok().filter(|&x| x < self.width)?;
        let y = usize::try_from(point.y).ok().filter(|&y| y < self.height)?;
        Some(y * self.width + x)
    }

    /// Fills `len` pixels of row `y` from column `x`, clipped.
    #[inline(always)]
    fn fill_row(&mut self, y: i32, x: i32, len: u32, value: S) {
        if let Some(run) = self.row_run(y, x, len) {
            // In this row: the rasterizer's spans always are.
            fill_run(run, value);
        } else {
            self.fill_row_clipped(y, x, len, value);
        }
    }

    /// [`Self::fill_row`] for rows that stick out.
    #[inline(never)]
    #[cold]
    fn fill_row_clipped(&mut self, y: i32, x: i32, len: u32, value: S) {
        let Ok(row) = usize::try_from(y) else { return };
        if row >= self.height {
            return;
        }
        let start = row * self.width;
        let end = (i64::from(x) + i64::from(len)).clamp(0, self.width as i64) as usize;
        let column = x.max(0) as usize;
        if let Some(run) = self.pixels.get_mut(start + column..start + end) {
            fill_run(run, value);
        }
    }

    /// `fill_contiguous` for areas of several rows (a band copied to the screen, say) or partly
    /// outside. Out of line, taking `colors` by value: the span loop's colour state is not
    /// pinned to memory. Areas inside the image are copied row by row (as one run when the
    /// rows are as wide as the image); the rest goes to
    /// [`Self::fill_contiguous_clipped`], type-erased.
    #[inline(never)]
    fn fill_contiguous_rows<I: Iterator<Item = C>>(&mut self, area: &Rectangle, mut colors: I) {
        match self.clip(area) {
            Some(window)
                if window.x0 as i64 == i64::from(area.top_left.x)
                    && window.y0 as i64 == i64::from(area.top_left.y)
                    && (window.x1 - window.x0) as u64 == u64::from(area.size.width)
                    && (window.y1 - window.y0) as u64 == u64::from(area.size.height) =>
            {
                // Rows as wide as the image (a band copied to the screen) lie end to end: one
                // run, without a row loop's set-up per row.
                let (runs, run_len) = if window.x1 - window.x0 == self.width {
                    (
                        window.y0..window.y0 + 1,
                        self.width * (window.y1 - window.y0),
                    )
                } else {
                    (window.y0..window.y1, window.x1 - window.x0)
                };
                for y in runs {
                    let start = y * self.width + window.x0;
                    let Some(run) = self.pixels.get_mut(start..start + run_len) else {
                        return;
                    };
                    let mut written = 0;
                    run.iter_mut()
                        .zip(colors.by_ref())
                        .for_each(|(dst, color)| {
                            *dst = S::store(color);
                            written += 1;
                        });
                    if written < run.len() {
                        return;
                    }
                }
            }
            _ => self.fill_contiguous_clipped(area, &mut Pull(&mut colors)),
        }
    }

    /// `fill_contiguous` for one row partly outside the image (never a rasterizer span: those
    /// are clipped to the target). Out of line and taking `colors` by value, as
    /// [`Self::fill_contiguous_rows`]: a small per-shader shim into the type-erased
    /// [`Self::fill_contiguous_clipped`].
    #[inline(never)]
    fn fill_contiguous_row_clipped<I: Iterator<Item = C>>(
        &mut self,
        area: &Rectangle,
        mut colors: I,
    ) {
        self.fill_row_clipped_erased(area, &mut Pull(&mut colors));
    }

    /// [`Self::fill_contiguous_clipped`] for one row: its colours left of the image skipped
    /// one by one, the rest written until the row leaves the image (the general walk, with
    /// rows above, below and to the right, cost each shading style's firmware ~300 bytes more).
    #[inline(never)]
    fn fill_row_clipped_erased(&mut self, area: &Rectangle, colors: &mut Pull<'_, C>) {
        let Some(window) = self.clip(area) else {
            return;
        };
        let left = (window.x0 as i64 - i64::from(area.top_left.x)) as u64;
        // One by one, not through `skip` (whose `nth` in chunks cost each share 48 more bytes
        // on Cortex-M0): every element is a call through `Pull` either way.
        for _ in 0..left {
            if colors.next().is_none() {
                return;
            }
        }
        let start = window.y0 * self.width;
        if let Some(row) = self.pixels.get_mut(start + window.x0..start + window.x1) {
            for (dst, color) in row.iter_mut().zip(colors) {
                *dst = S::store(color);
            }
        }
    }

    /// `fill_contiguous` for areas of several rows or partly outside. Type-erased: the
    /// rasterizer's spans never come here, so one copy per colour type serves every shader.
    #[inline(never)]
    fn fill_contiguous_clipped(&mut self, area: &Rectangle, colors: &mut Pull<'_, C>) {
        self.zip_area(area, colors, |dst, color| *dst = S::store(color));
    }

    /// Calls `write` with each pixel of `area` inside the image and its item from `colors`
    /// (a colour, or a colour and what to do with it), which holds one item per pixel of the
    /// whole area, row-major: the items of pixels outside the image are skipped. Stops when
    /// `colors` ends.
    #[inline]
    pub(super) fn zip_area<T, I: Iterator<Item = T> + ?Sized>(
        &mut self,
        area: &Rectangle,
        colors: &mut I,
        mut write: impl FnMut(&mut S, T),
    ) {
        let Some(window) = self.clip(area) else {
            return;
        };
        let width = self.width;
        // Colours of the area's pixels left of, right of and above the window are skipped.
        let left = (window.x0 as i64 - i64::from(area.top_left.x)) as u64;
        let right = u64::from(area.size.width) - left - (window.x1 - window.x0) as u64;
        let above = (window.y0 as i64 - i64::from(area.top_left.y)) as u64;
        skip(colors, above * u64::from(area.size.width));
        for y in window.y0..window.y1 {
            skip(colors, left);
            let Some(row) = self
                .pixels
                .get_mut(y * width + window.x0..y * width + window.x1)
            else {
                break;
            };
            let mut written = 0;
            for (dst, color) in row.iter_mut().zip(&mut *colors) {
                write(dst, color);
                written += 1;
            }
            if written < row.len() {
                break;
            }
            skip(colors, right);
        }
    }

    /// The pixels of one row from column `x`, `len` long, if all inside the image.
    #[inline(always)]
    fn row_run(&mut self, y: i32, x: i32, len: u32) -> Option<&mut [S]> {
        // Sides fit i32, so negative coordinates wrap to values above them. With 64-bit
        // `usize`, `row * width` cannot wrap (both are below 2^32), so the slice bound alone
        // rejects rows below the image; 32-bit targets check the row first.
        let (row, column) = (y as u32 as usize, x as u32);
        let row_inside = usize::BITS >= 64 || row < self.height;
        // Sides are below 2^31 (checked in `new`); saying so lets the compiler see that
        // `start + len` cannot overflow, leaving the slice bound as the only check.
        let width = self.width as u32;
        // No 64-bit sum: on 32-bit cores it is two more instructions per span.
        if row_inside && column <= width && len <= width - column {
            let start = row * width as usize + column as usize;
            self.pixels.get_mut(start..start + len as usize)
        } else {
            None
        }
    }

    /// The pixels of one row from column `x`, `len` long, if all inside the image.
    #[inline(always)]
    pub(super) fn row_mut(&mut self, y: i32, x: i32, len: u32) -> Option<&mut [S]> {
        self.row_run(y, x, len)
    }

    /// The stored pixel at `point`, if inside.
    pub(super) fn pixel_mut(&mut self, point: Point) -> Option<&mut S> {
        let i = self.index(point)?;
        self.pixels.get_mut(i)
    }

    /// `fill_solid` for areas of several rows.
    #[inline(never)]
    fn fill_rows(&mut self, area: &Rectangle, value: S) {
        let Some(window) = self.clip(area) else {
            return;
        };
        for y in window.y0..window.y1 {
            let start = y * self.width;
            fill_run(
                &mut self.pixels[start + window.x0..start + window.x1],
                value,
            );
        }
    }

    /// The part of `area` inside the image, as column and row ranges.
    #[inline(always)]
    fn clip(&self, area: &Rectangle) -> Option<Window> {
        let range = |start: i32, len: u32, limit: usize| {
            let start = i64::from(start);
            let end = start + i64::from(len);
            // `limit` is at most i32::MAX, so these conversions are lossless.
            let lo = start.clamp(0, limit as i64) as usize;
            let hi = end.clamp(0, limit as i64) as usize;
            (lo < hi).then_some((lo, hi))
        };
        let (x0, x1) = range(area.top_left.x, area.size.width, self.width)?;
        let (y0, y1) = range(area.top_left.y, area.size.height, self.height)?;
        Some(Window { x0, x1, y0, y1 })
    }
}

/// A non-empty clipped area: columns `x0..x1`, rows `y0..y1`.
#[derive(Copy, Clone)]
struct Window {
    x0: usize,
    x1: usize,
    y0: usize,
    y1: usize,
}

impl<C, S> DrawTarget for Framebuffer<'_, C, S>
where
    C: PixelColor,
    S: StoredPixel<C>,
{
    type Color = C;
    type Error = Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<C>>,
    {
        for Pixel(point, color) in pixels {
            if let Some(i) = self.index(point) {
                self.pixels[i] = S::store(color);
            }
        }
        Ok(())
    }

    #[inline(always)]
    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = C>,
    {
        if area.size.height == 1 {
            // One row inside, the shading styles' case: a plain zip, which the compiler can
            // vectorise when the colours are computed by additions.
            if let Some(run) = self.row_run(area.top_left.y, area.top_left.x, area.size.width) {
                for (dst, color) in run.iter_mut().zip(colors) {
                    *dst = S::store(color);
                }
            } else {
                self.fill_contiguous_row_clipped(area, colors.into_iter());
            }
        } else {
            // Several rows: the rasterizer's spans, whose height is the constant 1, never
            // instantiate this.
            self.fill_contiguous_rows(area, colors.into_iter());
        }
        Ok(())
    }

    #[inline(always)]
    fn fill_solid(&mut self, area: &Rectangle, color: C) -> Result<(), Self::Error> {
        if area.size.height == 1 {
            // One row, the rasterizer's case: kept small so it inlines into the span loop.
            self.fill_row(
                area.top_left.y,
                area.top_left.x,
                area.size.width,
                S::store(color),
            );
        } else {
            self.fill_rows(area, S::store(color));
        }
        Ok(())
    }

    fn clear(&mut self, color: C) -> Result<(), Self::Error> {
        // Eight stores a loop trip: `slice::fill` took four (band rendering clears every band).
        fill_run(self.pixels, S::store(color));
        Ok(())
    }
}

/// `slice::fill`, faster for the short runs triangles produce.
///
/// Runs under eight elements are written from both ends at once (two stores cover one or two
/// elements, four up to four, six up to seven); up to 32 as two blocks of eight or sixteen
/// from both ends (two 16-byte stores for `u16` pixels), overlapping; longer ones eight
/// elements at a time, every store written out, their ragged end as one more group of eight
/// overlapping the one before. No run up to 32 needs a loop. Long runs use no block copy:
/// with `opt-level = "s"` or `"z"` each block becomes a call of `memcpy` (measured: flat
/// `big` pixels cost Cortex-M0 17.6 instructions at `"s"` with blocks, 6.4 without, 3.6 at
/// `opt-level = 3` either way).
#[inline(always)]
pub(crate) fn fill_run<S: Copy>(run: &mut [S], value: S) {
    let n = run.len();
    if n < 8 {
        if n == 0 {
            return;
        }
        run[0] = value;
        run[n - 1] = value;
        if n > 2 {
            run[1] = value;
            run[n - 2] = value;
            if n > 4 {
                run[2] = value;
                run[3] = value;
                run[n - 3] = value;
            }
        }
    } else if n < 16 {
        // Groups of eight stores, not blocks copied from an array: at `opt-level = "s"` each
        // block copy became a call of `memcpy`.
        eight(&mut run[..8], value);
        eight(&mut run[n - 8..], value);
    } else if n <= 32 {
        eight(&mut run[..8], value);
        eight(&mut run[8..16], value);
        eight(&mut run[n - 16..n - 8], value);
        eight(&mut run[n - 8..], value);
    } else {
        fill_eights(run, value);
    }
}

/// [`fill_run`] for runs over 32 elements (it serves any of eight or more), out of line:
/// inlined, its loop keeps registers busy in the row loops of every triangle, and tiny
/// triangles pay for spans they never have.
#[inline(never)]
fn fill_eights<S: Copy>(run: &mut [S], value: S) {
    let n = run.len();
    let mut start = 0;
    // `get_mut` and arrays rather than indexing: the bounds are proved once per group, and no
    // panic (whose formatting is about 900 bytes of flash) can be reached.
    while let Some(group) = run.get_mut(start..start + 8) {
        eight(group, value);
        start += 8;
    }
    if start < n {
        if let Some(last) = run.get_mut(n.saturating_sub(8)..) {
            eight(last, value);
        }
    }
}

/// Stores `value` into the eight elements of `group` (shorter groups are left alone).
#[inline(always)]
fn eight<S: Copy>(group: &mut [S], value: S) {
    if let Ok(group) = <&mut [S; 8]>::try_from(group) {
        group[0] = value;
        group[1] = value;
        group[2] = value;
        group[3] = value;
        group[4] = value;
        group[5] = value;
        group[6] = value;
        group[7] = value;
    }
}

/// An iterator's `next`, alone: its trait object's table holds nothing else, where
/// `dyn Iterator`'s would bring each iterator type's `nth` and the rest into the flash (and
/// `dyn FnMut` a second copy of the call).
trait Next<T> {
    fn next_item(&mut self) -> Option<T>;
}

impl<I: Iterator> Next<I::Item> for I {
    #[inline]
    fn next_item(&mut self) -> Option<I::Item> {
        self.next()
    }
}

/// The items of a type-erased [`Next`]: an iterator whose methods are instantiated once per
/// item type.
struct Pull<'a, T>(&'a mut dyn Next<T>);

impl<T> Iterator for Pull<'_, T> {
    type Item = T;

    #[inline]
    fn next(&mut self) -> Option<T> {
        self.0.next_item()
    }
}

/// Drops `count` items; stops early if the iterator ends.
#[inline]
fn skip<I: Iterator + ?Sized>(iter: &mut I, count: u64) {
    if count > 0 {
        // `nth(n)` consumes n + 1 items.
        let mut remaining = count;
        while remaining > 0 {
            let chunk = usize::try_from(remaining).unwrap_or(usize::MAX);
            if iter.nth(chunk - 1).is_none() {
                return;
            }
            remaining -= chunk as u64;
        }
    }
}

impl<C, S> OriginDimensions for Framebuffer<'_, C, S> {
    fn size(&self) -> Size {
        // Both sides were checked to fit i32 at construction.
        Size::new(self.width as u32, self.height as u32)
    }
}

impl<C, S> fmt::Debug for Framebuffer<'_, C, S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Framebuffer")
            .field("width", &self.width)
            .field("height", &self.height)
            .finish_non_exhaustive()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_graphics::pixelcolor::Gray8;
    use embedded_graphics::prelude::*;

    fn gray(v: u8) -> Gray8 {
        Gray8::new(v)
    }

    #[test]
    fn rejects_wrong_lengths_and_huge_sizes() {
        let mut px = [gray(0); 12];
        assert_eq!(
            Framebuffer::new(&mut px, 4, 4).unwrap_err(),
            Error::BufferLength {
                expected: 16,
                actual: 12
            }
        );
        assert_eq!(
            Framebuffer::new(&mut px, u32::MAX, 1).unwrap_err(),
            Error::DimensionsTooLarge {
                width: u32::MAX,
                height: 1
            }
        );
        assert!(Framebuffer::new(&mut px, 4, 3).is_ok());
        assert!(Framebuffer::<Gray8>::new(&mut [], 0, 7).is_ok());
    }

    #[test]
    fn fill_solid_clips() {
        let mut px = [gray(0); 5 * 4];
        let mut fb = Framebuffer::new(&mut px, 5, 4).unwrap();
        fb.fill_solid(
            &Rectangle::new(Point::new(-2, -1), Size::new(4, 3)),
            gray(9),
        )
        .unwrap();
        fb.fill_solid(
            &Rectangle::new(Point::new(4, 3), Size::new(u32::MAX, u32::MAX)),
            gray(7),
        )
        .unwrap();
        // From i32::MIN across the whole row 0.
        fb.fill_solid(
            &Rectangle::new(Point::new(i32::MIN, 0), Size::new(u32::MAX, 1)),
            gray(3),
        )
        .unwrap();
        let v: [u8; 20] = px.map(|c| c.luma());
        assert_eq!(
            v,
            [3, 3, 3, 3, 3, 9, 9, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 7]
        );
    }

    #[test]
    fn fill_run_writes_exactly_the_run() {
        for len in 0..120 {
            for offset in 0..3 {
                let mut got = [0u16; 130];
                let mut want = [0u16; 130];
                fill_run(&mut got[offset..offset + len], 7);
                want[offset..offset + len].fill(7);
                assert_eq!(got, want, "len {len} offset {offset}");
            }
        }
    }

    #[test]
    fn single_rows_outside_are_ignored() {
        let mut px = [gray(0); 6 * 3];
        let mut fb = Framebuffer::new(&mut px, 6, 3).unwrap();
        for (x, y, w) in [
            (0, 3, 6),
            (0, -1, 6),
            (0, i32::MAX, 6),
            (0, i32::MIN, 6),
            (6, 0, 1),
            (i32::MAX, 1, 9),
            (-7, 2, 7),
        ] {
            fb.fill_solid(&Rectangle::new(Point::new(x, y), Size::new(w, 1)), gray(1))
                .unwrap();
        }
        assert!(px.iter().all(|c| c.luma() == 0));
        let mut fb = Framebuffer::new(&mut px, 6, 3).unwrap();
        fb.fill_solid(&Rectangle::new(Point::new(-2, 2), Size::new(4, 1)), gray(5))
            .unwrap();
        fb.fill_solid(&Rectangle::new(Point::new(4, 0), Size::new(9, 1)), gray(6))
            .unwrap();
        let v: [u8; 18] = px.map(|c| c.luma());
        assert_eq!(v, [0, 0, 0, 0, 6, 6, 0, 0, 0, 0, 0, 0, 5, 5, 0, 0, 0, 0]);
    }

    #[test]
    fn fill_contiguous_clips_in_row_major_order() {
        let mut px = [gray(0); 4 * 3];
        let mut fb = Framebuffer::new(&mut px, 4, 3).unwrap();
        // A 3x3 area hanging off the top-left corner, numbered 1..=9 row by row.
        let area = Rectangle::new(Point::new(-1, -1), Size::new(3, 3));
        fb.fill_contiguous(&area, (1..=9).map(gray)).unwrap();
        let v: [u8; 12] = px.map(|c| c.luma());
        assert_eq!(v, [5, 6, 0, 0, 8, 9, 0, 0, 0, 0, 0, 0]);
    }

    #[test]
    fn fill_contiguous_clips_single_rows() {
        // One row at a time, hanging off either side, off both, or outside: each pixel inside
        // gets the colour of its position in the row, as drawing pixel by pixel would give.
        for (x, y, w) in [
            (-2, 1, 4),
            (2, 0, 5),
            (-1, 2, 7),
            (0, 3, 2),
            (-9, 1, 3),
            (5, 0, 2),
        ] {
            let mut px = [gray(0); 5 * 3];
            let mut fb = Framebuffer::new(&mut px, 5, 3).unwrap();
            let area = Rectangle::new(Point::new(x, y), Size::new(w, 1));
            fb.fill_contiguous(&area, (1..=w as u8).map(gray)).unwrap();
            let mut want = [0u8; 5 * 3];
            for i in 0..w as i32 {
                if (0..5).contains(&(x + i)) && (0..3).contains(&y) {
                    want[(y * 5 + x + i) as usize] = i as u8 + 1;
                }
            }
            assert_eq!(px.map(|c| c.luma()), want, "row at ({x}, {y}), {w} long");
        }
    }

    #[test]
    fn fill_contiguous_fills_every_area_inside_in_row_major_order() {
        // Every area inside a 5x4 image, as wide as the image (one run) or narrower (row by
        // row): pixel k of the area, row-major, gets colour k + 1, and nothing else changes.
        for (x, y) in (0..5).flat_map(|x| (0..4).map(move |y| (x, y))) {
            for (w, h) in (1..=5 - x).flat_map(|w| (1..=4 - y).map(move |h| (w, h))) {
                let mut px = [gray(0); 5 * 4];
                let mut fb = Framebuffer::new(&mut px, 5, 4).unwrap();
                let area = Rectangle::new(Point::new(x, y), Size::new(w as u32, h as u32));
                fb.fill_contiguous(&area, (1..=(w * h) as u8).map(gray))
                    .unwrap();
                let mut want = [0u8; 5 * 4];
                for k in 0..w * h {
                    want[((y + k / w) * 5 + x + k % w) as usize] = k as u8 + 1;
                }
                assert_eq!(px.map(|c| c.luma()), want, "{w}x{h} at ({x}, {y})");
            }
        }
    }

    #[test]
    fn fill_contiguous_stops_when_colors_run_out() {
        let mut px = [gray(0); 3 * 2];
        let mut fb = Framebuffer::new(&mut px, 3, 2).unwrap();
        let area = Rectangle::new(Point::new(0, 0), Size::new(3, 2));
        fb.fill_contiguous(&area, (1..=4).map(gray)).unwrap();
        let v: [u8; 6] = px.map(|c| c.luma());
        assert_eq!(v, [1, 2, 3, 4, 0, 0]);
    }

    #[test]
    fn draw_iter_ignores_outside_pixels() {
        let mut px = [gray(0); 2 * 2];
        let mut fb = Framebuffer::new(&mut px, 2, 2).unwrap();
        let pixels = [
            Pixel(Point::new(1, 1), gray(3)),
            Pixel(Point::new(2, 0), gray(4)),
            Pixel(Point::new(-1, 0), gray(5)),
        ];
        fb.draw_iter(pixels).unwrap();
        let v: [u8; 4] = px.map(|c| c.luma());
        assert_eq!(v, [0, 0, 0, 3]);
    }
}
