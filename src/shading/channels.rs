//! Colour channels: what Gouraud shading, texture filtering and modulation compute with.

use embedded_graphics::pixelcolor::{
    Bgr555, Bgr565, Bgr666, Bgr888, BinaryColor, Gray2, Gray4, Gray8, GrayColor, PixelColor,
    Rgb555, Rgb565, Rgb666, Rgb888, RgbColor, raw::RawData,
};

use crate::{target::StoredPixel, unroll::each_slot};

/// Colours made of channels that trirast interpolates, each in its own range (0..=31 for the
/// red channel of `Rgb565`, 0..=3 for `Gray2`, 0..=1 for `BinaryColor`, ...): Gouraud shading,
/// bilinear texture filtering and texture modulation work on these channels.
///
/// Implemented for every colour type of embedded-graphics: `Rgb555`, `Rgb565`, `Rgb666`,
/// `Rgb888`, their `Bgr` variants, `Gray2`, `Gray4`, `Gray8` and `BinaryColor`.
///
/// # Examples
///
/// ```
/// use embedded_graphics::pixelcolor::{Gray4, GrayColor, Rgb565};
/// use trirast::shading::ChannelColor;
///
/// assert_eq!(Rgb565::new(31, 40, 2).channels(), [31, 40, 2]);
/// assert_eq!(Gray4::from_channels([9]), Gray4::new(9));
/// assert_eq!(Rgb565::MAX_CHANNELS, [31, 63, 31]);
/// ```
pub trait ChannelColor: PixelColor {
    /// The channel values: `[u8; 3]` (red, green, blue) or `[u8; 1]` (luma).
    type Channels: Copy + Default + AsRef<[u8]> + AsMut<[u8]>;

    /// The largest value of each channel.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray2;
    /// use trirast::shading::ChannelColor;
    ///
    /// assert_eq!(Gray2::MAX_CHANNELS, [3]);
    /// ```
    const MAX_CHANNELS: Self::Channels;

    /// The channel values of a colour.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use trirast::shading::ChannelColor;
    ///
    /// assert_eq!(BinaryColor::On.channels(), [1]);
    /// ```
    fn channels(self) -> Self::Channels;

    /// The colour with these channel values (out-of-range bits are dropped).
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb888, RgbColor};
    /// use trirast::shading::ChannelColor;
    ///
    /// assert_eq!(Rgb888::from_channels([255, 0, 0]), Rgb888::RED);
    /// ```
    fn from_channels(channels: Self::Channels) -> Self;

    /// Bits of the weights in [`ChannelColor::bilinear`]: 8 for channels of up to 6 bits, 9
    /// for 8-bit channels, so that every channel stays within one level of the exact blend.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
    /// use trirast::shading::ChannelColor;
    ///
    /// assert_eq!((Rgb565::WEIGHT_BITS, Rgb888::WEIGHT_BITS), (8, 9));
    /// ```
    const WEIGHT_BITS: u32;

    /// The bilinear blend of four texels, `[top left, top right, bottom left, bottom right]`,
    /// `x` and `y` of the way (in units of 2^-[`WEIGHT_BITS`](ChannelColor::WEIGHT_BITS),
    /// below 1) from the left to the right texels and from the top to the bottom ones.
    ///
    /// Each channel is the weighted sum rounded to nearest. `Rgb565` and `Bgr565` blend all
    /// three channels at once in one 64-bit word on 64-bit targets.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::Gray8;
    /// use trirast::shading::ChannelColor;
    ///
    /// let corners = [Gray8::new(0), Gray8::new(100), Gray8::new(200), Gray8::new(100)];
    /// // A quarter of the way right, halfway down (Gray8 weights have 9 bits).
    /// assert_eq!(Gray8::bilinear(corners, 128, 256), Gray8::new(100));
    /// ```
    #[inline(always)]
    #[must_use]
    fn bilinear(corners: [Self; 4], x: u32, y: u32) -> Self {
        blend_channels(corners, x, y)
    }

    /// This colour drawn over `under` at `opacity` (255: this colour, 0: `under`): each
    /// channel within 3/5 of a level of the exact `(self * opacity + under * (255 - opacity))
    /// / 255`. Channels of 8 bits are that value rounded to nearest (within half a level);
    /// narrower ones (`Rgb565`, `Gray4`, ...) take the opacity in 256ths, which saves a
    /// division's rounding steps per channel. What [`crate::target::blend`] computes.
    ///
    /// # Examples
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::{Gray8, GrayColor};
    /// use trirast::shading::ChannelColor;
    ///
    /// assert_eq!(Gray8::new(200).over(Gray8::new(100), 51), Gray8::new(120));
    /// ```
    #[inline(always)]
    #[must_use]
    fn over(self, under: Self, opacity: u8) -> Self {
        over_channels(self, under, opacity)
    }
}

/// [`ChannelColor::over`] channel by channel.
///
/// Channels of up to 6 bits (`WEIGHT_BITS == 8`) take the opacity in 256ths,
/// `a = opacity + opacity / 128` (0 to 256), and each is `d + ((s - d) a + 128) / 256`
/// rounded down: one product and a shift per channel, no division by 255. Against the exact
/// blend that is at most 3/5 of a level off (a 6-bit channel: half a level of rounding and
/// `63 * 127 / 65280` of opacity), exact at opacities 0 and 255. Wider channels, where the
/// opacity's error alone would approach a level, divide by 255.
#[inline(always)]
fn over_channels<C: ChannelColor>(source: C, under: C, opacity: u8) -> C {
    let (source, under) = (source.channels(), under.channels());
    let (source, under) = (source.as_ref(), under.as_ref());
    let mut out = C::Channels::default();
    if C::WEIGHT_BITS == 8 {
        let a = i32::from(opacity) + i32::from(opacity >> 7);
        each_slot!(out.as_mut(), |k| {
            let (s, d) = (i32::from(source[k]), i32::from(under[k]));
            (d + (((s - d) * a + 128) >> 8)) as u8
        });
    } else {
        let (a, b) = (u32::from(opacity), 255 - u32::from(opacity));
        each_slot!(out.as_mut(), |k| {
            let (s, d) = (u32::from(source[k]), u32::from(under[k]));
            div_255_rounded(s * a + d * b) as u8
        });
    }
    C::from_channels(out)
}

/// `value / 255` rounded to nearest, for `value <= 255 * 255`, without a division (a
/// library call on Cortex-M0).
#[inline(always)]
fn div_255_rounded(value: u32) -> u32 {
    let t = value + 128;
    (t + (t >> 8)) >> 8
}

/// [`ChannelColor::bilinear`] channel by channel.
#[inline(always)]
fn blend_channels<C: ChannelColor>(corners: [C; 4], wx: u32, wy: u32) -> C {
    let bits = C::WEIGHT_BITS;
    let one = 1u32 << bits;
    let weights = [
        (one - wx) * (one - wy),
        wx * (one - wy),
        (one - wx) * wy,
        wx * wy,
    ];
    let shift = 2 * bits;
    // Written out rather than mapped and looped over: `opt-level = "s"` keeps such loops and
    // calls (measured: a bilinear pixel cost Cortex-M4F three times as much).
    let [a, b, c, d] = corners;
    let channels = [a.channels(), b.channels(), c.channels(), d.channels()];
    let mut out = C::Channels::default();
    let (c0, c1) = (channels[0].as_ref(), channels[1].as_ref());
    let (c2, c3) = (channels[2].as_ref(), channels[3].as_ref());
    each_slot!(out.as_mut(), |k| {
        let sum = (1u32 << (shift - 1))
            + u32::from(c0[k]) * weights[0]
            + u32::from(c1[k]) * weights[1]
            + u32::from(c2[k]) * weights[2]
            + u32::from(c3[k]) * weights[3];
        (sum >> shift) as u8
    });
    C::from_channels(out)
}

/// `Rgb565`-layout bilinear blend with 8-bit weights, all channels in one 64-bit word: the
/// channels are spread to 21-, 22- and 21-bit lanes, wide enough for each channel times 2^16,
/// so two rounds of linear interpolation (across, then down) stay in their lanes.
#[inline(always)]
fn blend_565(corners: [u16; 4], x: u32, y: u32) -> u16 {
    // Low channel at bits 0..5, middle at 21..27, high at 43..48.
    const LANES: u64 = 0x0000_F800_07E0_001F;
    const COPIES: u64 = 0x0001_0001_0001;
    let spread = |c: u16| (u64::from(c) * COPIES) & LANES;
    let (wx, wy) = (u64::from(x), u64::from(y));
    let [top_left, top_right, bottom_left, bottom_right] = corners.map(spread);
    let top = top_left * (256 - wx) + top_right * wx;
    let bottom = bottom_left * (256 - wx) + bottom_right * wx;
    let half = (1 << 15) | (1 << 36) | (1 << 58); // half a level in each lane (2^15)
    let lanes = ((top * (256 - wy) + bottom * wy + half) >> 16) & LANES;
    // Gathers the three lanes back into 16 bits: they land disjointly in bits 32..48.
    (lanes.wrapping_mul(COPIES) >> 32) as u16
}

/// [`ChannelColor::over`] for the 5-6-5 layouts on their raw bits, as `over_channels` computes
/// it (opacity in 256ths): each field taken out by shifts and put back without masks, since a
/// blend lies between its two values and so within its field.
#[inline(always)]
fn over_565(source: u16, under: u16, opacity: u8) -> u16 {
    /// A named function, not a closure: at `opt-level = "z"` a closure called three times
    /// stays a call.
    #[inline(always)]
    fn blend(s: i32, d: i32, a: i32) -> i32 {
        d + (((s - d) * a + 128) >> 8)
    }
    let a = i32::from(opacity) + i32::from(opacity >> 7);
    let (s, d) = (i32::from(source), i32::from(under));
    let high = blend(s >> 11, d >> 11, a);
    let middle = blend((s >> 5) & 63, (d >> 5) & 63, a);
    let low = blend(s & 31, d & 31, a);
    ((high << 11) | (middle << 5) | low) as u16
}

macro_rules! rgb_channels {
    ($($color:ty),+) => {$(
        impl ChannelColor for $color {
            type Channels = [u8; 3];

            const MAX_CHANNELS: [u8; 3] = [<$color>::MAX_R, <$color>::MAX_G, <$color>::MAX_B];

            const WEIGHT_BITS: u32 = if <$color>::MAX_G > 63 { 9 } else { 8 };

            #[inline(always)]
            fn channels(self) -> [u8; 3] {
                [self.r(), self.g(), self.b()]
            }

            #[inline(always)]
            fn from_channels([r, g, b]: [u8; 3]) -> Self {
                Self::new(r, g, b)
            }
        }
    )+};
}

rgb_channels!(Rgb555, Bgr555, Rgb666, Bgr666, Rgb888, Bgr888);

macro_rules! rgb565_channels {
    ($($color:ty),+) => {$(
        impl ChannelColor for $color {
            type Channels = [u8; 3];

            const MAX_CHANNELS: [u8; 3] = [<$color>::MAX_R, <$color>::MAX_G, <$color>::MAX_B];

            const WEIGHT_BITS: u32 = if <$color>::MAX_G > 63 { 9 } else { 8 };

            #[inline(always)]
            fn channels(self) -> [u8; 3] {
                [self.r(), self.g(), self.b()]
            }

            #[inline(always)]
            fn from_channels([r, g, b]: [u8; 3]) -> Self {
                Self::new(r, g, b)
            }

            #[inline(always)]
            fn over(self, under: Self, opacity: u8) -> Self {
                // The raw bits as a `u16` frame stores them (not through embedded-graphics'
                // `IntoStorage`, a call per pixel at `opt-level = "s"`: see `StoredPixel`).
                let store = <u16 as StoredPixel<Self>>::store;
                StoredPixel::load(over_565(store(self), store(under), opacity))
            }

            #[inline(always)]
            fn bilinear(corners: [Self; 4], x: u32, y: u32) -> Self {
                // In one 64-bit word where registers hold one; 32-bit cores blend channel by
                // channel.
                if crate::arch::WORD_64 {
                    let store = <u16 as StoredPixel<Self>>::store;
                    StoredPixel::load(blend_565(corners.map(store), x, y))
                } else {
                    blend_channels(corners, x, y)
                }
            }

        }
    )+};
}

rgb565_channels!(Rgb565, Bgr565);

macro_rules! gray_channels {
    ($($color:ty),+) => {$(
        impl ChannelColor for $color {
            type Channels = [u8; 1];

            const MAX_CHANNELS: [u8; 1] = [((1u16 << <<$color as PixelColor>::Raw as RawData>::BITS_PER_PIXEL) - 1) as u8];

            const WEIGHT_BITS: u32 = if Self::MAX_CHANNELS[0] > 63 { 9 } else { 8 };

            #[inline(always)]
            fn channels(self) -> [u8; 1] {
                [self.luma()]
            }

            #[inline(always)]
            fn from_channels([luma]: [u8; 1]) -> Self {
                Self::new(luma)
            }
        }
    )+};
}

gray_channels!(Gray2, Gray4, Gray8);

impl ChannelColor for BinaryColor {
    type Channels = [u8; 1];

    const MAX_CHANNELS: [u8; 1] = [1];

    const WEIGHT_BITS: u32 = 8;

    #[inline(always)]
    fn channels(self) -> [u8; 1] {
        [u8::from(self.is_on())]
    }

    #[inline(always)]
    fn from_channels([on]: [u8; 1]) -> Self {
        if on & 1 == 1 {
            BinaryColor::On
        } else {
            BinaryColor::Off
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_graphics::pixelcolor::raw::RawU16;

    #[test]
    fn division_by_255_rounds_to_nearest() {
        for value in 0..=255 * 255 {
            let exact = (2 * value + 255) / 510; // round(value / 255), halves up
            assert_eq!(div_255_rounded(value), exact, "{value}");
        }
    }

    /// The blend of one channel with weights of `bits` bits, rounded half up.
    fn reference(c: [u8; 4], x: u32, y: u32, bits: u32) -> u32 {
        let one = 1u64 << bits;
        let (wx, wy) = (u64::from(x), u64::from(y));
        let w = [
            (one - wx) * (one - wy),
            wx * (one - wy),
            (one - wx) * wy,
            wx * wy,
        ];
        let sum: u64 = c.iter().zip(w).map(|(&c, w)| u64::from(c) * w).sum();
        ((sum + (1 << (2 * bits - 1))) >> (2 * bits)) as u32
    }

    #[test]
    fn rgb565_word_blend_equals_channel_blend() {
        let mut rng = crate::test_rng::XorShift(0x9E37_79B9_7F4A_7C15);
        let mut next = || rng.next_u64();
        for _ in 0..20_000 {
            let corners: [Rgb565; 4] = core::array::from_fn(|_| {
                let r = next();
                Rgb565::new((r & 31) as u8, (r >> 8 & 63) as u8, (r >> 16 & 31) as u8)
            });
            let (x, y) = ((next() & 0xFF) as u32, (next() & 0xFF) as u32);
            let got = Rgb565::bilinear(corners, x, y).channels();
            for k in 0..3 {
                let c = corners.map(|c| c.channels()[k]);
                assert_eq!(
                    u32::from(got[k]),
                    reference(c, x, y, 8),
                    "{corners:?} {x} {y}"
                );
            }
            let generic = blend_channels(corners, x, y);
            assert_eq!(generic, Rgb565::bilinear(corners, x, y));
        }
    }

    #[test]
    fn rgb565_raw_blend_equals_channel_blend() {
        use embedded_graphics::pixelcolor::{Bgr565, raw::RawU16};
        fn check<C: ChannelColor + From<RawU16> + core::fmt::Debug>(s: u16, d: u16, opacity: u8) {
            let (s, d) = (C::from(RawU16::new(s)), C::from(RawU16::new(d)));
            let want = over_channels(s, d, opacity);
            assert_eq!(s.over(d, opacity), want, "{s:?} over {d:?} at {opacity}");
        }
        let mut rng = crate::test_rng::XorShift(0x2545_F491_4F6C_DD1D);
        for _ in 0..200_000 {
            let r = rng.next_u64();
            let (s, d, opacity) = (r as u16, (r >> 16) as u16, (r >> 32) as u8);
            check::<Rgb565>(s, d, opacity);
            check::<Bgr565>(s, d, opacity);
        }
    }

    #[test]
    fn rgb565_raw_blend_equals_channel_blend_for_every_field_and_opacity() {
        // Every pair of values of each field at every opacity: `v` runs over the 6-bit field's
        // values, its low 5 bits and their complement over the 5-bit ones (fields blend
        // apart, so each is checked whatever the others hold).
        let color = |v: u16| ((v & 31) << 11) | (v << 5) | (!v & 31);
        for opacity in 0..=u8::MAX {
            for (s, d) in (0..64).flat_map(|s| (0..64).map(move |d| (s, d))) {
                let (s, d) = (
                    Rgb565::from(RawU16::new(color(s))),
                    Rgb565::from(RawU16::new(color(d))),
                );
                assert_eq!(
                    s.over(d, opacity),
                    over_channels(s, d, opacity),
                    "{s:?} over {d:?} at {opacity}"
                );
            }
        }
    }

    #[test]
    fn extreme_weights_and_values() {
        let white = [Rgb565::WHITE; 4];
        for (x, y) in [(0, 0), (255, 255), (0x7F, 0x80), (0x80, 0)] {
            assert_eq!(Rgb565::bilinear(white, x, y), Rgb565::WHITE);
            assert_eq!(
                Gray8::bilinear([Gray8::WHITE; 4], 2 * x, 2 * y + 1),
                Gray8::WHITE
            );
        }
        let corners = [Rgb565::RED, Rgb565::GREEN, Rgb565::BLUE, Rgb565::WHITE];
        assert_eq!(Rgb565::bilinear(corners, 0, 0), Rgb565::RED);
        // 255/256 of the way: within half a level of the far corner.
        assert_eq!(Rgb565::bilinear(corners, 255, 0), Rgb565::GREEN);
        assert_eq!(Rgb565::bilinear(corners, 0, 255), Rgb565::BLUE);
        assert_eq!(Rgb565::bilinear(corners, 255, 255), Rgb565::WHITE);
        assert_eq!(Gray4::MAX_CHANNELS, [15]);
        assert_eq!(Gray8::MAX_CHANNELS, [255]);
        assert_eq!(Rgb888::MAX_CHANNELS, [255; 3]);
    }
}
