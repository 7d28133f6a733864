//! The crate's error type.

use core::fmt;

/// What can go wrong when setting up buffers, targets and textures.
///
/// Drawing itself never fails on its own: bad geometry (degenerate, huge or off-screen
/// triangles) draws what the fill rule says, possibly nothing. Errors are reported where a
/// buffer is handed over, so nothing fails later, mid-frame.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use trirast::{Error, Framebuffer};
///
/// let mut pixels = [Rgb565::default(); 100];
/// let err = Framebuffer::new(&mut pixels, 16, 16).unwrap_err();
/// assert_eq!(err, Error::BufferLength { expected: 256, actual: 100 });
/// assert_eq!(err.to_string(), "buffer holds 100 elements, its dimensions need 256");
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Error {
    /// A buffer's length does not match `width * height`.
    BufferLength {
        /// The length the dimensions need.
        expected: usize,
        /// The length given.
        actual: usize,
    },
    /// A side exceeds `i32::MAX` (pixels need `Point` coordinates) or `width * height`
    /// overflows `usize`.
    DimensionsTooLarge {
        /// Width given.
        width: u32,
        /// Height given.
        height: u32,
    },
    /// A depth buffer's size differs from its target's.
    DepthBufferSize {
        /// The depth buffer's width and height.
        buffer: embedded_graphics::geometry::Size,
        /// The target's.
        target: embedded_graphics::geometry::Size,
    },
    /// A mesh triangle refers to a vertex that is not there.
    MeshIndex {
        /// The triangle's position in the index list.
        triangle: usize,
        /// The index past the end of the vertices.
        index: u16,
    },
    /// A scene is full: it holds `capacity` triangles already.
    SceneFull {
        /// The scene's capacity.
        capacity: usize,
    },
    /// A band of zero rows.
    BandHeight,
    /// Bands narrower or wider than the screen they render.
    BandWidth {
        /// The bands' width.
        band: u32,
        /// The screen's.
        screen: u32,
    },
    /// A scene with depth-tested triangles rendered by bands without a depth band.
    BandDepth,
    /// A scene with translucent or anti-aliased triangles rendered by
    /// [`Bands::render`](crate::band::Bands::render), which draws opaque triangles only (its
    /// code stays small): [`Bands::render_blended`](crate::band::Bands::render_blended) draws
    /// them.
    BandBlending,
    /// A texture side is zero or beyond [`MAX_TEXTURE_SIDE`](crate::texture::MAX_TEXTURE_SIDE),
    /// or an image gives no texels.
    TextureSize {
        /// Width given.
        width: u32,
        /// Height given.
        height: u32,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::BufferLength { expected, actual } => {
                write!(
                    f,
                    "buffer holds {actual} elements, its dimensions need {expected}"
                )
            }
            Self::DimensionsTooLarge { width, height } => {
                write!(f, "dimensions {width}x{height} are too large to address")
            }
            Self::DepthBufferSize { buffer, target } => write!(
                f,
                "depth buffer is {}x{} but its target is {}x{}",
                buffer.width, buffer.height, target.width, target.height
            ),
            Self::MeshIndex { triangle, index } => write!(
                f,
                "mesh triangle {triangle} refers to vertex {index}, past the last vertex"
            ),
            Self::SceneFull { capacity } => {
                write!(
                    f,
                    "scene is full: it holds its capacity of {capacity} triangles"
                )
            }
            Self::BandHeight => write!(f, "bands need at least one row"),
            Self::BandWidth { band, screen } => {
                write!(f, "bands are {band} pixels wide but the screen is {screen}")
            }
            Self::BandDepth => write!(
                f,
                "the scene has depth-tested triangles but the bands have no depth band"
            ),
            Self::BandBlending => write!(
                f,
                "the scene has translucent or anti-aliased triangles: render it with render_blended"
            ),
            Self::TextureSize { width, height } => write!(
                f,
                "texture size {width}x{height} is not usable: sides must be 1 to 32768"
            ),
        }
    }
}

impl core::error::Error for Error {}
