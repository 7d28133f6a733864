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

pub(crate) use address::{Axis, COORDINATE_BITS, Narrow, RAW_SHIFT, Scaled, Wrapped};
pub use source::{
    ImageTexels, MAX_TEXTURE_SIDE, NoTexture, RawTexels, TexelByteOrder, TexelSource, Texels,
};

pub use crate::interpolate::{Perspective, SubSpan};

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
