//! Depth testing: a z-buffer in caller memory, and a target wrapper that draws triangles with
//! per-vertex depth through it.
//!
//! Depths are `u16`, smaller is nearer with the default [`DepthTest::Less`]. Each triangle's
//! depth is interpolated from its vertices with 16 fraction bits, exactly at the start of each
//! span and by additions along it, and rounded to the nearest `u16`. Spans are tested first
//! and painted after: a span that passes whole goes out as one `fill_solid` or
//! `fill_contiguous` call, one that fails in places is broken into its passing runs.
//!
//! # Examples
//!
//! Two triangles crossing each other: the nearer one wins each pixel, whatever the order.
//!
//! ```
//! use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
//! use trirast::{depth::{DepthBuffer, DepthTarget}, FlatStyle, Framebuffer, Triangle};
//!
//! let mut pixels = [Rgb565::BLACK; 64 * 64];
//! let mut depths = [0u16; 64 * 64];
//! let mut display = Framebuffer::new(&mut pixels, 64, 64)?;
//! let mut zbuffer = DepthBuffer::new(&mut depths, 64, 64)?;
//! zbuffer.clear(u16::MAX);
//!
//! let mut scene = DepthTarget::new(&mut display, &mut zbuffer)?;
//! let (a, b, c) = (Point::new(0, 0), Point::new(63, 32), Point::new(0, 63));
//! let (d, e, f) = (Point::new(63, 0), Point::new(0, 32), Point::new(63, 63));
//! // Red leans back to the right, blue to the left: they cross at x = 32.
//! scene.draw(&Triangle::new(a, b, c), [1000, 9000, 1000], &FlatStyle::new(Rgb565::RED)).unwrap();
//! scene.draw(&Triangle::new(d, e, f), [1000, 9000, 1000], &FlatStyle::new(Rgb565::BLUE)).unwrap();
//! assert_eq!(display.pixel(Point::new(10, 32)), Some(Rgb565::RED));
//! assert_eq!(display.pixel(Point::new(53, 32)), Some(Rgb565::BLUE));
//! # Ok::<(), trirast::Error>(())
//! ```

mod spans;

use embedded_graphics::{
    draw_target::DrawTarget,
    geometry::{Point, Size},
    primitives::Rectangle,
};

use crate::{
    Error,
    geometry::Shape,
    interpolate::AreaMemo,
    shading::{TriangleStyle, paint::on_screen},
    target::fill_run,
};

/// A z-buffer: one `u16` depth per pixel, row-major, in memory you provide.
///
/// # Examples
///
/// ```
/// use embedded_graphics::prelude::*;
/// use trirast::depth::DepthBuffer;
///
/// let mut depths = [0u16; 32 * 24];
/// let mut zbuffer = DepthBuffer::new(&mut depths, 32, 24)?;
/// zbuffer.clear(u16::MAX);
/// assert_eq!(zbuffer.depth(Point::new(31, 23)), Some(u16::MAX));
/// assert_eq!(zbuffer.depth(Point::new(32, 0)), None);
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Debug)]
pub struct DepthBuffer<'a> {
    depths: &'a mut [u16],
    width: u32,
    height: u32,
}

impl<'a> DepthBuffer<'a> {
    /// Wraps `depths` as a `width` x `height` z-buffer.
    ///
    /// # Errors
    ///
    /// [`Error::BufferLength`] unless `depths.len() == width * height`;
    /// [`Error::DimensionsTooLarge`] if a side exceeds `i32::MAX` or the product overflows.
    ///
    /// # Examples
    ///
    /// ```
    /// use trirast::{depth::DepthBuffer, Error};
    ///
    /// let mut depths = [0u16; 100];
    /// assert!(matches!(DepthBuffer::new(&mut depths, 16, 16), Err(Error::BufferLength { .. })));
    /// ```
    pub fn new(depths: &'a mut [u16], width: u32, height: u32) -> Result<Self, Error> {
        let too_large = Error::DimensionsTooLarge { width, height };
        if i32::try_from(width).is_err() || i32::try_from(height).is_err() {
            return Err(too_large);
        }
        let expected = (width as usize)
            .checked_mul(height as usize)
            .ok_or(too_large)?;
        if depths.len() != expected {
            return Err(Error::BufferLength {
                expected,
                actual: depths.len(),
            });
        }
        Ok(Self {
            depths,
            width,
            height,
        })
    }

    /// Sets every depth to `depth`: `u16::MAX` (farthest) before a frame drawn with
    /// [`DepthTest::Less`].
    ///
    /// # Examples
    ///
    /// ```
    /// use trirast::depth::DepthBuffer;
    ///
    /// let mut depths = [7u16; 4];
    /// DepthBuffer::new(&mut depths, 2, 2)?.clear(0);
    /// assert_eq!(depths, [0; 4]);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn clear(&mut self, depth: u16) {
        // Eight stores a loop trip, as the bands clear theirs: `slice::fill` is a `memset`
        // call at `opt-level = 3` (1.5 instructions a depth on Cortex-M0, against about 1.25)
        // and a loop of its own at `"s"` (4).
        fill_run(self.depths, depth);
    }

    /// The depth at `point`, or `None` outside the buffer.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::depth::DepthBuffer;
    ///
    /// let mut depths = [1, 2, 3, 4];
    /// let zbuffer = DepthBuffer::new(&mut depths, 2, 2)?;
    /// assert_eq!(zbuffer.depth(Point::new(1, 1)), Some(4));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn depth(&self, point: Point) -> Option<u16> {
        let (x, y) = (u32::try_from(point.x).ok()?, u32::try_from(point.y).ok()?);
        (x < self.width && y < self.height)
            .then(|| self.depths[y as usize * self.width as usize + x as usize])
    }

    /// All depths, row-major.
    ///
    /// # Examples
    ///
    /// ```
    /// use trirast::depth::DepthBuffer;
    ///
    /// let mut depths = [5u16; 6];
    /// assert_eq!(DepthBuffer::new(&mut depths, 3, 2)?.depths(), &[5; 6]);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn depths(&self) -> &[u16] {
        self.depths
    }

    /// Width and height.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::prelude::*;
    /// use trirast::depth::DepthBuffer;
    ///
    /// let mut depths = [0u16; 6];
    /// assert_eq!(DepthBuffer::new(&mut depths, 3, 2)?.size(), Size::new(3, 2));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn size(&self) -> Size {
        Size::new(self.width, self.height)
    }

    /// The depths of `len` pixels of row `y` from column `x`, both relative to the buffer,
    /// which the run lies in (the depth pass's spans lie in the window the buffer covers): only
    /// the slice bound is checked, so a run past the row's end would go on in the next row,
    /// never outside the buffer.
    #[inline(always)]
    pub(crate) fn run_mut(&mut self, x: u32, y: u32, len: u32) -> Option<&mut [u16]> {
        debug_assert!(u64::from(x) + u64::from(len) <= u64::from(self.width));
        let start = (y as usize)
            .wrapping_mul(self.width as usize)
            .wrapping_add(x as usize);
        self.depths.get_mut(start..start.wrapping_add(len as usize))
    }
}

/// Which depths pass the test against the depth already stored.
///
/// # Examples
///
/// ```
/// use trirast::depth::DepthTest;
///
/// assert!(DepthTest::Less.passes(1, 2));
/// assert!(!DepthTest::Less.passes(2, 2));
/// assert!(DepthTest::LessOrEqual.passes(2, 2));
/// assert!(DepthTest::Always.passes(9, 0));
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, Hash)]
pub enum DepthTest {
    /// Nearer than what is there (smaller depth): the usual test.
    #[default]
    Less,
    /// Nearer or as near.
    LessOrEqual,
    /// Farther (larger depth).
    Greater,
    /// Farther or as far.
    GreaterOrEqual,
    /// Every pixel passes (depths are still written if writing is on).
    Always,
}

impl DepthTest {
    /// Whether `depth` passes against `stored`.
    ///
    /// # Examples
    ///
    /// ```
    /// use trirast::depth::DepthTest;
    ///
    /// assert!(DepthTest::Greater.passes(3, 2));
    /// assert!(DepthTest::GreaterOrEqual.passes(2, 2));
    /// ```
    #[must_use]
    pub const fn passes(self, depth: u16, stored: u16) -> bool {
        let (flip, slack) = self.comparison();
        ((depth ^ flip) as u32) < (stored ^ flip) as u32 + slack
    }

    /// The test as `(depth ^ flip) < (stored ^ flip) + slack`: one branch-free form for all.
    #[inline(always)]
    pub(crate) const fn comparison(self) -> (u16, u32) {
        match self {
            Self::Less => (0, 0),
            Self::LessOrEqual => (0, 1),
            Self::Greater => (u16::MAX, 0),
            Self::GreaterOrEqual => (u16::MAX, 1),
            Self::Always => (0, 1 << 16),
        }
    }
}

/// A draw target with a z-buffer: draws triangles with a depth per vertex, each pixel only if
/// it passes the depth test.
///
/// The buffer must cover the target's bounding box exactly (same size; it is addressed
/// relative to the box's top-left corner). Any [`TriangleStyle`] works: flat, Gouraud,
/// textured, user shaders.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use trirast::{depth::{DepthBuffer, DepthTarget, DepthTest}, GouraudStyle, Framebuffer, Triangle};
///
/// let mut pixels = [Gray8::BLACK; 32 * 32];
/// let mut depths = [u16::MAX; 32 * 32];
/// let mut display = Framebuffer::new(&mut pixels, 32, 32)?;
/// let mut zbuffer = DepthBuffer::new(&mut depths, 32, 32)?;
/// let mut scene = DepthTarget::new(&mut display, &mut zbuffer)?.with_test(DepthTest::LessOrEqual);
/// let style = GouraudStyle::new([Gray8::new(0), Gray8::new(128), Gray8::new(255)]);
/// let triangle = Triangle::new(Point::new(0, 0), Point::new(31, 0), Point::new(0, 31));
/// scene.draw(&triangle, [100, 200, 300], &style).unwrap();
/// assert_eq!(zbuffer.depth(Point::new(0, 0)), Some(100));
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Debug)]
pub struct DepthTarget<'a, 'b, D> {
    target: &'a mut D,
    buffer: &'a mut DepthBuffer<'b>,
    test: DepthTest,
    write: bool,
    /// The target's pixel `(x, y)` is the screen's `(x, y) + offset` (non-zero only for the
    /// band framebuffers of [`crate::band`]).
    offset: Point,
}

impl<'a, 'b, D: DrawTarget> DepthTarget<'a, 'b, D> {
    /// Draws into `target` through `buffer`, with [`DepthTest::Less`] and depth writes on.
    ///
    /// # Errors
    ///
    /// [`Error::DepthBufferSize`] unless `buffer` has the size of the target's bounding box.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::BinaryColor, mock_display::MockDisplay};
    /// use trirast::{depth::{DepthBuffer, DepthTarget}, Error};
    ///
    /// let mut display = MockDisplay::<BinaryColor>::new(); // 64 x 64
    /// let mut depths = [0u16; 32 * 32];
    /// let mut zbuffer = DepthBuffer::new(&mut depths, 32, 32)?;
    /// assert!(matches!(DepthTarget::new(&mut display, &mut zbuffer), Err(Error::DepthBufferSize { .. })));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn new(target: &'a mut D, buffer: &'a mut DepthBuffer<'b>) -> Result<Self, Error> {
        let expected = target.bounding_box().size;
        if buffer.size() != expected {
            return Err(Error::DepthBufferSize {
                buffer: buffer.size(),
                target: expected,
            });
        }
        Ok(Self {
            target,
            buffer,
            test: DepthTest::Less,
            write: true,
            offset: Point::zero(),
        })
    }

    /// The same target with another depth test.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use trirast::{depth::{DepthBuffer, DepthTarget, DepthTest}, Framebuffer};
    ///
    /// let (mut pixels, mut depths) = ([Gray8::BLACK; 4], [0u16; 4]);
    /// let mut display = Framebuffer::new(&mut pixels, 2, 2)?;
    /// let mut zbuffer = DepthBuffer::new(&mut depths, 2, 2)?;
    /// let scene = DepthTarget::new(&mut display, &mut zbuffer)?.with_test(DepthTest::Greater);
    /// assert_eq!(scene.test(), DepthTest::Greater);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn with_test(mut self, test: DepthTest) -> Self {
        self.test = test;
        self
    }

    /// The same target with depth writes on or off: off tests against the buffer without
    /// changing it (for transparent layers drawn after the opaque ones, say).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use trirast::{depth::{DepthBuffer, DepthTarget}, FlatStyle, Framebuffer, Triangle};
    ///
    /// let (mut pixels, mut depths) = ([Gray8::BLACK; 16], [u16::MAX; 16]);
    /// let mut display = Framebuffer::new(&mut pixels, 4, 4)?;
    /// let mut zbuffer = DepthBuffer::new(&mut depths, 4, 4)?;
    /// let mut scene = DepthTarget::new(&mut display, &mut zbuffer)?.with_write(false);
    /// let t = Triangle::new(Point::new(0, 0), Point::new(4, 0), Point::new(0, 4));
    /// scene.draw(&t, [5, 5, 5], &FlatStyle::new(Gray8::WHITE)).unwrap();
    /// assert_eq!(display.pixel(Point::zero()), Some(Gray8::WHITE));
    /// assert_eq!(zbuffer.depth(Point::zero()), Some(u16::MAX));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn with_write(mut self, write: bool) -> Self {
        self.write = write;
        self
    }

    /// The depth test in use.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use trirast::{depth::{DepthBuffer, DepthTarget, DepthTest}, Framebuffer};
    ///
    /// let (mut pixels, mut depths) = ([Gray8::BLACK; 1], [0u16; 1]);
    /// let mut display = Framebuffer::new(&mut pixels, 1, 1)?;
    /// let mut zbuffer = DepthBuffer::new(&mut depths, 1, 1)?;
    /// assert_eq!(DepthTarget::new(&mut display, &mut zbuffer)?.test(), DepthTest::Less);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn test(&self) -> DepthTest {
        self.test
    }

    /// Draws `triangle` (a [`Triangle`](crate::Triangle) or a
    /// [`SubPixelTriangle`](crate::geometry::SubPixelTriangle)), whose vertices have depths
    /// `depths` (in vertex order), with `style`: each covered pixel whose interpolated depth
    /// passes the test is painted and, if writing is on, its depth stored.
    ///
    /// # Errors
    ///
    /// The target's.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use trirast::{depth::{DepthBuffer, DepthTarget}, FlatStyle, Triangle};
    /// use trirast::Framebuffer;
    ///
    /// let (mut pixels, mut depths) = ([Gray8::BLACK; 64], [u16::MAX; 64]);
    /// let mut display = Framebuffer::new(&mut pixels, 8, 8)?;
    /// let mut zbuffer = DepthBuffer::new(&mut depths, 8, 8)?;
    /// let mut scene = DepthTarget::new(&mut display, &mut zbuffer)?;
    /// let t = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
    /// // Near first, then far: the far triangle fails the test everywhere they overlap.
    /// scene.draw(&t, [100; 3], &FlatStyle::new(Gray8::WHITE)).unwrap();
    /// scene.draw(&t, [900; 3], &FlatStyle::new(Gray8::new(50))).unwrap();
    /// assert_eq!(display.pixel(Point::new(1, 1)), Some(Gray8::WHITE));
    /// assert_eq!(depths[1 * 8 + 1], 100);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn draw<G, S>(&mut self, triangle: &G, depths: [u16; 3], style: &S) -> Result<(), D::Error>
    where
        G: Shape,
        S: TriangleStyle<Color = D::Color>,
    {
        let window = on_screen(self.target.bounding_box(), self.offset);
        self.draw_in(triangle, depths, style, &window)
    }

    /// The same target holding the part of the screen whose top-left corner is `offset`:
    /// the target's and the depth buffer's `(0, 0)` is the screen's `offset`.
    pub(crate) fn with_offset(mut self, offset: Point) -> Self {
        self.offset = offset;
        self
    }

    /// [`DepthTarget::draw`] with interpolation set up for `setup` (the whole screen, when the
    /// target is a band of it), so that colours and depths do not depend on the part drawn.
    // Always inlined, as the plain pass's walk: shared out of line between frames and bands,
    // it measured +17% per small depth-tested triangle on Cortex-M4F.
    #[inline(always)]
    pub(crate) fn draw_in<G, S>(
        &mut self,
        triangle: &G,
        depths: [u16; 3],
        style: &S,
        setup: &Rectangle,
    ) -> Result<(), D::Error>
    where
        G: Shape,
        S: TriangleStyle<Color = D::Color>,
    {
        let window = on_screen(self.target.bounding_box(), self.offset);
        let memo = AreaMemo::new();
        let visitor = spans::DepthVisitor {
            target: self.target,
            buffer: self.buffer,
            triangle,
            depths,
            rule: style.fill_rule(),
            window,
            setup: *setup,
            test: self.test,
            write: self.write,
            offset: self.offset,
            // Cores with a divider make the area's reciprocal again (see `AreaMemo`).
            memo: (!crate::arch::DIVIDES).then_some(&memo),
        };
        style.paint(triangle, setup, visitor).unwrap_or(Ok(()))
    }

    /// The target, for drawing without depth (text overlays, say).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use trirast::{depth::{DepthBuffer, DepthTarget}, Framebuffer};
    ///
    /// let (mut pixels, mut depths) = ([Gray8::BLACK; 4], [0u16; 4]);
    /// let mut display = Framebuffer::new(&mut pixels, 2, 2)?;
    /// let mut zbuffer = DepthBuffer::new(&mut depths, 2, 2)?;
    /// let mut scene = DepthTarget::new(&mut display, &mut zbuffer)?;
    /// scene.target().clear(Gray8::WHITE).unwrap();
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn target(&mut self) -> &mut D {
        self.target
    }
}
