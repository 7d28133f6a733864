//! How a colour is kept in one element of a framebuffer slice.

use embedded_graphics::pixelcolor::{
    Bgr555, Bgr565, Bgr666, Bgr888, BinaryColor, Gray2, Gray4, Gray8, GrayColor, PixelColor,
    Rgb555, Rgb565, Rgb666, Rgb888, RgbColor,
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

// The conversions go through the channels and the colours' `const fn` constructors, not through
// `IntoStorage` and `From<Raw..>`: embedded-graphics marks those conversions `#[inline]`
// nowhere, and at `opt-level = "s"` each became a call per pixel (a blend of `Rgb565` pixels on
// Cortex-M0 cost 82.7 instructions a pixel against 61.7 so). At `opt-level = 3` both ways fold
// to the bits themselves. The tests check them against embedded-graphics' own conversions.
macro_rules! rgb_storage {
    ($storage:ty => $($color:ty: ($r:expr, $g:expr, $b:expr)),+) => {$(
        impl StoredPixel<$color> for $storage {
            #[inline(always)]
            fn store(color: $color) -> Self {
                (<$storage>::from(color.r()) << $r)
                    | (<$storage>::from(color.g()) << $g)
                    | (<$storage>::from(color.b()) << $b)
            }

            #[inline(always)]
            fn load(self) -> $color {
                // `new` keeps each channel's low bits, as the raw types' conversions do.
                <$color>::new((self >> $r) as u8, (self >> $g) as u8, (self >> $b) as u8)
            }
        }
    )+};
}

rgb_storage!(u16 => Rgb565: (11, 5, 0), Bgr565: (0, 5, 11), Rgb555: (10, 5, 0), Bgr555: (0, 5, 10));
rgb_storage!(u32 => Rgb888: (16, 8, 0), Bgr888: (0, 8, 16), Rgb666: (12, 6, 0), Bgr666: (0, 6, 12));

macro_rules! gray_storage {
    ($($color:ty),+) => {$(
        impl StoredPixel<$color> for u8 {
            #[inline(always)]
            fn store(color: $color) -> Self {
                color.luma()
            }

            #[inline(always)]
            fn load(self) -> $color {
                // `new` keeps the low bits the format has, as the raw types' constructors do.
                <$color>::new(self)
            }
        }
    )+};
}

gray_storage!(Gray8, Gray4, Gray2);

impl StoredPixel<BinaryColor> for u8 {
    #[inline(always)]
    fn store(color: BinaryColor) -> Self {
        u8::from(color == BinaryColor::On)
    }

    #[inline(always)]
    fn load(self) -> BinaryColor {
        // The low bit, as `RawU1` keeps.
        if self & 1 == 0 {
            BinaryColor::Off
        } else {
            BinaryColor::On
        }
    }
}

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

    /// Every value of the 8- and 16-bit formats, and a spread of the 24-bit ones, stored and
    /// loaded as embedded-graphics' own raw conversions do.
    #[test]
    fn storage_is_embedded_graphics_raw_conversion() {
        use embedded_graphics::pixelcolor::{
            IntoStorage,
            raw::{RawData, RawU1, RawU2, RawU4, RawU8, RawU16, RawU24},
        };
        fn check<C, R, S>(raw: S)
        where
            C: PixelColor<Raw = R> + IntoStorage<Storage = S> + From<R> + core::fmt::Debug,
            R: RawData<Storage = S>,
            S: StoredPixel<C> + PartialEq + core::fmt::Debug + Into<u32>,
        {
            let loaded = C::from(R::from_u32(raw.into()));
            assert_eq!(raw.load(), loaded, "{raw:?}");
            assert_eq!(S::store(loaded), loaded.into_storage(), "{loaded:?}");
        }
        for raw in 0..=u16::MAX {
            check::<Rgb565, RawU16, u16>(raw);
            check::<Bgr565, RawU16, u16>(raw);
            check::<Rgb555, RawU16, u16>(raw);
            check::<Bgr555, RawU16, u16>(raw);
        }
        for raw in 0..=u8::MAX {
            check::<Gray8, RawU8, u8>(raw);
            check::<Gray4, RawU4, u8>(raw);
            check::<Gray2, RawU2, u8>(raw);
            check::<BinaryColor, RawU1, u8>(raw);
        }
        let mut raw = 0u32;
        for _ in 0..100_000 {
            raw = raw.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            for value in [raw, raw & 0xFF_FFFF] {
                check::<Rgb888, RawU24, u32>(value);
                check::<Bgr888, RawU24, u32>(value);
                check::<Rgb666, RawU24, u32>(value);
                check::<Bgr666, RawU24, u32>(value);
            }
        }
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
