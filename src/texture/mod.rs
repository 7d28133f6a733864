//! Textures: where texels come from and how texture coordinates address them.
//!
//! A texture is any [`TexelSource`]: [`Texels`] over a slice of colours (the fastest),
//! [`RawTexels`] over raw image bytes as `ImageRaw` and `include_bytes!` hold them, or
//! [`ImageTexels`] over any embedded-graphics image with random access (`ImageRaw`,
//! `tinybmp::Bmp`, ...). Nothing is copied or allocated.
//!
//! [`TextureStyle`](crate::TextureStyle) maps one onto triangles.
//!
//! # Texture coordinates
//!
//! Coordinates are in texels, as `I16F16`, and texel `(i, j)` is centred on `(i, j)`, like a
//! pixel in embedded-graphics: mapping a `w` x `h` texture's corners `(0, 0)` and `(w, h)` to
//! a rectangle's corners draws it pixel for pixel.
//!
//! - [`Filter::Nearest`] takes the texel containing the coordinate, the one at
//!   `floor(u + 1/2)`, `floor(v + 1/2)`: a coordinate exactly between two texels (`2.5`) takes
//!   the higher one (`3`).
//! - [`Filter::Bilinear`] blends the four texels around the coordinate, weighted by its
//!   fractions (see [`ChannelColor::bilinear`](crate::shading::ChannelColor::bilinear)).
//!
//! Coordinates outside the texture [`Wrap`] around or clamp to the edge.

mod address;
mod source;

pub(crate) use address::{Axis, Clamped, Direct, Pow2Repeated, Repeated, COORDINATE_BITS};
pub use source::{ImageTexels, RawTexels, TexelByteOrder, TexelSource, Texels, MAX_TEXTURE_SIDE};

/// How a texture is sampled between texel centres.
///
/// # Examples
///
/// ```
/// use trirast::texture::Filter;
///
/// assert_eq!(Filter::default(), Filter::Nearest);
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, Hash)]
pub enum Filter {
    /// The texel containing the coordinate: crisp, fastest.
    #[default]
    Nearest,
    /// The four texels around the coordinate, blended by distance: smooth when magnified.
    Bilinear,
}

/// What coordinates outside the texture address.
///
/// # Examples
///
/// ```
/// use trirast::texture::Wrap;
///
/// assert_eq!(Wrap::default(), Wrap::Clamp);
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, Hash)]
pub enum Wrap {
    /// The edge texels extend outwards forever (OpenGL's clamp-to-edge).
    #[default]
    Clamp,
    /// The texture tiles the plane. Power-of-two sides wrap by masking; other sides cost one
    /// division per span.
    Repeat,
}

/// How many pixels apart perspective-correct texturing divides: the true texture coordinates
/// are computed at both ends of each sub-span of a row, and stepped linearly between.
///
/// Shorter sub-spans follow the true curve more closely and divide more often. Within a
/// sub-span the error is what linear steps between two exact points give: at most
/// `L^2 * |d²u/dx²| / 8` texels for a sub-span of `L` pixels, small unless the texture is
/// magnified steeply along the row.
///
/// # Examples
///
/// ```
/// use trirast::texture::SubSpan;
///
/// assert_eq!(SubSpan::default(), SubSpan::Pixels16);
/// assert_eq!(SubSpan::Pixels8.pixels(), 8);
/// ```
#[derive(Copy, Clone, Debug, Default, PartialEq, Eq, Hash)]
pub enum SubSpan {
    /// 8 pixels.
    Pixels8,
    /// 16 pixels, as Quake divided.
    #[default]
    Pixels16,
    /// 32 pixels.
    Pixels32,
}

impl SubSpan {
    /// The pixels per sub-span.
    ///
    /// # Examples
    ///
    /// ```
    /// use trirast::texture::SubSpan;
    ///
    /// assert_eq!(SubSpan::Pixels32.pixels(), 32);
    /// ```
    #[inline]
    #[must_use]
    pub const fn pixels(self) -> u32 {
        match self {
            Self::Pixels8 => 8,
            Self::Pixels16 => 16,
            Self::Pixels32 => 32,
        }
    }
}

/// Perspective-correct texture mapping: each vertex's `w` (its distance along the view
/// direction, as the projection's fourth coordinate gives it), and the sub-span length.
///
/// Texture coordinates divided by `w` and `1 / w` itself are linear on screen; the true
/// coordinates are recovered from them at both ends of every [`SubSpan`] of a row, by a
/// reciprocal from a table and two Newton steps in integer arithmetic (no division, no
/// float), and stepped linearly between.
///
/// - At the ends of sub-spans the coordinates are within 1/256 texel of the exact rational
///   perspective ones, for `w` ratios up to 1:256 within a triangle and coordinates changing
///   by less than 4096 texels across it.
/// - Between, they follow the straight line between the two ends (see [`SubSpan`]).
/// - Equal `w` at the three vertices (a face parallel to the screen) draws exactly what the
///   affine mapping draws.
///
/// `w` must be positive; values that are not count as the smallest positive `I16F16`. Only the
/// ratios between the three matter. Modulation colours stay affine on screen.
///
/// # Examples
///
/// ```
/// use fixed::types::I16F16;
/// use trirast::texture::{Perspective, SubSpan};
///
/// let w = [1, 4, 4].map(I16F16::from_num);
/// let perspective = Perspective::new(w).with_sub_span(SubSpan::Pixels8);
/// assert_eq!(perspective.sub_span.pixels(), 8);
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Perspective {
    /// Each vertex's `w`, in the triangle's vertex order.
    pub w: [fixed::types::I16F16; 3],
    /// Pixels between divisions; [`SubSpan::Pixels16`] by default.
    pub sub_span: SubSpan,
}

impl Perspective {
    /// Perspective with weights `w`, one per vertex, and 16-pixel sub-spans.
    ///
    /// # Examples
    ///
    /// ```
    /// use fixed::types::I16F16;
    /// use trirast::texture::{Perspective, SubSpan};
    ///
    /// let perspective = Perspective::new([I16F16::ONE; 3]);
    /// assert_eq!(perspective.sub_span, SubSpan::Pixels16);
    /// ```
    #[inline]
    #[must_use]
    pub const fn new(w: [fixed::types::I16F16; 3]) -> Self {
        Self {
            w,
            sub_span: SubSpan::Pixels16,
        }
    }

    /// The same with another sub-span length.
    ///
    /// # Examples
    ///
    /// ```
    /// use fixed::types::I16F16;
    /// use trirast::texture::{Perspective, SubSpan};
    ///
    /// let perspective = Perspective::new([I16F16::ONE; 3]).with_sub_span(SubSpan::Pixels32);
    /// assert_eq!(perspective.sub_span, SubSpan::Pixels32);
    /// ```
    #[inline]
    #[must_use]
    pub const fn with_sub_span(mut self, sub_span: SubSpan) -> Self {
        self.sub_span = sub_span;
        self
    }

    /// Whether the three weights are equal: the mapping is then affine.
    #[inline]
    pub(crate) fn is_affine(&self) -> bool {
        let [a, b, c] = self.w.map(|w| w.to_bits().max(1));
        a == b && b == c
    }
}
