//! Band rendering: whole scenes on chips without memory for a whole frame.
//!
//! A [`Scene`] is a display list of triangles with a fixed capacity (a `heapless` vector inside,
//! no allocation). [`Bands`] renders it into a buffer of a few rows (and, for depth-tested
//! triangles, a depth band of the same rows), band after band from the top, and hands each
//! finished band to the display with one `fill_contiguous` call, which is how SPI displays take
//! a window of pixels.
//!
//! Every triangle is binned by its rows once per frame and drawn only into the bands it
//! touches. Its interpolation is set up for the whole screen, so each band gets exactly the
//! pixels, colours and depths a full-frame render would give it: band rendering is bit for bit
//! the same image, for any band height from one row to the full screen.
//!
//! # Memory
//!
//! For a 320 x 240 `Rgb565` screen: a 16-row band is 320 x 16 x 2 = 10,240 bytes, its depth band
//! another 10,240; a 200-triangle scene is 200 x `size_of::<SceneTriangle<Rgb565, _>>()`: 112
//! bytes each on 32-bit microcontrollers (22,400 in all; 128 bytes on a 64-bit host). The full
//! frame and its depth buffer would be 153,600 bytes each. Keeping each triangle's set-up and
//! walk between bands ([`Bands::with_setup_cache`], 192 bytes a triangle) trades memory for
//! speed.
//!
//! # Examples
//!
//! ```
//! use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
//! use trirast::{band::{Bands, Scene, SceneStyle}, FlatStyle, Framebuffer, GouraudStyle, Triangle};
//!
//! let screen = Rectangle::new(Point::zero(), Size::new(64, 48));
//! let mut scene: Scene<Rgb565, 8> = Scene::new(screen);
//! let t = Triangle::new(Point::new(2, 2), Point::new(60, 10), Point::new(20, 46));
//! scene.push(t, SceneStyle::Gouraud(GouraudStyle::new([Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE])))?;
//! scene.push_with_depth(t, [100, 200, 300], SceneStyle::Flat(FlatStyle::new(Rgb565::WHITE)))?;
//!
//! // Eight rows at a time, with a depth band.
//! let mut band = [Rgb565::BLACK; 64 * 8];
//! let mut depth_band = [0u16; 64 * 8];
//! let mut bands = Bands::new(&mut band, 64, 8)?.with_depth(&mut depth_band)?;
//!
//! // Any DrawTarget takes the bands; here a framebuffer stands in for the display.
//! let mut frame = [Rgb565::BLACK; 64 * 48];
//! let mut display = Framebuffer::new(&mut frame, 64, 48)?;
//! bands.render(&scene, Rgb565::BLACK, &mut display).unwrap();
//! assert_eq!(display.pixel(Point::new(20, 20)), Some(Rgb565::WHITE));
//! # Ok::<(), trirast::Error>(())
//! ```

use core::fmt;

mod setups;

pub(crate) use setups::Cached;
pub use setups::{NoSetupCache, SetupCache, SetupSlot};

use embedded_graphics::{
    draw_target::DrawTarget,
    geometry::{Point, Size},
    pixelcolor::PixelColor,
    primitives::Rectangle,
};

use crate::{
    Error,
    depth::{DepthBuffer, DepthTarget, DepthTest},
    geometry::{Shape, Triangle},
    shading::{
        ChannelColor, FlatStyle, GouraudStyle, TextureStyle,
        paint::{draw_anti_aliased_in, draw_plain_in},
    },
    target::{Framebuffer, StoredPixel, fill_run},
    texture::{TexelSource, Texels},
};

/// How a scene triangle is filled: the crate's styles, with textures of type `T`
/// ([`Texels`] unless chosen).
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::Gray8;
/// use trirast::{band::SceneStyle, FlatStyle};
///
/// use trirast::texture::Texels;
///
/// let style: SceneStyle<Gray8, Texels<Gray8>> = SceneStyle::Flat(FlatStyle::new(Gray8::new(200)));
/// assert!(matches!(style, SceneStyle::Flat(_)));
/// ```
#[derive(Copy, Clone, Debug)]
pub enum SceneStyle<C: PixelColor, T: TexelSource<Color = C>> {
    /// One colour.
    Flat(FlatStyle<C>),
    /// Colours interpolated between the vertices.
    Gouraud(GouraudStyle<C>),
    /// A borrowed texture.
    Texture(TextureStyle<T>),
}

/// One triangle of a [`Scene`]: its shape, depths if depth-tested, style, and the rows it
/// covers on screen.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
/// use trirast::{band::{Scene, SceneStyle}, FlatStyle, Triangle};
///
/// let mut scene: Scene<Gray8, 4> = Scene::new(Rectangle::new(Point::zero(), Size::new(32, 32)));
/// let t = Triangle::new(Point::new(0, 5), Point::new(9, 5), Point::new(0, 14));
/// scene.push(t, SceneStyle::Flat(FlatStyle::new(Gray8::WHITE)))?;
/// assert_eq!(scene.triangles()[0].rows, 5..15);
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct SceneTriangle<C: PixelColor, T: TexelSource<Color = C>, G = Triangle> {
    /// The triangle: a [`Triangle`] or a
    /// [`SubPixelTriangle`](crate::geometry::SubPixelTriangle).
    pub triangle: G,
    /// Depths per vertex, for triangles drawn through the depth test.
    pub depths: Option<[u16; 3]>,
    /// How it is filled.
    pub style: SceneStyle<C, T>,
    /// The screen rows its bounding box covers (empty when it is off screen).
    pub rows: core::ops::Range<i32>,
    /// How opaque it is drawn over what lies below (255: opaque).
    pub opacity: u8,
    /// Whether its edges are anti-aliased (blended by coverage).
    pub anti_aliased: bool,
}

/// A display list of up to `N` triangles for [`Bands`] to render, drawn in the order pushed.
///
/// `T` is the texture type of its textured triangles ([`Texels`] unless named). Rendering
/// builds in texture mapping for it; a scene of flat and Gouraud triangles only can name
/// [`NoTexture`](crate::texture::NoTexture) instead and leave all of that out of the flash
/// (about 10 KB on Cortex-M0).
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
/// use trirast::{band::{Scene, SceneStyle}, Error, FlatStyle, Triangle};
///
/// let mut scene: Scene<Rgb565, 1> = Scene::new(Rectangle::new(Point::zero(), Size::new(8, 8)));
/// let t = Triangle::new(Point::new(0, 0), Point::new(7, 0), Point::new(0, 7));
/// let style = SceneStyle::Flat(FlatStyle::new(Rgb565::RED));
/// scene.push(t, style)?;
/// assert_eq!(scene.push(t, style), Err(Error::SceneFull { capacity: 1 }));
/// # Ok::<(), trirast::Error>(())
/// ```
pub struct Scene<
    'a,
    C: PixelColor,
    const N: usize,
    T: TexelSource<Color = C> = Texels<'a, C>,
    G = Triangle,
> {
    screen: Rectangle,
    triangles: heapless::Vec<SceneTriangle<C, T, G>, N>,
    test: DepthTest,
    /// Textures are borrowed for `'a` (the default texture type names it).
    borrow: core::marker::PhantomData<&'a ()>,
}

impl<C: PixelColor, const N: usize, T: TexelSource<Color = C>, G: Shape> Scene<'_, C, N, T, G> {
    /// An empty scene for a screen covering `screen`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
    /// use trirast::band::Scene;
    ///
    /// let scene: Scene<Rgb565, 200> = Scene::new(Rectangle::new(Point::zero(), Size::new(320, 240)));
    /// assert!(scene.triangles().is_empty());
    /// ```
    #[must_use]
    pub fn new(screen: Rectangle) -> Self {
        Self {
            screen,
            triangles: heapless::Vec::new(),
            test: DepthTest::Less,
            borrow: core::marker::PhantomData,
        }
    }

    /// The same scene, depth-tested triangles drawn with `test` (default [`DepthTest::Less`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
    /// use trirast::{band::Scene, depth::DepthTest};
    ///
    /// let scene: Scene<Rgb565, 4> = Scene::new(Rectangle::new(Point::zero(), Size::new(8, 8)))
    ///     .with_depth_test(DepthTest::LessOrEqual);
    /// assert_eq!(scene.depth_test(), DepthTest::LessOrEqual);
    /// ```
    #[must_use]
    pub fn with_depth_test(mut self, test: DepthTest) -> Self {
        self.test = test;
        self
    }

    /// The depth test of depth-tested triangles.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
    /// use trirast::{band::Scene, depth::DepthTest};
    ///
    /// let scene: Scene<Rgb565, 4> = Scene::new(Rectangle::new(Point::zero(), Size::new(8, 8)));
    /// assert_eq!(scene.depth_test(), DepthTest::Less);
    /// ```
    #[must_use]
    pub fn depth_test(&self) -> DepthTest {
        self.test
    }

    /// The screen area.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
    /// use trirast::band::Scene;
    ///
    /// let screen = Rectangle::new(Point::zero(), Size::new(8, 8));
    /// assert_eq!(Scene::<Rgb565, 1>::new(screen).screen(), screen);
    /// ```
    #[must_use]
    pub fn screen(&self) -> Rectangle {
        self.screen
    }

    /// Adds a triangle drawn without a depth test.
    ///
    /// # Errors
    ///
    /// [`Error::SceneFull`] when the scene already holds `N` triangles.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
    /// use trirast::{band::{Scene, SceneStyle}, Error, FlatStyle, Triangle};
    ///
    /// let mut scene: Scene<Gray8, 1> = Scene::new(Rectangle::new(Point::zero(), Size::new(8, 8)));
    /// let t = Triangle::new(Point::new(0, 0), Point::new(7, 0), Point::new(0, 7));
    /// let style = SceneStyle::Flat(FlatStyle::new(Gray8::WHITE));
    /// scene.push(t, style)?;
    /// assert_eq!(scene.push(t, style), Err(Error::SceneFull { capacity: 1 }));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn push(&mut self, triangle: G, style: SceneStyle<C, T>) -> Result<(), Error> {
        self.push_item(triangle, None, style, u8::MAX, false)
    }

    /// Adds a triangle drawn through the depth test, with `depths` per vertex.
    ///
    /// # Errors
    ///
    /// [`Error::SceneFull`] when the scene already holds `N` triangles.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
    /// use trirast::{band::{Scene, SceneStyle}, FlatStyle, Triangle};
    ///
    /// let mut scene: Scene<Gray8, 4> = Scene::new(Rectangle::new(Point::zero(), Size::new(8, 8)));
    /// let t = Triangle::new(Point::new(0, 0), Point::new(7, 0), Point::new(0, 7));
    /// scene.push_with_depth(t, [10, 20, 30], SceneStyle::Flat(FlatStyle::new(Gray8::WHITE)))?;
    /// assert_eq!(scene.triangles()[0].depths, Some([10, 20, 30]));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn push_with_depth(
        &mut self,
        triangle: G,
        depths: [u16; 3],
        style: SceneStyle<C, T>,
    ) -> Result<(), Error> {
        self.push_item(triangle, Some(depths), style, u8::MAX, false)
    }

    /// Appends a triangle drawn at `opacity` (255: opaque) over what the band holds, as
    /// [`Framebuffer::translucent`](crate::Framebuffer::translucent) draws over a frame: each
    /// pixel blended once, by [`blend`](crate::target::blend). Not depth-tested. Render
    /// the scene with [`Bands::render_blended`].
    ///
    /// # Errors
    ///
    /// [`Error::SceneFull`] when the scene holds `N` triangles already.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::{Gray8, GrayColor}, prelude::*, primitives::Rectangle};
    /// use trirast::{band::{Bands, Scene, SceneStyle}, FlatStyle, Framebuffer, Triangle};
    ///
    /// let mut scene: Scene<Gray8, 1> = Scene::new(Rectangle::new(Point::zero(), Size::new(8, 8)));
    /// let t = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
    /// scene.push_translucent(t, SceneStyle::Flat(FlatStyle::new(Gray8::WHITE)), 128)?;
    /// let (mut band, mut frame) = ([Gray8::BLACK; 8 * 2], [Gray8::BLACK; 8 * 8]);
    /// let mut display = Framebuffer::new(&mut frame, 8, 8)?;
    /// Bands::new(&mut band, 8, 2)?.render_blended(&scene, Gray8::BLACK, &mut display).unwrap();
    /// assert_eq!(display.pixel(Point::new(1, 1)), Some(Gray8::new(128)));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn push_translucent(
        &mut self,
        triangle: G,
        style: SceneStyle<C, T>,
        opacity: u8,
    ) -> Result<(), Error> {
        self.push_item(triangle, None, style, opacity, false)
    }

    /// Appends a triangle drawn with anti-aliased edges at `opacity` (255: opaque), as
    /// [`BlendTarget::draw_anti_aliased`](crate::target::BlendTarget::draw_anti_aliased)
    /// draws into a frame: each pixel blended by the area of it the triangle covers. Not
    /// depth-tested. Render the scene with [`Bands::render_blended`].
    ///
    /// # Errors
    ///
    /// [`Error::SceneFull`] when the scene holds `N` triangles already.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::{Gray8, GrayColor}, prelude::*, primitives::Rectangle};
    /// use trirast::{band::{Bands, Scene, SceneStyle}, FlatStyle, Framebuffer, Triangle};
    ///
    /// let mut scene: Scene<Gray8, 1> = Scene::new(Rectangle::new(Point::zero(), Size::new(8, 8)));
    /// let t = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
    /// scene.push_anti_aliased(t, SceneStyle::Flat(FlatStyle::new(Gray8::WHITE)), 255)?;
    /// let (mut band, mut frame) = ([Gray8::BLACK; 8 * 2], [Gray8::BLACK; 8 * 8]);
    /// let mut display = Framebuffer::new(&mut frame, 8, 8)?;
    /// Bands::new(&mut band, 8, 2)?.render_blended(&scene, Gray8::BLACK, &mut display).unwrap();
    /// // On the hypotenuse (through pixel centres): half covered.
    /// assert_eq!(display.pixel(Point::new(4, 4)), Some(Gray8::new(128)));
    /// assert_eq!(display.pixel(Point::new(2, 2)), Some(Gray8::WHITE));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn push_anti_aliased(
        &mut self,
        triangle: G,
        style: SceneStyle<C, T>,
        opacity: u8,
    ) -> Result<(), Error> {
        self.push_item(triangle, None, style, opacity, true)
    }

    fn push_item(
        &mut self,
        triangle: G,
        depths: Option<[u16; 3]>,
        style: SceneStyle<C, T>,
        opacity: u8,
        anti_aliased: bool,
    ) -> Result<(), Error> {
        let rows = covered_rows(&triangle, &self.screen);
        self.triangles
            .push(SceneTriangle {
                triangle,
                depths,
                style,
                rows,
                opacity,
                anti_aliased,
            })
            .map_err(|_| Error::SceneFull { capacity: N })
    }

    /// Empties the scene for the next frame.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
    /// use trirast::{band::{Scene, SceneStyle}, FlatStyle, Triangle};
    ///
    /// let mut scene: Scene<Rgb565, 2> = Scene::new(Rectangle::new(Point::zero(), Size::new(8, 8)));
    /// scene.push(Triangle::new(Point::zero(), Point::new(4, 0), Point::new(0, 4)), SceneStyle::Flat(FlatStyle::new(Rgb565::RED)))?;
    /// scene.clear();
    /// assert!(scene.triangles().is_empty());
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn clear(&mut self) {
        self.triangles.clear();
    }

    /// The triangles, in drawing order.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*, primitives::Rectangle};
    /// use trirast::{band::{Scene, SceneStyle}, FlatStyle, Triangle};
    ///
    /// let mut scene: Scene<Gray8, 4> = Scene::new(Rectangle::new(Point::zero(), Size::new(8, 8)));
    /// let t = Triangle::new(Point::new(0, 2), Point::new(7, 2), Point::new(0, 5));
    /// scene.push(t, SceneStyle::Flat(FlatStyle::new(Gray8::WHITE)))?;
    /// assert_eq!(scene.triangles().len(), 1);
    /// assert_eq!(scene.triangles()[0].rows, 2..6);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn triangles(&self) -> &[SceneTriangle<C, T, G>] {
        &self.triangles
    }
}

impl<C: PixelColor, const N: usize, T: TexelSource<Color = C>, G> fmt::Debug
    for Scene<'_, C, N, T, G>
where
    C: fmt::Debug,
    T: fmt::Debug,
{
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Scene")
            .field("screen", &self.screen)
            .field("triangles", &self.triangles.len())
            .field("capacity", &N)
            .finish()
    }
}

/// The rows of `screen` the triangle's samples can lie on.
fn covered_rows<G: Shape>(triangle: &G, screen: &Rectangle) -> core::ops::Range<i32> {
    let (top, bottom) = triangle.sample_rows();
    let screen_top = i64::from(screen.top_left.y);
    let screen_bottom = screen_top + i64::from(screen.size.height);
    // Rows are pixel rows: the bottom vertex's row is included (inclusive fill rule).
    let (first, last) = (top.max(screen_top), (bottom + 1).min(screen_bottom));
    if first >= last {
        0..0
    } else {
        // Both within the screen, whose rows are i32.
        first as i32..last as i32
    }
}

/// What band rendering can fail with: a setup error, or the display's.
///
/// # Examples
///
/// ```
/// use trirast::{band::BandError, Error};
///
/// let e: BandError<core::convert::Infallible> = BandError::Setup(Error::SceneFull { capacity: 1 });
/// assert!(matches!(e, BandError::Setup(_)));
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum BandError<E> {
    /// The bands do not fit the scene's screen.
    Setup(Error),
    /// The display target failed.
    Target(E),
}

/// A band buffer of a few rows (and optionally a depth band) that renders a [`Scene`] into a
/// display target band by band.
///
/// `S` is how pixels are stored, as in [`Framebuffer`]: the colour itself, or raw `u16` for an
/// SPI display's byte order.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use trirast::{band::Bands, Error};
///
/// // 16 rows of a 320-pixel-wide screen, with a depth band: 20 KB in all.
/// let mut band = [Rgb565::default(); 320 * 16];
/// let mut depth_band = [0u16; 320 * 16];
/// let _bands = Bands::new(&mut band, 320, 16)?.with_depth(&mut depth_band)?;
/// // A buffer that does not hold the rows is an error, not a panic later.
/// assert_eq!(Bands::new(&mut [Rgb565::default(); 10], 320, 16).unwrap_err(),
///            Error::BufferLength { expected: 320 * 16, actual: 10 });
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Debug)]
pub struct Bands<'b, C, S = C, K = NoSetupCache> {
    pixels: &'b mut [S],
    depths: Option<&'b mut [u16]>,
    /// Where triangles' set-ups are kept between bands (nowhere unless given).
    setups: K,
    width: u32,
    rows: u32,
    far: u16,
    color: core::marker::PhantomData<C>,
}

impl<'b, C, S> Bands<'b, C, S>
where
    C: PixelColor,
    S: StoredPixel<C>,
{
    /// A band of `rows` rows of `width` pixels over `pixels`.
    ///
    /// # Errors
    ///
    /// [`Error::BandHeight`] for zero rows; [`Error::BufferLength`] unless
    /// `pixels.len() == width * rows`; [`Error::DimensionsTooLarge`] beyond `i32` sides.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Rgb565;
    /// use trirast::{band::Bands, Error};
    ///
    /// let mut band = [Rgb565::default(); 320 * 16];
    /// assert!(Bands::new(&mut band, 320, 16).is_ok());
    /// assert_eq!(Bands::new(&mut band, 320, 0).unwrap_err(), Error::BandHeight);
    /// ```
    pub fn new(pixels: &'b mut [S], width: u32, rows: u32) -> Result<Self, Error> {
        if rows == 0 {
            return Err(Error::BandHeight);
        }
        // Checks the length and the sides.
        Framebuffer::<C, S>::new(pixels, width, rows)?;
        Ok(Self {
            pixels,
            depths: None,
            setups: NoSetupCache,
            width,
            rows,
            far: u16::MAX,
            color: core::marker::PhantomData,
        })
    }

    /// The same bands keeping each triangle's interpolation set-up (colour, texture and depth
    /// planes) in `slots` between the bands it is drawn into, so that it is set up once per
    /// frame instead of once per band: memory for speed. Slot `k` serves the scene's triangle
    /// `k`; triangles beyond the slots are set up in every band they touch, as without a
    /// cache, and so are triangles within one band (nothing to keep). The image is the same,
    /// bit for bit, with or without.
    ///
    /// A 320 x 240 scene of 200 Gouraud triangles with depth in 16-row bands draws each
    /// triangle into 3.6 bands on average; with 200 slots (24,000 bytes on Cortex-M) the
    /// bands cost Cortex-M0 1.16 times the instructions of the full-frame render and
    /// Cortex-M4F 1.17 times, against 1.27 and 1.22 without (BENCHMARKS.md).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
    /// use trirast::{band::{Bands, Scene, SceneStyle, SetupSlot}, Framebuffer, GouraudStyle, Triangle};
    ///
    /// let screen = Rectangle::new(Point::zero(), Size::new(64, 48));
    /// let mut scene: Scene<Rgb565, 8> = Scene::new(screen);
    /// let t = Triangle::new(Point::new(2, 2), Point::new(60, 10), Point::new(20, 46));
    /// let style = SceneStyle::Gouraud(GouraudStyle::new([Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE]));
    /// scene.push_with_depth(t, [100, 200, 300], style)?;
    ///
    /// let (mut band, mut depth_band) = ([Rgb565::BLACK; 64 * 8], [0u16; 64 * 8]);
    /// let cache = [SetupSlot::EMPTY; 8];
    /// let mut bands = Bands::new(&mut band, 64, 8)?
    ///     .with_depth(&mut depth_band)?
    ///     .with_setup_cache(&cache);
    /// let mut frame = [Rgb565::BLACK; 64 * 48];
    /// let mut display = Framebuffer::new(&mut frame, 64, 48)?;
    /// bands.render(&scene, Rgb565::BLACK, &mut display).unwrap();
    ///
    /// // The same pixels as a full-frame render.
    /// let mut whole = [Rgb565::BLACK; 64 * 48];
    /// let mut frame_only = Framebuffer::new(&mut whole, 64, 48)?;
    /// let mut depths = [u16::MAX; 64 * 48];
    /// let mut zbuffer = trirast::depth::DepthBuffer::new(&mut depths, 64, 48)?;
    /// let mut layered = trirast::depth::DepthTarget::new(&mut frame_only, &mut zbuffer)?;
    /// layered.draw(&t, [100, 200, 300], &GouraudStyle::new([Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE])).unwrap();
    /// assert_eq!(frame, whole);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn with_setup_cache(self, slots: &'b [SetupSlot]) -> Bands<'b, C, S, &'b [SetupSlot]> {
        Bands {
            pixels: self.pixels,
            depths: self.depths,
            setups: slots,
            width: self.width,
            rows: self.rows,
            far: self.far,
            color: self.color,
        }
    }
}

impl<'b, C, S, K> Bands<'b, C, S, K>
where
    C: PixelColor,
    S: StoredPixel<C>,
    K: SetupCache,
{
    /// The same bands with a depth band over `depths` (as many entries as pixels), cleared to
    /// `u16::MAX` (farthest) before each band.
    ///
    /// # Errors
    ///
    /// [`Error::BufferLength`] unless `depths` has one entry per band pixel.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Rgb565;
    /// use trirast::{band::Bands, Error};
    ///
    /// let (mut band, mut depths) = ([Rgb565::default(); 64 * 4], [0u16; 64 * 3]);
    /// let bands = Bands::new(&mut band, 64, 4)?;
    /// assert!(matches!(bands.with_depth(&mut depths), Err(Error::BufferLength { .. })));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn with_depth(mut self, depths: &'b mut [u16]) -> Result<Self, Error> {
        let expected = self.pixels.len();
        if depths.len() != expected {
            return Err(Error::BufferLength {
                expected,
                actual: depths.len(),
            });
        }
        self.depths = Some(depths);
        Ok(self)
    }

    /// The same bands with depth bands cleared to `far` instead of `u16::MAX` (for
    /// [`DepthTest::Greater`], clear to 0).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Rgb565;
    /// use trirast::band::Bands;
    ///
    /// let mut band = [Rgb565::default(); 8];
    /// let _bands = Bands::new(&mut band, 8, 1)?.with_far_depth(0);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[must_use]
    pub fn with_far_depth(mut self, far: u16) -> Self {
        self.far = far;
        self
    }

    /// Renders `scene` band by band from the top: each band is cleared to `background` (and
    /// the depth band to the far depth), gets the triangles whose rows it touches, in scene
    /// order, and goes to `target` as one `fill_contiguous` call.
    ///
    /// # Errors
    ///
    /// [`BandError::Setup`] with [`Error::BandWidth`] unless the bands are as wide as the
    /// scene's screen, or [`Error::BandDepth`] if the scene has depth-tested triangles and the
    /// bands no depth band, or [`Error::BandBlending`] if it has translucent or anti-aliased
    /// triangles (see [`Bands::render_blended`]); [`BandError::Target`] with the target's
    /// first error.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{mock_display::MockDisplay, pixelcolor::BinaryColor, prelude::*, primitives::Rectangle};
    /// use trirast::{band::{Bands, Scene, SceneStyle}, FlatStyle, Triangle};
    ///
    /// let screen = Rectangle::new(Point::zero(), Size::new(4, 4));
    /// let mut scene: Scene<BinaryColor, 2> = Scene::new(screen);
    /// let t = Triangle::new(Point::new(0, 0), Point::new(4, 0), Point::new(0, 4));
    /// scene.push(t, SceneStyle::Flat(FlatStyle::new(BinaryColor::On)))?;
    /// // One row at a time: four bands, each one `fill_contiguous` call.
    /// let mut band = [BinaryColor::Off; 4];
    /// let mut display = MockDisplay::new();
    /// Bands::new(&mut band, 4, 1)?.render(&scene, BinaryColor::Off, &mut display).unwrap();
    /// display.assert_pattern(&["####", "###.", "##..", "#..."]);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn render<D, const N: usize, T, G>(
        &mut self,
        scene: &Scene<'_, C, N, T, G>,
        background: C,
        target: &mut D,
    ) -> Result<(), BandError<D::Error>>
    where
        D: DrawTarget<Color = C>,
        T: TexelSource<Color = C> + Copy,
        G: Shape,
        C: ChannelColor,
        TextureStyle<T>: crate::shading::TriangleStyle<Color = C>,
        GouraudStyle<C>: crate::shading::TriangleStyle<Color = C>,
    {
        self.render_with(scene, background, to_target(target))
    }

    /// [`Bands::render`] for scenes that also hold translucent and anti-aliased triangles
    /// ([`Scene::push_translucent`], [`Scene::push_anti_aliased`]), blended into the band as
    /// [`Framebuffer::translucent`] and
    /// [`BlendTarget::draw_anti_aliased`](crate::target::BlendTarget::draw_anti_aliased) blend
    /// into a frame: bit for bit the same image. A method of its own because blending brings
    /// its own copy of every style's drawing code (measured: 75 KB more `.text` on Cortex-M0
    /// for a firmware whose scenes use every texture filter, wrap and modulation), which
    /// firmware that renders opaque scenes should not carry.
    ///
    /// # Errors
    ///
    /// As [`Bands::render`], but for [`Error::BandBlending`].
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::{Gray8, GrayColor}, prelude::*, primitives::Rectangle};
    /// use trirast::{band::{BandError, Bands, Scene, SceneStyle}, Error, FlatStyle, Framebuffer, Triangle};
    ///
    /// let mut scene: Scene<Gray8, 1> = Scene::new(Rectangle::new(Point::zero(), Size::new(8, 8)));
    /// let t = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
    /// scene.push_translucent(t, SceneStyle::Flat(FlatStyle::new(Gray8::WHITE)), 64)?;
    /// let (mut band, mut frame) = ([Gray8::BLACK; 8 * 4], [Gray8::BLACK; 8 * 8]);
    /// let mut display = Framebuffer::new(&mut frame, 8, 8)?;
    /// let mut bands = Bands::new(&mut band, 8, 4)?;
    /// assert_eq!(bands.render(&scene, Gray8::BLACK, &mut display), Err(BandError::Setup(Error::BandBlending)));
    /// bands.render_blended(&scene, Gray8::BLACK, &mut display).unwrap();
    /// assert_eq!(display.pixel(Point::new(1, 1)), Some(Gray8::new(64)));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn render_blended<D, const N: usize, T, G>(
        &mut self,
        scene: &Scene<'_, C, N, T, G>,
        background: C,
        target: &mut D,
    ) -> Result<(), BandError<D::Error>>
    where
        D: DrawTarget<Color = C>,
        T: TexelSource<Color = C> + Copy,
        G: Shape,
        C: ChannelColor,
        TextureStyle<T>: crate::shading::TriangleStyle<Color = C>,
        GouraudStyle<C>: crate::shading::TriangleStyle<Color = C>,
    {
        self.render_blended_with(scene, background, to_target(target))
    }

    /// Renders `scene` as [`Bands::render`] does, but hands each finished band to `flush` as
    /// its screen area and its pixels as stored, row-major (`S`: raw `u16` in the display's
    /// byte order, say), instead of drawing it into a target: the way to stream bands to a
    /// display by DMA or a raw bus write, without a colour conversion per pixel. The buffer is
    /// reused for the next band once `flush` returns (with one band buffer, a DMA transfer
    /// must end before `flush` does).
    ///
    /// # Errors
    ///
    /// As [`Bands::render`]; [`BandError::Target`] with `flush`'s first error, after which no
    /// band is rendered.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
    /// use trirast::{band::{Bands, Scene, SceneStyle}, FlatStyle, Triangle};
    ///
    /// let screen = Rectangle::new(Point::zero(), Size::new(8, 8));
    /// let mut scene: Scene<Rgb565, 1> = Scene::new(screen);
    /// let t = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
    /// scene.push(t, SceneStyle::Flat(FlatStyle::new(Rgb565::RED)))?;
    ///
    /// // Pixels stored as the display takes them: big-endian Rgb565 words.
    /// let mut band = [0u16; 8 * 4];
    /// let mut bands: Bands<Rgb565, u16> = Bands::new(&mut band, 8, 4)?;
    /// let mut wire = Vec::new();
    /// bands
    ///     .render_with(&scene, Rgb565::BLACK, |area, pixels| {
    ///         // A display driver would set its window to `area` and send the bytes.
    ///         assert_eq!(area.size, Size::new(8, 4));
    ///         wire.extend(pixels.iter().flat_map(|p| p.to_be_bytes()));
    ///         Ok::<(), ()>(())
    ///     })
    ///     .unwrap();
    /// assert_eq!(wire.len(), 8 * 8 * 2);
    /// assert_eq!(&wire[..2], &[0xF8, 0x00]); // (0, 0) is red
    /// assert_eq!(&wire[wire.len() - 2..], &[0x00, 0x00]); // (7, 7) is black
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn render_with<E, const N: usize, T, G>(
        &mut self,
        scene: &Scene<'_, C, N, T, G>,
        background: C,
        flush: impl FnMut(&Rectangle, &[S]) -> Result<(), E>,
    ) -> Result<(), BandError<E>>
    where
        T: TexelSource<Color = C> + Copy,
        G: Shape,
        C: ChannelColor,
        TextureStyle<T>: crate::shading::TriangleStyle<Color = C>,
        GouraudStyle<C>: crate::shading::TriangleStyle<Color = C>,
    {
        if scene
            .triangles
            .iter()
            .any(|t| t.anti_aliased || t.opacity < u8::MAX)
        {
            return Err(BandError::Setup(Error::BandBlending));
        }
        self.render_each::<_, _, N, T, G, false>(scene, background, flush)
    }

    /// [`Bands::render_with`] for scenes that also hold translucent and anti-aliased
    /// triangles, blended as [`Bands::render_blended`] blends them.
    ///
    /// # Errors
    ///
    /// As [`Bands::render_with`], but for [`Error::BandBlending`].
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::{Gray8, GrayColor}, prelude::*, primitives::Rectangle};
    /// use trirast::{band::{Bands, Scene, SceneStyle}, FlatStyle, Triangle};
    ///
    /// let mut scene: Scene<Gray8, 1> = Scene::new(Rectangle::new(Point::zero(), Size::new(8, 8)));
    /// let t = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
    /// scene.push_translucent(t, SceneStyle::Flat(FlatStyle::new(Gray8::WHITE)), 64)?;
    /// let mut band = [0u8; 8 * 4];
    /// let mut bands: Bands<Gray8, u8> = Bands::new(&mut band, 8, 4)?;
    /// let mut first = None;
    /// bands
    ///     .render_blended_with(&scene, Gray8::BLACK, |_, pixels| {
    ///         first.get_or_insert(pixels[0]);
    ///         Ok::<(), ()>(())
    ///     })
    ///     .unwrap();
    /// assert_eq!(first, Some(64));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    pub fn render_blended_with<E, const N: usize, T, G>(
        &mut self,
        scene: &Scene<'_, C, N, T, G>,
        background: C,
        flush: impl FnMut(&Rectangle, &[S]) -> Result<(), E>,
    ) -> Result<(), BandError<E>>
    where
        T: TexelSource<Color = C> + Copy,
        G: Shape,
        C: ChannelColor,
        TextureStyle<T>: crate::shading::TriangleStyle<Color = C>,
        GouraudStyle<C>: crate::shading::TriangleStyle<Color = C>,
    {
        self.render_each::<_, _, N, T, G, true>(scene, background, flush)
    }

    /// Renders every band; `BLEND` builds in the drawing of translucent and anti-aliased
    /// triangles.
    fn render_each<E, F, const N: usize, T, G, const BLEND: bool>(
        &mut self,
        scene: &Scene<'_, C, N, T, G>,
        background: C,
        mut flush: F,
    ) -> Result<(), BandError<E>>
    where
        F: FnMut(&Rectangle, &[S]) -> Result<(), E>,
        T: TexelSource<Color = C> + Copy,
        G: Shape,
        C: ChannelColor,
        TextureStyle<T>: crate::shading::TriangleStyle<Color = C>,
        GouraudStyle<C>: crate::shading::TriangleStyle<Color = C>,
    {
        let screen = scene.screen;
        if screen.size.width != self.width {
            return Err(BandError::Setup(Error::BandWidth {
                band: self.width,
                screen: screen.size.width,
            }));
        }
        if self.depths.is_none() && scene.triangles.iter().any(|t| t.depths.is_some()) {
            return Err(BandError::Setup(Error::BandDepth));
        }
        // Set-ups kept from an earlier frame may belong to other triangles now (a cache sized
        // for the largest scene need not be cleared whole for a smaller one).
        self.setups.forget(scene.triangles.len());
        let bottom = i64::from(screen.top_left.y) + i64::from(screen.size.height);
        let mut top = i64::from(screen.top_left.y);
        while top < bottom {
            // Rows of this band: at most `rows`, fewer for the last one.
            let rows = (bottom - top).min(i64::from(self.rows)) as u32;
            let len = (self.width * rows) as usize;
            let band_top = top as i32;
            let area = Rectangle::new(
                Point::new(screen.top_left.x, band_top),
                Size::new(self.width, rows),
            );
            self.render_band::<N, T, G, BLEND>(scene, background, &area, len);
            flush(&area, &self.pixels[..len]).map_err(BandError::Target)?;
            top += i64::from(rows);
        }
        Ok(())
    }

    /// Draws the triangles touching `area` (one band) into the band buffers.
    fn render_band<const N: usize, T, G, const BLEND: bool>(
        &mut self,
        scene: &Scene<'_, C, N, T, G>,
        background: C,
        area: &Rectangle,
        len: usize,
    ) where
        T: TexelSource<Color = C> + Copy,
        G: Shape,
        C: ChannelColor,
        TextureStyle<T>: crate::shading::TriangleStyle<Color = C>,
        GouraudStyle<C>: crate::shading::TriangleStyle<Color = C>,
    {
        let rows = area.size.height;
        let mut band = Framebuffer::<C, S>::new(&mut self.pixels[..len], self.width, rows)
            .unwrap_or_else(|_| unreachable!("band sized in Bands::new"));
        // Never fails: the framebuffer's error is Infallible.
        let _ = band.clear(background);
        // The band framebuffer addresses its rows from 0: its (0, 0) is the screen's `offset`,
        // which the painters subtract (one copy of each painter serves bands and frames).
        let offset = area.top_left;
        let mut depth_band = match self.depths.as_deref_mut() {
            Some(depths) => {
                let depths = &mut depths[..len];
                fill_run(depths, self.far);
                Some(
                    DepthBuffer::new(depths, self.width, rows)
                        .unwrap_or_else(|_| unreachable!("depth band sized in with_depth")),
                )
            }
            None => None,
        };
        let band_rows = area.top_left.y..area.top_left.y + rows as i32;
        let target = BandTarget {
            screen: scene.screen,
            offset,
            test: scene.test,
        };
        let setups = self.setups;
        for (index, item) in scene
            .triangles
            .iter()
            .enumerate()
            .filter(|(_, t)| t.rows.start < band_rows.end && band_rows.start < t.rows.end)
        {
            // With a cache, through the triangle's slot; without, the triangle itself, so
            // that bands without a cache build exactly the code they did before it existed.
            let drawn = if K::KEEPS {
                let later = item.rows.end > band_rows.end;
                let cached = Cached::new(&item.triangle, setups, index, later);
                let depth_band = depth_band.as_mut();
                draw_item::<_, _, _, _, BLEND>(&cached, item, &mut band, depth_band, &target)
            } else {
                let depth_band = depth_band.as_mut();
                draw_item::<_, _, _, _, BLEND>(&item.triangle, item, &mut band, depth_band, &target)
            };
            // The band framebuffer cannot fail.
            let Ok(()) = drawn;
        }
    }
}

/// The flush of [`Bands::render`]: each band into `target` as one `fill_contiguous` call.
fn to_target<C, S, D>(target: &mut D) -> impl FnMut(&Rectangle, &[S]) -> Result<(), D::Error> + '_
where
    C: PixelColor,
    S: StoredPixel<C>,
    D: DrawTarget<Color = C>,
{
    move |area, pixels| target.fill_contiguous(area, pixels.iter().map(|&p| p.load()))
}

/// Where a band's triangles go: the screen their interpolation is set up for, the band's
/// corner on it and the depth test.
struct BandTarget {
    screen: Rectangle,
    offset: Point,
    test: DepthTest,
}

/// Draws the scene triangle `item`, as `triangle`, into the band (and its depth band).
#[inline(always)]
fn draw_item<C, S, T, G, const BLEND: bool>(
    triangle: &impl Shape,
    item: &SceneTriangle<C, T, G>,
    band: &mut Framebuffer<'_, C, S>,
    depth_band: Option<&mut DepthBuffer<'_>>,
    target: &BandTarget,
) -> Result<(), core::convert::Infallible>
where
    C: ChannelColor,
    S: StoredPixel<C>,
    T: TexelSource<Color = C> + Copy,
    TextureStyle<T>: crate::shading::TriangleStyle<Color = C>,
    GouraudStyle<C>: crate::shading::TriangleStyle<Color = C>,
{
    let (screen, offset) = (target.screen, target.offset);
    match (item.depths, depth_band) {
        (Some(depths), Some(buffer)) => {
            let mut layered = DepthTarget::new(band, buffer)
                .unwrap_or_else(|_| unreachable!("band and depth band match"))
                .with_test(target.test)
                .with_offset(offset);
            match &item.style {
                SceneStyle::Flat(s) => layered.draw_in(triangle, depths, s, &screen),
                SceneStyle::Gouraud(s) => layered.draw_in(triangle, depths, s, &screen),
                SceneStyle::Texture(s) => layered.draw_in(triangle, depths, s, &screen),
            }
        }
        _ if BLEND && item.anti_aliased => {
            let mut blended = band.translucent(item.opacity);
            match &item.style {
                SceneStyle::Flat(s) => {
                    draw_anti_aliased_in(triangle, s, &mut blended, &screen, offset)
                }
                SceneStyle::Gouraud(s) => {
                    draw_anti_aliased_in(triangle, s, &mut blended, &screen, offset)
                }
                SceneStyle::Texture(s) => {
                    draw_anti_aliased_in(triangle, s, &mut blended, &screen, offset)
                }
            }
        }
        _ if BLEND && item.opacity < u8::MAX => {
            let mut blended = band.translucent(item.opacity);
            match &item.style {
                SceneStyle::Flat(s) => draw_plain_in(triangle, s, &mut blended, &screen, offset),
                SceneStyle::Gouraud(s) => draw_plain_in(triangle, s, &mut blended, &screen, offset),
                SceneStyle::Texture(s) => draw_plain_in(triangle, s, &mut blended, &screen, offset),
            }
        }
        _ => match &item.style {
            SceneStyle::Flat(s) => draw_plain_in(triangle, s, band, &screen, offset),
            SceneStyle::Gouraud(s) => draw_plain_in(triangle, s, band, &screen, offset),
            SceneStyle::Texture(s) => draw_plain_in(triangle, s, band, &screen, offset),
        },
    }
}
