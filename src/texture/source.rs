//! Where texels come from: typed slices, raw image bytes, or any embedded-graphics image.

use core::marker::PhantomData;

use embedded_graphics::{
    geometry::{OriginDimensions, Point, Size},
    image::GetPixel,
    pixelcolor::{
        PixelColor,
        raw::{BigEndian, ByteOrder, LittleEndian, RawData},
    },
};

use crate::Error;
use crate::bounds::{at, from, out_of_range};

/// A rectangle of texels with random access: what texture sampling reads.
///
/// Implemented by [`Texels`] (a slice of colours: the fastest), [`RawTexels`] (raw image bytes,
/// as `ImageRaw` and `include_bytes!` hold them) and [`ImageTexels`] (any embedded-graphics
/// image with random access, such as `ImageRaw` or `tinybmp::Bmp`). Images that can only be
/// read in order (a `tinytga::Tga`, for instance) can be drawn once into a
/// [`Framebuffer`](crate::Framebuffer) over a slice and used through [`Texels`].
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
/// use trirast::texture::{TexelSource, Texels};
///
/// let data = [Gray8::new(1), Gray8::new(2), Gray8::new(3), Gray8::new(4)];
/// let texels = Texels::new(&data, 2, 2)?;
/// assert_eq!(texels.size(), Size::new(2, 2));
/// assert_eq!(texels.texel(1, 1), Gray8::new(4));
/// # Ok::<(), trirast::Error>(())
/// ```
pub trait TexelSource {
    /// The colour of each texel.
    type Color: PixelColor;

    /// Width and height, both at least 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::BinaryColor, prelude::*};
    /// use trirast::texture::{TexelSource, Texels};
    ///
    /// let data = [BinaryColor::On; 6];
    /// assert_eq!(Texels::new(&data, 3, 2)?.size(), Size::new(3, 2));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    fn size(&self) -> Size;

    /// The texel at column `x`, row `y`; the caller keeps `x < width` and `y < height`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
    /// use trirast::texture::{TexelSource, Texels};
    ///
    /// let data = [Rgb565::RED, Rgb565::GREEN];
    /// assert_eq!(Texels::new(&data, 2, 1)?.texel(1, 0), Rgb565::GREEN);
    /// # Ok::<(), trirast::Error>(())
    /// ```
    fn texel(&self, x: u32, y: u32) -> Self::Color;

    /// The texels at columns `left` and `right` of rows `top` and `bottom` (in that order:
    /// top left, top right, bottom left, bottom right), for bilinear filtering; each within
    /// [`TexelSource::size`] by the same contract as [`TexelSource::texel`]. Four reads by
    /// default.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{pixelcolor::Gray8, prelude::*};
    /// use trirast::texture::{TexelSource, Texels};
    ///
    /// let data = [1, 2, 3, 4].map(Gray8::new);
    /// let texels = Texels::new(&data, 2, 2)?;
    /// assert_eq!(texels.quad(0, 1, 0, 1), [1, 2, 3, 4].map(Gray8::new));
    /// # Ok::<(), trirast::Error>(())
    /// ```
    #[inline(always)]
    fn quad(&self, left: u32, right: u32, top: u32, bottom: u32) -> [Self::Color; 4] {
        [
            self.texel(left, top),
            self.texel(right, top),
            self.texel(left, bottom),
            self.texel(right, bottom),
        ]
    }
}

/// The texture type of a scene without textures: a [`TexelSource`] no value can have.
///
/// A [`band::Scene`](crate::band::Scene) names one texture type for all its textured
/// triangles, and rendering it builds in texture mapping for that type. With `NoTexture` no
/// triangle can be textured, so the compiler leaves all of that out: about 10 KB of flash on
/// Cortex-M0 for a scene of flat and Gouraud triangles (`benches/firmware-size.sh`).
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*, primitives::Rectangle};
/// use trirast::{band::{Scene, SceneStyle}, texture::NoTexture, FlatStyle, Triangle};
///
/// let screen = Rectangle::new(Point::zero(), Size::new(8, 8));
/// let mut scene: Scene<Rgb565, 4, NoTexture<Rgb565>> = Scene::new(screen);
/// let t = Triangle::new(Point::new(0, 0), Point::new(8, 0), Point::new(0, 8));
/// scene.push(t, SceneStyle::Flat(FlatStyle::new(Rgb565::RED)))?;
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq, Hash)]
pub struct NoTexture<C>(core::convert::Infallible, PhantomData<C>);

impl<C: PixelColor> TexelSource for NoTexture<C> {
    type Color = C;

    #[inline(always)]
    fn size(&self) -> Size {
        match self.0 {}
    }

    #[inline(always)]
    fn texel(&self, _x: u32, _y: u32) -> C {
        match self.0 {}
    }
}

/// The largest texture side: texture coordinates are `I16F16`, which reach just below 2^15.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::BinaryColor;
/// use trirast::{texture::{RawTexels, MAX_TEXTURE_SIDE}, Error};
///
/// let wide = RawTexels::<BinaryColor>::new(&[0; 8192], 2 * MAX_TEXTURE_SIDE, 1);
/// assert!(matches!(wide, Err(Error::TextureSize { .. })));
/// ```
pub const MAX_TEXTURE_SIDE: u32 = 1 << 15;

/// Checks texture dimensions: both sides from 1 to [`MAX_TEXTURE_SIDE`].
fn checked_size(width: u32, height: u32) -> Result<(), Error> {
    let side = 1..=MAX_TEXTURE_SIDE;
    if side.contains(&width) && side.contains(&height) {
        Ok(())
    } else {
        Err(Error::TextureSize { width, height })
    }
}

/// Checks texture dimensions against a buffer length.
fn checked_len(width: u32, height: u32, len: usize) -> Result<(), Error> {
    checked_size(width, height)?;
    let expected = (width as usize)
        .checked_mul(height as usize)
        .ok_or(Error::TextureSize { width, height })?;
    if len == expected {
        Ok(())
    } else {
        Err(Error::BufferLength {
            expected,
            actual: len,
        })
    }
}

/// Texels in a slice of colours, row-major: the fastest source.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::Rgb565, prelude::*};
/// use trirast::{texture::Texels, Error};
///
/// static CHECKER: [Rgb565; 4] = [Rgb565::WHITE, Rgb565::BLACK, Rgb565::BLACK, Rgb565::WHITE];
/// let texels = Texels::new(&CHECKER, 2, 2)?;
/// assert!(matches!(Texels::new(&CHECKER, 3, 2), Err(Error::BufferLength { .. })));
/// assert!(matches!(Texels::new(&CHECKER[..0], 0, 0), Err(Error::TextureSize { .. })));
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Texels<'a, C> {
    pixels: &'a [C],
    width: u32,
    height: u32,
}

impl<'a, C: PixelColor> Texels<'a, C> {
    /// Wraps `pixels` as a `width` x `height` texture.
    ///
    /// # Errors
    ///
    /// [`Error::TextureSize`] if a side is zero or beyond [`MAX_TEXTURE_SIDE`],
    /// [`Error::BufferLength`] unless `pixels.len() == width * height`.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray4;
    /// use trirast::texture::Texels;
    ///
    /// let pixels = [Gray4::new(15); 8 * 8];
    /// assert!(Texels::new(&pixels, 8, 8).is_ok());
    /// ```
    pub fn new(pixels: &'a [C], width: u32, height: u32) -> Result<Self, Error> {
        checked_len(width, height, pixels.len())?;
        Ok(Self {
            pixels,
            width,
            height,
        })
    }
}

impl<C: PixelColor> TexelSource for Texels<'_, C> {
    type Color = C;

    #[inline(always)]
    fn size(&self) -> Size {
        Size::new(self.width, self.height)
    }

    #[inline(always)]
    fn texel(&self, x: u32, y: u32) -> C {
        // In range by the caller's contract; an index past the end would be a bug here, and the
        // check turns it into a panic rather than a wrong read (see `crate::bounds`).
        *at(self.pixels, y as usize * self.width as usize + x as usize)
    }

    /// One test of the largest of the four indices instead of one per read: the compiler
    /// then drops the reads' own (Cortex-M0 bilinear `big` -1.1%, M4F -1.3%).
    #[inline(always)]
    fn quad(&self, left: u32, right: u32, top: u32, bottom: u32) -> [C; 4] {
        let width = self.width as usize;
        let (top, bottom) = (top as usize * width, bottom as usize * width);
        let (left, right) = (left as usize, right as usize);
        let indices = [top + left, top + right, bottom + left, bottom + right];
        let last = indices[0].max(indices[1]).max(indices[2]).max(indices[3]);
        if last >= self.pixels.len() {
            quad_out_of_range(last, self.pixels.len());
        }
        indices.map(|i| self.pixels[i])
    }
}

/// [`out_of_range`] for [`Texels::quad`], cold only from Cortex-M3 up: with a plain call
/// there Cortex-M0's bilinear loops measured 0.5 to 2.4% faster, M4F's perspective-correct
/// bilinear ones 1.5 to 4% slower.
#[cfg_attr(target_has_atomic = "32", cold)]
#[inline(never)]
fn quad_out_of_range(index: usize, len: usize) -> ! {
    out_of_range(index, len)
}

/// Texels in raw image bytes, packed as embedded-graphics' `ImageRaw` packs them: rows of
/// `C::Raw` values in byte order `BO`, each row padded to whole bytes for formats under 8 bits
/// per pixel (first pixel in the most significant bits). Use it on the same bytes (for example
/// an `include_bytes!`) that you would give `ImageRaw`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{pixelcolor::{raw::LittleEndian, Rgb565}, prelude::*};
/// use trirast::texture::{RawTexels, TexelSource};
///
/// // Two Rgb565 pixels, little endian: pure red and pure blue.
/// const DATA: &[u8] = &[0x00, 0xF8, 0x1F, 0x00];
/// let texels = RawTexels::<Rgb565, LittleEndian>::new(DATA, 2, 1)?;
/// assert_eq!(texels.texel(0, 0), Rgb565::RED);
/// assert_eq!(texels.texel(1, 0), Rgb565::BLUE);
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct RawTexels<'a, C, BO = BigEndian> {
    data: &'a [u8],
    width: u32,
    height: u32,
    row_bytes: usize,
    color: PhantomData<(C, BO)>,
}

impl<'a, C, BO> RawTexels<'a, C, BO>
where
    C: PixelColor + From<C::Raw>,
    BO: TexelByteOrder,
{
    /// Wraps `data` as a `width` x `height` texture in byte order `BO` (big endian unless
    /// given, as for `ImageRaw`).
    ///
    /// # Errors
    ///
    /// [`Error::TextureSize`] if a side is zero or beyond [`MAX_TEXTURE_SIDE`],
    /// [`Error::BufferLength`] unless `data` holds exactly `height` rows.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{raw::LittleEndian, BinaryColor};
    /// use trirast::texture::RawTexels;
    ///
    /// // 10 one-bit pixels per row take 2 bytes; 3 rows take 6.
    /// assert!(RawTexels::<BinaryColor, LittleEndian>::new(&[0; 6], 10, 3).is_ok());
    /// assert!(RawTexels::<BinaryColor, LittleEndian>::new(&[0; 5], 10, 3).is_err());
    /// ```
    pub fn new(data: &'a [u8], width: u32, height: u32) -> Result<Self, Error> {
        checked_size(width, height)?;
        let too_large = Error::TextureSize { width, height };
        let row_bytes = (width as usize)
            .checked_mul(C::Raw::BITS_PER_PIXEL)
            .ok_or(too_large)?
            .div_ceil(8);
        let expected = row_bytes.checked_mul(height as usize).ok_or(too_large)?;
        if data.len() != expected {
            return Err(Error::BufferLength {
                expected,
                actual: data.len(),
            });
        }
        Ok(Self {
            data,
            width,
            height,
            row_bytes,
            color: PhantomData,
        })
    }
}

impl<C, BO> TexelSource for RawTexels<'_, C, BO>
where
    C: PixelColor + From<C::Raw>,
    BO: TexelByteOrder,
{
    type Color = C;

    #[inline(always)]
    fn size(&self) -> Size {
        Size::new(self.width, self.height)
    }

    #[inline(always)]
    fn texel(&self, x: u32, y: u32) -> C {
        let bits = C::Raw::BITS_PER_PIXEL;
        let row = from(self.data, y as usize * self.row_bytes);
        let byte_at = |index: usize| u32::from(*at(row, index));
        let value = if bits >= 8 {
            let bytes = bits / 8;
            let at = x as usize * bytes;
            let mut value = 0u32;
            for i in 0..bytes {
                let byte = byte_at(at + i);
                value = if BO::LITTLE_ENDIAN {
                    value | byte << (8 * i)
                } else {
                    value << 8 | byte
                };
            }
            value
        } else {
            // Sub-byte pixels, first pixel in the most significant bits.
            let bit = x as usize * bits;
            let byte = byte_at(bit / 8);
            byte >> (8 - bits - bit % 8)
        };
        C::Raw::from_u32(value).into()
    }
}

/// The byte order of multi-byte texels, as a constant: embedded-graphics' `ByteOrder` markers
/// carry no information of their own. Implemented for `LittleEndian` and `BigEndian`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::raw::{BigEndian, LittleEndian};
/// use trirast::texture::TexelByteOrder;
///
/// assert!(LittleEndian::LITTLE_ENDIAN);
/// assert!(!BigEndian::LITTLE_ENDIAN);
/// ```
pub trait TexelByteOrder: ByteOrder {
    /// True when the least significant byte comes first.
    const LITTLE_ENDIAN: bool;
}

impl TexelByteOrder for LittleEndian {
    const LITTLE_ENDIAN: bool = true;
}

impl TexelByteOrder for BigEndian {
    const LITTLE_ENDIAN: bool = false;
}

/// Any embedded-graphics image with random pixel access (`GetPixel`) used as texels without
/// copying: `ImageRaw`, `tinybmp::Bmp`, an image of your own. Reading goes through the image's
/// `pixel` method, which decodes each texel; [`Texels`] and [`RawTexels`] are faster.
///
/// # Examples
///
/// ```
/// use embedded_graphics::{image::ImageRaw, pixelcolor::BinaryColor, prelude::*};
/// use trirast::texture::{ImageTexels, TexelSource};
///
/// // An 8x2 one-bit image: a row of "on" pixels over a row of "off" ones.
/// let image = ImageRaw::<BinaryColor>::new(&[0xFF, 0x00], 8);
/// let texels = ImageTexels::new(&image)?;
/// assert_eq!(texels.texel(3, 0), BinaryColor::On);
/// assert_eq!(texels.texel(3, 1), BinaryColor::Off);
/// # Ok::<(), trirast::Error>(())
/// ```
#[derive(Copy, Clone, Debug)]
pub struct ImageTexels<'a, T: GetPixel> {
    image: &'a T,
    size: Size,
    /// Returned for a texel the image does not give (it never should, in range).
    fallback: T::Color,
}

impl<'a, T> ImageTexels<'a, T>
where
    T: GetPixel + OriginDimensions,
{
    /// Wraps `image`.
    ///
    /// # Errors
    ///
    /// [`Error::TextureSize`] if the image is empty, has a side beyond [`MAX_TEXTURE_SIDE`] or
    /// gives no pixel at its origin.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::{image::ImageRaw, pixelcolor::Gray8};
    /// use trirast::texture::ImageTexels;
    ///
    /// let empty = ImageRaw::<Gray8>::new(&[], 4);
    /// assert!(ImageTexels::new(&empty).is_err());
    /// ```
    pub fn new(image: &'a T) -> Result<Self, Error> {
        let size = image.size();
        let error = Error::TextureSize {
            width: size.width,
            height: size.height,
        };
        checked_size(size.width, size.height)?;
        let fallback = image.pixel(Point::zero()).ok_or(error)?;
        Ok(Self {
            image,
            size,
            fallback,
        })
    }
}

impl<T: GetPixel> TexelSource for ImageTexels<'_, T> {
    type Color = T::Color;

    #[inline]
    fn size(&self) -> Size {
        self.size
    }

    #[inline]
    fn texel(&self, x: u32, y: u32) -> T::Color {
        self.image
            .pixel(Point::new(x as i32, y as i32))
            .unwrap_or(self.fallback)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_graphics::{
        image::ImageRaw,
        pixelcolor::{BinaryColor, Gray2, Gray4, Gray8, Rgb565, Rgb888},
    };

    /// `Texels::quad`, with its single test, reads what four `texel` reads do, for every
    /// corner order the wrap modes produce (right of left or wrapped to column 0, the same
    /// for rows) on textures of several shapes.
    #[test]
    fn quad_is_four_reads() {
        for (width, height) in [(1, 1), (2, 3), (5, 2), (7, 7)] {
            let data: [Gray8; 49] = core::array::from_fn(|i| Gray8::new(i as u8 * 5));
            let len = (width * height) as usize;
            let texels = Texels::new(&data[..len], width, height).unwrap();
            for top in 0..height {
                for bottom in 0..height {
                    for left in 0..width {
                        for right in 0..width {
                            let want = [
                                texels.texel(left, top),
                                texels.texel(right, top),
                                texels.texel(left, bottom),
                                texels.texel(right, bottom),
                            ];
                            let got = texels.quad(left, right, top, bottom);
                            assert_eq!(got, want, "{width}x{height} {left} {right} {top} {bottom}");
                        }
                    }
                }
            }
        }
    }

    /// Every texel of a raw source equals what `ImageRaw` decodes from the same bytes.
    fn agrees<C, BO>(data: &[u8], width: u32, height: u32)
    where
        C: PixelColor + From<C::Raw> + core::fmt::Debug,
        BO: TexelByteOrder,
        for<'a> embedded_graphics::iterator::raw::RawDataSlice<'a, C::Raw, BO>:
            IntoIterator<Item = C::Raw>,
    {
        let raw = RawTexels::<C, BO>::new(data, width, height).unwrap();
        let image = ImageRaw::<C, BO>::new(data, width);
        let via_image = ImageTexels::new(&image).unwrap();
        for y in 0..height {
            for x in 0..width {
                let want = image.pixel(Point::new(x as i32, y as i32)).unwrap();
                assert_eq!(raw.texel(x, y), want, "({x}, {y})");
                assert_eq!(via_image.texel(x, y), want);
            }
        }
    }

    #[test]
    fn raw_texels_decode_like_image_raw() {
        let bytes: [u8; 48] = core::array::from_fn(|i| (i as u8).wrapping_mul(37).wrapping_add(11));
        agrees::<Rgb565, LittleEndian>(&bytes, 4, 6);
        agrees::<Rgb565, BigEndian>(&bytes, 6, 4);
        agrees::<Rgb888, LittleEndian>(&bytes, 4, 4);
        agrees::<Rgb888, BigEndian>(&bytes[..36], 3, 4);
        agrees::<Gray8, BigEndian>(&bytes, 8, 6);
        agrees::<Gray4, BigEndian>(&bytes[..12], 5, 4);
        agrees::<Gray2, LittleEndian>(&bytes[..10], 7, 5);
        agrees::<BinaryColor, BigEndian>(&bytes[..12], 13, 6);
    }

    #[test]
    fn bad_sizes_are_errors() {
        assert_eq!(
            RawTexels::<Rgb565, LittleEndian>::new(&[0; 7], 2, 2),
            Err(Error::BufferLength {
                expected: 8,
                actual: 7
            })
        );
        assert_eq!(
            RawTexels::<Rgb565, LittleEndian>::new(&[], 0, 5),
            Err(Error::TextureSize {
                width: 0,
                height: 5
            })
        );
        assert_eq!(
            Texels::new(&[Gray8::new(0); 3], 3, 0),
            Err(Error::TextureSize {
                width: 3,
                height: 0
            })
        );
        assert!(Texels::new(&[Gray8::new(0)], 1, 1).is_ok());
    }
}
