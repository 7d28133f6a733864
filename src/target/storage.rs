//! How a colour is kept in one element of a framebuffer slice.

use embedded_graphics::pixelcolor::{
    raw::{RawU16, RawU24, RawU8},
    Bgr555, Bgr565, Bgr666, Bgr888, BinaryColor, Gray2, Gray4, Gray8, IntoStorage, PixelColor,
    Rgb555, Rgb565, Rgb666, Rgb888,
};

/// A slice element that holds one pixel of colour `C`.
///
/// Every colour type stores itself (`&mut [Rgb565]`), and the usual colour types can also live
/// in their raw integer (`&mut [u16]` for `Rgb565`, `&mut [u32]` for `Rgb888`, `&mut [u8]` for
/// `Gray8` or `BinaryColor`), for buffers shared with DMA or display drivers. One element per
/// pixel: sub-byte formats are not packed.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use trirast::StoredPixel;
///
/// assert_eq!(<u16 as StoredPixel<Rgb565>>::store(Rgb565::RED), 0xF800);
/// assert_eq!(<u16 as StoredPixel<Rgb565>>::load(0x07E0), Rgb565::GREEN);
/// ```
pub trait StoredPixel<C>: Copy {
    /// Encodes a colour.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use trirast::StoredPixel;
    ///
    /// assert_eq!(<u8 as StoredPixel<Gray8>>::store(Gray8::new(77)), 77);
    /// ```
    fn store(color: C) -> Self;

    /// Decodes a colour.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{BinaryColor, Rgb888, RgbColor};
    /// use trirast::StoredPixel;
    ///
    /// assert_eq!(<u32 as StoredPixel<Rgb888>>::load(0x0000FF), Rgb888::BLUE);
    /// assert_eq!(<u8 as StoredPixel<BinaryColor>>::load(1), BinaryColor::On);
    /// ```
    fn load(self) -> C;
}

impl<C: PixelColor> StoredPixel<C> for C {
    #[inline(always)]
    fn store(color: C) -> Self {
        color
    }

    #[inline(always)]
    fn load(self) -> C {
        self
    }
}

macro_rules! raw_storage {
    ($storage:ty, $raw:ty => $($color:ty),+) => {$(
        impl StoredPixel<$color> for $storage {
            #[inline(always)]
            fn store(color: $color) -> Self {
                color.into_storage()
            }

            #[inline(always)]
            fn load(self) -> $color {
                <$raw>::new(self).into()
            }
        }
    )+};
}

raw_storage!(u16, RawU16 => Rgb565, Bgr565, Rgb555, Bgr555);
raw_storage!(u32, RawU24 => Rgb888, Bgr888, Rgb666, Bgr666);
raw_storage!(u8, RawU8 => Gray8);

macro_rules! small_storage {
    ($($color:ty),+) => {$(
        impl StoredPixel<$color> for u8 {
            #[inline(always)]
            fn store(color: $color) -> Self {
                color.into_storage()
            }

            #[inline(always)]
            fn load(self) -> $color {
                // Keep the low bits the format has, as the raw types' constructors do.
                let raw = <<$color as PixelColor>::Raw as embedded_graphics::pixelcolor::raw::RawData>::from_u32(u32::from(self));
                raw.into()
            }
        }
    )+};
}

small_storage!(Gray2, Gray4, BinaryColor);

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_graphics::pixelcolor::RgbColor;

    fn round_trip<C: PixelColor + core::fmt::Debug, S: StoredPixel<C>>(colors: &[C]) {
        for &c in colors {
            assert_eq!(S::store(c).load(), c);
        }
    }

    #[test]
    fn raw_storage_round_trips() {
        round_trip::<Rgb565, u16>(&[Rgb565::RED, Rgb565::new(3, 40, 17), Rgb565::WHITE]);
        round_trip::<Bgr565, u16>(&[Bgr565::BLUE, Bgr565::new(31, 1, 2)]);
        round_trip::<Rgb888, u32>(&[Rgb888::new(1, 2, 3), Rgb888::WHITE]);
        round_trip::<Rgb666, u32>(&[Rgb666::new(63, 0, 9)]);
        round_trip::<Gray8, u8>(&[Gray8::new(0), Gray8::new(200)]);
        round_trip::<Gray4, u8>(&[Gray4::new(15), Gray4::new(6)]);
        round_trip::<Gray2, u8>(&[Gray2::new(3), Gray2::new(1)]);
        round_trip::<BinaryColor, u8>(&[BinaryColor::On, BinaryColor::Off]);
        round_trip::<Rgb565, Rgb565>(&[Rgb565::CYAN]);
    }

    #[test]
    fn rgb565_raw_layout() {
        assert_eq!(
            <u16 as StoredPixel<Rgb565>>::store(Rgb565::new(31, 0, 0)),
            0xF800
        );
        assert_eq!(
            <u16 as StoredPixel<Rgb565>>::store(Rgb565::new(0, 63, 0)),
            0x07E0
        );
        assert_eq!(
            <u16 as StoredPixel<Rgb565>>::store(Rgb565::new(0, 0, 31)),
            0x001F
        );
    }
}
